// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/BlendRadius.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "FeatureLines/curvature/Curvature.h"
#include "FeatureLines/smooth/LineBand.h"

namespace featurelines {

namespace {

double median(std::vector<double>& v)
{
    const size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
    return v[mid];
}

} // namespace

std::vector<double> blendRadii(const RegionGeometry& region, const SmoothEdgeLevel& level,
                               const BlendRadiusOptions& options)
{
    const std::vector<Polyline>& lines = level.network.lines;
    std::vector<double> radii(lines.size(), std::numeric_limits<double>::quiet_NaN());
    const double reach = options.reach * region.spacing * region.curvatureScale;
    if (lines.empty() || !(reach > 0.0) || region.neighbours.size() != region.points.rows()) {
        return radii;
    }
    const LineBand band(lines, reach);
    std::vector<std::vector<double>> curvatures(lines.size());
    for (size_t i = 0; i < level.labels.size(); ++i) {
        if (level.labels[i] != PointLabel::Inner) {
            continue;
        }
        const Eigen::Index p = static_cast<Eigen::Index>(i);
        const int line = band.nearestLine(region.points.row(p));
        if (line < 0) {
            continue;
        }
        const double kappa = largestCurvature(region.points, region.normals, region.neighbours, p);
        if (std::isfinite(kappa) && kappa > 0.0) {
            curvatures[static_cast<size_t>(line)].push_back(kappa);
        }
    }
    for (size_t l = 0; l < lines.size(); ++l) {
        if (static_cast<int>(curvatures[l].size()) >= std::max(1, options.minPoints)) {
            radii[l] = 1.0 / median(curvatures[l]);
        }
    }
    return radii;
}

} // namespace featurelines
