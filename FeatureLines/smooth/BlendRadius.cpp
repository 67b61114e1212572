// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/BlendRadius.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "FeatureLines/curvature/Curvature.h"

namespace featurelines {

namespace {

/// The lines' vertices and the points between them at most a cell apart, each with its line,
/// in a uniform hash grid of cells `cell` wide.
class LineSamples
{
public:
    LineSamples(const std::vector<Polyline>& lines, double cell) : cell_(cell)
    {
        for (size_t l = 0; l < lines.size(); ++l) {
            const PointMatrix& V = lines[l].points;
            const Eigen::Index n = V.rows();
            const Eigen::Index segments = lines[l].closed ? n : n - 1;
            if (n == 1) {
                insert(V.row(0), static_cast<int>(l));
            }
            for (Eigen::Index s = 0; s < segments; ++s) {
                const Eigen::RowVector3d a = V.row(s), b = V.row((s + 1) % n);
                const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / cell)));
                for (int j = 0; j < pieces; ++j) {
                    insert(a + (b - a) * (static_cast<double>(j) / pieces), static_cast<int>(l));
                }
            }
            if (!lines[l].closed && n > 1) {
                insert(V.row(n - 1), static_cast<int>(l));
            }
        }
    }

    /// The line of the sample nearest p within the cell width, -1 for none.
    int nearestLine(const Eigen::RowVector3d& p) const
    {
        const long long x = key(p(0)), y = key(p(1)), z = key(p(2));
        double best = cell_ * cell_;
        int line = -1;
        for (long long dx = -1; dx <= 1; ++dx) {
            for (long long dy = -1; dy <= 1; ++dy) {
                for (long long dz = -1; dz <= 1; ++dz) {
                    const auto it = cells_.find(hash(x + dx, y + dy, z + dz));
                    if (it == cells_.end()) {
                        continue;
                    }
                    for (const Sample& s : it->second) {
                        const double d = (s.position - p).squaredNorm();
                        if (d < best) {
                            best = d;
                            line = s.line;
                        }
                    }
                }
            }
        }
        return line;
    }

private:
    struct Sample
    {
        Eigen::RowVector3d position;
        int line;
    };

    long long key(double v) const { return static_cast<long long>(std::floor(v / cell_)); }
    static long long hash(long long x, long long y, long long z)
    {
        return x * 73856093LL ^ y * 19349663LL ^ z * 83492791LL;
    }
    void insert(const Eigen::RowVector3d& p, int line)
    {
        // Cells sharing a hash share a list: the look-up compares distances, so a stranger's
        // samples are only farther candidates.
        cells_[hash(key(p(0)), key(p(1)), key(p(2)))].push_back({p, line});
    }

    double cell_;
    std::unordered_map<long long, std::vector<Sample>> cells_;
};

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
    const LineSamples samples(lines, reach);
    std::vector<std::vector<double>> curvatures(lines.size());
    for (size_t i = 0; i < level.labels.size(); ++i) {
        if (level.labels[i] != PointLabel::Inner) {
            continue;
        }
        const Eigen::Index p = static_cast<Eigen::Index>(i);
        const int line = samples.nearestLine(region.points.row(p));
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
