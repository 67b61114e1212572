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
    /// The plane is normal . x = offset.
    double offset = 0.0;
    /// RMS distance of the fitted points to it (length).
    double rms = 0.0;
    /// False where the fitted points lie along a line (a scan row): no sheet is told there.
    bool defined = true;
};

/// Fitted points spread less than this across their line are one scan row: a row's nearest
/// points leave its plane undefined (BalancedNeighbourhoods.h uses 0.02 over k points).
constexpr double minSpread = 0.05;

/// Points fitted per local plane at most (the point and its nearest neighbours).
constexpr int maxFitted = 32;

/// Two groups of offsets are two sheets only when their means lie at least this many times
/// their pooled deviation apart: the largest split of one Gaussian group of 17 offsets reaches
/// 3.0 times at the median, 4.7 at one in a hundred (and the offsets of a curved patch or of a
/// crease, spread evenly, as far), while two sheets 2 spacings apart under noise of 0.3 spacing
/// lie 6.7 apart. Together with the least wall (minWall), which noise alone does not reach.
constexpr double minSeparation = 3.5;

/// cos(20 degrees): neighbours' first planes turned from the point's by less than this on
/// average agree with it (one fit of 9 points under noise of 0.3 spacing turns by about 7).
const double cosAgree = std::cos(20.0 * pi / 180.0);

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
    bool use[maxFitted] = {};
    double d[maxFitted];
    double sorted[maxFitted];
    const int count = m + 1;
    const Eigen::Vector3d origin = P.row(i).transpose();
    x[0].setZero();
    for (int j = 0; j < m; ++j) {
        x[j + 1] = P.row(N.indices(i, j)).transpose() - origin;
    }
    for (int r = 0; r < count; ++r) {
        use[r] = true;
    }
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
        for (int r = 0; r < count; ++r) {
            use[r] = true;
        }
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
    plane.rms = rms;
    plane.offset = plane.normal.dot(origin + mean);
    plane.defined = spread >= minSpread;
    return plane;
}

/// Point i's plane read again from the first pass's planes: where a thin wall's other sheet
/// holds part of the m nearest, their least-squares plane tilts towards it, or turns across the
/// wall when it holds half. The sheet's direction is instead the dominant one of the first
/// pass's normals of the point and its k neighbours (most of them fitted their own sheet). Along
/// it the offsets of the point and its k neighbours fall in one group or, where the other sheet
/// is within reach, in two: split where the two groups' variance between them is largest, they
/// are two sheets when their means lie at least `minWall` (length) apart and `minSeparation`
/// times their pooled deviation; the plane then passes through the mean of the point's group and
/// its deviation is that group's.
LocalPlane votedPlane(const PointMatrix& P, const Neighbourhoods& N, Eigen::Index i,
                      double minGap, double minWall, double noiseGap,
                      const std::vector<LocalPlane>& first, const std::vector<double>& quiet)
{
    const LocalPlane& own = first[static_cast<size_t>(i)];
    if (!own.defined) {
        return own;
    }
    const int k = N.k();
    // No other sheet within reach, and the point's first plane not drawn off by one: its
    // residual no more than twice the quiet residual about it (`quiet`, the lower quartile of
    // the first residuals of the point and its nearest), its neighbours' first planes turned
    // from it by under 20 degrees on average, and none of them farther off it than half the
    // least wall or 4 quiet residuals. Then the first plane stands: most points of a clean or
    // noisy single sheet.
    {
        const double q = quiet[static_cast<size_t>(i)];
        const double reach = std::max(0.5 * minWall, 4.0 * q);
        double turn = 0.0;
        bool single = own.rms <= 2.0 * q + 0.01 * minWall;
        for (int j = 0; j < k && single; ++j) {
            const int r = N.indices(i, j);
            const LocalPlane& f = first[static_cast<size_t>(r)];
            single = f.defined &&
                     std::abs(own.normal.dot(P.row(r).transpose()) - own.offset) < reach;
            turn += std::abs(f.normal.dot(own.normal));
        }
        if (single && turn >= k * cosAgree) {
            return own;
        }
    }
    Eigen::Matrix3d S = own.normal * own.normal.transpose();
    for (int j = 0; j < k; ++j) {
        const LocalPlane& f = first[static_cast<size_t>(N.indices(i, j))];
        if (f.defined) {
            S += f.normal * f.normal.transpose();
        }
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(S, Eigen::ComputeEigenvectors);
    LocalPlane plane;
    plane.normal = solver.eigenvectors().col(2);
    const Eigen::Vector3d origin = P.row(i).transpose();
    // Buffers reused by each thread: this runs for every point.
    thread_local std::vector<double> o;
    thread_local std::vector<double> prefix;
    thread_local std::vector<double> prefix2;
    const int count = k + 1;
    o.resize(static_cast<size_t>(count));
    prefix.assign(static_cast<size_t>(count + 1), 0.0);
    prefix2.assign(static_cast<size_t>(count + 1), 0.0);
    o[0] = 0.0;
    for (int j = 0; j < k; ++j) {
        o[static_cast<size_t>(j + 1)] =
            plane.normal.dot(P.row(N.indices(i, j)).transpose() - origin);
    }
    std::sort(o.begin(), o.end());
    for (int r = 0; r < count; ++r) {
        prefix[r + 1] = prefix[r] + o[r];
        prefix2[r + 1] = prefix2[r] + o[r] * o[r];
    }
    // Sum of squared deviations of o[from, to).
    const auto scatter = [&](int from, int to) {
        const double sum = prefix[to] - prefix[from];
        return std::max(0.0, prefix2[to] - prefix2[from] - sum * sum / double(to - from));
    };
    int split = 0;
    double best = 0.0;
    for (int r = 2; r + 2 <= count; ++r) {
        const double m1 = (prefix[r] - prefix[0]) / r;
        const double m2 = (prefix[count] - prefix[r]) / double(count - r);
        const double between = double(r) * double(count - r) * (m2 - m1) * (m2 - m1);
        if (between > best) {
            best = between;
            split = r;
        }
    }
    int from = 0;
    int to = count;
    if (split > 0) {
        const double m1 = prefix[split] / split;
        const double m2 = (prefix[count] - prefix[split]) / double(count - split);
        const double pooled = std::sqrt((scatter(0, split) + scatter(split, count)) / (count - 2));
        if (m2 - m1 >= minWall && m2 - m1 >= minSeparation * pooled) {
            // The point's own group: the one its offset 0 falls in.
            if (0.0 < 0.5 * (o[split - 1] + o[split])) {
                to = split;
            } else {
                from = split;
            }
        }
    }
    const int kept = to - from;
    if (kept < 5) {
        return own;
    }
    const double centre = (prefix[to] - prefix[from]) / kept;
    const double rms = std::sqrt(scatter(from, to) / double(std::max(1, kept - 3)));
    plane.gap = std::max(minGap, noiseGap * rms);
    plane.offset = plane.normal.dot(origin) + centre;
    return plane;
}

/// Per point i, the lower quartile of value(j) over i and its m < maxFitted nearest.
template <typename Value>
std::vector<double> lowerQuartileNear(const Neighbourhoods& N, int m, int workers, Value value)
{
    const Eigen::Index n = N.size();
    std::vector<double> result(static_cast<size_t>(n));
#pragma omp parallel for num_threads(workers) schedule(static, 1024)
    for (Eigen::Index i = 0; i < n; ++i) {
        double near[maxFitted];
        int count = 0;
        near[count++] = value(i);
        for (int j = 0; j < m; ++j) {
            near[count++] = value(N.indices(i, j));
        }
        std::nth_element(near, near + count / 4, near + count);
        result[static_cast<size_t>(i)] = near[count / 4];
    }
    return result;
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
        !(options.minWall > 0.0) || !(options.noiseGap >= 0.0) ||
        !(options.maxTurnDegrees >= 0.0) || !(options.maxTurnDegrees < 90.0) ||
        options.fitPoints < 3 || options.minAcross < 1) {
        throw std::invalid_argument("sheet neighbourhoods: the spacing, the least gap and the "
                                    "least wall must be positive, the turn below 90 degrees, at "
                                    "least 3 points fitted and 1 across");
    }
    const Eigen::Index n = N.size();
    const int k = N.k();
    if (!options.separate || n == 0) {
        return {};
    }
    const int m = std::min({options.fitPoints, k, maxFitted - 1});
    const int workers = threadCount(threads);
    std::vector<LocalPlane> planes(static_cast<size_t>(n));
    {
        std::vector<LocalPlane> first(static_cast<size_t>(n));
#pragma omp parallel for num_threads(workers) schedule(static, 1024)
        for (Eigen::Index i = 0; i < n; ++i) {
            first[static_cast<size_t>(i)] =
                localPlane(P, N, i, m, options.minGap * spacing, options.noiseGap);
        }
        // The quiet residual about each point: the lower quartile of the first residuals of it
        // and its nearest (a fit the other sheet reached reads too much).
        const std::vector<double> quiet = lowerQuartileNear(
            N, m, workers, [&](Eigen::Index j) { return first[static_cast<size_t>(j)].rms; });
#pragma omp parallel for num_threads(workers) schedule(static, 1024)
        for (Eigen::Index i = 0; i < n; ++i) {
            planes[static_cast<size_t>(i)] =
                votedPlane(P, N, i, options.minGap * spacing, options.minWall * spacing,
                           options.noiseGap, first, quiet);
        }
    }
    // The gap follows the noise, which one fit of a few points reads with a spread of a third:
    // each point takes the lower quartile of its own and its fitted neighbours' gaps (a fit
    // that a thin wall's other sheet still reached reads too much noise; the others are its
    // own sheet's).
    {
        const std::vector<double> gaps = lowerQuartileNear(
            N, m, workers, [&](Eigen::Index j) { return planes[static_cast<size_t>(j)].gap; });
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
        const Eigen::Vector3d xa = P.row(a).transpose();
        const Eigen::Vector3d xb = P.row(b).transpose();
        return std::abs(pa.normal.dot(xb) - pa.offset) >= pa.gap &&
               std::abs(pb.normal.dot(xa) - pb.offset) >= pb.gap;
    };
    std::vector<char> flagged(static_cast<size_t>(n), 0);
#pragma omp parallel for num_threads(workers) schedule(static, 1024)
    for (Eigen::Index i = 0; i < n; ++i) {
        // A second sheet lies on one side, with more than one point of it in reach; noise puts
        // its stray far points on either side.
        int above = 0, below = 0;
        const LocalPlane& plane = planes[static_cast<size_t>(i)];
        for (int j = 0; j < k; ++j) {
            const int q = N.indices(i, j);
            if (opposite(static_cast<int>(i), q)) {
                (plane.normal.dot(P.row(q).transpose()) > plane.offset ? above : below) += 1;
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
