// SPDX-License-Identifier: LGPL-2.1-or-later
// The corners of lines whose corners are known: a square loop's four (clean and with noise of
// 0.3 spacing across it), a spherical triangle's three (arcs meeting at right angles), an L's
// one; and none on circles of 4 to 40 spacings' radius, a rounded rectangle whose corners are
// arcs of 12 spacings, a noisy straight line, or a straight line with a slow excursion.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "FeatureLines/curves/LineCorners.h"

using namespace featurelines;

namespace {

constexpr double pi = 3.14159265358979323846;

/// A rotation that tilts the xy plane out of every coordinate plane.
Eigen::Matrix3d tilt()
{
    return (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
            Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
}

/// The polyline through `corners` (a closed polygon when `closed`), a vertex every `step`,
/// tilted, moved by Gaussian noise of `sigma` in every coordinate.
PointMatrix polygon(const std::vector<Eigen::Vector3d>& corners, bool closed, double step,
                    double sigma, unsigned seed)
{
    std::vector<Eigen::Vector3d> out;
    const size_t sides = closed ? corners.size() : corners.size() - 1;
    for (size_t k = 0; k < sides; ++k) {
        const Eigen::Vector3d a = corners[k], b = corners[(k + 1) % corners.size()];
        const int n = static_cast<int>(std::round((b - a).norm() / step));
        for (int i = 0; i < n; ++i) {
            out.push_back(a + (b - a) * i / n);
        }
    }
    if (!closed) {
        out.push_back(corners.back());
    }
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    PointMatrix P(static_cast<Eigen::Index>(out.size()), 3);
    for (size_t i = 0; i < out.size(); ++i) {
        const Eigen::Vector3d p =
            out[i] + (sigma > 0 ? Eigen::Vector3d(noise(rng), noise(rng), noise(rng))
                                : Eigen::Vector3d::Zero());
        P.row(static_cast<Eigen::Index>(i)) = (tilt() * p).transpose();
    }
    return P;
}

/// n points of f(t), t from a to b (closed: b excluded), tilted, with Gaussian noise.
template <typename F>
PointMatrix curve(F f, double a, double b, int n, bool closed, double sigma, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    PointMatrix P(n, 3);
    for (int i = 0; i < n; ++i) {
        const double t = a + (b - a) * i / (closed ? n : n - 1);
        Eigen::Vector3d p = f(t);
        if (sigma > 0) {
            p += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
        }
        P.row(i) = (tilt() * p).transpose();
    }
    return P;
}

} // namespace

TEST(LineCorners, ASquareLoopHasItsFourCornersWhereItsSidesMeet)
{
    const std::vector<Eigen::Vector3d> square{{0, 0, 0}, {30, 0, 0}, {30, 30, 0}, {0, 30, 0}};
    for (double sigma : {0.0, 0.3 / std::sqrt(3.0)}) {
        const PointMatrix P = polygon(square, true, 1.0, sigma, 3);
        const std::vector<LineCorner> corners = findLineCorners(P, true, 1.0);
        ASSERT_EQ(corners.size(), 4u) << "noise " << sigma;
        for (const LineCorner& c : corners) {
            double nearest = 1e9;
            for (const Eigen::Vector3d& q : square) {
                nearest = std::min(nearest, (c.position - tilt() * q).norm());
            }
            EXPECT_LE(nearest, sigma > 0 ? 0.6 : 0.1)
                << "noise " << sigma << " vertex " << c.vertex << " at "
                << (tilt().transpose() * c.position).transpose();
            EXPECT_NEAR(c.turn, 90.0, sigma > 0 ? 6.0 : 1.0);
        }
    }
}

TEST(LineCorners, ACornerBlendsBorderHasThreeCornersBetweenItsArcs)
{
    // The border of a sphere's octant of radius 12: three quarter circles meeting at right
    // angles (where a rounded cube's corner blend meets its faces and fillets).
    const double r = 12.0;
    const int n = 30;
    std::vector<Eigen::Vector3d> points;
    for (int arc = 0; arc < 3; ++arc) {
        for (int i = 0; i < n; ++i) {
            const double t = pi / 2 * i / n;
            Eigen::Vector3d p = Eigen::Vector3d::Zero();
            p((arc + 0) % 3) = r * std::cos(t);
            p((arc + 1) % 3) = r * std::sin(t);
            points.push_back(p);
        }
    }
    PointMatrix P(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i) {
        P.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
    }
    const std::vector<LineCorner> corners = findLineCorners(P, true, 0.6);
    ASSERT_EQ(corners.size(), 3u);
    for (const LineCorner& c : corners) {
        // On a coordinate axis at distance r: two coordinates near 0.
        Eigen::Vector3d a = c.position.cwiseAbs();
        std::sort(a.data(), a.data() + 3);
        EXPECT_LE(a(1), 0.6) << c.position.transpose();
        EXPECT_NEAR(a(2), r, 0.6);
        EXPECT_NEAR(c.turn, 90.0, 8.0);
    }
}

TEST(LineCorners, AnOpenLShapeHasOneCornerAndNoneAtItsEnds)
{
    const PointMatrix P = polygon({{0, 0, 0}, {20, 0, 0}, {20, 14, 0}}, false, 1.0, 0.1, 5);
    const std::vector<LineCorner> corners = findLineCorners(P, false, 1.0);
    ASSERT_EQ(corners.size(), 1u);
    EXPECT_LE((corners[0].position - tilt() * Eigen::Vector3d(20, 0, 0)).norm(), 0.5);
}

TEST(LineCorners, CirclesHaveNoCornerCleanOrNoisy)
{
    for (double radius : {4.0, 8.0, 15.0, 40.0}) {
        for (double sigma : {0.0, 0.3 / std::sqrt(3.0)}) {
            const int n = static_cast<int>(std::round(2 * pi * radius));
            const PointMatrix P = curve(
                [radius](double t) {
                    return Eigen::Vector3d(radius * std::cos(t), radius * std::sin(t), 0);
                },
                0, 2 * pi, n, true, sigma, 7);
            EXPECT_TRUE(findLineCorners(P, true, 1.0).empty())
                << "radius " << radius << " noise " << sigma;
        }
    }
}

TEST(LineCorners, ARoundedRectanglesTangentArcsAreNoCorners)
{
    // Sides of 50 and 40 spacings joined by quarter circles of radius 12: the border of a
    // face whose neighbours meet it through fillets of 12 spacings. Clean and with noise of
    // 0.3 spacing.
    const double a = 25, b = 20, r = 12;
    std::vector<Eigen::Vector3d> points;
    const Eigen::Vector3d centres[4] = {
        {a - r, b - r, 0}, {-a + r, b - r, 0}, {-a + r, -b + r, 0}, {a - r, -b + r, 0}};
    for (int k = 0; k < 4; ++k) {
        const double start = k * pi / 2;
        const int arc = static_cast<int>(std::round(pi / 2 * r));
        for (int i = 0; i < arc; ++i) {
            const double t = start + pi / 2 * i / arc;
            points.push_back(centres[k] + r * Eigen::Vector3d(std::cos(t), std::sin(t), 0));
        }
        const Eigen::Vector3d radial(std::cos(start + pi / 2), std::sin(start + pi / 2), 0);
        const Eigen::Vector3d from = centres[k] + r * radial,
                              to = centres[(k + 1) % 4] + r * radial;
        const int n = static_cast<int>(std::round((to - from).norm()));
        for (int i = 0; i < n; ++i) {
            points.push_back(from + (to - from) * i / n);
        }
    }
    for (double sigma : {0.0, 0.3 / std::sqrt(3.0)}) {
        std::mt19937 rng(13);
        std::normal_distribution<double> noise(0.0, sigma > 0 ? sigma : 1.0);
        PointMatrix P(static_cast<Eigen::Index>(points.size()), 3);
        for (size_t i = 0; i < points.size(); ++i) {
            Eigen::Vector3d p = points[i];
            if (sigma > 0) {
                p += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
            }
            P.row(static_cast<Eigen::Index>(i)) = (tilt() * p).transpose();
        }
        EXPECT_TRUE(findLineCorners(P, true, 1.0).empty()) << "noise " << sigma;
    }
}

TEST(LineCorners, StraightLinesNoisyOrWithASlowExcursionHaveNoCorner)
{
    const PointMatrix noisy = polygon({{0, 0, 0}, {60, 0, 0}}, false, 1.0, 0.3 / std::sqrt(3.0), 9);
    EXPECT_TRUE(findLineCorners(noisy, false, 1.0).empty());
    // An excursion of 1.5 spacings over 8, as a sharp line strays off its edge and back.
    const PointMatrix excursion = curve(
        [](double t) {
            const double bump = std::abs(t - 30) < 8 ? 0.75 * (1 + std::cos(pi * (t - 30) / 8)) : 0;
            return Eigen::Vector3d(t, bump, 0);
        },
        0, 60, 61, false, 0.05, 11);
    EXPECT_TRUE(findLineCorners(excursion, false, 1.0).empty());
}

TEST(LineCorners, NonsenseOptionsAreRefused)
{
    const PointMatrix P = polygon({{0, 0, 0}, {20, 0, 0}, {20, 14, 0}}, false, 1.0, 0.0, 5);
    LineCornerOptions o;
    o.window = 0.5; // narrower than the gap
    EXPECT_THROW(findLineCorners(P, false, 1.0, o), std::invalid_argument);
    EXPECT_THROW(findLineCorners(P, false, 0.0), std::invalid_argument);
    o = LineCornerOptions();
    o.angle = std::nan("");
    EXPECT_THROW(findLineCorners(P, false, 1.0, o), std::invalid_argument);
    EXPECT_TRUE(findLineCorners(PointMatrix(0, 3), true, 1.0).empty());
}
