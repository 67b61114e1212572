// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/curvature/Smoothing.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "FeatureLines/support/HugePages.h"

namespace featurelines {

namespace {

/// p + factor (mean of the umbrella - p) for the point p, from the sum of its umbrella's
/// coordinates (in the umbrella's order, from zero) and its size.
inline void moveTowards(const double* point, const double (&sum)[3], int size, double factor,
                        double* out)
{
    for (int d = 0; d < 3; ++d) {
        const double mean = sum[d] / size;
        out[d] = point[d] + factor * (mean - point[d]);
    }
}

/// Row `out` of `to`: the point at row `point` of `from` moved by `factor` towards the mean of
/// the rows umbrella[0 .. size) of `from` (summed in that order), or copied when size is 0.
inline void umbrellaRow(const double* from, double* to, std::ptrdiff_t point, std::ptrdiff_t out,
                        const int* umbrella, int size, double factor)
{
    if (size == 0) {
        std::copy(from + 3 * point, from + 3 * point + 3, to + 3 * out);
        return;
    }
    double sum[3] = {0.0, 0.0, 0.0};
    for (int j = 0; j < size; ++j) {
        const double* q = from + 3 * static_cast<std::ptrdiff_t>(umbrella[j]);
        sum[0] += q[0];
        sum[1] += q[1];
        sum[2] += q[2];
    }
    moveTowards(from + 3 * point, sum, size, factor, to + 3 * out);
}

/// One umbrella step of the rows [first, last) of a subset of every row, whose umbrellas are
/// the k neighbours of each row: two rows at a time, whose sums are independent chains of
/// additions (the processor overlaps their loads).
void umbrellaStep(const double* from, double* to, const int* neighbours, int k, double factor,
                  Eigen::Index first, Eigen::Index last)
{
    Eigen::Index s = first;
    for (; s + 1 < last; s += 2) {
        const int* a = neighbours + s * k;
        const int* b = a + k;
        double sa[3] = {0.0, 0.0, 0.0}, sb[3] = {0.0, 0.0, 0.0};
        for (int j = 0; j < k; ++j) {
            const double* qa = from + 3 * static_cast<std::ptrdiff_t>(a[j]);
            const double* qb = from + 3 * static_cast<std::ptrdiff_t>(b[j]);
            sa[0] += qa[0];
            sa[1] += qa[1];
            sa[2] += qa[2];
            sb[0] += qb[0];
            sb[1] += qb[1];
            sb[2] += qb[2];
        }
        moveTowards(from + 3 * s, sa, k, factor, to + 3 * s);
        moveTowards(from + 3 * (s + 1), sb, k, factor, to + 3 * (s + 1));
    }
    if (s < last) {
        umbrellaRow(from, to, s, s, neighbours + s * k, k, factor);
    }
}

void checkInput(const PointMatrix& P, const Neighbourhoods& N, const SmoothingOptions& options)
{
    if (N.size() != P.rows()) {
        throw std::invalid_argument("smoothing: the neighbourhoods were computed for another "
                                    "cloud (" +
                                    std::to_string(N.size()) + " rows for " +
                                    std::to_string(P.rows()) + " points)");
    }
    if (options.iterations < 0 || !std::isfinite(options.lambda) || !std::isfinite(options.mu)) {
        throw std::invalid_argument("smoothing: iterations must be >= 0 and lambda, mu finite");
    }
}

/// #n: nonzero for the points of `subset`. Throws for an index outside [0, n) or listed twice.
std::vector<char> subsetFlags(const std::vector<int>& subset, Eigen::Index n)
{
    std::vector<char> inSubset(n, 0);
    for (const int i : subset) {
        if (i < 0 || i >= n) {
            throw std::invalid_argument("smoothing: point index " + std::to_string(i) +
                                        " is outside the cloud of " + std::to_string(n) +
                                        " points");
        }
        if (inSubset[i]) {
            throw std::invalid_argument("smoothing: point index " + std::to_string(i) +
                                        " is listed twice");
        }
        inSubset[i] = 1;
    }
    return inSubset;
}

/// Each subset point's umbrella: its neighbours in the subset (Sec. 2.4: the region holds no
/// sharp edge, so its points are smoothed among themselves; neighbours outside it, across a
/// sharp edge, are left out).
struct Umbrellas
{
    /// The subset is every point in row order (a whole region): the umbrellas are the
    /// neighbourhoods themselves (every neighbour is in the subset) and need no copying back.
    bool everyRow = false;
    /// Then: the neighbourhoods' rows of k indices each.
    const int* rows = nullptr;
    int k = 0;
    /// Otherwise subset point s's umbrella is members[offsets[s] .. offsets[s + 1]).
    std::vector<int> offsets;
    std::vector<int> members;
};

Umbrellas umbrellasOf(const Neighbourhoods& N, const std::vector<int>& subset,
                      const std::vector<char>& inSubset)
{
    const Eigen::Index m = static_cast<Eigen::Index>(subset.size());
    Umbrellas u;
    u.everyRow = m == N.size() && N.k() > 0;
    for (Eigen::Index s = 0; s < m && u.everyRow; ++s) {
        u.everyRow = subset[s] == s;
    }
    u.rows = N.indices.data();
    u.k = N.k();
    if (!u.everyRow) {
        u.offsets.assign(static_cast<size_t>(m) + 1, 0);
        u.members.reserve(m * N.k());
        for (Eigen::Index s = 0; s < m; ++s) {
            const int i = subset[s];
            for (int j = 0; j < N.k(); ++j) {
                if (inSubset[N.indices(i, j)]) {
                    u.members.push_back(N.indices(i, j));
                }
            }
            u.offsets[s + 1] = static_cast<int>(u.members.size());
        }
    }
    return u;
}

/// One umbrella step for every subset point from the same positions (Jacobi), so the result
/// does not depend on the order of `subset`: p += factor * (mean of its umbrella - p). `moved`
/// is a #subset by 3 buffer.
void jacobiStep(PointMatrix& current, PointMatrix& moved, const std::vector<int>& subset,
                const Umbrellas& umbrellas, double factor)
{
    const Eigen::Index m = static_cast<Eigen::Index>(subset.size());
    if (umbrellas.everyRow) {
        const double* from = current.data();
        double* to = moved.data();
        const Eigen::Index blocks = (m + 4095) / 4096;
#pragma omp parallel for schedule(static, 1)
        for (Eigen::Index b = 0; b < blocks; ++b) {
            umbrellaStep(from, to, umbrellas.rows, umbrellas.k, factor, b * 4096,
                         std::min(m, (b + 1) * 4096));
        }
        current.swap(moved); // every row moved
        return;
    }
    const int* umbrella = umbrellas.members.data();
    const std::vector<int>& offsets = umbrellas.offsets;
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index s = 0; s < m; ++s) {
        umbrellaRow(current.data(), moved.data(), subset[s], s, umbrella + offsets[s],
                    offsets[s + 1] - offsets[s], factor);
    }
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index s = 0; s < m; ++s) {
        current.row(subset[s]) = moved.row(s);
    }
}

} // namespace

PointMatrix laplacianSmooth(const PointMatrix& P, const Neighbourhoods& N,
                            const std::vector<int>& subset, const SmoothingOptions& options,
                            const ProgressSpan& progress)
{
    checkInput(P, N, options);
    const Eigen::Index n = P.rows();
    const Umbrellas umbrellas = umbrellasOf(N, subset, subsetFlags(subset, n));
    PointMatrix current(n, 3), moved(static_cast<Eigen::Index>(subset.size()), 3);
    adviseHugePagesOf(current);
    adviseHugePagesOf(moved);
    current = P;
    for (int iteration = 0; iteration < options.iterations; ++iteration) {
        // Taubin (1995): a shrinking step lambda > 0 then an inflating step mu < -lambda.
        jacobiStep(current, moved, subset, umbrellas, options.lambda);
        if (options.mu != 0.0) {
            jacobiStep(current, moved, subset, umbrellas, options.mu);
        }
        progress.report(static_cast<double>(iteration + 1) / options.iterations);
    }
    return current;
}

} // namespace featurelines
