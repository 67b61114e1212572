// SPDX-License-Identifier: LGPL-2.1-or-later
// The fits of one curve on points whose curve is known: a segment, an arc in a tilted plane, a
// circle, a helix (no plane: a B-spline), a closed non-planar loop (a periodic B-spline), and a
// zigzag about an arc that the tolerance smooths away.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "FeatureLines/curves/CurveFit.h"

using namespace featurelines;

namespace {

constexpr double pi = 3.14159265358979323846;

/// n points of f(t) for t from a to b (closed: b excluded).
template <typename F> PointMatrix pointsOf(F f, double a, double b, int n, bool closed = false)
{
    PointMatrix P(n, 3);
    for (int i = 0; i < n; ++i) {
        const double t = a + (b - a) * i / (closed ? n : n - 1);
        P.row(i) = f(t).transpose();
    }
    return P;
}

CurveFitInput input(const PointMatrix& P, double tolerance, bool closed = false)
{
    CurveFitInput in;
    in.points = P;
    in.closed = closed;
    in.freeVertex = closed;
    in.tolerance = tolerance;
    return in;
}

/// A rotation that tilts the xy plane out of every coordinate plane.
Eigen::Matrix3d tilt()
{
    return (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
            Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
}

} // namespace

TEST(CurveFit, NoisyStraightPointsGiveTheSegmentBetweenTheEnds)
{
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> jitter(-0.05, 0.05);
    PointMatrix P = pointsOf([](double t) { return Eigen::Vector3d(t, 2 * t, -t); }, 0, 10, 50);
    for (Eigen::Index i = 1; i + 1 < P.rows(); ++i) {
        P.row(i) += Eigen::RowVector3d(jitter(rng), jitter(rng), jitter(rng));
    }
    const FittedCurve c = fitCurve(input(P, 0.25));
    EXPECT_EQ(c.kind, CurveKind::Segment);
    EXPECT_EQ(c.start, Eigen::Vector3d(P.row(0).transpose()));
    EXPECT_EQ(c.end, Eigen::Vector3d(P.row(49).transpose()));
    EXPECT_LE(c.maxDeviation, 0.05 * std::sqrt(3.0));
    EXPECT_STREQ(curveKindName(c.kind), "segment");
}

TEST(CurveFit, PointsOnATiltedArcGiveThatArc)
{
    const Eigen::Matrix3d R = tilt();
    const Eigen::Vector3d centre(1, -2, 3);
    const double radius = 5.0;
    const auto onArc = [&](double t) {
        return Eigen::Vector3d(
            centre + R * Eigen::Vector3d(radius * std::cos(t), radius * std::sin(t), 0.0));
    };
    // Clockwise about R z: the arc's axis is -R z.
    const PointMatrix P = pointsOf(onArc, 2.0, 2.0 - 2 * pi / 3, 40);
    const FittedCurve c = fitCurve(input(P, 0.01));
    ASSERT_EQ(c.kind, CurveKind::Arc);
    EXPECT_NEAR(c.radius, radius, 1e-9);
    EXPECT_NEAR((c.centre - centre).norm(), 0.0, 1e-9);
    EXPECT_NEAR(c.axis.dot(-R.col(2)), 1.0, 1e-9);
    EXPECT_EQ(c.start, Eigen::Vector3d(P.row(0).transpose()));
    EXPECT_EQ(c.end, Eigen::Vector3d(P.row(39).transpose()));
    EXPECT_NEAR((curvePoint(c, 0.5) - onArc(2.0 - pi / 3)).norm(), 0.0, 1e-9);
    EXPECT_NEAR(curveLength(c), radius * 2 * pi / 3, 1e-4);
    EXPECT_NEAR(c.maxDeviation, 0.0, 1e-9);
}

TEST(CurveFit, ALoopOnACircleGivesTheCircleWithItsVertexOnIt)
{
    const Eigen::Matrix3d R = tilt();
    const auto onCircle = [&](double t) {
        return Eigen::Vector3d(R * Eigen::Vector3d(3 * std::cos(t), 3 * std::sin(t), 0.0));
    };
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.01);
    PointMatrix P = pointsOf(onCircle, 0, 2 * pi, 60, true);
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        P.row(i) += Eigen::RowVector3d(noise(rng), noise(rng), noise(rng));
    }
    const FittedCurve c = fitCurve(input(P, 0.1, true));
    ASSERT_EQ(c.kind, CurveKind::Circle);
    EXPECT_NEAR(c.radius, 3.0, 0.01);
    EXPECT_NEAR(c.centre.norm(), 0.0, 0.01);
    EXPECT_NEAR(std::abs(c.axis.dot(R.col(2))), 1.0, 1e-4);
    EXPECT_EQ(c.start, c.end);
    EXPECT_NEAR(((c.start - c.centre).norm()), c.radius, 1e-12) << "the vertex is on the circle";
    EXPECT_LT((c.start - Eigen::Vector3d(P.row(0).transpose())).norm(), 0.05);
}

TEST(CurveFit, AHelixGivesAClampedBSplineWithFewPolesWithinTheTolerance)
{
    const auto helix = [](double t) {
        return Eigen::Vector3d(4 * std::cos(t), 4 * std::sin(t), 0.8 * t);
    };
    const PointMatrix P = pointsOf(helix, 0, 3 * pi, 300);
    const double tolerance = 0.02;
    const FittedCurve c = fitCurve(input(P, tolerance));
    ASSERT_EQ(c.kind, CurveKind::BSpline) << "a helix lies in no plane";
    EXPECT_FALSE(c.periodic);
    EXPECT_EQ(c.degree, 3);
    EXPECT_LE(c.maxDeviation, tolerance);
    EXPECT_LE(c.poles.rows(), 20) << "1.5 turns need a handful of cubic pieces";
    // OpenCASCADE's clamped form: end knots of multiplicity 4, poles = sum of mults - 4.
    EXPECT_EQ(c.multiplicities.front(), 4);
    EXPECT_EQ(c.multiplicities.back(), 4);
    int sum = 0;
    for (int m : c.multiplicities) {
        sum += m;
    }
    EXPECT_EQ(c.poles.rows(), sum - 4);
    EXPECT_EQ(c.start, Eigen::Vector3d(P.row(0).transpose()));
    EXPECT_EQ(Eigen::Vector3d(c.poles.row(0).transpose()), c.start);
    EXPECT_EQ(Eigen::Vector3d(c.poles.row(c.poles.rows() - 1).transpose()), c.end);
    // The curve, not only at the points: a dense sampling of the true helix is within the
    // tolerance of it.
    const PointMatrix truth = pointsOf(helix, 0, 3 * pi, 3000);
    EXPECT_LE(distancesToCurve(c, truth, 0.005).maxCoeff(), tolerance * 1.5);
}

TEST(CurveFit, AClosedLoopOutOfPlaneGivesAPeriodicBSpline)
{
    const auto saddle = [](double t) {
        return Eigen::Vector3d(4 * std::cos(t), 2 * std::sin(t), 0.7 * std::sin(2 * t));
    };
    const PointMatrix P = pointsOf(saddle, 0, 2 * pi, 200, true);
    const double tolerance = 0.01;
    const FittedCurve c = fitCurve(input(P, tolerance, true));
    ASSERT_EQ(c.kind, CurveKind::BSpline);
    EXPECT_TRUE(c.periodic);
    EXPECT_LE(c.maxDeviation, tolerance);
    // OpenCASCADE's periodic form: simple knots, as many poles as knot spans.
    EXPECT_EQ(c.poles.rows(), static_cast<Eigen::Index>(c.knots.size()) - 1);
    EXPECT_EQ(c.start, c.end);
    EXPECT_LT((curvePoint(c, 1e-9) - curvePoint(c, 1.0 - 1e-9)).norm(), 1e-6) << "closes";
    EXPECT_GT(curveTangent(c, 1e-9).dot(curveTangent(c, 1.0 - 1e-9)), 1.0 - 1e-6) << "smoothly";
    const PointMatrix truth = pointsOf(saddle, 0, 2 * pi, 2000, true);
    EXPECT_LE(distancesToCurve(c, truth, 0.005).maxCoeff(), tolerance * 1.5);
}

TEST(CurveFit, AStraightEdgeBowedByItsLinesPlacementIsASegmentNotAHugeArc)
{
    // 67 long, bowed by 0.25 at its middle (a line placed a third of a spacing off at its
    // ends), tolerance 0.19: the arc through the ends would hold it, with a radius of 2 200.
    const auto bowed = [](double t) {
        return Eigen::Vector3d(t, 0.25 * (1.0 - (2.0 * t / 67.0 - 1.0) * (2.0 * t / 67.0 - 1.0)),
                               0.0);
    };
    const CurveFitInput in = input(pointsOf(bowed, 0, 67, 90), 0.19);
    ASSERT_FALSE(fitSegment(in)) << "the segment alone does not hold: the test is not empty";
    ASSERT_TRUE(fitArc(in));
    const FittedCurve c = fitCurve(in);
    EXPECT_EQ(c.kind, CurveKind::Segment) << "radius " << c.radius;
}

TEST(CurveFit, AGivenEndTangentIsKept)
{
    const auto bend = [](double t) { return Eigen::Vector3d(t, 0.1 * t * t * t, 0.0); };
    CurveFitInput in = input(pointsOf(bend, 0, 3, 60), 0.01);
    const Eigen::Vector3d tangent = Eigen::Vector3d(1, -0.2, 0).normalized();
    in.startTangent = tangent;
    const FittedCurve c = fitBSpline(in);
    EXPECT_GT(curveTangent(c, 0.0).dot(tangent), 1.0 - 1e-8);
    EXPECT_LE(c.maxDeviation, 0.01);
}

TEST(CurveFit, AZigzagOfOneSpacingAboutAnArcIsSmoothedAwayByTheNoiseAwareTolerance)
{
    // A polyline zigzagging +-0.5 (one spacing peak to peak) about a quarter circle of radius
    // 20: the scatter raises the tolerance, and the fit runs along the middle.
    const double radius = 20.0;
    PointMatrix P(64, 3);
    for (int i = 0; i < 64; ++i) {
        const double t = 0.5 * pi * i / 63;
        const double r = radius + ((i == 0 || i == 63) ? 0.0 : (i % 2 ? 0.5 : -0.5));
        P.row(i) << r * std::cos(t), r * std::sin(t), 0.0;
    }
    const double scatter = polylineScatter(P, false);
    EXPECT_GT(scatter, 0.4);
    const FittedCurve c = fitCurve(input(P, std::max(0.25, 4 * scatter)));
    const PointMatrix truth = pointsOf(
        [&](double t) { return Eigen::Vector3d(radius * std::cos(t), radius * std::sin(t), 0); }, 0,
        0.5 * pi, 500);
    const Eigen::VectorXd d = distancesToCurve(c, truth, 0.05);
    EXPECT_LE(d.maxCoeff(), 0.1) << curveKindName(c.kind);
}
