// SPDX-License-Identifier: LGPL-2.1-or-later
// The fitted line network (FeatureLines/curves/CurveNetwork.h) as OpenCASCADE shapes: one
// TopoDS_Vertex per network vertex, shared by every edge that meets there; one edge per network
// edge on its fitted curve (Segment: Geom_Line, Arc and Circle: Geom_Circle, BSpline:
// Geom_BSplineCurve); the patches' border loops as wires of those same edges.
// OpenCASCADE and the core only, no FreeCAD: the FreeCAD module (App/) and the command-line
// tool featurelines-cad build their shapes here, so both write the same network.
#pragma once

#include <Geom_Curve.hxx>
#include <Standard_Handle.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Trsf.hxx>

#include <string>
#include <vector>

#include "FeatureLines/curves/CurveNetwork.h"

namespace featurelines::cad {

/// A curve and the parameters of its first and last point.
struct CurveSpan
{
    Handle(Geom_Curve) curve;
    double first = 0.0;
    double last = 0.0;
};

/// The fitted curve as an OpenCASCADE curve, in the network's coordinates. Throws
/// std::invalid_argument naming the problem for data that make no curve (a zero radius, an axis
/// along the start, poles that do not match the knots, ...).
CurveSpan makeCurve(const FittedCurve& curve);

/// The polyline V  #V by 3 as a degree-1 B-spline through its vertices (the ones closer than
/// OpenCASCADE's confusion distance to the previous dropped), from its first to its last vertex.
/// Throws std::invalid_argument when fewer than two distinct vertices are left.
CurveSpan makePolylineCurve(const PointMatrix& points);

/// The farthest a point of the curve lies from the polyline V  #V by 3 (the curve sampled
/// evenly along its length, 4 points per polyline vertex, at least 64, and 3 points inside
/// every knot span of a B-spline). Throws
/// std::invalid_argument when OpenCASCADE cannot sample it.
double strayFromPolyline(const CurveSpan& span, const PointMatrix& points);

/// The network's shapes, in world coordinates (`toWorld`: a rigid motion from the network's
/// coordinates). vertices[i] is network vertex i, edges[e] network edge e. A fitted curve that
/// strays farther than `maxStray` (network units; 0: no check) from the polyline it was fitted
/// to is a failed fit, drawn as the polyline.
struct NetworkShapes
{
    std::vector<TopoDS_Vertex> vertices;
    /// A null edge where not even the polyline makes an edge (all its points on one spot).
    std::vector<TopoDS_Edge> edges;
    /// Per edge: its fitted curve made no valid edge, so the edge runs along the polyline the
    /// curve was fitted to (a degree-1 B-spline between the same two vertices).
    std::vector<bool> polyline;
    /// One line per edge that fell back to its polyline or was left out, naming it and why.
    std::vector<std::string> problems;
};
NetworkShapes makeNetworkShapes(const CurveNetwork& network, const gp_Trsf& toWorld = gp_Trsf(),
                                double maxStray = 0.0);

/// One patch's border as wires of the network's edges.
struct BorderWires
{
    int patch = -1;
    /// The closed wires: the outer one first, then the holes. Empty when the border is not
    /// closed.
    std::vector<TopoDS_Wire> wires;
    /// Why the border has no wire ("" when it has): where the lines found leave it open.
    std::string problem;
};
BorderWires makeBorderWires(const PatchBorder& border, const NetworkShapes& shapes);

/// A compound of every edge of the network (the null ones left out).
TopoDS_Compound makeEdgeCompound(const NetworkShapes& shapes);

} // namespace featurelines::cad
