// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/neighbourhoods/SheetNeighbourhoods.h"
#include "FeatureLines/support/IdleThreads.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>
#include <omp.h>

namespace featurelines {

namespace {

constexpr double pi = 3.14159265358979323846;

struct LocalPlane
{
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
    /// The least gap to another sheet (length).
    double gap = 0.0;
    /// False where the fitted points lie along a line (a scan row): no sheet is told there.
    bool defined = true;
};

/// Fitted points spread less than this across their line are one scan row: a row's nearest
/// points leave its plane undefined (BalancedNeighbourhoods.h uses 0.02 over k points).
constexpr double minSpread = 0.05;

/// Points fitted per local plane at most (the point and its nearest neighbours).
constexpr int maxFitted = 32;

/// The least-squares plane of the first `count` of `x` where `use` is set: its normal, the
/// points' mean, and `spread` the middle eigenvalue of their covariance over the largest (near 0
/// along one scan row, where the plane is not defined).
Eigen::Vector3d planeNormal(const Eigen::Vector3d* x, const bool* use, int count,
                            Eigen::Vector3d& mean, double& spread)
{
    mean.setZero();
    int used = 0;
    for (int r = 0; r < count; ++r) {
        if (use[r]) {
            mean += x[r];
            ++used;
        }
    }
    mean /= double(used);
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    for (int r = 0; r < count; ++r) {
        if (use[r]) {
            const Eigen::Vector3d d = x[r] - mean;
            C += d * d.transpose();
        }
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(C, Eigen::ComputeEigenvectors);
    const Eigen::Vector3d values = solver.eigenvalues();
    spread = values(2) > 0.0 ? values(1) / values(2) : 0.0;
    return solver.eigenvectors().col(0);
}

/// Point i's local plane: fitted to it and its m nearest neighbours (m < maxFitted), again
/// without the outliers; its gap and whether it is defined. Allocates nothing: it runs for every
/// point.
LocalPlane localPlane(const PointMatrix& P, const Neighbourhoods& N, Eigen::Index i, int m,
                      double minGap, double noiseGap)
{
    Eigen::Vector3d x[maxFitted];
    bool use[maxFitted];
    double d[maxFitted];
    double sorted[maxFitted];
    const int count = m + 1;
    const Eigen::Vector3d origin = P.row(i).transpose();
    x[0].setZero();
    for (int j = 0; j < m; ++j) {
        x[j + 1] = P.row(N.indices(i, j)).transpose() - origin;
    }
    std::fill(use, use + count, true);
    LocalPlane plane;
    double spread = 0.0;
    Eigen::Vector3d mean;
    plane.normal = planeNormal(x, use, count, mean, spread);
    for (int r = 0; r < count; ++r) {
        d[r] = std::abs(plane.normal.dot(x[r] - mean));
        sorted[r] = d[r];
    }
    std::nth_element(sorted, sorted + count / 2, sorted + count);
    const double cut = std::max(3.0 * 1.4826 * sorted[count / 2], 0.5 * minGap);
    int kept = 0;
    for (int r = 0; r < count; ++r) {
        use[r] = d[r] <= cut;
        kept += use[r] ? 1 : 0;
    }
    if (kept < count && kept >= 5) {
        plane.normal = planeNormal(x, use, count, mean, spread);
        for (int r = 0; r < count; ++r) {
            d[r] = std::abs(plane.normal.dot(x[r] - mean));
        }
    } else {
        std::fill(use, use + count, true);
        kept = count;
    }
    double squares = 0.0;
    for (int r = 0; r < count; ++r) {
        if (use[r]) {
            squares += d[r] * d[r];
        }
    }
    const double rms = std::sqrt(squares / double(std::max(1, kept - 3)));
    plane.gap = std::max(minGap, noiseGap * rms);
    plane.defined = spread >= minSpread;
    return plane;
}

} // namespace

std::vector<int> separateSheets(const PointMatrix& P, Neighbourhoods& N, double spacing,
                                const SheetOptions& options, int threads)
{
    if (P.rows() != N.size()) {
        throw std::invalid_argument("sheet neighbourhoods: " + std::to_string(P.rows()) +
                                    " points and " + std::to_string(N.size()) +
                                    " neighbourhoods do not match");
    }
    if (!(spacing > 0.0) || !std::isfinite(spacing) || !(options.minGap > 0.0) ||
        !(options.noiseGap >= 0.0) || !(options.maxTurnDegrees >= 0.0) ||
        !(options.maxTurnDegrees < 90.0) || options.fitPoints < 3) {
        throw std::invalid_argument("sheet neighbourhoods: the spacing and the least gap must be "
                                    "positive, the turn below 90 degrees and at least 3 points "
                                    "fitted");
    }
    const Eigen::Index n = N.size();
    const int k = N.k();
    if (!options.separate || n == 0) {
        return {};
    }
    const int m = std::min({options.fitPoints, k, maxFitted - 1});
    const int workers = threadCount(threads);
    std::vector<LocalPlane> planes(static_cast<size_t>(n));
#pragma omp parallel for num_threads(workers) schedule(static, 1024)
    for (Eigen::Index i = 0; i < n; ++i) {
        planes[static_cast<size_t>(i)] =
            localPlane(P, N, i, m, options.minGap * spacing, options.noiseGap);
    }
    // The gap follows the noise, which one fit of a few points reads with a spread of a third:
    // each point takes the median of its own and its fitted neighbours' gaps.
    {
        std::vector<double> gaps(static_cast<size_t>(n));
#pragma omp parallel for num_threads(workers) schedule(static, 1024)
        for (Eigen::Index i = 0; i < n; ++i) {
            double near[maxFitted]; // the point and its m < maxFitted nearest
            int count = 0;
            near[count++] = planes[static_cast<size_t>(i)].gap;
            for (int j = 0; j < m; ++j) {
                near[count++] = planes[static_cast<size_t>(N.indices(i, j))].gap;
            }
            std::nth_element(near, near + count / 2, near + count);
            gaps[static_cast<size_t>(i)] = near[count / 2];
        }
        for (Eigen::Index i = 0; i < n; ++i) {
            planes[static_cast<size_t>(i)].gap = gaps[static_cast<size_t>(i)];
        }
    }
    const double parallel = std::cos(options.maxTurnDegrees * pi / 180.0);
    const auto opposite = [&](int a, int b) {
        const LocalPlane& pa = planes[static_cast<size_t>(a)];
        const LocalPlane& pb = planes[static_cast<size_t>(b)];
        if (!pa.defined || !pb.defined || std::abs(pa.normal.dot(pb.normal)) < parallel) {
            return false;
        }
        const Eigen::Vector3d d = (P.row(b) - P.row(a)).transpose();
        return std::abs(pa.normal.dot(d)) >= pa.gap && std::abs(pb.normal.dot(d)) >= pb.gap;
    };
    std::vector<char> flagged(static_cast<size_t>(n), 0);
#pragma omp parallel for num_threads(workers) schedule(static, 1024)
    for (Eigen::Index i = 0; i < n; ++i) {
        // A second sheet lies on one side, with more than one point of it in reach; noise puts
        // its stray far points on either side.
        int above = 0, below = 0;
        const Eigen::Vector3d& normal = planes[static_cast<size_t>(i)].normal;
        for (int j = 0; j < k; ++j) {
            const int q = N.indices(i, j);
            if (opposite(static_cast<int>(i), q)) {
                (normal.dot((P.row(q) - P.row(i)).transpose()) > 0.0 ? above : below) += 1;
            }
        }
        flagged[static_cast<size_t>(i)] =
            (std::max(above, below) >= options.minAcross && std::min(above, below) == 0) ? 1 : 0;
    }
    std::vector<int> rows;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (flagged[static_cast<size_t>(i)] != 0) {
            rows.push_back(static_cast<int>(i));
        }
    }
    // The rebuilt rows are written after every row is chosen: the candidates are read from the
    // neighbourhoods as found.
    std::vector<std::vector<std::pair<double, int>>> chosenRows(rows.size());
#pragma omp parallel for num_threads(workers) schedule(dynamic, 64)
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const int i = rows[r];
        std::vector<int> candidates;
        candidates.reserve(static_cast<size_t>(k * (k + 1)));
        for (int j = 0; j < k; ++j) {
            const int q = N.indices(i, j);
            candidates.push_back(q);
            for (int l = 0; l < k; ++l) {
                candidates.push_back(N.indices(q, l));
            }
        }
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        std::vector<std::pair<double, int>>& chosen = chosenRows[r];
        for (int q : candidates) {
            if (q != i && !opposite(i, q)) {
                chosen.emplace_back((P.row(q) - P.row(i)).squaredNorm(), q);
            }
        }
        std::sort(chosen.begin(), chosen.end());
        if (int(chosen.size()) < k) {
            chosen.clear(); // too few on its own sheet: the row stays as found
            continue;
        }
        chosen.resize(static_cast<size_t>(k));
    }
    std::vector<int> rebuilt;
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const std::vector<std::pair<double, int>>& chosen = chosenRows[r];
        if (chosen.empty()) {
            continue;
        }
        const int i = rows[r];
        for (int j = 0; j < k; ++j) {
            N.squaredDistances(i, j) = chosen[static_cast<size_t>(j)].first;
            N.indices(i, j) = chosen[static_cast<size_t>(j)].second;
        }
        rebuilt.push_back(i);
    }
    return rebuilt;
}

} // namespace featurelines
