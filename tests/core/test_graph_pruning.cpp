// SPDX-License-Identifier: LGPL-2.1-or-later
// The cutting steps of the cluster graph on hand-made node graphs of unit spacing whose answer
// is exact: a spur cut, a bubble dropped, two close junctions merged, a speck dropped, a free
// end removed.
#include <gtest/gtest.h>

#include "FeatureLines/network/GraphPruning.h"

using namespace featurelines::clustergraph;

namespace {

/// Nodes at the given points, edges between consecutive ones of each path.
struct HandGraph
{
    std::vector<Eigen::Vector3d> centres;
    Graph graph;

    explicit HandGraph(std::vector<Eigen::Vector3d> points)
        : centres(std::move(points)), graph(centres, 1.0)
    {
    }

    void path(std::initializer_list<int> nodes)
    {
        const std::vector<int> v(nodes);
        for (std::size_t i = 0; i + 1 < v.size(); ++i) {
            graph.addEdge(v[i], v[i + 1]);
        }
    }
};

/// Nodes 0 .. n-1 at (0, 0), (1, 0), ..., (n-1, 0).
std::vector<Eigen::Vector3d> row(int n)
{
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < n; ++i) {
        points.emplace_back(i, 0.0, 0.0);
    }
    return points;
}

} // namespace

TEST(GraphPruning, ShortSpurIsCutLongArmsStay)
{
    // A row of 21 nodes with a spur of 2 nodes up from node 10.
    std::vector<Eigen::Vector3d> points = row(21);
    points.emplace_back(10.0, 1.0, 0.0); // 21
    points.emplace_back(10.0, 2.0, 0.0); // 22
    HandGraph h(points);
    for (int i = 0; i < 20; ++i) {
        h.graph.addEdge(i, i + 1);
    }
    h.path({10, 21, 22});
    EXPECT_EQ(pruneShortBranches(h.graph, 6.0), 1);
    EXPECT_EQ(h.graph.degree(21), 0);
    EXPECT_EQ(h.graph.degree(22), 0);
    EXPECT_EQ(h.graph.degree(10), 2);
    EXPECT_EQ(h.graph.degree(0), 1);
    EXPECT_EQ(h.graph.degree(20), 1);
}

TEST(GraphPruning, LongerOfTwoShortParallelChainsIsDropped)
{
    // Junctions 0 and 4 (each with an arm out) joined straight along y = 0 and by a detour
    // through y = 1.
    HandGraph h({{0, 0, 0},
                 {1, 0, 0},
                 {2, 0, 0},
                 {3, 0, 0},
                 {4, 0, 0},
                 {0, 1, 0},
                 {1, 1, 0},
                 {2, 1, 0},
                 {3, 1, 0},
                 {4, 1, 0},
                 {-10, 0, 0},
                 {14, 0, 0}});
    h.path({0, 1, 2, 3, 4});
    h.path({0, 5, 6, 7, 8, 9, 4});
    h.path({10, 0});
    h.path({4, 11});
    EXPECT_EQ(removeBubbles(h.graph, 18.0), 1);
    for (int v : {6, 7, 8}) {
        EXPECT_EQ(h.graph.degree(v), 0) << "node " << v << " of the detour";
    }
    EXPECT_EQ(h.graph.degree(2), 2) << "the straight chain stays";
}

TEST(GraphPruning, CloseJunctionsBecomeOneAtTheirMean)
{
    // Two forks one spacing apart: 0 - 1 - 2 - 3 along x with arms up and down at 1 and 2.
    HandGraph h({{-10, 0, 0}, {0, 0, 0}, {1, 0, 0}, {11, 0, 0}, {0, 10, 0}, {1, -10, 0}});
    h.path({0, 1, 2, 3});
    h.path({1, 4});
    h.path({2, 5});
    EXPECT_EQ(mergeCloseJunctions(h.graph, 3.0), 1);
    EXPECT_EQ(h.graph.degree(1), 4);
    EXPECT_EQ(h.graph.degree(2), 0);
    EXPECT_DOUBLE_EQ(h.graph.centre(1).x(), 0.5);
}

TEST(GraphPruning, ShortPiecesAreDroppedOpenOnesUpToTheirOwnLength)
{
    // A speck of length 2, an open line of length 10, a square loop of perimeter 12.
    HandGraph h({{0, 0, 0},
                 {1, 0, 0},
                 {2, 0, 0},
                 {0, 5, 0},
                 {10, 5, 0},
                 {0, 9, 0},
                 {3, 9, 0},
                 {3, 12, 0},
                 {0, 12, 0}});
    h.path({0, 1, 2});
    h.path({3, 4});
    h.path({5, 6, 7, 8, 5});
    EXPECT_EQ(dropShortComponents(h.graph, 6.0, 15.0), 2);
    EXPECT_EQ(h.graph.degree(1), 0);
    EXPECT_EQ(h.graph.degree(3), 0);
    EXPECT_EQ(h.graph.degree(5), 2) << "the loop has a cycle and length 12 >= 6";
}

TEST(GraphPruning, FreeEndsAreRemovedUpToALength)
{
    // A loop with an arm of length 3 ending in nothing.
    HandGraph h({{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {0, 3, 0}, {-3, 0, 0}});
    h.path({0, 1, 2, 3, 0});
    h.path({0, 4});
    EXPECT_EQ(removeFreeEnds(h.graph, 2.0), 0) << "longer than the limit";
    EXPECT_EQ(removeFreeEnds(h.graph, 3.0), 1);
    EXPECT_EQ(h.graph.degree(4), 0);
    EXPECT_EQ(h.graph.degree(0), 2);
}
