// SPDX-License-Identifier: LGPL-2.1-or-later
// Crease placement: fitted planes around every node, the node onto their meeting line.
#include "FeatureLines/sharp/CreasePlacement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "FeatureLines/sharp/PlaneFit.h"

namespace featurelines {

namespace {

constexpr double pi = 3.14159265358979323846;

/// Where a node of the graph goes: onto a crease line, onto a corner, or nowhere.
struct Placement
{
    enum Kind
    {
        None,
        Line,
        Corner
    } kind = None;
    Eigen::Vector3d point = Eigen::Vector3d::Zero(); // on the line, or the corner
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();

    Eigen::Vector3d project(const Eigen::Vector3d& x) const
    {
        switch (kind) {
        case Line:
            return point + direction * direction.dot(x - point);
        case Corner:
            return point;
        default:
            return x;
        }
    }
};

class CreasePlacer
{
public:
    CreasePlacer(const CreasePlacementInput& in, const SharpEdgeOptions& options)
        : P_(in.P), N_(in.N), normals_(in.normals), sharp_(in.sharp), options_(options),
          radius_(options.fitRadius * in.spacing), maxShift_(options.maxCreaseShift * in.spacing),
          sinMinAngle_(std::sin(options.minCreaseAngle * pi / 180.0)), stamp_(in.P.rows(), -1)
    {
    }

    Placement place(int node, const std::vector<int>& seeds, const Eigen::Vector3d& centre,
                    bool junction);

private:
    Placement cornerOfThreePlanes(const std::vector<Plane>& planes,
                                  const Eigen::Vector3d& centre) const;
    Placement lineOfTwoPlanes(const std::vector<Plane>& planes,
                              const Eigen::Vector3d& centre) const;
    std::vector<Plane> fitNearbyClusters(int node, const std::vector<int>& seeds,
                                         const Eigen::Vector3d& centre, double radius);

    const PointMatrix& P_;
    const Neighbourhoods& N_;
    const NormalMatrix* normals_;
    const SharpEdges& sharp_;
    const SharpEdgeOptions& options_;
    double radius_;
    double maxShift_;
    double sinMinAngle_;
    std::vector<int> stamp_;
};

/// The placement of a node whose points are `seeds` and centre `centre`; at a junction
/// a corner of three planes is tried first.
Placement CreasePlacer::place(int node, const std::vector<int>& seeds,
                              const Eigen::Vector3d& centre, bool junction)
{
    // A junction's node can sit a few spacings along one edge from the corner (where the
    // reconnection met the line), so its search reaches that much farther for the third
    // face.
    const std::vector<Plane> planes =
        fitNearbyClusters(node, seeds, centre, junction ? radius_ + maxShift_ : radius_);
    if (junction) {
        const Placement corner = cornerOfThreePlanes(planes, centre);
        if (corner.kind == Placement::Corner) {
            return corner;
        }
    }
    return lineOfTwoPlanes(planes, centre);
}

/// The corner of three of the planes nearest to the centre, within fitRadius (None if none).
Placement CreasePlacer::cornerOfThreePlanes(const std::vector<Plane>& planes,
                                            const Eigen::Vector3d& centre) const
{
    Placement best;
    double bestShift = radius_;
    for (std::size_t a = 0; a < planes.size(); ++a) {
        for (std::size_t b = a + 1; b < planes.size(); ++b) {
            for (std::size_t c = b + 1; c < planes.size(); ++c) {
                Eigen::Matrix3d m;
                m << planes[a].normal.transpose(), planes[b].normal.transpose(),
                    planes[c].normal.transpose();
                // Three planes meet in a well-defined corner only when no two of them
                // are nearly parallel and they do not share a line.
                if (std::abs(m.determinant()) < sinMinAngle_ * sinMinAngle_) {
                    continue;
                }
                const Eigen::Vector3d corner = m.fullPivLu().solve(
                    Eigen::Vector3d(planes[a].offset, planes[b].offset, planes[c].offset));
                const double shift = (corner - centre).norm();
                if (shift < bestShift) {
                    bestShift = shift;
                    best.kind = Placement::Corner;
                    best.point = corner;
                }
            }
        }
    }
    return best;
}

/// The crease line of two of the planes nearest to the centre, within maxCreaseShift (None if
/// none).
Placement CreasePlacer::lineOfTwoPlanes(const std::vector<Plane>& planes,
                                        const Eigen::Vector3d& centre) const
{
    Placement best;
    double bestShift = maxShift_;
    // The pair of faces whose crease passes closest to the node: near a corner every
    // pair's crease passes close, and any of them is then a good place.
    for (std::size_t a = 0; a < planes.size(); ++a) {
        for (std::size_t b = a + 1; b < planes.size(); ++b) {
            const Eigen::Vector3d direction = planes[a].normal.cross(planes[b].normal);
            if (direction.norm() < sinMinAngle_) {
                continue;
            }
            const Eigen::Vector3d onLine = closestOnIntersection(planes[a], planes[b], centre);
            const double shift = (onLine - centre).norm();
            if (shift < bestShift) {
                bestShift = shift;
                best.kind = Placement::Line;
                best.point = onLine;
                best.direction = direction.normalized();
            }
        }
    }
    return best;
}

/// Planes fitted to the points of every large cluster within `radius` of the centre,
/// reached from the node's points through the neighbourhoods.
std::vector<Plane> CreasePlacer::fitNearbyClusters(int node, const std::vector<int>& seeds,
                                                   const Eigen::Vector3d& centre, double radius)
{
    const FirstOrderSegmentation& s = sharp_.segmentation;
    std::vector<int> queue;
    for (int seed : seeds) {
        if (stamp_[seed] != node) {
            stamp_[seed] = node;
            queue.push_back(seed);
        }
    }
    struct Members
    {
        std::vector<Eigen::Vector3d> points;
        std::vector<Eigen::Vector3d> normals; // empty without the cloud's normals
    };
    std::unordered_map<int, Members> byCluster;
    const double r2 = radius * radius;
    for (std::size_t q = 0; q < queue.size(); ++q) {
        const int i = queue[q];
        const int c = s.cluster[i];
        if (!s.smallCluster[c] && (sharp_.isBoundary.empty() || !sharp_.isBoundary[i])) {
            Members& members = byCluster[c];
            members.points.push_back(P_.row(i).transpose());
            if (normals_ != nullptr) {
                members.normals.push_back(normals_->row(i).transpose());
            }
        }
        for (int j = 0; j < N_.k(); ++j) {
            const int u = N_.indices(i, j);
            if (stamp_[u] != node && (P_.row(u).transpose() - centre).squaredNorm() <= r2) {
                stamp_[u] = node;
                queue.push_back(u);
            }
        }
    }
    // In cluster order, so the result does not depend on the hash map's order.
    std::vector<int> clusters;
    for (const auto& entry : byCluster) {
        if (static_cast<int>(entry.second.points.size()) >= options_.minFitPoints) {
            clusters.push_back(entry.first);
        }
    }
    std::sort(clusters.begin(), clusters.end());
    std::vector<Plane> planes;
    for (int c : clusters) {
        const Members& members = byCluster[c];
        planes.push_back(normals_ != nullptr
                             ? fitPlaneByNormals(members.points, members.normals,
                                                 options_.minFitPoints)
                             : fitPlane(members.points, options_.minFitPoints));
    }
    return planes;
}

/// Drops the vertices where the line folds back on itself (a node projected behind its
/// predecessor) and repeated vertices; `nodes` follows the vertices.
void removeFolds(std::vector<Eigen::Vector3d>& vertices, std::vector<int>& nodes, bool closed,
                 double tolerance)
{
    for (bool changed = true; changed && vertices.size() > 2;) {
        changed = false;
        const std::size_t m = vertices.size();
        for (std::size_t i = 0; i < m; ++i) {
            if (!closed && (i == 0 || i + 1 == m)) {
                continue;
            }
            const Eigen::Vector3d& before = vertices[(i + m - 1) % m];
            const Eigen::Vector3d& after = vertices[(i + 1) % m];
            const Eigen::Vector3d in = vertices[i] - before;
            const Eigen::Vector3d out = after - vertices[i];
            if (in.norm() <= tolerance || out.norm() <= tolerance || in.dot(out) < 0.0) {
                vertices.erase(vertices.begin() + static_cast<std::ptrdiff_t>(i));
                nodes.erase(nodes.begin() + static_cast<std::ptrdiff_t>(i));
                changed = true;
                break;
            }
        }
    }
}

/// The points of every node, to start the search for the faces around it.
std::vector<std::vector<int>> pointsOfNodes(const ClusterGraph& graph, Eigen::Index n)
{
    const int nodeCount = static_cast<int>(graph.nodes.rows());
    std::vector<std::vector<int>> nodePoints(nodeCount);
    for (Eigen::Index i = 0; i < n; ++i) {
        if (graph.nodeOfPoint[i] >= 0) {
            nodePoints[graph.nodeOfPoint[i]].push_back(static_cast<int>(i));
        }
    }
    // A node where the lines of free ends were joined has no points of its own: the search
    // for its faces starts from the points of the nodes beside it on its lines.
    for (const std::vector<int>& nodes : graph.lineNodes) {
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            if (!nodePoints[nodes[i]].empty()) {
                continue;
            }
            for (std::size_t j : {i - 1, i + 1}) {
                if (j < nodes.size() && nodes[j] != nodes[i]) {
                    const std::vector<int>& beside = nodePoints[nodes[j]];
                    nodePoints[nodes[i]].insert(nodePoints[nodes[i]].end(), beside.begin(),
                                                beside.end());
                }
            }
        }
    }
    return nodePoints;
}

/// #nodes nonzero for the junction nodes.
std::vector<char> junctionFlags(const ClusterGraph& graph)
{
    std::vector<char> isJunction(graph.nodes.rows(), 0);
    for (int v : graph.junctionNodes) {
        isJunction[v] = 1;
    }
    return isJunction;
}

/// The placement of the nodes of sharp lines and of every junction (a sharp line may end on
/// a boundary line there); the other nodes stay where they are.
std::vector<Placement> placeNodes(const CreasePlacementInput& in, const SharpEdgeOptions& options,
                                  const std::vector<std::vector<int>>& nodePoints,
                                  const std::vector<char>& isJunction)
{
    const ClusterGraph& graph = in.graph;
    const int nodeCount = static_cast<int>(graph.nodes.rows());
    std::vector<char> needed(nodeCount, 0);
    for (std::size_t l = 0; l < graph.lineNodes.size(); ++l) {
        if (graph.network.lines[l].label == sharpLineLabel) {
            for (int v : graph.lineNodes[l]) {
                needed[v] = 1;
            }
        }
    }
    std::vector<Placement> placement(nodeCount);
    CreasePlacer placer(in, options);
    for (int v = 0; v < nodeCount; ++v) {
        if (needed[v] || isJunction[v]) {
            placement[v] =
                placer.place(v, nodePoints[v], graph.nodes.row(v).transpose(), isJunction[v] != 0);
        }
    }
    return placement;
}

/// Around a junction, within a reach: the nodes of its boundary lines and its own node (the
/// junction may be a boundary node itself), and the sum of the directions from its sharp
/// lines' nodes to it.
struct JunctionRim
{
    std::vector<int> rimNodes;
    Eigen::Vector3d outwards = Eigen::Vector3d::Zero();
};

JunctionRim rimAroundJunction(const ClusterGraph& graph, std::size_t j, double reach)
{
    const int v = graph.junctionNodes[j];
    const Eigen::Vector3d centre = graph.nodes.row(v).transpose();
    JunctionRim rim;
    rim.rimNodes = {v};
    for (std::size_t l = 0; l < graph.lineNodes.size(); ++l) {
        const std::vector<int>& nodes = graph.lineNodes[l];
        const Polyline& line = graph.network.lines[l];
        if (line.closed || nodes.size() < 2) {
            continue;
        }
        for (int side = 0; side < 2; ++side) {
            if ((side == 0 ? line.startJunction : line.endJunction) != static_cast<int>(j)) {
                continue;
            }
            for (std::size_t i = 1; i < nodes.size(); ++i) {
                const int u = nodes[side == 0 ? i : nodes.size() - 1 - i];
                if ((graph.nodes.row(u).transpose() - centre).norm() > reach) {
                    break;
                }
                if (line.label == boundaryLineLabel) {
                    rim.rimNodes.push_back(u);
                } else {
                    rim.outwards += centre - graph.nodes.row(u).transpose();
                }
            }
        }
    }
    return rim;
}

/// Where a sharp line meets the boundary, the junction node is often a sharp node a few
/// spacings short of the rim: it slides along its crease, away from its sharp lines, to
/// the last boundary point lying on the crease (within a spacing of it) near the junction.
void slideJunctionsToRim(const CreasePlacementInput& in, const SharpEdgeOptions& options,
                         const std::vector<std::vector<int>>& nodePoints,
                         std::vector<Placement>& placement)
{
    const ClusterGraph& graph = in.graph;
    const double spacing = in.spacing;
    const double reach = options.fitRadius * spacing;
    for (std::size_t j = 0; j < graph.junctionNodes.size(); ++j) {
        Placement& p = placement[graph.junctionNodes[j]];
        if (p.kind != Placement::Line) {
            continue;
        }
        const JunctionRim rim = rimAroundJunction(graph, j, reach);
        if (rim.rimNodes.size() == 1 || rim.outwards.norm() <= 0.0) {
            continue;
        }
        const Eigen::Vector3d d = p.direction.dot(rim.outwards) >= 0.0 ? p.direction : -p.direction;
        double farthest = -std::numeric_limits<double>::infinity();
        for (int u : rim.rimNodes) {
            for (int i : nodePoints[u]) {
                const Eigen::Vector3d x = in.P.row(i).transpose() - p.point;
                const double t = x.dot(d);
                if ((x - t * d).norm() <= spacing) {
                    farthest = std::max(farthest, t);
                }
            }
        }
        if (std::isfinite(farthest)) {
            p.kind = Placement::Corner;
            p.point += farthest * d;
        }
    }
}

/// The vertices of a sharp line after fold removal resampled at `step`, every new vertex put
/// back on the crease of the nearer of the two nodes around it.
PointMatrix resampledOnCreases(const std::vector<Eigen::Vector3d>& vertices,
                               const std::vector<int>& nodes, bool closed,
                               const std::vector<Placement>& placement, double step)
{
    const std::size_t m = vertices.size();
    PointMatrix points(static_cast<Eigen::Index>(m), 3);
    std::vector<double> arc(m + 1, 0.0);
    for (std::size_t i = 0; i < m; ++i) {
        points.row(i) = vertices[i].transpose();
        if (i > 0) {
            arc[i] = arc[i - 1] + (vertices[i] - vertices[i - 1]).norm();
        }
    }
    arc[m] = arc[m - 1] + (closed ? (vertices[0] - vertices[m - 1]).norm() : 0.0);
    if (!(step > 0.0 && m >= 2)) {
        return points;
    }
    PointMatrix resampled = resamplePolyline(points, closed, step);
    const Eigen::Index r = resampled.rows();
    const double total = closed ? arc[m] : arc[m - 1];
    const Eigen::Index count = closed ? r : r - 1;
    std::size_t segment = 0;
    for (Eigen::Index i = 0; i < r; ++i) {
        if (!closed && (i == 0 || i == r - 1)) {
            continue;
        }
        const double t = total * static_cast<double>(i) / static_cast<double>(count);
        while (segment + 1 < m && arc[segment + 1] < t) {
            ++segment;
        }
        const std::size_t after = (segment + 1) % m;
        const bool nearerBefore = t - arc[segment] <= arc[segment + 1] - t;
        const Placement& p = placement[nodes[nearerBefore ? segment : after]];
        if (p.kind == Placement::Line) {
            resampled.row(i) = p.project(resampled.row(i).transpose()).transpose();
        }
    }
    return resampled;
}

/// Line l of the graph: a sharp line through its placed nodes, folds removed, resampled on
/// the creases; another line through its nodes (placed at junctions), smoothed and resampled
/// as options.graph says.
Polyline placedLine(const CreasePlacementInput& in, const SharpEdgeOptions& options,
                    const std::vector<Placement>& placement, const std::vector<char>& isJunction,
                    std::size_t l)
{
    const ClusterGraph& graph = in.graph;
    const double spacing = in.spacing;
    auto placed = [&](int v) { return placement[v].project(graph.nodes.row(v).transpose()); };
    Polyline line = graph.network.lines[l];
    std::vector<int> nodes = graph.lineNodes[l];
    std::vector<Eigen::Vector3d> vertices;
    for (int v : nodes) {
        vertices.push_back(line.label == sharpLineLabel || isJunction[v]
                               ? placed(v)
                               : Eigen::Vector3d(graph.nodes.row(v).transpose()));
    }
    if (line.label != sharpLineLabel) {
        PointMatrix points(static_cast<Eigen::Index>(vertices.size()), 3);
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            points.row(i) = vertices[i].transpose();
        }
        points = smoothPolyline(points, line.closed, options.graph.smoothingLength * spacing);
        if (options.graph.resampleSpacing > 0.0) {
            points = resamplePolyline(points, line.closed, options.graph.resampleSpacing * spacing);
        }
        line.points = std::move(points);
        return line;
    }
    removeFolds(vertices, nodes, line.closed, 1e-9 * spacing);
    line.points = resampledOnCreases(vertices, nodes, line.closed, placement,
                                     options.resampleSpacing * spacing);
    return line;
}

} // namespace

LineNetwork placeOnCreases(const CreasePlacementInput& in, const SharpEdgeOptions& options)
{
    const ClusterGraph& graph = in.graph;
    const std::vector<std::vector<int>> nodePoints = pointsOfNodes(graph, in.P.rows());
    const std::vector<char> isJunction = junctionFlags(graph);
    std::vector<Placement> placement = placeNodes(in, options, nodePoints, isJunction);
    slideJunctionsToRim(in, options, nodePoints, placement);

    LineNetwork network;
    network.junctions.resize(graph.network.junctions.rows(), 3);
    for (std::size_t j = 0; j < graph.junctionNodes.size(); ++j) {
        const int v = graph.junctionNodes[j];
        network.junctions.row(j) = placement[v].project(graph.nodes.row(v).transpose()).transpose();
    }
    for (std::size_t l = 0; l < graph.network.lines.size(); ++l) {
        network.lines.push_back(placedLine(in, options, placement, isJunction, l));
    }
    return network;
}

} // namespace featurelines
