// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "FeatureLines/neighbourhoods/Normals.h"
#include "SampledShapes.h"

using namespace featurelines;

namespace {

constexpr double degree = 3.14159265358979323846 / 180.0;

/// Angle in degrees between two unoriented directions.
double unorientedAngle(const Eigen::RowVector3d& a, const Eigen::RowVector3d& b)
{
    return std::acos(std::min(1.0, std::abs(a.dot(b)) / (a.norm() * b.norm()))) / degree;
}

} // namespace

TEST(Normals, PlaneNormalsAreAllZ)
{
    const shapes::Sample s = shapes::plane(30.0, 1.0, 1);
    const NormalEstimate e = pcaNormals(s.points, nearestNeighbours(s.points));
    for (Eigen::Index i = 0; i < s.size(); ++i) {
        // The largest component is positive, so every normal is exactly +z, not -z.
        EXPECT_NEAR(e.normals(i, 2), 1.0, 1e-12) << "point " << i;
        EXPECT_NEAR(e.variation(i), 0.0, 1e-12);
    }
}

TEST(Normals, TiltedPlaneFarFromOrigin)
{
    // A plane through (1e6, -2e6, 5e5) with normal (1, 2, 2)/3: the covariance is taken about
    // each point, so the offset costs no accuracy.
    const shapes::Sample s = shapes::plane(30.0, 1.0, 2);
    const Eigen::Vector3d n = Eigen::Vector3d(1, 2, 2) / 3.0;
    const Eigen::Vector3d u = n.unitOrthogonal();
    const Eigen::Vector3d v = n.cross(u);
    PointMatrix P(s.size(), 3);
    for (Eigen::Index i = 0; i < s.size(); ++i) {
        P.row(i) =
            (Eigen::Vector3d(1e6, -2e6, 5e5) + s.points(i, 0) * u + s.points(i, 1) * v).transpose();
    }
    const NormalEstimate e = pcaNormals(P, nearestNeighbours(P));
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        EXPECT_LT(unorientedAngle(e.normals.row(i), n.transpose()), 1e-4) << "point " << i;
    }
}

TEST(Normals, SphereNormalsAreRadial)
{
    // r = 20 spacings, k = 16: the neighbourhood spans about 4 spacings, 12 degrees of arc.
    const shapes::Sample s = shapes::sphere(20.0, 1.0, 3);
    const NormalEstimate e = pcaNormals(s.points, nearestNeighbours(s.points, {16, 0}));
    double worst = 0.0;
    for (Eigen::Index i = 0; i < s.size(); ++i) {
        EXPECT_NEAR(e.normals.row(i).norm(), 1.0, 1e-12);
        worst = std::max(worst, unorientedAngle(e.normals.row(i), s.normals.row(i)));
    }
    EXPECT_LT(worst, 2.0);
}

TEST(Normals, CoincidentNeighboursGiveAFiniteNormal)
{
    // Four copies of each of two points: some neighbourhoods are a single repeated point.
    PointMatrix P(8, 3);
    P.topRows(4).rowwise() = Eigen::RowVector3d(0, 0, 0);
    P.bottomRows(4).rowwise() = Eigen::RowVector3d(1, 0, 0);
    const NormalEstimate e = pcaNormals(P, nearestNeighbours(P, {3, 0}));
    EXPECT_TRUE(e.normals.allFinite());
    EXPECT_TRUE(e.variation.allFinite());
}

TEST(Normals, BadInputThrows)
{
    const shapes::Sample s = shapes::plane(10.0, 1.0, 4);
    const Neighbourhoods N = nearestNeighbours(s.points, {8, 0});
    EXPECT_THROW(pcaNormals(s.points, N, {9, 0}), std::invalid_argument);
    EXPECT_THROW(pcaNormals(s.points.topRows(20), N), std::invalid_argument);
}

TEST(Normals, CovarianceOfACubesCornersFarFromTheOrigin)
{
    // The corners of a unit cube, each 25 000 times (200 000 rows, many blocks), a million
    // units from the origin: each coordinate is 0 or 1 with even odds, independently, so the
    // covariance is I / 4.
    PointMatrix P(200000, 3);
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        const int corner = static_cast<int>(i % 8);
        P.row(i) << 1e6 + (corner & 1), -2e6 + ((corner >> 1) & 1), 3e6 + ((corner >> 2) & 1);
    }
    const Eigen::Matrix3d C = covarianceOf(P);
    EXPECT_LT((C - 0.25 * Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-9);
    // Every eighth row: always the same corner, no spread at all.
    EXPECT_LT(covarianceOf(P, 8).cwiseAbs().maxCoeff(), 1e-12);
    // Every second row: x stays 0 (even corners), y and z still spread.
    const Eigen::Matrix3d half = covarianceOf(P, 2);
    EXPECT_LT(std::abs(half(0, 0)), 1e-12);
    EXPECT_NEAR(half(1, 1), 0.25, 1e-9);
    EXPECT_NEAR(half(2, 2), 0.25, 1e-9);
    // The means: the cube's centre, then the one corner of every eighth row, then x at the
    // even corners' 0 (to the digits a million units allow).
    const Eigen::RowVector3d centre(1e6 + 0.5, -2e6 + 0.5, 3e6 + 0.5);
    EXPECT_LT((momentsOf(P).mean - centre).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LT((momentsOf(P, 8).mean - P.row(0)).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_NEAR(momentsOf(P, 2).mean.x(), 1e6, 1e-9);
    EXPECT_EQ(momentsOf(P).covariance, C);
    EXPECT_THROW(covarianceOf(PointMatrix(0, 3)), std::invalid_argument);
    EXPECT_THROW(covarianceOf(P, 0), std::invalid_argument);
    EXPECT_THROW(momentsOf(P, -1), std::invalid_argument);
}
