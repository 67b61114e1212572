// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/neighbourhoods/BalancedNeighbourhoods.h"
#include "FeatureLines/support/IdleThreads.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>
#include <omp.h>

namespace featurelines {

namespace {

/// The direction of point i's row: the principal axis of it and its neighbours.
Eigen::Vector3d rowDirection(const PointMatrix& P, const Neighbourhoods& N, Eigen::Index i)
{
    const int k = N.k();
    Eigen::Vector3d mean = P.row(i).transpose();
    for (int j = 0; j < k; ++j) {
        mean += P.row(N.indices(i, j)).transpose();
    }
    mean /= double(k + 1);
    Eigen::Matrix3d C = (P.row(i).transpose() - mean) * (P.row(i).transpose() - mean).transpose();
    for (int j = 0; j < k; ++j) {
        const Eigen::Vector3d d = P.row(N.indices(i, j)).transpose() - mean;
        C += d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(C, Eigen::ComputeEigenvectors);
    return solver.eigenvectors().col(2);
}

} // namespace

std::vector<int> balanceCollinearNeighbourhoods(const PointMatrix& P, Neighbourhoods& N,
                                                const Eigen::VectorXd& spread,
                                                const BalanceOptions& options)
{
    if (spread.size() != N.size() || P.rows() != N.size()) {
        throw std::invalid_argument("balanced neighbourhoods: " + std::to_string(P.rows()) +
                                    " points, " + std::to_string(N.size()) +
                                    " neighbourhoods and " + std::to_string(spread.size()) +
                                    " spreads do not match");
    }
    const Eigen::Index n = N.size();
    const int k = N.k();
    const int threads = threadCount(options.threads);
    std::vector<int> rows;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (spread(i) < options.collinearShare) {
            rows.push_back(static_cast<int>(i));
        }
    }
    if (rows.empty() || double(rows.size()) < options.minCollinearShare * double(n)) {
        return {};
    }
    NeighbourOptions wideOptions;
    wideOptions.k = std::min<Eigen::Index>(options.widerFactor * k, n - 1);
    wideOptions.threads = options.threads;
    const Neighbourhoods wide = nearestNeighbours(P, wideOptions);
    const double offRow = 2.0 * meanSpacing(N);
    const int keep = k / 2;
#pragma omp parallel for num_threads(threads) schedule(dynamic, 256)
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const Eigen::Index i = rows[r];
        const Eigen::Vector3d u = rowDirection(P, N, i);
        std::vector<std::pair<double, int>> chosen;
        chosen.reserve(static_cast<std::size_t>(k));
        for (int j = 0; j < keep; ++j) {
            chosen.emplace_back(N.squaredDistances(i, j), N.indices(i, j));
        }
        for (int j = 0; j < wide.k() && int(chosen.size()) < k; ++j) {
            const int q = wide.indices(i, j);
            const Eigen::Vector3d d = (P.row(q) - P.row(i)).transpose();
            if ((d - d.dot(u) * u).norm() > offRow) {
                chosen.emplace_back(wide.squaredDistances(i, j), q);
            }
        }
        // Too few points off the row within the wider search: keep the row's neighbours.
        for (int j = keep; int(chosen.size()) < k && j < k; ++j) {
            const int q = N.indices(i, j);
            if (std::none_of(chosen.begin(), chosen.end(),
                             [q](const std::pair<double, int>& c) { return c.second == q; })) {
                chosen.emplace_back(N.squaredDistances(i, j), q);
            }
        }
        std::sort(chosen.begin(), chosen.end());
        for (int j = 0; j < k; ++j) {
            N.squaredDistances(i, j) = chosen[static_cast<std::size_t>(j)].first;
            N.indices(i, j) = chosen[static_cast<std::size_t>(j)].second;
        }
    }
    return rows;
}

} // namespace featurelines
