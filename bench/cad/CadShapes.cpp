// SPDX-License-Identifier: LGPL-2.1-or-later
#include "CadShapes.h"

#include <cmath>
#include <functional>
#include <stdexcept>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepFilletAPI_MakeChamfer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRep_Builder.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <gp_Lin.hxx>

namespace featurelines::bench {

namespace {

/// Lengths below this (mm) are equal when selecting edges by their geometry.
constexpr double selectTolerance = 1e-6;

using EdgePredicate = std::function<bool(const BRepAdaptor_Curve&)>;

std::vector<TopoDS_Edge> edgesWhere(const TopoDS_Shape& shape, const EdgePredicate& keep)
{
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(shape, TopAbs_EDGE, edges);
    std::vector<TopoDS_Edge> result;
    for (int i = 1; i <= edges.Extent(); ++i) {
        const TopoDS_Edge& e = TopoDS::Edge(edges(i));
        if (keep(BRepAdaptor_Curve(e))) {
            result.push_back(e);
        }
    }
    return result;
}

bool isLineAlong(const BRepAdaptor_Curve& c, const gp_Dir& axis)
{
    return c.GetType() == GeomAbs_Line && c.Line().Direction().IsParallel(axis, 1e-9);
}

gp_Pnt midpoint(const BRepAdaptor_Curve& c)
{
    return c.Value(0.5 * (c.FirstParameter() + c.LastParameter()));
}

void check(bool done, const std::string& part, const char* step)
{
    if (!done) {
        throw std::runtime_error("OpenCASCADE could not build the part " + part + " (" + step +
                                 ").");
    }
}

/// Merges faces that a boolean operation left split on one surface, so that the B-rep's
/// edges are the part's real edges.
TopoDS_Shape unified(const TopoDS_Shape& shape)
{
    ShapeUpgrade_UnifySameDomain unify(shape, true, true, false);
    unify.Build();
    return unify.Shape();
}

TopoDS_Shape fillet(const TopoDS_Shape& shape, const std::vector<TopoDS_Edge>& edges, double radius,
                    const std::string& part)
{
    check(!edges.empty(), part, "no edge to fillet");
    BRepFilletAPI_MakeFillet maker(shape);
    for (const TopoDS_Edge& e : edges) {
        maker.Add(radius, e);
    }
    maker.Build();
    check(maker.IsDone(), part, "fillet");
    return maker.Shape();
}

// A box 100 x 80 x 50 with every edge filleted: the four vertical edges at 10 mm, the eight
// horizontal ones at 6 mm, blended at the corners. Only smooth edges: plane|cylinder fillet
// borders and the borders of the corner blends.
CadShape boxFillets()
{
    const std::string name = "box_fillets";
    TopoDS_Shape s = BRepPrimAPI_MakeBox(100.0, 80.0, 50.0).Shape();
    s = fillet(s, edgesWhere(s, [](const auto& c) { return isLineAlong(c, gp::DZ()); }), 10.0,
               name);
    // The horizontal rims are now tangent chains of lines and arcs; a fillet follows the chain.
    s = fillet(
        s,
        edgesWhere(
            s, [](const auto& c) { return isLineAlong(c, gp::DX()) || isLineAlong(c, gp::DY()); }),
        6.0, name);
    return {name,
            "box 100 x 80 x 50 mm, vertical edges filleted at 10 mm then the top and bottom "
            "rims at 6 mm (toroidal corner blends); smooth edges only",
            s, 6.0};
}

// A box 100 x 80 x 50 with all twelve edges chamfered at 6 mm: sharp edges at 135 degrees and
// triangular corner faces.
CadShape boxChamfers()
{
    const std::string name = "box_chamfers";
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(100.0, 80.0, 50.0).Shape();
    BRepFilletAPI_MakeChamfer maker(box);
    for (const TopoDS_Edge& e : edgesWhere(box, [](const auto&) { return true; })) {
        maker.Add(6.0, e);
    }
    maker.Build();
    check(maker.IsDone(), name, "chamfer");
    return {name,
            "box 100 x 80 x 50 mm, all twelve edges chamfered at 6 mm; sharp edges only (135 "
            "and 90 degrees at the corner triangles)",
            maker.Shape(), 0.0};
}

// A box 120 x 80 x 40 whose front top edge carries a fillet growing linearly from 5 to 14 mm:
// a smooth edge pair that is not parallel, ending on sharp edges at the end faces.
CadShape variableFillet()
{
    const std::string name = "variable_fillet";
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(120.0, 80.0, 40.0).Shape();
    const auto edges = edgesWhere(box, [](const BRepAdaptor_Curve& c) {
        const gp_Pnt m = midpoint(c);
        return isLineAlong(c, gp::DX()) && std::abs(m.Y()) < selectTolerance &&
               std::abs(m.Z() - 40.0) < selectTolerance;
    });
    check(edges.size() == 1, name, "front top edge");
    BRepFilletAPI_MakeFillet maker(box);
    maker.Add(5.0, 14.0, edges.front());
    maker.Build();
    check(maker.IsDone(), name, "variable fillet");
    return {name,
            "box 120 x 80 x 40 mm, front top edge filleted with a radius growing linearly "
            "from 5 to 14 mm; the other edges sharp",
            maker.Shape(), 5.0};
}

// A plate 120 x 90 x 15 with rounded vertical corners (12 mm), a cylindrical boss (radius
// 22, height 25) blended into the plate by a 6 mm fillet, a sharp top rim and a 9 mm hole
// through boss and plate.
CadShape bossBlend()
{
    const std::string name = "boss_blend";
    TopoDS_Shape plate = BRepPrimAPI_MakeBox(120.0, 90.0, 15.0).Shape();
    plate = fillet(plate, edgesWhere(plate, [](const auto& c) { return isLineAlong(c, gp::DZ()); }),
                   12.0, name);
    const gp_Ax2 bossAxis(gp_Pnt(60.0, 45.0, 15.0), gp::DZ());
    const TopoDS_Shape boss = BRepPrimAPI_MakeCylinder(bossAxis, 22.0, 25.0).Shape();
    BRepAlgoAPI_Fuse fuse(plate, boss);
    check(fuse.IsDone(), name, "fuse boss");
    TopoDS_Shape s = unified(fuse.Shape());
    s = fillet(s,
               edgesWhere(s,
                          [](const BRepAdaptor_Curve& c) {
                              return c.GetType() == GeomAbs_Circle &&
                                     std::abs(c.Circle().Radius() - 22.0) < selectTolerance &&
                                     std::abs(c.Circle().Location().Z() - 15.0) < selectTolerance;
                          }),
               6.0, name);
    const gp_Ax2 holeAxis(gp_Pnt(60.0, 45.0, -1.0), gp::DZ());
    BRepAlgoAPI_Cut cut(s, BRepPrimAPI_MakeCylinder(holeAxis, 9.0, 45.0).Shape());
    check(cut.IsDone(), name, "cut hole");
    return {name,
            "plate 120 x 90 x 15 mm with vertical corners filleted at 12 mm, a cylindrical "
            "boss (radius 22, height 25) blended by a 6 mm fillet, sharp top rim, a 9 mm hole "
            "through; sharp and smooth edges",
            unified(cut.Shape()), 6.0};
}

// A plate 120 x 80 x 10 with three sharp through holes of radius 5, 8 and 12 mm.
CadShape plateHoles()
{
    const std::string name = "plate_holes";
    TopoDS_Shape s = BRepPrimAPI_MakeBox(120.0, 80.0, 10.0).Shape();
    const double holes[3][2] = {{22.0, 5.0}, {52.0, 8.0}, {90.0, 12.0}}; // x, radius
    for (const auto& h : holes) {
        const gp_Ax2 axis(gp_Pnt(h[0], 40.0, -1.0), gp::DZ());
        BRepAlgoAPI_Cut cut(s, BRepPrimAPI_MakeCylinder(axis, h[1], 12.0).Shape());
        check(cut.IsDone(), name, "cut hole");
        s = cut.Shape();
    }
    return {name,
            "plate 120 x 80 x 10 mm with through holes of radius 5, 8 and 12 mm; sharp edges only",
            unified(s), 0.0};
}

// An open tray: a box 100 x 80 x 40 with vertical edges filleted at 10 mm and the bottom rim
// at 8 mm, its top face removed. The top rim is the boundary of an open surface; inside, the
// fillet borders are smooth edges.
CadShape openSheet()
{
    const std::string name = "open_sheet";
    TopoDS_Shape s = BRepPrimAPI_MakeBox(100.0, 80.0, 40.0).Shape();
    s = fillet(s, edgesWhere(s, [](const auto& c) { return isLineAlong(c, gp::DZ()); }), 10.0,
               name);
    s = fillet(s,
               edgesWhere(s,
                          [](const BRepAdaptor_Curve& c) {
                              return (isLineAlong(c, gp::DX()) || isLineAlong(c, gp::DY())) &&
                                     std::abs(midpoint(c).Z()) < selectTolerance;
                          }),
               8.0, name);
    TopoDS_Shell shell;
    BRep_Builder builder;
    builder.MakeShell(shell);
    int removed = 0;
    for (TopExp_Explorer f(s, TopAbs_FACE); f.More(); f.Next()) {
        const BRepAdaptor_Surface surface(TopoDS::Face(f.Current()));
        const bool top = surface.GetType() == GeomAbs_Plane &&
                         surface.Plane().Axis().Direction().IsParallel(gp::DZ(), 1e-9) &&
                         std::abs(surface.Plane().Location().Z() - 40.0) < selectTolerance;
        if (top) {
            ++removed;
        } else {
            builder.Add(shell, f.Current());
        }
    }
    check(removed == 1, name, "remove the top face");
    return {name,
            "open tray: box 100 x 80 x 40 mm, vertical edges filleted at 10 mm, bottom rim at "
            "8 mm, top face removed; boundary and smooth edges",
            shell, 8.0};
}

// A plate 120 x 80 x 10 with a rib 16 mm thick and 25 mm high along its length. The rib's
// top edges are filleted at 6 mm, leaving a 4 mm flat between two smooth edges; its base
// edges carry concave 6 mm fillets.
CadShape closeFillets()
{
    const std::string name = "close_fillets";
    const TopoDS_Shape plate = BRepPrimAPI_MakeBox(120.0, 80.0, 10.0).Shape();
    const TopoDS_Shape rib =
        BRepPrimAPI_MakeBox(gp_Pnt(0.0, 32.0, 10.0), 120.0, 16.0, 25.0).Shape();
    BRepAlgoAPI_Fuse fuse(plate, rib);
    check(fuse.IsDone(), name, "fuse rib");
    TopoDS_Shape s = unified(fuse.Shape());
    const auto ribEdgeAt = [](double z) {
        return [z](const BRepAdaptor_Curve& c) {
            const gp_Pnt m = midpoint(c);
            const bool onRibSide = std::abs(m.Y() - 32.0) < selectTolerance ||
                                   std::abs(m.Y() - 48.0) < selectTolerance;
            return isLineAlong(c, gp::DX()) && onRibSide && std::abs(m.Z() - z) < selectTolerance;
        };
    };
    BRepFilletAPI_MakeFillet maker(s);
    const auto top = edgesWhere(s, ribEdgeAt(35.0));
    const auto base = edgesWhere(s, ribEdgeAt(10.0));
    check(top.size() == 2 && base.size() == 2, name, "rib edges");
    for (const TopoDS_Edge& e : top) {
        maker.Add(6.0, e);
    }
    for (const TopoDS_Edge& e : base) {
        maker.Add(6.0, e);
    }
    maker.Build();
    check(maker.IsDone(), name, "rib fillets");
    return {name,
            "plate 120 x 80 x 10 mm with a rib 16 mm thick and 25 mm high; rib top edges "
            "filleted at 6 mm (4 mm flat between two smooth edges), rib base at 6 mm (concave)",
            maker.Shape(), 6.0};
}

// Held out: never used to tune the method (docs/ACCURACY.md reports them apart).

// A prism 60 mm long over a right trapezoid (bottom 100, height 30, top 48): its slanted face
// meets the bottom at 30 degrees (a knife edge, the normal turning by 150) and the top at 150
// degrees (a shallow crease, the normal turning by 30); right angles elsewhere.
CadShape wedge()
{
    const std::string name = "wedge";
    const double pi = 3.14159265358979323846;
    const double length = 100.0, height = 30.0, depth = 60.0;
    const double top = length - height / std::tan(30.0 * pi / 180.0);
    BRepBuilderAPI_MakePolygon section(gp_Pnt(0.0, 0.0, 0.0), gp_Pnt(length, 0.0, 0.0),
                                       gp_Pnt(top, 0.0, height), gp_Pnt(0.0, 0.0, height), true);
    check(section.IsDone(), name, "section");
    BRepBuilderAPI_MakeFace face(section.Wire(), true);
    check(face.IsDone(), name, "section face");
    BRepPrimAPI_MakePrism prism(face.Face(), gp_Vec(0.0, depth, 0.0));
    check(prism.IsDone(), name, "prism");
    return {name,
            "prism 60 mm long over a right trapezoid 100 x 30 mm: a 30 degree knife edge and a "
            "150 degree shallow crease (normal turning by 30 degrees); sharp edges only",
            prism.Shape(), 0.0};
}

// A cylinder of radius 30 and height 40 whose top rim is chamfered at 5 mm (two circular
// sharp edges of 45 degrees, a conical face between) and whose bottom rim is filleted at 8 mm
// (two circular smooth edges, a torus between).
CadShape chamferedCylinder()
{
    const std::string name = "chamfered_cylinder";
    const TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(30.0, 40.0).Shape();
    const auto rimAt = [](double z) {
        return [z](const BRepAdaptor_Curve& c) {
            return c.GetType() == GeomAbs_Circle &&
                   std::abs(c.Circle().Location().Z() - z) < selectTolerance;
        };
    };
    const auto top = edgesWhere(cylinder, rimAt(40.0));
    check(top.size() == 1, name, "top rim");
    BRepFilletAPI_MakeChamfer chamfer(cylinder);
    chamfer.Add(5.0, top.front());
    chamfer.Build();
    check(chamfer.IsDone(), name, "chamfer");
    const TopoDS_Shape s = chamfer.Shape();
    const auto bottom = edgesWhere(s, rimAt(0.0));
    check(bottom.size() == 1, name, "bottom rim");
    return {name,
            "cylinder of radius 30 and height 40 mm, top rim chamfered at 5 mm (sharp circles at "
            "45 degrees), bottom rim filleted at 8 mm (smooth circles); sharp and smooth edges",
            fillet(s, bottom, 8.0, name), 8.0};
}

} // namespace

std::vector<std::string> cadShapeNames()
{
    return {"box_fillets", "box_chamfers", "variable_fillet", "boss_blend",
            "plate_holes", "open_sheet",   "close_fillets"};
}

std::vector<std::string> heldOutShapeNames()
{
    return {"wedge", "chamfered_cylinder"};
}

CadShape makeCadShape(const std::string& name)
{
    try {
        if (name == "box_fillets") {
            return boxFillets();
        }
        if (name == "box_chamfers") {
            return boxChamfers();
        }
        if (name == "variable_fillet") {
            return variableFillet();
        }
        if (name == "boss_blend") {
            return bossBlend();
        }
        if (name == "plate_holes") {
            return plateHoles();
        }
        if (name == "open_sheet") {
            return openSheet();
        }
        if (name == "close_fillets") {
            return closeFillets();
        }
        if (name == "wedge") {
            return wedge();
        }
        if (name == "chamfered_cylinder") {
            return chamferedCylinder();
        }
    } catch (const Standard_Failure& e) {
        throw std::runtime_error("OpenCASCADE could not build the part " + name + ": " +
                                 e.GetMessageString());
    }
    std::string known;
    std::vector<std::string> all = cadShapeNames();
    for (const std::string& n : heldOutShapeNames()) {
        all.push_back(n);
    }
    for (const std::string& n : all) {
        known += (known.empty() ? "" : ", ") + n;
    }
    throw std::invalid_argument("Unknown benchmark part \"" + name + "\"; known parts: " + known +
                                ".");
}

} // namespace featurelines::bench
