// SPDX-License-Identifier: LGPL-2.1-or-later
// The node graph and the hash grid over node centres.
#include "FeatureLines/network/NodeGraph.h"

#include <algorithm>
#include <functional>
#include <queue>

namespace featurelines::clustergraph {

NodeGrid::NodeGrid(const std::vector<Eigen::Vector3d>& centres, double cell)
    : centres_(centres), cell_(cell)
{
    for (int i = 0; i < static_cast<int>(centres.size()); ++i) {
        cells_[key(cellOf(centres[i]))].push_back(i);
    }
}

Eigen::Vector3i NodeGrid::cellOf(const Eigen::Vector3d& x) const
{
    return (x / cell_).array().floor().cast<int>();
}

std::int64_t NodeGrid::key(const Eigen::Vector3i& c)
{
    const auto part = [](int v) { return static_cast<std::int64_t>(v & 0x1FFFFF); };
    return (part(c.x()) << 42) | (part(c.y()) << 21) | part(c.z());
}

std::int64_t pairKey(int a, int b)
{
    if (b < a) {
        std::swap(a, b);
    }
    return (static_cast<std::int64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

bool Graph::hasEdge(int a, int b) const
{
    const auto& n = adjacency_[a];
    return std::find(n.begin(), n.end(), b) != n.end();
}

void Graph::addEdge(int a, int b)
{
    if (a == b || hasEdge(a, b)) {
        return;
    }
    adjacency_[a].push_back(b);
    adjacency_[b].push_back(a);
}

void Graph::removeEdge(int a, int b)
{
    auto drop = [](std::vector<int>& n, int v) {
        const auto at = std::find(n.begin(), n.end(), v);
        if (at != n.end()) {
            n.erase(at);
        }
    };
    drop(adjacency_[a], b);
    drop(adjacency_[b], a);
}

int Graph::addNode(const Eigen::Vector3d& centre)
{
    centres_.push_back(centre);
    adjacency_.emplace_back();
    return static_cast<int>(adjacency_.size()) - 1;
}

void Graph::isolate(int v)
{
    const std::vector<int> n = adjacency_[v];
    for (int u : n) {
        removeEdge(v, u);
    }
}

std::pair<std::vector<int>, double> Graph::chainFrom(int leaf, int first) const
{
    std::vector<int> chain{leaf};
    double length = 0.0;
    int previous = leaf;
    int current = first;
    while (true) {
        length += this->length(previous, current);
        chain.push_back(current);
        if (degree(current) != 2 || current == leaf) {
            break;
        }
        const int next =
            adjacency_[current][0] == previous ? adjacency_[current][1] : adjacency_[current][0];
        previous = current;
        current = next;
    }
    return {chain, length};
}

std::unordered_map<int, double> Graph::distancesFrom(int source, double limit) const
{
    std::unordered_map<int, double> distance{{source, 0.0}};
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    queue.push({0.0, source});
    while (!queue.empty()) {
        const auto [d, v] = queue.top();
        queue.pop();
        if (d > distance[v]) {
            continue;
        }
        for (int u : adjacency_[v]) {
            const double du = d + length(v, u);
            if (du > limit) {
                continue;
            }
            const auto known = distance.find(u);
            if (known == distance.end() || du < known->second) {
                distance[u] = du;
                queue.push({du, u});
            }
        }
    }
    return distance;
}

} // namespace featurelines::clustergraph
