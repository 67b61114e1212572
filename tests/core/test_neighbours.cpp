// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "FeatureLines/neighbourhoods/MortonOrder.h"
#include "FeatureLines/neighbourhoods/Neighbours.h"

using namespace featurelines;

namespace {

PointMatrix randomCloud(int n, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    PointMatrix P(n, 3);
    for (int i = 0; i < n; ++i) {
        for (int d = 0; d < 3; ++d) {
            P(i, d) = coordinate(rng);
        }
    }
    return P;
}

/// The k nearest other points of point i by sorting all distances.
std::vector<int> bruteForce(const PointMatrix& P, int i, int k)
{
    std::vector<int> order;
    for (int j = 0; j < P.rows(); ++j) {
        if (j != i) {
            order.push_back(j);
        }
    }
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return (P.row(a) - P.row(i)).squaredNorm() < (P.row(b) - P.row(i)).squaredNorm();
    });
    order.resize(k);
    return order;
}

/// Square lattice of side n in the plane z = 0 with the given spacing.
PointMatrix squareLattice(int n, double spacing)
{
    PointMatrix P(n * n, 3);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            P.row(i * n + j) << i * spacing, j * spacing, 0.0;
        }
    }
    return P;
}

/// The search's k neighbours of every point are the brute force's, in its order.
void expectBruteForceNeighbours(const PointMatrix& P, int k)
{
    const Neighbourhoods N = nearestNeighbours(P, {k, 0});
    for (int i = 0; i < P.rows(); ++i) {
        const std::vector<int> expected = bruteForce(P, i, k);
        for (int j = 0; j < k; ++j) {
            ASSERT_EQ(N.indices(i, j), expected[j]) << "point " << i << ", neighbour " << j;
        }
    }
}

} // namespace

TEST(Neighbours, MatchBruteForceOnRandomCloud)
{
    const PointMatrix P = randomCloud(600, 7);
    const int k = 12;
    const Neighbourhoods N = nearestNeighbours(P, {k, 0});
    ASSERT_EQ(N.size(), P.rows());
    ASSERT_EQ(N.k(), k);
    for (int i = 0; i < P.rows(); ++i) {
        const std::vector<int> expected = bruteForce(P, i, k);
        for (int j = 0; j < k; ++j) {
            ASSERT_EQ(N.indices(i, j), expected[j]) << "point " << i << ", neighbour " << j;
            EXPECT_DOUBLE_EQ(N.squaredDistances(i, j),
                             (P.row(expected[j]) - P.row(i)).squaredNorm());
        }
    }
}

TEST(Neighbours, MatchBruteForceAcrossScales)
{
    // Tight clusters (extent 1e-7 and 1e-4) inside a cloud of extent 1e3: the search batches
    // neighbouring points and cuts candidates in float first, which must not lose a neighbour
    // when a leaf mixes very different scales.
    const PointMatrix spread = randomCloud(400, 8) * 1e3;
    const PointMatrix tight = randomCloud(40, 9) * 1e-7;
    const PointMatrix small = randomCloud(40, 10) * 1e-4;
    PointMatrix P(spread.rows() + tight.rows() + small.rows(), 3);
    P << spread, tight.rowwise() + Eigen::RowVector3d(5.0, 5.0, 5.0),
        small.rowwise() + Eigen::RowVector3d(5.0, 5.0, 5.0);
    expectBruteForceNeighbours(P, 10);
}

TEST(Neighbours, MatchBruteForceInMortonOrder)
{
    // A noisy plane in the order of its Morton keys (the canonical order analyseCloud gives):
    // the search then runs on the cloud itself instead of a sorted copy.
    std::mt19937 rng(12);
    std::normal_distribution<double> noise(0.0, 0.01);
    PointMatrix plane = randomCloud(2000, 12);
    for (Eigen::Index i = 0; i < plane.rows(); ++i) {
        plane(i, 2) = noise(rng);
    }
    const MortonGrid grid(plane);
    std::vector<std::pair<std::uint64_t, int>> keyed;
    for (Eigen::Index i = 0; i < plane.rows(); ++i) {
        keyed.emplace_back(grid.key(plane, i), static_cast<int>(i));
    }
    sortByMortonKey(keyed);
    PointMatrix P(plane.rows(), 3);
    for (size_t r = 0; r < keyed.size(); ++r) {
        P.row(static_cast<Eigen::Index>(r)) = plane.row(keyed[r].second);
    }
    expectBruteForceNeighbours(P, 16);
}

TEST(Neighbours, MatchBruteForceWithFarOutliers)
{
    // A dense lattice with a few points far off it: their neighbours lie far beyond the cells
    // around them, and every lattice point has exact ties among its neighbours.
    const PointMatrix lattice = squareLattice(40, 0.1);
    PointMatrix P(lattice.rows() + 4, 3);
    P.topRows(lattice.rows()) = lattice;
    P.bottomRows(4) << 50.0, 0.0, 3.0, -20.0, 7.0, 1.0, 1.0, 1.0, 30.0, 2.0, 2.0, -0.5;
    const int k = 8;
    const Neighbourhoods N = nearestNeighbours(P, {k, 0});
    for (int i = 0; i < P.rows(); ++i) {
        // The brute force's sort is not stable: compare distances, they are unique up to ties.
        const std::vector<int> expected = bruteForce(P, i, k);
        for (int j = 0; j < k; ++j) {
            ASSERT_EQ(N.squaredDistances(i, j), (P.row(expected[j]) - P.row(i)).squaredNorm())
                << "point " << i << ", neighbour " << j;
        }
        for (int j = 1; j < k; ++j) {
            const double a = N.squaredDistances(i, j - 1), b = N.squaredDistances(i, j);
            ASSERT_TRUE(a < b || (a == b && N.indices(i, j - 1) < N.indices(i, j)))
                << "point " << i << ": ties go by index";
        }
    }
}

TEST(Neighbours, SameAnswerForAnyThreadCount)
{
    const PointMatrix P = randomCloud(3000, 11);
    const Neighbourhoods one = nearestNeighbours(P, {16, 1});
    const Neighbourhoods two = nearestNeighbours(P, {16, 2});
    EXPECT_EQ(one.indices, two.indices);
    EXPECT_EQ(one.squaredDistances, two.squaredDistances);
}

TEST(Neighbours, DuplicatePointsAreNeighboursButNeverTheQueryItself)
{
    // Every lattice point twice: its twin is its nearest neighbour, at distance zero.
    const PointMatrix lattice = squareLattice(10, 0.5);
    const Eigen::Index n = lattice.rows();
    PointMatrix P(2 * n, 3);
    P << lattice, lattice;
    const Neighbourhoods N = nearestNeighbours(P, {6, 0});
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        const Eigen::Index twin = i < n ? i + n : i - n;
        EXPECT_EQ(N.indices(i, 0), twin);
        EXPECT_EQ(N.squaredDistances(i, 0), 0.0);
        for (int j = 0; j < N.k(); ++j) {
            EXPECT_NE(N.indices(i, j), i);
        }
    }
    // Zero distances are not spacing: the lattice spacing remains.
    EXPECT_DOUBLE_EQ(meanSpacing(N), 0.5);
}

TEST(Neighbours, MoreCoincidentPointsThanNeighbours)
{
    // 30 copies of one point among a lattice: each copy's neighbours are other copies only.
    const PointMatrix lattice = squareLattice(8, 1.0);
    PointMatrix P(lattice.rows() + 30, 3);
    P.topRows(lattice.rows()) = lattice;
    P.bottomRows(30).rowwise() = Eigen::RowVector3d(3.5, 3.5, 2.0);
    const Neighbourhoods N = nearestNeighbours(P, {5, 0});
    for (Eigen::Index i = lattice.rows(); i < P.rows(); ++i) {
        for (int j = 0; j < N.k(); ++j) {
            EXPECT_NE(N.indices(i, j), i);
            EXPECT_GE(N.indices(i, j), lattice.rows());
            EXPECT_EQ(N.squaredDistances(i, j), 0.0);
        }
    }
}

TEST(Neighbours, MeanSpacingOfSquareLattice)
{
    const Neighbourhoods N = nearestNeighbours(squareLattice(20, 0.25), {8, 0});
    EXPECT_DOUBLE_EQ(meanSpacing(N), 0.25);
}

namespace {

/// Rows of points `step` apart along x, `rowGap` apart along y, in the plane z = 0.
PointMatrix rowsOfPoints(int perRow, int rows, double step, double rowGap)
{
    PointMatrix P(perRow * rows, 3);
    for (int r = 0; r < rows; ++r) {
        for (int i = 0; i < perRow; ++i) {
            P.row(r * perRow + i) << i * step, r * rowGap, 0.0;
        }
    }
    return P;
}

} // namespace

TEST(Neighbours, SamplingSpacingOfAnEvenSamplingIsItsNearestSpacing)
{
    // A square lattice is as even as a sampling gets: nothing to raise.
    const Neighbourhoods N = nearestNeighbours(squareLattice(40, 0.25), {16, 0});
    EXPECT_DOUBLE_EQ(samplingSpacing(N), meanSpacing(N));
}

TEST(Neighbours, SamplingSpacingOfScanRowsFollowsTheAreaPerPoint)
{
    // Rows 4 steps apart: nearest neighbours 1 step away along a row, but one point per 4
    // square steps, so 0.8 * sqrt(4) = 1.6 steps (to the k-neighbourhood's rounding).
    const Neighbourhoods N = nearestNeighbours(rowsOfPoints(200, 50, 1.0, 4.0), {16, 0});
    EXPECT_DOUBLE_EQ(meanSpacing(N), 1.0);
    EXPECT_NEAR(samplingSpacing(N), 1.6, 0.16);
}

TEST(Neighbours, SamplingSpacingOfARandomSamplingFollowsTheAreaPerPoint)
{
    // 40 000 uniform random points on a unit square: 1/200 apart on average per area, but
    // nearest neighbours only half that (1 / (2 sqrt(density))).
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    PointMatrix P(40000, 3);
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        P.row(i) << unit(rng), unit(rng), 0.0;
    }
    const Neighbourhoods N = nearestNeighbours(P, {16, 0});
    EXPECT_NEAR(meanSpacing(N), 0.5 / 200.0, 0.05 / 200.0);
    EXPECT_NEAR(samplingSpacing(N), 0.8 / 200.0, 0.08 / 200.0);
}

TEST(Neighbours, BadInputThrows)
{
    const PointMatrix P = randomCloud(10, 3);
    EXPECT_THROW(nearestNeighbours(P, {10, 0}), std::invalid_argument); // k == #P
    EXPECT_THROW(nearestNeighbours(P, {12, 0}), std::invalid_argument); // k > #P
    EXPECT_THROW(nearestNeighbours(P, {2, 0}), std::invalid_argument);  // k < 3
    EXPECT_NO_THROW(nearestNeighbours(P, {9, 0}));

    PointMatrix withNan = P;
    withNan(4, 1) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(nearestNeighbours(withNan, {3, 0}), std::invalid_argument);

    PointMatrix allSame(8, 3);
    allSame.setConstant(1.0);
    EXPECT_THROW(meanSpacing(nearestNeighbours(allSame, {3, 0})), std::invalid_argument);
}
