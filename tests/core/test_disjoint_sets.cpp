// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "FeatureLines/support/DisjointSets.h"

using namespace featurelines;

namespace {

/// The edges of a w x h grid of nodes (node = row * w + column) between horizontal and
/// vertical neighbours, without the edges that cross column `cut` from its left: the grid
/// falls into two parts, columns [0, cut) and [cut, w).
std::vector<std::pair<int, int>> cutGridEdges(int w, int h, int cut)
{
    std::vector<std::pair<int, int>> edges;
    for (int r = 0; r < h; ++r) {
        for (int c = 0; c < w; ++c) {
            const int node = r * w + c;
            if (c + 1 < w && c + 1 != cut) {
                edges.emplace_back(node, node + 1);
            }
            if (r + 1 < h) {
                edges.emplace_back(node, node + w);
            }
        }
    }
    return edges;
}

std::vector<int> joinInParallel(int n, const std::vector<std::pair<int, int>>& edges, int threads)
{
    DisjointSets sets(n);
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads)
    for (long e = 0; e < static_cast<long>(edges.size()); ++e) {
        // Either end first: the sets must not depend on it.
        const auto [a, b] = edges[static_cast<size_t>(e)];
        if (e % 2 == 0) {
            sets.join(a, b);
        } else {
            sets.join(b, a);
        }
    }
    return sets.representatives();
}

} // namespace

TEST(DisjointSets, CutGridFallsIntoTwoPartsEachRepresentedByItsSmallestNode)
{
    const int w = 120, h = 90, cut = 50;
    std::vector<std::pair<int, int>> edges = cutGridEdges(w, h, cut);
    std::mt19937 generator(7);
    std::shuffle(edges.begin(), edges.end(), generator);
    for (int threads : {1, 2, 4}) {
        const std::vector<int> root = joinInParallel(w * h, edges, threads);
        for (int node = 0; node < w * h; ++node) {
            // The left part's smallest node is 0 (row 0, column 0), the right part's is node
            // `cut` (row 0, column cut).
            const int expected = node % w < cut ? 0 : cut;
            ASSERT_EQ(root[static_cast<size_t>(node)], expected)
                << "node " << node << " at " << threads << " threads";
        }
    }
}

TEST(DisjointSets, UntouchedElementsStaySingletons)
{
    // Only the even elements are chained: 0-2-4-...; the odd ones keep their own sets.
    const int n = 1001;
    std::vector<std::pair<int, int>> edges;
    for (int i = 2; i < n; i += 2) {
        edges.emplace_back(i, i - 2);
    }
    const std::vector<int> root = joinInParallel(n, edges, 2);
    for (int i = 0; i < n; ++i) {
        EXPECT_EQ(root[static_cast<size_t>(i)], i % 2 == 0 ? 0 : i) << "element " << i;
    }
}

TEST(DisjointSets, JoinReturnsAnElementOfTheJoinedSet)
{
    DisjointSets sets(10);
    EXPECT_EQ(sets.join(7, 3), 3);
    EXPECT_EQ(sets.join(9, 7), 3);
    EXPECT_EQ(sets.join(3, 9), 3); // already one set
    const int r = sets.join(1, 9);
    EXPECT_EQ(r, 1);
    for (int i : {1, 3, 7, 9}) {
        EXPECT_EQ(sets.find(i), 1);
    }
    for (int i : {0, 2, 4, 5, 6, 8}) {
        EXPECT_EQ(sets.find(i), i);
    }
}

TEST(DisjointSets, UniteTellsWhetherItJoinedTwoSets)
{
    DisjointSets sets(6);
    EXPECT_TRUE(sets.unite(4, 2));
    EXPECT_FALSE(sets.unite(2, 4));
    EXPECT_TRUE(sets.unite(5, 4));
    EXPECT_FALSE(sets.unite(5, 2));
    EXPECT_EQ(sets.find(5), 2);
    // On threads: every successful unite removes one set, so a grid cut in two parts sees
    // exactly nodes - 2 of them, whatever the threads' order.
    const int w = 120, h = 90, cut = 50;
    const std::vector<std::pair<int, int>> edges = cutGridEdges(w, h, cut);
    DisjointSets grid(w * h);
    long linked = 0;
#pragma omp parallel for schedule(dynamic, 64) num_threads(2) reduction(+ : linked)
    for (long e = 0; e < static_cast<long>(edges.size()); ++e) {
        const auto [a, b] = edges[static_cast<size_t>(e)];
        linked += grid.unite(a, b) ? 1 : 0;
    }
    EXPECT_EQ(linked, w * h - 2);
}

TEST(DisjointSets, EmptyAndNegativeSizes)
{
    EXPECT_TRUE(DisjointSets(0).representatives().empty());
    EXPECT_THROW(DisjointSets(-1), std::invalid_argument);
}
