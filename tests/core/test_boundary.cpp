// SPDX-License-Identifier: LGPL-2.1-or-later
// The boundary of open clouds whose border is known: a square patch has one loop along its
// perimeter, a square with a round hole two, an open tube one per rim; closed surfaces none.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "FeatureLines/boundary/Boundary.h"
#include "FeatureLines/neighbourhoods/Normals.h"
#include "SampledShapes.h"

using namespace featurelines;

namespace {

struct BoundaryRun
{
    Boundary boundary;
    double spacing;
};

BoundaryRun extract(const PointMatrix& P)
{
    const Neighbourhoods N = nearestNeighbours(P);
    const double spacing = meanSpacing(N);
    const NormalEstimate normals = pcaNormals(P, N);
    return {extractBoundary(P, normals.normals, N, spacing), spacing};
}

/// Distance from (x, y) to the outline of the square [-h, h]^2.
double distanceToSquareOutline(double x, double y, double h)
{
    const double dx = std::abs(x) - h, dy = std::abs(y) - h;
    if (dx <= 0.0 && dy <= 0.0) {
        return -std::max(dx, dy);
    }
    return std::hypot(std::max(dx, 0.0), std::max(dy, 0.0));
}

double loopLength(const Polyline& line)
{
    double length = 0.0;
    const Eigen::Index m = line.points.rows();
    for (Eigen::Index i = 0; i < m; ++i) {
        length += (line.points.row((i + 1) % m) - line.points.row(i)).norm();
    }
    return length;
}

} // namespace

TEST(Boundary, SquarePatchHasOneLoopAlongItsPerimeter)
{
    const double size = 30.0, h = size / 2;
    const shapes::Sample plane = shapes::plane(size, 1.0, 1);
    const BoundaryRun r = extract(plane.points);

    // Boundary points are the outer row of the grid; the outer row (within half a grid step
    // of the outline, given the jitter of 0.2) is found entirely.
    int outerRow = 0, outerFound = 0;
    for (Eigen::Index i = 0; i < plane.size(); ++i) {
        const double d = distanceToSquareOutline(plane.points(i, 0), plane.points(i, 1), h);
        if (r.boundary.isBoundary[i]) {
            EXPECT_LT(d, 1.0) << "boundary point inside the patch at " << i;
        }
        if (d < 0.5) {
            ++outerRow;
            outerFound += r.boundary.isBoundary[i] ? 1 : 0;
        }
    }
    EXPECT_EQ(outerFound, outerRow);

    ASSERT_EQ(r.boundary.network.lines.size(), 1u);
    const Polyline& loop = r.boundary.network.lines[0];
    EXPECT_TRUE(loop.closed);
    EXPECT_EQ(r.boundary.network.junctions.rows(), 0);
    // Within the outer row (half a grid step in), the corners cut by about a spacing.
    for (Eigen::Index i = 0; i < loop.points.rows(); ++i) {
        EXPECT_LT(distanceToSquareOutline(loop.points(i, 0), loop.points(i, 1), h),
                  2.0 * r.spacing);
    }
    // The outer row runs half a step inside the outline; corners are cut a little.
    EXPECT_NEAR(loopLength(loop), 4.0 * (size - 1.0), 0.05 * 4.0 * size);
}

TEST(Boundary, HoleGivesASecondLoop)
{
    const double size = 40.0, hole = 8.0;
    const shapes::Sample plane = shapes::plane(size, 1.0, 2);
    std::vector<Eigen::Index> keep;
    for (Eigen::Index i = 0; i < plane.size(); ++i) {
        if (plane.points.row(i).head<2>().norm() > hole) {
            keep.push_back(i);
        }
    }
    PointMatrix P(static_cast<Eigen::Index>(keep.size()), 3);
    for (size_t i = 0; i < keep.size(); ++i) {
        P.row(i) = plane.points.row(keep[i]);
    }
    const BoundaryRun r = extract(P);
    ASSERT_EQ(r.boundary.network.lines.size(), 2u);
    int aroundHole = 0;
    for (const Polyline& loop : r.boundary.network.lines) {
        EXPECT_TRUE(loop.closed);
        const double meanRadius = loop.points.leftCols(2).rowwise().norm().mean();
        if (meanRadius < size / 4) {
            ++aroundHole;
            for (Eigen::Index i = 0; i < loop.points.rows(); ++i) {
                EXPECT_NEAR(loop.points.row(i).head<2>().norm(), hole, 1.5 * r.spacing);
            }
        }
    }
    EXPECT_EQ(aroundHole, 1);
}

TEST(Boundary, OpenTubeHasOneLoopPerRim)
{
    const double radius = 8.0, height = 24.0;
    const shapes::Sample tube = shapes::cylinder(radius, height, 1.0, 3);
    const BoundaryRun r = extract(tube.points);
    ASSERT_EQ(r.boundary.network.lines.size(), 2u);
    std::vector<double> heights;
    for (const Polyline& loop : r.boundary.network.lines) {
        EXPECT_TRUE(loop.closed);
        heights.push_back(loop.points.col(2).mean());
        EXPECT_NEAR(loopLength(loop), 2.0 * 3.14159265358979 * radius,
                    0.1 * 2.0 * 3.14159 * radius);
    }
    std::sort(heights.begin(), heights.end());
    EXPECT_NEAR(heights[0], -height / 2, 1.0 * r.spacing);
    EXPECT_NEAR(heights[1], height / 2, 1.0 * r.spacing);
}

TEST(Boundary, ClosedSurfacesHaveNone)
{
    for (const shapes::Sample& closed :
         {shapes::sphere(12.0, 1.0, 4), shapes::cube(20.0, 1.0, 5)}) {
        const BoundaryRun r = extract(closed.points);
        int flagged = 0;
        for (char b : r.boundary.isBoundary) {
            flagged += b;
        }
        EXPECT_EQ(flagged, 0);
        EXPECT_TRUE(r.boundary.network.lines.empty());
    }
}

// An irregular sampling: a regular one with 30 % of its points dropped at random (a thinned or
// patchy scan). Inside, a point's 16 nearest neighbours then leave a gap wider than 90
// degrees often enough for the scattered points to chain into false lines; wider than 120
// rarely, and never in chains. The border is found as on the whole sampling.
TEST(Boundary, ThinnedSamplingGivesTheBorderOnly)
{
    std::mt19937 random(12);
    std::bernoulli_distribution kept(0.7);
    const auto thinned = [&](const PointMatrix& P) {
        std::vector<Eigen::Index> rows;
        for (Eigen::Index i = 0; i < P.rows(); ++i) {
            if (kept(random)) {
                rows.push_back(i);
            }
        }
        PointMatrix T(static_cast<Eigen::Index>(rows.size()), 3);
        for (size_t i = 0; i < rows.size(); ++i) {
            T.row(static_cast<Eigen::Index>(i)) = P.row(rows[i]);
        }
        return T;
    };
    const double size = 40.0, h = size / 2;
    const PointMatrix sheet = thinned(shapes::plane(size, 1.0, 9).points);
    const BoundaryRun r = extract(sheet);
    ASSERT_EQ(r.boundary.network.lines.size(), 1u);
    const Polyline& loop = r.boundary.network.lines[0];
    EXPECT_TRUE(loop.closed);
    for (Eigen::Index i = 0; i < loop.points.rows(); ++i) {
        EXPECT_LT(distanceToSquareOutline(loop.points(i, 0), loop.points(i, 1), h),
                  2.0 * r.spacing);
    }
    EXPECT_NEAR(loopLength(loop), 4.0 * (size - 1.0), 0.05 * 4.0 * size);

    // Closed surfaces thinned alike: no line.
    for (const shapes::Sample& closed :
         {shapes::sphere(12.0, 1.0, 10), shapes::cube(20.0, 1.0, 11)}) {
        EXPECT_TRUE(extract(thinned(closed.points)).boundary.network.lines.empty());
    }
}

// Independent uniform points (no Poisson disk, no grid: the clumps and gaps of a random
// sampling). Inside, about 4 % of the points see a gap wider than 120 degrees among their 16
// neighbours; one ring further out the gap is filled, so none is a boundary point. On a sphere
// there is then no boundary at all; on a square sheet every boundary point lies at the border
// and the border is found all round.
namespace {

PointMatrix uniformSphere(double radius, int count, unsigned seed)
{
    std::mt19937 random(seed);
    std::normal_distribution<double> gauss;
    PointMatrix P(count, 3);
    for (int i = 0; i < count; ++i) {
        const Eigen::Vector3d d(gauss(random), gauss(random), gauss(random));
        P.row(i) = radius * d.normalized().transpose();
    }
    return P;
}

PointMatrix uniformSquare(double size, int count, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> coordinate(-size / 2, size / 2);
    PointMatrix P(count, 3);
    for (int i = 0; i < count; ++i) {
        P.row(i) << coordinate(random), coordinate(random), 0.0;
    }
    return P;
}

int flaggedCount(const std::vector<char>& flags)
{
    int count = 0;
    for (char f : flags) {
        count += f;
    }
    return count;
}

} // namespace

TEST(Boundary, RandomSamplingOfAClosedSurfaceHasNone)
{
    const PointMatrix sphere = uniformSphere(20.0, 20000, 21);
    const Neighbourhoods N = nearestNeighbours(sphere);
    const NormalEstimate normals = pcaNormals(sphere, N);
    BoundaryOptions firstRingOnly;
    firstRingOnly.confirmationReach = 0.0;
    // The k neighbours alone leave chance gaps: the test below is not empty-handed.
    EXPECT_GT(flaggedCount(boundaryPoints(sphere, normals.normals, N, firstRingOnly)), 100);
    EXPECT_EQ(flaggedCount(boundaryPoints(sphere, normals.normals, N)), 0);
    EXPECT_TRUE(extract(sphere).boundary.network.lines.empty());
}

TEST(Boundary, RandomSamplingOfASheetGivesItsBorderAllRound)
{
    const double size = 60.0, h = size / 2;
    const PointMatrix sheet = uniformSquare(size, 12000, 22);
    const BoundaryRun r = extract(sheet);
    std::vector<Eigen::Vector2d> found;
    for (Eigen::Index i = 0; i < sheet.rows(); ++i) {
        if (r.boundary.isBoundary[static_cast<size_t>(i)]) {
            EXPECT_LT(distanceToSquareOutline(sheet(i, 0), sheet(i, 1), h), 5.0 * r.spacing)
                << "boundary point inside the sheet at " << i;
            found.emplace_back(sheet(i, 0), sheet(i, 1));
        }
    }
    // Every stretch of the outline has a boundary point within two spacings of where the
    // cloud itself ends (a random sampling leaves the outline bare here and there).
    const auto nearestTo = [](const std::vector<Eigen::Vector2d>& points,
                              const Eigen::Vector2d& x) {
        double nearest = 1e300;
        for (const Eigen::Vector2d& p : points) {
            nearest = std::min(nearest, (p - x).norm());
        }
        return nearest;
    };
    std::vector<Eigen::Vector2d> cloud;
    for (Eigen::Index i = 0; i < sheet.rows(); ++i) {
        cloud.emplace_back(sheet(i, 0), sheet(i, 1));
    }
    for (double t = -h; t <= h; t += r.spacing) {
        for (const Eigen::Vector2d& onOutline : {Eigen::Vector2d(t, -h), Eigen::Vector2d(t, h),
                                                 Eigen::Vector2d(-h, t), Eigen::Vector2d(h, t)}) {
            EXPECT_LT(nearestTo(found, onOutline), nearestTo(cloud, onOutline) + 2.0 * r.spacing)
                << "no boundary point near " << onOutline.transpose();
        }
    }
}

TEST(Boundary, BadInputThrows)
{
    const shapes::Sample plane = shapes::plane(10.0, 1.0, 1);
    const Neighbourhoods N = nearestNeighbours(plane.points);
    const NormalEstimate normals = pcaNormals(plane.points, N);
    EXPECT_THROW(boundaryPoints(plane.points, normals.normals.topRows(3), N),
                 std::invalid_argument);
    EXPECT_THROW(extractBoundary(plane.points, normals.normals, N, -1.0), std::invalid_argument);
    BoundaryOptions zero;
    zero.minGapAngle = 0.0;
    EXPECT_THROW(boundaryPoints(plane.points, normals.normals, N, zero), std::invalid_argument);
    BoundaryOptions negativeReach;
    negativeReach.confirmationReach = -1.0;
    EXPECT_THROW(boundaryPoints(plane.points, normals.normals, N, negativeReach),
                 std::invalid_argument);
    // Every neighbour on the point itself: no direction, no boundary, no crash.
    const PointMatrix same = PointMatrix::Ones(30, 3);
    const Neighbourhoods SN = nearestNeighbours(same);
    const NormalMatrix up = NormalMatrix::Ones(30, 3).rowwise().normalized();
    for (char b : boundaryPoints(same, up, SN)) {
        EXPECT_EQ(b, 0);
    }
}
