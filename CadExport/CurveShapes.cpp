// SPDX-License-Identifier: LGPL-2.1-or-later
#include "CurveShapes.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <ElCLib.hxx>
#include <GCPnts_QuasiUniformAbscissa.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Line.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace featurelines::cad {

namespace {

gp_Pnt point(const Eigen::Vector3d& p)
{
    return gp_Pnt(p.x(), p.y(), p.z());
}

gp_Pnt pointOf(const PointMatrix& P, Eigen::Index row)
{
    return gp_Pnt(P(row, 0), P(row, 1), P(row, 2));
}

bool finite(const Eigen::Vector3d& v)
{
    return v.allFinite();
}

CurveSpan segmentCurve(const FittedCurve& c)
{
    const gp_Pnt a = point(c.start), b = point(c.end);
    const double length = a.Distance(b);
    if (!(length > Precision::Confusion())) {
        throw std::invalid_argument("a segment of length 0");
    }
    return {new Geom_Line(a, gp_Dir(gp_Vec(a, b))), 0.0, length};
}

/// The circle of an arc or a full circle, its parameter 0 at `start`.
Handle(Geom_Circle) circleCurve(const FittedCurve& c)
{
    if (!(c.radius > Precision::Confusion()) || !std::isfinite(c.radius) || !finite(c.centre)) {
        throw std::invalid_argument("a circle of radius " + std::to_string(c.radius));
    }
    const gp_Vec axis(c.axis.x(), c.axis.y(), c.axis.z());
    const gp_Vec toStart(point(c.centre), point(c.start));
    if (axis.Magnitude() < Precision::Confusion() || toStart.Magnitude() < Precision::Confusion() ||
        axis.IsParallel(toStart, Precision::Angular())) {
        throw std::invalid_argument("a circle whose axis lies along its start or is zero");
    }
    // Parameter 0 where the start is; gp_Ax2 makes the x direction normal to the axis.
    const gp_Ax2 frame(point(c.centre), gp_Dir(axis), gp_Dir(toStart));
    return new Geom_Circle(frame, c.radius);
}

CurveSpan arcCurve(const FittedCurve& c)
{
    Handle(Geom_Circle) circle = circleCurve(c);
    // Counter-clockwise about the axis from the start (parameter 0) to the end.
    double last = ElCLib::Parameter(circle->Circ(), point(c.end));
    if (last < Precision::PConfusion()) {
        last += 2.0 * M_PI;
    }
    return {circle, 0.0, last};
}

CurveSpan bsplineCurve(const FittedCurve& c)
{
    const Eigen::Index n = c.poles.rows();
    const size_t k = c.knots.size();
    if (n < 2 || c.poles.cols() != 3 || k < 2 || c.multiplicities.size() != k || c.degree < 1 ||
        !c.poles.allFinite()) {
        throw std::invalid_argument("a B-spline of " + std::to_string(n) + " poles, " +
                                    std::to_string(k) + " knots and " +
                                    std::to_string(c.multiplicities.size()) + " multiplicities");
    }
    TColgp_Array1OfPnt poles(1, static_cast<int>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
        poles.SetValue(static_cast<int>(i) + 1, pointOf(c.poles, i));
    }
    TColStd_Array1OfReal knots(1, static_cast<int>(k));
    TColStd_Array1OfInteger multiplicities(1, static_cast<int>(k));
    for (size_t i = 0; i < k; ++i) {
        knots.SetValue(static_cast<int>(i) + 1, c.knots[i]);
        multiplicities.SetValue(static_cast<int>(i) + 1, c.multiplicities[i]);
    }
    // OpenCASCADE checks the rest (knots increasing, multiplicities adding up) and throws.
    Handle(Geom_BSplineCurve) curve =
        new Geom_BSplineCurve(poles, knots, multiplicities, c.degree, c.periodic);
    return {curve, curve->FirstParameter(), curve->LastParameter()};
}

/// The curve's ends on the two vertices: an end further than the vertex's tolerance from it
/// makes no valid edge.
void requireEnds(const CurveSpan& span, const gp_Pnt& start, const gp_Pnt& end)
{
    const double offStart = span.curve->Value(span.first).Distance(start);
    const double offEnd = span.curve->Value(span.last).Distance(end);
    if (offStart > Precision::Confusion() || offEnd > Precision::Confusion()) {
        throw std::invalid_argument("its ends lie " + std::to_string(offStart) + " and " +
                                    std::to_string(offEnd) + " from its vertices");
    }
}

/// Distance from p to the segment ab.
double distanceToSegment(const gp_Pnt& p, const gp_Pnt& a, const gp_Pnt& b)
{
    const gp_Vec ab(a, b), ap(a, p);
    const double length2 = ab.SquareMagnitude();
    const double t = length2 > 0.0 ? std::clamp(ap.Dot(ab) / length2, 0.0, 1.0) : 0.0;
    return p.Distance(a.Translated(t * ab));
}

TopoDS_Edge edgeOn(const CurveSpan& span, const TopoDS_Vertex& v1, const TopoDS_Vertex& v2)
{
    BRepBuilderAPI_MakeEdge make(span.curve, v1, v2, span.first, span.last);
    if (!make.IsDone()) {
        throw std::invalid_argument("OpenCASCADE made no edge of it (BRepBuilderAPI_MakeEdge "
                                    "error " +
                                    std::to_string(int(make.Error())) + ")");
    }
    return make.Edge();
}

/// The edge's polyline with its ends exactly on its vertices.
PointMatrix polylineBetween(const NetworkEdge& e, const gp_Pnt& start, const gp_Pnt& end)
{
    PointMatrix P(e.points.rows() + 2, 3);
    P.row(0) << start.X(), start.Y(), start.Z();
    P.middleRows(1, e.points.rows()) = e.points;
    P.row(P.rows() - 1) << end.X(), end.Y(), end.Z();
    return P;
}

std::string edgeName(size_t e, const NetworkEdge& edge)
{
    return "edge " + std::to_string(e) + " (line " + std::to_string(edge.line) + ", " +
           curveKindName(edge.curve.kind) + ")";
}

} // namespace

CurveSpan makeCurve(const FittedCurve& c)
{
    if (!finite(c.start) || !finite(c.end)) {
        throw std::invalid_argument("a curve with an end that is not finite");
    }
    try {
        switch (c.kind) {
        case CurveKind::Segment:
            return segmentCurve(c);
        case CurveKind::Arc:
            return arcCurve(c);
        case CurveKind::Circle: {
            Handle(Geom_Circle) circle = circleCurve(c);
            return {circle, 0.0, 2.0 * M_PI};
        }
        case CurveKind::BSpline:
            return bsplineCurve(c);
        }
    } catch (const Standard_Failure& failure) {
        throw std::invalid_argument(std::string("OpenCASCADE: ") + failure.GetMessageString());
    }
    throw std::invalid_argument("a curve of unknown kind " + std::to_string(int(c.kind)));
}

double strayFromPolyline(const CurveSpan& span, const PointMatrix& points)
{
    const Eigen::Index n = points.rows();
    if (n == 0) {
        return 0.0;
    }
    // Evenly along the curve's length, not its parameter: a B-spline whose fit went wrong can
    // loop far out over a tiny parameter range between two close knots.
    const int samples = static_cast<int>(std::max<Eigen::Index>(64, 4 * n));
    const GeomAdaptor_Curve curve(span.curve, span.first, span.last);
    GCPnts_QuasiUniformAbscissa along(curve, samples + 1, span.first, span.last);
    if (!along.IsDone()) {
        throw std::invalid_argument("its length cannot be measured");
    }
    std::vector<double> parameters;
    for (int i = 1; i <= along.NbPoints(); ++i) {
        parameters.push_back(along.Parameter(i));
    }
    // And inside every knot span of a B-spline, however short: measuring the length can step
    // over a spike in a span of 1e-20.
    if (auto bspline = Handle(Geom_BSplineCurve)::DownCast(span.curve)) {
        for (int k = 1; k < bspline->NbKnots(); ++k) {
            const double a = std::max(bspline->Knot(k), span.first);
            const double b = std::min(bspline->Knot(k + 1), span.last);
            for (int j = 1; j < 4 && a < b; ++j) {
                parameters.push_back(a + (b - a) * j / 4.0);
            }
        }
    }
    double stray = 0.0;
    for (double t : parameters) {
        const gp_Pnt p = span.curve->Value(t);
        double nearest = p.Distance(pointOf(points, 0));
        for (Eigen::Index j = 1; j < n; ++j) {
            nearest =
                std::min(nearest, distanceToSegment(p, pointOf(points, j - 1), pointOf(points, j)));
        }
        stray = std::max(stray, nearest);
    }
    return stray;
}

CurveSpan makePolylineCurve(const PointMatrix& points)
{
    std::vector<gp_Pnt> kept;
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        const gp_Pnt p = pointOf(points, i);
        if (kept.empty() || p.Distance(kept.back()) > Precision::Confusion()) {
            kept.push_back(p);
        }
    }
    const int n = static_cast<int>(kept.size());
    if (n < 2) {
        throw std::invalid_argument("a polyline whose points all lie on one spot");
    }
    // Degree 1, one knot per vertex at its distance along the polyline: the polyline itself.
    TColgp_Array1OfPnt poles(1, n);
    TColStd_Array1OfReal knots(1, n);
    TColStd_Array1OfInteger multiplicities(1, n);
    double along = 0.0;
    for (int i = 0; i < n; ++i) {
        along += i > 0 ? kept[i].Distance(kept[i - 1]) : 0.0;
        poles.SetValue(i + 1, kept[i]);
        knots.SetValue(i + 1, along);
        multiplicities.SetValue(i + 1, i == 0 || i == n - 1 ? 2 : 1);
    }
    Handle(Geom_BSplineCurve) curve = new Geom_BSplineCurve(poles, knots, multiplicities, 1);
    return {curve, 0.0, along};
}

NetworkShapes makeNetworkShapes(const CurveNetwork& network, const gp_Trsf& toWorld,
                                double maxStray)
{
    NetworkShapes out;
    std::vector<gp_Pnt> positions;
    for (Eigen::Index i = 0; i < network.vertices.rows(); ++i) {
        positions.push_back(pointOf(network.vertices, i));
        out.vertices.push_back(BRepBuilderAPI_MakeVertex(positions.back()).Vertex());
    }
    const int vertexCount = static_cast<int>(positions.size());
    for (size_t e = 0; e < network.edges.size(); ++e) {
        const NetworkEdge& edge = network.edges[e];
        out.edges.emplace_back();
        out.polyline.push_back(false);
        if (edge.startVertex < 0 || edge.startVertex >= vertexCount || edge.endVertex < 0 ||
            edge.endVertex >= vertexCount) {
            out.problems.push_back(edgeName(e, edge) + " left out: its vertices " +
                                   std::to_string(edge.startVertex) + " and " +
                                   std::to_string(edge.endVertex) + " are not in the network");
            continue;
        }
        const TopoDS_Vertex& v1 = out.vertices[static_cast<size_t>(edge.startVertex)];
        const TopoDS_Vertex& v2 = out.vertices[static_cast<size_t>(edge.endVertex)];
        const gp_Pnt& p1 = positions[static_cast<size_t>(edge.startVertex)];
        const gp_Pnt& p2 = positions[static_cast<size_t>(edge.endVertex)];
        std::string why;
        try {
            const CurveSpan span = makeCurve(edge.curve);
            requireEnds(span, p1, p2);
            if (maxStray > 0.0) {
                const double stray = strayFromPolyline(span, polylineBetween(edge, p1, p2));
                if (stray > maxStray) {
                    throw std::invalid_argument("it strays " + std::to_string(stray) +
                                                " from its points (more than " +
                                                std::to_string(maxStray) + ")");
                }
            }
            out.edges.back() = edgeOn(span, v1, v2);
            continue;
        } catch (const std::invalid_argument& error) {
            why = error.what();
        } catch (const Standard_Failure& failure) {
            why = std::string("OpenCASCADE: ") + failure.GetMessageString();
        }
        try {
            out.edges.back() = edgeOn(makePolylineCurve(polylineBetween(edge, p1, p2)), v1, v2);
            out.polyline.back() = true;
            out.problems.push_back(edgeName(e, edge) + " is its polyline: " + why);
        } catch (const std::invalid_argument& error) {
            out.problems.push_back(edgeName(e, edge) + " left out: " + why + "; " + error.what());
        } catch (const Standard_Failure& failure) {
            out.problems.push_back(edgeName(e, edge) + " left out: " + why +
                                   "; OpenCASCADE: " + failure.GetMessageString());
        }
    }
    if (toWorld.Form() != gp_Identity) {
        // One location on every shape: the shared vertices stay shared.
        const TopLoc_Location location(toWorld);
        for (TopoDS_Vertex& v : out.vertices) {
            v.Move(location);
        }
        for (TopoDS_Edge& e : out.edges) {
            if (!e.IsNull()) {
                e.Move(location);
            }
        }
    }
    return out;
}

BorderWires makeBorderWires(const PatchBorder& border, const NetworkShapes& shapes)
{
    BorderWires out;
    out.patch = border.patch;
    const std::string name = "patch " + std::to_string(border.patch);
    if (!border.closed()) {
        out.problem = border.loops.empty() && border.openEdges.empty()
                          ? name + ": no line borders it"
                          : name + ": its border is open (" +
                                std::to_string(border.openEdges.size()) +
                                " edges close no loop around it)";
        return out;
    }
    std::vector<TopoDS_Wire> wires;
    for (size_t l = 0; l < border.loops.size(); ++l) {
        BRepBuilderAPI_MakeWire make;
        for (const LoopEdge& le : border.loops[l]) {
            const bool known = le.edge >= 0 && static_cast<size_t>(le.edge) < shapes.edges.size() &&
                               !shapes.edges[static_cast<size_t>(le.edge)].IsNull();
            if (!known) {
                out.problem = name + ": loop " + std::to_string(l) + " runs over edge " +
                              std::to_string(le.edge) + ", which has no shape";
                return out;
            }
            const TopoDS_Edge& edge = shapes.edges[static_cast<size_t>(le.edge)];
            make.Add(le.reversed ? TopoDS::Edge(edge.Reversed()) : edge);
            if (!make.IsDone()) {
                out.problem = name + ": loop " + std::to_string(l) + " breaks at edge " +
                              std::to_string(le.edge);
                return out;
            }
        }
        if (!make.IsDone() || !BRep_Tool::IsClosed(make.Wire())) {
            out.problem = name + ": loop " + std::to_string(l) + " does not close";
            return out;
        }
        wires.push_back(make.Wire());
    }
    out.wires = wires;
    return out;
}

TopoDS_Compound makeEdgeCompound(const NetworkShapes& shapes)
{
    BRep_Builder builder;
    TopoDS_Compound compound;
    builder.MakeCompound(compound);
    for (const TopoDS_Edge& e : shapes.edges) {
        if (!e.IsNull()) {
            builder.Add(compound, e);
        }
    }
    return compound;
}

} // namespace featurelines::cad
