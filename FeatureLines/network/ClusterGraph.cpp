// SPDX-License-Identifier: LGPL-2.1-or-later
// buildClusterGraph as the steps of the 2007 paper: nodes, G_all, G_extended, pruned MST, then
// the pruning and joining steps, then the lines read off.
#include "FeatureLines/network/ClusterGraph.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "FeatureLines/network/FreeEndJoins.h"
#include "FeatureLines/network/GraphPruning.h"
#include "FeatureLines/network/NodeGraph.h"
#include "FeatureLines/support/DisjointSets.h"

namespace featurelines {

using namespace clustergraph;

namespace {

/// The input with its optional parts read (empty when not given).
struct Input
{
    const ClusterGraphInput& in;
    const std::vector<int>& clusterLabel;
    const std::vector<char>& supportingPoint;

    Eigen::Index points() const { return in.points.rows(); }
    int clusters() const { return static_cast<int>(in.candidateCluster.size()); }
    bool isCandidate(Eigen::Index i) const
    {
        return in.cluster[i] >= 0 && in.candidateCluster[in.cluster[i]] != 0;
    }
    int labelOf(int c) const { return clusterLabel.empty() ? 0 : clusterLabel[c]; }
};

void checkInput(const Input& input)
{
    const ClusterGraphInput& in = input.in;
    const Eigen::Index n = input.points();
    if (in.neighbours.size() != n || static_cast<Eigen::Index>(in.cluster.size()) != n) {
        throw std::invalid_argument(
            "cluster graph: the neighbourhoods and cluster ids must have one row per point (" +
            std::to_string(n) + " points, " + std::to_string(in.neighbours.size()) +
            " neighbourhoods, " + std::to_string(in.cluster.size()) + " cluster ids)");
    }
    if (!(in.spacing > 0.0) || !std::isfinite(in.spacing)) {
        throw std::invalid_argument("cluster graph: the point spacing must be a positive number");
    }
    const int clusterCount = input.clusters();
    if (!input.supportingPoint.empty() &&
        static_cast<Eigen::Index>(input.supportingPoint.size()) != n) {
        throw std::invalid_argument("cluster graph: the supporting-point flags must have one "
                                    "entry per point");
    }
    if (!input.clusterLabel.empty() &&
        static_cast<int>(input.clusterLabel.size()) != clusterCount) {
        throw std::invalid_argument("cluster graph: one label per cluster is needed (" +
                                    std::to_string(input.clusterLabel.size()) + " labels for " +
                                    std::to_string(clusterCount) + " clusters)");
    }
    for (Eigen::Index i = 0; i < n; ++i) {
        if (in.cluster[i] < -1 || in.cluster[i] >= clusterCount) {
            throw std::invalid_argument("cluster graph: point " + std::to_string(i) +
                                        " has cluster id " + std::to_string(in.cluster[i]) +
                                        ", outside 0.." + std::to_string(clusterCount - 1));
        }
    }
}

/// The candidate clusters: the points of cluster c are members[start[c] .. start[c + 1]).
struct CandidateClusters
{
    std::vector<int> start;
    std::vector<int> members;
    std::vector<Eigen::Vector3d> centre;
    /// pairKey() of the candidate clusters adjacent through the k nearest neighbours of their
    /// points, sorted, and per cluster the clusters adjacent to it.
    std::vector<std::int64_t> adjacentPairs;
    std::vector<std::vector<int>> neighbours;
};

/// The points of each candidate cluster and their centre.
void gatherClusterPoints(const Input& input, CandidateClusters& clusters)
{
    const Eigen::Index n = input.points();
    const int clusterCount = input.clusters();
    const std::vector<int>& cluster = input.in.cluster;
    std::vector<int>& start = clusters.start;
    start.assign(clusterCount + 1, 0);
    for (Eigen::Index i = 0; i < n; ++i) {
        if (input.isCandidate(i)) {
            ++start[cluster[i] + 1];
        }
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    clusters.members.assign(start.back(), 0);
    {
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (Eigen::Index i = 0; i < n; ++i) {
            if (input.isCandidate(i)) {
                clusters.members[fill[cluster[i]]++] = static_cast<int>(i);
            }
        }
    }
    clusters.centre.assign(clusterCount, Eigen::Vector3d::Zero());
    for (int c = 0; c < clusterCount; ++c) {
        for (int m = start[c]; m < start[c + 1]; ++m) {
            clusters.centre[c] += input.in.points.row(clusters.members[m]).transpose();
        }
        if (start[c + 1] > start[c]) {
            clusters.centre[c] /= static_cast<double>(start[c + 1] - start[c]);
        }
    }
}

/// Candidate clusters adjacent through the k nearest neighbours of their points.
void findAdjacentClusters(const Input& input, CandidateClusters& clusters)
{
    const std::vector<int>& cluster = input.in.cluster;
    const Neighbourhoods& N = input.in.neighbours;
    std::vector<std::int64_t>& pairs = clusters.adjacentPairs;
    for (Eigen::Index i = 0; i < input.points(); ++i) {
        if (!input.isCandidate(i)) {
            continue;
        }
        for (int j = 0; j < N.k(); ++j) {
            const int q = N.indices(i, j);
            if (input.isCandidate(q) && cluster[q] != cluster[i]) {
                pairs.push_back(pairKey(cluster[i], cluster[q]));
            }
        }
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    clusters.neighbours.assign(input.clusters(), {});
    for (std::int64_t key : pairs) {
        const int a = static_cast<int>(key >> 32);
        const int b = static_cast<int>(key & 0xFFFFFFFF);
        clusters.neighbours[a].push_back(b);
        clusters.neighbours[b].push_back(a);
    }
}

/// The graph's nodes: per candidate cluster its node, per node its label and centre.
struct Nodes
{
    std::vector<int> ofCluster;
    std::vector<int> label;
    std::vector<Eigen::Vector3d> centres;
};

/// Nodes: adjacent candidate clusters of one label gathered within `radius` of the node's
/// first cluster; the centre is the mean of the node's points.
Nodes gatherNodes(const Input& input, const CandidateClusters& clusters, double radius)
{
    const std::vector<int>& start = clusters.start;
    const std::vector<Eigen::Vector3d>& clusterCentre = clusters.centre;
    Nodes nodes;
    nodes.ofCluster.assign(input.clusters(), -1);
    std::vector<double> weight;
    for (int c = 0; c < input.clusters(); ++c) {
        if (!input.in.candidateCluster[c] || start[c + 1] == start[c] || nodes.ofCluster[c] >= 0) {
            continue;
        }
        const int node = static_cast<int>(nodes.centres.size());
        nodes.label.push_back(input.labelOf(c));
        nodes.centres.emplace_back(Eigen::Vector3d::Zero());
        weight.push_back(0.0);
        std::vector<int> queue{c};
        nodes.ofCluster[c] = node;
        for (std::size_t q = 0; q < queue.size(); ++q) {
            const int a = queue[q];
            const double size = start[a + 1] - start[a];
            nodes.centres[node] += size * clusterCentre[a];
            weight[node] += size;
            for (int b : clusters.neighbours[a]) {
                if (nodes.ofCluster[b] < 0 && input.labelOf(b) == nodes.label[node] &&
                    (clusterCentre[b] - clusterCentre[c]).norm() <= radius) {
                    nodes.ofCluster[b] = node;
                    queue.push_back(b);
                }
            }
        }
        nodes.centres[node] /= weight[node];
    }
    return nodes;
}

/// G_all: pairKey() of the nodes whose clusters are adjacent, sorted.
std::vector<std::int64_t> allEdges(const CandidateClusters& clusters, const Nodes& nodes)
{
    std::vector<std::int64_t> edges;
    for (std::int64_t key : clusters.adjacentPairs) {
        const int a = nodes.ofCluster[key >> 32];
        const int b = nodes.ofCluster[key & 0xFFFFFFFF];
        if (a != b) {
            edges.push_back(pairKey(a, b));
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
}

/// G_extended: G_all plus every pair of nodes within `radius`.
void addExtendedEdges(const std::vector<Eigen::Vector3d>& centres, double radius,
                      std::vector<std::int64_t>& edges)
{
    if (!(radius > 0.0)) {
        return;
    }
    NodeGrid grid(centres, radius);
    for (int a = 0; a < static_cast<int>(centres.size()); ++a) {
        grid.forEachWithin(centres[a], radius, [&](int b) {
            if (b > a) {
                edges.push_back(pairKey(a, b));
            }
        });
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
}

/// The minimum spanning forest of the edges (Kruskal), then G_pruned_mst: its edges longer
/// than maxLength cut.
void addPrunedSpanningForest(const std::vector<std::int64_t>& edges, double maxLength, Graph& graph,
                             ClusterGraphCounts& counts)
{
    const std::vector<Eigen::Vector3d>& centres = graph.centres();
    std::vector<std::tuple<double, int, int>> weighted;
    weighted.reserve(edges.size());
    for (std::int64_t key : edges) {
        const int a = static_cast<int>(key >> 32);
        const int b = static_cast<int>(key & 0xFFFFFFFF);
        weighted.emplace_back((centres[a] - centres[b]).norm(), a, b);
    }
    std::sort(weighted.begin(), weighted.end());
    DisjointSets forest(graph.size());
    for (const auto& [length, a, b] : weighted) {
        if (!forest.unite(a, b)) {
            continue;
        }
        ++counts.treeEdges;
        if (length > maxLength) {
            ++counts.overlongEdges;
            continue;
        }
        graph.addEdge(a, b);
    }
}

/// G_pruned_branches and the joins that close lines at their free ends: reconnection (and
/// the spurs it can leave: an end joined to the node beside the other end of a broken cycle
/// leaves that end as a short tip), facing ends, converging ends (whose join at a corner can
/// leave the tip of a third line there as a spur).
void pruneBranchesAndJoinEnds(Graph& graph, std::vector<int>& nodeLabel, const Support* support,
                              const ClusterGraphOptions& options, ClusterGraphCounts& counts)
{
    const double minBranch = options.minBranchLength * graph.spacing();
    counts.prunedBranches = pruneShortBranches(graph, minBranch);
    if (options.reconnectRadius > 0.0) {
        counts.reconnections = reconnectEnds(graph, options, nodeLabel, support);
        counts.prunedBranches += pruneShortBranches(graph, minBranch);
        counts.reconnections += joinFacingEnds(graph, options, support);
        counts.reconnections += joinConvergingEnds(graph, options, nodeLabel, support);
        counts.prunedBranches += pruneShortBranches(graph, minBranch);
    }
}

/// Bubbles, close junctions and short pieces go; then free ends are extended to the line
/// they point at and those still left removed (both off unless the options say).
void cleanUpAndExtendEnds(Graph& graph, const Support* support, const ClusterGraphOptions& options,
                          ClusterGraphCounts& counts)
{
    const double spacing = graph.spacing();
    counts.bubbles = removeBubbles(graph, options.maxBubbleLength * spacing);
    counts.mergedJunctions = mergeCloseJunctions(graph, options.junctionMergeLength * spacing);
    counts.droppedComponents = dropShortComponents(graph, options.minComponentLength * spacing,
                                                   options.minOpenComponentLength * spacing);
    if (options.extendReach > 0.0) {
        counts.extensions = extendFreeEnds(graph, options, support);
    }
    if (options.maxFreeEndLength > 0.0) {
        counts.removedFreeEnds = removeFreeEnds(graph, options.maxFreeEndLength * spacing);
    }
}

/// The nodes of degree 3 or more become the junctions (in node order); returns per node its
/// junction, -1 for none.
std::vector<int> readOffJunctions(const Graph& graph, ClusterGraph& result)
{
    std::vector<int> junctionOf(graph.size(), -1);
    for (int v = 0; v < graph.size(); ++v) {
        if (graph.degree(v) >= 3) {
            junctionOf[v] = static_cast<int>(result.junctionNodes.size());
            result.junctionNodes.push_back(v);
        }
    }
    result.network.junctions.resize(static_cast<Eigen::Index>(result.junctionNodes.size()), 3);
    for (std::size_t j = 0; j < result.junctionNodes.size(); ++j) {
        result.network.junctions.row(j) = graph.centre(result.junctionNodes[j]).transpose();
    }
    return junctionOf;
}

/// The node chains of the lines: chains between nodes of degree other than 2, then the
/// cycles left (closed: true, the first node not repeated).
std::vector<std::pair<std::vector<int>, bool>> readOffChains(const Graph& graph)
{
    std::unordered_set<std::int64_t> walked;
    auto walk = [&](int from, int first) {
        std::vector<int> chain{from};
        int previous = from;
        int current = first;
        walked.insert(pairKey(from, first));
        while (graph.degree(current) == 2 && current != from) {
            chain.push_back(current);
            const auto& nb = graph.neighbours(current);
            const int next = nb[0] == previous ? nb[1] : nb[0];
            walked.insert(pairKey(current, next));
            previous = current;
            current = next;
        }
        chain.push_back(current);
        return chain;
    };
    std::vector<std::pair<std::vector<int>, bool>> chains;
    for (int v = 0; v < graph.size(); ++v) {
        if (graph.degree(v) == 0 || graph.degree(v) == 2) {
            continue;
        }
        for (int u : graph.neighbours(v)) {
            if (!walked.count(pairKey(v, u))) {
                chains.emplace_back(walk(v, u), false);
            }
        }
    }
    for (int v = 0; v < graph.size(); ++v) {
        if (graph.degree(v) == 2 && !walked.count(pairKey(v, graph.neighbours(v)[0]))) {
            std::vector<int> cycle = walk(v, graph.neighbours(v)[0]);
            cycle.pop_back(); // the walk returns to v
            chains.emplace_back(std::move(cycle), true);
        }
    }
    return chains;
}

/// The majority label of the chain's nodes (of equally frequent labels, the smallest).
int majorityLabel(const std::vector<int>& chain, const std::vector<int>& nodeLabel)
{
    std::unordered_map<int, int> votes;
    for (int v : chain) {
        ++votes[nodeLabel[v]];
    }
    return std::min_element(votes.begin(), votes.end(),
                            [](const auto& a, const auto& b) {
                                return std::tie(b.second, a.first) < std::tie(a.second, b.first);
                            })
        ->first;
}

/// The polyline through the chain's node centres, smoothed and resampled as the options say.
PointMatrix linePoints(const Graph& graph, const std::vector<int>& chain, bool closed,
                       const ClusterGraphOptions& options)
{
    const double spacing = graph.spacing();
    PointMatrix points(static_cast<Eigen::Index>(chain.size()), 3);
    for (std::size_t i = 0; i < chain.size(); ++i) {
        points.row(i) = graph.centre(chain[i]).transpose();
    }
    points = smoothPolyline(points, closed, options.smoothingLength * spacing);
    if (options.resampleSpacing > 0.0) {
        points = resamplePolyline(points, closed, options.resampleSpacing * spacing);
    }
    return points;
}

/// The lines read off the final graph: its nodes, junctions, lines and free ends.
void readOffLines(const Graph& graph, const std::vector<int>& nodeLabel,
                  const ClusterGraphOptions& options, ClusterGraph& result)
{
    // The joins of converging ends may have added nodes.
    result.nodes.resize(graph.size(), 3);
    for (int v = 0; v < graph.size(); ++v) {
        result.nodes.row(v) = graph.centre(v).transpose();
    }
    const std::vector<int> junctionOf = readOffJunctions(graph, result);
    int freeEnds = 0;
    for (auto& [chain, closed] : readOffChains(graph)) {
        Polyline line;
        line.closed = closed;
        if (!closed) {
            line.startJunction = junctionOf[chain.front()];
            line.endJunction = junctionOf[chain.back()];
            freeEnds += (line.startJunction < 0 ? 1 : 0) + (line.endJunction < 0 ? 1 : 0);
        }
        line.label = majorityLabel(chain, nodeLabel);
        line.points = linePoints(graph, chain, closed, options);
        result.network.lines.push_back(std::move(line));
        result.lineNodes.push_back(std::move(chain));
    }
    result.counts.freeEnds = freeEnds;
}

/// Per point its node, -1 for points of no candidate cluster.
std::vector<int> nodeOfPoints(const Input& input, const Nodes& nodes)
{
    std::vector<int> nodeOfPoint(input.points(), -1);
    for (Eigen::Index i = 0; i < input.points(); ++i) {
        if (input.isCandidate(i)) {
            nodeOfPoint[i] = nodes.ofCluster[input.in.cluster[i]];
        }
    }
    return nodeOfPoint;
}

/// Where joins may run when the caller marks supporting points (null when it does not): along
/// those points and the candidates.
std::unique_ptr<Support> supportOf(const Input& input, const ClusterGraphOptions& options)
{
    if (input.supportingPoint.empty()) {
        return nullptr;
    }
    return std::make_unique<Support>(
        input.in.points,
        [&](Eigen::Index i) { return input.supportingPoint[i] != 0 || input.isCandidate(i); },
        options.supportRadius * input.in.spacing);
}

} // namespace

ClusterGraph buildClusterGraph(const ClusterGraphInput& in, const ClusterGraphOptions& options)
{
    static const std::vector<int> noLabels;
    static const std::vector<char> noSupport;
    const Input input{in, in.clusterLabel ? *in.clusterLabel : noLabels,
                      in.supportingPoint ? *in.supportingPoint : noSupport};
    checkInput(input);
    const double spacing = in.spacing;
    ClusterGraph result;

    // Nodes: the candidate clusters gathered.
    CandidateClusters clusters;
    gatherClusterPoints(input, clusters);
    findAdjacentClusters(input, clusters);
    Nodes nodes = gatherNodes(input, clusters, options.nodeRadius * spacing);
    result.counts.nodes = static_cast<int>(nodes.centres.size());
    result.nodeOfPoint = nodeOfPoints(input, nodes);

    // G_all, G_extended, G_pruned_mst.
    std::vector<std::int64_t> edges = allEdges(clusters, nodes);
    result.counts.allEdges = static_cast<int>(edges.size());
    addExtendedEdges(nodes.centres, options.extendedRadius * spacing, edges);
    result.counts.extendedEdges = static_cast<int>(edges.size()) - result.counts.allEdges;
    Graph graph(nodes.centres, spacing);
    addPrunedSpanningForest(edges, options.maxEdgeLength * spacing, graph, result.counts);

    // G_pruned_branches, the reconnection and the other joins, the clean-up, the lines.
    const std::unique_ptr<Support> support = supportOf(input, options);
    pruneBranchesAndJoinEnds(graph, nodes.label, support.get(), options, result.counts);
    cleanUpAndExtendEnds(graph, support.get(), options, result.counts);
    readOffLines(graph, nodes.label, options, result);

    // Points of nodes no line runs through any more (pruned, dropped, merged into a
    // junction) are no longer on a node.
    for (Eigen::Index i = 0; i < input.points(); ++i) {
        const int v = result.nodeOfPoint[i];
        if (v >= 0 && graph.degree(v) == 0) {
            result.nodeOfPoint[i] = -1;
        }
    }
    return result;
}

} // namespace featurelines
