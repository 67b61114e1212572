// SPDX-License-Identifier: LGPL-2.1-or-later
// The four joins of free ends as one cone search (joinFreeEnds) and a policy per join.
#include "FeatureLines/network/FreeEndJoins.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>
#include <unordered_map>

namespace featurelines::clustergraph {

double Support::along(const Eigen::Vector3d& a, const Eigen::Vector3d& da, const Eigen::Vector3d& b,
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

namespace {

constexpr double pi = 3.14159265358979323846;

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

/// A new edge from a to b is acceptable: short (within half maxEdgeLength, the reach of the
/// spanning tree's own edges), or running along supporting points on the curve leaving a in
/// direction da and arriving at b in direction db (zero: the straight segment), or no support
/// given.
bool supported(const Support* support, const Eigen::Vector3d& a, const Eigen::Vector3d& da,
               const Eigen::Vector3d& b, const Eigen::Vector3d& db,
               const ClusterGraphOptions& options, double spacing)
{
    return !support || (b - a).norm() <= 0.5 * options.maxEdgeLength * spacing ||
           support->along(a, da, b, db, spacing) >= options.minExtendSupport;
}

bool supported(const Support* support, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
               const ClusterGraphOptions& options, double spacing)
{
    return supported(support, a, Eigen::Vector3d::Zero(), b, Eigen::Vector3d::Zero(), options,
                     spacing);
}

/// The direction at an end is read over the length below which branches count as spurs.
double directionLength(const ClusterGraphOptions& options, double spacing)
{
    return std::max(options.minBranchLength, 1.0) * spacing;
}

// ---- The one search: from every free end, the targets in a cone ------------------------------

/// A node of degree 1, where its line stops.
struct FreeEnd
{
    int node;
    Eigen::Vector3d tip;
    /// The way the line leaves it, read over the join's direction length; zero when the line
    /// has no length there.
    Eigen::Vector3d direction;
};

/// The free ends in node order; those whose line has no direction over `length` are left out
/// unless `keepAll`.
std::vector<FreeEnd> freeEnds(const Graph& g, double length, bool keepAll)
{
    std::vector<FreeEnd> ends;
    for (int v = 0; v < g.size(); ++v) {
        Eigen::Vector3d direction = Eigen::Vector3d::Zero();
        if (g.degree(v) == 1 && (endDirection(g, v, length, direction) || keepAll)) {
            ends.push_back({v, g.centre(v), direction});
        }
    }
    return ends;
}

/// One cone to look in from a free end: around `direction` (the line's, read over `length`),
/// or in any direction, up to `radius`.
struct View
{
    Eigen::Vector3d direction;
    double length;
    double radius;
    bool anyDirection;
};

/// A target in a view: `key` (the distance, or the way, to it) orders the targets of one end
/// and the joins of all ends; `tie` may break equal keys among the targets of one end.
struct Hit
{
    int target;
    double key;
    double tie;
};

/// A join to carry out, from ends[end] to the policy's target.
struct Proposal
{
    double key;
    int end;
    int target;
};

/// Join::tries for a join of pairs of ends: every hit is proposed (tested when carried out).
constexpr std::size_t everyHit = 0;

/// The targets in one view of end e: the first of them (in the join's order) among
/// Join::tries whose way is supported is proposed, or every one for a join of pairs of ends.
/// True when something was proposed.
template <class Join>
bool searchView(Join& join, int e, const View& view, std::vector<Proposal>& proposals)
{
    const FreeEnd& end = join.ends[e];
    std::vector<Hit> hits;
    join.forEachTarget(e, view, [&](int target) {
        Hit hit{target, 0.0, 0.0};
        if (join.inCone(end, view, target, hit)) {
            hits.push_back(hit);
        }
    });
    if constexpr (Join::tries == everyHit) {
        for (const Hit& hit : hits) {
            proposals.push_back({hit.key, e, hit.target});
        }
        return !hits.empty();
    } else {
        std::stable_sort(hits.begin(), hits.end(), Join::before);
        const std::size_t tries = std::min(hits.size(), Join::tries);
        for (std::size_t t = 0; t < tries; ++t) {
            if (join.supports(end, view, hits[t])) {
                proposals.push_back({hits[t].key, e, hits[t].target});
                return true;
            }
        }
        return false;
    }
}

/// The search every join runs. A join policy says:
///   ends                       which free ends look for a target
///   views(end)                 the cones to look in, in turn, until one gives a target
///   forEachTarget(e, view, f)  what counts as a target: nodes within the view's radius, or the
///                              other free ends
///   inCone(end, view, t, hit)  whether t lies in the cone, and its keys
///   tries, before, supports    how many targets are tried, in which order, for which support
///   carryOut(proposal)         what is done on a hit; the proposals of all ends are carried
///                              out nearest first, each checking its ends are still free
/// Returns the number of edges added.
template <class Join> int joinFreeEnds(Join& join)
{
    std::vector<Proposal> proposals;
    for (int e = 0; e < static_cast<int>(join.ends.size()); ++e) {
        for (const View& view : join.views(join.ends[e])) {
            if (searchView(join, e, view, proposals)) {
                break;
            }
        }
    }
    std::sort(proposals.begin(), proposals.end(), [](const Proposal& a, const Proposal& b) {
        return std::tie(a.key, a.end, a.target) < std::tie(b.key, b.end, b.target);
    });
    int added = 0;
    for (const Proposal& p : proposals) {
        added += join.carryOut(p);
    }
    return added;
}

/// What the policies share: the graph, the options and the free ends.
struct JoinBase
{
    JoinBase(Graph& g, const ClusterGraphOptions& options, const Support* support, bool keepAll)
        : g(g), options(options), support(support), spacing(g.spacing()),
          directionLength(featurelines::clustergraph::directionLength(options, spacing)),
          ends(freeEnds(g, directionLength, keepAll))
    {
    }

    /// Not back onto the end's own line a little behind it: `own` holds the distances along
    /// the graph from the end.
    bool farAlongGraph(const std::unordered_map<int, double>& own, int target,
                       double distance) const
    {
        const auto found = own.find(target);
        return found == own.end() || found->second >= options.minCycleRatio * distance;
    }

    Graph& g;
    const ClusterGraphOptions& options;
    const Support* support;
    const double spacing;
    const double directionLength;
    const std::vector<FreeEnd> ends;
};

// ---- The policies ----------------------------------------------------------------------------

/// Reconnection: the nearest node ahead, within reconnectAngle and reconnectRadius, that
/// closes no short cycle and whose way is supported.
struct Reconnection : JoinBase
{
    Reconnection(Graph& g, const ClusterGraphOptions& options, std::vector<int>& labels,
                 const Support* support)
        : JoinBase(g, options, support, false), labels(labels),
          radius(options.reconnectRadius * spacing),
          cosAngle(std::cos(options.reconnectAngle * pi / 180.0)),
          distanceLimit(options.minCycleRatio * radius),
          grid(g.centres(), std::max(radius, spacing))
    {
    }

    std::vector<View> views(const FreeEnd& end)
    {
        own = g.distancesFrom(end.node, distanceLimit);
        return {{end.direction, directionLength, radius, false}};
    }

    template <class F> void forEachTarget(int e, const View& view, F f) const
    {
        grid.forEachWithin(ends[e].tip, view.radius, f);
    }

    bool inCone(const FreeEnd& end, const View& view, int target, Hit& hit) const;

    /// The nearest; of equally near ones, the first met.
    static constexpr std::size_t tries = std::numeric_limits<std::size_t>::max();
    static bool before(const Hit& a, const Hit& b) { return a.key < b.key; }

    bool supports(const FreeEnd& end, const View&, const Hit& hit) const;

    int carryOut(const Proposal& p);

    std::vector<int>& labels;
    const double radius, cosAngle, distanceLimit;
    const NodeGrid grid;
    std::unordered_map<int, double> own; ///< distances along the graph from the current end
};

bool Reconnection::inCone(const FreeEnd& end, const View& view, int target, Hit& hit) const
{
    if (target == end.node || g.degree(target) == 0 || g.hasEdge(end.node, target)) {
        return false;
    }
    const Eigen::Vector3d step = g.centre(target) - end.tip;
    const double distance = step.norm();
    if (!(distance > 0.0) || step.dot(view.direction) < cosAngle * distance ||
        !farAlongGraph(own, target, distance)) {
        return false;
    }
    hit.key = distance;
    return true;
}

bool Reconnection::supports(const FreeEnd& end, const View&, const Hit& hit) const
{
    return supported(support, end.tip, g.centre(hit.target), options, spacing);
}

int Reconnection::carryOut(const Proposal& p)
{
    const int leaf = ends[p.end].node;
    // An earlier reconnection may have reached this end already, or made the new edge a
    // short cycle.
    if (g.degree(leaf) != 1 || g.degree(p.target) == 0 ||
        !farAlongGraph(g.distancesFrom(leaf, distanceLimit), p.target, g.length(leaf, p.target))) {
        return 0;
    }
    // Two free ends whose lines meet at an angle are joined through the corner where
    // they meet: a straight join would cut it.
    Eigen::Vector3d from, to, corner;
    double along = 0.0;
    if (g.degree(p.target) == 1 && endDirection(g, leaf, directionLength, from) &&
        endDirection(g, p.target, directionLength, to) &&
        raysMeet(g.centre(leaf), from, g.centre(p.target), to, radius,
                 0.5 * options.maxEdgeLength * spacing, corner, along) &&
        supported(support, g.centre(leaf), corner, options, spacing) &&
        supported(support, corner, g.centre(p.target), options, spacing)) {
        const int node = g.addNode(corner);
        labels.push_back(labels[leaf]);
        g.addEdge(leaf, node);
        g.addEdge(node, p.target);
    } else {
        g.addEdge(leaf, p.target);
    }
    return 1;
}

/// Facing ends: pairs of free ends each ahead of the other within facingEndsRadius, joined
/// end to end when they are not the two ends of one short piece and the curve they continue
/// into each other on is supported.
struct FacingEnds : JoinBase
{
    FacingEnds(Graph& g, const ClusterGraphOptions& options, const Support* support)
        : JoinBase(g, options, support, false), radius(options.facingEndsRadius * spacing),
          // Half the reconnection's cone without support; the whole cone with it
          // (docs/design/network.md, facing ends).
          cosAngle(std::cos((support ? 1.0 : 0.5) * options.reconnectAngle * pi / 180.0)),
          tips(tipsOf(ends)), grid(tips, radius)
    {
    }

    static std::vector<Eigen::Vector3d> tipsOf(const std::vector<FreeEnd>& ends)
    {
        std::vector<Eigen::Vector3d> tips;
        for (const FreeEnd& end : ends) {
            tips.push_back(end.tip);
        }
        return tips;
    }

    std::vector<View> views(const FreeEnd& end) const
    {
        return {{end.direction, directionLength, radius, false}};
    }

    /// The free ends after e (each pair once).
    template <class F> void forEachTarget(int e, const View& view, F f) const
    {
        grid.forEachWithin(tips[e], view.radius, [&](int b) {
            if (b > e) {
                f(b);
            }
        });
    }

    bool inCone(const FreeEnd& end, const View& view, int b, Hit& hit) const;

    static constexpr std::size_t tries = everyHit;

    int carryOut(const Proposal& p);

    const double radius, cosAngle;
    const std::vector<Eigen::Vector3d> tips;
    const NodeGrid grid;
};

bool FacingEnds::inCone(const FreeEnd& end, const View& view, int b, Hit& hit) const
{
    const Eigen::Vector3d step = tips[b] - end.tip;
    const double distance = step.norm();
    if (distance > 0.0 && step.dot(view.direction) >= cosAngle * distance &&
        -step.dot(ends[b].direction) >= cosAngle * distance) {
        hit.key = distance;
        return true;
    }
    return false;
}

int FacingEnds::carryOut(const Proposal& p)
{
    const FreeEnd &a = ends[p.end], &b = ends[p.target];
    const int u = a.node, v = b.node;
    if (g.degree(u) != 1 || g.degree(v) != 1) {
        return 0;
    }
    if (g.distancesFrom(u, options.minCycleRatio * p.key).count(v)) {
        return 0; // the two ends of one short piece
    }
    // Along the curve the two ends continue into each other.
    if (!supported(support, g.centre(u), a.direction, g.centre(v), b.direction, options, spacing)) {
        return 0;
    }
    g.addEdge(u, v);
    return 1;
}

/// Converging ends: pairs of free ends whose lines, continued straight ahead, meet within
/// twice reconnectRadius, joined through a new node where they meet; further free ends
/// heading for that node join it too.
struct ConvergingEnds : JoinBase
{
    ConvergingEnds(Graph& g, const ClusterGraphOptions& options, std::vector<int>& labels,
                   const Support* support)
        : JoinBase(g, options, support, false), labels(labels),
          reach(2.0 * options.reconnectRadius * spacing),
          tolerance(0.5 * options.maxEdgeLength * spacing)
    {
    }

    std::vector<View> views(const FreeEnd& end) const
    {
        return {{end.direction, directionLength, 2.0 * reach, false}};
    }

    /// The free ends after e (each pair once).
    template <class F> void forEachTarget(int e, const View&, F f) const
    {
        for (int b = e + 1; b < static_cast<int>(ends.size()); ++b) {
            f(b);
        }
    }

    bool inCone(const FreeEnd& end, const View& view, int b, Hit& hit) const;

    static constexpr std::size_t tries = everyHit;

    /// The two rays meet, and the ways from both ends to where they meet are supported.
    bool meet(const FreeEnd& a, const FreeEnd& b, Eigen::Vector3d& where, double& along) const
    {
        return raysMeet(a.tip, a.direction, b.tip, b.direction, reach, tolerance, where, along) &&
               supported(support, a.tip, where, options, spacing) &&
               supported(support, where, b.tip, options, spacing);
    }

    int carryOut(const Proposal& p);

    std::vector<int>& labels;
    const double reach, tolerance;
};

bool ConvergingEnds::inCone(const FreeEnd& end, const View& view, int b, Hit& hit) const
{
    Eigen::Vector3d where;
    double along = 0.0;
    if ((end.tip - ends[b].tip).norm() <= view.radius && meet(end, ends[b], where, along)) {
        hit.key = along;
        return true;
    }
    return false;
}

int ConvergingEnds::carryOut(const Proposal& p)
{
    const FreeEnd &a = ends[p.end], &b = ends[p.target];
    if (g.degree(a.node) != 1 || g.degree(b.node) != 1) {
        return 0;
    }
    Eigen::Vector3d where;
    double unused = 0.0;
    meet(a, b, where, unused);
    const int corner = g.addNode(where);
    labels.push_back(labels[a.node]);
    g.addEdge(a.node, corner);
    g.addEdge(corner, b.node);
    int added = 1;
    // Other free ends heading for the same corner.
    for (const FreeEnd& c : ends) {
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
    return added;
}

/// Extension: straight ahead within extendAngle (plus half maxEdgeLength sideways), up to
/// extendReach, the first node met whose way is supported; the direction read over the spur
/// length, then a half and a quarter of it. With support and nothing ahead, the nearest node
/// within twice reconnectRadius in any direction whose way is supported.
struct Extension : JoinBase
{
    Extension(Graph& g, const ClusterGraphOptions& options, const Support* support)
        : JoinBase(g, options, support, true), reach(options.extendReach * spacing),
          slope(std::tan(options.extendAngle * pi / 180.0)),
          base(0.5 * options.maxEdgeLength * spacing), grid(g.centres(), reach)
    {
    }

    /// The end's direction over the spur length, then over half and a quarter of it (an end a
    /// few spacings past a corner of its line points along its last stretch only over the
    /// shorter ones); last, with support, any direction.
    std::vector<View> views(const FreeEnd& end);

    template <class F> void forEachTarget(int e, const View& view, F f) const
    {
        grid.forEachWithin(ends[e].tip, view.radius, f);
    }

    bool inCone(const FreeEnd& end, const View& view, int target, Hit& hit) const;

    /// A few tries, as the nodes of one line come one after another.
    static constexpr std::size_t tries = 8;
    static bool before(const Hit& a, const Hit& b)
    {
        return std::tie(a.key, a.tie, a.target) < std::tie(b.key, b.tie, b.target);
    }

    /// Along the way the end continues on: leaving in its direction, arriving against the
    /// target's own end direction when that is a free end too (two ends of a curved crease),
    /// else along the chord. Straight in the view of any direction.
    bool supports(const FreeEnd& end, const View& view, const Hit& hit) const;

    int carryOut(const Proposal& p);

    const double reach, slope, base;
    const NodeGrid grid;
    std::unordered_map<int, double> own; ///< distances along the graph from the current end
};

std::vector<View> Extension::views(const FreeEnd& end)
{
    own = g.distancesFrom(end.node, options.minCycleRatio * reach);
    std::vector<View> out;
    for (const double length : {directionLength, 0.5 * directionLength, 0.25 * directionLength}) {
        Eigen::Vector3d direction;
        if (endDirection(g, end.node, length, direction)) {
            out.push_back({direction, length, reach, false});
        }
    }
    if (support) {
        const double near = 2.0 * options.reconnectRadius * spacing;
        out.push_back({Eigen::Vector3d::Zero(), 0.0, std::min(near, reach), true});
    }
    return out;
}

bool Extension::inCone(const FreeEnd& end, const View& view, int target, Hit& hit) const
{
    if (view.anyDirection) {
        const double distance = (g.centre(target) - end.tip).norm();
        hit.key = distance;
        return target != end.node && g.degree(target) > 0 && farAlongGraph(own, target, distance);
    }
    if (target == end.node || g.degree(target) == 0) {
        return false;
    }
    const Eigen::Vector3d step = g.centre(target) - end.tip;
    const double distance = step.norm();
    double along = step.dot(view.direction);
    const double aside = (step - along * view.direction).norm();
    // Ahead within the cone, or touching the end whatever the direction (an end that stops
    // beside another line is on it).
    if (distance <= base) {
        along = std::max(along, 0.0);
    } else if (!(along > 0.0) || aside > base + along * slope) {
        return false;
    }
    if (!farAlongGraph(own, target, distance)) {
        return false;
    }
    // Where the way ahead meets a line: the node of the first line met that lies nearest
    // to the way (a node beside it lies as much farther).
    hit.key = along + aside;
    hit.tie = aside;
    return true;
}

bool Extension::supports(const FreeEnd& end, const View& view, const Hit& hit) const
{
    if (view.anyDirection) {
        return supported(support, end.tip, g.centre(hit.target), options, spacing);
    }
    const Eigen::Vector3d chord = g.centre(hit.target) - end.tip;
    Eigen::Vector3d arrival = chord.normalized();
    Eigen::Vector3d other;
    if (g.degree(hit.target) == 1 && endDirection(g, hit.target, view.length, other)) {
        arrival = -other;
    }
    return supported(support, end.tip, view.direction, g.centre(hit.target), -arrival, options,
                     spacing);
}

int Extension::carryOut(const Proposal& p)
{
    const int leaf = ends[p.end].node;
    // An earlier extension may have reached this end already.
    if (g.degree(leaf) != 1 || g.degree(p.target) == 0 || g.hasEdge(leaf, p.target)) {
        return 0;
    }
    g.addEdge(leaf, p.target);
    return 1;
}

} // namespace

int reconnectEnds(Graph& g, const ClusterGraphOptions& options, std::vector<int>& labels,
                  const Support* support)
{
    Reconnection join(g, options, labels, support);
    return joinFreeEnds(join);
}

int joinFacingEnds(Graph& g, const ClusterGraphOptions& options, const Support* support)
{
    if (!(options.facingEndsRadius * g.spacing() > 0.0)) {
        return 0;
    }
    FacingEnds join(g, options, support);
    return joinFreeEnds(join);
}

int joinConvergingEnds(Graph& g, const ClusterGraphOptions& options, std::vector<int>& labels,
                       const Support* support)
{
    if (!(2.0 * options.reconnectRadius * g.spacing() > 0.0)) {
        return 0;
    }
    ConvergingEnds join(g, options, labels, support);
    return joinFreeEnds(join);
}

int extendFreeEnds(Graph& g, const ClusterGraphOptions& options, const Support* support)
{
    if (!(options.extendReach * g.spacing() > 0.0)) {
        return 0;
    }
    Extension join(g, options, support);
    return joinFreeEnds(join);
}

} // namespace featurelines::clustergraph
