// SPDX-License-Identifier: LGPL-2.1-or-later
// A region whose curvature is prescribed, for the tests of the smooth-edge stage: the
// automatic rule, the labels and the lines see exactly the levels drawn.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>

#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/smooth/RegionGeometry.h"

namespace featurelines {

/// A triangular lattice of unit spacing in the plane z = 0, nx by ny points, with the
/// curvature field given (the region's own geometry, no fit): the automatic rule sees exactly
/// the levels drawn.
inline RegionGeometry latticeRegion(int nx, int ny,
                                    const std::function<double(double, double)>& field,
                                    double curvatureNoise = 0.0)
{
    RegionGeometry g;
    g.region = 0;
    g.points.resize(nx * ny, 3);
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            g.points.row(j * nx + i) << i + 0.5 * (j % 2), j * std::sqrt(3.0) / 2.0, 0.0;
        }
    }
    g.members.resize(static_cast<size_t>(nx * ny));
    for (size_t i = 0; i < g.members.size(); ++i) {
        g.members[i] = static_cast<int>(i);
    }
    g.neighbours = nearestNeighbours(g.points);
    g.normals = pcaNormals(g.points, g.neighbours).normals;
    g.ring = ringNeighbourhoods(g.points, g.normals, g.neighbours);
    g.spacing = meanSpacing(g.neighbours);
    g.curvature.resize(nx * ny);
    for (Eigen::Index p = 0; p < g.points.rows(); ++p) {
        g.curvature[p] = field(g.points(p, 0), g.points(p, 1));
    }
    g.curvatureNoise = curvatureNoise;
    return g;
}

/// A level that steps from `low` to `high` across x = edge, blurred over `ramp` spacings as
/// the quadric fit blurs a step.
inline double step(double x, double edge, double low, double high, double ramp)
{
    const double t = std::clamp((x - edge) / ramp + 0.5, 0.0, 1.0);
    return low + t * (high - low);
}

} // namespace featurelines
