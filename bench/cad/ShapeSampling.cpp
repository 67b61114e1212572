// SPDX-License-Identifier: LGPL-2.1-or-later
#include "ShapeSampling.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Curve2d.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <GProp_GProps.hxx>
#include <Poly_Triangulation.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <Eigen/Geometry>

#include "PointGrid.h"

namespace featurelines::bench {

namespace {

constexpr double pi = 3.14159265358979323846;

/// Samples per unit area of a greedy Poisson-disk set of radius 1 thinned from 10 uniform
/// candidates per sample: about 0.57 (a truly maximal set reaches about 0.7).
constexpr double poissonDensity = 0.57;

/// Parametric resolution passed to OpenCASCADE's local-property evaluators.
constexpr double propertyResolution = 1e-9;

Eigen::Vector3d toEigen(const gp_XYZ& p)
{
    return {p.X(), p.Y(), p.Z()};
}

/// Surface point and outward normal of `face` at (u, v); false where the normal is undefined
/// (a pole of a sphere, the apex of a cone).
bool evaluateFace(const BRepAdaptor_Surface& surface, bool reversed, double u, double v,
                  Eigen::Vector3d& point, Eigen::Vector3d& normal)
{
    BRepLProp_SLProps props(surface, u, v, 1, propertyResolution);
    if (!props.IsNormalDefined()) {
        return false;
    }
    point = toEigen(props.Value().XYZ());
    normal = toEigen(props.Normal().XYZ());
    if (reversed) {
        normal = -normal;
    }
    return true;
}

/// Normal and signed principal curvatures (min, max) of a face at a point of one of its
/// edges, both relative to the face's outward normal.
struct EdgeSideProperties
{
    bool valid = false;
    Eigen::Vector3d normal;
    double kMin = 0.0;
    double kMax = 0.0;
};

EdgeSideProperties edgeSide(const TopoDS_Edge& edge, const TopoDS_Face& face,
                            const BRepAdaptor_Surface& surface, double t, const gp_Pnt& p)
{
    gp_Pnt2d uv;
    bool haveUV = false;
    try {
        const BRepAdaptor_Curve2d pcurve(edge, face);
        uv = pcurve.Value(t);
        haveUV = true;
    } catch (const Standard_Failure&) {
        haveUV = false;
    }
    if (!haveUV) {
        ShapeAnalysis_Surface analysis(BRep_Tool::Surface(face));
        uv = analysis.ValueOfUV(p, 1e-7);
    }
    EdgeSideProperties side;
    BRepLProp_SLProps props(surface, uv.X(), uv.Y(), 2, propertyResolution);
    if (!props.IsNormalDefined() || !props.IsCurvatureDefined()) {
        return side;
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    side.valid = true;
    side.normal = toEigen(props.Normal().XYZ());
    side.kMin = props.MinCurvature();
    side.kMax = props.MaxCurvature();
    if (reversed) {
        // Curvatures are signed along the surface's own normal: flipping the normal negates
        // them and swaps which one is the larger.
        side.normal = -side.normal;
        const double kMin = -side.kMax;
        side.kMax = -side.kMin;
        side.kMin = kMin;
    }
    return side;
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

/// Decides the type of an edge between two faces (line.type) and its angle (sharp: inside the
/// wedge, 180 less the median turn of the outward normals) or radius (smooth: 1 over the median
/// largest principal curvature of the two sides); false when it is no feature (the same
/// surface continued across the edge).
bool classifyTwoFaceEdge(const TopoDS_Edge& edge, const TopoDS_Face& f1, const TopoDS_Face& f2,
                         const TruthOptions& options, TypedPolyline& line)
{
    const BRepAdaptor_Curve curve(edge);
    const BRepAdaptor_Surface s1(f1);
    const BRepAdaptor_Surface s2(f2);
    std::vector<double> angles;
    std::vector<double> curvatureGaps;
    std::vector<double> curvatureScales;
    const int n = std::max(1, options.classificationSamples);
    for (int i = 0; i < n; ++i) {
        // Interior samples only: at the vertices other faces meet.
        const double t = curve.FirstParameter() +
                         (curve.LastParameter() - curve.FirstParameter()) * (i + 0.5) / n;
        const gp_Pnt p = curve.Value(t);
        const EdgeSideProperties a = edgeSide(edge, f1, s1, t, p);
        const EdgeSideProperties b = edgeSide(edge, f2, s2, t, p);
        if (!a.valid || !b.valid) {
            continue;
        }
        angles.push_back(std::acos(std::clamp(a.normal.dot(b.normal), -1.0, 1.0)) * 180.0 / pi);
        curvatureGaps.push_back(std::max(std::abs(a.kMin - b.kMin), std::abs(a.kMax - b.kMax)));
        curvatureScales.push_back(
            std::max({std::abs(a.kMin), std::abs(a.kMax), std::abs(b.kMin), std::abs(b.kMax)}));
    }
    if (angles.empty()) {
        return false;
    }
    const double turn = median(angles);
    if (turn > options.sharpAngleDegrees) {
        line.type = LineType::Sharp;
        line.angle = 180.0 - turn;
        return true;
    }
    const double gap = median(curvatureGaps);
    const double scale = median(curvatureScales);
    if (scale > 0.0 && gap > options.curvatureRelativeTolerance * scale) {
        line.type = LineType::Smooth;
        line.radius = 1.0 / scale;
        return true;
    }
    return false;
}

/// The samples of `edge` about `step` apart, into `line` (its type and estimates stay).
void sampleEdge(const TopoDS_Edge& edge, double step, TypedPolyline& line)
{
    const BRepAdaptor_Curve curve(edge);
    const double length = GCPnts_AbscissaPoint::Length(curve);
    const int count = std::max(2, static_cast<int>(std::ceil(length / step)) + 1);
    GCPnts_UniformAbscissa uniform(curve, count);
    // A closed edge (a full circle) is a closed line; its last sample repeats the first.
    line.closed = BRep_Tool::IsClosed(edge);
    std::vector<Eigen::Vector3d> pts;
    if (uniform.IsDone()) {
        for (int i = 1; i <= uniform.NbPoints(); ++i) {
            pts.push_back(toEigen(curve.Value(uniform.Parameter(i)).XYZ()));
        }
    } else {
        for (int i = 0; i < count; ++i) {
            const double t = curve.FirstParameter() +
                             (curve.LastParameter() - curve.FirstParameter()) * i / (count - 1);
            pts.push_back(toEigen(curve.Value(t).XYZ()));
        }
    }
    if (line.closed && pts.size() > 2) {
        pts.pop_back();
    }
    line.points.resize(static_cast<Eigen::Index>(pts.size()), 3);
    for (size_t i = 0; i < pts.size(); ++i) {
        line.points.row(static_cast<Eigen::Index>(i)) = pts[i].transpose();
    }
}

} // namespace

SurfaceTriangulation::SurfaceTriangulation(const TopoDS_Shape& shape, double deflection)
{
    BRepMesh_IncrementalMesh mesher(shape, deflection, false, 0.2, false);
    if (!mesher.IsDone()) {
        throw std::runtime_error("OpenCASCADE could not triangulate the shape to sample it.");
    }
    double total = 0.0;
    for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
        const TopoDS_Face face = TopoDS::Face(ex.Current());
        TopLoc_Location loc;
        const Handle(Poly_Triangulation)& mesh = BRep_Tool::Triangulation(face, loc);
        if (mesh.IsNull() || !mesh->HasUVNodes()) {
            throw std::runtime_error("OpenCASCADE left a face of the shape without a usable "
                                     "triangulation.");
        }
        const int faceIndex = static_cast<int>(faces.size());
        faces.push_back(face);
        const gp_Trsf trsf = loc.Transformation();
        for (int t = 1; t <= mesh->NbTriangles(); ++t) {
            int n[3];
            mesh->Triangle(t).Get(n[0], n[1], n[2]);
            Triangle tri;
            tri.face = faceIndex;
            for (int c = 0; c < 3; ++c) {
                tri.p[c] = toEigen(mesh->Node(n[c]).Transformed(trsf).XYZ());
                const gp_Pnt2d uv = mesh->UVNode(n[c]);
                tri.uv[c] = {uv.X(), uv.Y()};
            }
            const double a = 0.5 * (tri.p[1] - tri.p[0]).cross(tri.p[2] - tri.p[0]).norm();
            if (a <= 0.0) {
                continue;
            }
            total += a;
            triangleList.push_back(tri);
            cumulativeArea.push_back(total);
        }
    }
    if (triangleList.empty()) {
        throw std::runtime_error("The triangulation of the shape to sample is empty.");
    }

    surfaces.reserve(faces.size());
    for (const TopoDS_Face& f : faces) {
        surfaces.emplace_back(f);
    }
}

std::size_t SurfaceTriangulation::triangleAtArea(double a) const
{
    const size_t k = static_cast<size_t>(
        std::lower_bound(cumulativeArea.begin(), cumulativeArea.end(), a) - cumulativeArea.begin());
    return std::min(k, triangleList.size() - 1);
}

bool SurfaceTriangulation::place(std::size_t t, double b0, double b1, double b2,
                                 Eigen::Vector3d& point, Eigen::Vector3d& normal) const
{
    const Triangle& tri = triangleList[t];
    const Eigen::Vector2d uv = b0 * tri.uv[0] + b1 * tri.uv[1] + b2 * tri.uv[2];
    const size_t f = static_cast<size_t>(tri.face);
    return evaluateFace(surfaces[f], faces[f].Orientation() == TopAbs_REVERSED, uv.x(), uv.y(),
                        point, normal);
}

double shapeArea(const TopoDS_Shape& shape)
{
    GProp_GProps props;
    BRepGProp::SurfaceProperties(shape, props);
    return props.Mass();
}

double boundingDiagonal(const TopoDS_Shape& shape)
{
    Bnd_Box box;
    BRepBndLib::Add(shape, box);
    if (box.IsVoid()) {
        return 0.0;
    }
    return std::sqrt(box.SquareExtent());
}

double radiusForPointCount(double area, double points)
{
    if (!(area > 0.0) || !(points > 0.0)) {
        throw std::invalid_argument("The sampled surface and the point count must be positive.");
    }
    return std::sqrt(poissonDensity * area / points);
}

SampledCloud sampleShape(const TopoDS_Shape& shape, const SamplingOptions& options)
{
    const double r = options.radius;
    if (!(r > 0.0) || !std::isfinite(r)) {
        throw std::invalid_argument("The sampling radius must be a positive length.");
    }
    const double area = shapeArea(shape);
    if (!(area > 0.0)) {
        throw std::invalid_argument("The shape to sample has no face.");
    }

    // A fine triangulation carries the (u, v) of its nodes: candidates are drawn by area on it.
    const SurfaceTriangulation mesh(shape, options.meshDeflectionFactor * r);
    const double total = mesh.area();

    // Greedy Poisson-disk thinning of uniform candidates in draw order (random order): a
    // candidate is kept when no kept sample lies within r.
    std::mt19937 rng(options.seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const long candidates =
        static_cast<long>(std::ceil(options.oversampling * poissonDensity * area / (r * r)));
    PointGrid grid(r);
    std::vector<Eigen::Vector3d> points;
    std::vector<Eigen::Vector3d> normals;
    for (long c = 0; c < candidates; ++c) {
        const size_t k = mesh.triangleAtArea(unit(rng) * total);
        const SurfaceTriangulation::Triangle& tri = mesh.triangles()[k];
        // Uniform barycentric coordinates (square-root warp of two uniforms).
        const double s = std::sqrt(unit(rng));
        const double w2 = unit(rng);
        const double b0 = 1.0 - s;
        const double b1 = s * (1.0 - w2);
        const double b2 = s * w2;
        const Eigen::Vector3d approx = b0 * tri.p[0] + b1 * tri.p[1] + b2 * tri.p[2];
        if (grid.anyWithin(approx, r)) {
            continue;
        }
        Eigen::Vector3d p;
        Eigen::Vector3d n;
        if (!mesh.place(k, b0, b1, b2, p, n)) {
            continue;
        }
        grid.insert(p, static_cast<int>(points.size()));
        points.push_back(p);
        normals.push_back(n);
    }

    SampledCloud cloud;
    cloud.points.resize(static_cast<Eigen::Index>(points.size()), 3);
    cloud.normals.resize(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i) {
        cloud.points.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
        cloud.normals.row(static_cast<Eigen::Index>(i)) = normals[i].transpose();
    }
    return cloud;
}

void addNormalNoise(SampledCloud& cloud, double sigma, std::uint32_t seed)
{
    if (!(sigma >= 0.0) || !std::isfinite(sigma)) {
        throw std::invalid_argument("The noise level must be zero or a positive length.");
    }
    if (sigma == 0.0) {
        return;
    }
    std::mt19937 rng(seed);
    std::normal_distribution<double> gauss(0.0, sigma);
    for (Eigen::Index i = 0; i < cloud.points.rows(); ++i) {
        cloud.points.row(i) += gauss(rng) * cloud.normals.row(i);
    }
}

double meanNearestSpacing(const PointMatrix& P)
{
    const Eigen::Index n = P.rows();
    if (n < 2) {
        throw std::invalid_argument("The spacing of a cloud needs at least two points.");
    }
    const Eigen::Vector3d extent = P.colwise().maxCoeff() - P.colwise().minCoeff();
    // A first search radius near the spacing of a surface-like cloud; points that find no
    // neighbour within it are searched again with a doubled radius.
    double radius = std::max(extent.norm() / std::sqrt(static_cast<double>(n)), 1e-300);
    std::vector<double> nearest(static_cast<size_t>(n), -1.0);
    std::vector<Eigen::Index> pending(static_cast<size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
        pending[static_cast<size_t>(i)] = i;
    }
    while (!pending.empty()) {
        PointGrid grid(radius);
        for (Eigen::Index i = 0; i < n; ++i) {
            grid.insert(P.row(i).transpose(), static_cast<int>(i));
        }
        std::vector<Eigen::Index> still;
        for (Eigen::Index i : pending) {
            double best = -1.0;
            grid.forEachWithin(P.row(i).transpose(), radius, [&](int, double d2) {
                if (d2 > 0.0 && (best < 0.0 || d2 < best)) {
                    best = d2;
                }
                return true;
            });
            if (best > 0.0) {
                nearest[static_cast<size_t>(i)] = std::sqrt(best);
            } else {
                still.push_back(i);
            }
        }
        if (still.size() == pending.size() && radius > extent.norm()) {
            throw std::invalid_argument("Every point of the cloud coincides: it has no spacing.");
        }
        pending.swap(still);
        radius *= 2.0;
    }
    double sum = 0.0;
    for (double d : nearest) {
        sum += d;
    }
    return sum / static_cast<double>(n);
}

std::vector<TypedPolyline> truthEdges(const TopoDS_Shape& shape, const TruthOptions& options)
{
    if (!(options.step > 0.0) || !std::isfinite(options.step)) {
        throw std::invalid_argument("The sampling step along the edges must be a positive length.");
    }
    TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
    TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
    std::vector<TypedPolyline> lines;
    for (int i = 1; i <= edgeFaces.Extent(); ++i) {
        const TopoDS_Edge& edge = TopoDS::Edge(edgeFaces.FindKey(i));
        if (BRep_Tool::Degenerated(edge)) {
            continue;
        }
        // The distinct faces around the edge (a seam lists its face twice).
        std::vector<TopoDS_Face> faces;
        bool seam = false;
        for (TopTools_ListIteratorOfListOfShape it(edgeFaces.FindFromIndex(i)); it.More();
             it.Next()) {
            const TopoDS_Face& f = TopoDS::Face(it.Value());
            seam = seam || BRep_Tool::IsClosed(edge, f);
            const bool known = std::any_of(faces.begin(), faces.end(),
                                           [&f](const TopoDS_Face& g) { return g.IsSame(f); });
            if (!known) {
                faces.push_back(f);
            }
        }
        if (seam || faces.empty()) {
            continue;
        }
        TypedPolyline line;
        line.type = LineType::Sharp;
        if (faces.size() == 1) {
            line.type = LineType::Boundary;
        } else if (faces.size() == 2) {
            if (!classifyTwoFaceEdge(edge, faces[0], faces[1], options, line)) {
                continue;
            }
        }
        sampleEdge(edge, options.step, line);
        lines.push_back(std::move(line));
    }
    return lines;
}

} // namespace featurelines::bench
