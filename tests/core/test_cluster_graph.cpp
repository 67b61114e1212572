// SPDX-License-Identifier: LGPL-2.1-or-later
// The cluster graph on hand-made bands of candidate points whose lines are known: a square
// ring closes into one loop, a cross meets at one junction, a broken ring is reconnected, a
// spur is pruned, a line stopping short of another is extended to it (along supporting points
// only), free ends are removed up to a length, separate rings stay separate, a speck is
// dropped.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "FeatureLines/network/ClusterGraph.h"

using namespace featurelines;

namespace {

/// Points on a jittered grid of unit spacing in the plane z = 0, kept where `inside` holds.
template <class Inside> PointMatrix band(double extent, Inside inside, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    std::vector<Eigen::RowVector3d> kept;
    for (double x = -extent; x <= extent; x += 1.0) {
        for (double y = -extent; y <= extent; y += 1.0) {
            const Eigen::RowVector3d p(x + jitter(rng), y + jitter(rng), 0.0);
            if (inside(p.x(), p.y())) {
                kept.push_back(p);
            }
        }
    }
    PointMatrix P(static_cast<Eigen::Index>(kept.size()), 3);
    for (size_t i = 0; i < kept.size(); ++i) {
        P.row(i) = kept[i];
    }
    return P;
}

/// The square ring |max(|x|, |y|) - 15| < 1.5: a band three points wide around a square of
/// side 30.
bool squareRing(double x, double y)
{
    return std::abs(std::max(std::abs(x), std::abs(y)) - 15.0) < 1.5;
}

struct GraphRun
{
    ClusterGraph graph;
    double spacing;
};

/// Every point a candidate cluster of its own, as the boundary and Sec. 3 give them.
GraphRun runGraph(const PointMatrix& P, const ClusterGraphOptions& options = {})
{
    const Neighbourhoods N = nearestNeighbours(P);
    std::vector<int> cluster(P.rows());
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        cluster[i] = static_cast<int>(i);
    }
    const double spacing = meanSpacing(N);
    const std::vector<char> candidate(P.rows(), 1);
    return {buildClusterGraph({P, N, cluster, candidate, spacing}, options), spacing};
}

double polylineLength(const Polyline& line)
{
    double length = 0.0;
    const Eigen::Index m = line.points.rows();
    for (Eigen::Index i = 0; i + 1 < m; ++i) {
        length += (line.points.row(i + 1) - line.points.row(i)).norm();
    }
    if (line.closed && m > 1) {
        length += (line.points.row(0) - line.points.row(m - 1)).norm();
    }
    return length;
}

} // namespace

TEST(ClusterGraph, SquareRingBandBecomesOneClosedLoopOnItsCentreLine)
{
    const PointMatrix P = band(18.0, squareRing, 1);
    const GraphRun r = runGraph(P);
    ASSERT_EQ(r.graph.network.lines.size(), 1u);
    const Polyline& loop = r.graph.network.lines[0];
    EXPECT_TRUE(loop.closed);
    EXPECT_EQ(loop.startJunction, -1);
    EXPECT_EQ(r.graph.network.junctions.rows(), 0);
    EXPECT_EQ(r.graph.counts.freeEnds, 0);
    // The spanning tree breaks the ring once; reconnection closes it.
    EXPECT_GE(r.graph.counts.reconnections, 1);
    for (Eigen::Index i = 0; i < loop.points.rows(); ++i) {
        const double d = std::max(std::abs(loop.points(i, 0)), std::abs(loop.points(i, 1)));
        EXPECT_NEAR(d, 15.0, 2.0) << "vertex " << i << " strays from the band's centre line";
    }
    // Corners get cut by the smoothing a little (hence 2 above); the length stays near 4 x 30.
    EXPECT_NEAR(polylineLength(loop), 120.0, 8.0);
}

TEST(ClusterGraph, CrossMeetsAtOneJunction)
{
    const PointMatrix P = band(
        20.0,
        [](double x, double y) {
            return (std::abs(x) < 1.5 && std::abs(y) < 18.0) ||
                   (std::abs(y) < 1.5 && std::abs(x) < 18.0);
        },
        2);
    const GraphRun r = runGraph(P);
    ASSERT_EQ(r.graph.network.junctions.rows(), 1);
    EXPECT_LT(r.graph.network.junctions.row(0).norm(), 2.0) << "the junction is at the crossing";
    ASSERT_EQ(r.graph.network.lines.size(), 4u);
    for (const Polyline& line : r.graph.network.lines) {
        EXPECT_FALSE(line.closed);
        // One end on the junction, the other free: the arms end in nothing.
        EXPECT_TRUE((line.startJunction == 0) != (line.endJunction == 0));
        EXPECT_NEAR(polylineLength(line), 18.0, 3.0);
    }
}

TEST(ClusterGraph, GapInARingIsReconnected)
{
    // A gap of 5 spacings: wider than G_extended bridges, within the reconnection radius.
    const PointMatrix P = band(
        18.0,
        [](double x, double y) { return squareRing(x, y) && !(x > 10.0 && x < 15.5 && y > 0.0); },
        3);
    const GraphRun r = runGraph(P);
    ASSERT_EQ(r.graph.network.lines.size(), 1u);
    EXPECT_TRUE(r.graph.network.lines[0].closed);
    EXPECT_EQ(r.graph.counts.freeEnds, 0);
}

TEST(ClusterGraph, FacingEndsAcrossALongGapAreJoined)
{
    // A straight band broken for 20 spacings (as noise leaves a shallow crease): beyond the
    // reconnection radius, but the two ends face each other.
    const PointMatrix P = band(
        45.0,
        [](double x, double y) {
            return std::abs(y) < 1.0 && std::abs(x) < 42.0 && std::abs(x) > 9.0;
        },
        8);
    const GraphRun r = runGraph(P);
    ASSERT_EQ(r.graph.network.lines.size(), 1u);
    const Polyline& line = r.graph.network.lines[0];
    EXPECT_NEAR(std::abs(line.points(0, 0)), 41.0, 2.0);
    EXPECT_NEAR(std::abs(line.points(line.points.rows() - 1, 0)), 41.0, 2.0);
    EXPECT_LT(line.points.col(1).cwiseAbs().maxCoeff(), 1.5) << "straight across the gap";
}

TEST(ClusterGraph, EndsHeadingForOneCornerMeetThere)
{
    // Two arms of an L whose last 8 spacings before the corner (0, 0) left no candidates.
    const PointMatrix P = band(
        45.0,
        [](double x, double y) {
            const bool horizontal = std::abs(y) < 1.0 && x > 8.0 && x < 40.0;
            const bool vertical = std::abs(x) < 1.0 && y > 8.0 && y < 40.0;
            return horizontal || vertical;
        },
        9);
    const GraphRun r = runGraph(P);
    ASSERT_EQ(r.graph.network.lines.size(), 1u);
    const Polyline& line = r.graph.network.lines[0];
    double closest = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < line.points.rows(); ++i) {
        closest = std::min(closest, line.points.row(i).norm());
    }
    EXPECT_LT(closest, 2.0) << "the line turns at the corner, not across it";
}

TEST(ClusterGraph, ShortSpurIsPrunedLongBranchIsKept)
{
    // A ring with a spur 3 spacings long (pruned) and an arm 12 long (a real line).
    const PointMatrix P = band(
        30.0,
        [](double x, double y) {
            const bool spur = std::abs(y) < 1.0 && x > 16.0 && x < 19.5;
            const bool arm = std::abs(x) < 1.0 && y < -16.0 && y > -28.5;
            return squareRing(x, y) || spur || arm;
        },
        4);
    const GraphRun r = runGraph(P);
    EXPECT_GE(r.graph.counts.prunedBranches, 1);
    ASSERT_EQ(r.graph.network.junctions.rows(), 1) << "only the arm meets the ring";
    EXPECT_NEAR(r.graph.network.junctions(0, 1), -15.0, 2.0);
    EXPECT_NEAR(r.graph.network.junctions(0, 0), 0.0, 2.0);
}

TEST(ClusterGraph, FreeEndPointingAtALineIsExtendedToIt)
{
    // A T whose stem stops 19 spacings short of the bar: beyond the reconnection, facing no
    // other end, heading for no corner. Extended straight ahead, it ends on the bar.
    const PointMatrix P = band(
        50.0,
        [](double x, double y) {
            const bool bar = std::abs(y) < 1.0 && std::abs(x) < 40.0;
            const bool stem = std::abs(x) < 1.0 && y > 20.0 && y < 44.0;
            return bar || stem;
        },
        10);
    EXPECT_EQ(runGraph(P).graph.network.junctions.rows(), 0) << "off by default";
    ClusterGraphOptions options;
    options.extendReach = 48.0;
    const GraphRun r = runGraph(P, options);
    EXPECT_EQ(r.graph.counts.extensions, 1);
    ASSERT_EQ(r.graph.network.junctions.rows(), 1);
    EXPECT_LT(r.graph.network.junctions.row(0).norm(), 2.0) << "the stem meets the bar below it";
    EXPECT_EQ(r.graph.network.lines.size(), 3u);
}

TEST(ClusterGraph, ExtensionRunsOnlyAlongSupportingPoints)
{
    // The same T with points in the gap that are no candidates: the stem is extended across
    // the gap only when they are marked as supporting (as a crease's bending normals mark
    // them), never across points that are not.
    const PointMatrix P = band(
        50.0,
        [](double x, double y) {
            const bool bar = std::abs(y) < 1.0 && std::abs(x) < 40.0;
            const bool stemAndGap = std::abs(x) < 1.0 && y > 0.0 && y < 44.0;
            return bar || stemAndGap;
        },
        11);
    const Neighbourhoods N = nearestNeighbours(P);
    std::vector<int> cluster(P.rows());
    std::vector<char> candidate(P.rows()), gap(P.rows()), none(P.rows(), 0);
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        cluster[i] = static_cast<int>(i);
        gap[i] = std::abs(P(i, 1)) >= 1.0 && P(i, 1) <= 20.0 ? 1 : 0;
        candidate[i] = gap[i] ? 0 : 1;
    }
    ClusterGraphOptions options;
    options.extendReach = 48.0;
    const double spacing = meanSpacing(N);
    const ClusterGraph across =
        buildClusterGraph({P, N, cluster, candidate, spacing, nullptr, &gap}, options);
    EXPECT_EQ(across.network.junctions.rows(), 1);
    const ClusterGraph refused =
        buildClusterGraph({P, N, cluster, candidate, spacing, nullptr, &none}, options);
    EXPECT_EQ(refused.network.junctions.rows(), 0);
    EXPECT_EQ(refused.counts.extensions, 0);
}

TEST(ClusterGraph, ArcBrokenOverAGapCloses)
{
    // A circular band of radius 40 whose candidates are missing over 32 units of arc (a
    // hole's rim where noise left none), the points there marked as supporting: the two ends
    // meet the chord at 23 degrees each and join along the curve they continue into each other
    // on, though the chord cuts the bend by 3 units, beyond the supporting band.
    const double radius = 40.0;
    const PointMatrix P = band(
        45.0, [&](double x, double y) { return std::abs(std::hypot(x, y) - radius) < 1.0; }, 13);
    const Neighbourhoods N = nearestNeighbours(P);
    std::vector<int> cluster(P.rows());
    std::vector<char> candidate(P.rows()), gap(P.rows());
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        cluster[i] = static_cast<int>(i);
        gap[i] = P(i, 0) > 0.0 && std::abs(std::atan2(P(i, 1), P(i, 0))) < 0.4 ? 1 : 0;
        candidate[i] = gap[i] ? 0 : 1;
    }
    ClusterGraphOptions options;
    options.extendReach = 48.0;
    const ClusterGraph g =
        buildClusterGraph({P, N, cluster, candidate, meanSpacing(N), nullptr, &gap}, options);
    ASSERT_EQ(g.network.lines.size(), 1u);
    EXPECT_TRUE(g.network.lines[0].closed);
    EXPECT_EQ(g.counts.freeEnds, 0);
}

TEST(ClusterGraph, FreeEndsThatReachNothingAreRemovedUpToALength)
{
    // A ring with an arm 20 spacings long, then 60 long, both ending in nothing: with
    // maxFreeEndLength 48 the short arm goes (the ring is left closed), the long one stays.
    for (const double length : {20.0, 60.0}) {
        const PointMatrix P = band(
            80.0,
            [length](double x, double y) {
                const bool arm = std::abs(y) < 1.0 && x > 16.0 && x < 16.0 + length;
                return squareRing(x, y) || arm;
            },
            12);
        ClusterGraphOptions options;
        options.maxFreeEndLength = 48.0;
        const GraphRun r = runGraph(P, options);
        SCOPED_TRACE("arm of " + std::to_string(length));
        if (length < 48.0) {
            EXPECT_EQ(r.graph.counts.removedFreeEnds, 1);
            ASSERT_EQ(r.graph.network.lines.size(), 1u);
            EXPECT_TRUE(r.graph.network.lines[0].closed);
            EXPECT_EQ(r.graph.counts.freeEnds, 0);
        } else {
            EXPECT_EQ(r.graph.counts.removedFreeEnds, 0);
            EXPECT_EQ(r.graph.network.junctions.rows(), 1);
            EXPECT_EQ(r.graph.counts.freeEnds, 1);
        }
    }
}

TEST(ClusterGraph, SeparateRingsStaySeparateAndSpecksAreDropped)
{
    const PointMatrix P = band(
        60.0,
        [](double x, double y) {
            const bool left = squareRing(x + 30.0, y);
            const bool right = squareRing(x - 30.0, y);
            const bool speck = std::abs(x) < 1.5 && std::abs(y - 40.0) < 1.5;
            return left || right || speck;
        },
        5);
    const GraphRun r = runGraph(P);
    ASSERT_EQ(r.graph.network.lines.size(), 2u);
    EXPECT_TRUE(r.graph.network.lines[0].closed);
    EXPECT_TRUE(r.graph.network.lines[1].closed);
    EXPECT_GE(r.graph.counts.droppedComponents, 1);
    EXPECT_NE(r.graph.network.lines[0].points(0, 0) > 0, r.graph.network.lines[1].points(0, 0) > 0);
}

TEST(ClusterGraph, ClustersWithoutCandidatesAreLeftOutAndLabelsCarryOver)
{
    // Two rings; the right one's points belong to non-candidate clusters, the left one's to
    // candidates labelled 7.
    const PointMatrix P = band(
        60.0, [](double x, double y) { return squareRing(x + 30.0, y) || squareRing(x - 30.0, y); },
        6);
    const Neighbourhoods N = nearestNeighbours(P);
    std::vector<int> cluster(P.rows());
    std::vector<char> candidate(P.rows());
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        cluster[i] = static_cast<int>(i);
        candidate[i] = P(i, 0) < 0.0 ? 1 : 0;
    }
    const std::vector<int> labels(P.rows(), 7);
    const ClusterGraph g = buildClusterGraph({P, N, cluster, candidate, meanSpacing(N), &labels});
    ASSERT_EQ(g.network.lines.size(), 1u);
    EXPECT_EQ(g.network.lines[0].label, 7);
    EXPECT_LT(g.network.lines[0].points.col(0).maxCoeff(), 0.0);
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        if (!candidate[i]) {
            EXPECT_EQ(g.nodeOfPoint[i], -1);
        }
    }
}

TEST(ClusterGraph, BadInputThrows)
{
    const PointMatrix P = band(
        5.0, [](double, double) { return true; }, 7);
    const Neighbourhoods N = nearestNeighbours(P);
    const std::vector<char> candidate(P.rows(), 1);
    std::vector<int> cluster(P.rows(), 0);
    const std::vector<int> threeClusterIds(3, 0), twoLabels(2, 0);
    const std::vector<char> twoFlags(2, 0), noCandidate(P.rows(), 0);
    EXPECT_THROW(buildClusterGraph({P, N, threeClusterIds, candidate, 1.0}), std::invalid_argument);
    cluster[2] = static_cast<int>(P.rows()); // no such cluster
    EXPECT_THROW(buildClusterGraph({P, N, cluster, candidate, 1.0}), std::invalid_argument);
    cluster[2] = 0;
    EXPECT_THROW(buildClusterGraph({P, N, cluster, candidate, 0.0}), std::invalid_argument);
    EXPECT_THROW(buildClusterGraph({P, N, cluster, candidate, 1.0, &twoLabels}),
                 std::invalid_argument);
    EXPECT_THROW(buildClusterGraph({P, N, cluster, candidate, 1.0, nullptr, &twoFlags}),
                 std::invalid_argument);
    // Nothing marked as candidate: an empty network, no crash.
    const ClusterGraph none = buildClusterGraph({P, N, cluster, noCandidate, 1.0});
    EXPECT_TRUE(none.network.lines.empty());
}
