// SPDX-License-Identifier: LGPL-2.1-or-later
#include "PartFamilies.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <stdexcept>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Curve2d.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepFilletAPI_MakeChamfer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepGProp.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepOffsetAPI_DraftAngle.hxx>
#include <BRepOffsetAPI_MakeThickSolid.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <ShapeFix_Shape.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <Standard_Failure.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>
#include <gp_Pln.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Trsf.hxx>

namespace featurelines::bench {

namespace {

constexpr double pi = 3.14159265358979323846;

double radians(double degrees)
{
    return degrees * pi / 180.0;
}

/// The part's numbers, drawn from one std::mt19937 through its 32-bit integers only (the
/// engine's output is fixed by the standard, the std:: distributions' is not), each recorded
/// with its range.
class Draws
{
public:
    explicit Draws(std::uint32_t seed) : engine_(seed) {}

    /// Uniform in (0, 1).
    double unit() { return (static_cast<double>(engine_() & 0xffffffffu) + 0.5) / 4294967296.0; }

    bool chance(double p) { return unit() < p; }

    /// Uniform in 0 .. n-1, not recorded (edge picks).
    int index(int n) { return std::min(n - 1, static_cast<int>(unit() * n)); }

    double uniform(const std::string& name, double lo, double hi)
    {
        hi = std::max(hi, lo);
        return record(name, std::clamp(lo + (hi - lo) * unit(), lo, hi), lo, hi);
    }

    double logUniform(const std::string& name, double lo, double hi)
    {
        hi = std::max(hi, lo);
        return record(name, std::clamp(lo * std::pow(hi / lo, unit()), lo, hi), lo, hi);
    }

    int integer(const std::string& name, int lo, int hi)
    {
        hi = std::max(hi, lo);
        const int v = lo + index(hi - lo + 1);
        record(name, v, lo, hi);
        return v;
    }

    /// A value that follows from drawn ones (lo = hi = value).
    double note(const std::string& name, double value) { return record(name, value, value, value); }

    std::vector<DrawnValue> values;

private:
    double record(const std::string& name, double v, double lo, double hi)
    {
        values.push_back({name, v, lo, hi});
        return v;
    }

    std::mt19937 engine_;
};

/// What one part's construction carries along: options, draws, the smallest rounding and the
/// steps that failed.
struct PartBuild
{
    PartBuild(const RandomPartOptions& o, std::uint32_t seed) : options(o), draws(seed) {}

    const RandomPartOptions& options;
    Draws draws;
    bool closed = true;
    double smallestRadius = 0.0;
    std::string fallbacks;

    void noteRadius(double r)
    {
        if (r > 0.0 && (smallestRadius == 0.0 || r < smallestRadius)) {
            smallestRadius = r;
        }
    }
    void failed(const std::string& what) { fallbacks += (fallbacks.empty() ? "" : "; ") + what; }
    /// A dihedral angle (degrees) in the options' range intersected with [lo, hi].
    double dihedral(const std::string& name, double lo, double hi)
    {
        return draws.uniform(name, std::max(lo, options.minDihedralDegrees),
                             std::min(hi, options.maxDihedralDegrees));
    }
    /// A radius (spacings), log-uniform in [minRadius, min(maxRadius, cap)].
    double radius(const std::string& name, double cap)
    {
        return draws.logUniform(name, options.minRadius, std::min(options.maxRadius, cap));
    }
};

void require(bool done, const std::string& step)
{
    if (!done) {
        throw std::runtime_error("OpenCASCADE failed: " + step);
    }
}

int countOf(const TopoDS_Shape& shape, TopAbs_ShapeEnum type)
{
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(shape, type, map);
    return map.Extent();
}

/// A solid part is one valid solid of positive volume; an open part a valid set of faces.
bool isValidPart(const TopoDS_Shape& shape, bool closed)
{
    if (shape.IsNull() || countOf(shape, TopAbs_FACE) == 0 ||
        !BRepCheck_Analyzer(shape).IsValid()) {
        return false;
    }
    if (!closed) {
        return true;
    }
    if (countOf(shape, TopAbs_SOLID) != 1) {
        return false;
    }
    GProp_GProps props;
    BRepGProp::VolumeProperties(shape, props);
    return props.Mass() > 0.0;
}

/// `shape` when it is a valid part, else ShapeFix's repair of it (fillets on B-spline faces
/// come out with tolerances BRepCheck rejects), which the caller checks again.
TopoDS_Shape healed(const TopoDS_Shape& shape, bool closed)
{
    if (isValidPart(shape, closed)) {
        return shape;
    }
    ShapeFix_Shape fix(shape);
    fix.Perform();
    return fix.Shape();
}

/// The one solid of `shape` (booleans return compounds).
TopoDS_Shape singleSolid(const TopoDS_Shape& shape)
{
    TopExp_Explorer ex(shape, TopAbs_SOLID);
    require(ex.More(), "no solid");
    const TopoDS_Shape solid = ex.Current();
    ex.Next();
    require(!ex.More(), "the part fell apart into several solids");
    return solid;
}

/// Merges faces that a boolean left split on one surface, so the B-rep's edges are the part's.
TopoDS_Shape unified(const TopoDS_Shape& shape)
{
    ShapeUpgrade_UnifySameDomain unify(shape, true, true, false);
    unify.Build();
    return unify.Shape();
}

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b)
{
    BRepAlgoAPI_Cut op(a, b);
    require(op.IsDone() && !op.HasErrors(), "cut");
    return unified(op.Shape());
}

TopoDS_Shape fuse(const TopoDS_Shape& a, const TopoDS_Shape& b)
{
    BRepAlgoAPI_Fuse op(a, b);
    require(op.IsDone() && !op.HasErrors(), "fuse");
    return unified(op.Shape());
}

TopoDS_Shape box(double x, double y, double z, double dx, double dy, double dz)
{
    return BRepPrimAPI_MakeBox(gp_Pnt(x, y, z), dx, dy, dz).Shape();
}

TopoDS_Shape cylinder(const gp_Pnt& base, const gp_Dir& axis, double r, double h)
{
    return BRepPrimAPI_MakeCylinder(gp_Ax2(base, axis), r, h).Shape();
}

/// A planar face on a closed polygon.
TopoDS_Face polygonFace(const std::vector<gp_Pnt>& corners)
{
    BRepBuilderAPI_MakePolygon polygon;
    for (const gp_Pnt& p : corners) {
        polygon.Add(p);
    }
    polygon.Close();
    require(polygon.IsDone(), "polygon");
    BRepBuilderAPI_MakeFace face(polygon.Wire(), true);
    require(face.IsDone(), "polygon face");
    return face.Face();
}

TopoDS_Shape prism(const TopoDS_Shape& profile, const gp_Vec& direction)
{
    BRepPrimAPI_MakePrism maker(profile, direction);
    require(maker.IsDone(), "prism");
    return maker.Shape();
}

/// Applies one step of the part (a boolean feature); when OpenCASCADE throws or the result
/// is not a valid part, the part stays as it was and the step is reported.
bool tryStep(PartBuild& build, TopoDS_Shape& shape, const std::string& what,
             const std::function<TopoDS_Shape(const TopoDS_Shape&)>& step)
{
    try {
        TopoDS_Shape next = step(shape);
        next = healed(build.closed ? singleSolid(next) : next, build.closed);
        if (build.closed) {
            next = singleSolid(next);
        }
        if (isValidPart(next, build.closed)) {
            shape = next;
            return true;
        }
    } catch (const Standard_Failure&) {
    } catch (const std::runtime_error&) {
    }
    build.failed(what + " left out");
    return false;
}

/// Largest angle between the outward normals of `f1` and `f2` at three points inside `edge`
/// (degrees); 0 where a normal is undefined.
double creaseDegrees(const TopoDS_Edge& edge, const TopoDS_Face& f1, const TopoDS_Face& f2)
{
    const BRepAdaptor_Curve curve(edge);
    double largest = 0.0;
    for (const double share : {0.25, 0.5, 0.75}) {
        const double t =
            curve.FirstParameter() + share * (curve.LastParameter() - curve.FirstParameter());
        gp_Dir normal[2];
        bool defined = true;
        for (int k = 0; k < 2; ++k) {
            const TopoDS_Face& face = k == 0 ? f1 : f2;
            const gp_Pnt2d uv = BRepAdaptor_Curve2d(edge, face).Value(t);
            BRepLProp_SLProps props(BRepAdaptor_Surface(face), uv.X(), uv.Y(), 1, 1e-9);
            defined = defined && props.IsNormalDefined();
            if (defined) {
                normal[k] = face.Orientation() == TopAbs_REVERSED ? props.Normal().Reversed()
                                                                  : props.Normal();
            }
        }
        if (defined) {
            largest = std::max(largest, normal[0].Angle(normal[1]) * 180.0 / pi);
        }
    }
    return largest;
}

/// `edges` in an order of their geometry alone: by the point at the middle of their parameter
/// range, then by length. The shape's own order is not a property of the part: OpenCASCADE's
/// hollowing (BRepOffsetAPI_MakeThickSolid) builds the same solid with its edges in an order
/// that changes from run to run, so picking "the i-th edge" in it made a seed's part differ
/// between runs (random part 165 came out in three shapes over eight runs).
void sortByGeometry(std::vector<TopoDS_Edge>& edges)
{
    struct Keyed
    {
        std::array<double, 4> key;
        TopoDS_Edge edge;
    };
    std::vector<Keyed> keyed;
    keyed.reserve(edges.size());
    for (const TopoDS_Edge& e : edges) {
        const BRepAdaptor_Curve c(e);
        const gp_Pnt m = c.Value(0.5 * (c.FirstParameter() + c.LastParameter()));
        keyed.push_back({{m.X(), m.Y(), m.Z(), GCPnts_AbscissaPoint::Length(c)}, e});
    }
    std::stable_sort(keyed.begin(), keyed.end(),
                     [](const Keyed& a, const Keyed& b) { return a.key < b.key; });
    for (size_t i = 0; i < edges.size(); ++i) {
        edges[i] = keyed[i].edge;
    }
}

/// The edges of `shape` between two faces meeting at a crease of at least
/// RandomPartOptions::minCreaseDegrees (no tangent join, no seam), at least `minLength` long,
/// in the order of sortByGeometry.
std::vector<TopoDS_Edge> sharpEdges(const TopoDS_Shape& shape, double minLength,
                                    double minCreaseDegrees)
{
    TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
    TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
    std::vector<TopoDS_Edge> result;
    for (int i = 1; i <= edgeFaces.Extent(); ++i) {
        const TopoDS_Edge& edge = TopoDS::Edge(edgeFaces.FindKey(i));
        const TopTools_ListOfShape& faces = edgeFaces.FindFromIndex(i);
        if (BRep_Tool::Degenerated(edge) || faces.Extent() != 2) {
            continue;
        }
        const TopoDS_Face& f1 = TopoDS::Face(faces.First());
        const TopoDS_Face& f2 = TopoDS::Face(faces.Last());
        if (f1.IsSame(f2) || GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(edge)) < minLength) {
            continue;
        }
        try {
            if (creaseDegrees(edge, f1, f2) >= minCreaseDegrees) {
                result.push_back(edge);
            }
        } catch (const Standard_Failure&) {
            // No curve on a face: not an edge to round.
        }
    }
    sortByGeometry(result);
    return result;
}

/// `count` distinct edges of `edges` picked at random.
std::vector<TopoDS_Edge> pickEdges(Draws& draws, std::vector<TopoDS_Edge> edges, int count)
{
    count = std::min<int>(count, static_cast<int>(edges.size()));
    for (int i = 0; i < count; ++i) {
        const int j = i + draws.index(static_cast<int>(edges.size()) - i);
        std::swap(edges[static_cast<size_t>(i)], edges[static_cast<size_t>(j)]);
    }
    edges.resize(static_cast<size_t>(count));
    return edges;
}

struct Rounding
{
    TopoDS_Edge edge;
    double start = 0.0;
    double end = 0.0; // equal to start unless the radius varies along the edge
};

/// One rounding attempt: `roundings` with their sizes times `factor` (at least minRadius).
/// True, with `shape` replaced, when OpenCASCADE made a valid part.
bool roundOnce(PartBuild& build, TopoDS_Shape& shape, const std::vector<Rounding>& roundings,
               bool chamfer, double factor)
{
    const double minR = build.options.minRadius;
    try {
        TopoDS_Shape next;
        double smallest = 0.0;
        if (chamfer) {
            BRepFilletAPI_MakeChamfer maker(shape);
            for (const Rounding& r : roundings) {
                maker.Add(std::max(minR, factor * r.start), r.edge);
            }
            maker.Build();
            if (!maker.IsDone()) {
                return false;
            }
            next = maker.Shape();
        } else {
            BRepFilletAPI_MakeFillet maker(shape);
            for (const Rounding& r : roundings) {
                const double r1 = std::max(minR, factor * r.start);
                const double r2 = std::max(minR, factor * r.end);
                if (r1 == r2) {
                    maker.Add(r1, r.edge);
                } else {
                    maker.Add(r1, r2, r.edge);
                }
                smallest = smallest == 0.0 ? std::min(r1, r2) : std::min({smallest, r1, r2});
            }
            maker.Build();
            if (!maker.IsDone()) {
                return false;
            }
            next = maker.Shape();
        }
        next = healed(build.closed ? singleSolid(next) : next, build.closed);
        if (build.closed) {
            next = singleSolid(next);
        }
        if (!isValidPart(next, build.closed)) {
            return false;
        }
        shape = next;
        build.noteRadius(smallest);
        return true;
    } catch (const Standard_Failure&) {
    } catch (const std::runtime_error&) {
    }
    return false;
}

/// True when a face of `shape` bounded by `edge` is not analytic (a B-spline, Bezier or offset
/// surface, as the freeform family's lofts).
bool touchesFreeformFace(const TopoDS_Shape& shape, const TopoDS_Edge& edge)
{
    TopTools_IndexedDataMapOfShapeListOfShape facesOfEdge;
    TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, facesOfEdge);
    const int index = facesOfEdge.FindIndex(edge);
    if (index == 0) {
        return false;
    }
    for (const TopoDS_Shape& face : facesOfEdge(index)) {
        const GeomAbs_SurfaceType type = BRepAdaptor_Surface(TopoDS::Face(face)).GetType();
        if (type == GeomAbs_BSplineSurface || type == GeomAbs_BezierSurface ||
            type == GeomAbs_OffsetSurface || type == GeomAbs_OtherSurface) {
            return true;
        }
    }
    return false;
}

/// Tries the roundings with the retry ladder of RandomPartOptions::roundingTries: as drawn,
/// sizes halved, then half the edges, a quarter, ...; the last try takes each edge alone at
/// the smallest size until one works. Returns the try that worked (0 = as drawn) or -1.
/// The last try leaves out edges of freeform faces: a rounding of the smallest size along a
/// lofted B-spline face can keep OpenCASCADE's blend approximation busy for many minutes
/// (random part 71 at 50 000 points), so the ladder ends by a rule of the shape, not a timer.
int applyRoundings(PartBuild& build, TopoDS_Shape& shape, const std::vector<Rounding>& roundings,
                   bool chamfer)
{
    const int tries = build.options.roundingTries;
    for (int attempt = 0; attempt < tries; ++attempt) {
        if (attempt > 0 && attempt == tries - 1) {
            for (const Rounding& r : roundings) {
                if (touchesFreeformFace(shape, r.edge)) {
                    continue;
                }
                if (roundOnce(build, shape, {r}, chamfer, 0.0)) {
                    return attempt;
                }
            }
            return -1;
        }
        const size_t count =
            attempt < 2 ? roundings.size() : std::max<size_t>(1, roundings.size() >> (attempt - 1));
        const std::vector<Rounding> some(roundings.begin(),
                                         roundings.begin() + static_cast<long>(count));
        if (roundOnce(build, shape, some, chamfer, attempt == 0 ? 1.0 : 0.5)) {
            return attempt;
        }
    }
    return -1;
}

/// Chamfers, then fillets (fixed or variable radius) on random sharp edges of a solid part,
/// sizes up to `cap` spacings (the family's features' scale).
TopoDS_Shape roundRandomEdges(PartBuild& build, TopoDS_Shape shape, double cap)
{
    Draws& draws = build.draws;
    const RandomPartOptions& o = build.options;
    const int total = draws.integer("rounded_edges", 1, o.maxRoundedEdges);
    int chamfers = 0;
    for (int i = 0; i < total; ++i) {
        chamfers += draws.chance(o.chamferShare) ? 1 : 0;
    }
    const int fillets = total - chamfers;
    draws.note("chamfered_edges", chamfers);
    draws.note("filleted_edges", fillets);
    for (const bool chamfer : {true, false}) {
        const int count = chamfer ? chamfers : fillets;
        if (count == 0) {
            continue;
        }
        const auto edges =
            pickEdges(draws, sharpEdges(shape, 2.0 * o.minRadius, o.minCreaseDegrees), count);
        std::vector<Rounding> roundings;
        for (const TopoDS_Edge& e : edges) {
            Rounding r;
            r.edge = e;
            r.start = build.radius(chamfer ? "chamfer_distance" : "fillet_radius", cap);
            r.end = r.start;
            if (!chamfer && draws.chance(o.variableFilletShare)) {
                r.end = build.radius("fillet_radius_end", cap);
            }
            roundings.push_back(r);
        }
        if (roundings.empty()) {
            build.failed(std::string(chamfer ? "chamfers" : "fillets") +
                         " left out (no sharp edge long enough)");
            continue;
        }
        const int attempt = applyRoundings(build, shape, roundings, chamfer);
        const std::string what = chamfer ? "chamfers" : "fillets";
        if (attempt < 0) {
            build.failed(what + " left out (" + std::to_string(o.roundingTries) + " tries)");
        } else if (attempt > 0) {
            build.failed(what + " made at try " + std::to_string(attempt + 1));
        }
    }
    return shape;
}

/// The side of a square-ish part whose area, `areaPerSide2` times the side squared, is
/// `area`.
double sideForArea(double area, double areaPerSide2)
{
    return std::sqrt(area / areaPerSide2);
}

struct Point2
{
    double x = 0.0;
    double y = 0.0;
};

Point2 operator+(Point2 a, Point2 b)
{
    return {a.x + b.x, a.y + b.y};
}
Point2 operator-(Point2 a, Point2 b)
{
    return {a.x - b.x, a.y - b.y};
}
Point2 operator*(double s, Point2 a)
{
    return {s * a.x, s * a.y};
}
double norm(Point2 a)
{
    return std::hypot(a.x, a.y);
}
Point2 unitOf(Point2 a)
{
    return (1.0 / norm(a)) * a;
}
Point2 leftNormal(Point2 d)
{
    return {-d.y, d.x};
}

/// The outline of a polyline thickened by `t` about its centre line, with mitred corners.
std::vector<Point2> thickPolyline(const std::vector<Point2>& c, double t)
{
    std::vector<Point2> left;
    std::vector<Point2> right;
    const size_t n = c.size();
    for (size_t i = 0; i < n; ++i) {
        Point2 offset;
        if (i == 0 || i + 1 == n) {
            const Point2 d = i == 0 ? unitOf(c[1] - c[0]) : unitOf(c[n - 1] - c[n - 2]);
            offset = (0.5 * t) * leftNormal(d);
        } else {
            const Point2 n0 = leftNormal(unitOf(c[i] - c[i - 1]));
            const Point2 n1 = leftNormal(unitOf(c[i + 1] - c[i]));
            const Point2 m = unitOf(n0 + n1);
            offset = (0.5 * t / (m.x * n0.x + m.y * n0.y)) * m;
        }
        left.push_back(c[i] + offset);
        right.push_back(c[i] - offset);
    }
    std::vector<Point2> outline = left;
    outline.insert(outline.end(), right.rbegin(), right.rend());
    return outline;
}

/// Points (x, z) of the XZ plane as 3D points at y = 0.
std::vector<gp_Pnt> inXZ(const std::vector<Point2>& pts)
{
    std::vector<gp_Pnt> result;
    for (const Point2& p : pts) {
        result.emplace_back(p.x, 0.0, p.y);
    }
    return result;
}

// ---- Prismatic block -------------------------------------------------------------------

// A block whose end face is slanted at a drawn dihedral angle to its bottom, with pockets, a
// slot across, a step along the front, through and blind holes from the top.
TopoDS_Shape prismaticBlock(PartBuild& b, double area)
{
    Draws& d = b.draws;
    const double depthRatio = d.uniform("depth_ratio", 0.4, 1.0);
    const double heightRatio = d.uniform("height_ratio", 0.15, 0.5);
    const double theta = b.dihedral("end_dihedral", 10.0, 170.0);
    const double W = d.note(
        "length", sideForArea(area, 2.0 * (depthRatio + heightRatio + depthRatio * heightRatio)));
    const double D = d.note("depth", depthRatio * W);
    const double knife = radians(std::min(theta, 180.0 - theta));
    const double H = d.note("height", std::min(heightRatio * W, 0.6 * W * std::tan(knife)));
    const double run = H / std::tan(radians(theta)); // > 0: the top is shorter than the bottom
    TopoDS_Shape s =
        prism(polygonFace(inXZ({{0, 0}, {W, 0}, {W - run, H}, {0, H}})), gp_Vec(0, D, 0));
    s = singleSolid(s);

    const double top = std::min(W, W - run); // length of the region under the flat top
    const double margin = 0.05 * W;
    const auto place = [&](const std::string& name, double size, double extent) {
        return d.uniform(name, margin, std::max(margin, extent - margin - size));
    };
    for (int i = d.integer("pockets", 0, 2); i > 0; --i) {
        const double lx = d.uniform("pocket_length", 0.1 * top, 0.35 * top);
        const double ly = d.uniform("pocket_width", 0.1 * D, 0.4 * D);
        const double depth = d.uniform("pocket_depth", 0.2 * H, 0.7 * H);
        const double x = place("pocket_x", lx, top);
        const double y = place("pocket_y", ly, D);
        tryStep(b, s, "pocket", [&](const TopoDS_Shape& p) {
            return cut(p, box(x, y, H - depth, lx, ly, depth + 1.0));
        });
    }
    if (d.integer("slots", 0, 1) == 1) {
        const double w = d.uniform("slot_width", 2.0, std::max(2.0, 0.15 * top));
        const double depth = d.uniform("slot_depth", 0.2 * H, 0.6 * H);
        const double x = place("slot_x", w, top);
        tryStep(b, s, "slot", [&](const TopoDS_Shape& p) {
            return cut(p, box(x, -1.0, H - depth, w, D + 2.0, depth + 1.0));
        });
    }
    if (d.integer("steps", 0, 1) == 1) {
        const double w = d.uniform("step_width", 0.1 * D, 0.3 * D);
        const double depth = d.uniform("step_depth", 0.2 * H, 0.6 * H);
        tryStep(b, s, "step", [&](const TopoDS_Shape& p) {
            return cut(p, box(-1.0, -1.0, H - depth, 2.0 * W + 2.0, w + 1.0, depth + 1.0));
        });
    }
    const int through = d.integer("through_holes", 0, 3);
    const int blind = d.integer("blind_holes", 0, 2);
    for (int i = 0; i < through + blind; ++i) {
        const bool isThrough = i < through;
        const double r = d.uniform("hole_radius", 2.0, std::max(2.0, 0.08 * std::min(top, D)));
        const double depth = isThrough ? H + 2.0 : d.uniform("hole_depth", 0.3 * H, 0.8 * H);
        const double x = place("hole_x", 2.0 * r, top) + r;
        const double y = place("hole_y", 2.0 * r, D) + r;
        tryStep(b, s, isThrough ? "through hole" : "blind hole", [&](const TopoDS_Shape& p) {
            return cut(p, cylinder(gp_Pnt(x, y, H + 1.0 - depth - (isThrough ? 0.0 : 1.0)),
                                   gp::DZ(), r, depth + (isThrough ? 0.0 : 1.0)));
        });
    }
    return roundRandomEdges(b, s, 0.3 * H);
}

// ---- Bracket -----------------------------------------------------------------------------

// An L- or U-bracket: a thick polyline (base and one or two legs at drawn angles) extruded,
// with through holes in the base.
TopoDS_Shape bracket(PartBuild& b, double area)
{
    Draws& d = b.draws;
    const bool u = d.integer("u_shaped", 0, 1) == 1;
    const double widthRatio = d.uniform("width_ratio", 0.3, 1.0);
    const double leg1 = d.uniform("leg_ratio", 0.3, 1.0);
    const double leg2 = u ? d.uniform("leg_ratio", 0.3, 1.0) : 0.0;
    const double phi1 = b.dihedral("leg_dihedral", u ? 75.0 : 30.0, 150.0);
    const double phi2 = u ? b.dihedral("leg_dihedral", 75.0, 150.0) : 0.0;
    const double L =
        d.note("base_length", sideForArea(area, 2.0 * widthRatio * (1.0 + leg1 + leg2)));
    const double D = d.note("width", widthRatio * L);
    const double t = d.uniform("thickness", std::max(3.0, 0.03 * L), std::max(3.0, 0.1 * L));
    std::vector<Point2> centre;
    centre.push_back(leg1 * L * Point2{std::cos(radians(phi1)), std::sin(radians(phi1))});
    centre.push_back({0.0, 0.0});
    centre.push_back({L, 0.0});
    if (u) {
        centre.push_back(Point2{L, 0.0} +
                         leg2 * L * Point2{-std::cos(radians(phi2)), std::sin(radians(phi2))});
    }
    TopoDS_Shape s =
        singleSolid(prism(polygonFace(inXZ(thickPolyline(centre, t))), gp_Vec(0, D, 0)));
    for (int i = d.integer("holes", 0, 3); i > 0; --i) {
        const double r = d.uniform("hole_radius", 2.0, std::max(2.0, 0.12 * D));
        const double x = d.uniform("hole_x", 0.25 * L + r, 0.85 * L - r);
        const double y = d.uniform("hole_y", 0.1 * D + r, 0.9 * D - r);
        tryStep(b, s, "hole", [&](const TopoDS_Shape& p) {
            return cut(p, cylinder(gp_Pnt(x, y, -t), gp::DZ(), r, 2.0 * t));
        });
    }
    return roundRandomEdges(b, s, 2.0 * t);
}

// ---- Ribbed plate --------------------------------------------------------------------------

// A plate with drafted ribs and rectangular or V grooves along its length on top, drawn gaps
// between them.
TopoDS_Shape ribbedPlate(PartBuild& b, double area)
{
    Draws& d = b.draws;
    const RandomPartOptions& o = b.options;
    const double depthRatio = d.uniform("depth_ratio", 0.5, 1.0);
    const double thickRatio = d.uniform("thickness_ratio", 0.04, 0.12);
    const int features = d.integer("features", 2, 8);
    std::vector<double> heights;
    double ribArea = 0.0;
    for (int i = 0; i < features; ++i) {
        heights.push_back(d.uniform("rib_height_ratio", 0.02, 0.1));
        ribArea += 2.0 * heights.back();
    }
    const double W =
        d.note("length", sideForArea(area, 2.0 * depthRatio +
                                               2.0 * thickRatio * (1.0 + depthRatio) + ribArea));
    const double D = d.note("depth", depthRatio * W);
    const double T = d.note("thickness", thickRatio * W);
    TopoDS_Shape s = box(0, 0, 0, W, D, T);
    double y = d.uniform("first_offset", 0.05 * D, 0.25 * D);
    for (int i = 0; i < features; ++i) {
        const bool rib = d.chance(0.6);
        const double inset = d.chance(0.5) ? d.uniform("end_inset", 0.05 * W, 0.2 * W) : 0.0;
        const double x0 = inset > 0.0 ? inset : -1.0;
        const double length = inset > 0.0 ? W - 2.0 * inset : W + 2.0;
        std::vector<Point2> profile; // (y, z)
        if (rib) {
            const double w = d.uniform("rib_width", 3.0, 20.0);
            // Interior angle between the rib's top and its side: 90 is a straight rib.
            const double beta = b.dihedral("rib_top_dihedral", 90.0, 135.0);
            const double lean = std::tan(radians(beta - 90.0));
            const double h =
                std::min(heights[static_cast<size_t>(i)] * W, lean > 0.0 ? 0.35 * w / lean : 1e300);
            profile = {{y, T}, {y + w, T}, {y + w - h * lean, T + h}, {y + h * lean, T + h}};
            d.note("rib_height", h);
            y += w;
        } else {
            const double depth = d.uniform("groove_depth", 1.0, std::max(1.0, 0.6 * T));
            if (d.chance(0.5)) {
                const double gamma = b.dihedral("groove_dihedral", 30.0, 150.0);
                const double half = depth * std::tan(radians(0.5 * gamma));
                profile = {{y, T + 1.0}, {y + 2.0 * half, T + 1.0}, {y + half, T - depth}};
                y += 2.0 * half;
            } else {
                const double w = d.uniform("groove_width", 2.0, 20.0);
                profile = {{y, T + 1.0}, {y + w, T + 1.0}, {y + w, T - depth}, {y, T - depth}};
                y += w;
            }
        }
        std::vector<gp_Pnt> corners;
        for (const Point2& p : profile) {
            corners.emplace_back(x0, p.x, p.y);
        }
        if (y > 0.95 * D) {
            d.note("features_placed", i);
            break;
        }
        const TopoDS_Shape body = prism(polygonFace(corners), gp_Vec(length, 0, 0));
        tryStep(b, s, rib ? "rib" : "groove",
                [&](const TopoDS_Shape& p) { return rib ? fuse(p, body) : cut(p, body); });
        y += d.uniform("feature_gap", o.minRibGap, o.maxRibGap);
    }
    return roundRandomEdges(b, s, std::max(o.minRadius, 0.5 * T));
}

// ---- Boss plate ----------------------------------------------------------------------------

/// A hole of the drawn kind down the axis (x, y) from height `top`: plain, counterbored or
/// countersunk, through the part (to z = -1).
TopoDS_Shape holeTool(PartBuild& b, double x, double y, double top, double maxRadius)
{
    Draws& d = b.draws;
    const int kind = d.integer("hole_kind", 0, 2); // plain, counterbore, countersink
    const double r = d.uniform("bore_radius", 1.5, std::max(1.5, 0.5 * maxRadius));
    TopoDS_Shape tool = cylinder(gp_Pnt(x, y, -1.0), gp::DZ(), r, top + 2.0);
    if (kind == 1) {
        const double r2 = d.uniform("counterbore_radius", r + 1.0, std::max(r + 1.0, maxRadius));
        const double depth = d.uniform("counterbore_depth", 1.0, std::max(1.0, 0.4 * top));
        tool = fuse(tool, cylinder(gp_Pnt(x, y, top - depth), gp::DZ(), r2, depth + 1.0));
    } else if (kind == 2) {
        const double r2 = d.uniform("countersink_radius", r + 1.0, std::max(r + 1.0, maxRadius));
        // The cone's opening angle, the dihedral at its bottom circle is 180 - half of it.
        const double gamma = b.dihedral("countersink_dihedral", 60.0, 120.0);
        const double h = (r2 - r) / std::tan(radians(0.5 * gamma));
        const double over = 1.0 / std::tan(radians(0.5 * gamma)); // 1 above the top
        tool = fuse(tool, BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(x, y, top - h), gp::DZ()), r, r2 + 1.0,
                                               h + over)
                              .Shape());
    }
    return tool;
}

// A plate with cylindrical bosses, each bored through (plain, counterbored or countersunk),
// and such holes in the plate.
TopoDS_Shape bossPlate(PartBuild& b, double area)
{
    Draws& d = b.draws;
    const double depthRatio = d.uniform("depth_ratio", 0.5, 1.0);
    const double thickRatio = d.uniform("thickness_ratio", 0.05, 0.15);
    const int bosses = d.integer("bosses", 1, 3);
    std::vector<double> radii;
    std::vector<double> heights;
    double bossArea = 0.0;
    for (int i = 0; i < bosses; ++i) {
        radii.push_back(d.uniform("boss_radius_ratio", 0.06, 0.15));
        heights.push_back(d.uniform("boss_height_ratio", 0.05, 0.3));
        bossArea += 2.0 * pi * radii.back() * heights.back();
    }
    const double W =
        d.note("length", sideForArea(area, 2.0 * depthRatio +
                                               2.0 * thickRatio * (1.0 + depthRatio) + bossArea));
    const double D = d.note("depth", depthRatio * W);
    const double T = d.note("thickness", thickRatio * W);
    TopoDS_Shape s = box(0, 0, 0, W, D, T);
    for (int i = 0; i < bosses; ++i) {
        const double R = radii[static_cast<size_t>(i)] * W;
        const double h = heights[static_cast<size_t>(i)] * W;
        const double x = d.uniform("boss_x", R + 0.05 * W, W - R - 0.05 * W);
        const double y =
            d.uniform("boss_y", R + 0.05 * W, std::max(R + 0.05 * W, D - R - 0.05 * W));
        tryStep(b, s, "boss", [&](const TopoDS_Shape& p) {
            return fuse(p, cylinder(gp_Pnt(x, y, T), gp::DZ(), R, h));
        });
        const TopoDS_Shape tool = holeTool(b, x, y, T + h, 0.7 * R);
        tryStep(b, s, "boss hole", [&](const TopoDS_Shape& p) { return cut(p, tool); });
    }
    for (int i = d.integer("plate_holes", 0, 3); i > 0; --i) {
        const double R = d.uniform("plate_hole_radius", 3.0, std::max(3.0, 0.06 * W));
        const double x = d.uniform("hole_x", R + 0.05 * W, W - R - 0.05 * W);
        const double y =
            d.uniform("hole_y", R + 0.05 * W, std::max(R + 0.05 * W, D - R - 0.05 * W));
        const TopoDS_Shape tool = holeTool(b, x, y, T, R);
        tryStep(b, s, "plate hole", [&](const TopoDS_Shape& p) { return cut(p, tool); });
    }
    return roundRandomEdges(b, s, std::max(b.options.minRadius, 0.5 * T));
}

// ---- Revolved ------------------------------------------------------------------------------

// A shaft: sections of drawn radius and length joined by shoulders or cones, rectangular
// grooves, an optional bore; revolved about z.
TopoDS_Shape revolved(PartBuild& b, double area)
{
    Draws& d = b.draws;
    const double lengthRatio = d.uniform("length_ratio", 2.0, 8.0);
    const double R = d.note("radius", std::sqrt(area / (2.0 * pi * (lengthRatio + 1.0))));
    const double Z = d.note("length", lengthRatio * R);
    const int sections = d.integer("sections", 2, 5);
    std::vector<double> radius;
    std::vector<double> length;
    double sum = 0.0;
    for (int i = 0; i < sections; ++i) {
        double r = d.uniform("section_radius", 0.4 * R, R);
        if (i > 0 && std::abs(r - radius.back()) < b.options.minShoulder) {
            // A shoulder thinner than a detector can see: pushed to the smallest step.
            r = d.note("section_radius_stepped",
                       radius.back() + (r < radius.back() ? -1.0 : 1.0) * b.options.minShoulder);
        }
        radius.push_back(r);
        length.push_back(d.uniform("section_length_weight", 0.5, 1.5));
        sum += length.back();
    }
    for (double& l : length) {
        l *= Z / sum;
    }
    const double smallest = *std::min_element(radius.begin(), radius.end());
    const double bore =
        d.chance(0.4) ? d.uniform("bore_radius", 1.5, std::max(1.5, 0.4 * smallest)) : 0.0;

    std::vector<Point2> profile{{bore, 0.0}}; // (r, z)
    double z = 0.0;
    for (int i = 0; i < sections; ++i) {
        const double r = radius[static_cast<size_t>(i)];
        const double l = length[static_cast<size_t>(i)];
        double start = z;
        if (i == 0) {
            profile.push_back({r, 0.0});
        } else {
            const double previous = radius[static_cast<size_t>(i) - 1];
            // A cone whose face meets the previous section's cylinder at the drawn dihedral
            // (180 - its angle to the axis), or a square shoulder.
            const bool cone = d.chance(0.5);
            const double angle = cone ? b.dihedral("cone_dihedral", 100.0, 170.0) : 90.0;
            const double run =
                cone ? std::abs(r - previous) / std::tan(radians(180.0 - angle)) : 0.0;
            if (run < 0.5 * l) {
                start += run;
            }
            profile.push_back({previous, z});
            profile.push_back({r, start});
        }
        const double end = z + l;
        // A groove where the section is over 12 spacings long with 4 of material over the bore.
        if (end - start > 12.0 && r - bore > 4.0 && d.chance(0.4)) {
            const double w = d.uniform("groove_width", 2.0, std::max(2.0, 0.3 * (end - start)));
            const double depth = d.uniform("groove_depth", 1.0, std::max(1.0, 0.3 * (r - bore)));
            const double c = 0.5 * (start + end);
            profile.push_back({r, c - 0.5 * w});
            profile.push_back({r - depth, c - 0.5 * w});
            profile.push_back({r - depth, c + 0.5 * w});
            profile.push_back({r, c + 0.5 * w});
        }
        z = end;
    }
    profile.push_back({radius.back(), z});
    profile.push_back({bore, z});
    // Drop consecutive duplicates (a shoulder without run repeats its corner).
    std::vector<Point2> clean;
    for (const Point2& p : profile) {
        if (clean.empty() || norm(p - clean.back()) > 1e-9) {
            clean.push_back(p);
        }
    }
    BRepPrimAPI_MakeRevol revol(polygonFace(inXZ(clean)), gp_Ax1(gp::Origin(), gp::DZ()));
    require(revol.IsDone(), "revolve");
    const TopoDS_Shape s = singleSolid(unified(revol.Shape()));
    return roundRandomEdges(b, s, 0.25 * smallest);
}

// ---- Thin shell ----------------------------------------------------------------------------

/// The edges of `shape` whose two ends satisfy `keep`, in the order of sortByGeometry.
std::vector<TopoDS_Edge> edgesWhere(const TopoDS_Shape& shape,
                                    const std::function<bool(const gp_Pnt&, const gp_Pnt&)>& keep)
{
    std::vector<TopoDS_Edge> result;
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(shape, TopAbs_EDGE, edges);
    for (int i = 1; i <= edges.Extent(); ++i) {
        const TopoDS_Edge& e = TopoDS::Edge(edges(i));
        const BRepAdaptor_Curve c(e);
        if (keep(c.Value(c.FirstParameter()), c.Value(c.LastParameter()))) {
            result.push_back(e);
        }
    }
    sortByGeometry(result);
    return result;
}

/// The planar faces of `shape` whose normal is perpendicular to z (`sides`) or along z at
/// height `z` (not `sides`).
TopTools_ListOfShape planarFaces(const TopoDS_Shape& shape, bool sides, double z)
{
    TopTools_ListOfShape faces;
    for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) {
        const BRepAdaptor_Surface surface(TopoDS::Face(f.Current()));
        if (surface.GetType() != GeomAbs_Plane) {
            continue;
        }
        const gp_Dir normal = surface.Plane().Axis().Direction();
        if (sides ? normal.IsNormal(gp::DZ(), 1e-9)
                  : normal.IsParallel(gp::DZ(), 1e-9) &&
                        std::abs(surface.Plane().Location().Z() - z) < 1e-6) {
            faces.Append(f.Current());
        }
    }
    return faces;
}

/// Fillets `edges` of `shape` at `radius`, throwing when OpenCASCADE cannot.
TopoDS_Shape filleted(const TopoDS_Shape& shape, const std::vector<TopoDS_Edge>& edges,
                      double radius)
{
    BRepFilletAPI_MakeFillet maker(shape);
    for (const TopoDS_Edge& e : edges) {
        maker.Add(radius, e);
    }
    maker.Build();
    require(maker.IsDone(), "fillets");
    return maker.Shape();
}

/// The side faces of `box` leaning out by `draft` (radians) about the bottom.
TopoDS_Shape drafted(const TopoDS_Shape& box, double draft)
{
    BRepOffsetAPI_DraftAngle maker(box);
    const TopTools_ListOfShape sides = planarFaces(box, true, 0.0);
    for (TopTools_ListIteratorOfListOfShape f(sides); f.More(); f.Next()) {
        maker.Add(TopoDS::Face(f.Value()), gp::DZ(), -draft, gp_Pln(gp::Origin(), gp::DZ()));
        require(maker.AddDone(), "draft of a wall");
    }
    maker.Build();
    require(maker.IsDone(), "draft");
    return maker.Shape();
}

/// `solid` hollowed to walls `t` thick, its top face (at height `top`) removed.
TopoDS_Shape hollowed(const TopoDS_Shape& solid, double top, double t)
{
    const TopTools_ListOfShape open = planarFaces(solid, false, top);
    require(open.Extent() == 1, "top face of the shell");
    BRepOffsetAPI_MakeThickSolid thick;
    thick.MakeThickSolidByJoin(solid, open, -t, 1e-4, BRepOffset_Skin, false, false, GeomAbs_Arc);
    thick.Build();
    require(thick.IsDone(), "hollowing");
    const TopoDS_Shape s = singleSolid(thick.Shape());
    require(isValidPart(s, true), "hollowed shell");
    return s;
}

// A tray: a box whose side walls lean out by a draft, rounded corners and bottom rim, hollowed
// to a drawn wall thickness with its top open, holes through two walls.
TopoDS_Shape thinShell(PartBuild& b, double area)
{
    Draws& d = b.draws;
    const RandomPartOptions& o = b.options;
    const double depthRatio = d.uniform("depth_ratio", 0.5, 1.0);
    const double heightRatio = d.uniform("height_ratio", 0.2, 0.6);
    const double W = d.note(
        "length", sideForArea(area, 2.0 * (depthRatio + 2.0 * heightRatio * (1.0 + depthRatio))));
    const double D = d.note("depth", depthRatio * W);
    const double H = d.note("height", heightRatio * W);
    const double t = d.uniform("wall", o.minWall, o.maxWall);
    TopoDS_Shape s = box(0, 0, 0, W, D, H);
    // The dihedral between the bottom and a wall, inside the material, is 90 degrees plus the
    // draft.
    const double draft = radians(b.dihedral("wall_dihedral", 90.0, 120.0) - 90.0);
    if (draft > 0.0) {
        tryStep(b, s, "draft", [&](const TopoDS_Shape& p) { return drafted(p, draft); });
    }
    // The inner surface's radius is the outer one less the wall: both at least minRadius.
    const double cornerCap = std::min(o.maxRadius, 0.2 * std::min(W, D));
    if (d.chance(0.7)) {
        const double rc =
            d.logUniform("corner_radius", t + o.minRadius, std::max(t + o.minRadius, cornerCap));
        const auto corners = [](const gp_Pnt& a, const gp_Pnt& c) {
            return std::abs(a.Z() - c.Z()) > 1e-6;
        };
        if (tryStep(b, s, "corner fillets", [&](const TopoDS_Shape& p) {
                return filleted(p, edgesWhere(p, corners), rc);
            })) {
            b.noteRadius(rc - t);
        }
    }
    if (d.chance(0.5)) {
        const double rb = d.logUniform("bottom_radius", t + o.minRadius,
                                       std::max(t + o.minRadius, std::min(cornerCap, 0.5 * H)));
        const auto bottom = [](const gp_Pnt& a, const gp_Pnt& c) {
            return std::abs(a.Z()) < 1e-9 && std::abs(c.Z()) < 1e-9;
        };
        if (tryStep(b, s, "bottom fillets", [&](const TopoDS_Shape& p) {
                return filleted(p, edgesWhere(p, bottom), rb);
            })) {
            b.noteRadius(rb - t);
        }
    }
    s = hollowed(s, H, t);
    for (int i = d.integer("wall_holes", 0, 3); i > 0; --i) {
        const bool front = d.chance(0.5);
        const double span = front ? W : D;
        const double r = d.uniform("hole_radius", 2.0, std::max(2.0, 0.12 * std::min(H, span)));
        const double u = d.uniform("hole_u", 0.3 * span, 0.7 * span);
        const double v = d.uniform("hole_z", 0.35 * H, 0.75 * H);
        tryStep(b, s, "wall hole", [&](const TopoDS_Shape& p) {
            // From outside the leaning wall to just inside it.
            const double out = H * std::tan(draft) + 1.0;
            const gp_Pnt base = front ? gp_Pnt(u, -out, v) : gp_Pnt(-out, u, v);
            return cut(
                p, cylinder(base, front ? gp::DY() : gp::DX(), r, out + t / std::cos(draft) + 1.0));
        });
    }
    return roundRandomEdges(b, s, std::max(o.minRadius, t));
}

// ---- Sheet metal ---------------------------------------------------------------------------

/// Smallest distance between two segments of the plane (0 when they cross).
double segmentDistance(Point2 a, Point2 b, Point2 c, Point2 e)
{
    const auto cross = [](Point2 u, Point2 v) { return u.x * v.y - u.y * v.x; };
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, e - a);
    const double d3 = cross(e - c, a - c), d4 = cross(e - c, b - c);
    if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0))) {
        return 0.0;
    }
    const auto pointSegment = [](Point2 p, Point2 s0, Point2 s1) {
        const Point2 v = s1 - s0;
        const double t = std::clamp(
            ((p.x - s0.x) * v.x + (p.y - s0.y) * v.y) / (v.x * v.x + v.y * v.y), 0.0, 1.0);
        return norm(p - (s0 + t * v));
    };
    return std::min({pointSegment(a, c, e), pointSegment(b, c, e), pointSegment(c, a, b),
                     pointSegment(e, a, b)});
}

/// The sheet's cross-section in the XZ plane: the centre polyline's corners and, at each
/// corner, the length the bend's arc takes from both flanges (0 at the ends and sharp folds).
struct SheetProfile
{
    std::vector<Point2> corner;
    std::vector<double> tangentLength;

    size_t flanges() const { return corner.size() - 1; }
    /// Length of flange f's flat part, between its bends.
    double flat(size_t f) const
    {
        return norm(corner[f + 1] - corner[f]) - tangentLength[f] - tangentLength[f + 1];
    }
};

/// Flanges of the drawn lengths; each bend turns by 180 - its dihedral, left or right; a turn
/// that would bring the sheet within 4 spacings of itself turns the other way, then square.
/// A bend's radius fits where its arc takes at most 0.4 of the shorter flange, else the fold
/// is sharp (so is a fifth of them).
SheetProfile drawSheetProfile(PartBuild& b, const std::vector<double>& lengths)
{
    Draws& d = b.draws;
    SheetProfile profile;
    profile.corner.push_back({0.0, 0.0});
    std::vector<double> turn{0.0};
    double heading = 0.0;
    for (size_t i = 0; i < lengths.size(); ++i) {
        const double len = lengths[i];
        const std::vector<Point2>& corner = profile.corner;
        if (i > 0) {
            const double dihedral = b.dihedral("bend_dihedral", 10.0, 170.0);
            double signedTurn = (d.chance(0.5) ? 1.0 : -1.0) * (180.0 - dihedral);
            const auto clear = [&](double trial) {
                const double h = heading + radians(trial);
                const Point2 end = corner.back() + len * Point2{std::cos(h), std::sin(h)};
                for (size_t k = 0; k + 2 < corner.size(); ++k) {
                    if (segmentDistance(corner[k], corner[k + 1], corner.back(), end) < 4.0) {
                        return false;
                    }
                }
                return true;
            };
            if (!clear(signedTurn)) {
                signedTurn = -signedTurn;
                if (!clear(signedTurn)) {
                    signedTurn = signedTurn > 0 ? 90.0 : -90.0;
                    d.note("bend_squared", 1.0);
                }
            }
            turn.push_back(signedTurn);
            heading += radians(signedTurn);
        }
        profile.corner.push_back(corner.back() +
                                 len * Point2{std::cos(heading), std::sin(heading)});
    }
    turn.push_back(0.0);
    profile.tangentLength.assign(profile.corner.size(), 0.0);
    for (size_t i = 1; i + 1 < profile.corner.size(); ++i) {
        const double halfTurn = 0.5 * radians(std::abs(turn[i]));
        const double fit = 0.4 * std::min(lengths[i - 1], lengths[i]) / std::tan(halfTurn);
        if (fit >= b.options.minRadius && !d.chance(0.2)) {
            const double r = b.radius("bend_radius", fit);
            b.noteRadius(r);
            profile.tangentLength[i] = r * std::tan(halfTurn);
        }
    }
    return profile;
}

/// The profile as a wire of lines and tangent arcs in the XZ plane.
TopoDS_Wire sheetWire(const SheetProfile& profile)
{
    BRepBuilderAPI_MakeWire wire;
    const auto at = [](Point2 p) { return gp_Pnt(p.x, 0.0, p.y); };
    const std::vector<Point2>& corner = profile.corner;
    Point2 from = corner[0];
    for (size_t i = 0; i < profile.flanges(); ++i) {
        const Point2 dir = unitOf(corner[i + 1] - corner[i]);
        const double trim = profile.tangentLength[i + 1];
        const Point2 to = corner[i + 1] - trim * dir;
        wire.Add(BRepBuilderAPI_MakeEdge(at(from), at(to)).Edge());
        from = to;
        if (trim > 0.0) {
            const Point2 after = corner[i + 1] + trim * unitOf(corner[i + 2] - corner[i + 1]);
            GC_MakeArcOfCircle arc(at(to), gp_Vec(dir.x, 0.0, dir.y), at(after));
            require(arc.IsDone(), "bend arc");
            wire.Add(BRepBuilderAPI_MakeEdge(arc.Value()).Edge());
            from = after;
        }
    }
    require(wire.IsDone(), "sheet profile");
    return wire.Wire();
}

/// Round holes through the flat parts of random flanges of a sheet `width` wide.
void punchHoles(PartBuild& b, TopoDS_Shape& sheet, const SheetProfile& profile, double width)
{
    Draws& d = b.draws;
    for (int i = d.integer("holes", 0, 3); i > 0; --i) {
        const size_t f = static_cast<size_t>(
            d.integer("hole_flange", 0, static_cast<int>(profile.flanges()) - 1));
        const double flat = profile.flat(f);
        const double r = d.uniform("hole_radius", 2.0, std::max(2.0, 0.15 * std::min(flat, width)));
        const double along = d.uniform("hole_along", 0.3, 0.7);
        const double y = d.uniform("hole_y", 0.25 * width, 0.75 * width);
        const Point2 dir = unitOf(profile.corner[f + 1] - profile.corner[f]);
        const Point2 centre = profile.corner[f] + (profile.tangentLength[f] + along * flat) * dir;
        const Point2 n = leftNormal(dir);
        tryStep(b, sheet, "hole", [&](const TopoDS_Shape& p) {
            const gp_Pnt base(centre.x - n.x, y, centre.y - n.y);
            return cut(p, cylinder(base, gp_Dir(n.x, 0.0, n.y), r, 2.0));
        });
    }
}

/// The free ends' four corners: rounded or chamfered in the sheet's plane, or left square.
void finishFreeCorners(PartBuild& b, TopoDS_Shape& sheet, const SheetProfile& profile, double width)
{
    const RandomPartOptions& o = b.options;
    for (const bool last : {false, true}) {
        const size_t f = last ? profile.flanges() - 1 : 0;
        const Point2 end = last ? profile.corner.back() : profile.corner.front();
        const Point2 dir = unitOf(profile.corner[last ? f : 1] - end); // into the flange
        const double cap = std::min({o.maxRadius, 0.4 * profile.flat(f), 0.4 * width});
        for (const bool far : {false, true}) {
            const int kind = b.draws.integer("end_corner_kind", 0, 2); // square, round, chamfer
            if (kind == 0 || cap < o.minRadius) {
                continue;
            }
            const double size = b.radius(kind == 1 ? "corner_radius" : "chamfer_distance", cap);
            // (s, v): s along the flange from its end, v across from the corner's side; the
            // tool reaches one spacing to either side of the sheet.
            const Point2 n = leftNormal(dir);
            const gp_Vec across(2.0 * n.x, 0.0, 2.0 * n.y);
            const auto at = [&](double s, double v) {
                const Point2 p = end + s * dir - n;
                return gp_Pnt(p.x, far ? width - v : v, p.y);
            };
            const bool made = tryStep(b, sheet, "end corner", [&](const TopoDS_Shape& p) {
                if (kind == 2) {
                    // The triangle beyond the line from (size, 0) to (0, size).
                    return cut(p, prism(polygonFace({at(-1.0, -1.0), at(size + 1.0, -1.0),
                                                     at(-1.0, size + 1.0)}),
                                        across));
                }
                // The square beyond the quarter circle of radius `size` at the corner.
                const TopoDS_Shape square = prism(
                    polygonFace({at(-1.0, -1.0), at(size, -1.0), at(size, size), at(-1.0, size)}),
                    across);
                return cut(p, cut(square, cylinder(at(size, size), gp_Dir(across), size,
                                                   across.Magnitude())));
            });
            if (made && kind == 1) {
                b.noteRadius(size);
            }
        }
    }
}

// An open shell: flat flanges joined by bends of drawn angle and radius (a zero radius is a
// sharp fold), holes punched through the flanges, the free ends' corners finished.
TopoDS_Shape sheetMetal(PartBuild& b, double area)
{
    Draws& d = b.draws;
    b.closed = false;
    const int flanges = d.integer("flanges", 2, 5);
    const double widthRatio = d.uniform("width_ratio", 0.3, 1.0);
    std::vector<double> lengths;
    double sum = 0.0;
    for (int i = 0; i < flanges; ++i) {
        lengths.push_back(d.uniform("flange_ratio", 0.3, 1.0));
        sum += lengths.back();
    }
    const double L = d.note("scale", sideForArea(area, widthRatio * sum));
    const double D = d.note("width", widthRatio * L);
    for (double& l : lengths) {
        l *= L;
    }
    const SheetProfile profile = drawSheetProfile(b, lengths);
    TopoDS_Shape s = prism(sheetWire(profile), gp_Vec(0, D, 0));
    require(isValidPart(s, false), "sheet");
    punchHoles(b, s, profile, D);
    finishFreeCorners(b, s, profile, D);
    return s;
}

// ---- Freeform ------------------------------------------------------------------------------

/// A closed wire of `pieces` B-spline arcs through `through` (per piece: its join point, then
/// its inner points), each join with one tangent for both arcs.
TopoDS_Wire tangentSplineLoop(const std::vector<std::vector<gp_Pnt>>& through)
{
    const size_t pieces = through.size();
    std::vector<gp_Vec> tangent;
    for (size_t i = 0; i < pieces; ++i) {
        tangent.emplace_back(through[(i + pieces - 1) % pieces].back(), through[i][1]);
    }
    BRepBuilderAPI_MakeWire wire;
    for (size_t i = 0; i < pieces; ++i) {
        const auto& mine = through[i];
        const size_t next = (i + 1) % pieces;
        Handle(TColgp_HArray1OfPnt) pts =
            new TColgp_HArray1OfPnt(1, static_cast<int>(mine.size()) + 1);
        for (size_t k = 0; k < mine.size(); ++k) {
            pts->SetValue(static_cast<int>(k) + 1, mine[k]);
        }
        pts->SetValue(static_cast<int>(mine.size()) + 1, through[next][0]);
        GeomAPI_Interpolate interpolate(pts, false, 1e-7);
        interpolate.Load(tangent[i], tangent[next]);
        interpolate.Perform();
        require(interpolate.IsDone(), "B-spline profile");
        wire.Add(BRepBuilderAPI_MakeEdge(interpolate.Curve()).Edge());
    }
    require(wire.IsDone(), "freeform profile");
    return wire.Wire();
}

struct FreeformDraws
{
    double height = 0.0;
    /// Per piece, the polar angles and radii of its join point and inner points.
    std::vector<std::vector<double>> angles;
    std::vector<std::vector<double>> radii;
    bool lofted = false;
    double topScale = 1.0;
    gp_Vec topShift;
};

/// The body of the freeform part, its radii pulled towards their mean by `flatten` (0: as
/// drawn, 1: all equal) and lofted or not.
TopoDS_Shape freeformBody(const FreeformDraws& f, double flatten, bool lofted)
{
    double mean = 0.0;
    int count = 0;
    for (const auto& piece : f.radii) {
        for (double r : piece) {
            mean += r;
            ++count;
        }
    }
    mean /= count;
    std::vector<std::vector<gp_Pnt>> through(f.radii.size());
    for (size_t i = 0; i < f.radii.size(); ++i) {
        for (size_t k = 0; k < f.radii[i].size(); ++k) {
            const double r = mean + (1.0 - flatten) * (f.radii[i][k] - mean);
            const double a = f.angles[i][k];
            through[i].emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
        }
    }
    const TopoDS_Wire bottom = tangentSplineLoop(through);
    // A straight extrusion is the ruled loft to a shifted copy as well: OpenCASCADE's fillets
    // fail on the edges of its surfaces of linear extrusion, not on the loft's B-splines.
    gp_Trsf scaling;
    scaling.SetScale(gp::Origin(), lofted ? f.topScale : 1.0);
    gp_Trsf shift;
    shift.SetTranslation(lofted ? f.topShift : gp_Vec(0.0, 0.0, f.height));
    const TopoDS_Wire top =
        TopoDS::Wire(BRepBuilderAPI_Transform(bottom, shift * scaling, true).Shape());
    // Ruled between homothetic sections: the joins stay tangent along their whole height.
    BRepOffsetAPI_ThruSections loft(true, true);
    loft.AddWire(bottom);
    loft.AddWire(top);
    loft.CheckCompatibility(false);
    loft.Build();
    require(loft.IsDone(), "loft");
    const TopoDS_Shape s = singleSolid(loft.Shape());
    require(isValidPart(s, true), "freeform body");
    return s;
}

// A closed profile of B-spline arcs joined with equal tangents (curvature jumps at the joins)
// on a star-shaped loop, extruded straight or lofted (ruled) to a scaled, shifted copy; an
// optional hole down its axis. A profile OpenCASCADE cannot make a valid body of is tried
// again extruded, then with its radii pulled halfway and fully to their mean.
TopoDS_Shape freeform(PartBuild& b, double area)
{
    Draws& d = b.draws;
    FreeformDraws f;
    const double heightRatio = d.uniform("height_ratio", 0.15, 0.6);
    const double L = d.note("size", sideForArea(area, 2.5 * heightRatio + 1.0));
    f.height = d.note("height", heightRatio * L);
    const int pieces = d.integer("pieces", 2, 5);
    for (int i = 0; i < pieces; ++i) {
        const int extra = d.integer("piece_points", 1, 3);
        f.angles.emplace_back();
        f.radii.emplace_back();
        for (int k = 0; k <= extra; ++k) {
            f.angles.back().push_back(2.0 * pi * (i + static_cast<double>(k) / (extra + 1)) /
                                      pieces);
            f.radii.back().push_back(0.5 * L * d.uniform("radius_ratio", 0.6, 1.0));
        }
    }
    f.lofted = d.chance(0.5);
    if (f.lofted) {
        d.note("lofted", 1.0);
        f.topScale = d.uniform("top_scale", 0.5, 1.3);
        // One draw per statement: the order of a call's arguments is unspecified.
        const double shiftX = d.uniform("top_shift_x", -0.05 * L, 0.05 * L);
        const double shiftY = d.uniform("top_shift_y", -0.05 * L, 0.05 * L);
        f.topShift = gp_Vec(shiftX, shiftY, f.height);
    }
    TopoDS_Shape s;
    const struct
    {
        double flatten;
        bool lofted;
    } tries[] = {{0.0, f.lofted}, {0.0, false}, {0.5, false}, {1.0, false}};
    for (const auto& attempt : tries) {
        if (&attempt == &tries[1] && !f.lofted) {
            continue; // the drawn extrusion was the first try
        }
        try {
            s = freeformBody(f, attempt.flatten, attempt.lofted);
            break;
        } catch (const Standard_Failure&) {
        } catch (const std::runtime_error&) {
        }
        b.failed(std::string(attempt.lofted ? "loft" : "extrusion") + " of the profile" +
                 (attempt.flatten == 0.0   ? ""
                  : attempt.flatten == 1.0 ? " with equal radii"
                                           : " with radii halfway to equal") +
                 " failed");
    }
    require(!s.IsNull(), "freeform body");
    if (d.chance(0.5)) {
        const double r = d.uniform("hole_radius", 2.0, std::max(2.0, 0.05 * L));
        tryStep(b, s, "hole", [&](const TopoDS_Shape& p) {
            return cut(p, cylinder(gp_Pnt(0, 0, -1.0), gp::DZ(), r, f.height + 2.0));
        });
    }
    return roundRandomEdges(b, s, 0.3 * f.height);
}

std::string formatParameters(const std::vector<DrawnValue>& values)
{
    std::string text;
    for (const DrawnValue& v : values) {
        char number[32];
        std::snprintf(number, sizeof number, "%.4g", v.value);
        text += (text.empty() ? "" : " ") + v.name + "=" + number;
    }
    return text;
}

void checkOptions(const RandomPartOptions& o)
{
    const auto positiveRange = [](double lo, double hi) {
        return lo > 0.0 && std::isfinite(hi) && lo <= hi;
    };
    if (!(o.points >= 0.0) || !positiveRange(o.minPoints, o.maxPoints) ||
        !(o.pointsPerSquareSpacing > 0.0) || !(o.radiusPerSpacing > 0.0) ||
        !(o.minCreaseDegrees >= 0.0) || !positiveRange(o.minRadius, o.maxRadius) ||
        o.maxRoundedEdges < 1 || o.roundingTries < 1 ||
        !positiveRange(o.minDihedralDegrees, o.maxDihedralDegrees) ||
        !(o.maxDihedralDegrees < 180.0) || !positiveRange(o.minWall, o.maxWall) ||
        !positiveRange(o.minRibGap, o.maxRibGap) || !(o.minShoulder > 0.0) ||
        !(o.chamferShare >= 0.0) || !(o.chamferShare <= 1.0) || !(o.variableFilletShare >= 0.0) ||
        !(o.variableFilletShare <= 1.0)) {
        throw std::invalid_argument("Random part options: every range needs 0 < min <= max, "
                                    "dihedral angles below 180 degrees, shares in [0, 1], at "
                                    "least one rounded edge and one try.");
    }
}

} // namespace

std::string partFamilyName(PartFamily family)
{
    switch (family) {
    case PartFamily::PrismaticBlock:
        return "prismatic_block";
    case PartFamily::Bracket:
        return "bracket";
    case PartFamily::RibbedPlate:
        return "ribbed_plate";
    case PartFamily::BossPlate:
        return "boss_plate";
    case PartFamily::Revolved:
        return "revolved";
    case PartFamily::ThinShell:
        return "thin_shell";
    case PartFamily::SheetMetal:
        return "sheet_metal";
    case PartFamily::Freeform:
        return "freeform";
    }
    throw std::invalid_argument("Unknown part family.");
}

PartFamily partFamilyOfSeed(std::uint32_t seed)
{
    return static_cast<PartFamily>(seed % partFamilyCount);
}

RandomPart makeRandomPart(std::uint32_t seed, const RandomPartOptions& options)
{
    checkOptions(options);
    PartBuild build(options, seed);
    RandomPart part;
    part.seed = seed;
    part.family = partFamilyOfSeed(seed);
    part.familyName = partFamilyName(part.family);
    part.targetPoints = options.points > 0.0 ? build.draws.note("points", options.points)
                                             : build.draws.logUniform("points", options.minPoints,
                                                                      options.maxPoints);
    const double area = part.targetPoints / options.pointsPerSquareSpacing;
    using Family = TopoDS_Shape (*)(PartBuild&, double);
    static const Family families[partFamilyCount] = {
        prismaticBlock, bracket, ribbedPlate, bossPlate, revolved, thinShell, sheetMetal, freeform};
    try {
        part.shape = families[static_cast<int>(part.family)](build, area);
    } catch (const Standard_Failure& e) {
        throw std::runtime_error(
            "Random part " + std::to_string(seed) + " (" + part.familyName +
            "): OpenCASCADE failed on the plain body: " + e.GetMessageString());
    } catch (const std::runtime_error& e) {
        throw std::runtime_error("Random part " + std::to_string(seed) + " (" + part.familyName +
                                 "): " + e.what());
    }
    if (!isValidPart(part.shape, build.closed)) {
        throw std::runtime_error("Random part " + std::to_string(seed) + " (" + part.familyName +
                                 "): the plain body is not a valid shape.");
    }
    part.samplingRadius = part.spacing * options.radiusPerSpacing;
    part.closed = build.closed;
    part.smallestRadius = build.smallestRadius;
    part.fallbacks = build.fallbacks;
    part.drawn = build.draws.values;
    part.parameters = formatParameters(part.drawn);
    return part;
}

} // namespace featurelines::bench
