// SPDX-License-Identifier: LGPL-2.1-or-later
// From lines to surfaces with known answers: sampled planes, spheres, cylinders, cones and tori
// are recognised with their radii and axes; a saddle is a B-spline within a fraction of a
// spacing; a sampled box goes from its cloud to 6 planes sewn into a valid solid of the box's
// volume, clean and noisy; a cylinder with flat ends to 1 cylinder of its radius and 2 planes;
// the shipped demo cloud to the demo part's 7 planes, 6 cylinders and 1 torus, a valid solid
// of the B-rep's volume.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <GeomAPI_PointsToBSpline.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_Surface.hxx>

#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include "CadShapes.h"
#include "PartFamilies.h"
#include "ScanSampling.h"
#include "FeatureLines/Extraction.h"
#include "FeatureLines/curves/CurveNetwork.h"
#include "FeatureLines/io/CloudIO.h"
#include "PatchSurfaces.h"
#include "SampledShapes.h"
#include "SurfaceFit.h"

using namespace featurelines;
using namespace featurelines::surfaces;

namespace {

TEST(SurfaceFit, ASampledPlaneIsAPlane)
{
    const shapes::Sample s = shapes::plane(20.0, 1.0, 1);
    const FittedSurface f = fitSurface(s.points, 1.0);
    EXPECT_EQ(f.kind, SurfaceKind::Plane);
    EXPECT_NEAR(std::abs(f.axis.z()), 1.0, 1e-9);
    EXPECT_LT(f.maxDeviation, 1e-9);
}

TEST(SurfaceFit, ASampledSphereIsASphereOfItsRadius)
{
    shapes::Sample s = shapes::sphere(10.0, 1.0, 2);
    FittedSurface f = fitSurface(s.points, 1.0);
    EXPECT_EQ(f.kind, SurfaceKind::Sphere);
    EXPECT_NEAR(f.radius, 10.0, 0.01);
    EXPECT_LT(f.origin.norm(), 0.01);
    // With noise of 0.2 spacing the radius stays within 1 %.
    shapes::addNormalNoise(s, 0.2, 3);
    f = fitSurface(s.points, 1.0, 0.2);
    EXPECT_EQ(f.kind, SurfaceKind::Sphere);
    EXPECT_NEAR(f.radius, 10.0, 0.1);
}

TEST(SurfaceFit, ASampledCylinderIsACylinderOfItsRadiusAndAxis)
{
    shapes::Sample s = shapes::cylinder(8.0, 30.0, 1.0, 4);
    // Tilted and moved: the axis is found, not assumed.
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(0.4, Eigen::Vector3d(1.0, 2.0, 0.5).normalized()).toRotationMatrix();
    const Eigen::Vector3d shift(3.0, -2.0, 7.0);
    for (Eigen::Index i = 0; i < s.points.rows(); ++i) {
        s.points.row(i) = (R * s.points.row(i).transpose() + shift).transpose();
    }
    const FittedSurface f = fitSurface(s.points, 1.0);
    EXPECT_EQ(f.kind, SurfaceKind::Cylinder);
    EXPECT_NEAR(f.radius, 8.0, 0.01);
    EXPECT_NEAR(std::abs(f.axis.dot(R * Eigen::Vector3d::UnitZ())), 1.0, 1e-6);
    const Eigen::Vector3d d = f.origin - shift;
    EXPECT_LT((d - d.dot(f.axis) * f.axis).norm(), 0.01);
}

/// Points on the surface of revolution of the profile (rho(t), h(t)), t in [t0, t1], about the
/// axis through `centre` along `axis`, about one spacing apart.
PointMatrix revolved(const std::function<Eigen::Vector2d(double)>& profile, double t0, double t1,
                     const Eigen::Vector3d& centre, const Eigen::Vector3d& axis, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Eigen::Vector3d e1 = axis.unitOrthogonal();
    Eigen::Vector3d e2 = axis.cross(e1);
    std::vector<Eigen::Vector3d> points;
    const int steps = 400;
    for (int k = 0; k < steps; ++k) {
        const double t = t0 + (t1 - t0) * (k + unit(rng)) / steps;
        const double dt = (profile(std::min(t1, t + 1e-4)) - profile(std::max(t0, t - 1e-4))).norm() /
                          (std::min(t1, t + 1e-4) - std::max(t0, t - 1e-4));
        const Eigen::Vector2d rh = profile(t);
        // As many points round the circle of radius rho as one per spacing of the strip.
        const double around = 2.0 * M_PI * rh.x() * dt * (t1 - t0) / steps;
        for (int j = 0; j < static_cast<int>(around + unit(rng)); ++j) {
            const double u = 2.0 * M_PI * unit(rng);
            points.push_back(centre + rh.y() * axis +
                             rh.x() * (std::cos(u) * e1 + std::sin(u) * e2));
        }
    }
    PointMatrix P(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i) {
        P.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
    }
    return P;
}

TEST(SurfaceFit, ASampledConeIsAConeOfItsAngle)
{
    // Radius 12 at h = 0 narrowing by tan(20 degrees) per unit up to h = 15.
    const double angle = 20.0 * M_PI / 180.0;
    const Eigen::Vector3d axis = Eigen::Vector3d(0.2, -0.3, 1.0).normalized();
    const Eigen::Vector3d centre(4.0, 5.0, -6.0);
    const PointMatrix P = revolved(
        [&](double t) { return Eigen::Vector2d(12.0 - t * std::tan(angle), t); }, 0.0, 15.0,
        centre, axis, 12);
    const FittedSurface f = fitSurface(P, 1.0);
    ASSERT_EQ(f.kind, SurfaceKind::Cone);
    EXPECT_NEAR(std::abs(f.axis.dot(axis)), 1.0, 1e-6);
    // The half angle signed along the fitted axis: narrowing along +axis is negative.
    EXPECT_NEAR(std::abs(f.halfAngle), angle, 1e-3);
    EXPECT_LT(f.rmsDeviation, 1e-3);
    // The radius at the point level with h = 7.5 is 12 - 7.5 tan(20).
    EXPECT_NEAR(surfaceDistance(f, centre + 7.5 * axis + (12.0 - 7.5 * std::tan(angle)) *
                                                         axis.unitOrthogonal()),
                0.0, 1e-3);
}

TEST(SurfaceFit, AFilletRingIsATorusOfItsRadii)
{
    // The foot of a boss of radius 10 on a plate, rounded with radius 4: a quarter of the tube
    // of a torus of major radius 14 about the boss's axis, the tube centre 4 above the plate.
    const Eigen::Vector3d axis = Eigen::Vector3d(-0.1, 0.4, 1.0).normalized();
    const Eigen::Vector3d centre(1.0, 2.0, 3.0);
    const PointMatrix P = revolved(
        [](double v) { return Eigen::Vector2d(14.0 + 4.0 * std::cos(v), 4.0 + 4.0 * std::sin(v)); },
        M_PI, 1.5 * M_PI, centre, axis, 13);
    const FittedSurface f = fitSurface(P, 1.0);
    ASSERT_EQ(f.kind, SurfaceKind::Torus);
    EXPECT_NEAR(f.radius, 14.0, 0.01);
    EXPECT_NEAR(f.minorRadius, 4.0, 0.01);
    EXPECT_NEAR(std::abs(f.axis.dot(axis)), 1.0, 1e-6);
    EXPECT_LT((f.origin - (centre + 4.0 * axis)).norm(), 0.01);
}

TEST(SurfaceFit, ASaddleIsABSplineCloseToItsPoints)
{
    // z = (x^2 - y^2) / 40 over [-10, 10]^2: no plane, sphere or cylinder.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    PointMatrix P(600, 3);
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        const double x = u(rng);
        const double y = u(rng);
        P.row(i) << x, y, (x * x - y * y) / 40.0;
    }
    const FittedSurface f = fitSurface(P, 1.0);
    EXPECT_EQ(f.kind, SurfaceKind::BSpline);
    EXPECT_LT(f.rmsDeviation, 0.05);
    EXPECT_LT(surfaceDistance(f, Eigen::Vector3d(5.0, 5.0, 0.0)), 0.05);
    EXPECT_NEAR(surfaceDistance(f, Eigen::Vector3d(5.0, 0.0, 0.0)), 25.0 / 40.0, 0.05);
}

TEST(SurfaceFit, TheSignedDistanceIsPositiveWhereTheSurfacesNormalPoints)
{
    // For each kind, points moved off makeSurface()'s surface along its own unit normal by t
    // are at signed distance t (the height field's vertical distance: t over the cosine of the
    // slope, so the same sign and within 10 % on this gentle saddle).
    std::vector<FittedSurface> surfaces(5);
    surfaces[0].kind = SurfaceKind::Plane;
    surfaces[0].origin = Eigen::Vector3d(1.0, 2.0, 3.0);
    surfaces[0].axis = Eigen::Vector3d(0.2, -0.3, 1.0).normalized();
    surfaces[1].kind = SurfaceKind::Sphere;
    surfaces[1].radius = 7.0;
    surfaces[2].kind = SurfaceKind::Cylinder;
    surfaces[2].axis = Eigen::Vector3d(1.0, 1.0, 0.0).normalized();
    surfaces[2].radius = 5.0;
    surfaces[3].kind = SurfaceKind::Cone;
    surfaces[3].radius = 6.0;
    surfaces[3].halfAngle = -0.4;
    surfaces[4].kind = SurfaceKind::Torus;
    surfaces[4].radius = 12.0;
    surfaces[4].minorRadius = 3.0;
    {
        std::mt19937 rng(21);
        std::uniform_real_distribution<double> u(-10.0, 10.0);
        PointMatrix P(600, 3);
        for (Eigen::Index i = 0; i < P.rows(); ++i) {
            const double x = u(rng);
            const double y = u(rng);
            P.row(i) << x, y, (x * x - y * y) / 80.0;
        }
        surfaces.push_back(fitSurface(P, 1.0));
        ASSERT_EQ(surfaces.back().kind, SurfaceKind::BSpline);
    }
    for (const FittedSurface& f : surfaces) {
        SCOPED_TRACE(surfaceKindName(f.kind));
        const Handle(Geom_Surface) surface = makeSurface(f);
        Standard_Real u0 = 0.0, u1 = 0.0, v0 = 0.0, v1 = 0.0;
        surface->Bounds(u0, u1, v0, v1);
        // Planes, cylinders and cones are unbounded in v: a window about the origin.
        v0 = std::max(v0, -5.0);
        v1 = std::min(v1, 5.0);
        u0 = std::max(u0, -5.0);
        u1 = std::min(u1, 5.0);
        for (int i = 1; i < 5; ++i) {
            for (int j = 1; j < 5; ++j) {
                const double u = u0 + (u1 - u0) * i / 5.0;
                const double v = v0 + (v1 - v0) * j / 5.0;
                GeomLProp_SLProps props(surface, u, v, 1, 1e-9);
                ASSERT_TRUE(props.IsNormalDefined());
                const gp_Pnt p = props.Value();
                const gp_Dir n = props.Normal();
                for (double t : {-0.3, 0.2}) {
                    const Eigen::Vector3d x(p.X() + t * n.X(), p.Y() + t * n.Y(),
                                            p.Z() + t * n.Z());
                    const double d = signedSurfaceDistance(f, x);
                    if (f.kind == SurfaceKind::BSpline) {
                        EXPECT_GT(d * t, 0.0);
                        EXPECT_NEAR(d, t, 0.1 * std::abs(t));
                    } else {
                        EXPECT_NEAR(d, t, 1e-6);
                    }
                    EXPECT_NEAR(surfaceDistance(f, x), std::abs(d), 1e-12);
                }
            }
        }
    }
}

TEST(SurfaceFit, ANoisyFilletWithAStripOfItsFaceIsNoCylinder)
{
    // A quarter cylinder of radius 5 along x and, tangent to it, a 6-spacing strip of the face
    // it blends into; noise of 0.3 spacing along the normal. Within the noise the points fit one
    // cylinder (its RMS under 1.5 times the noise), but they leave it by a like amount all along
    // the strip: the systematic test refuses it, and the patch gets the B-spline. A whole noisy
    // cylinder stays a cylinder.
    std::mt19937 rng(37);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> noise(0.0, 0.3);
    const double r = 5.0;
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < 1500; ++i) {
        const double x = 30.0 * unit(rng);
        const double t = unit(rng) * (0.5 * M_PI * r + 6.0);
        Eigen::Vector3d p;
        Eigen::Vector3d n;
        if (t < 0.5 * M_PI * r) {
            const double a = t / r;
            n = Eigen::Vector3d(0.0, std::cos(a), std::sin(a));
            p = Eigen::Vector3d(x, 0.0, 0.0) + r * n;
        } else {
            // The face z = r beyond the fillet's end at y = 0, running to negative y.
            n = Eigen::Vector3d(0.0, 0.0, 1.0);
            p = Eigen::Vector3d(x, -(t - 0.5 * M_PI * r), r);
        }
        points.push_back(p + noise(rng) * n);
    }
    PointMatrix P(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i) {
        P.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
    }
    SurfaceFitOptions without;
    without.systematicTolerance = 0.0;
    const FittedSurface loose = fitSurface(P, 1.0, 0.3, without);
    EXPECT_NE(loose.kind, SurfaceKind::BSpline) << "the test's patch no longer fits one surface "
                                                  "within the noise";
    EXPECT_EQ(fitSurface(P, 1.0, 0.3).kind, SurfaceKind::BSpline);
    shapes::Sample cylinder = shapes::cylinder(r, 30.0, 1.0, 38);
    shapes::addNormalNoise(cylinder, 0.3, 39);
    EXPECT_EQ(fitSurface(cylinder.points, 1.0, 0.3).kind, SurfaceKind::Cylinder);
}

TEST(SurfaceFit, BadPatchesAreNamed)
{
    PointMatrix few(5, 3);
    few.setRandom();
    EXPECT_THROW(fitSurface(few, 1.0), std::invalid_argument);
    PointMatrix line(10, 3);
    for (int i = 0; i < 10; ++i) {
        line.row(i) << i, 2.0 * i, 0.0;
    }
    EXPECT_THROW(fitSurface(line, 1.0), std::invalid_argument);
    PointMatrix bad = shapes::plane(10.0, 1.0, 1).points;
    bad(3, 1) = std::nan("");
    EXPECT_THROW(fitSurface(bad, 1.0), std::invalid_argument);
    EXPECT_THROW(fitSurface(shapes::plane(10.0, 1.0, 1).points, 0.0), std::invalid_argument);
}

/// The cloud's lines, network, borders and patch surfaces.
PatchSurfaces surfacesOf(const PointMatrix& P)
{
    return surfacesOfExtraction(P, extractFeatureLines(P));
}

double volumeOf(const TopoDS_Shape& shape)
{
    GProp_GProps props;
    BRepGProp::VolumeProperties(shape, props);
    return std::abs(props.Mass());
}

int countKind(const PatchSurfaces& s, SurfaceKind kind)
{
    int n = 0;
    for (const PatchFace& f : s.faces) {
        n += !f.face.IsNull() && f.surface.kind == kind ? 1 : 0;
    }
    return n;
}

TEST(PatchSurfaces, ASampledBoxIsSixPlanesSewnIntoASolidOfItsVolume)
{
    const double edge = 30.0;
    const shapes::Sample s = shapes::cube(edge, 1.0, 7);
    const PatchSurfaces out = surfacesOf(s.points);
    for (const std::string& p : out.problems) {
        ADD_FAILURE() << p;
    }
    EXPECT_EQ(countKind(out, SurfaceKind::Plane), 6);
    EXPECT_EQ(out.faces.size(), 6u);
    ASSERT_TRUE(out.solid);
    EXPECT_TRUE(out.valid);
    EXPECT_NEAR(volumeOf(out.shape), edge * edge * edge, 0.01 * edge * edge * edge);
}

TEST(PatchSurfaces, ANoisyBoxStillGivesAValidSolid)
{
    const double edge = 30.0;
    shapes::Sample s = shapes::cube(edge, 1.0, 8);
    shapes::addNormalNoise(s, 0.3, 9);
    const PatchSurfaces out = surfacesOf(s.points);
    EXPECT_EQ(countKind(out, SurfaceKind::Plane), 6);
    ASSERT_TRUE(out.solid);
    EXPECT_TRUE(out.valid);
    EXPECT_NEAR(volumeOf(out.shape), edge * edge * edge, 0.02 * edge * edge * edge);
}

TEST(PatchSurfaces, APointsDeviationIsItsNoiseAlongTheOutwardNormal)
{
    // The noisy box of the test above: a point moved by t along its face's outward normal lies
    // t from the fitted plane on the outer side of the solid's face (the plane passes through
    // the face's points on average, a few hundredths of a spacing from the true face).
    const double edge = 30.0;
    const shapes::Sample clean = shapes::cube(edge, 1.0, 8);
    shapes::Sample s = clean;
    shapes::addNormalNoise(s, 0.3, 9);
    const ExtractionResult result = extractFeatureLines(s.points);
    const PatchSurfaces out = surfacesOfExtraction(s.points, result);
    ASSERT_TRUE(out.solid);
    int checked = 0;
    int close = 0;
    for (const PatchFace& pf : out.faces) {
        ASSERT_FALSE(pf.face.IsNull());
        ASSERT_EQ(pf.deviations.size(), static_cast<size_t>(pf.points));
        // The patch's points in the order of the cloud's rows.
        size_t k = 0;
        for (Eigen::Index i = 0; i < s.points.rows(); ++i) {
            if (result.patch[static_cast<size_t>(i)] != pf.patch) {
                continue;
            }
            const double t = (s.points.row(i) - clean.points.row(i)).dot(clean.normals.row(i));
            close += std::abs(pf.deviations[k] - t) < 0.05 ? 1 : 0;
            ++checked;
            ++k;
        }
        EXPECT_EQ(k, pf.deviations.size());
    }
    EXPECT_GT(checked, s.points.rows() / 2);
    EXPECT_GT(close, 0.95 * checked);
}

TEST(PatchSurfaces, ACylinderWithFlatEndsIsACylinderOfItsRadiusAndTwoPlanes)
{
    const double r = 10.0;
    const double h = 30.0;
    shapes::Sample side = shapes::cylinder(r, h, 1.0, 10);
    // The two ends: discs sampled on a jittered grid one spacing apart.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    std::vector<Eigen::Vector3d> points;
    for (Eigen::Index i = 0; i < side.points.rows(); ++i) {
        points.push_back(side.points.row(i).transpose());
    }
    for (double z : {-h / 2.0, h / 2.0}) {
        for (double x = -r + 0.5; x < r; x += 1.0) {
            for (double y = -r + 0.5; y < r; y += 1.0) {
                const Eigen::Vector3d p(x + jitter(rng), y + jitter(rng), z);
                if (std::hypot(p.x(), p.y()) < r - 0.3) {
                    points.push_back(p);
                }
            }
        }
    }
    PointMatrix P(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i) {
        P.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
    }
    const PatchSurfaces out = surfacesOf(P);
    for (const std::string& p : out.problems) {
        ADD_FAILURE() << p;
    }
    EXPECT_EQ(countKind(out, SurfaceKind::Plane), 2);
    ASSERT_EQ(countKind(out, SurfaceKind::Cylinder), 1);
    for (const PatchFace& f : out.faces) {
        if (f.surface.kind == SurfaceKind::Cylinder) {
            EXPECT_NEAR(f.surface.radius, r, 0.05 * r);
        }
    }
    ASSERT_TRUE(out.solid) << "shape type " << (out.shape.IsNull() ? -1 : out.shape.ShapeType());
    EXPECT_TRUE(out.valid);
    EXPECT_NEAR(volumeOf(out.shape), M_PI * r * r * h, 0.03 * M_PI * r * r * h);
}

TEST(PatchSurfaces, TheDemoCloudIsTheDemoPartsSolid)
{
    // samples/boss_blend.xyz: a plate with rounded vertical corners, a boss with a bore
    // through it and the plate, a fillet round the boss's foot.
    const PointMatrix P = readCloud(FEATURELINES_SAMPLES_DIR "/boss_blend.xyz");
    const PatchSurfaces out = surfacesOf(P);
    for (const std::string& p : out.problems) {
        ADD_FAILURE() << p;
    }
    EXPECT_EQ(countKind(out, SurfaceKind::Plane), 7);
    EXPECT_EQ(countKind(out, SurfaceKind::Cylinder), 6);
    EXPECT_EQ(countKind(out, SurfaceKind::Torus), 1);
    ASSERT_TRUE(out.solid);
    EXPECT_TRUE(out.valid);
    const double truth = volumeOf(bench::makeCadShape("boss_blend").shape);
    EXPECT_NEAR(volumeOf(out.shape), truth, 0.01 * truth);
}

TEST(PatchSurfaces, AMergedViewScansPatchesGiveFacesOrReasonsNotACrash)
{
    // The random bracket of benchmark seed 1025 scanned in merged views: one patch's border
    // made OpenCASCADE 7.6's ShapeFix_Face::FixPeriodicDegenerated dereference a null handle
    // (a segmentation fault, which no exception handler catches). Every patch now gets a valid
    // face or a reason.
    const bench::RandomPart part = bench::makeRandomPart(1025);
    bench::ScanOptions scan = bench::drawScanOptions(1025);
    scan.points = part.targetPoints;
    const bench::ScannedCloud cloud = bench::sampleLikeAScanner(part.shape, scan);
    const PatchSurfaces out = surfacesOf(cloud.points);
    ASSERT_FALSE(out.faces.empty());
    for (const PatchFace& f : out.faces) {
        if (f.face.IsNull()) {
            EXPECT_FALSE(f.problem.empty()) << "patch " << f.patch;
        } else {
            EXPECT_TRUE(f.problem.empty()) << f.problem;
        }
    }
}

/// The border of the height field z over the square [-10, 10]^2: its four sides lifted onto it,
/// each a B-spline through 21 of its points.
TopoDS_Wire borderOver(const std::function<double(double, double)>& z)
{
    const double corners[5][2] = {{-10, -10}, {10, -10}, {10, 10}, {-10, 10}, {-10, -10}};
    BRepBuilderAPI_MakeWire wire;
    for (int side = 0; side < 4; ++side) {
        TColgp_Array1OfPnt along(1, 21);
        for (int k = 0; k <= 20; ++k) {
            const double t = k / 20.0;
            const double x = corners[side][0] + t * (corners[side + 1][0] - corners[side][0]);
            const double y = corners[side][1] + t * (corners[side + 1][1] - corners[side][1]);
            along.SetValue(k + 1, gp_Pnt(x, y, z(x, y)));
        }
        wire.Add(BRepBuilderAPI_MakeEdge(GeomAPI_PointsToBSpline(along).Curve()).Edge());
    }
    EXPECT_TRUE(wire.IsDone());
    return wire.Wire();
}

TEST(PatchSurfaces, ASaddlePatchGetsAHeightFieldOrAPlateThroughItsBorder)
{
    // z = (x^2 - y^2) / 40 over [-10, 10]^2, its border four B-spline edges on the saddle: both
    // B-spline faces lie within a twentieth of a spacing of the points (along the normal), the
    // plate through the border's own edges, each of the saddle's area.
    const auto z = [](double x, double y) { return (x * x - y * y) / 40.0; };
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    PointMatrix P(800, 3);
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        const double x = u(rng);
        const double y = u(rng);
        P.row(i) << x, y, z(x, y);
    }
    const std::vector<TopoDS_Wire> border = {borderOver(z)};
    const auto rmsOf = [](const std::vector<double>& d) {
        double sum = 0.0;
        for (double x : d) {
            sum += x * x;
        }
        return std::sqrt(sum / static_cast<double>(d.size()));
    };
    // The saddle's area over the square, by the midpoint rule: the integral of
    // sqrt(1 + (x / 20)^2 + (y / 20)^2).
    double area = 0.0;
    const int cells = 400;
    const double h = 20.0 / cells;
    for (int i = 0; i < cells; ++i) {
        for (int j = 0; j < cells; ++j) {
            const double x = -10.0 + (i + 0.5) * h;
            const double y = -10.0 + (j + 0.5) * h;
            area += std::sqrt(1.0 + x * x / 400.0 + y * y / 400.0) * h * h;
        }
    }
    PatchSurfaceOptions options;
    for (BSplineFace method : {BSplineFace::HeightField, BSplineFace::Plate}) {
        options.bspline = method;
        const PatchFace f = fitPatchFace(3, P, border, 1.0, 0.0, options);
        ASSERT_FALSE(f.face.IsNull()) << f.problem;
        EXPECT_EQ(f.surface.kind, SurfaceKind::BSpline);
        EXPECT_EQ(f.plate, method == BSplineFace::Plate);
        EXPECT_LT(f.surface.rmsDeviation, 0.05);
        ASSERT_EQ(f.deviations.size(), static_cast<size_t>(P.rows()));
        EXPECT_NEAR(rmsOf(f.deviations), f.surface.rmsDeviation, 1e-9);
        GProp_GProps props;
        BRepGProp::SurfaceProperties(f.face, props);
        EXPECT_NEAR(props.Mass(), area, 0.005 * area);
    }
}

TEST(PatchSurfaces, ABSplinesDeviationsAreAlongItsNormal)
{
    // A steeper saddle, z = (x^2 - y^2) / 20 (slopes up to 1), its points moved along the true
    // normal by Gaussian noise of 0.1: the height field's points lie 0.1 (RMS) from it along the
    // normal, though their vertical distances, which the fit itself minimises, are larger.
    const auto z = [](double x, double y) { return (x * x - y * y) / 20.0; };
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    std::normal_distribution<double> noise(0.0, 0.1);
    PointMatrix P(3000, 3);
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        const double x = u(rng);
        const double y = u(rng);
        const Eigen::Vector3d n = Eigen::Vector3d(-x / 10.0, y / 10.0, 1.0).normalized();
        P.row(i) = (Eigen::Vector3d(x, y, z(x, y)) + noise(rng) * n).transpose();
    }
    const PatchFace f = fitPatchFace(4, P, {borderOver(z)}, 1.0, 0.1);
    ASSERT_FALSE(f.face.IsNull()) << f.problem;
    ASSERT_EQ(f.surface.kind, SurfaceKind::BSpline);
    EXPECT_NEAR(f.surface.rmsDeviation, 0.1, 0.015);
    EXPECT_GT(fitSurface(P, 1.0, 0.1).rmsDeviation, 1.1 * f.surface.rmsDeviation);
}

TEST(PatchSurfaces, ABadPatchGetsNoFaceAndAReason)
{
    // A square border wire around points that make no surface: too few, on a line, not finite;
    // and good points without a border.
    const double h = 5.0;
    BRepBuilderAPI_MakePolygon square(gp_Pnt(-h, -h, 0), gp_Pnt(h, -h, 0), gp_Pnt(h, h, 0),
                                      gp_Pnt(-h, h, 0), Standard_True);
    const std::vector<TopoDS_Wire> wires = {square.Wire()};
    PointMatrix few(4, 3);
    few << 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0;
    PointMatrix line(20, 3);
    for (int i = 0; i < 20; ++i) {
        line.row(i) << -4.0 + 0.4 * i, 0.0, 0.0;
    }
    PointMatrix notFinite = shapes::plane(9.0, 1.0, 3).points;
    notFinite(5, 2) = std::numeric_limits<double>::infinity();
    for (const PointMatrix* bad : {&few, &line, &notFinite}) {
        const PatchFace f = fitPatchFace(7, *bad, wires, 1.0, 0.0);
        EXPECT_TRUE(f.face.IsNull());
        EXPECT_NE(f.problem.find("patch 7: "), std::string::npos) << f.problem;
    }
    const PatchFace open = fitPatchFace(8, shapes::plane(9.0, 1.0, 3).points, {}, 1.0, 0.0);
    EXPECT_TRUE(open.face.IsNull());
    EXPECT_EQ(open.problem, "patch 8: no closed border");
    // The good patch with its border: a plane face of the square's area.
    const PatchFace good = fitPatchFace(9, shapes::plane(9.0, 1.0, 3).points, wires, 1.0, 0.0);
    ASSERT_FALSE(good.face.IsNull()) << good.problem;
    GProp_GProps props;
    BRepGProp::SurfaceProperties(good.face, props);
    EXPECT_NEAR(props.Mass(), 4.0 * h * h, 1e-6);
    // Sewing nothing is no shape and no crash; the reasons are kept.
    const PatchSurfaces none = sewPatchFaces({open}, 1.0);
    EXPECT_TRUE(none.shape.IsNull());
    EXPECT_FALSE(none.solid);
    ASSERT_EQ(none.problems.size(), 1u);
}

} // namespace
