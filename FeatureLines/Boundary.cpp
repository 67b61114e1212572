// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/Boundary.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>
#include <omp.h>

namespace featurelines {

namespace {

constexpr double pi = 3.14159265358979323846;

int threadCount(int requested)
{
    return requested > 0 ? requested : omp_get_max_threads();
}

} // namespace

std::vector<char> boundaryPoints(const PointMatrix& P, const NormalMatrix& normals,
                                 const Neighbourhoods& N, const BoundaryOptions& options)
{
    const Eigen::Index n = P.rows();
    if (normals.rows() != n || N.size() != n) {
        throw std::invalid_argument(
            "boundary: the normals and neighbourhoods must have one row per point (" +
            std::to_string(n) + " points, " + std::to_string(normals.rows()) + " normals, " +
            std::to_string(N.size()) + " neighbourhoods)");
    }
    if (!(options.minGapAngle > 0.0 && options.minGapAngle < 360.0)) {
        throw std::invalid_argument("boundary: the gap angle must be between 0 and 360 degrees, not " +
                                    std::to_string(options.minGapAngle));
    }
    const int k = N.k();
    const double minGap = options.minGapAngle * pi / 180.0;
    std::vector<char> boundary(n, 0);
#pragma omp parallel num_threads(threadCount(options.threads))
    {
        std::vector<double> angles(k);
#pragma omp for schedule(static, 4096)
        for (Eigen::Index i = 0; i < n; ++i) {
            // A frame of the tangent plane.
            const Eigen::Vector3d normal = normals.row(i).transpose();
            const Eigen::Vector3d helper = std::abs(normal.x()) < 0.9 ? Eigen::Vector3d::UnitX()
                                                                       : Eigen::Vector3d::UnitY();
            const Eigen::Vector3d u = normal.cross(helper).normalized();
            const Eigen::Vector3d v = normal.cross(u);
            const double tiny = 1e-12 * (1.0 + P.row(i).cwiseAbs().maxCoeff());
            int count = 0;
            for (int j = 0; j < k; ++j) {
                const Eigen::Vector3d d = (P.row(N.indices(i, j)) - P.row(i)).transpose();
                const double x = d.dot(u);
                const double y = d.dot(v);
                if (std::abs(x) + std::abs(y) > tiny) {
                    angles[count++] = std::atan2(y, x);
                }
            }
            if (count == 0) {
                continue;
            }
            std::sort(angles.begin(), angles.begin() + count);
            double widest = angles[0] + 2.0 * pi - angles[count - 1];
            for (int j = 1; j < count; ++j) {
                widest = std::max(widest, angles[j] - angles[j - 1]);
            }
            boundary[i] = widest > minGap ? 1 : 0;
        }
    }
    return boundary;
}

Boundary extractBoundary(const PointMatrix& P, const NormalMatrix& normals,
                         const Neighbourhoods& N, double spacing, const BoundaryOptions& options)
{
    if (!(spacing > 0.0) || !std::isfinite(spacing)) {
        throw std::invalid_argument("boundary: the point spacing must be a positive number");
    }
    Boundary result;
    result.isBoundary = boundaryPoints(P, normals, N, options);
    // Every boundary point is a candidate cluster of its own; other points are left out.
    std::vector<int> cluster(result.isBoundary.size(), -1);
    int count = 0;
    for (std::size_t i = 0; i < cluster.size(); ++i) {
        if (result.isBoundary[i]) {
            cluster[i] = count++;
        }
    }
    const std::vector<char> candidate(count, 1);
    result.network = buildClusterGraph(P, N, cluster, candidate, spacing, options.graph).network;
    return result;
}

} // namespace featurelines
