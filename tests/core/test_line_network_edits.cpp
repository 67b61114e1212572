// SPDX-License-Identifier: LGPL-2.1-or-later
// LineNetworkEdits.h: the line-end processing on hand-made networks.
#include <gtest/gtest.h>

#include <initializer_list>
#include <vector>

#include "FeatureLines/network/LineNetworkEdits.h"

using namespace featurelines;

namespace {

Polyline line(std::initializer_list<Eigen::RowVector3d> vertices, int start = -1, int end = -1)
{
    Polyline l;
    l.points.resize(static_cast<Eigen::Index>(vertices.size()), 3);
    Eigen::Index i = 0;
    for (const Eigen::RowVector3d& v : vertices) {
        l.points.row(i++) = v;
    }
    l.startJunction = start;
    l.endJunction = end;
    return l;
}

Polyline straight(const Eigen::RowVector3d& a, const Eigen::RowVector3d& b, int start = -1,
                  int end = -1)
{
    return line({a, 0.5 * (a + b), b}, start, end);
}

} // namespace

TEST(LineNetworkEdits, FreeEndsAreAnchoredOnTheLineAheadOnly)
{
    LineNetwork network;
    network.lines.push_back(straight({0, 0, 0}, {10, 0, 0}));     // heads for x = 13
    network.lines.push_back(straight({0, 20, 0}, {10, 20, 0}));   // too far: 12 away
    network.lines.push_back(straight({14, -10, 0}, {14, -4, 0})); // beside the anchor's end
    const std::vector<Polyline> anchors{straight({13, -2, 0}, {13, 8, 0}),
                                        straight({30, 5, 0}, {30, 6, 0})};
    const std::vector<char> anchored = anchorLineEnds(network, anchors, 5.0, 90.0);
    ASSERT_EQ(anchored.size(), 6u);
    EXPECT_FALSE(anchored[0]);
    EXPECT_TRUE(anchored[1]);
    const Polyline& first = network.lines[0];
    EXPECT_TRUE(first.points.bottomRows(1).isApprox(Eigen::RowVector3d(13, 0, 0)));
    EXPECT_FALSE(anchored[2] || anchored[3]);
    // Its end at (14, -4) is 2.2 from the anchor's end (13, -2), to the side but ahead of it:
    // taken. Its start at (14, -10) is 8 from it: not.
    EXPECT_FALSE(anchored[4]);
    EXPECT_TRUE(anchored[5]);
}

TEST(LineNetworkEdits, ShortSpursArePrunedAndTheirLoopClosed)
{
    // A loop leaving junction 0 and returning to it, a spur of 4 from it to nothing, and a
    // long branch of 30 from it to nothing.
    LineNetwork network;
    network.junctions.resize(1, 3);
    network.junctions.row(0) << 0, 0, 0;
    network.lines.push_back(
        line({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {0, 0, 0}}, 0, 0));
    network.lines.push_back(straight({0, 0, 0}, {-4, 0, 0}, 0, -1));
    std::vector<char> anchored(4, 0);
    EXPECT_EQ(pruneDanglingLines(network, anchored, 15.0), 1);
    ASSERT_EQ(network.lines.size(), 1u);
    EXPECT_TRUE(network.lines[0].closed);
    EXPECT_EQ(network.lines[0].points.rows(), 4)
        << "a closed line does not repeat its first vertex";
    EXPECT_EQ(network.lines[0].startJunction, -1);

    // The same spur anchored on another line is part of the network: kept.
    LineNetwork kept;
    kept.junctions = network.junctions;
    kept.lines.push_back(line({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {0, 0, 0}}, 0, 0));
    kept.lines.push_back(straight({0, 0, 0}, {-4, 0, 0}, 0, -1));
    std::vector<char> spurAnchored{0, 0, 0, 1};
    EXPECT_EQ(pruneDanglingLines(kept, spurAnchored, 15.0), 0);
    EXPECT_EQ(kept.lines.size(), 2u);
}

TEST(LineNetworkEdits, ShortOpenPiecesGoUnlessBothEndsAreOnLines)
{
    LineNetwork network;
    network.lines.push_back(straight({0, 0, 0}, {10, 0, 0}));   // short, free: dropped
    network.lines.push_back(straight({0, 5, 0}, {10, 5, 0}));   // short, anchored both ends
    network.lines.push_back(straight({0, 10, 0}, {30, 10, 0})); // long enough
    const std::vector<char> anchored{0, 0, 1, 1, 0, 0};
    EXPECT_EQ(dropOpenPieces(network, anchored, 15.0), 1);
    ASSERT_EQ(network.lines.size(), 2u);
    EXPECT_DOUBLE_EQ(network.lines[0].points(0, 1), 5.0);
    EXPECT_DOUBLE_EQ(network.lines[1].points(0, 1), 10.0);
}

TEST(LineNetworkEdits, DroppingALineJoinsTheTwoLeftAtItsJunction)
{
    // Junction 0 at the origin joins a, b and c; junction 1 at (20, 0) joins b, d and e.
    // Dropping c leaves junction 0 with two line ends: a and b become one line, which ends at
    // the remaining junction, renumbered 0. a's start is anchored: the flag follows the line.
    LineNetwork network;
    network.junctions.resize(2, 3);
    network.junctions << 0, 0, 0, 20, 0, 0;
    network.lines.push_back(straight({-10, 0, 0}, {0, 0, 0}, -1, 0));  // a
    network.lines.push_back(straight({0, 0, 0}, {20, 0, 0}, 0, 1));    // b
    network.lines.push_back(straight({0, 0, 0}, {0, 10, 0}, 0, -1));   // c
    network.lines.push_back(straight({20, 0, 0}, {20, 10, 0}, 1, -1)); // d
    network.lines.push_back(straight({20, 0, 0}, {30, 0, 0}, 1, -1));  // e
    std::vector<char> anchored{1, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    dropLines(network, anchored, {0, 0, 1, 0, 0});
    ASSERT_EQ(network.lines.size(), 3u);
    ASSERT_EQ(network.junctions.rows(), 1);
    EXPECT_TRUE(network.junctions.row(0).isApprox(Eigen::RowVector3d(20, 0, 0)));
    const Polyline& ab = network.lines[0];
    EXPECT_FALSE(ab.closed);
    ASSERT_EQ(ab.points.rows(), 5) << "3 + 3 vertices, the junction's once";
    EXPECT_TRUE(ab.points.row(0).isApprox(Eigen::RowVector3d(-10, 0, 0)));
    EXPECT_TRUE(ab.points.row(4).isApprox(Eigen::RowVector3d(20, 0, 0)));
    EXPECT_EQ(ab.startJunction, -1);
    EXPECT_EQ(ab.endJunction, 0);
    EXPECT_EQ(network.lines[1].startJunction, 0);
    EXPECT_EQ(network.lines[2].startJunction, 0);
    EXPECT_EQ(anchored, (std::vector<char>{1, 0, 0, 0, 0, 0}));
}
