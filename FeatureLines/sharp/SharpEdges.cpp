// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/sharp/SharpEdges.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "FeatureLines/neighbourhoods/Normals.h"

namespace featurelines {

namespace {

constexpr double pi = 3.14159265358979323846;

struct Plane
{
    Eigen::Vector3d normal;
    double offset; // normal . x = offset
};

/// Least-squares plane through `points` (principal component analysis), refitted once
/// without the points farther than 2.5 times the RMS distance (points of the other face that
/// the segmentation gave to this one).
Plane fitPlane(const std::vector<Eigen::Vector3d>& points, int minPoints)
{
    auto fit = [](const std::vector<const Eigen::Vector3d*>& use) {
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        for (const auto* p : use) {
            mean += *p;
        }
        mean /= static_cast<double>(use.size());
        Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
        for (const auto* p : use) {
            const Eigen::Vector3d d = *p - mean;
            covariance += d * d.transpose();
        }
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
        solver.computeDirect(covariance);
        const Eigen::Vector3d normal = solver.eigenvectors().col(0).normalized();
        return Plane{normal, normal.dot(mean)};
    };
    std::vector<const Eigen::Vector3d*> use;
    for (const auto& p : points) {
        use.push_back(&p);
    }
    Plane plane = fit(use);
    double sum = 0.0;
    for (const auto* p : use) {
        sum += std::pow(plane.normal.dot(*p) - plane.offset, 2);
    }
    const double limit = 2.5 * std::sqrt(sum / static_cast<double>(use.size()));
    std::vector<const Eigen::Vector3d*> kept;
    for (const auto* p : use) {
        if (std::abs(plane.normal.dot(*p) - plane.offset) <= limit) {
            kept.push_back(p);
        }
    }
    if (static_cast<int>(kept.size()) >= minPoints && kept.size() < use.size()) {
        plane = fit(kept);
    }
    return plane;
}

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

/// The point of the line {x : a.x = a.offset, b.x = b.offset} closest to c.
Eigen::Vector3d closestOnIntersection(const Plane& a, const Plane& b, const Eigen::Vector3d& c)
{
    Eigen::Matrix2d gram;
    gram << 1.0, a.normal.dot(b.normal), a.normal.dot(b.normal), 1.0;
    const Eigen::Vector2d rhs(a.offset - a.normal.dot(c), b.offset - b.normal.dot(c));
    const Eigen::Vector2d w = gram.inverse() * rhs;
    return c + w(0) * a.normal + w(1) * b.normal;
}

class CreasePlacer
{
public:
    CreasePlacer(const PointMatrix& P, const Neighbourhoods& N, const SharpEdges& sharp,
                 double spacing, const SharpEdgeOptions& options)
        : P_(P), N_(N), sharp_(sharp), options_(options), radius_(options.fitRadius * spacing),
          maxShift_(options.maxCreaseShift * spacing),
          sinMinAngle_(std::sin(options.minCreaseAngle * pi / 180.0)), stamp_(P.rows(), -1)
    {
    }

    /// The placement of a node whose points are `seeds` and centre `centre`; at a junction
    /// a corner of three planes is tried first.
    Placement place(int node, const std::vector<int>& seeds, const Eigen::Vector3d& centre,
                    bool junction)
    {
        // A junction's node can sit a few spacings along one edge from the corner (where the
        // reconnection met the line), so its search reaches that much farther for the third
        // face.
        const std::vector<Plane> planes =
            fitNearbyClusters(node, seeds, centre, junction ? radius_ + maxShift_ : radius_);
        Placement best;
        double bestShift = radius_;
        if (junction) {
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
            if (best.kind == Placement::Corner) {
                return best;
            }
        }
        bestShift = maxShift_;
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

private:
    /// Planes fitted to the points of every large cluster within `radius` of the centre,
    /// reached from the node's points through the neighbourhoods.
    std::vector<Plane> fitNearbyClusters(int node, const std::vector<int>& seeds,
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
        std::unordered_map<int, std::vector<Eigen::Vector3d>> byCluster;
        const double r2 = radius * radius;
        for (std::size_t q = 0; q < queue.size(); ++q) {
            const int i = queue[q];
            const int c = s.cluster[i];
            if (!s.smallCluster[c] && (sharp_.isBoundary.empty() || !sharp_.isBoundary[i])) {
                byCluster[c].push_back(P_.row(i).transpose());
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
            if (static_cast<int>(entry.second.size()) >= options_.minFitPoints) {
                clusters.push_back(entry.first);
            }
        }
        std::sort(clusters.begin(), clusters.end());
        std::vector<Plane> planes;
        for (int c : clusters) {
            planes.push_back(fitPlane(byCluster[c], options_.minFitPoints));
        }
        return planes;
    }

    const PointMatrix& P_;
    const Neighbourhoods& N_;
    const SharpEdges& sharp_;
    const SharpEdgeOptions& options_;
    double radius_;
    double maxShift_;
    double sinMinAngle_;
    std::vector<int> stamp_;
};

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

void requireSurface(const PointMatrix& P, double spacing)
{
    // Over an even stride of at most ~100 000 points.
    const Eigen::Index stride = std::max<Eigen::Index>(1, P.rows() / 100000);
    const Eigen::Matrix3d covariance = covarianceOf(P, stride);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance, Eigen::EigenvaluesOnly);
    // The middle eigenvalue is the spread across the cloud's main direction.
    if (std::sqrt(std::max(0.0, solver.eigenvalues()(1))) < spacing) {
        throw std::invalid_argument("sharp edges: the points lie on a line (or a strip narrower "
                                    "than the point spacing); there is no surface to have edges");
    }
}

} // namespace

SharpEdges extractSharpEdges(const PointMatrix& P, const NormalMatrix& normals,
                             const Neighbourhoods& N, double spacing,
                             const SharpEdgeOptions& options)
{
    const Eigen::Index n = P.rows();
    if (normals.rows() != n || N.size() != n) {
        throw std::invalid_argument(
            "sharp edges: the normals and neighbourhoods must have one row per point (" +
            std::to_string(n) + " points, " + std::to_string(normals.rows()) + " normals, " +
            std::to_string(N.size()) + " neighbourhoods)");
    }
    if (!(spacing > 0.0) || !std::isfinite(spacing)) {
        throw std::invalid_argument("sharp edges: the point spacing must be a positive number");
    }
    if (!(options.fitRadius > 0.0) || options.minFitPoints < 3 ||
        !(options.resampleSpacing >= 0.0)) {
        throw std::invalid_argument(
            "sharp edges: the fit radius must be positive, the fit needs "
            "at least 3 points and the resampling step must not be negative");
    }
    requireSurface(P, spacing);

    SharpEdges result;
    result.segmentation = segmentByNormals(P, normals, N, spacing, options.segmentation);
    const FirstOrderSegmentation& s = result.segmentation;
    result.isSharpCandidate.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        result.isSharpCandidate[i] = s.isCandidate(i) ? 1 : 0;
    }

    // The graph's clusters: the segmentation's, with every boundary point taken out into a
    // candidate cluster of its own, labelled as boundary.
    std::vector<int> cluster = s.cluster;
    std::vector<char> candidate = s.smallCluster;
    std::vector<int> label(candidate.size(), sharpLineLabel);
    result.isBoundary.assign(n, 0);
    if (options.includeBoundary) {
        result.isBoundary = boundaryPoints(P, normals, N, options.boundary);
        for (Eigen::Index i = 0; i < n; ++i) {
            if (result.isBoundary[i]) {
                cluster[i] = static_cast<int>(candidate.size());
                candidate.push_back(1);
                label.push_back(boundaryLineLabel);
            }
        }
    }
    ClusterGraphOptions graphOptions = options.graph;
    graphOptions.smoothingLength = 0.0;
    graphOptions.resampleSpacing = 0.0;
    // Free ends are extended only along points whose normals spread as a crease's do: a
    // crease that left too few candidates (noise thins them) still bends the normals. Beyond
    // the segmentation's limit and beyond what noise gives (noiseSpreadTail): above noise of
    // about 0.3 spacing the limit is clamped below the noise's own spread, a third of a
    // plane's points pass it, and every way across a face found support.
    const double supportAngle = std::max(s.growAngle, s.noiseSpreadLimit);
    std::vector<char> bending(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        bending[i] = s.spread(i) > supportAngle ? 1 : 0;
    }
    ClusterGraphInput graphInput{P, N, cluster, candidate, spacing};
    graphInput.clusterLabel = &label;
    graphInput.supportingPoint = &bending;
    const ClusterGraph graph = buildClusterGraph(graphInput, graphOptions);
    result.counts = graph.counts;

    // The points of every node, to start the search for the faces around it.
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
    std::vector<char> isJunction(nodeCount, 0);
    for (int v : graph.junctionNodes) {
        isJunction[v] = 1;
    }
    // Nodes to place: those of sharp lines, and every junction (a sharp line may end on a
    // boundary line there).
    std::vector<char> needed(nodeCount, 0);
    for (std::size_t l = 0; l < graph.lineNodes.size(); ++l) {
        if (graph.network.lines[l].label == sharpLineLabel) {
            for (int v : graph.lineNodes[l]) {
                needed[v] = 1;
            }
        }
    }
    std::vector<Placement> placement(nodeCount);
    CreasePlacer placer(P, N, result, spacing, options);
    for (int v = 0; v < nodeCount; ++v) {
        if (needed[v] || isJunction[v]) {
            placement[v] =
                placer.place(v, nodePoints[v], graph.nodes.row(v).transpose(), isJunction[v] != 0);
        }
    }
    // Where a sharp line meets the boundary, the junction node is often a sharp node a few
    // spacings short of the rim: it slides along its crease, away from its sharp lines, to
    // the last boundary point lying on the crease (within a spacing of it) near the junction.
    const double reach = options.fitRadius * spacing;
    for (std::size_t j = 0; j < graph.junctionNodes.size(); ++j) {
        const int v = graph.junctionNodes[j];
        Placement& p = placement[v];
        if (p.kind != Placement::Line) {
            continue;
        }
        const Eigen::Vector3d centre = graph.nodes.row(v).transpose();
        Eigen::Vector3d outwards = Eigen::Vector3d::Zero();
        std::vector<int> rimNodes{v}; // the junction may be a boundary node itself
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
                        rimNodes.push_back(u);
                    } else {
                        outwards += centre - graph.nodes.row(u).transpose();
                    }
                }
            }
        }
        if (rimNodes.size() == 1 || outwards.norm() <= 0.0) {
            continue;
        }
        const Eigen::Vector3d d = p.direction.dot(outwards) >= 0.0 ? p.direction : -p.direction;
        double farthest = -std::numeric_limits<double>::infinity();
        for (int u : rimNodes) {
            for (int i : nodePoints[u]) {
                const Eigen::Vector3d x = P.row(i).transpose() - p.point;
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
    auto placed = [&](int v) { return placement[v].project(graph.nodes.row(v).transpose()); };

    result.network.junctions.resize(graph.network.junctions.rows(), 3);
    for (std::size_t j = 0; j < graph.junctionNodes.size(); ++j) {
        result.network.junctions.row(j) = placed(graph.junctionNodes[j]).transpose();
    }
    const double step = options.resampleSpacing * spacing;
    for (std::size_t l = 0; l < graph.network.lines.size(); ++l) {
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
                points =
                    resamplePolyline(points, line.closed, options.graph.resampleSpacing * spacing);
            }
            line.points = std::move(points);
            result.network.lines.push_back(std::move(line));
            continue;
        }
        // Sharp line: placed nodes, folds removed, resampled, and every new vertex put back
        // on the crease of the nearer of the two nodes around it.
        removeFolds(vertices, nodes, line.closed, 1e-9 * spacing);
        const std::size_t m = vertices.size();
        PointMatrix points(static_cast<Eigen::Index>(m), 3);
        std::vector<double> arc(m + 1, 0.0);
        for (std::size_t i = 0; i < m; ++i) {
            points.row(i) = vertices[i].transpose();
            if (i > 0) {
                arc[i] = arc[i - 1] + (vertices[i] - vertices[i - 1]).norm();
            }
        }
        arc[m] = arc[m - 1] + (line.closed ? (vertices[0] - vertices[m - 1]).norm() : 0.0);
        if (step > 0.0 && m >= 2) {
            PointMatrix resampled = resamplePolyline(points, line.closed, step);
            const Eigen::Index r = resampled.rows();
            const double total = line.closed ? arc[m] : arc[m - 1];
            const Eigen::Index count = line.closed ? r : r - 1;
            std::size_t segment = 0;
            for (Eigen::Index i = 0; i < r; ++i) {
                if (!line.closed && (i == 0 || i == r - 1)) {
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
            points = std::move(resampled);
        }
        line.points = std::move(points);
        result.network.lines.push_back(std::move(line));
    }
    return result;
}

} // namespace featurelines
