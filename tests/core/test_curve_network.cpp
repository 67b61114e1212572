// SPDX-License-Identifier: LGPL-2.1-or-later
// The fitted network of shapes whose edges are known: a box's twelve segments on eight shared
// corners (also under noise), a closed cylinder's two rim circles, a rounded cube's fillet
// borders as a few smooth curves.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "FeatureLines/Extraction.h"
#include "FeatureLines/curves/CurveFit.h"
#include "FeatureLines/curves/CurveNetwork.h"
#include "SampledShapes.h"

using namespace featurelines;

namespace {

constexpr double pi = 3.14159265358979323846;

std::vector<int> vertexDegrees(const CurveNetwork& net)
{
    std::vector<int> degree(static_cast<size_t>(net.vertices.rows()), 0);
    for (const NetworkEdge& e : net.edges) {
        ++degree[static_cast<size_t>(e.startVertex)];
        ++degree[static_cast<size_t>(e.endVertex)];
    }
    return degree;
}

/// Every edge's curve starts and ends exactly on its vertices.
void expectCurvesOnVertices(const CurveNetwork& net)
{
    for (const NetworkEdge& e : net.edges) {
        EXPECT_EQ(e.curve.start, Eigen::Vector3d(net.vertices.row(e.startVertex).transpose()));
        EXPECT_EQ(e.curve.end, Eigen::Vector3d(net.vertices.row(e.endVertex).transpose()));
    }
}

/// The box's network: 12 segments of the edge's length, 8 vertices of degree 3 at the corners.
void expectBoxNetwork(const CurveNetwork& net, double edge, double spacing, double cornerTolerance)
{
    ASSERT_EQ(net.edges.size(), 12u);
    ASSERT_EQ(net.vertices.rows(), 8);
    for (int d : vertexDegrees(net)) {
        EXPECT_EQ(d, 3);
    }
    for (Eigen::Index v = 0; v < 8; ++v) {
        const Eigen::Vector3d corner = net.vertices.row(v).cwiseSign().transpose() * edge / 2;
        EXPECT_LE((net.vertices.row(v).transpose() - corner).norm(), cornerTolerance * spacing);
    }
    for (const NetworkEdge& e : net.edges) {
        EXPECT_EQ(e.curve.kind, CurveKind::Segment);
        EXPECT_NE(e.startVertex, e.endVertex);
        EXPECT_NEAR(curveLength(e.curve), edge, 2 * cornerTolerance * spacing);
    }
    expectCurvesOnVertices(net);
}

} // namespace

TEST(CurveNetwork, ABoxGivesTwelveSegmentsOnEightSharedCorners)
{
    const double edge = 20.0, h = 0.5;
    const shapes::Sample cube = shapes::cube(edge, h, 11);
    const ExtractionResult r = extractFeatureLines(cube.points);
    const CurveNetwork net = fitCurveNetwork(r);
    expectBoxNetwork(net, edge, r.spacing, 1.5);
}

TEST(CurveNetwork, ANoisyBoxStillGivesTwelveSegments)
{
    const double edge = 20.0, h = 0.5;
    shapes::Sample cube = shapes::cube(edge, h, 12);
    shapes::addNormalNoise(cube, 0.2 * h, 13);
    const ExtractionResult r = extractFeatureLines(cube.points);
    const CurveNetwork net = fitCurveNetwork(r);
    expectBoxNetwork(net, edge, r.spacing, 2.0);
}

namespace {

/// A closed cylinder: the open cylinder and two discs, jittered grids of spacing h.
PointMatrix closedCylinder(double radius, double height, double h, unsigned seed)
{
    const shapes::Sample side = shapes::cylinder(radius, height, h, seed);
    std::mt19937 rng(seed + 1);
    std::uniform_real_distribution<double> jitter(-0.2 * h, 0.2 * h);
    std::vector<Eigen::RowVector3d> caps;
    for (double x = -radius + h / 2; x < radius; x += h) {
        for (double y = -radius + h / 2; y < radius; y += h) {
            const double px = x + jitter(rng), py = y + jitter(rng);
            if (std::hypot(px, py) < radius - 0.25 * h) {
                caps.emplace_back(px, py, height / 2);
                caps.emplace_back(px, py, -height / 2);
            }
        }
    }
    PointMatrix P(side.size() + static_cast<Eigen::Index>(caps.size()), 3);
    P.topRows(side.size()) = side.points;
    for (size_t i = 0; i < caps.size(); ++i) {
        P.row(side.size() + static_cast<Eigen::Index>(i)) = caps[i];
    }
    return P;
}

} // namespace

TEST(CurveNetwork, AClosedCylindersRimsAreCirclesOfItsRadiusAboutItsAxis)
{
    const double radius = 10.0, height = 16.0, h = 0.5;
    const ExtractionResult r = extractFeatureLines(closedCylinder(radius, height, h, 21));
    const CurveNetwork net = fitCurveNetwork(r);
    ASSERT_EQ(net.edges.size(), 2u);
    std::vector<double> heights;
    for (const NetworkEdge& e : net.edges) {
        ASSERT_EQ(e.curve.kind, CurveKind::Circle);
        // The fit: within a tenth of a spacing of the rim line's own mean radius. The line:
        // the crease placement's planes, fitted to the curved side over a few spacings, put
        // it about 0.9 / radius inside the rim (0.23 spacing at this radius of 24 spacings).
        double lineRadius = 0.0;
        for (Eigen::Index i = 0; i < e.points.rows(); ++i) {
            lineRadius += std::hypot(e.points(i, 0), e.points(i, 1)) / double(e.points.rows());
        }
        EXPECT_NEAR(e.curve.radius, lineRadius, 0.1 * r.spacing);
        EXPECT_NEAR(e.curve.radius, radius, 0.3 * r.spacing);
        EXPECT_NEAR(std::abs(e.curve.axis.z()), 1.0, 1e-3);
        EXPECT_NEAR(std::hypot(e.curve.centre.x(), e.curve.centre.y()), 0.0, 0.1 * r.spacing);
        heights.push_back(e.curve.centre.z());
        EXPECT_EQ(e.startVertex, e.endVertex);
    }
    std::sort(heights.begin(), heights.end());
    EXPECT_NEAR(heights[0], -height / 2, 0.5 * r.spacing);
    EXPECT_NEAR(heights[1], height / 2, 0.5 * r.spacing);
    expectCurvesOnVertices(net);
}

TEST(CurveNetwork, ARoundedCubesFilletBordersAreAFewSmoothCurves)
{
    const double edge = 40.0, radius = 6.0, h = 0.5;
    const shapes::Sample s = shapes::roundedCube(edge, radius, h, 5);
    const ExtractionResult r = extractFeatureLines(s.points);
    const CurveNetwork net = fitCurveNetwork(r);
    ASSERT_EQ(r.lines.size(), 14u) << "8 corner loops and 6 face loops";
    // Each loop is one closed curve, not a polygon of its hundred vertices.
    ASSERT_EQ(net.edges.size(), 14u);
    for (const NetworkEdge& e : net.edges) {
        EXPECT_EQ(e.startVertex, e.endVertex);
        EXPECT_NE(e.curve.kind, CurveKind::Segment);
        if (e.curve.kind == CurveKind::BSpline) {
            EXPECT_TRUE(e.curve.periodic);
            EXPECT_LE(e.curve.poles.rows(), 40) << e.points.rows() << " points";
        }
    }
    expectCurvesOnVertices(net);
}
