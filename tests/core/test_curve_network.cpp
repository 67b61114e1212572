// SPDX-License-Identifier: LGPL-2.1-or-later
// The fitted network of shapes whose edges are known: a box's twelve segments on eight shared
// corners (also under noise), a closed cylinder's two rim circles, a rounded cube's fillet
// borders as one smooth curve each (by default) or cut at their corners (cornerAngle).
#include <gtest/gtest.h>

#include <algorithm>
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

/// Every edge's curve stays near the points it was fitted to, all along (a curve can hold
/// its points and still swing out between them): each sample within `reach` of them.
void expectCurvesStayOnTheirPoints(const CurveNetwork& net, double reach)
{
    for (const NetworkEdge& e : net.edges) {
        const PointMatrix samples = sampleCurve(e.curve, 0.25 * reach);
        for (Eigen::Index i = 0; i < samples.rows(); ++i) {
            const double nearest =
                (e.points.rowwise() - samples.row(i)).rowwise().norm().minCoeff();
            ASSERT_LE(nearest, reach) << curveKindName(e.curve.kind) << " edge of line " << e.line
                                      << " leaves its points at sample " << i;
        }
    }
}

/// Every loop runs end to start through shared vertices and closes.
void expectLoopsChain(const CurveNetwork& net, const PatchBorder& b)
{
    for (const std::vector<LoopEdge>& loop : b.loops) {
        ASSERT_FALSE(loop.empty());
        for (size_t k = 0; k < loop.size(); ++k) {
            const NetworkEdge& a = net.edges[static_cast<size_t>(loop[k].edge)];
            const NetworkEdge& c = net.edges[static_cast<size_t>(loop[(k + 1) % loop.size()].edge)];
            const int aEnd = loop[k].reversed ? a.startVertex : a.endVertex;
            const int cStart = loop[(k + 1) % loop.size()].reversed ? c.endVertex : c.startVertex;
            EXPECT_EQ(aEnd, cStart) << "patch " << b.patch << " loop edge " << k;
        }
    }
}

} // namespace

TEST(CurveNetwork, ABoxGivesTwelveSegmentsOnEightSharedCornersAndSixClosedFaceBorders)
{
    const double edge = 20.0, h = 0.5;
    const shapes::Sample cube = shapes::cube(edge, h, 11);
    const ExtractionResult r = extractFeatureLines(cube.points);
    const CurveNetwork net = fitCurveNetwork(r);
    expectBoxNetwork(net, edge, r.spacing, 1.5);
    const std::vector<PatchBorder> borders = patchBorders(net, r, cube.points);
    ASSERT_EQ(borders.size(), 6u);
    std::map<int, int> patchesOfEdge;
    for (const PatchBorder& b : borders) {
        EXPECT_TRUE(b.closed()) << "patch " << b.patch;
        ASSERT_EQ(b.loops.size(), 1u);
        EXPECT_EQ(b.loops[0].size(), 4u);
        expectLoopsChain(net, b);
        // The four edges of the face the patch is: its points' face is the one whose axis
        // coordinate every edge shares.
        int face = -1;
        for (size_t i = 0; i < cube.part.size(); ++i) {
            if (r.patch[i] == b.patch) {
                face = cube.part[i];
                break;
            }
        }
        const int axis = face / 2;
        const double side = face % 2 ? -edge / 2 : edge / 2;
        for (const LoopEdge& le : b.loops[0]) {
            const NetworkEdge& e = net.edges[static_cast<size_t>(le.edge)];
            EXPECT_NEAR(e.curve.start[axis], side, 1.5 * r.spacing);
            EXPECT_NEAR(e.curve.end[axis], side, 1.5 * r.spacing);
            ++patchesOfEdge[le.edge];
        }
    }
    ASSERT_EQ(patchesOfEdge.size(), 12u);
    for (const auto& [e, n] : patchesOfEdge) {
        EXPECT_EQ(n, 2) << "every edge borders two faces";
    }
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
    const PointMatrix P = closedCylinder(radius, height, h, 21);
    const ExtractionResult r = extractFeatureLines(P);
    const CurveNetwork net = fitCurveNetwork(r);
    ASSERT_EQ(net.edges.size(), 2u);
    // Three patches: the side, bordered by both rims (the longer first; equal here), and
    // each cap by its own rim.
    const std::vector<PatchBorder> borders = patchBorders(net, r, P);
    ASSERT_EQ(borders.size(), 3u);
    int loops = 0;
    for (const PatchBorder& b : borders) {
        EXPECT_TRUE(b.closed());
        loops += static_cast<int>(b.loops.size());
        expectLoopsChain(net, b);
    }
    EXPECT_EQ(loops, 4);
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

TEST(CurveNetwork, ARoundedCubesFilletBordersAreCutAtTheirCorners)
{
    // A cube of edge 40 whose edges and corners are rounded with radius 6: each flat face's
    // border is a square of side 28 (the fillets' tangent lines), each corner blend's a
    // spherical triangle of three quarter circles; they touch at the squares' corners.
    const double edge = 40.0, radius = 6.0, h = 0.5;
    const shapes::Sample s = shapes::roundedCube(edge, radius, h, 5);
    const ExtractionResult r = extractFeatureLines(s.points);
    CurveFitOptions options;
    options.cornerAngle = 30.0;
    const CurveNetwork net = fitCurveNetwork(r, options);
    ASSERT_EQ(r.lines.size(), 14u) << "8 corner loops and 6 face loops";
    // Each face loop is four edges meeting at its corners, each corner loop three: not one
    // closed curve rounded over them.
    std::map<int, int> edgesOfLine;
    for (const NetworkEdge& e : net.edges) {
        ++edgesOfLine[e.line];
        EXPECT_NE(e.startVertex, e.endVertex);
    }
    const double inner = edge / 2 - radius;
    for (size_t l = 0; l < r.lines.size(); ++l) {
        // A face loop lies in its face's plane, |coordinate| = edge / 2 for one coordinate.
        const bool face =
            (r.lines[l].points.cwiseAbs().colwise().minCoeff().array() > edge / 2 - h).any();
        EXPECT_EQ(edgesOfLine[static_cast<int>(l)], face ? 4 : 3) << "line " << l;
    }
    // The face loops' vertices lie at the squares' corners, where two coordinates are the
    // fillets' inset and the third the face's: within 3.5 spacings, as the smooth lines round
    // these corners (where a face, two fillets and a corner blend meet) off by up to three.
    for (const NetworkEdge& e : net.edges) {
        const bool face = (e.points.cwiseAbs().colwise().minCoeff().array() > edge / 2 - h).any();
        if (!face) {
            continue;
        }
        Eigen::Vector3d v = net.vertices.row(e.startVertex).cwiseAbs().transpose();
        std::sort(v.data(), v.data() + 3);
        EXPECT_LE((v - Eigen::Vector3d(inner, inner, edge / 2)).norm(), 3.5 * h)
            << net.vertices.row(e.startVertex);
    }
    expectCurvesOnVertices(net);
    expectCurvesStayOnTheirPoints(net, 3 * h);
    // Every patch closed: the faces and corners by one loop each, the fillets between them
    // by all fourteen.
    const std::vector<PatchBorder> borders = patchBorders(net, r, s.points);
    int loops = 0;
    for (const PatchBorder& b : borders) {
        EXPECT_TRUE(b.closed()) << "patch " << b.patch;
        loops += static_cast<int>(b.loops.size());
        expectLoopsChain(net, b);
    }
    EXPECT_EQ(loops, 28);
}

TEST(CurveNetwork, ByDefaultARoundedCubesBordersAreOneSmoothCurveEach)
{
    const double edge = 40.0, radius = 6.0, h = 0.5;
    const shapes::Sample s = shapes::roundedCube(edge, radius, h, 5);
    const ExtractionResult r = extractFeatureLines(s.points);
    const CurveNetwork net = fitCurveNetwork(r);
    ASSERT_EQ(r.lines.size(), 14u);
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
    expectCurvesStayOnTheirPoints(net, 3 * h);
}

namespace {

/// An open line of n points along f(t) for t in [a, b], free ends.
template <typename F> FeatureLine openLine(F f, double a, double b, int n)
{
    FeatureLine l;
    l.type = LineType::Smooth;
    l.points.resize(n, 3);
    for (int i = 0; i < n; ++i) {
        l.points.row(i) = f(a + (b - a) * i / (n - 1)).transpose();
    }
    return l;
}

} // namespace

TEST(CurveNetwork, TwoLinesMeetingEndToEndShareAVertexAndRunOnWithOneTangent)
{
    // A helix cut in two where the halves meet: one vertex of degree 2 between them, and the
    // two B-splines leave it along one tangent.
    const auto helix = [](double t) {
        return Eigen::Vector3d(10 * std::cos(t), 10 * std::sin(t), 3 * t);
    };
    ExtractionResult r;
    r.spacing = 1.0;
    r.junctions.resize(0, 3);
    r.lines.push_back(openLine(helix, 0.0, 2.0, 40));
    r.lines.push_back(openLine(helix, 2.0, 4.0, 40));
    const CurveNetwork net = fitCurveNetwork(r);
    ASSERT_EQ(net.edges.size(), 2u);
    ASSERT_EQ(net.vertices.rows(), 3);
    const NetworkEdge& a = net.edges[0];
    const NetworkEdge& b = net.edges[1];
    ASSERT_EQ(a.endVertex, b.startVertex) << "one shared vertex";
    ASSERT_EQ(a.curve.kind, CurveKind::BSpline);
    ASSERT_EQ(b.curve.kind, CurveKind::BSpline);
    EXPECT_GT(curveTangent(a.curve, 1.0).dot(curveTangent(b.curve, 0.0)), 1.0 - 1e-8);
    EXPECT_LT((net.vertices.row(a.endVertex).transpose() - helix(2.0)).norm(), 1e-9);
    expectCurvesOnVertices(net);
}

TEST(CurveNetwork, AFaceBordersCornersAreCutAndItsTightRoundsRunOnWithOneTangent)
{
    // One closed line (no junction): a square of side 40 spacings whose corners are rounded
    // with radius 6 on two of them (a turn through a right angle within about one corner
    // window) and sharp on the other two. Cut at corners, it gives an edge between every two
    // corners; at the sharp corners the edges turn by the right angle, at the tight rounds,
    // cut at their middle, they leave the vertex along one tangent.
    const double side = 40, r = 6;
    std::vector<Eigen::Vector3d> points;
    const auto straight = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
        const int n = static_cast<int>(std::round((b - a).norm()));
        for (int i = 0; i < n; ++i) {
            points.push_back(a + (b - a) * i / n);
        }
    };
    const auto round = [&](const Eigen::Vector3d& centre, double from) {
        const int n = static_cast<int>(std::round(pi / 2 * r));
        for (int i = 0; i < n; ++i) {
            const double t = from + pi / 2 * i / n;
            points.push_back(centre + r * Eigen::Vector3d(std::cos(t), std::sin(t), 0));
        }
    };
    // Counter-clockwise from (0, 0): sharp corner, side, round about (side - r, r), side,
    // sharp corner (side, side)... as (0,0) sharp, (side,0) round, (side,side) sharp,
    // (0,side) round.
    straight({0, 0, 0}, {side - r, 0, 0});
    round({side - r, r, 0}, -pi / 2);
    straight({side, r, 0}, {side, side, 0});
    straight({side, side, 0}, {r, side, 0});
    round({r, side - r, 0}, pi / 2);
    straight({0, side - r, 0}, {0, 0, 0});
    ExtractionResult result;
    result.spacing = 1.0;
    result.junctions.resize(0, 3);
    FeatureLine line;
    line.type = LineType::Smooth;
    line.closed = true;
    line.points.resize(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i) {
        line.points.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
    }
    result.lines.push_back(line);
    CurveFitOptions options;
    options.cornerAngle = 30;
    const CurveNetwork net = fitCurveNetwork(result, options);
    ASSERT_EQ(net.edges.size(), 4u);
    ASSERT_EQ(net.vertices.rows(), 4);
    expectCurvesOnVertices(net);
    int sharp = 0, smooth = 0;
    for (const NetworkEdge& e : net.edges) {
        EXPECT_EQ(e.run, net.edges[0].run) << "one stretch of one line";
        const NetworkEdge& next = net.edges[(&e - net.edges.data() + 1) % net.edges.size()];
        ASSERT_EQ(e.endVertex, next.startVertex);
        const double turn =
            std::acos(std::clamp(curveTangent(e.curve, 1.0).dot(curveTangent(next.curve, 0.0)),
                                 -1.0, 1.0)) *
            180 / pi;
        const Eigen::Vector3d v = net.vertices.row(e.endVertex).transpose();
        if ((v - Eigen::Vector3d(0, 0, 0)).norm() < 1 ||
            (v - Eigen::Vector3d(side, side, 0)).norm() < 1) {
            EXPECT_NEAR(turn, 90, 5);
            ++sharp;
        } else {
            EXPECT_LT(turn, 0.1) << v.transpose();
            ++smooth;
        }
    }
    EXPECT_EQ(sharp, 2);
    EXPECT_EQ(smooth, 2);
}

TEST(CurveNetwork, ALineEndingOnAnotherLinesInteriorCutsItThere)
{
    // A smooth line ends half a spacing from the middle of a straight sharp line, without a
    // junction (as fillet borders end on sharp edges): three edges meet at one new vertex on
    // the sharp line.
    ExtractionResult r;
    r.spacing = 1.0;
    r.junctions.resize(0, 3);
    FeatureLine sharp =
        openLine([](double t) { return Eigen::Vector3d(t, 0, 0); }, -20.0, 20.0, 41);
    sharp.type = LineType::Sharp;
    r.lines.push_back(sharp);
    r.lines.push_back(openLine([](double t) { return Eigen::Vector3d(0.3, t, 0); }, 0.5, 20.0, 20));
    const CurveNetwork net = fitCurveNetwork(r);
    ASSERT_EQ(net.edges.size(), 3u);
    const std::vector<int> degree = vertexDegrees(net);
    int meeting = -1;
    for (size_t v = 0; v < degree.size(); ++v) {
        if (degree[v] == 3) {
            meeting = static_cast<int>(v);
        }
    }
    ASSERT_GE(meeting, 0) << "a vertex where the three edges meet";
    EXPECT_LT((net.vertices.row(meeting) - Eigen::RowVector3d(0.3, 0, 0)).norm(), 1e-9)
        << "on the sharp line, where the smooth line's end projects";
    for (const NetworkEdge& e : net.edges) {
        EXPECT_EQ(e.curve.kind, CurveKind::Segment);
    }
    expectCurvesOnVertices(net);
}

TEST(CurveNetwork, ALineFoldedOntoItsOwnEndIsNoCurveAndNoFailure)
{
    // A three-vertex line from a vertex back to the same place (the sharp stage can leave such
    // a stub where a junction's lines were joined): it is left out, the straight line kept.
    ExtractionResult r;
    r.spacing = 1.0;
    r.junctions.resize(0, 3);
    r.lines.push_back(openLine([](double t) { return Eigen::Vector3d(t, 0, 0); }, 0.0, 20.0, 21));
    FeatureLine stub;
    stub.type = LineType::Sharp;
    stub.points.resize(3, 3);
    stub.points << 20, 0, 0, 20.4, 0.3, 0, 20, 0, 0;
    r.lines.push_back(stub);
    const CurveNetwork net = fitCurveNetwork(r);
    ASSERT_EQ(net.edges.size(), 1u);
    EXPECT_EQ(net.edges[0].curve.kind, CurveKind::Segment);
}
