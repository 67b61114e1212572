// SPDX-License-Identifier: LGPL-2.1-or-later
// Sharp edges on shapes whose edges are known: a cube has twelve, meeting three by three at
// eight corners, with or without noise; an open box has eight ending on its rim; a plane, a
// sphere, an open tube and a cube rounded with fillets of six spacings have none, nor one
// with fillets of eight spacings under noise of 0.5 spacing; a chamfered cube has 48 (half of
// them 35 degree creases) in one closed network, with or without noise; a ridge of 35
// degrees is sharp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <set>
#include <stdexcept>

#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/sharp/SharpEdges.h"
#include "SampledShapes.h"

using namespace featurelines;

namespace {

struct Segment
{
    Eigen::Vector3d a, b;

    double distance(const Eigen::Vector3d& p) const
    {
        const Eigen::Vector3d d = b - a;
        const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
        return (a + t * d - p).norm();
    }
};

/// The twelve edges of the cube [-h, h]^3.
std::vector<Segment> cubeEdges(double h)
{
    std::vector<Segment> edges;
    for (int axis = 0; axis < 3; ++axis) {
        for (double s : {-h, h}) {
            for (double t : {-h, h}) {
                Eigen::Vector3d a, b;
                a[axis] = -h;
                b[axis] = h;
                a[(axis + 1) % 3] = b[(axis + 1) % 3] = s;
                a[(axis + 2) % 3] = b[(axis + 2) % 3] = t;
                edges.push_back({a, b});
            }
        }
    }
    return edges;
}

double distanceToPolyline(const Eigen::Vector3d& p, const Polyline& line)
{
    double best = std::numeric_limits<double>::infinity();
    const Eigen::Index m = line.points.rows();
    const Eigen::Index segments = line.closed ? m : m - 1;
    for (Eigen::Index i = 0; i < segments; ++i) {
        best = std::min(
            best, Segment{line.points.row(i).transpose(), line.points.row((i + 1) % m).transpose()}
                      .distance(p));
    }
    return m == 1 ? (line.points.row(0).transpose() - p).norm() : best;
}

struct SharpRun
{
    SharpEdges sharp;
    double spacing;
};

SharpRun extract(const shapes::Sample& s, const SharpEdgeOptions& options = {})
{
    const Neighbourhoods N = nearestNeighbours(s.points);
    const double spacing = meanSpacing(N);
    const NormalEstimate normals = pcaNormals(s.points, N);
    return {extractSharpEdges(s.points, normals.normals, N, spacing, options), spacing};
}

std::vector<const Polyline*> linesLabelled(const SharpEdges& r, int label)
{
    std::vector<const Polyline*> out;
    for (const Polyline& line : r.network.lines) {
        if (line.label == label) {
            out.push_back(&line);
        }
    }
    return out;
}

/// How many lines end on each junction.
std::vector<int> junctionDegrees(const LineNetwork& network)
{
    std::vector<int> degree(network.junctions.rows(), 0);
    for (const Polyline& line : network.lines) {
        for (int j : {line.startJunction, line.endJunction}) {
            if (j >= 0) {
                ++degree[j];
            }
        }
    }
    return degree;
}

/// Number of pieces the network falls into (lines joined through shared junctions).
int connectedPieces(const LineNetwork& network)
{
    const int lines = static_cast<int>(network.lines.size());
    std::vector<int> parent(lines + network.junctions.rows());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int a) {
        while (parent[a] != a) {
            a = parent[a] = parent[parent[a]];
        }
        return a;
    };
    for (int l = 0; l < lines; ++l) {
        for (int j : {network.lines[l].startJunction, network.lines[l].endJunction}) {
            if (j >= 0) {
                parent[find(l)] = find(lines + j);
            }
        }
    }
    std::set<int> pieces;
    for (int l = 0; l < lines; ++l) {
        pieces.insert(find(l));
    }
    return static_cast<int>(pieces.size());
}

/// The cube's answer: twelve lines, one closed network with eight corners of degree three,
/// every line on an edge (within `tolerance` spacings) and every edge covered.
void expectCubeEdges(const SharpRun& r, double edge, double tolerance)
{
    const LineNetwork& network = r.sharp.network;
    const auto sharp = linesLabelled(r.sharp, sharpLineLabel);
    EXPECT_EQ(sharp.size(), 12u);
    EXPECT_EQ(sharp.size(), network.lines.size()) << "a closed cube has no boundary";
    ASSERT_EQ(network.junctions.rows(), 8);
    for (int degree : junctionDegrees(network)) {
        EXPECT_EQ(degree, 3);
    }
    for (const Polyline& line : network.lines) {
        EXPECT_FALSE(line.closed);
        EXPECT_GE(line.startJunction, 0) << "a free end";
        EXPECT_GE(line.endJunction, 0) << "a free end";
    }
    EXPECT_EQ(connectedPieces(network), 1);
    const double h = edge / 2;
    for (int j = 0; j < 8; ++j) {
        EXPECT_NEAR(network.junctions.row(j).cwiseAbs().minCoeff(), h, tolerance * r.spacing)
            << "junction " << j << " is not at a corner";
    }
    const std::vector<Segment> edges = cubeEdges(h);
    for (const Polyline& line : network.lines) {
        for (Eigen::Index i = 0; i < line.points.rows(); ++i) {
            double d = std::numeric_limits<double>::infinity();
            for (const Segment& e : edges) {
                d = std::min(d, e.distance(line.points.row(i).transpose()));
            }
            EXPECT_LT(d, tolerance * r.spacing) << "vertex " << i << " off every edge";
        }
    }
    // Every edge covered over at least 90 % of its length by one line.
    for (const Segment& e : edges) {
        double best = 0.0;
        for (const Polyline& line : network.lines) {
            int covered = 0;
            const int samples = 100;
            for (int s = 0; s <= samples; ++s) {
                const Eigen::Vector3d p = e.a + (e.b - e.a) * (static_cast<double>(s) / samples);
                covered += distanceToPolyline(p, line) < tolerance * r.spacing ? 1 : 0;
            }
            best = std::max(best, covered / static_cast<double>(samples + 1));
        }
        EXPECT_GE(best, 0.9);
    }
}

} // namespace

TEST(SharpEdges, CubeHasTwelveEdgesOnTheCreasesMeetingAtEightCorners)
{
    const double edge = 40.0;
    for (unsigned seed : {1u, 2u}) {
        const SharpRun r = extract(shapes::cube(edge, 1.0, seed));
        SCOPED_TRACE("seed " + std::to_string(seed));
        // Crease placement: the lines lie on the intersection of the fitted faces, within a
        // spacing of the true edge although the candidate band is three spacings wide.
        expectCubeEdges(r, edge, 1.0);
        for (const Polyline& line : r.sharp.network.lines) {
            for (Eigen::Index i = 1; i < line.points.rows(); ++i) {
                const double step = (line.points.row(i) - line.points.row(i - 1)).norm();
                EXPECT_NEAR(step, r.spacing, 0.5 * r.spacing) << "resampled at one spacing";
            }
        }
    }
}

TEST(SharpEdges, NoisyCubeStillHasTwelveEdgesInOneNetwork)
{
    const double edge = 40.0;
    for (double sigma : {0.2, 0.3}) {
        shapes::Sample cube = shapes::cube(edge, 1.0, 3);
        const Neighbourhoods N = nearestNeighbours(cube.points);
        const double spacing = meanSpacing(N);
        shapes::addNormalNoise(cube, sigma * spacing, 4);
        const SharpRun r = extract(cube);
        SCOPED_TRACE("sigma " + std::to_string(sigma));
        expectCubeEdges(r, edge, 2.0);
    }
}

TEST(SharpEdges, SmoothSurfacesHaveNone)
{
    EXPECT_TRUE(extract(shapes::sphere(15.0, 1.0, 1)).sharp.network.lines.empty());
    const SharpRun plane = extract(shapes::plane(30.0, 1.0, 2));
    EXPECT_TRUE(linesLabelled(plane.sharp, sharpLineLabel).empty());
}

TEST(SharpEdges, FilletsOfSixSpacingsAreNotSharp)
{
    // Adjacent normals differ by about spacing / r = 10 degrees there, and the points follow
    // a parabola, not a kink.
    for (double radius : {6.0, 8.0}) {
        const shapes::Sample rounded = shapes::roundedCube(40.0, radius, 1.0, 5);
        const SharpRun r = extract(rounded);
        ASSERT_GE(radius / r.spacing, 6.0);
        EXPECT_TRUE(r.sharp.network.lines.empty()) << "radius " << radius;
    }
}

TEST(SharpEdges, FilletsOfEightSpacingsStaySmoothUnderHeavyNoise)
{
    // Noise of 0.5 spacing spreads the normals of a third of a plane's points beyond the
    // segmentation's limit (clamped at growAngle); joins across gaps may only run along points
    // that spread beyond what noise gives (noiseSpreadTail), so the few candidates noise
    // leaves on the fillets are not joined into lines.
    for (unsigned seed : {1u, 2u, 3u}) {
        shapes::Sample rounded = shapes::roundedCube(60.0, 8.0, 1.0, seed);
        const double spacing = meanSpacing(nearestNeighbours(rounded.points));
        ASSERT_GE(8.0 / spacing, 8.0);
        shapes::addNormalNoise(rounded, 0.5 * spacing, seed + 40);
        EXPECT_TRUE(extract(rounded).sharp.network.lines.empty()) << "seed " << seed;
    }
}

TEST(SharpEdges, OpenTubeHasNoSharpEdgeAndTwoBoundaryLoops)
{
    const double radius = 10.0, height = 30.0;
    const SharpRun r = extract(shapes::cylinder(radius, height, 1.0, 3));
    EXPECT_TRUE(linesLabelled(r.sharp, sharpLineLabel).empty());
    const auto rims = linesLabelled(r.sharp, boundaryLineLabel);
    ASSERT_EQ(rims.size(), 2u);
    double zSum = 0.0;
    for (const Polyline* rim : rims) {
        EXPECT_TRUE(rim->closed);
        const double z = rim->points.col(2).mean();
        EXPECT_NEAR(std::abs(z), height / 2, 1.5 * r.spacing);
        zSum += z;
        for (Eigen::Index i = 0; i < rim->points.rows(); ++i) {
            EXPECT_NEAR(rim->points.row(i).head<2>().norm(), radius, 1.5 * r.spacing);
        }
    }
    EXPECT_NEAR(zSum, 0.0, 3.0 * r.spacing) << "one loop at each end";
}

TEST(SharpEdges, OpenBoxEdgesEndOnItsRim)
{
    // A cube without its top face: four vertical and four bottom edges are sharp, the top rim
    // is the boundary, and the vertical edges end on it (the boundary is in the graph).
    const double edge = 40.0, h = edge / 2;
    const shapes::Sample cube = shapes::cube(edge, 1.0, 6);
    shapes::Sample box;
    std::vector<Eigen::Index> keep;
    for (Eigen::Index i = 0; i < cube.size(); ++i) {
        if (cube.part[i] != 4) {
            keep.push_back(i);
        }
    }
    box.points.resize(static_cast<Eigen::Index>(keep.size()), 3);
    for (size_t i = 0; i < keep.size(); ++i) {
        box.points.row(i) = cube.points.row(keep[i]);
    }
    const SharpRun r = extract(box);
    const auto sharp = linesLabelled(r.sharp, sharpLineLabel);
    EXPECT_EQ(sharp.size(), 8u);
    const auto rim = linesLabelled(r.sharp, boundaryLineLabel);
    EXPECT_GE(rim.size(), 1u);
    for (const Polyline* line : rim) {
        for (Eigen::Index i = 0; i < line->points.rows(); ++i) {
            EXPECT_NEAR(line->points(i, 2), h, 2.0 * r.spacing) << "the rim is at the top";
        }
    }
    for (const Polyline& line : r.sharp.network.lines) {
        EXPECT_TRUE(line.closed || (line.startJunction >= 0 && line.endJunction >= 0))
            << "every line closes or ends on another";
    }
    EXPECT_EQ(connectedPieces(r.sharp.network), 1);
    // Four junctions on the rim (vertical edges meet it) and four at the bottom corners.
    int onRim = 0;
    for (Eigen::Index j = 0; j < r.sharp.network.junctions.rows(); ++j) {
        onRim += std::abs(r.sharp.network.junctions(j, 2) - h) < 2.0 * r.spacing ? 1 : 0;
    }
    EXPECT_EQ(onRim, 4);
    EXPECT_EQ(r.sharp.network.junctions.rows(), 8);
}

TEST(SharpEdges, DegenerateInputIsRefused)
{
    // Collinear points: no surface, no edges to speak of.
    PointMatrix line(40, 3);
    for (Eigen::Index i = 0; i < line.rows(); ++i) {
        line.row(i) << static_cast<double>(i), 2.0 * static_cast<double>(i), 0.0;
    }
    const Neighbourhoods N = nearestNeighbours(line);
    const NormalEstimate normals = pcaNormals(line, N);
    EXPECT_THROW(extractSharpEdges(line, normals.normals, N, meanSpacing(N)),
                 std::invalid_argument);

    const shapes::Sample plane = shapes::plane(10.0, 1.0, 1);
    const Neighbourhoods PN = nearestNeighbours(plane.points);
    const NormalEstimate PNormals = pcaNormals(plane.points, PN);
    EXPECT_THROW(extractSharpEdges(plane.points, PNormals.normals, PN, 0.0), std::invalid_argument);
    EXPECT_THROW(extractSharpEdges(plane.points, PNormals.normals.topRows(5), PN, 1.0),
                 std::invalid_argument);
    // Fewer points than neighbours, or all points coinciding, are refused before this stage.
    EXPECT_THROW(nearestNeighbours(plane.points.topRows(10)), std::invalid_argument);
    const PointMatrix same = PointMatrix::Ones(30, 3);
    EXPECT_THROW(meanSpacing(nearestNeighbours(same)), std::invalid_argument);
}

namespace {

/// The edges of shapes::chamferedCube(edge, chamfer): 24 between faces and chamfers (45
/// degrees), 24 between chamfers and corner triangles (35.26 degrees).
std::vector<Segment> chamferedCubeEdges(double edge, double chamfer, bool shallow)
{
    const double h = edge / 2, k = h - chamfer;
    std::vector<Segment> edges;
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        for (double sb : {-1.0, 1.0}) {
            for (double sc : {-1.0, 1.0}) {
                // The chamfer along axis a at corner (sb, sc) of the other two: its two long
                // edges on the faces b and c, and the short edges to the corner triangles.
                Eigen::Vector3d p, q;
                p[a] = -k;
                q[a] = k;
                p[b] = q[b] = sb * h;
                p[c] = q[c] = sc * k;
                if (!shallow) {
                    edges.push_back({p, q});
                }
                Eigen::Vector3d r = p, s = q;
                r[b] = s[b] = sb * k;
                r[c] = s[c] = sc * h;
                if (!shallow) {
                    edges.push_back({r, s});
                } else {
                    edges.push_back({p, r});
                    edges.push_back({q, s});
                }
            }
        }
    }
    return edges;
}

/// Share of the segment's length within `tolerance` of a line of the network.
double coverage(const Segment& e, const LineNetwork& network, double tolerance)
{
    int covered = 0;
    const int samples = 50;
    for (int s = 0; s <= samples; ++s) {
        const Eigen::Vector3d p = e.a + (e.b - e.a) * (static_cast<double>(s) / samples);
        for (const Polyline& line : network.lines) {
            if (distanceToPolyline(p, line) < tolerance) {
                ++covered;
                break;
            }
        }
    }
    return covered / static_cast<double>(samples + 1);
}

} // namespace

/// Every line closes on itself or ends on junctions at both ends.
void expectClosedNetwork(const LineNetwork& network)
{
    for (const Polyline& line : network.lines) {
        EXPECT_TRUE(line.closed || (line.startJunction >= 0 && line.endJunction >= 0))
            << "a line with a free end";
    }
}

/// Share of the vertices of the network within `tolerance` of one of the edges.
double shareOnEdges(const LineNetwork& network, const std::vector<Segment>& edges, double tolerance)
{
    int on = 0, all = 0;
    for (const Polyline& line : network.lines) {
        for (Eigen::Index i = 0; i < line.points.rows(); ++i) {
            double d = std::numeric_limits<double>::infinity();
            for (const Segment& e : edges) {
                d = std::min(d, e.distance(line.points.row(i).transpose()));
            }
            on += d < tolerance ? 1 : 0;
            ++all;
        }
    }
    return all > 0 ? on / static_cast<double>(all) : 0.0;
}

double meanCoverage(const std::vector<Segment>& edges, const LineNetwork& network, double tolerance)
{
    double sum = 0.0;
    for (const Segment& e : edges) {
        sum += coverage(e, network, tolerance);
    }
    return sum / static_cast<double>(edges.size());
}

TEST(SharpEdges, ChamferedCubeHasItsFortyEightEdgesInOneClosedNetwork)
{
    // 24 edges of 45 degrees, 24 of 35 degrees around the corner triangles (whose inradius,
    // 3.7 spacings, is barely a neighbourhood).
    const double edge = 60.0, chamfer = 9.0;
    for (unsigned seed : {1u, 2u, 3u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        const SharpRun r = extract(shapes::chamferedCube(edge, chamfer, 1.0, seed));
        expectClosedNetwork(r.sharp.network);
        const double tolerance = 2.0 * r.spacing;
        const std::vector<Segment> steep = chamferedCubeEdges(edge, chamfer, false);
        const std::vector<Segment> shallow = chamferedCubeEdges(edge, chamfer, true);
        std::vector<Segment> all = steep;
        all.insert(all.end(), shallow.begin(), shallow.end());
        EXPECT_EQ(shareOnEdges(r.sharp.network, all, tolerance), 1.0);
        for (const Segment& e : steep) {
            EXPECT_GE(coverage(e, r.sharp.network, tolerance), 0.9);
        }
        EXPECT_GE(meanCoverage(shallow, r.sharp.network, tolerance), 0.9);
    }
}

TEST(SharpEdges, NoisyChamferedCubeIsOneClosedNetwork)
{
    // Noise of 0.3 spacing thins the candidates of the 45 degree creases and mostly hides the
    // 35 degree ones: the free ends left are extended to the lines they point at, along
    // points whose normals bend, or removed.
    const double edge = 60.0, chamfer = 9.0;
    for (unsigned seed : {1u, 2u, 3u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        shapes::Sample cube = shapes::chamferedCube(edge, chamfer, 1.0, seed);
        const double spacing = meanSpacing(nearestNeighbours(cube.points));
        shapes::addNormalNoise(cube, 0.3 * spacing, seed + 10);
        const SharpRun r = extract(cube);
        EXPECT_EQ(r.sharp.counts.freeEnds, 0);
        expectClosedNetwork(r.sharp.network);
        std::vector<Segment> all = chamferedCubeEdges(edge, chamfer, false);
        const std::vector<Segment> shallow = chamferedCubeEdges(edge, chamfer, true);
        all.insert(all.end(), shallow.begin(), shallow.end());
        EXPECT_GE(shareOnEdges(r.sharp.network, all, 3.0 * r.spacing), 0.95);
        EXPECT_GE(meanCoverage(chamferedCubeEdges(edge, chamfer, false), r.sharp.network,
                               3.0 * r.spacing),
                  0.85);
    }
}

TEST(SharpEdges, RidgeOfThirtyFiveDegreesIsSharpOnACleanCloud)
{
    // A house-shaped prism: walls 30 apart, a roof whose ridge turns the normal by 35
    // degrees, eaves of 72.5 degrees, right angles elsewhere: 15 edges.
    const double w = 15.0, pi = 3.14159265358979323846;
    const double rise = w * std::tan(17.5 * pi / 180.0);
    const std::vector<Eigen::Vector2d> section = {
        {-w, -15.0}, {w, -15.0}, {w, 10.0}, {0.0, 10.0 + rise}, {-w, 10.0}};
    const double height = 40.0;
    const SharpRun r = extract(shapes::prism(section, height, 1.0, 1));
    expectClosedNetwork(r.sharp.network);
    std::vector<Segment> edges;
    for (std::size_t k = 0; k < section.size(); ++k) {
        const Eigen::Vector2d a = section[k], b = section[(k + 1) % section.size()];
        edges.push_back({{a.x(), a.y(), -height / 2}, {a.x(), a.y(), height / 2}});
        for (double z : {-height / 2, height / 2}) {
            edges.push_back({{a.x(), a.y(), z}, {b.x(), b.y(), z}});
        }
    }
    const double tolerance = 2.0 * r.spacing;
    EXPECT_EQ(shareOnEdges(r.sharp.network, edges, tolerance), 1.0);
    for (const Segment& e : edges) {
        EXPECT_GE(coverage(e, r.sharp.network, tolerance), 0.9);
    }
}
