// SPDX-License-Identifier: LGPL-2.1-or-later
// Patch faces: the fitted surface, the border's wires with curves on it made by ShapeFix
// (projection of the network's edges) or, for a band all round a surface of revolution, the
// surface's own circles; and the sewing of the faces (BRepBuilderAPI_Sewing).
#include "PatchSurfaces.h"

#include <BRep_Tool.hxx>
#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_ListOfStatus.hxx>
#include <BRepCheck_Result.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepFill_Filling.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomLProp_SLProps.hxx>
#include <gp_Ax3.hxx>
#include <gp_Vec.hxx>
#include <gp_Pnt2d.hxx>
#include <Precision.hxx>
#include <ShapeAnalysis_ShapeTolerance.hxx>
#include <ShapeFix_Face.hxx>
#include <ShapeFix_Solid.hxx>
#include <Standard_Failure.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_TShape.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include <Eigen/Geometry>

namespace featurelines::surfaces {

namespace {

gp_Pnt point(const Eigen::Vector3d& p)
{
    return gp_Pnt(p.x(), p.y(), p.z());
}

gp_Dir direction(const Eigen::Vector3d& d)
{
    if (!(d.norm() > 0.0) || !d.allFinite()) {
        throw std::invalid_argument("a surface with a zero or non-finite axis");
    }
    return gp_Dir(d.x(), d.y(), d.z());
}

Handle(Geom_Surface) heightField(const FittedSurface& s)
{
    if (s.uPoles < 4 || s.vPoles < 4 || s.heights.size() != s.uPoles * s.vPoles ||
        !(s.uMax > s.uMin) || !(s.vMax > s.vMin)) {
        throw std::invalid_argument("a B-spline height field without its poles");
    }
    const Eigen::Vector3d e1 = s.uDirection.normalized();
    const Eigen::Vector3d e2 = s.axis.normalized().cross(e1);
    // Clamped uniform cubic knots; the poles at the Greville abscissae, so that u and v run
    // linearly over the plane and the height is the fitted field's.
    auto knots = [](int poles, TColStd_Array1OfReal& values, TColStd_Array1OfInteger& mults,
                    std::vector<double>& greville) {
        const int spans = poles - 3;
        for (int i = 0; i <= spans; ++i) {
            values.SetValue(i + 1, static_cast<double>(i) / spans);
            mults.SetValue(i + 1, i == 0 || i == spans ? 4 : 1);
        }
        std::vector<double> full;
        for (int i = 0; i < poles + 4; ++i) {
            full.push_back(std::clamp(static_cast<double>(i - 3) / spans, 0.0, 1.0));
        }
        for (int i = 0; i < poles; ++i) {
            greville.push_back((full[i + 1] + full[i + 2] + full[i + 3]) / 3.0);
        }
    };
    TColStd_Array1OfReal uKnots(1, s.uPoles - 2);
    TColStd_Array1OfInteger uMults(1, s.uPoles - 2);
    TColStd_Array1OfReal vKnots(1, s.vPoles - 2);
    TColStd_Array1OfInteger vMults(1, s.vPoles - 2);
    std::vector<double> gu;
    std::vector<double> gv;
    knots(s.uPoles, uKnots, uMults, gu);
    knots(s.vPoles, vKnots, vMults, gv);
    TColgp_Array2OfPnt poles(1, s.uPoles, 1, s.vPoles);
    for (int i = 0; i < s.uPoles; ++i) {
        for (int j = 0; j < s.vPoles; ++j) {
            const double u = s.uMin + gu[i] * (s.uMax - s.uMin);
            const double v = s.vMin + gv[j] * (s.vMax - s.vMin);
            poles.SetValue(i + 1, j + 1,
                           point(s.origin + u * e1 + v * e2 + s.heights[i + j * s.uPoles] * s.axis));
        }
    }
    return new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, 3, 3);
}

/// `wire` turned, if need be, so that the patch's points lie on its left, seen from the
/// surface's normal: a vote over the midpoints of its edges, each against the nearest of the
/// points. The network's loops run either way round; a surface's face lies left of its wires
/// (a band of a cylinder between two circles needs them to run opposite ways).
TopoDS_Wire orientedWire(const TopoDS_Wire& wire, const Handle(Geom_Surface)& surface,
                         const PointMatrix& points)
{
    int left = 0;
    int right = 0;
    const Eigen::Index step = std::max<Eigen::Index>(1, points.rows() / 4000);
    for (BRepTools_WireExplorer e(wire); e.More(); e.Next()) {
        const TopoDS_Edge& edge = e.Current();
        BRepAdaptor_Curve curve(edge);
        const double t = 0.5 * (curve.FirstParameter() + curve.LastParameter());
        gp_Pnt x;
        gp_Vec tangent;
        curve.D1(t, x, tangent);
        if (edge.Orientation() == TopAbs_REVERSED) {
            tangent.Reverse();
        }
        GeomAPI_ProjectPointOnSurf projection(x, surface);
        if (projection.NbPoints() == 0 || tangent.Magnitude() < Precision::Confusion()) {
            continue;
        }
        double u = 0.0;
        double v = 0.0;
        projection.LowerDistanceParameters(u, v);
        GeomLProp_SLProps props(surface, u, v, 1, Precision::Confusion());
        if (!props.IsNormalDefined()) {
            continue;
        }
        const gp_Dir n = props.Normal();
        Eigen::Index nearest = -1;
        double best = std::numeric_limits<double>::max();
        for (Eigen::Index i = 0; i < points.rows(); i += step) {
            const double d = gp_Pnt(points(i, 0), points(i, 1), points(i, 2)).SquareDistance(x);
            if (d < best) {
                best = d;
                nearest = i;
            }
        }
        if (nearest < 0) {
            continue;
        }
        const gp_Vec toPoint(x, gp_Pnt(points(nearest, 0), points(nearest, 1), points(nearest, 2)));
        const double side = gp_Vec(n).Crossed(tangent).Dot(toPoint);
        left += side > 0.0 ? 1 : 0;
        right += side < 0.0 ? 1 : 0;
    }
    if (right <= left) {
        return wire;
    }
    // The same edges, each reversed, in the opposite order: a wire of its own rather than a
    // reversed wire, whose flag ShapeFix's seam does not follow.
    std::vector<TopoDS_Edge> edges;
    for (BRepTools_WireExplorer e(wire); e.More(); e.Next()) {
        edges.push_back(TopoDS::Edge(e.Current().Reversed()));
    }
    BRepBuilderAPI_MakeWire make;
    for (auto it = edges.rbegin(); it != edges.rend(); ++it) {
        make.Add(*it);
    }
    return make.IsDone() ? make.Wire() : TopoDS::Wire(wire.Reversed());
}

/// The face of `surface` bounded by `wires` (the outer first), with curves on the surface for
/// every edge (ShapeFix projects the network's edges), or null. `wires` run either way round;
/// the face is the side that holds `inside` (points of the patch): on a sphere or a cylinder
/// either side of a loop is a face.
TopoDS_Face trimmedFace(const Handle(Geom_Surface)& surface, const std::vector<TopoDS_Wire>& wires,
                        const PointMatrix& inside, double precision, double maxTolerance)
{
    auto build = [&](bool reversed) {
        // A copy of each wire: ShapeFix gives the edges curves on this face's surface and may
        // cut them at its seam, which must not change the faces that share the network's
        // edges (the sewing joins the copies again).
        auto wire = [&](size_t w) {
            const TopoDS_Wire copy = orientedWire(
                TopoDS::Wire(BRepBuilderAPI_Copy(wires[w]).Shape()), surface, inside);
            return reversed ? TopoDS::Wire(copy.Reversed()) : copy;
        };
        BRepBuilderAPI_MakeFace make(surface, wire(0), Standard_True);
        for (size_t w = 1; w < wires.size() && make.IsDone(); ++w) {
            make.Add(wire(w));
        }
        if (!make.IsDone()) {
            return TopoDS_Face();
        }
        ShapeFix_Face fix(make.Face());
        fix.SetPrecision(precision);
        fix.SetMaxTolerance(maxTolerance);
        fix.FixAddNaturalBoundMode() = 0;
        fix.FixOrientationMode() = 0;
        // OpenCASCADE 7.6's fix of degenerated edges on periodic surfaces dereferenced a null
        // handle on the border of a merged-view scan's patch (held-out seed 1025): off, as a
        // patch's border has no degenerated edge to fix.
        fix.FixPeriodicDegeneratedMode() = 0;
        fix.Perform();
        return fix.Face();
    };
    // The share of the sample of `inside` the face holds.
    auto holds = [&](const TopoDS_Face& face) {
        int in = 0;
        int tried = 0;
        const Eigen::Index step = std::max<Eigen::Index>(1, inside.rows() / 25);
        for (Eigen::Index i = 0; i < inside.rows(); i += step) {
            GeomAPI_ProjectPointOnSurf projection(gp_Pnt(inside(i, 0), inside(i, 1), inside(i, 2)),
                                                  surface);
            if (projection.NbPoints() == 0) {
                continue;
            }
            double u = 0.0;
            double v = 0.0;
            projection.LowerDistanceParameters(u, v);
            BRepClass_FaceClassifier classifier(face, gp_Pnt2d(u, v), precision);
            in += classifier.State() == TopAbs_IN ? 1 : 0;
            ++tried;
        }
        return tried > 0 ? static_cast<double>(in) / tried : 0.0;
    };
    TopoDS_Face face = build(false);
    if (face.IsNull() || holds(face) < 0.5) {
        const TopoDS_Face other = build(true);
        if (!other.IsNull() && (face.IsNull() || holds(other) > holds(face))) {
            face = other;
        }
    }
    return face;
}

/// The parametrisation of a sphere, cylinder, cone or torus placed for the patch: its seam (and
/// a sphere's poles) away from the patch's points where they leave room, else the seam through
/// a vertex of the outer border wire (a band all round the axis, a sphere beyond a hemisphere),
/// so that the border's edges need not be cut where the seam crosses them.
/// Returns whether the points wrap all round (the seam runs through the vertex).
bool placeSeam(FittedSurface& s, const PointMatrix& points, const TopoDS_Wire& outer)
{
    if (s.kind == SurfaceKind::Plane || s.kind == SurfaceKind::BSpline) {
        return false;
    }
    const BRepTools_WireExplorer first(outer);
    const gp_Pnt v = BRep_Tool::Pnt(first.CurrentVertex());
    const Eigen::Vector3d vertex = Eigen::Vector3d(v.X(), v.Y(), v.Z()) - s.origin;
    if (s.kind == SurfaceKind::Sphere) {
        // A cap within 80 degrees of its mean direction: the poles at right angles to it, the
        // seam opposite it.
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        for (Eigen::Index i = 0; i < points.rows(); ++i) {
            mean += (points.row(i).transpose() - s.origin).normalized();
        }
        if (mean.norm() > 0.0) {
            mean.normalize();
            double widest = 1.0;
            for (Eigen::Index i = 0; i < points.rows(); ++i) {
                widest = std::min(widest, (points.row(i).transpose() - s.origin).normalized().dot(mean));
            }
            if (widest > std::cos(80.0 * M_PI / 180.0)) {
                s.axis = mean.unitOrthogonal();
                s.seam = -mean;
                return false;
            }
        }
        s.seam = vertex;
        return true;
    }
    // About an axis (cylinder, cone, torus): the middle of the widest angular gap between its
    // points, when over 20 degrees.
    const Eigen::Vector3d a = s.axis.normalized();
    const Eigen::Vector3d e1 = a.unitOrthogonal();
    const Eigen::Vector3d e2 = a.cross(e1);
    std::vector<double> angles;
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        const Eigen::Vector3d d = points.row(i).transpose() - s.origin;
        angles.push_back(std::atan2(d.dot(e2), d.dot(e1)));
    }
    std::sort(angles.begin(), angles.end());
    double gap = 0.0;
    double middle = 0.0;
    for (size_t i = 0; i < angles.size(); ++i) {
        const double next = i + 1 < angles.size() ? angles[i + 1] : angles.front() + 2.0 * M_PI;
        if (next - angles[i] > gap) {
            gap = next - angles[i];
            middle = angles[i] + gap / 2.0;
        }
    }
    const bool wraps = !(gap > 20.0 * M_PI / 180.0);
    s.seam = wraps ? vertex : Eigen::Vector3d(std::cos(middle) * e1 + std::sin(middle) * e2);
    return wraps;
}

/// The surface parameter across the axis's circles of a surface of revolution at x: the
/// height (cylinder), the length along the cone's lines, the angle round the tube (torus, in
/// [0, 2 pi), 0 outermost), as OpenCASCADE parametrises them.
double acrossParameter(const FittedSurface& s, const Eigen::Vector3d& x)
{
    const Eigen::Vector3d a = s.axis.normalized();
    const Eigen::Vector3d d = x - s.origin;
    const double h = d.dot(a);
    switch (s.kind) {
    case SurfaceKind::Cone:
        return h / std::cos(s.halfAngle);
    case SurfaceKind::Torus: {
        const double v = std::atan2(h, (d - h * a).norm() - s.radius);
        return v < 0.0 ? v + 2.0 * M_PI : v;
    }
    default:
        return h;
    }
}

/// A band of a cylinder, cone or torus (its points all round the axis) between two loops that
/// each run along one of the surface's circles (the rims of a bore or a boss, a fillet round
/// it): the surface between those circles, whose own circles and seam OpenCASCADE makes
/// (ShapeFix_Face leaves such a band with its seam used once). Null when the patch is no such
/// band.
TopoDS_Face revolutionBand(const FittedSurface& s, const Handle(Geom_Surface)& surface,
                           const std::vector<TopoDS_Wire>& wires, const PointMatrix& inside,
                           double spacing, double flat)
{
    const bool revolution = s.kind == SurfaceKind::Cylinder || s.kind == SurfaceKind::Cone ||
                            s.kind == SurfaceKind::Torus;
    if (!revolution || wires.size() != 2) {
        return TopoDS_Face();
    }
    // Lengths across the circles per unit of the parameter.
    const double scale = s.kind == SurfaceKind::Torus ? s.minorRadius : 1.0;
    double at[2];
    for (int l = 0; l < 2; ++l) {
        // The loop's edges sampled about a spacing apart.
        std::vector<double> values;
        for (TopExp_Explorer e(wires[static_cast<size_t>(l)], TopAbs_EDGE); e.More(); e.Next()) {
            BRepAdaptor_Curve curve(TopoDS::Edge(e.Current()));
            const double t0 = curve.FirstParameter();
            const double t1 = curve.LastParameter();
            const double length = GCPnts_AbscissaPoint::Length(curve);
            const int n = std::max(4, static_cast<int>(length / spacing));
            for (int i = 0; i <= n; ++i) {
                const gp_Pnt p = curve.Value(t0 + (t1 - t0) * i / n);
                values.push_back(acrossParameter(s, Eigen::Vector3d(p.X(), p.Y(), p.Z())));
            }
        }
        if (values.empty()) {
            return TopoDS_Face();
        }
        // On a torus the angles may straddle 0: read them about their first.
        const double first = values.front();
        for (double& v : values) {
            if (s.kind == SurfaceKind::Torus) {
                v = first + std::remainder(v - first, 2.0 * M_PI);
            }
        }
        // The loop's 10th to 90th percentile (a line strays a spacing here and there).
        std::sort(values.begin(), values.end());
        const double low = values[values.size() / 10];
        const double high = values[values.size() - 1 - values.size() / 10];
        if (!((high - low) * scale <= flat)) {
            return TopoDS_Face();
        }
        at[l] = values[values.size() / 2];
    }
    double v0 = std::min(at[0], at[1]);
    double v1 = std::max(at[0], at[1]);
    if (s.kind == SurfaceKind::Torus) {
        // The arc of the tube between the two circles that holds the points.
        v0 = std::fmod(v0 + 2.0 * M_PI, 2.0 * M_PI);
        v1 = std::fmod(v1 + 2.0 * M_PI, 2.0 * M_PI);
        if (v1 < v0) {
            std::swap(v0, v1);
        }
        std::vector<double> middle;
        for (Eigen::Index i = 0; i < inside.rows(); i += std::max<Eigen::Index>(1, inside.rows() / 200)) {
            middle.push_back(acrossParameter(s, inside.row(i).transpose()));
        }
        std::nth_element(middle.begin(), middle.begin() + static_cast<std::ptrdiff_t>(middle.size() / 2),
                         middle.end());
        const double m = middle[middle.size() / 2];
        if (!(m >= v0 && m <= v1)) {
            const double w = v1;
            v1 = v0 + 2.0 * M_PI;
            v0 = w;
        }
    }
    BRepBuilderAPI_MakeFace make(surface, 0.0, 2.0 * M_PI, v0, v1, Precision::Confusion());
    return make.IsDone() ? make.Face() : TopoDS_Face();
}

/// What BRepCheck finds wrong with `shape` or its edges, wires and vertices: the first few
/// statuses, by name ("" when it finds nothing).
std::string checkProblems(const TopoDS_Shape& shape)
{
    BRepCheck_Analyzer analyzer(shape);
    if (analyzer.IsValid()) {
        return "";
    }
    std::ostringstream text;
    int listed = 0;
    auto list = [&](const TopoDS_Shape& sub, const char* what) {
        const Handle(BRepCheck_Result) result = analyzer.Result(sub);
        if (result.IsNull()) {
            return;
        }
        auto print = [&](const BRepCheck_ListOfStatus& statuses) {
            for (BRepCheck_ListIteratorOfListOfStatus it(statuses); it.More(); it.Next()) {
                if (it.Value() != BRepCheck_NoError && listed < 4) {
                    text << (listed++ ? ", " : "") << what << " ";
                    BRepCheck::Print(it.Value(), text);
                }
            }
        };
        // The sub-shape's own statuses, then those in the context of the shapes around it.
        print(result->Status());
        for (result->InitContextIterator(); result->MoreShapeInContext();
             result->NextShapeInContext()) {
            print(result->StatusOnShape());
        }
    };
    list(shape, "face");
    for (TopExp_Explorer e(shape, TopAbs_WIRE); e.More(); e.Next()) {
        list(e.Current(), "wire");
    }
    for (TopExp_Explorer e(shape, TopAbs_EDGE); e.More(); e.Next()) {
        list(e.Current(), "edge");
    }
    std::string out = text.str();
    out.erase(std::remove(out.begin(), out.end(), '\n'), out.end());
    return out.empty() ? "invalid" : out;
}

} // namespace

namespace {

/// The signed distances of `points` from `face`'s surface along its normal (turned with the
/// face's orientation), by projection: for a surface that is no FittedSurface (the plate).
std::vector<double> projectedDeviations(const TopoDS_Face& face, const PointMatrix& points)
{
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
    Standard_Real u0 = 0.0, u1 = 0.0, v0 = 0.0, v1 = 0.0;
    surface->Bounds(u0, u1, v0, v1);
    GeomAPI_ProjectPointOnSurf projection;
    projection.Init(surface, u0, u1, v0, v1);
    const double sign = face.Orientation() == TopAbs_REVERSED ? -1.0 : 1.0;
    std::vector<double> out(static_cast<size_t>(points.rows()),
                            std::numeric_limits<double>::quiet_NaN());
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        const gp_Pnt x(points(i, 0), points(i, 1), points(i, 2));
        projection.Perform(x);
        if (projection.NbPoints() == 0) {
            continue;
        }
        double u = 0.0;
        double v = 0.0;
        projection.LowerDistanceParameters(u, v);
        GeomLProp_SLProps props(surface, u, v, 1, 1e-9);
        const gp_Pnt foot = props.Value();
        double d = projection.LowerDistance();
        if (props.IsNormalDefined()) {
            const gp_Dir n = props.Normal();
            d = gp_Vec(foot, x).Dot(gp_Vec(n));
        }
        out[static_cast<size_t>(i)] = sign * d;
    }
    return out;
}

/// A B-spline patch's face as OpenCASCADE's plate: BRepFill_Filling through the edges of its
/// one border wire (C0: the face keeps the network's edges) and up to 300 of its points; null
/// for a border with holes or where the plate cannot be built or is not a valid face.
TopoDS_Face plateFace(const std::vector<TopoDS_Wire>& wires, const PointMatrix& points,
                      double spacing)
{
    if (wires.size() != 1) {
        return TopoDS_Face();
    }
    try {
        BRepFill_Filling filling(3, 15, 2, Standard_False, 1e-5, 0.01 * spacing);
        for (BRepTools_WireExplorer it(wires.front()); it.More(); it.Next()) {
            filling.Add(it.Current(), GeomAbs_C0, Standard_True);
        }
        const Eigen::Index step = std::max<Eigen::Index>(1, points.rows() / 300);
        for (Eigen::Index i = 0; i < points.rows(); i += step) {
            filling.Add(gp_Pnt(points(i, 0), points(i, 1), points(i, 2)));
        }
        filling.Build();
        if (!filling.IsDone()) {
            return TopoDS_Face();
        }
        const TopoDS_Face face = filling.Face();
        return !face.IsNull() && checkProblems(face).empty() ? face : TopoDS_Face();
    } catch (const Standard_Failure&) {
        return TopoDS_Face();
    }
}

/// The RMS and largest of finite `d`; infinite without any.
std::pair<double, double> rmsAndLargest(const std::vector<double>& d)
{
    double sum = 0.0;
    double largest = 0.0;
    int n = 0;
    for (double x : d) {
        if (std::isfinite(x)) {
            sum += x * x;
            largest = std::max(largest, std::abs(x));
            ++n;
        }
    }
    const double inf = std::numeric_limits<double>::infinity();
    return n > 0 ? std::pair{std::sqrt(sum / n), largest} : std::pair{inf, inf};
}

} // namespace

Handle(Geom_Surface) makeSurface(const FittedSurface& s)
{
    switch (s.kind) {
    case SurfaceKind::Plane:
        return new Geom_Plane(gp_Ax3(point(s.origin), direction(s.axis)));
    case SurfaceKind::Sphere:
    case SurfaceKind::Cylinder: {
        if (!(s.radius > 0.0) || !std::isfinite(s.radius)) {
            throw std::invalid_argument(std::string("a ") + surfaceKindName(s.kind) +
                                        " of radius " + std::to_string(s.radius));
        }
        gp_Ax3 frame(point(s.origin), direction(s.axis));
        const Eigen::Vector3d seam = s.seam - s.seam.dot(s.axis.normalized()) * s.axis.normalized();
        if (seam.norm() > 1e-9 * std::max(1.0, s.seam.norm())) {
            frame.SetXDirection(direction(seam));
        }
        if (s.kind == SurfaceKind::Sphere) {
            return new Geom_SphericalSurface(frame, s.radius);
        }
        return new Geom_CylindricalSurface(frame, s.radius);
    }
    case SurfaceKind::Cone:
    case SurfaceKind::Torus: {
        gp_Ax3 frame(point(s.origin), direction(s.axis));
        const Eigen::Vector3d seam = s.seam - s.seam.dot(s.axis.normalized()) * s.axis.normalized();
        if (seam.norm() > 1e-9 * std::max(1.0, s.seam.norm())) {
            frame.SetXDirection(direction(seam));
        }
        if (s.kind == SurfaceKind::Cone) {
            if (!(s.radius > 0.0) || !(std::abs(s.halfAngle) > 1e-9) ||
                !(std::abs(s.halfAngle) < M_PI / 2.0 - 1e-9)) {
                throw std::invalid_argument("a cone of radius " + std::to_string(s.radius) +
                                            " and half angle " + std::to_string(s.halfAngle));
            }
            return new Geom_ConicalSurface(frame, s.halfAngle, s.radius);
        }
        if (!(s.radius > 0.0) || !(s.minorRadius > 0.0)) {
            throw std::invalid_argument("a torus of radii " + std::to_string(s.radius) + " and " +
                                        std::to_string(s.minorRadius));
        }
        return new Geom_ToroidalSurface(frame, s.radius, s.minorRadius);
    }
    case SurfaceKind::BSpline:
        return heightField(s);
    }
    throw std::invalid_argument("an unknown surface kind");
}

PatchFace fitPatchFace(int patch, const PointMatrix& points, const std::vector<TopoDS_Wire>& wires,
                       double spacing, double noise, const PatchSurfaceOptions& options)
{
    PatchFace pf;
    pf.patch = patch;
    pf.points = static_cast<int>(points.rows());
    const std::string name = "patch " + std::to_string(patch);
    if (wires.empty()) {
        pf.problem = name + ": no closed border";
        return pf;
    }
    try {
        if (noise < 0.0) {
            noise = estimatePatchNoise(points, spacing);
        }
        pf.surface = fitSurface(points, spacing, noise, options.fit);
        const bool wraps = placeSeam(pf.surface, points, wires.front());
        const Handle(Geom_Surface) surface = makeSurface(pf.surface);
        if (wraps) {
            // The lines stray up to two spacings or so from the circle they follow.
            pf.face = revolutionBand(pf.surface, surface, wires, points, spacing,
                                     std::max(3.0 * spacing, 4.0 * pf.surface.tolerance));
        }
        if (pf.face.IsNull()) {
            pf.face = trimmedFace(surface, wires, points, 0.01 * spacing,
                                  options.sewingTolerance * spacing);
        }
        std::string check = pf.face.IsNull() ? "no face" : checkProblems(pf.face);
        if (pf.surface.kind == SurfaceKind::BSpline && options.bspline == BSplineFace::Plate) {
            const TopoDS_Face plate = plateFace(wires, points, spacing);
            if (!plate.IsNull()) {
                pf.deviations = projectedDeviations(plate, points);
                const auto [rms, largest] = rmsAndLargest(pf.deviations);
                pf.face = plate;
                pf.plate = true;
                pf.surface.rmsDeviation = rms;
                pf.surface.maxDeviation = largest;
                check.clear();
            } else {
                check = "no plate through the border and the points";
            }
        }
        if (!check.empty()) {
            pf.problem = name + ": OpenCASCADE made no valid face of its " +
                         surfaceKindName(pf.surface.kind) + " and border (" + check + ")";
            pf.face.Nullify();
            pf.plate = false;
            pf.deviations.clear();
        } else if (pf.surface.kind == SurfaceKind::BSpline && !pf.plate) {
            // The height field's own distance is vertical, more than the distance along the
            // normal where the surface slopes: the points' deviations and their RMS and largest
            // are measured along the normal, as for every other kind.
            pf.deviations = projectedDeviations(pf.face, points);
            const auto [rms, largest] = rmsAndLargest(pf.deviations);
            pf.surface.rmsDeviation = rms;
            pf.surface.maxDeviation = largest;
        } else if (!pf.plate) {
            const double sign = pf.face.Orientation() == TopAbs_REVERSED ? -1.0 : 1.0;
            pf.deviations.resize(static_cast<size_t>(points.rows()));
            for (Eigen::Index i = 0; i < points.rows(); ++i) {
                pf.deviations[static_cast<size_t>(i)] =
                    sign * signedSurfaceDistance(pf.surface, points.row(i).transpose());
            }
        }
    } catch (const std::invalid_argument& e) {
        pf.problem = name + ": " + e.what();
    } catch (const Standard_Failure& e) {
        pf.problem = name + ": OpenCASCADE failed: " + e.GetMessageString();
    }
    return pf;
}

namespace {

/// Each face replaced by what became of it in the sewn `shape` (as oriented there), its
/// deviations' sign turned with it where the sewing or the solid reversed it.
void adoptSewnFaces(std::vector<PatchFace>& faces, const BRepBuilderAPI_Sewing& sew,
                    const TopoDS_Shape& shape)
{
    std::unordered_map<const TopoDS_TShape*, TopoDS_Face> inShape;
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
        inShape.emplace(it.Current().TShape().get(), TopoDS::Face(it.Current()));
    }
    for (PatchFace& pf : faces) {
        if (pf.face.IsNull()) {
            continue;
        }
        const TopoDS_Shape sewn = sew.IsModified(pf.face) ? sew.Modified(pf.face) : pf.face;
        const auto found = inShape.find(sewn.TShape().get());
        if (found == inShape.end()) {
            continue;
        }
        if (found->second.Orientation() != pf.face.Orientation()) {
            for (double& d : pf.deviations) {
                d = -d;
            }
        }
        pf.face = found->second;
    }
}

} // namespace

PatchSurfaces sewPatchFaces(std::vector<PatchFace> faces, double tolerance)
{
    PatchSurfaces out;
    BRepBuilderAPI_Sewing sew(tolerance);
    int added = 0;
    for (PatchFace& pf : faces) {
        if (!pf.face.IsNull()) {
            sew.Add(pf.face);
            ++added;
        } else {
            out.problems.push_back(pf.problem);
        }
    }
    out.faces = std::move(faces);
    if (added == 0) {
        return out;
    }
    try {
        sew.Perform();
        TopoDS_Shape sewn = sew.SewedShape();
        if (sewn.ShapeType() == TopAbs_SHELL && BRep_Tool::IsClosed(sewn)) {
            BRepBuilderAPI_MakeSolid make(TopoDS::Shell(sewn));
            if (make.IsDone()) {
                ShapeFix_Solid fix(make.Solid());
                fix.Perform();
                const TopoDS_Shape solid = fix.Solid();
                if (!solid.IsNull() && solid.ShapeType() == TopAbs_SOLID) {
                    sewn = solid;
                    out.solid = true;
                }
            }
        }
        out.shape = sewn;
        out.valid = BRepCheck_Analyzer(out.shape).IsValid();
        ShapeAnalysis_ShapeTolerance tolerances;
        out.tolerance = std::max(tolerances.Tolerance(out.shape, 1, TopAbs_EDGE),
                                 tolerances.Tolerance(out.shape, 1, TopAbs_VERTEX));
        if (out.solid && !out.valid) {
            out.problems.push_back("the sewn solid is not valid (BRepCheck_Analyzer)");
        }
        adoptSewnFaces(out.faces, sew, out.shape);
    } catch (const Standard_Failure& e) {
        out.problems.push_back(std::string("sewing failed: ") + e.GetMessageString());
    }
    return out;
}

PatchSurfaces fitPatchSurfaces(const PointMatrix& P, const ExtractionResult& result,
                               const std::vector<PatchBorder>& borders,
                               const cad::NetworkShapes& shapes, double noise,
                               const PatchSurfaceOptions& options)
{
    if (static_cast<Eigen::Index>(result.patch.size()) != P.rows()) {
        throw std::invalid_argument("the extraction result has " +
                                    std::to_string(result.patch.size()) + " patch ids for " +
                                    std::to_string(P.rows()) + " points");
    }
    std::map<int, std::vector<Eigen::Index>> rows;
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        if (result.patch[static_cast<size_t>(i)] >= 0) {
            rows[result.patch[static_cast<size_t>(i)]].push_back(i);
        }
    }
    std::vector<PatchFace> faces;
    for (const PatchBorder& border : borders) {
        const auto found = rows.find(border.patch);
        const Eigen::Index n =
            found == rows.end() ? 0 : static_cast<Eigen::Index>(found->second.size());
        PointMatrix points(n, 3);
        for (Eigen::Index i = 0; i < n; ++i) {
            points.row(i) = P.row(found->second[static_cast<size_t>(i)]);
        }
        const cad::BorderWires wires = cad::makeBorderWires(border, shapes);
        if (wires.wires.empty()) {
            PatchFace pf;
            pf.patch = border.patch;
            pf.points = static_cast<int>(n);
            pf.problem = wires.problem;
            faces.push_back(std::move(pf));
            continue;
        }
        faces.push_back(fitPatchFace(border.patch, points, wires.wires, result.spacing, noise,
                                     options));
    }
    return sewPatchFaces(std::move(faces), options.sewingTolerance * result.spacing);
}

double medianNoise(const ExtractionResult& result)
{
    // The regions' estimates are in spacings, the tolerance in model units.
    return cloudNoise(result) * result.spacing;
}

PatchSurfaces surfacesOfExtraction(const PointMatrix& P, const ExtractionResult& result,
                                   const CurveFitOptions& fit, const PatchSurfaceOptions& options)
{
    const CurveNetwork network = fitCurveNetwork(result, fit);
    const cad::NetworkShapes shapes =
        cad::makeNetworkShapes(network, gp_Trsf(), 2.0 * result.spacing);
    const std::vector<PatchBorder> borders = patchBorders(network, result, P);
    return fitPatchSurfaces(P, result, borders, shapes, medianNoise(result), options);
}

} // namespace featurelines::surfaces
