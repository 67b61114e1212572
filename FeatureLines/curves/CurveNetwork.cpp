// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/curves/CurveNetwork.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "FeatureLines/curves/CurveFit.h"
#include "FeatureLines/curves/LineCorners.h"

namespace featurelines {

const char* curveKindName(CurveKind kind)
{
    switch (kind) {
    case CurveKind::Segment:
        return "segment";
    case CurveKind::Arc:
        return "arc";
    case CurveKind::Circle:
        return "circle";
    case CurveKind::BSpline:
        return "bspline";
    }
    return "bspline";
}

namespace {

using Vec3 = Eigen::Vector3d;

constexpr double pi = 3.14159265358979323846;

Vec3 row(const PointMatrix& P, Eigen::Index i)
{
    return P.row(i).transpose();
}

/// A place on a line where an edge starts or ends: the point `t` of the way along the
/// line's segment `segment` (from vertex `segment` to the next), and the network vertex there.
struct Split
{
    int segment = 0;
    double t = 0.0;
    int vertex = -1;
    bool corner = false;
    double position() const { return segment + t; }
};

/// The nearest point of line `l` to p: its segment, the fraction along it and the distance.
struct LinePoint
{
    int segment = -1;
    double t = 0.0;
    double distance = std::numeric_limits<double>::infinity();
};

LinePoint nearestOnLine(const FeatureLine& l, const Vec3& p)
{
    LinePoint best;
    const Eigen::Index n = l.points.rows();
    const Eigen::Index segments = l.closed ? n : n - 1;
    for (Eigen::Index i = 0; i < segments; ++i) {
        const Vec3 a = row(l.points, i), b = row(l.points, (i + 1) % n);
        const Vec3 d = b - a;
        const double len2 = d.squaredNorm();
        const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
        const double dist = (p - a - t * d).norm();
        if (dist < best.distance) {
            best = {static_cast<int>(i), t, dist};
        }
    }
    if (n == 1) {
        best = {0, 0.0, (p - row(l.points, 0)).norm()};
    }
    return best;
}

double polylineLength(const PointMatrix& P)
{
    double s = 0.0;
    for (Eigen::Index i = 0; i + 1 < P.rows(); ++i) {
        s += (P.row(i + 1) - P.row(i)).norm();
    }
    return s;
}

/// Length along the open line from its vertex 0 to the given place.
double lengthTo(const FeatureLine& l, int segment, double t)
{
    double s = 0.0;
    for (int i = 0; i < segment; ++i) {
        s += (l.points.row(i + 1) - l.points.row(i)).norm();
    }
    if (segment + 1 < l.points.rows()) {
        s += t * (l.points.row(segment + 1) - l.points.row(segment)).norm();
    }
    return s;
}

/// The network under construction: vertices, and per line the places it is cut.
class NetworkBuilder
{
public:
    NetworkBuilder(const ExtractionResult& result, double join, double merge)
        : result_(result), join_(join), merge_(merge), splits_(result.lines.size()),
          junctionVertex_(static_cast<size_t>(result.junctions.rows()), -1)
    {
    }

    /// Cuts every line at its junctions, joins the free ends (to a vertex near them, else to
    /// the interior of a line near them, else a vertex of their own), cuts the lines at their
    /// corners, and gives every closed line that is cut nowhere a vertex at its first point.
    void cutLines(const LineCornerOptions& corners)
    {
        for (size_t l = 0; l < result_.lines.size(); ++l) {
            const FeatureLine& line = result_.lines[l];
            if (line.points.rows() == 0) {
                continue;
            }
            if (line.startJunction >= 0) {
                addSplit(l, 0, 0.0, junctionVertex(line.startJunction));
            }
            if (!line.closed && line.endJunction >= 0) {
                addSplit(l, lastSegment(line), 1.0, junctionVertex(line.endJunction));
            }
        }
        for (size_t l = 0; l < result_.lines.size(); ++l) {
            const FeatureLine& line = result_.lines[l];
            if (line.closed || line.points.rows() == 0) {
                continue;
            }
            if (line.startJunction < 0) {
                joinFreeEnd(l, false);
            }
            if (line.endJunction < 0) {
                joinFreeEnd(l, true);
            }
        }
        if (corners.angle < 180.0) {
            for (size_t l = 0; l < result_.lines.size(); ++l) {
                cutAtCorners(l, corners);
            }
        }
        for (size_t l = 0; l < result_.lines.size(); ++l) {
            const FeatureLine& line = result_.lines[l];
            if (line.closed && line.points.rows() > 0 && splits_[l].empty()) {
                addSplit(l, 0, 0.0, newVertex(row(line.points, 0)));
                loopVertexFree_.push_back(static_cast<int>(l));
            }
        }
    }

    /// The edges between consecutive cuts of each line, with their points (vertex positions
    /// at both ends).
    std::vector<NetworkEdge> edges(double minimumGap) const
    {
        std::vector<NetworkEdge> out;
        int run = -1;
        for (size_t l = 0; l < result_.lines.size(); ++l) {
            const FeatureLine& line = result_.lines[l];
            std::vector<Split> cuts = splits_[l];
            if (cuts.empty()) {
                continue;
            }
            std::sort(cuts.begin(), cuts.end(),
                      [](const Split& a, const Split& b) { return a.position() < b.position(); });
            // A closed line's pieces are taken from a cut that is no corner, where there is
            // one, so that each stretch between junctions is a run of consecutive pieces.
            size_t first = 0;
            if (line.closed) {
                while (first < cuts.size() && cuts[first].corner) {
                    ++first;
                }
                first = first == cuts.size() ? 0 : first;
            }
            const size_t pieces = line.closed ? cuts.size() : cuts.size() - 1;
            for (size_t j = 0; j < pieces; ++j) {
                const size_t k = (first + j) % cuts.size();
                const Split& a = cuts[k];
                const Split& b = cuts[(k + 1) % cuts.size()];
                if (j == 0 || !a.corner) {
                    ++run;
                }
                NetworkEdge e;
                e.type = line.type;
                e.line = static_cast<int>(l);
                e.run = run;
                e.startVertex = a.vertex;
                e.endVertex = b.vertex;
                e.points = piecePoints(line, a, b, k + 1 == cuts.size(), minimumGap);
                if (e.startVertex == e.endVertex && !freeLoop(static_cast<int>(l)) &&
                    polylineLength(e.points) <= 2 * join_) {
                    continue; // a piece from a vertex back to it, shorter than a join: none
                }
                out.push_back(std::move(e));
            }
        }
        return out;
    }

    std::vector<Vec3> vertices;

    /// Whether line l's only vertex is one of its own (no junction, no other line on it).
    bool freeLoop(int l) const
    {
        return std::find(loopVertexFree_.begin(), loopVertexFree_.end(), l) !=
               loopVertexFree_.end();
    }

private:
    static int lastSegment(const FeatureLine& line)
    {
        return std::max<int>(0, static_cast<int>(line.points.rows()) - 2);
    }

    int newVertex(const Vec3& p)
    {
        vertices.push_back(p);
        return static_cast<int>(vertices.size()) - 1;
    }

    /// The vertex of junction j: a junction within mergeDistance of one met before shares its
    /// vertex (the crease placement can put two junctions of one corner on the same spot).
    int junctionVertex(int j)
    {
        int& v = junctionVertex_[static_cast<size_t>(j)];
        if (v < 0) {
            const Vec3 p = result_.junctions.row(j).transpose();
            for (int other : junctionVertex_) {
                if (other >= 0 && (vertices[static_cast<size_t>(other)] - p).norm() <= merge_) {
                    v = other;
                    return v;
                }
            }
            v = newVertex(p);
        }
        return v;
    }

    void addSplit(size_t l, int segment, double t, int vertex, bool corner = false)
    {
        splits_[l].push_back({segment, t, vertex, corner});
    }

    /// Cuts line l at its corners. A corner within a join distance of a junction's vertex or
    /// of another line's corner takes that vertex: where a flat face's border and a corner
    /// blend's border meet at one point of the part, their lines pass close by each other
    /// without a junction between them. A corner within half a corner window of a cut of its
    /// own line (a junction, or where another line's free end joins it) is none: the line
    /// bends into the junction, and the cut there is a vertex already.
    void cutAtCorners(size_t l, const LineCornerOptions& options)
    {
        const FeatureLine& line = result_.lines[l];
        const double spacing = result_.spacing;
        const std::vector<LineCorner> corners =
            findLineCorners(line.points, line.closed, spacing, options);
        const std::vector<Split> junctions = splits_[l];
        for (const LineCorner& c : corners) {
            const Vec3 at = row(line.points, c.vertex);
            bool nearJunction = false;
            for (const Split& j : junctions) {
                const Vec3 q = vertices[static_cast<size_t>(j.vertex)];
                nearJunction = nearJunction || (q - at).norm() < options.window * spacing / 2;
            }
            if (nearJunction) {
                continue;
            }
            int shared = -1;
            double nearest = join_;
            for (const auto& [vertex, owner] : cornerVertices_) {
                const double d = (vertices[static_cast<size_t>(vertex)] - c.position).norm();
                if (owner != static_cast<int>(l) && d <= nearest) {
                    shared = vertex;
                    nearest = d;
                }
            }
            for (int vertex : junctionVertex_) {
                if (vertex >= 0) {
                    const double d = (vertices[static_cast<size_t>(vertex)] - c.position).norm();
                    if (d <= nearest) {
                        shared = vertex;
                        nearest = d;
                    }
                }
            }
            if (shared < 0) {
                shared = newVertex(c.position);
                cornerVertices_.emplace_back(shared, static_cast<int>(l));
            }
            addSplit(l, c.vertex, 0.0, shared, true);
        }
    }

    /// The free end of open line l (its last point when atEnd).
    void joinFreeEnd(size_t l, bool atEnd)
    {
        const FeatureLine& line = result_.lines[l];
        const Vec3 p = row(line.points, atEnd ? line.points.rows() - 1 : 0);
        const int segment = atEnd ? lastSegment(line) : 0;
        const double t = atEnd ? 1.0 : 0.0;
        // A vertex near it: a junction, a line's end, or a cut already made.
        int nearest = -1;
        double nearestDistance = join_;
        for (size_t v = 0; v < vertices.size(); ++v) {
            const double d = (vertices[v] - p).norm();
            if (d <= nearestDistance) {
                nearest = static_cast<int>(v);
                nearestDistance = d;
            }
        }
        if (nearest >= 0) {
            addSplit(l, segment, t, nearest);
            return;
        }
        // The interior of a line near it (a smooth line ending on a sharp edge); on its own
        // line only farther along it than a few join distances (a line that curls onto
        // itself).
        const double ownLength = lengthTo(line, lastSegment(line), 1.0);
        const double endPosition = atEnd ? ownLength : 0.0;
        LinePoint best;
        size_t bestLine = 0;
        for (size_t m = 0; m < result_.lines.size(); ++m) {
            const FeatureLine& other = result_.lines[m];
            if (other.points.rows() < 2) {
                continue;
            }
            const LinePoint q = nearestOnLine(other, p);
            if (m == l && std::abs(lengthTo(line, q.segment, q.t) - endPosition) < 4 * join_) {
                continue;
            }
            if (q.distance <= join_ && q.distance < best.distance) {
                best = q;
                bestLine = m;
            }
        }
        if (best.segment >= 0) {
            const FeatureLine& other = result_.lines[bestLine];
            const Eigen::Index n = other.points.rows();
            const Vec3 a = row(other.points, best.segment);
            const Vec3 b = row(other.points, (best.segment + 1) % n);
            const int v = newVertex(a + best.t * (b - a));
            addSplit(bestLine, best.segment, best.t, v);
            addSplit(l, segment, t, v);
            return;
        }
        addSplit(l, segment, t, newVertex(p));
    }

    /// The points of line `line` from cut a to cut b (around the loop when b is at or before
    /// a, or `wraps`): the vertices at the ends, the line's vertices strictly between, less
    /// those within minimumGap of an end.
    PointMatrix piecePoints(const FeatureLine& line, const Split& a, const Split& b, bool wraps,
                            double minimumGap) const
    {
        const Eigen::Index n = line.points.rows();
        const Vec3 first = vertices[static_cast<size_t>(a.vertex)];
        const Vec3 last = vertices[static_cast<size_t>(b.vertex)];
        double end = b.position();
        if (line.closed && (wraps || end <= a.position())) {
            end += static_cast<double>(n);
        }
        std::vector<Vec3> points{first};
        for (long k = static_cast<long>(std::floor(a.position())) + 1; static_cast<double>(k) < end;
             ++k) {
            const Vec3 q = row(line.points, k % n);
            if ((q - first).norm() >= minimumGap && (q - last).norm() >= minimumGap) {
                points.push_back(q);
            }
        }
        points.push_back(last);
        PointMatrix P(static_cast<Eigen::Index>(points.size()), 3);
        for (size_t i = 0; i < points.size(); ++i) {
            P.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
        }
        return P;
    }

    const ExtractionResult& result_;
    double join_;
    double merge_;
    std::vector<std::vector<Split>> splits_;
    std::vector<int> junctionVertex_;
    std::vector<int> loopVertexFree_;
    /// The vertices made at corners, and the line each was first made for.
    std::vector<std::pair<int, int>> cornerVertices_;
};

/// The fit of one edge's points; a closed edge's points repeat its vertex at the end.
CurveFitInput fitInput(const NetworkEdge& e, bool freeLoop, const CurveFitOptions& options,
                       double spacing, double cloudNoise)
{
    CurveFitInput in;
    in.closed = e.startVertex == e.endVertex && freeLoop;
    in.freeVertex = in.closed;
    in.points = in.closed ? PointMatrix(e.points.topRows(e.points.rows() - 1)) : e.points;
    const double noise = std::max(cloudNoise * spacing, polylineScatter(in.points, in.closed));
    in.tolerance = std::max(options.tolerance * spacing, options.noiseFactor * noise);
    return in;
}

/// The direction of travel of edge e's curve leaving (atEnd false) or arriving at (true)
/// its vertex.
Vec3 endDirection(const NetworkEdge& e, bool atEnd)
{
    return curveTangent(e.curve, atEnd ? 1.0 : 0.0);
}

/// Tangent continuity where exactly two edge ends meet at a vertex and the direction turns
/// there by less than `smoothAngle`: a B-spline takes the tangent of an analytic neighbour
/// (a segment or arc keeps its own), two B-splines the mean of theirs, and is refitted.
void joinTangents(CurveNetwork& net, std::vector<CurveFitInput>& inputs, double smoothAngle)
{
    struct End
    {
        int edge;
        bool atEnd;
    };
    std::vector<std::vector<End>> ends(static_cast<size_t>(net.vertices.rows()));
    for (size_t i = 0; i < net.edges.size(); ++i) {
        const NetworkEdge& e = net.edges[i];
        if (inputs[i].closed) {
            continue; // a periodic loop is smooth by construction
        }
        ends[static_cast<size_t>(e.startVertex)].push_back({static_cast<int>(i), false});
        ends[static_cast<size_t>(e.endVertex)].push_back({static_cast<int>(i), true});
    }
    std::vector<bool> refit(net.edges.size(), false);
    const double cosLimit = std::cos(smoothAngle * pi / 180.0);
    for (const std::vector<End>& at : ends) {
        if (at.size() != 2) {
            continue;
        }
        // Both as directions of travel through the vertex: into it along the first end, out
        // of it along the second.
        const NetworkEdge& e0 = net.edges[static_cast<size_t>(at[0].edge)];
        const NetworkEdge& e1 = net.edges[static_cast<size_t>(at[1].edge)];
        const Vec3 in = at[0].atEnd ? endDirection(e0, true) : Vec3(-endDirection(e0, false));
        const Vec3 out = at[1].atEnd ? Vec3(-endDirection(e1, true)) : endDirection(e1, false);
        if (in.dot(out) < cosLimit) {
            continue;
        }
        const bool spline0 = e0.curve.kind == CurveKind::BSpline;
        const bool spline1 = e1.curve.kind == CurveKind::BSpline;
        if (!spline0 && !spline1) {
            continue;
        }
        const Vec3 through = !spline0 ? in : !spline1 ? out : Vec3((in + out).normalized());
        const auto setTangent = [&](const End& end, const Vec3& travel, bool arriving) {
            CurveFitInput& input = inputs[static_cast<size_t>(end.edge)];
            // travel is along the network's path; the edge runs with it when it arrives at
            // its end or leaves from its start, else against it.
            const Vec3 own = (end.atEnd == arriving) ? travel : Vec3(-travel);
            if (end.atEnd) {
                input.endTangent = own;
            } else {
                input.startTangent = own;
            }
            refit[static_cast<size_t>(end.edge)] = true;
        };
        if (spline0) {
            setTangent(at[0], through, true);
        }
        if (spline1) {
            setTangent(at[1], through, false);
        }
    }
    for (size_t i = 0; i < net.edges.size(); ++i) {
        if (refit[i]) {
            net.edges[i].curve = fitBSpline(inputs[i]);
        }
    }
}

} // namespace

double cloudNoise(const ExtractionResult& result)
{
    std::vector<double> noise;
    for (const RegionReport& r : result.regions) {
        if (std::isfinite(r.noise)) {
            noise.push_back(r.noise);
        }
    }
    if (noise.empty()) {
        return 0.0;
    }
    std::nth_element(noise.begin(), noise.begin() + noise.size() / 2, noise.end());
    return noise[noise.size() / 2];
}

CurveNetwork fitCurveNetwork(const ExtractionResult& result, const CurveFitOptions& options)
{
    if (!(options.tolerance > 0) || !(options.noiseFactor >= 0) || !(options.joinDistance >= 0) ||
        !(options.vertexGap >= 0) || !(options.mergeDistance >= 0) || !(options.smoothAngle >= 0) ||
        !(options.cornerAngle >= 0) || !(options.cornerWindow > 1)) {
        throw std::invalid_argument("the curve fitting options must be positive numbers");
    }
    CurveNetwork net;
    if (result.lines.empty()) {
        net.vertices.resize(0, 3);
        return net;
    }
    if (!(result.spacing > 0)) {
        throw std::invalid_argument("the extraction result has no point spacing");
    }
    const double spacing = result.spacing;
    NetworkBuilder builder(result, options.joinDistance * spacing, options.mergeDistance * spacing);
    LineCornerOptions corners;
    corners.angle = options.cornerAngle;
    corners.window = options.cornerWindow;
    builder.cutLines(corners);
    net.edges = builder.edges(options.vertexGap * spacing);
    // A piece of fewer than two vertices, or a loop back to its vertex through fewer than two
    // others (a line folded onto itself), is no curve.
    net.edges.erase(std::remove_if(net.edges.begin(), net.edges.end(),
                                   [](const NetworkEdge& e) {
                                       return e.points.rows() <
                                              (e.startVertex == e.endVertex ? 4 : 2);
                                   }),
                    net.edges.end());
    net.vertices.resize(static_cast<Eigen::Index>(builder.vertices.size()), 3);
    for (size_t v = 0; v < builder.vertices.size(); ++v) {
        net.vertices.row(static_cast<Eigen::Index>(v)) = builder.vertices[v].transpose();
    }

    std::vector<CurveFitInput> inputs;
    const double noise = cloudNoise(result);
    for (NetworkEdge& e : net.edges) {
        inputs.push_back(fitInput(e, builder.freeLoop(e.line), options, spacing, noise));
        e.curve = fitCurve(inputs.back());
    }
    joinTangents(net, inputs, options.smoothAngle);
    // A loop's own vertex slides onto its curve (a circle or periodic B-spline).
    for (size_t i = 0; i < net.edges.size(); ++i) {
        NetworkEdge& e = net.edges[i];
        if (inputs[i].freeVertex) {
            net.vertices.row(e.startVertex) = e.curve.start.transpose();
            e.points.row(0) = e.curve.start.transpose();
            e.points.row(e.points.rows() - 1) = e.curve.start.transpose();
        }
    }
    return net;
}

} // namespace featurelines
