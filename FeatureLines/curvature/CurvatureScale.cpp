// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/curvature/CurvatureScale.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include <Eigen/Eigenvalues>

#include "FeatureLines/neighbourhoods/MortonOrder.h"
#include "FeatureLines/neighbourhoods/Normals.h"

namespace featurelines {

std::vector<std::pair<std::uint64_t, int>> gridCellKeys(const PointMatrix& P,
                                                        const Eigen::RowVector3d& low, double cell)
{
    // Each point's cell as a Morton key; sorting the keys groups a cell's points and orders
    // the cells along the Z curve. The point index breaks ties, so the result is deterministic.
    const Eigen::Index n = P.rows();
    std::vector<std::pair<std::uint64_t, int>> keyed(static_cast<size_t>(n));
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < n; ++i) {
        std::uint64_t c[3];
        for (int d = 0; d < 3; ++d) {
            c[d] = static_cast<std::uint64_t>(std::floor((P(i, d) - low[d]) / cell));
        }
        keyed[static_cast<size_t>(i)] = {mortonKey(c[0], c[1], c[2]), static_cast<int>(i)};
    }
    // Stable: the pairs come in index order, so this is their order by (key, index).
    sortByMortonKey(keyed);
    return keyed;
}

GridCentroids gridCentroids(const PointMatrix& P, double cell)
{
    if (!(cell > 0.0) || !std::isfinite(cell)) {
        throw std::invalid_argument("grid centroids: the cell size must be a positive number");
    }
    const Eigen::Index n = P.rows();
    if (n == 0) {
        throw std::invalid_argument("grid centroids: no points");
    }
    const Eigen::RowVector3d low = P.colwise().minCoeff();
    const Eigen::RowVector3d cells = ((P.colwise().maxCoeff() - low) / cell).array().floor();
    if (!(cells.maxCoeff() < static_cast<double>(1 << mortonBitsPerAxis))) {
        throw std::invalid_argument("grid centroids: the cloud spans too many cells");
    }
    const std::vector<std::pair<std::uint64_t, int>> keyed = gridCellKeys(P, low, cell);
    GridCentroids grid;
    grid.cellOf.resize(static_cast<size_t>(n));
    std::vector<Eigen::RowVector3d> sums;
    std::vector<int> counts;
    for (size_t j = 0; j < keyed.size(); ++j) {
        if (j == 0 || keyed[j].first != keyed[j - 1].first) {
            sums.emplace_back(Eigen::RowVector3d::Zero());
            counts.push_back(0);
        }
        const int i = keyed[j].second;
        sums.back() += P.row(i);
        ++counts.back();
        grid.cellOf[static_cast<size_t>(i)] = static_cast<int>(sums.size()) - 1;
    }
    grid.points.resize(static_cast<Eigen::Index>(sums.size()), 3);
    for (size_t c = 0; c < sums.size(); ++c) {
        grid.points.row(static_cast<Eigen::Index>(c)) = sums[c] / counts[c];
    }
    return grid;
}

double planeDeviation(const PointMatrix& P, double share)
{
    const Eigen::Index n = P.rows();
    if (n < 3 || !(share >= 0.0 && share < 1.0)) {
        throw std::invalid_argument("plane deviation: needs 3 points or more and a share in "
                                    "[0, 1)");
    }
    const Moments moments = momentsOf(P);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(moments.covariance);
    const Eigen::RowVector3d normal = solver.eigenvectors().col(0).transpose(); // smallest
    std::vector<double> distance(static_cast<size_t>(n));
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < n; ++i) {
        distance[static_cast<size_t>(i)] = std::abs((P.row(i) - moments.mean).dot(normal));
    }
    const auto at = distance.begin() +
                    std::min<Eigen::Index>(
                        n - 1, static_cast<Eigen::Index>(std::floor((1.0 - share) * (n - 1))));
    std::nth_element(distance.begin(), at, distance.end());
    return *at;
}

Eigen::VectorXd valuesAtPoints(const PointMatrix& P, const GridCentroids& grid,
                               const Neighbourhoods& N, const Eigen::VectorXd& values, double width)
{
    const Eigen::Index n = P.rows();
    if (static_cast<Eigen::Index>(grid.cellOf.size()) != n || N.size() != grid.points.rows() ||
        values.size() != grid.points.rows()) {
        throw std::invalid_argument("valuesAtPoints: the points, cells and values do not match");
    }
    if (!(width > 0.0)) {
        throw std::invalid_argument("valuesAtPoints: the width must be positive");
    }
    const double scale = -0.5 / (width * width);
    Eigen::VectorXd result(n);
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < n; ++i) {
        const int c = grid.cellOf[static_cast<size_t>(i)];
        double weight = std::exp(scale * (grid.points.row(c) - P.row(i)).squaredNorm());
        double sum = weight * values[c];
        for (int j = 0; j < N.k(); ++j) {
            const int q = N.indices(c, j);
            const double w = std::exp(scale * (grid.points.row(q) - P.row(i)).squaredNorm());
            weight += w;
            sum += w * values[q];
        }
        // The cell's own centroid lies within a cell of p, so the weights never all vanish
        // unless the width is far below the cell; then p keeps its cell's value.
        result[i] = weight > 0.0 ? sum / weight : values[c];
    }
    return result;
}

} // namespace featurelines
