// SPDX-License-Identifier: LGPL-2.1-or-later
// The fitted curves' plain data read by OpenCASCADE as the FreeCAD side reads it: a clamped and
// a periodic B-spline given to Geom_BSplineCurve as they are (poles, knots, multiplicities,
// degree, periodic), and an arc given to gp_Circ, are the curves the core evaluates.
#include <cmath>

#include <gtest/gtest.h>

#include <ElCLib.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>

#include "FeatureLines/curves/CurveFit.h"

using namespace featurelines;

namespace {

constexpr double pi = 3.14159265358979323846;

Handle(Geom_BSplineCurve) toOcct(const FittedCurve& c)
{
    TColgp_Array1OfPnt poles(1, static_cast<int>(c.poles.rows()));
    for (int i = 0; i < c.poles.rows(); ++i) {
        poles(i + 1) = gp_Pnt(c.poles(i, 0), c.poles(i, 1), c.poles(i, 2));
    }
    const int n = static_cast<int>(c.knots.size());
    TColStd_Array1OfReal knots(1, n);
    TColStd_Array1OfInteger multiplicities(1, n);
    for (int i = 0; i < n; ++i) {
        knots(i + 1) = c.knots[static_cast<size_t>(i)];
        multiplicities(i + 1) = c.multiplicities[static_cast<size_t>(i)];
    }
    return new Geom_BSplineCurve(poles, knots, multiplicities, c.degree, c.periodic);
}

/// The largest distance between the core's and OpenCASCADE's points at 101 parameters.
double largestGap(const FittedCurve& c)
{
    const Handle(Geom_BSplineCurve) occt = toOcct(c);
    const double first = occt->FirstParameter(), last = occt->LastParameter();
    double gap = 0.0;
    for (int i = 0; i <= 100; ++i) {
        const double s = i / 100.0;
        const gp_Pnt q = occt->Value(first + s * (last - first));
        gap = std::max(gap, (curvePoint(c, s) - Eigen::Vector3d(q.X(), q.Y(), q.Z())).norm());
    }
    return gap;
}

PointMatrix pointsOf(double (*x)(double), double (*y)(double), double (*z)(double), int n,
                     double turn, bool closed)
{
    PointMatrix P(n, 3);
    for (int i = 0; i < n; ++i) {
        const double t = turn * i / (closed ? n : n - 1);
        P.row(i) << x(t), y(t), z(t);
    }
    return P;
}

} // namespace

TEST(CurveOcct, AClampedBSplineIsTheSameCurveInOpenCascade)
{
    CurveFitInput in;
    in.points =
        pointsOf([](double t) { return 4 * std::cos(t); }, [](double t) { return 4 * std::sin(t); },
                 [](double t) { return 0.8 * t; }, 200, 3 * pi, false);
    in.tolerance = 0.02;
    const FittedCurve c = fitBSpline(in);
    ASSERT_FALSE(c.periodic);
    EXPECT_LT(largestGap(c), 1e-9);
}

TEST(CurveOcct, APeriodicBSplineIsTheSameCurveInOpenCascade)
{
    CurveFitInput in;
    in.points =
        pointsOf([](double t) { return 4 * std::cos(t); }, [](double t) { return 2 * std::sin(t); },
                 [](double t) { return 0.7 * std::sin(2 * t); }, 200, 2 * pi, true);
    in.closed = in.freeVertex = true;
    in.tolerance = 0.01;
    const FittedCurve c = fitBSpline(in);
    ASSERT_TRUE(c.periodic);
    EXPECT_LT(largestGap(c), 1e-9);
}

TEST(CurveOcct, AnArcRunsCounterClockwiseAboutItsAxisAsGpCirc)
{
    // Points clockwise about +z: the fitted arc's axis is -z, and gp_Circ on that axis, its X
    // direction towards the start, meets the end at the arc's sweep.
    CurveFitInput in;
    in.points = pointsOf([](double t) { return 3 * std::cos(-t); },
                         [](double t) { return 3 * std::sin(-t); }, [](double) { return 1.0; }, 30,
                         2.0, false);
    in.tolerance = 0.01;
    const FittedCurve c = fitCurve(in);
    ASSERT_EQ(c.kind, CurveKind::Arc);
    const gp_Circ circle(gp_Ax2(gp_Pnt(c.centre.x(), c.centre.y(), c.centre.z()),
                                gp_Dir(c.axis.x(), c.axis.y(), c.axis.z()),
                                gp_Dir(c.start.x() - c.centre.x(), c.start.y() - c.centre.y(),
                                       c.start.z() - c.centre.z())),
                         c.radius);
    for (int i = 0; i <= 10; ++i) {
        const gp_Pnt q = ElCLib::Value(2.0 * i / 10, circle);
        EXPECT_LT((curvePoint(c, i / 10.0) - Eigen::Vector3d(q.X(), q.Y(), q.Z())).norm(), 1e-9);
    }
}
