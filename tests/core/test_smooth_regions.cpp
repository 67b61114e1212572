// SPDX-License-Identifier: LGPL-2.1-or-later
// Sec. 1.2: the cloud divided into smooth regions by its sharp lines. Every region must be one
// connected piece, and no region may reach across a sharp line.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "FeatureLines/Neighbours.h"
#include "FeatureLines/SmoothRegions.h"

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
    const SmoothRegions r = divideSmoothRegions(P, N, {}, candidate, meanSpacing(N));
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
    const SmoothRegions r = divideSmoothRegions(P, N, {sharp}, {}, spacing);
    ASSERT_EQ(r.count(), 2);
    const auto left = regionsOf(r, P, [](double x) { return x < 0.0; });
    const auto right = regionsOf(r, P, [](double x) { return x > 0.0; });
    ASSERT_EQ(left.size(), 1u);
    ASSERT_EQ(right.size(), 1u);
    EXPECT_NE(*left.begin(), *right.begin());
}
