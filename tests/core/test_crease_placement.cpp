// SPDX-License-Identifier: LGPL-2.1-or-later
// Crease placement on an L of two perpendicular grids meeting along the x axis: a sharp line
// of nodes off the crease ends on it exactly; a node farther than maxCreaseShift, or a line of
// another label, stays where it is.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/sharp/CreasePlacement.h"
#include "FeatureLines/sharp/PlaneFit.h"

using namespace featurelines;

namespace {

/// Face A, z = 0 for y in [-8, 0] (cluster 0), meets face B, y = 0 for z in (0, 8] (cluster 1),
/// along the x axis, x in [0, 20], one spacing apart. The points within two spacings of the
/// crease form a small cluster (2).
struct LShape
{
    PointMatrix P;
    SharpEdges sharp;
};

LShape lShape()
{
    std::vector<Eigen::Vector3d> points;
    std::vector<int> cluster;
    for (int x = 0; x <= 20; ++x) {
        for (int y = -8; y <= 0; ++y) {
            points.emplace_back(x, y, 0.0);
            cluster.push_back(y > -2 ? 2 : 0);
        }
        for (int z = 1; z <= 8; ++z) {
            points.emplace_back(x, 0.0, z);
            cluster.push_back(z < 2 ? 2 : 1);
        }
    }
    LShape shape;
    shape.P.resize(static_cast<Eigen::Index>(points.size()), 3);
    for (std::size_t i = 0; i < points.size(); ++i) {
        shape.P.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
    }
    shape.sharp.segmentation.cluster = cluster;
    shape.sharp.segmentation.clusterSize = {0, 0, 0};
    for (int c : cluster) {
        ++shape.sharp.segmentation.clusterSize[c];
    }
    shape.sharp.segmentation.smallCluster = {0, 0, 1};
    shape.sharp.isBoundary.assign(points.size(), 0);
    return shape;
}

/// One open line of `label` through nodes at x = 2, 4, .., 18 and the given (y, z), each node
/// holding the small cluster's points of its x and the next.
ClusterGraph lineOfNodes(const LShape& shape, double y, double z, int label)
{
    ClusterGraph graph;
    const int count = 9;
    graph.nodes.resize(count, 3);
    std::vector<int> nodes;
    for (int v = 0; v < count; ++v) {
        graph.nodes.row(v) << 2.0 * (v + 1), y, z;
        nodes.push_back(v);
    }
    graph.nodeOfPoint.assign(static_cast<std::size_t>(shape.P.rows()), -1);
    for (Eigen::Index i = 0; i < shape.P.rows(); ++i) {
        const int v = static_cast<int>(shape.P(i, 0)) / 2 - 1;
        if (shape.sharp.segmentation.cluster[i] == 2 && v >= 0 && v < count) {
            graph.nodeOfPoint[i] = v;
        }
    }
    graph.lineNodes = {nodes};
    Polyline line;
    line.points = graph.nodes;
    line.label = label;
    graph.network.lines = {line};
    graph.network.junctions.resize(0, 3);
    return graph;
}

/// The largest distance of the line's vertices from the line {(x, y, z) : x real}.
double largestDistanceFrom(const Polyline& line, double y, double z)
{
    double largest = 0.0;
    for (Eigen::Index i = 0; i < line.points.rows(); ++i) {
        largest =
            std::max(largest, (line.points.row(i).tail<2>() - Eigen::RowVector2d(y, z)).norm());
    }
    return largest;
}

/// The network placeOnCreases makes of a line of `label` through nodes at (y, z) on the L.
LineNetwork placedLineOfNodes(double y, double z, int label, const SharpEdgeOptions& options = {})
{
    const LShape shape = lShape();
    const Neighbourhoods N = nearestNeighbours(shape.P);
    const ClusterGraph graph = lineOfNodes(shape, y, z, label);
    return placeOnCreases({shape.P, N, graph, shape.sharp, 1.0}, options);
}

} // namespace

TEST(CreasePlacement, SharpLineOffTheCreaseEndsOnIt)
{
    const LineNetwork network = placedLineOfNodes(-0.6, 0.6, sharpLineLabel);
    ASSERT_EQ(network.lines.size(), 1u);
    const Polyline& line = network.lines[0];
    EXPECT_LT(largestDistanceFrom(line, 0.0, 0.0), 1e-6);
    // Resampled at one spacing from the first node (x = 2) to the last (x = 18).
    EXPECT_EQ(line.points.rows(), 17);
    EXPECT_NEAR(line.points(0, 0), 2.0, 1e-6);
    EXPECT_NEAR(line.points(line.points.rows() - 1, 0), 18.0, 1e-6);
}

TEST(CreasePlacement, NodesFartherThanTheLargestShiftStay)
{
    // 3 spacings from the crease: beyond maxCreaseShift (2.5).
    const LineNetwork network = placedLineOfNodes(-2.1, 2.1, sharpLineLabel);
    ASSERT_EQ(network.lines.size(), 1u);
    EXPECT_LT(largestDistanceFrom(network.lines[0], -2.1, 2.1), 1e-9);
}

TEST(CreasePlacement, LinesOfOtherLabelsKeepTheirNodes)
{
    SharpEdgeOptions options;
    options.graph.smoothingLength = 0.0;
    options.graph.resampleSpacing = 0.0;
    const LineNetwork network = placedLineOfNodes(-0.6, 0.6, boundaryLineLabel, options);
    ASSERT_EQ(network.lines.size(), 1u);
    EXPECT_TRUE(network.lines[0].points.isApprox(
        lineOfNodes(lShape(), -0.6, 0.6, boundaryLineLabel).nodes));
}

// A face's strip beside an edge, 3 spacings wide, the normals of the points within a spacing
// of the edge leaning towards the other face (their neighbourhoods reach it).
std::vector<Eigen::Vector3d> stripNormals(double lean, double scatter, unsigned seed,
                                          std::vector<Eigen::Vector3d>& points, double noise)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> along(0.0, noise), turn(0.0, scatter * M_PI / 180.0);
    std::vector<Eigen::Vector3d> normals;
    points.clear();
    for (double x = 0.25; x < 3.0; x += 0.5) {
        for (double y = 0.25; y < 10.0; y += 0.5) {
            points.emplace_back(x, y, 2.0 + along(rng));
            const double a = (x < 1.0 ? lean * M_PI / 180.0 : 0.0) + turn(rng);
            normals.push_back(Eigen::Vector3d(std::sin(a), std::sin(turn(rng)), std::cos(a)).normalized());
        }
    }
    return normals;
}

double turnFromZ(const Plane& plane)
{
    return std::acos(std::min(1.0, std::abs(plane.normal.z()))) * 180.0 / M_PI;
}

// Noise of 0.3 spacing along the normal and 3 degrees in the normals, the edge's normals
// leaning 20 degrees: the normals' plane is the face's within a degree and a tenth of a
// spacing. Clean, the edge's normals leaning 5 degrees: the positions fix the plane, and it is
// the face's exactly.
TEST(CreasePlacement, FacePlaneFromNormalsIgnoresNoiseAndTheEdgesBlend)
{
    std::vector<Eigen::Vector3d> points;
    std::vector<Eigen::Vector3d> normals = stripNormals(20.0, 3.0, 5, points, 0.3);
    const Plane noisy = fitPlaneByNormals(points, normals, 6);
    EXPECT_LT(turnFromZ(noisy), 1.0);
    EXPECT_NEAR(std::abs(noisy.offset), 2.0, 0.1);

    normals = stripNormals(5.0, 0.0, 5, points, 0.0);
    const Plane clean = fitPlaneByNormals(points, normals, 6);
    EXPECT_LT(turnFromZ(clean), 1e-9);
    EXPECT_NEAR(std::abs(clean.offset), 2.0, 1e-9);

    // Too few normals near the face's direction: the positions' plane.
    const std::vector<Eigen::Vector3d> few(points.begin(), points.begin() + 4);
    const std::vector<Eigen::Vector3d> fewNormals(normals.begin(), normals.begin() + 4);
    EXPECT_DOUBLE_EQ(fitPlaneByNormals(few, fewNormals, 6).offset, fitPlane(few, 6).offset);
}
