// SPDX-License-Identifier: LGPL-2.1-or-later
// The joins of free ends on hand-made node graphs of unit spacing: a gap of 5 is reconnected,
// ends facing each other across 20 are joined, ends heading for a missing corner meet there, a
// stem pointing at a bar is extended to it.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "FeatureLines/network/FreeEndJoins.h"

using namespace featurelines;
using namespace featurelines::clustergraph;

namespace {

/// Straight chains of nodes one unit apart, and the graph of them.
struct Chains
{
    std::vector<Eigen::Vector3d> centres;
    std::vector<std::pair<int, int>> links;

    /// Nodes from a to b inclusive; returns the node at a.
    int add(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
    {
        const int first = static_cast<int>(centres.size());
        const int steps = static_cast<int>(std::lround((b - a).norm()));
        for (int i = 0; i <= steps; ++i) {
            centres.push_back(a + (b - a) * (static_cast<double>(i) / steps));
            if (i > 0) {
                links.emplace_back(first + i - 1, first + i);
            }
        }
        return first;
    }

    std::unique_ptr<Graph> graph()
    {
        auto g = std::make_unique<Graph>(centres, 1.0);
        for (const auto& [a, b] : links) {
            g->addEdge(a, b);
        }
        return g;
    }
};

} // namespace

TEST(FreeEndJoins, GapAheadIsReconnected)
{
    Chains c;
    c.add({0, 0, 0}, {9, 0, 0});
    const int far = c.add({15, 0, 0}, {24, 0, 0});
    auto g = c.graph();
    const int nodes = g->size();
    std::vector<int> labels(nodes, 0);
    EXPECT_EQ(reconnectEnds(*g, {}, labels, nullptr), 1);
    EXPECT_TRUE(g->hasEdge(9, far)) << "end to end: the two lines run straight on";
    EXPECT_EQ(g->size(), nodes) << "no corner node";
}

TEST(FreeEndJoins, EndsFacingEachOtherAcrossALongGapAreJoined)
{
    Chains c;
    c.add({0, 0, 0}, {9, 0, 0});
    const int far = c.add({30, 0, 0}, {39, 0, 0});
    auto g = c.graph();
    EXPECT_EQ(joinFacingEnds(*g, {}, nullptr), 1);
    EXPECT_TRUE(g->hasEdge(9, far));
}

TEST(FreeEndJoins, EndsHeadingForOneCornerMeetThere)
{
    // An L whose last 8 units before the corner (0, 0) are missing on both arms.
    Chains c;
    const int horizontal = c.add({8, 0, 0}, {20, 0, 0});
    const int vertical = c.add({0, 8, 0}, {0, 20, 0});
    auto g = c.graph();
    const int nodes = g->size();
    std::vector<int> labels(nodes, 3);
    EXPECT_EQ(joinConvergingEnds(*g, {}, labels, nullptr), 1);
    ASSERT_EQ(g->size(), nodes + 1) << "one node added, at the corner";
    const int corner = nodes;
    EXPECT_LT(g->centre(corner).norm(), 1e-12);
    EXPECT_TRUE(g->hasEdge(horizontal, corner));
    EXPECT_TRUE(g->hasEdge(vertical, corner));
    EXPECT_EQ(labels.back(), 3) << "the corner carries its line's label";
}

TEST(FreeEndJoins, StemPointingAtABarIsExtendedToIt)
{
    // A bar along x and a stem stopping 20 units above its middle.
    Chains c;
    const int bar = c.add({-20, 0, 0}, {20, 0, 0});
    const int stem = c.add({0, 20, 0}, {0, 40, 0});
    auto g = c.graph();
    EXPECT_EQ(extendFreeEnds(*g, {}, nullptr), 0) << "off by default";
    ClusterGraphOptions options;
    options.extendReach = 48.0;
    EXPECT_EQ(extendFreeEnds(*g, options, nullptr), 1);
    EXPECT_TRUE(g->hasEdge(stem, bar + 20)) << "to the bar's node right below the stem";
}
