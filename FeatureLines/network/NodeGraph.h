// SPDX-License-Identifier: LGPL-2.1-or-later
// The node graph every step of the cluster graph edits, and a hash grid over node centres for
// its radius queries. Internal to the network stage (docs/design/network.md).
#pragma once

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace featurelines::clustergraph {

/// A uniform hash grid over the node centres, for the radius queries of G_extended and of
/// the joins (a few thousand nodes: no tree needed).
class NodeGrid
{
public:
    NodeGrid(const std::vector<Eigen::Vector3d>& centres, double cell);

    /// Calls f(i) for every centre i within `radius` (<= the cell size) of x.
    template <class F> void forEachWithin(const Eigen::Vector3d& x, double radius, F f) const
    {
        const Eigen::Vector3i c = cellOf(x);
        const double r2 = radius * radius;
        for (int dx = -1; dx <= 1; ++dx) {
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto found = cells_.find(key(c + Eigen::Vector3i(dx, dy, dz)));
                    if (found == cells_.end()) {
                        continue;
                    }
                    for (int i : found->second) {
                        if ((centres_[i] - x).squaredNorm() <= r2) {
                            f(i);
                        }
                    }
                }
            }
        }
    }

private:
    Eigen::Vector3i cellOf(const Eigen::Vector3d& x) const;
    static std::int64_t key(const Eigen::Vector3i& c);

    const std::vector<Eigen::Vector3d>& centres_;
    double cell_;
    std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

/// One key for the unordered pair {a, b}.
std::int64_t pairKey(int a, int b);

/// The node graph with the operations the steps need. Nodes are never renumbered: a removed
/// node simply has no edge left.
class Graph
{
public:
    Graph(std::vector<Eigen::Vector3d>& centres, double spacing)
        : centres_(centres), adjacency_(centres.size()), spacing_(spacing)
    {
    }

    int size() const { return static_cast<int>(adjacency_.size()); }
    int degree(int v) const { return static_cast<int>(adjacency_[v].size()); }
    const std::vector<int>& neighbours(int v) const { return adjacency_[v]; }
    const Eigen::Vector3d& centre(int v) const { return centres_[v]; }
    double length(int a, int b) const { return (centres_[a] - centres_[b]).norm(); }
    double spacing() const { return spacing_; }
    std::vector<Eigen::Vector3d>& centres() { return centres_; }

    bool hasEdge(int a, int b) const;
    void addEdge(int a, int b);
    void removeEdge(int a, int b);
    /// A node with no points of its own (where the lines of free ends meet).
    int addNode(const Eigen::Vector3d& centre);
    /// Removes every edge of v.
    void isolate(int v);

    /// From the free end `leaf`, the chain of degree-2 nodes up to the first node of another
    /// degree: returns the nodes (leaf first, that node last) and the chain's length.
    std::pair<std::vector<int>, double> chainFrom(int leaf, int first) const;

    /// Shortest path lengths from `source` along the graph, up to `limit`; nodes farther away
    /// are absent from the map.
    std::unordered_map<int, double> distancesFrom(int source, double limit) const;

private:
    std::vector<Eigen::Vector3d>& centres_;
    std::vector<std::vector<int>> adjacency_;
    double spacing_;
};

} // namespace featurelines::clustergraph
