// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cmath>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "FeatureLines/smooth/LinePlacement.h"
#include "SampledShapes.h"

using namespace featurelines;

namespace {

/// A plane (s < 0) blending through a fillet of radius r (0 <= s <= r pi / 4) into a plane
/// rising at 45 degrees: a profile in (x, z) sampled by its arc length s on a jittered grid of
/// the given spacing, extruded along y over [-width/2, width/2]. The fillet's borders, where
/// the curvature steps from 0 to 1 / r and back, are the lines x = 0 and x = r sin(pi / 4).
/// Normal noise of sigma (seeded).
shapes::Sample filletedStep(double r, double width, double spacing, double sigma, unsigned seed)
{
    const double arc = r * M_PI / 4;
    const double s0 = -width / 2, s1 = arc + width / 2;
    const int ns = static_cast<int>((s1 - s0) / spacing);
    const int ny = static_cast<int>(width / spacing);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.2 * spacing, 0.2 * spacing);
    std::normal_distribution<double> noise(0.0, sigma);
    shapes::Sample out;
    out.points.resize(static_cast<Eigen::Index>(ns) * ny, 3);
    out.normals.resize(out.points.rows(), 3);
    Eigen::Index row = 0;
    for (int i = 0; i < ns; ++i) {
        for (int j = 0; j < ny; ++j) {
            const double s = s0 + (i + 0.5) * spacing + jitter(rng);
            const double y = -width / 2 + (j + 0.5) * spacing + jitter(rng);
            double x, z, phi;
            if (s < 0) {
                x = s, z = 0, phi = 0;
            } else if (s <= arc) {
                phi = s / r;
                x = r * std::sin(phi), z = r * (1 - std::cos(phi));
            } else {
                phi = M_PI / 4;
                x = r * std::sin(phi) + (s - arc) * std::cos(phi);
                z = r * (1 - std::cos(phi)) + (s - arc) * std::sin(phi);
            }
            const Eigen::RowVector3d n(-std::sin(phi), 0, std::cos(phi));
            out.points.row(row) = Eigen::RowVector3d(x, y, z) + noise(rng) * n;
            out.normals.row(row) = n;
            ++row;
        }
    }
    return out;
}

/// An open line along y at x, on the surface z = 0 side of the step, vertices `step` apart.
Polyline lineAlongY(double x, double z, double halfLength, double step)
{
    const int m = static_cast<int>(2 * halfLength / step) + 1;
    Polyline line;
    line.points.resize(m, 3);
    for (int i = 0; i < m; ++i) {
        line.points.row(i) << x, -halfLength + i * step, z;
    }
    return line;
}

LineNetwork networkOf(Polyline line)
{
    LineNetwork network;
    network.lines.push_back(std::move(line));
    return network;
}

} // namespace

// Spacing 1, the line found at a scale of 8 spacings 5 spacings off the border of a fillet of
// radius 60 spacings on the flat side: its inner vertices come onto the border (x = 0) within
// half a spacing, noisy or not, from either side; its ends, which sit on junctions or anchors,
// stay.
TEST(LinePlacement, VerticesComeOntoTheFilletBorder)
{
    const double h = 1.0, scale = 8.0, r = 60.0;
    for (double sigma : {0.0, 0.3}) {
        const shapes::Sample s = filletedStep(r, 100.0, h, sigma, 3);
        for (double offset : {-5.0, 5.0}) {
            LineNetwork network = networkOf(lineAlongY(offset, 0.0, 30.0, 1.5));
            const PointMatrix before = network.lines[0].points;
            const int moved = placeOnCurvatureSteps(
                network, {s.points, s.normals, Eigen::VectorXd(), h, scale * h, 0.0});
            const PointMatrix& V = network.lines[0].points;
            EXPECT_GT(moved, V.rows() / 2) << "sigma " << sigma << " offset " << offset;
            for (Eigen::Index i = 1; i + 1 < V.rows(); ++i) {
                // Within a stride (half the strip's length, 3 fit spacings: 12) of an end the
                // move tapers off: such vertices lie between their old place and the border.
                if (std::abs(V(i, 1)) <= 30.0 - 12.0) {
                    EXPECT_NEAR(V(i, 0), 0.0, h)
                        << "vertex " << i << " sigma " << sigma << " offset " << offset;
                } else {
                    EXPECT_LE(std::abs(V(i, 0)), std::abs(offset) + h) << "vertex " << i;
                    EXPECT_LT(std::abs(V(i, 0)), std::abs(offset)) << "vertex " << i;
                }
                EXPECT_DOUBLE_EQ(V(i, 1), before(i, 1)) << "moved across the line only";
            }
            EXPECT_TRUE(V.row(0) == before.row(0));
            EXPECT_TRUE(V.row(V.rows() - 1) == before.row(before.rows() - 1));
        }
    }
}

// The second border, between the fillet and the 45 degree plane, is found the same way.
TEST(LinePlacement, TheFarBorderIsFoundToo)
{
    const double h = 1.0, scale = 8.0, r = 60.0;
    const shapes::Sample s = filletedStep(r, 100.0, h, 0.3, 5);
    const double angle = M_PI / 4;
    // The true border and a point 5 spacings back along the fillet's arc.
    const Eigen::RowVector3d border(r * std::sin(angle), 0, r * (1 - std::cos(angle)));
    const double back = angle - 5.0 / r;
    const Eigen::RowVector3d start(r * std::sin(back), 0, r * (1 - std::cos(back)));
    Polyline line = lineAlongY(start.x(), start.z(), 30.0, 1.5);
    LineNetwork network = networkOf(line);
    placeOnCurvatureSteps(network, {s.points, s.normals, Eigen::VectorXd(), h, scale * h, 0.0});
    const PointMatrix& V = network.lines[0].points;
    for (Eigen::Index i = 1; i + 1 < V.rows(); ++i) {
        if (std::abs(V(i, 1)) > 30.0 - 12.0) {
            continue; // the taper at the ends
        }
        const Eigen::RowVector2d xz(V(i, 0), V(i, 2));
        EXPECT_LT((xz - Eigen::RowVector2d(border.x(), border.z())).norm(), h) << "vertex " << i;
    }
}

// Surfaces without a curvature step under the line leave it where it is: a noisy plane, and a
// sphere (one curvature everywhere).
TEST(LinePlacement, NoStepNoMove)
{
    const double h = 1.0;
    const shapes::Sample plane = [] {
        shapes::Sample p = shapes::plane(60.0, 1.0, 7);
        shapes::addNormalNoise(p, 0.3, 8);
        return p;
    }();
    LineNetwork onPlane = networkOf(lineAlongY(2.0, 0.0, 20.0, 1.5));
    EXPECT_EQ(placeOnCurvatureSteps(
                  onPlane, {plane.points, plane.normals, Eigen::VectorXd(), h, 4 * h, 0.0}),
              0);

    const double R = 30.0;
    const shapes::Sample sphere = shapes::sphere(R, 1.0, 9);
    // A closed circle of latitude 20 degrees above the equator.
    Polyline circle;
    const int m = 120;
    circle.closed = true;
    circle.points.resize(m, 3);
    const double lat = 20.0 * M_PI / 180.0;
    for (int i = 0; i < m; ++i) {
        const double t = 2 * M_PI * i / m;
        circle.points.row(i) << R * std::cos(lat) * std::cos(t), R * std::cos(lat) * std::sin(t),
            R * std::sin(lat);
    }
    LineNetwork onSphere = networkOf(circle);
    EXPECT_EQ(placeOnCurvatureSteps(
                  onSphere, {sphere.points, sphere.normals, Eigen::VectorXd(), h, 4 * h, 0.0}),
              0);
}

// A line 6 spacings off a border, found at a scale of 4: one strip (half width 12, shifts up to
// 4) puts the border on the edge of its range; centred there, the next strip finds it, and the
// inner vertices come onto it (within a spacing, the end tapers aside).
TEST(LinePlacement, ABorderBeyondOneStripIsFoundFromItsEdge)
{
    const double h = 1.0, scale = 4.0;
    for (double sigma : {0.0, 0.3}) {
        const shapes::Sample s = filletedStep(40.0, 60.0, h, sigma, 3);
        for (double offset : {-6.0, 6.0}) {
            LinePlacementOptions options;
            options.maxShift = 1.0 / 3.0; // 4 spacings of a strip 12 wide
            LineNetwork network = networkOf(lineAlongY(offset, 0.0, 20.0, 1.5));
            placeOnCurvatureSteps(
                network, {s.points, s.normals, Eigen::VectorXd(), h, scale * h, 0.0}, options);
            const PointMatrix& V = network.lines[0].points;
            for (Eigen::Index i = 1; i + 1 < V.rows(); ++i) {
                // A stride is half the strip's length: 6.
                if (std::abs(V(i, 1)) <= 20.0 - 6.0) {
                    EXPECT_NEAR(V(i, 0), 0.0, h)
                        << "vertex " << i << " sigma " << sigma << " offset " << offset;
                } else {
                    EXPECT_LT(std::abs(V(i, 0)), std::abs(offset)) << "vertex " << i;
                }
            }
        }
    }
}

// The coarse field's lines zigzag: here by 1.5 spacings across, in runs of two vertices, so
// the chord between a vertex's two neighbours is 45 degrees off the border. Each strip is laid
// along the line's direction over the strip's own length, and the line comes onto the border
// (its zigzag stays: the vertices between fitted ones move as their fitted neighbours do).
TEST(LinePlacement, AZigzagLineIsPlacedAlongItsDirectionOverTheStrip)
{
    const double h = 1.0, scale = 8.0;
    const shapes::Sample s = filletedStep(60.0, 100.0, h, 0.3, 3);
    Polyline line = lineAlongY(-5.0, 0.0, 40.0, 1.5);
    for (Eigen::Index i = 0; i < line.points.rows(); ++i) {
        line.points(i, 0) += (i / 2) % 2 == 0 ? 1.5 : -1.5;
    }
    LineNetwork network = networkOf(line);
    placeOnCurvatureSteps(network, {s.points, s.normals, Eigen::VectorXd(), h, scale * h, 0.0});
    const PointMatrix& V = network.lines[0].points;
    double sum = 0.0;
    int count = 0;
    for (Eigen::Index i = 1; i + 1 < V.rows(); ++i) {
        // Away from the ends' taper (a stride: 12).
        if (std::abs(V(i, 1)) <= 40.0 - 12.0) {
            EXPECT_LT(std::abs(V(i, 0)), 1.5 + 1.5 * h) << "vertex " << i;
            sum += V(i, 0);
            ++count;
        }
    }
    ASSERT_GT(count, 0);
    EXPECT_NEAR(sum / count, 0.0, 0.5 * h) << "the line's mean place: the border";
}

// A threshold low in its valley implies a fillet larger than the one the points show (radius
// 60 spacings against 10 here), and a strip that wide would reach over the whole fillet into
// the plane beyond it, a second hinge. Given the points' curvature, the strip is narrowed to
// 0.4 of the radius the points on the line's high side show, and the border is found.
TEST(LinePlacement, TheStripNarrowsToTheFilletThePointsShow)
{
    const double h = 1.0, scale = 2.0, r = 10.0;
    const shapes::Sample s = filletedStep(r, 60.0, h, 0.3, 3);
    Eigen::VectorXd H(s.points.rows());
    for (Eigen::Index i = 0; i < H.size(); ++i) {
        const double x = s.points(i, 0);
        H[i] = x >= 0.0 && x <= r * std::sin(M_PI / 4) ? 1.0 / (2.0 * r) : 0.0;
    }
    const double threshold = 1.0 / (4.0 * 60.0);
    const auto meanDistance = [&](const Eigen::VectorXd& curvature) {
        LineNetwork network = networkOf(lineAlongY(-2.0, 0.0, 20.0, 1.5));
        placeOnCurvatureSteps(network, {s.points, s.normals, curvature, h, scale * h, threshold});
        const PointMatrix& V = network.lines[0].points;
        double sum = 0.0;
        int count = 0;
        for (Eigen::Index i = 1; i + 1 < V.rows(); ++i) {
            if (std::abs(V(i, 1)) <= 10.0) {
                sum += std::abs(V(i, 0));
                ++count;
            }
        }
        return sum / count;
    };
    const double narrowed = meanDistance(H), wide = meanDistance(Eigen::VectorXd());
    EXPECT_LT(narrowed, h);
    EXPECT_LT(narrowed, wide) << "the strip as wide as the threshold implies reaches past the "
                                 "fillet";
}

// Beyond what the strips reach (one strip: 4 spacings; three: 12), the vertices stay.
TEST(LinePlacement, ABorderBeyondTheLargestShiftIsLeftAlone)
{
    const double h = 1.0, scale = 4.0;
    const shapes::Sample s = filletedStep(40.0, 60.0, h, 0.0, 3);
    for (const auto& [recentres, offset] : {std::pair{0, -6.0}, std::pair{2, -16.0}}) {
        LinePlacementOptions options;
        options.maxShift = 1.0 / 3.0;
        options.recentres = recentres;
        LineNetwork network = networkOf(lineAlongY(offset, 0.0, 20.0, 1.5));
        const PointMatrix before = network.lines[0].points;
        EXPECT_EQ(placeOnCurvatureSteps(network,
                                        {s.points, s.normals, Eigen::VectorXd(), h, scale * h, 0.0},
                                        options),
                  0)
            << recentres << " re-centred strips, the border " << -offset << " off";
        EXPECT_TRUE(network.lines[0].points == before);
    }
}

TEST(LinePlacement, BadInputIsRefused)
{
    const shapes::Sample s = filletedStep(40.0, 20.0, 1.0, 0.0, 3);
    LineNetwork network = networkOf(lineAlongY(0.0, 0.0, 5.0, 1.5));
    EXPECT_THROW(placeOnCurvatureSteps(
                     network, {s.points, s.normals.topRows(3), Eigen::VectorXd(), 1.0, 4.0, 0.0}),
                 std::invalid_argument);
    EXPECT_THROW(placeOnCurvatureSteps(
                     network, {s.points, s.normals, Eigen::VectorXd::Ones(3), 1.0, 4.0, 0.0}),
                 std::invalid_argument);
    EXPECT_THROW(
        placeOnCurvatureSteps(network, {s.points, s.normals, Eigen::VectorXd(), 0.0, 4.0, 0.0}),
        std::invalid_argument);
    EXPECT_THROW(
        placeOnCurvatureSteps(network, {s.points, s.normals, Eigen::VectorXd(), 1.0, 0.5, 0.0}),
        std::invalid_argument);
    EXPECT_THROW(
        placeOnCurvatureSteps(network, {s.points, s.normals, Eigen::VectorXd(), 1.0, NAN, 0.0}),
        std::invalid_argument);
    for (auto set : {+[](LinePlacementOptions& o) { o.halfWidth = 0; },
                     +[](LinePlacementOptions& o) { o.halfLength = -1; },
                     +[](LinePlacementOptions& o) { o.maxShift = INFINITY; },
                     +[](LinePlacementOptions& o) { o.step = 0; },
                     +[](LinePlacementOptions& o) { o.minEvidence = -1; },
                     +[](LinePlacementOptions& o) { o.minPointsPerSide = 0; },
                     +[](LinePlacementOptions& o) { o.medianHalfWindow = -1; },
                     +[](LinePlacementOptions& o) { o.recentres = -1; }}) {
        LinePlacementOptions o;
        set(o);
        EXPECT_THROW(placeOnCurvatureSteps(
                         network, {s.points, s.normals, Eigen::VectorXd(), 1.0, 4.0, 0.0}, o),
                     std::invalid_argument);
    }
    // Nothing to place on: no points, no lines.
    EXPECT_EQ(placeOnCurvatureSteps(network, {PointMatrix(0, 3), NormalMatrix(0, 3),
                                              Eigen::VectorXd(), 1.0, 4.0, 0.0}),
              0);
    LineNetwork none;
    EXPECT_EQ(placeOnCurvatureSteps(none, {s.points, s.normals, Eigen::VectorXd(), 1.0, 4.0, 0.0}),
              0);
}
