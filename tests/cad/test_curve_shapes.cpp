// SPDX-License-Identifier: LGPL-2.1-or-later
// The fitted network as OpenCASCADE shapes (CadExport/CurveShapes.h) on hand-made networks
// whose answer is exact: a square of segments, arcs and a circle, a B-spline, curves that make
// no edge (the polyline instead), an open border, a moved network.
#include <gtest/gtest.h>

#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Line.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <cmath>

#include "CurveShapes.h"
#include "ShapeCounts.h"

using namespace featurelines;
using namespace featurelines::cad;

namespace {

double lengthOf(const TopoDS_Shape& shape)
{
    GProp_GProps props;
    BRepGProp::LinearProperties(shape, props);
    return props.Mass();
}

Handle(Geom_Curve) curveOf(const TopoDS_Edge& edge)
{
    double first = 0.0, last = 0.0;
    return BRep_Tool::Curve(edge, first, last);
}

FittedCurve segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    FittedCurve c;
    c.kind = CurveKind::Segment;
    c.start = a;
    c.end = b;
    return c;
}

NetworkEdge edgeOf(int v1, int v2, const FittedCurve& curve, const PointMatrix& vertices)
{
    NetworkEdge e;
    e.startVertex = v1;
    e.endVertex = v2;
    e.curve = curve;
    e.points.resize(2, 3);
    e.points.row(0) = vertices.row(v1);
    e.points.row(1) = vertices.row(v2);
    return e;
}

/// The unit square in z = 0, corners counter-clockwise, edge i from corner i to i + 1.
CurveNetwork square(double side)
{
    CurveNetwork n;
    n.vertices.resize(4, 3);
    n.vertices << 0, 0, 0, side, 0, 0, side, side, 0, 0, side, 0;
    for (int i = 0; i < 4; ++i) {
        const int j = (i + 1) % 4;
        n.edges.push_back(
            edgeOf(i, j, segment(n.vertices.row(i).transpose(), n.vertices.row(j).transpose()),
                   n.vertices));
    }
    return n;
}

} // namespace

TEST(CurveShapes, ASquareOfSegmentsSharesItsFourCorners)
{
    const NetworkShapes shapes = makeNetworkShapes(square(2.0));
    ASSERT_EQ(shapes.edges.size(), 4u);
    EXPECT_TRUE(shapes.problems.empty());
    const TopoDS_Compound all = makeEdgeCompound(shapes);
    EXPECT_EQ(countOf(all, TopAbs_EDGE), 4);
    EXPECT_EQ(countOf(all, TopAbs_VERTEX), 4) << "one vertex per corner, shared by two edges";
    for (const TopoDS_Edge& e : shapes.edges) {
        EXPECT_FALSE(Handle(Geom_Line)::DownCast(curveOf(e)).IsNull());
        EXPECT_NEAR(lengthOf(e), 2.0, 1e-12);
    }
    // Edge 1 ends where edge 2 starts: the same vertex, not two at one place.
    EXPECT_TRUE(TopExp::LastVertex(shapes.edges[1]).IsSame(TopExp::FirstVertex(shapes.edges[2])));
}

TEST(CurveShapes, ABorderLoopIsAClosedWireOfTheSameEdges)
{
    const CurveNetwork n = square(2.0);
    const NetworkShapes shapes = makeNetworkShapes(n);
    PatchBorder border;
    border.patch = 7;
    // Walked clockwise: every edge reversed, in the opposite order.
    border.loops = {{{3, true}, {2, true}, {1, true}, {0, true}}};
    const BorderWires wires = makeBorderWires(border, shapes);
    EXPECT_EQ(wires.patch, 7);
    EXPECT_EQ(wires.problem, "");
    ASSERT_EQ(wires.wires.size(), 1u);
    const TopoDS_Wire& wire = wires.wires[0];
    EXPECT_TRUE(BRep_Tool::IsClosed(wire));
    EXPECT_NEAR(lengthOf(wire), 8.0, 1e-12);
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(wire, TopAbs_EDGE, edges);
    ASSERT_EQ(edges.Extent(), 4);
    for (int i = 1; i <= 4; ++i) {
        const bool shared = std::any_of(shapes.edges.begin(), shapes.edges.end(),
                                        [&](const TopoDS_Edge& e) { return e.IsSame(edges(i)); });
        EXPECT_TRUE(shared) << "the wire's edge " << i << " is one of the network's";
    }
}

TEST(CurveShapes, AnOpenBorderGetsNoWireAndSaysSo)
{
    const NetworkShapes shapes = makeNetworkShapes(square(2.0));
    PatchBorder open;
    open.patch = 3;
    open.openEdges = {0, 1};
    const BorderWires wires = makeBorderWires(open, shapes);
    EXPECT_TRUE(wires.wires.empty());
    EXPECT_EQ(wires.problem, "patch 3: its border is open (2 edges close no loop around it)");

    PatchBorder broken;
    broken.patch = 4;
    broken.loops = {{{0, false}, {2, false}}}; // edges 0 and 2 do not meet
    EXPECT_EQ(makeBorderWires(broken, shapes).problem, "patch 4: loop 0 breaks at edge 2");

    PatchBorder unknown;
    unknown.patch = 5;
    unknown.loops = {{{9, false}}};
    EXPECT_EQ(makeBorderWires(unknown, shapes).problem,
              "patch 5: loop 0 runs over edge 9, which has no shape");
}

TEST(CurveShapes, ArcsRunCounterClockwiseAboutTheirAxisAndACircleClosesOnOneVertex)
{
    CurveNetwork n;
    n.vertices.resize(3, 3);
    n.vertices << 2, 0, 0, 0, 2, 0, 5, 0, 1;
    FittedCurve quarter;
    quarter.kind = CurveKind::Arc;
    quarter.start = {2, 0, 0};
    quarter.end = {0, 2, 0};
    quarter.centre = {0, 0, 0};
    quarter.axis = {0, 0, 1};
    quarter.radius = 2.0;
    FittedCurve threeQuarters = quarter;
    threeQuarters.axis = {0, 0, -1};
    FittedCurve circle;
    circle.kind = CurveKind::Circle;
    circle.start = circle.end = {5, 0, 1};
    circle.centre = {3, 0, 1};
    circle.axis = {0, 0, 1};
    circle.radius = 2.0;
    n.edges = {edgeOf(0, 1, quarter, n.vertices), edgeOf(0, 1, threeQuarters, n.vertices),
               edgeOf(2, 2, circle, n.vertices)};
    const NetworkShapes shapes = makeNetworkShapes(n);
    EXPECT_TRUE(shapes.problems.empty()) << shapes.problems.front();
    EXPECT_NEAR(lengthOf(shapes.edges[0]), M_PI, 1e-9);
    EXPECT_NEAR(lengthOf(shapes.edges[1]), 3.0 * M_PI, 1e-9);
    EXPECT_NEAR(lengthOf(shapes.edges[2]), 4.0 * M_PI, 1e-9);
    for (const TopoDS_Edge& e : shapes.edges) {
        const Handle(Geom_Circle) c = Handle(Geom_Circle)::DownCast(curveOf(e));
        ASSERT_FALSE(c.IsNull());
        EXPECT_NEAR(c->Radius(), 2.0, 1e-12);
    }
    EXPECT_TRUE(BRep_Tool::IsClosed(shapes.edges[2]));
    EXPECT_TRUE(TopExp::FirstVertex(shapes.edges[2]).IsSame(TopExp::LastVertex(shapes.edges[2])));
    EXPECT_EQ(countOf(makeEdgeCompound(shapes), TopAbs_VERTEX), 3);
}

TEST(CurveShapes, ABSplineKeepsItsPolesKnotsAndMultiplicities)
{
    CurveNetwork n;
    n.vertices.resize(2, 3);
    n.vertices << 0, 0, 0, 3, 0, 0;
    FittedCurve c;
    c.kind = CurveKind::BSpline;
    c.start = {0, 0, 0};
    c.end = {3, 0, 0};
    c.degree = 3;
    c.poles.resize(5, 3);
    c.poles << 0, 0, 0, 0.5, 1, 0, 1.5, 1, 0, 2.5, -1, 0, 3, 0, 0;
    c.knots = {0.0, 0.5, 1.0};
    c.multiplicities = {4, 1, 4};
    n.edges = {edgeOf(0, 1, c, n.vertices)};
    const NetworkShapes shapes = makeNetworkShapes(n);
    ASSERT_TRUE(shapes.problems.empty()) << shapes.problems.front();
    EXPECT_FALSE(shapes.polyline[0]);
    const Handle(Geom_BSplineCurve) b =
        Handle(Geom_BSplineCurve)::DownCast(curveOf(shapes.edges[0]));
    ASSERT_FALSE(b.IsNull());
    EXPECT_EQ(b->Degree(), 3);
    EXPECT_EQ(b->NbPoles(), 5);
    EXPECT_EQ(b->NbKnots(), 3);
    EXPECT_EQ(b->Multiplicity(2), 1);
    EXPECT_NEAR(b->Pole(4).Y(), -1.0, 1e-15);
}

TEST(CurveShapes, ACurveThatMakesNoEdgeFallsBackToItsPolylineAndIsReported)
{
    CurveNetwork n;
    n.vertices.resize(2, 3);
    n.vertices << 0, 0, 0, 4, 0, 0;
    FittedCurve badKnots;
    badKnots.kind = CurveKind::BSpline;
    badKnots.start = {0, 0, 0};
    badKnots.end = {4, 0, 0};
    badKnots.poles.resize(4, 3);
    badKnots.poles << 0, 0, 0, 1, 1, 0, 3, 1, 0, 4, 0, 0;
    badKnots.knots = {0.0, 1.0};
    badKnots.multiplicities = {4, 3}; // 7 knots for 4 poles of degree 3: one too few
    FittedCurve offItsVertex = segment({0, 0, 0}, {4, 0.1, 0});
    FittedCurve zeroRadius;
    zeroRadius.kind = CurveKind::Arc;
    zeroRadius.start = {0, 0, 0};
    zeroRadius.end = {4, 0, 0};
    for (const FittedCurve& c : {badKnots, offItsVertex, zeroRadius}) {
        NetworkEdge e = edgeOf(0, 1, c, n.vertices);
        e.line = 6;
        e.points.resize(3, 3);
        e.points << 0, 0, 0, 2, 1, 0, 4, 0, 0;
        n.edges.push_back(e);
    }
    const NetworkShapes shapes = makeNetworkShapes(n);
    ASSERT_EQ(shapes.problems.size(), 3u);
    EXPECT_EQ(shapes.problems[0].rfind("edge 0 (line 6, bspline) is its polyline: OpenCASCADE", 0),
              0u)
        << shapes.problems[0];
    EXPECT_EQ(shapes.problems[1].rfind("edge 1 (line 6, segment) is its polyline: its ends lie", 0),
              0u)
        << shapes.problems[1];
    EXPECT_EQ(shapes.problems[2], "edge 2 (line 6, arc) is its polyline: a circle of radius "
                                  "0.000000");
    for (size_t e = 0; e < 3; ++e) {
        EXPECT_TRUE(shapes.polyline[e]);
        // The polyline (0,0)-(2,1)-(4,0), between the network's own two vertices.
        EXPECT_NEAR(lengthOf(shapes.edges[e]), 2.0 * std::sqrt(5.0), 1e-12);
        EXPECT_TRUE(TopExp::FirstVertex(shapes.edges[e]).IsSame(shapes.vertices[0]));
        EXPECT_TRUE(TopExp::LastVertex(shapes.edges[e]).IsSame(shapes.vertices[1]));
    }
}

TEST(CurveShapes, AnEdgeOnVerticesOutsideTheNetworkIsLeftOut)
{
    CurveNetwork n = square(1.0);
    n.edges[2].endVertex = 4;
    const NetworkShapes shapes = makeNetworkShapes(n);
    ASSERT_EQ(shapes.problems.size(), 1u);
    EXPECT_EQ(shapes.problems[0], "edge 2 (line -1, segment) left out: its vertices 2 and 4 are "
                                  "not in the network");
    EXPECT_TRUE(shapes.edges[2].IsNull());
    EXPECT_EQ(countOf(makeEdgeCompound(shapes), TopAbs_EDGE), 3);
}

TEST(CurveShapes, TheNetworkMovesToTheWorldWithItsVerticesStillShared)
{
    gp_Trsf toWorld;
    toWorld.SetTranslation(gp_Vec(10, 0, 0));
    const NetworkShapes shapes = makeNetworkShapes(square(2.0), toWorld);
    const gp_Pnt corner = BRep_Tool::Pnt(TopExp::FirstVertex(shapes.edges[1]));
    EXPECT_NEAR(corner.X(), 12.0, 1e-12);
    EXPECT_NEAR(corner.Y(), 0.0, 1e-12);
    EXPECT_TRUE(TopExp::LastVertex(shapes.edges[0]).IsSame(TopExp::FirstVertex(shapes.edges[1])));
    EXPECT_EQ(countOf(makeEdgeCompound(shapes), TopAbs_VERTEX), 4);
}

TEST(CurveShapes, ACurveStrayingFromItsPointsIsAFailedFit)
{
    CurveNetwork n;
    n.vertices.resize(2, 3);
    n.vertices << 0, 0, 0, 4, 0, 0;
    // Through both vertices, but bulging 7.5 away from the straight points between them.
    FittedCurve bulge;
    bulge.kind = CurveKind::BSpline;
    bulge.start = {0, 0, 0};
    bulge.end = {4, 0, 0};
    bulge.poles.resize(4, 3);
    bulge.poles << 0, 0, 0, 1, 10, 0, 3, 10, 0, 4, 0, 0;
    bulge.knots = {0.0, 1.0};
    bulge.multiplicities = {4, 4};
    NetworkEdge e = edgeOf(0, 1, bulge, n.vertices);
    e.points.resize(3, 3);
    e.points << 0, 0, 0, 2, 0, 0, 4, 0, 0;
    n.edges = {e};
    EXPECT_NEAR(strayFromPolyline(makeCurve(bulge), e.points), 7.5, 1e-9) << "at t = 1/2";

    const NetworkShapes unchecked = makeNetworkShapes(n);
    EXPECT_FALSE(unchecked.polyline[0]);
    const NetworkShapes checked = makeNetworkShapes(n, gp_Trsf(), 1.0);
    ASSERT_TRUE(checked.polyline[0]);
    EXPECT_NEAR(lengthOf(checked.edges[0]), 4.0, 1e-12);
    ASSERT_EQ(checked.problems.size(), 1u);
    EXPECT_EQ(checked.problems[0], "edge 0 (line -1, bspline) is its polyline: it strays 7.500000 "
                                   "from its points (more than 1.000000)");
}
