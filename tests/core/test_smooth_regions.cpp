// SPDX-License-Identifier: LGPL-2.1-or-later
// Sec. 1.2: the cloud divided into smooth regions by its sharp lines. Every region must be one
// connected piece, no region may reach across a sharp line, and every region point keeps a
// neighbourhood inside its region (the k-nearest-neighbour rows its curvature is fitted over).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/smooth/RegionNeighbourhoods.h"
#include "FeatureLines/smooth/SmoothRegions.h"

using namespace featurelines;

namespace {

void addGrid(std::vector<Eigen::RowVector3d>& points, double x0, double x1, double y0, double y1,
             double step)
{
    for (double x = x0; x <= x1 + 1e-9; x += step) {
        for (double y = y0; y <= y1 + 1e-9; y += step) {
            points.emplace_back(x, y, 0.0);
        }
    }
}

PointMatrix toMatrix(const std::vector<Eigen::RowVector3d>& points)
{
    PointMatrix P(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i) {
        P.row(static_cast<Eigen::Index>(i)) = points[i];
    }
    return P;
}

std::set<int> regionsOf(const SmoothRegions& r, const PointMatrix& P, bool (*where)(double x))
{
    std::set<int> ids;
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        if (where(P(i, 0)) && r.region[static_cast<size_t>(i)] >= 0) {
            ids.insert(r.region[static_cast<size_t>(i)]);
        }
    }
    return ids;
}

/// Neighbourhoods of k = 8 given row by row; the squared distances grow along each row.
Neighbourhoods handMade(const std::vector<std::vector<int>>& rows)
{
    Neighbourhoods N;
    N.indices.resize(static_cast<Eigen::Index>(rows.size()), 8);
    N.squaredDistances.resize(static_cast<Eigen::Index>(rows.size()), 8);
    for (size_t i = 0; i < rows.size(); ++i) {
        for (int j = 0; j < 8; ++j) {
            N.indices(static_cast<Eigen::Index>(i), j) = rows[i][static_cast<size_t>(j)];
            N.squaredDistances(static_cast<Eigen::Index>(i), j) = 1.0 + j;
        }
    }
    return N;
}

} // namespace

// Two squares whose gap is all sharp candidates but for one row of points: the row joins them
// while the components are grown, but its points see too few of their own region (most of
// their neighbours are candidates) and leave it. What they joined is then two regions, not one
// region in two pieces.
TEST(SmoothRegions, ARegionIsConnectedAfterItsThinPointsLeave)
{
    std::vector<Eigen::RowVector3d> points;
    addGrid(points, -30.0, 30.0, 0.0, 20.0, 1.0);
    const PointMatrix P = toMatrix(points);
    std::vector<char> candidate(points.size(), 0);
    for (size_t i = 0; i < points.size(); ++i) {
        candidate[i] = std::abs(points[i].x()) < 9.5 && std::abs(points[i].y() - 10.0) > 0.5;
    }
    const Neighbourhoods N = nearestNeighbours(P);
    const SmoothRegions r = divideSmoothRegions({P, N, {}, candidate, meanSpacing(N)});
    ASSERT_EQ(r.count(), 2);
    const auto left = regionsOf(r, P, [](double x) { return x < -9.5; });
    const auto right = regionsOf(r, P, [](double x) { return x > 9.5; });
    ASSERT_EQ(left.size(), 1u);
    ASSERT_EQ(right.size(), 1u);
    EXPECT_NE(*left.begin(), *right.begin());
    EXPECT_EQ(r.region[static_cast<size_t>(30 * 21 + 10)], -1) << "the row's middle point";
}

// Where the sampling is sparse a point's k nearest neighbours reach farther than the band
// around a sharp line is wide: two rows of points 2.6 spacings either side of a sharp line
// along x = 0 see each other (16 neighbours on a row reach 8 spacings along it). They lie
// off the band, but the edges between them cross it: two regions.
TEST(SmoothRegions, ALongNeighbourEdgeDoesNotJumpTheBand)
{
    std::vector<Eigen::RowVector3d> points;
    for (double y = 0.0; y <= 60.0; y += 1.0) {
        points.emplace_back(-2.6, y, 0.0);
        points.emplace_back(2.6, y, 0.0);
    }
    const PointMatrix P = toMatrix(points);
    const Neighbourhoods N = nearestNeighbours(P);
    const double spacing = meanSpacing(N);
    ASSERT_NEAR(spacing, 1.0, 1e-9);
    bool crosses = false;
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        for (int j = 0; j < N.k(); ++j) {
            crosses = crosses || P(i, 0) * P(N.indices(i, j), 0) < 0.0;
        }
    }
    ASSERT_TRUE(crosses) << "the rows must see each other for the test to mean anything";
    Polyline sharp;
    sharp.points.resize(2, 3);
    sharp.points << 0.0, -5.0, 0.0, 0.0, 65.0, 0.0;
    const SmoothRegions r = divideSmoothRegions({P, N, {sharp}, {}, spacing});
    ASSERT_EQ(r.count(), 2);
    const auto left = regionsOf(r, P, [](double x) { return x < 0.0; });
    const auto right = regionsOf(r, P, [](double x) { return x > 0.0; });
    ASSERT_EQ(left.size(), 1u);
    ASSERT_EQ(right.size(), 1u);
    EXPECT_NE(*left.begin(), *right.begin());
}

TEST(SmoothRegions, PointLeftWithoutARegionNeighbourJoinsTheBand)
{
    // Point 0 sees eight eligible points 1..8 (enough at first); each of those sees point 0
    // and seven candidates 9..15 of the sharp stage, so all eight join the band and point 0 is
    // left with no neighbour in its region. Points 16..24 see only one another: a region.
    std::vector<std::vector<int>> rows(25);
    rows[0] = {1, 2, 3, 4, 5, 6, 7, 8};
    for (int i = 1; i <= 8; ++i) {
        rows[i] = {0, 9, 10, 11, 12, 13, 14, 15};
    }
    for (int i = 9; i <= 15; ++i) {
        rows[i] = {0, 1, 2, 3, 4, 5, 6, 7};
    }
    for (int i = 16; i <= 24; ++i) {
        for (int j = 16; j <= 24; ++j) {
            if (j != i) {
                rows[i].push_back(j);
            }
        }
    }
    const Neighbourhoods N = handMade(rows);
    PointMatrix P = PointMatrix::Zero(25, 3);
    for (Eigen::Index i = 0; i < 25; ++i) {
        P(i, 0) = static_cast<double>(i);
    }
    std::vector<char> candidate(25, 0);
    for (int i = 9; i <= 15; ++i) {
        candidate[static_cast<size_t>(i)] = 1;
    }
    SmoothRegionOptions options;
    options.minRegionNeighbours = 5;
    options.minRegionPoints = 1;
    const SmoothRegions regions = divideSmoothRegions({P, N, {}, candidate, 1.0}, options);

    EXPECT_EQ(regions.region[0], -1) << "a point with no neighbour in its region";
    ASSERT_EQ(regions.count(), 1);
    EXPECT_EQ(regions.members[0].size(), 9u);
    EXPECT_EQ(regions.members[0].front(), 16);
    // Every region has its neighbourhoods (this threw for point 0 before).
    for (int r = 0; r < regions.count(); ++r) {
        EXPECT_NO_THROW(regionNeighbourhoods(N, regions.region, regions.members[r], r));
    }
}
