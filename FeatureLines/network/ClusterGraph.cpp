// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/network/ClusterGraph.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <queue>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "FeatureLines/support/DisjointSets.h"

namespace featurelines {

namespace {

constexpr double pi = 3.14159265358979323846;

/// A uniform hash grid over the node centres, for the radius queries of G_extended and of
/// the reconnection (a few thousand nodes: no tree needed).
class NodeGrid
{
public:
    NodeGrid(const std::vector<Eigen::Vector3d>& centres, double cell)
        : centres_(centres), cell_(cell)
    {
        for (int i = 0; i < static_cast<int>(centres.size()); ++i) {
            cells_[key(cellOf(centres[i]))].push_back(i);
        }
    }

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
    Eigen::Vector3i cellOf(const Eigen::Vector3d& x) const
    {
        return (x / cell_).array().floor().cast<int>();
    }

    static std::int64_t key(const Eigen::Vector3i& c)
    {
        const auto part = [](int v) { return static_cast<std::int64_t>(v & 0x1FFFFF); };
        return (part(c.x()) << 42) | (part(c.y()) << 21) | part(c.z());
    }

    const std::vector<Eigen::Vector3d>& centres_;
    double cell_;
    std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

std::int64_t pairKey(int a, int b)
{
    if (b < a) {
        std::swap(a, b);
    }
    return (static_cast<std::int64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

/// The node graph with the operations the stages need. Nodes are never renumbered: a removed
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

    bool hasEdge(int a, int b) const
    {
        const auto& n = adjacency_[a];
        return std::find(n.begin(), n.end(), b) != n.end();
    }

    void addEdge(int a, int b)
    {
        if (a == b || hasEdge(a, b)) {
            return;
        }
        adjacency_[a].push_back(b);
        adjacency_[b].push_back(a);
    }

    void removeEdge(int a, int b)
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

    /// A node with no points of its own (where the lines of free ends meet).
    int addNode(const Eigen::Vector3d& centre)
    {
        centres_.push_back(centre);
        adjacency_.emplace_back();
        return static_cast<int>(adjacency_.size()) - 1;
    }

    void isolate(int v)
    {
        const std::vector<int> n = adjacency_[v];
        for (int u : n) {
            removeEdge(v, u);
        }
    }

    /// From the free end `leaf`, the chain of degree-2 nodes up to the first node of another
    /// degree: returns the nodes (leaf first, that node last) and the chain's length.
    std::pair<std::vector<int>, double> chainFrom(int leaf, int first) const
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
            const int next = adjacency_[current][0] == previous ? adjacency_[current][1]
                                                                : adjacency_[current][0];
            previous = current;
            current = next;
        }
        return {chain, length};
    }

    /// Shortest path lengths from `source` along the graph, up to `limit`; nodes farther away
    /// are absent from the map.
    std::unordered_map<int, double> distancesFrom(int source, double limit) const
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

    double spacing() const { return spacing_; }
    std::vector<Eigen::Vector3d>& centres() { return centres_; }

private:
    std::vector<Eigen::Vector3d>& centres_;
    std::vector<std::vector<int>> adjacency_;
    double spacing_;
};

/// G_pruned_branches: cuts branches from a junction to a free end shorter than minLength,
/// repeatedly, but never more than leaves the junction two branches: at the end of a line
/// that forks into two short tips the longer tip stays, so the line keeps its length.
int pruneShortBranches(Graph& g, double minLength)
{
    int pruned = 0;
    for (bool changed = true; changed;) {
        changed = false;
        // (junction, length, chain without the junction)
        std::vector<std::tuple<int, double, std::vector<int>>> branches;
        for (int v = 0; v < g.size(); ++v) {
            if (g.degree(v) != 1) {
                continue;
            }
            auto [chain, length] = g.chainFrom(v, g.neighbours(v)[0]);
            const int end = chain.back();
            if (g.degree(end) >= 3) {
                chain.pop_back();
                branches.emplace_back(end, length, std::move(chain));
            }
        }
        std::sort(branches.begin(), branches.end(), [](const auto& a, const auto& b) {
            return std::tie(std::get<0>(a), std::get<1>(a), std::get<2>(a)) <
                   std::tie(std::get<0>(b), std::get<1>(b), std::get<2>(b));
        });
        for (const auto& [junction, length, chain] : branches) {
            // The degree is read now, so cuts made at this junction in this round count.
            if (length >= minLength || g.degree(junction) <= 2) {
                continue;
            }
            // A branch met from both of its ends (two junctions joined through free ends)
            // cannot occur: a chain that starts at a free end ends at the first node of
            // another degree.
            for (int v : chain) {
                g.isolate(v);
            }
            ++pruned;
            changed = true;
        }
    }
    return pruned;
}

/// The direction in which the line of the free end `leaf` leaves it, read from the node
/// about `length` back along the line; false when the line has no length.
bool endDirection(const Graph& g, int leaf, double length, Eigen::Vector3d& direction)
{
    int previous = leaf;
    int current = g.neighbours(leaf)[0];
    while (g.length(leaf, current) < length && g.degree(current) == 2) {
        const int next = g.neighbours(current)[0] == previous ? g.neighbours(current)[1]
                                                              : g.neighbours(current)[0];
        if (next == leaf) {
            break;
        }
        previous = current;
        current = next;
    }
    const Eigen::Vector3d back = g.centre(leaf) - g.centre(current);
    if (!(back.norm() > 0.0)) {
        return false;
    }
    direction = back.normalized();
    return true;
}

/// Where the rays a + t da and b + u db (unit directions) pass closest: true when both t and
/// u lie in [0, reach], the rays are more than 20 degrees from parallel (parallel ends are
/// joined end to end, not at a corner) and they pass within `tolerance` of each other;
/// `where` is then the middle of the closest points and `along` is t + u.
bool raysMeet(const Eigen::Vector3d& a, const Eigen::Vector3d& da, const Eigen::Vector3d& b,
              const Eigen::Vector3d& db, double reach, double tolerance, Eigen::Vector3d& where,
              double& along)
{
    const Eigen::Vector3d w = a - b;
    const double c = da.dot(db);
    const double denominator = 1.0 - c * c;
    if (denominator < std::pow(std::sin(20.0 * pi / 180.0), 2)) {
        return false;
    }
    const double d = da.dot(w), e = db.dot(w);
    const double t = (c * e - d) / denominator;
    const double u = (e - c * d) / denominator;
    if (t < 0.0 || u < 0.0 || t > reach || u > reach) {
        return false;
    }
    const Eigen::Vector3d pa = a + t * da, pb = b + u * db;
    if ((pa - pb).norm() > tolerance) {
        return false;
    }
    where = 0.5 * (pa + pb);
    along = t + u;
    return true;
}

/// Where a line may run: along candidates, or where the caller marks points as supporting.
class Support
{
public:
    template <class Supports>
    Support(const PointMatrix& P, Supports supports, double radius) : radius_(radius)
    {
        for (Eigen::Index i = 0; i < P.rows(); ++i) {
            if (supports(i)) {
                points_.emplace_back(P.row(i).transpose());
            }
        }
        grid_ = std::make_unique<NodeGrid>(points_, radius);
    }

    /// Share of the steps (one spacing apart) along the segment from a to b that have a
    /// supporting point within the radius.
    double along(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double spacing) const
    {
        return alongCurve(a, Eigen::Vector3d::Zero(), b, Eigen::Vector3d::Zero(), spacing);
    }

    /// The same along the cubic (Hermite) curve from a, leaving in direction da, to b,
    /// arriving against db (unit directions, or zero for a straight segment): the way two
    /// facing ends of a curved crease (an arc of a hole or a rim) continue into each other,
    /// where their chord cuts the bend by up to a quarter of the gap squared over the radius.
    double alongCurve(const Eigen::Vector3d& a, const Eigen::Vector3d& da, const Eigen::Vector3d& b,
                      const Eigen::Vector3d& db, double spacing) const
    {
        const double length = (b - a).norm();
        const int steps = std::max(1, static_cast<int>(std::ceil(length / spacing)));
        int supported = 0;
        for (int s = 0; s <= steps; ++s) {
            const double t = static_cast<double>(s) / steps, t2 = t * t, t3 = t2 * t;
            const Eigen::Vector3d x = (2 * t3 - 3 * t2 + 1) * a + (t3 - 2 * t2 + t) * length * da +
                                      (-2 * t3 + 3 * t2) * b + (t3 - t2) * length * (-db);
            bool found = false;
            grid_->forEachWithin(x, radius_, [&](int) { found = true; });
            supported += found ? 1 : 0;
        }
        return supported / static_cast<double>(steps + 1);
    }

private:
    double radius_;
    std::vector<Eigen::Vector3d> points_;
    std::unique_ptr<NodeGrid> grid_;
};

/// A new edge from a to b is acceptable: short (within half maxEdgeLength, the reach of the
/// spanning tree's own edges), or running along supporting points, or no support given.
bool supported(const Support* support, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
               const ClusterGraphOptions& options, double spacing)
{
    return !support || (b - a).norm() <= 0.5 * options.maxEdgeLength * spacing ||
           support->along(a, b, spacing) >= options.minExtendSupport;
}

/// Reconnection: every free end is joined to the nearest node ahead of it, so that lines
/// close (the spanning tree broke every cycle of the feature network once) or end on
/// another line.
int reconnectEnds(Graph& g, const ClusterGraphOptions& options, std::vector<int>& labels,
                  const Support* support)
{
    const double spacing = g.spacing();
    const double radius = options.reconnectRadius * spacing;
    const double cosAngle = std::cos(options.reconnectAngle * pi / 180.0);
    // The direction at an end is read over the length below which branches count as spurs.
    const double directionLength = std::max(options.minBranchLength, 1.0) * spacing;
    const double distanceLimit = options.minCycleRatio * radius;
    NodeGrid grid(g.centres(), std::max(radius, spacing));

    auto acceptable = [&](int leaf, int target) {
        const auto along = g.distancesFrom(leaf, distanceLimit);
        const auto found = along.find(target);
        return found == along.end() ||
               found->second >= options.minCycleRatio * g.length(leaf, target);
    };

    struct Proposal
    {
        double distance;
        int leaf;
        int target;
    };
    std::vector<Proposal> proposals;
    for (int leaf = 0; leaf < g.size(); ++leaf) {
        if (g.degree(leaf) != 1) {
            continue;
        }
        const Eigen::Vector3d tip = g.centre(leaf);
        Eigen::Vector3d direction;
        if (!endDirection(g, leaf, directionLength, direction)) {
            continue;
        }
        const auto along = g.distancesFrom(leaf, distanceLimit);
        int best = -1;
        double bestDistance = std::numeric_limits<double>::infinity();
        grid.forEachWithin(tip, radius, [&](int target) {
            if (target == leaf || g.degree(target) == 0 || g.hasEdge(leaf, target)) {
                return;
            }
            const Eigen::Vector3d step = g.centre(target) - tip;
            const double distance = step.norm();
            if (!(distance > 0.0) || step.dot(direction) < cosAngle * distance ||
                distance >= bestDistance) {
                return;
            }
            const auto found = along.find(target);
            if (found != along.end() && found->second < options.minCycleRatio * distance) {
                return;
            }
            if (!supported(support, tip, g.centre(target), options, spacing)) {
                return;
            }
            best = target;
            bestDistance = distance;
        });
        if (best >= 0) {
            proposals.push_back({bestDistance, leaf, best});
        }
    }
    std::sort(proposals.begin(), proposals.end(), [](const Proposal& a, const Proposal& b) {
        return std::tie(a.distance, a.leaf, a.target) < std::tie(b.distance, b.leaf, b.target);
    });
    int added = 0;
    for (const Proposal& p : proposals) {
        // An earlier reconnection may have reached this end already, or made the new edge a
        // short cycle.
        if (g.degree(p.leaf) != 1 || g.degree(p.target) == 0 || !acceptable(p.leaf, p.target)) {
            continue;
        }
        // Two free ends whose lines meet at an angle are joined through the corner where
        // they meet: a straight join would cut it.
        Eigen::Vector3d from, to, corner;
        double along = 0.0;
        if (g.degree(p.target) == 1 && endDirection(g, p.leaf, directionLength, from) &&
            endDirection(g, p.target, directionLength, to) &&
            raysMeet(g.centre(p.leaf), from, g.centre(p.target), to, radius,
                     0.5 * options.maxEdgeLength * spacing, corner, along) &&
            supported(support, g.centre(p.leaf), corner, options, spacing) &&
            supported(support, corner, g.centre(p.target), options, spacing)) {
            const int node = g.addNode(corner);
            labels.push_back(labels[p.leaf]);
            g.addEdge(p.leaf, node);
            g.addEdge(node, p.target);
        } else {
            g.addEdge(p.leaf, p.target);
        }
        ++added;
    }
    return added;
}

/// Free ends left after the reconnection that face each other across a longer gap (where
/// noise thinned the candidates of a shallow crease) are joined, end to end: each must lie
/// ahead of the other, so a line is only ever continued in its own direction.
int joinFacingEnds(Graph& g, const ClusterGraphOptions& options, const Support* support)
{
    const double spacing = g.spacing();
    const double radius = options.facingEndsRadius * spacing;
    if (!(radius > 0.0)) {
        return 0;
    }
    // Half the reconnection's cone: far apart, two ends of parallel lines running opposite
    // ways could otherwise face each other across the gap between the lines. With supporting
    // points the join must follow the curve the two ends continue into each other along,
    // which such a gap does not support: the whole cone, as the ends of an arc (a hole's rim)
    // broken over a gap meet its chord at half the arc's angle, and noise adds its own.
    const double cosAngle = std::cos((support ? 1.0 : 0.5) * options.reconnectAngle * pi / 180.0);
    const double directionLength = std::max(options.minBranchLength, 1.0) * spacing;
    std::vector<int> ends;
    std::vector<Eigen::Vector3d> tips, directions;
    for (int v = 0; v < g.size(); ++v) {
        Eigen::Vector3d direction;
        if (g.degree(v) == 1 && endDirection(g, v, directionLength, direction)) {
            ends.push_back(v);
            tips.push_back(g.centre(v));
            directions.push_back(direction);
        }
    }
    NodeGrid grid(tips, radius);
    std::vector<std::tuple<double, int, int>> proposals;
    for (int a = 0; a < static_cast<int>(ends.size()); ++a) {
        grid.forEachWithin(tips[a], radius, [&](int b) {
            if (b <= a) {
                return;
            }
            const Eigen::Vector3d step = tips[b] - tips[a];
            const double distance = step.norm();
            if (distance > 0.0 && step.dot(directions[a]) >= cosAngle * distance &&
                -step.dot(directions[b]) >= cosAngle * distance) {
                proposals.emplace_back(distance, a, b);
            }
        });
    }
    std::sort(proposals.begin(), proposals.end());
    int added = 0;
    for (const auto& [distance, a, b] : proposals) {
        const int u = ends[a], v = ends[b];
        if (g.degree(u) != 1 || g.degree(v) != 1) {
            continue;
        }
        const auto along = g.distancesFrom(u, options.minCycleRatio * distance);
        if (along.count(v)) {
            continue; // the two ends of one short piece
        }
        // Along the curve the two ends continue into each other.
        if (support && (g.centre(v) - g.centre(u)).norm() > 0.5 * options.maxEdgeLength * spacing &&
            support->alongCurve(g.centre(u), directions[a], g.centre(v), directions[b], spacing) <
                options.minExtendSupport) {
            continue;
        }
        g.addEdge(u, v);
        ++added;
    }
    return added;
}

/// Free ends still left whose lines, continued straight ahead, meet within twice
/// reconnectRadius are joined through a new node where they meet: the corner of two creases whose
/// last few spacings (and the faint edges between them, as at the triangles of a chamfered box's
/// corners) left no candidates. Further free ends heading for that node join it too.
int joinConvergingEnds(Graph& g, const ClusterGraphOptions& options, std::vector<int>& labels,
                       const Support* support)
{
    const double spacing = g.spacing();
    const double reach = 2.0 * options.reconnectRadius * spacing;
    const double tolerance = 0.5 * options.maxEdgeLength * spacing;
    const double directionLength = std::max(options.minBranchLength, 1.0) * spacing;
    if (!(reach > 0.0)) {
        return 0;
    }
    struct End
    {
        int node;
        Eigen::Vector3d tip, direction;
    };
    std::vector<End> ends;
    for (int v = 0; v < g.size(); ++v) {
        Eigen::Vector3d direction;
        if (g.degree(v) == 1 && endDirection(g, v, directionLength, direction)) {
            ends.push_back({v, g.centre(v), direction});
        }
    }
    auto meet = [&](const End& a, const End& b, Eigen::Vector3d& where, double& along) {
        return raysMeet(a.tip, a.direction, b.tip, b.direction, reach, tolerance, where, along) &&
               supported(support, a.tip, where, options, spacing) &&
               supported(support, where, b.tip, options, spacing);
    };
    std::vector<std::tuple<double, int, int>> pairs;
    for (int a = 0; a < static_cast<int>(ends.size()); ++a) {
        for (int b = a + 1; b < static_cast<int>(ends.size()); ++b) {
            Eigen::Vector3d where;
            double along = 0.0;
            if ((ends[a].tip - ends[b].tip).norm() <= 2.0 * reach &&
                meet(ends[a], ends[b], where, along)) {
                pairs.emplace_back(along, a, b);
            }
        }
    }
    std::sort(pairs.begin(), pairs.end());
    int added = 0;
    for (const auto& [along, a, b] : pairs) {
        if (g.degree(ends[a].node) != 1 || g.degree(ends[b].node) != 1) {
            continue;
        }
        Eigen::Vector3d where;
        double unused = 0.0;
        meet(ends[a], ends[b], where, unused);
        const int corner = g.addNode(where);
        labels.push_back(labels[ends[a].node]);
        g.addEdge(ends[a].node, corner);
        g.addEdge(corner, ends[b].node);
        ++added;
        // Other free ends heading for the same corner.
        for (const End& c : ends) {
            if (g.degree(c.node) != 1) {
                continue;
            }
            const Eigen::Vector3d step = where - c.tip;
            const double t = step.dot(c.direction);
            if (t >= 0.0 && t <= reach && (step - t * c.direction).norm() <= tolerance &&
                supported(support, c.tip, where, options, spacing)) {
                g.addEdge(c.node, corner);
                ++added;
            }
        }
    }
    return added;
}

/// Free ends still left are extended straight ahead to the line they point at: along the
/// line's direction at the end, the first node of another line (or of a far part of the same
/// line) lying within a narrow cone around that direction, up to extendReach, whose way there
/// runs along supporting points (when the caller marks them). A crease whose stretch left too
/// few candidates still runs on straight to the corner where it meets the other edges, and
/// its normals still bend all the way (Sec. 1.2 of the 2008 paper: the lines close on each
/// other).
int extendFreeEnds(Graph& g, const ClusterGraphOptions& options, const Support* support)
{
    const double spacing = g.spacing();
    const double reach = options.extendReach * spacing;
    if (!(reach > 0.0)) {
        return 0;
    }
    const double slope = std::tan(options.extendAngle * pi / 180.0);
    const double base = 0.5 * options.maxEdgeLength * spacing;
    const double directionLength = std::max(options.minBranchLength, 1.0) * spacing;
    NodeGrid grid(g.centres(), reach);
    struct Proposal
    {
        double along;
        int leaf;
        int target;
    };
    std::vector<Proposal> proposals;
    for (int leaf = 0; leaf < g.size(); ++leaf) {
        if (g.degree(leaf) != 1) {
            continue;
        }
        const Eigen::Vector3d tip = g.centre(leaf);
        const auto own = g.distancesFrom(leaf, options.minCycleRatio * reach);
        // The direction over the spur length, then over half of it: an end a few spacings
        // past a corner of its line points along its last stretch only over the shorter one.
        for (const double length :
             {directionLength, 0.5 * directionLength, 0.25 * directionLength}) {
            Eigen::Vector3d direction;
            if (!endDirection(g, leaf, length, direction)) {
                continue;
            }
            std::vector<std::tuple<double, double, int>> ahead; // along + aside, aside, target
            grid.forEachWithin(tip, reach, [&](int target) {
                if (target == leaf || g.degree(target) == 0) {
                    return;
                }
                const Eigen::Vector3d step = g.centre(target) - tip;
                const double distance = step.norm();
                double along = step.dot(direction);
                const double aside = (step - along * direction).norm();
                // Ahead within the cone, or touching the end whatever the direction (an end
                // that stops beside another line is on it).
                if (distance <= base) {
                    along = std::max(along, 0.0);
                } else if (!(along > 0.0) || aside > base + along * slope) {
                    return;
                }
                // Not back onto the end's own line a little behind it.
                const auto found = own.find(target);
                if (found != own.end() && found->second < options.minCycleRatio * distance) {
                    return;
                }
                // Where the way ahead meets a line: the node of the first line met that lies
                // nearest to the way (a node beside it lies as much farther).
                ahead.emplace_back(along + aside, aside, target);
            });
            std::sort(ahead.begin(), ahead.end());
            // The first node met whose way is supported; a few tries, as the nodes of one
            // line come one after another.
            const std::size_t tries = std::min<std::size_t>(ahead.size(), 8);
            int chosen = -1;
            double chosenAlong = 0.0;
            for (std::size_t t = 0; t < tries && chosen < 0; ++t) {
                const auto [along, aside, target] = ahead[t];
                // Along the way the end continues on: leaving in its direction, arriving
                // against the target's own end direction when that is a free end too (two
                // ends of a curved crease), else along the chord.
                const Eigen::Vector3d chord = g.centre(target) - tip;
                Eigen::Vector3d arrival = chord.normalized();
                Eigen::Vector3d other;
                if (g.degree(target) == 1 && endDirection(g, target, length, other)) {
                    arrival = -other;
                }
                if (support && chord.norm() > base &&
                    support->alongCurve(tip, direction, g.centre(target), -arrival, spacing) <
                        options.minExtendSupport) {
                    continue;
                }
                chosen = target;
                chosenAlong = along;
            }
            if (chosen >= 0) {
                proposals.push_back({chosenAlong, leaf, chosen});
                break;
            }
        }
        if (!proposals.empty() && proposals.back().leaf == leaf) {
            continue;
        }
        // Nothing ahead: where the line's last stretch is too short or too bent to tell its
        // way (an end a few spacings before a corner whose other edges left no candidates), the
        // nearest node within reconnectRadius in any direction, if the way there is
        // supported. Without supporting points this is not tried.
        if (!support) {
            continue;
        }
        const double near = 2.0 * options.reconnectRadius * spacing;
        std::vector<std::pair<double, int>> around;
        grid.forEachWithin(tip, std::min(near, reach), [&](int target) {
            const double distance = (g.centre(target) - tip).norm();
            const auto found = own.find(target);
            if (target != leaf && g.degree(target) > 0 &&
                (found == own.end() || found->second >= options.minCycleRatio * distance)) {
                around.emplace_back(distance, target);
            }
        });
        std::sort(around.begin(), around.end());
        for (std::size_t t = 0; t < std::min<std::size_t>(around.size(), 8); ++t) {
            if (supported(support, tip, g.centre(around[t].second), options, spacing)) {
                proposals.push_back({around[t].first, leaf, around[t].second});
                break;
            }
        }
    }
    std::sort(proposals.begin(), proposals.end(), [](const Proposal& a, const Proposal& b) {
        return std::tie(a.along, a.leaf, a.target) < std::tie(b.along, b.leaf, b.target);
    });
    int added = 0;
    for (const Proposal& p : proposals) {
        // An earlier extension may have reached this end already.
        if (g.degree(p.leaf) != 1 || g.degree(p.target) == 0 || g.hasEdge(p.leaf, p.target)) {
            continue;
        }
        g.addEdge(p.leaf, p.target);
        ++added;
    }
    return added;
}

/// The free ends no join reached are removed with their branch, up to the first junction
/// (an open piece ending in nothing on both sides goes whole), when the branch or piece is no
/// longer than maxLength: what cannot close is not a boundary of a patch. Repeated, because
/// cutting a fork can leave the line it ended as a new free end.
int removeFreeEnds(Graph& g, double maxLength)
{
    int removed = 0;
    for (bool changed = true; changed;) {
        changed = false;
        std::vector<std::pair<std::vector<int>, double>> branches;
        for (int v = 0; v < g.size(); ++v) {
            if (g.degree(v) == 1) {
                branches.push_back(g.chainFrom(v, g.neighbours(v)[0]));
            }
        }
        for (const auto& [chain, length] : branches) {
            const int end = chain.back();
            if (g.degree(chain.front()) != 1 || length > maxLength) {
                continue; // removed with an open piece from its other end, or long
            }
            if (g.degree(end) == 2) {
                continue; // a junction an earlier cut of this round left with two lines
            }
            for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
                g.isolate(chain[i]);
            }
            if (g.degree(end) == 1) {
                g.isolate(end); // the other end of an open piece
            }
            ++removed;
            changed = true;
        }
    }
    return removed;
}

/// Bubbles: where a band is two nodes wide, the tree may run two parallel chains that the
/// reconnection then joins at both ends. Of two chains joining the same two junctions (or a
/// chain leaving a junction and returning to it) the longer is dropped when it is shorter
/// than maxLength; a real face is bounded by more junctions or by longer lines.
int removeBubbles(Graph& g, double maxLength)
{
    int removed = 0;
    for (bool changed = true; changed;) {
        changed = false;
        std::map<std::pair<int, int>, std::vector<std::pair<double, std::vector<int>>>> chains;
        for (int j = 0; j < g.size() && !changed; ++j) {
            if (g.degree(j) < 3) {
                continue;
            }
            for (int first : g.neighbours(j)) {
                auto [chain, length] = g.chainFrom(j, first);
                const int end = chain.back();
                if (g.degree(end) < 3 || length >= maxLength) {
                    continue;
                }
                if (end == j) {
                    // A short loop hanging at one junction.
                    for (std::size_t i = 1; i + 1 < chain.size(); ++i) {
                        g.isolate(chain[i]);
                    }
                    if (chain.size() == 2) {
                        g.removeEdge(j, first);
                    }
                    ++removed;
                    changed = true;
                    break;
                }
                if (j < end) {
                    chains[{j, end}].emplace_back(length, std::move(chain));
                }
            }
        }
        if (changed) {
            continue;
        }
        for (auto& [ends, list] : chains) {
            if (list.size() < 2) {
                continue;
            }
            std::sort(list.begin(), list.end());
            const std::vector<int>& drop = list[1].second;
            if (drop.size() == 2) {
                g.removeEdge(drop[0], drop[1]);
            }
            for (std::size_t i = 1; i + 1 < drop.size(); ++i) {
                g.isolate(drop[i]);
            }
            ++removed;
            changed = true;
            break;
        }
    }
    return removed;
}

/// Junctions joined by a short chain (and short loops hanging at one junction) become one
/// junction at the mean of the merged nodes.
int mergeCloseJunctions(Graph& g, double maxLength)
{
    DisjointSets sets(g.size());
    int merged = 0;
    for (int j = 0; j < g.size(); ++j) {
        if (g.degree(j) < 3) {
            continue;
        }
        for (int first : g.neighbours(j)) {
            auto [chain, length] = g.chainFrom(j, first);
            if (length < maxLength && g.degree(chain.back()) >= 3) {
                for (int v : chain) {
                    merged += sets.unite(j, v) ? 1 : 0;
                }
            }
        }
    }
    if (merged == 0) {
        return 0;
    }
    std::unordered_map<int, std::vector<int>> groups;
    for (int v = 0; v < g.size(); ++v) {
        if (g.degree(v) > 0 && sets.find(v) != v) {
            groups[sets.find(v)].push_back(v);
        }
    }
    std::vector<std::pair<int, int>> edges;
    for (auto& [root, members] : groups) {
        Eigen::Vector3d sum = g.centre(root);
        for (int v : members) {
            sum += g.centre(v);
            for (int u : g.neighbours(v)) {
                edges.emplace_back(v, u);
            }
            g.isolate(v);
        }
        g.centres()[root] = sum / static_cast<double>(members.size() + 1);
    }
    for (const auto& [a, b] : edges) {
        g.addEdge(sets.find(a), sets.find(b)); // self loops are ignored
    }
    return merged;
}

/// Drops connected pieces whose total length is below minLength, and those without a cycle
/// (open lines and trees) whose length is below minOpenLength.
int dropShortComponents(Graph& g, double minLength, double minOpenLength)
{
    std::vector<char> seen(g.size(), 0);
    int dropped = 0;
    for (int s = 0; s < g.size(); ++s) {
        if (seen[s] || g.degree(s) == 0) {
            continue;
        }
        std::vector<int> component{s};
        seen[s] = 1;
        double length = 0.0;
        std::size_t edgeEnds = 0;
        for (std::size_t i = 0; i < component.size(); ++i) {
            const int v = component[i];
            edgeEnds += g.neighbours(v).size();
            for (int u : g.neighbours(v)) {
                length += 0.5 * g.length(v, u);
                if (!seen[u]) {
                    seen[u] = 1;
                    component.push_back(u);
                }
            }
        }
        const bool hasCycle = edgeEnds / 2 >= component.size();
        if (length < minLength || (!hasCycle && length < minOpenLength)) {
            for (int v : component) {
                g.isolate(v);
            }
            ++dropped;
        }
    }
    return dropped;
}

} // namespace

PointMatrix smoothPolyline(const PointMatrix& points, bool closed, double length)
{
    if (!(length > 0.0) || points.rows() < 3) {
        return points;
    }
    // Each pass of (1/4, 1/2, 1/4) adds a variance of half a step squared: eight passes at a
    // step of length / 2 give a variance of length^2.
    const double step = 0.5 * length;
    const int passes = 8;
    PointMatrix smoothed = resamplePolyline(points, closed, step);
    const Eigen::Index m = smoothed.rows();
    for (int pass = 0; pass < passes && m >= 3; ++pass) {
        const PointMatrix old = smoothed;
        for (Eigen::Index i = 0; i < m; ++i) {
            if (!closed && (i == 0 || i == m - 1)) {
                continue;
            }
            smoothed.row(i) =
                0.25 * old.row((i + m - 1) % m) + 0.5 * old.row(i) + 0.25 * old.row((i + 1) % m);
        }
    }
    return smoothed;
}

PointMatrix resamplePolyline(const PointMatrix& points, bool closed, double step)
{
    const Eigen::Index m = points.rows();
    if (m < 2 || !(step > 0.0) || !std::isfinite(step)) {
        return points;
    }
    const Eigen::Index segments = closed ? m : m - 1;
    std::vector<double> arc(segments + 1, 0.0);
    for (Eigen::Index s = 0; s < segments; ++s) {
        arc[s + 1] = arc[s] + (points.row((s + 1) % m) - points.row(s)).norm();
    }
    const double total = arc.back();
    if (!(total > 0.0)) {
        return points.topRows(1);
    }
    Eigen::Index count = std::max<Eigen::Index>(1, std::llround(total / step));
    if (closed) {
        count = std::max<Eigen::Index>(3, count);
    }
    const Eigen::Index rows = closed ? count : count + 1;
    PointMatrix out(rows, 3);
    Eigen::Index s = 0;
    for (Eigen::Index i = 0; i < rows; ++i) {
        const double t = total * static_cast<double>(i) / static_cast<double>(count);
        while (s + 1 < segments && arc[s + 1] < t) {
            ++s;
        }
        const double span = arc[s + 1] - arc[s];
        const double f = span > 0.0 ? std::clamp((t - arc[s]) / span, 0.0, 1.0) : 0.0;
        out.row(i) = (1.0 - f) * points.row(s) + f * points.row((s + 1) % m);
    }
    if (!closed) {
        out.row(rows - 1) = points.row(m - 1);
    }
    return out;
}

ClusterGraph buildClusterGraph(const PointMatrix& P, const Neighbourhoods& N,
                               const std::vector<int>& cluster,
                               const std::vector<char>& candidateCluster, double spacing,
                               const ClusterGraphOptions& options,
                               const std::vector<int>& clusterLabel,
                               const std::vector<char>& supportingPoint)
{
    const Eigen::Index n = P.rows();
    if (N.size() != n || static_cast<Eigen::Index>(cluster.size()) != n) {
        throw std::invalid_argument(
            "cluster graph: the neighbourhoods and cluster ids must have one row per point (" +
            std::to_string(n) + " points, " + std::to_string(N.size()) + " neighbourhoods, " +
            std::to_string(cluster.size()) + " cluster ids)");
    }
    if (!(spacing > 0.0) || !std::isfinite(spacing)) {
        throw std::invalid_argument("cluster graph: the point spacing must be a positive number");
    }
    const int clusterCount = static_cast<int>(candidateCluster.size());
    if (!supportingPoint.empty() && static_cast<Eigen::Index>(supportingPoint.size()) != n) {
        throw std::invalid_argument("cluster graph: the supporting-point flags must have one "
                                    "entry per point");
    }
    if (!clusterLabel.empty() && static_cast<int>(clusterLabel.size()) != clusterCount) {
        throw std::invalid_argument("cluster graph: one label per cluster is needed (" +
                                    std::to_string(clusterLabel.size()) + " labels for " +
                                    std::to_string(clusterCount) + " clusters)");
    }
    for (Eigen::Index i = 0; i < n; ++i) {
        if (cluster[i] < -1 || cluster[i] >= clusterCount) {
            throw std::invalid_argument("cluster graph: point " + std::to_string(i) +
                                        " has cluster id " + std::to_string(cluster[i]) +
                                        ", outside 0.." + std::to_string(clusterCount - 1));
        }
    }
    auto isCandidate = [&](Eigen::Index i) {
        return cluster[i] >= 0 && candidateCluster[cluster[i]] != 0;
    };
    auto labelOf = [&](int c) { return clusterLabel.empty() ? 0 : clusterLabel[c]; };

    ClusterGraph result;
    result.nodeOfPoint.assign(n, -1);

    // Candidate clusters: their points and centres.
    std::vector<int> start(clusterCount + 1, 0);
    for (Eigen::Index i = 0; i < n; ++i) {
        if (isCandidate(i)) {
            ++start[cluster[i] + 1];
        }
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<int> members(start.back());
    {
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (Eigen::Index i = 0; i < n; ++i) {
            if (isCandidate(i)) {
                members[fill[cluster[i]]++] = static_cast<int>(i);
            }
        }
    }
    std::vector<Eigen::Vector3d> clusterCentre(clusterCount, Eigen::Vector3d::Zero());
    for (int c = 0; c < clusterCount; ++c) {
        for (int m = start[c]; m < start[c + 1]; ++m) {
            clusterCentre[c] += P.row(members[m]).transpose();
        }
        if (start[c + 1] > start[c]) {
            clusterCentre[c] /= static_cast<double>(start[c + 1] - start[c]);
        }
    }

    // Candidate clusters adjacent through the k nearest neighbours of their points.
    std::vector<std::int64_t> clusterPairs;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (!isCandidate(i)) {
            continue;
        }
        for (int j = 0; j < N.k(); ++j) {
            const int q = N.indices(i, j);
            if (isCandidate(q) && cluster[q] != cluster[i]) {
                clusterPairs.push_back(pairKey(cluster[i], cluster[q]));
            }
        }
    }
    std::sort(clusterPairs.begin(), clusterPairs.end());
    clusterPairs.erase(std::unique(clusterPairs.begin(), clusterPairs.end()), clusterPairs.end());
    std::vector<std::vector<int>> clusterNeighbours(clusterCount);
    for (std::int64_t key : clusterPairs) {
        const int a = static_cast<int>(key >> 32);
        const int b = static_cast<int>(key & 0xFFFFFFFF);
        clusterNeighbours[a].push_back(b);
        clusterNeighbours[b].push_back(a);
    }

    // Nodes: adjacent candidate clusters of one label gathered within nodeRadius of the
    // node's first cluster.
    const double nodeRadius = options.nodeRadius * spacing;
    std::vector<int> nodeOfCluster(clusterCount, -1);
    std::vector<int> nodeLabel;
    std::vector<Eigen::Vector3d> centres;
    std::vector<double> weight;
    for (int c = 0; c < clusterCount; ++c) {
        if (!candidateCluster[c] || start[c + 1] == start[c] || nodeOfCluster[c] >= 0) {
            continue;
        }
        const int node = static_cast<int>(centres.size());
        nodeLabel.push_back(labelOf(c));
        centres.emplace_back(Eigen::Vector3d::Zero());
        weight.push_back(0.0);
        std::vector<int> queue{c};
        nodeOfCluster[c] = node;
        for (std::size_t q = 0; q < queue.size(); ++q) {
            const int a = queue[q];
            const double size = start[a + 1] - start[a];
            centres[node] += size * clusterCentre[a];
            weight[node] += size;
            for (int b : clusterNeighbours[a]) {
                if (nodeOfCluster[b] < 0 && labelOf(b) == nodeLabel[node] &&
                    (clusterCentre[b] - clusterCentre[c]).norm() <= nodeRadius) {
                    nodeOfCluster[b] = node;
                    queue.push_back(b);
                }
            }
        }
        centres[node] /= weight[node];
    }
    const int nodeCount = static_cast<int>(centres.size());
    result.counts.nodes = nodeCount;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (isCandidate(i)) {
            result.nodeOfPoint[i] = nodeOfCluster[cluster[i]];
        }
    }

    // G_all: nodes whose clusters are adjacent. G_extended: plus every pair of nodes within
    // extendedRadius.
    std::vector<std::int64_t> edges;
    for (std::int64_t key : clusterPairs) {
        const int a = nodeOfCluster[key >> 32];
        const int b = nodeOfCluster[key & 0xFFFFFFFF];
        if (a != b) {
            edges.push_back(pairKey(a, b));
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    result.counts.allEdges = static_cast<int>(edges.size());
    const double extendedRadius = options.extendedRadius * spacing;
    if (extendedRadius > 0.0) {
        NodeGrid grid(centres, extendedRadius);
        for (int a = 0; a < nodeCount; ++a) {
            grid.forEachWithin(centres[a], extendedRadius, [&](int b) {
                if (b > a) {
                    edges.push_back(pairKey(a, b));
                }
            });
        }
        std::sort(edges.begin(), edges.end());
        edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    }
    result.counts.extendedEdges = static_cast<int>(edges.size()) - result.counts.allEdges;

    // Minimum spanning forest of G_extended (Kruskal), then G_pruned_mst: overlong edges cut.
    std::vector<std::tuple<double, int, int>> weighted;
    weighted.reserve(edges.size());
    for (std::int64_t key : edges) {
        const int a = static_cast<int>(key >> 32);
        const int b = static_cast<int>(key & 0xFFFFFFFF);
        weighted.emplace_back((centres[a] - centres[b]).norm(), a, b);
    }
    std::sort(weighted.begin(), weighted.end());
    Graph graph(centres, spacing);
    DisjointSets forest(nodeCount);
    for (const auto& [length, a, b] : weighted) {
        if (!forest.unite(a, b)) {
            continue;
        }
        ++result.counts.treeEdges;
        if (length > options.maxEdgeLength * spacing) {
            ++result.counts.overlongEdges;
            continue;
        }
        graph.addEdge(a, b);
    }

    // G_pruned_branches, reconnection, and the spurs a reconnection can leave (an end joined
    // to the node beside the other end of a broken cycle leaves that end as a short tip).
    const double minBranch = options.minBranchLength * spacing;
    std::unique_ptr<Support> support;
    if (!supportingPoint.empty()) {
        support = std::make_unique<Support>(
            P, [&](Eigen::Index i) { return supportingPoint[i] != 0 || isCandidate(i); },
            options.supportRadius * spacing);
    }
    result.counts.prunedBranches = pruneShortBranches(graph, minBranch);
    if (options.reconnectRadius > 0.0) {
        result.counts.reconnections = reconnectEnds(graph, options, nodeLabel, support.get());
        result.counts.prunedBranches += pruneShortBranches(graph, minBranch);
        result.counts.reconnections += joinFacingEnds(graph, options, support.get());
        result.counts.reconnections += joinConvergingEnds(graph, options, nodeLabel, support.get());
        // A join at a corner can leave the tip of a third line there as a spur.
        result.counts.prunedBranches += pruneShortBranches(graph, minBranch);
    }
    result.counts.bubbles = removeBubbles(graph, options.maxBubbleLength * spacing);
    result.counts.mergedJunctions =
        mergeCloseJunctions(graph, options.junctionMergeLength * spacing);
    result.counts.droppedComponents = dropShortComponents(
        graph, options.minComponentLength * spacing, options.minOpenComponentLength * spacing);
    if (options.extendReach > 0.0) {
        result.counts.extensions = extendFreeEnds(graph, options, support.get());
    }
    if (options.maxFreeEndLength > 0.0) {
        result.counts.removedFreeEnds = removeFreeEnds(graph, options.maxFreeEndLength * spacing);
    }

    // The joins of converging ends may have added nodes.
    const int finalCount = graph.size();
    result.nodes.resize(finalCount, 3);
    for (int v = 0; v < finalCount; ++v) {
        result.nodes.row(v) = centres[v].transpose();
    }

    // Polylines: chains between nodes of degree other than 2, then the cycles left.
    std::vector<int> junctionOf(finalCount, -1);
    for (int v = 0; v < finalCount; ++v) {
        if (graph.degree(v) >= 3) {
            junctionOf[v] = static_cast<int>(result.junctionNodes.size());
            result.junctionNodes.push_back(v);
        }
    }
    result.network.junctions.resize(static_cast<Eigen::Index>(result.junctionNodes.size()), 3);
    for (std::size_t j = 0; j < result.junctionNodes.size(); ++j) {
        result.network.junctions.row(j) = centres[result.junctionNodes[j]].transpose();
    }
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
    for (int v = 0; v < finalCount; ++v) {
        if (graph.degree(v) == 0 || graph.degree(v) == 2) {
            continue;
        }
        for (int u : graph.neighbours(v)) {
            if (!walked.count(pairKey(v, u))) {
                chains.emplace_back(walk(v, u), false);
            }
        }
    }
    for (int v = 0; v < finalCount; ++v) {
        if (graph.degree(v) == 2 && !walked.count(pairKey(v, graph.neighbours(v)[0]))) {
            std::vector<int> cycle = walk(v, graph.neighbours(v)[0]);
            cycle.pop_back(); // the walk returns to v
            chains.emplace_back(std::move(cycle), true);
        }
    }

    int freeEnds = 0;
    for (auto& [chain, closed] : chains) {
        Polyline line;
        line.closed = closed;
        if (!closed) {
            line.startJunction = junctionOf[chain.front()];
            line.endJunction = junctionOf[chain.back()];
            freeEnds += (line.startJunction < 0 ? 1 : 0) + (line.endJunction < 0 ? 1 : 0);
        }
        std::unordered_map<int, int> votes;
        for (int v : chain) {
            ++votes[nodeLabel[v]];
        }
        line.label = std::min_element(votes.begin(), votes.end(), [](const auto& a, const auto& b) {
                         return std::tie(b.second, a.first) < std::tie(a.second, b.first);
                     })->first;
        PointMatrix points(static_cast<Eigen::Index>(chain.size()), 3);
        for (std::size_t i = 0; i < chain.size(); ++i) {
            points.row(i) = centres[chain[i]].transpose();
        }
        points = smoothPolyline(points, closed, options.smoothingLength * spacing);
        if (options.resampleSpacing > 0.0) {
            points = resamplePolyline(points, closed, options.resampleSpacing * spacing);
        }
        line.points = std::move(points);
        result.network.lines.push_back(std::move(line));
        result.lineNodes.push_back(std::move(chain));
    }
    result.counts.freeEnds = freeEnds;

    // Points of nodes no line runs through any more (pruned, dropped, merged into a
    // junction) are no longer on a node.
    for (Eigen::Index i = 0; i < n; ++i) {
        const int v = result.nodeOfPoint[i];
        if (v >= 0 && graph.degree(v) == 0) {
            result.nodeOfPoint[i] = -1;
        }
    }
    return result;
}

} // namespace featurelines
