// SPDX-License-Identifier: LGPL-2.1-or-later
// SmoothEdgeLevel.h: the lines at one threshold on regions whose answer is known: one level
// (no line), discs of a prescribed level (a loop each, noise islands levelled), and the
// contrast across a line read at a coarser scale.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "FeatureLines/curvature/CurvatureScale.h"
#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/smooth/SmoothEdgeLevel.h"
#include "RegionLattice.h"
#include "SampledShapes.h"

using namespace featurelines;

TEST(SmoothEdgeLevel, IslandsSmallerThanAPatchOfTheCurvaturesScaleAreLevelled)
{
    // A disc of radius 12 spacings at level 0.2 in a plane, and beside it one of radius 5
    // (about 90 points). With the curvature computed three spacings coarse, a patch needs a
    // patch's worth of those samples (2 k = 32 of them, 9 points each): at a threshold between
    // the levels the large disc gets its closed loop, the small one is noise of that scale.
    RegionGeometry g = latticeRegion(80, 60, [](double x, double y) {
        const double disc = std::hypot(x - 25.0, y - 26.0) < 12.0 ? 0.2 : 0.0;
        const double speck = std::hypot(x - 60.0, y - 26.0) < 5.0 ? 0.2 : 0.0;
        return disc + speck;
    });
    g.curvatureScale = 3.0;
    const SmoothEdgeLevel level = smoothEdgesAtThreshold(g, 0.1);
    ASSERT_EQ(level.network.lines.size(), 1u);
    const Polyline& loop = level.network.lines[0];
    EXPECT_TRUE(loop.closed);
    for (Eigen::Index i = 0; i < loop.points.rows(); ++i) {
        EXPECT_NEAR(std::hypot(loop.points(i, 0) - 25.0, loop.points(i, 1) - 26.0), 12.0, 2.0);
    }
    // At the cloud's own scale the small disc is a patch too.
    g.curvatureScale = 1.0;
    EXPECT_EQ(smoothEdgesAtThreshold(g, 0.1).network.lines.size(), 2u);
}
// A curvature step of height 1 read on a grid of 8 spacings and carried back to a square
// lattice: the carried values cross tau = 0.5 over the coarse fit's width, so within two fit
// radii of the lattice's own sampling a line along the step shows only part of it; at the
// coarse cells its points were averaged into, the whole step.
TEST(SmoothEdgeLevel, ALineAtACoarserScaleIsJudgedByTheContrastThere)
{
    const int half = 40;
    PointMatrix P(4 * half * half, 3);
    for (int i = 0, r = 0; i < 2 * half; ++i) {
        for (int j = 0; j < 2 * half; ++j, ++r) {
            P.row(r) << i - half + 0.5, j - half + 0.5, 0.0;
        }
    }
    GridCentroids grid = gridCentroids(P, 8.0);
    auto coarse = std::make_shared<RegionGeometry>();
    coarse->points = grid.points;
    coarse->neighbours = nearestNeighbours(grid.points);
    coarse->spacing = meanSpacing(coarse->neighbours);
    coarse->curvature.resize(grid.points.rows());
    for (Eigen::Index c = 0; c < grid.points.rows(); ++c) {
        coarse->curvature[c] = grid.points(c, 0) > 0.0 ? 1.0 : 0.0;
    }
    RegionGeometry g;
    g.points = P;
    g.neighbours = nearestNeighbours(P);
    g.spacing = meanSpacing(g.neighbours);
    g.curvature = valuesAtPoints(P, grid, coarse->neighbours, coarse->curvature, 4.0);
    // The line's points: the two columns either side of x = 0, away from the lattice's ends.
    std::vector<int> line;
    for (Eigen::Index r = 0; r < P.rows(); ++r) {
        if (std::abs(P(r, 0)) < 1.0 && std::abs(P(r, 1)) < half - 10) {
            line.push_back(static_cast<int>(r));
        }
    }
    ASSERT_EQ(line.size(), 2u * (2 * half - 20));

    const double own = lineContrast(g, g.curvature, 0.5, line);
    EXPECT_GT(own, 0.0);
    EXPECT_LT(own, 0.6) << "two fit radii of the lattice see about half the ramp";

    g.curvatureScale = 8.0;
    g.coarse = coarse;
    g.coarseRowOf = grid.cellOf;
    EXPECT_NEAR(lineContrast(g, g.curvature, 0.5, line), 1.0, 1e-12);
    // One level only: no contrast.
    EXPECT_EQ(lineContrast(g, g.curvature, 2.0, line), 0.0);
}
TEST(SmoothEdgeLevel, ARegionOfOneLevelHasNoLine)
{
    // A clean plane (|H| = 0) and a clean cylinder (|H| = 1 / 2r = 0.05): one curvature level
    // each, on one side of tau, so every point carries the same label and no line parts them.
    const double spacing = 0.5;
    const shapes::Sample plane = shapes::plane(30.0, spacing, 2);
    const shapes::Sample cylinder = shapes::cylinder(10.0, 30.0, spacing, 4);
    for (const PointMatrix* P : {&plane.points, &cylinder.points}) {
        const Neighbourhoods N = nearestNeighbours(*P);
        const std::vector<int> region(static_cast<size_t>(P->rows()), 0);
        std::vector<int> members(region.size());
        for (size_t i = 0; i < members.size(); ++i) {
            members[i] = static_cast<int>(i);
        }
        const RegionGeometry g = analyseRegion(*P, N, region, members, 0, meanSpacing(N));
        for (double tau : {0.02, 0.1}) {
            EXPECT_TRUE(smoothEdgesAtThreshold(g, tau).network.lines.empty()) << tau;
        }
    }
}

TEST(SmoothEdgeLevel, TheGraphLeavesOpenPiecesToTheAnchoredLines)
{
    // The graph drops no open piece (the level drops them once their ends are anchored); every
    // other graph option is the caller's.
    SmoothEdgeOptions options;
    options.graph.minOpenComponentLength = 12.0;
    options.graph.maxBubbleLength = 7.0;
    const ClusterGraphOptions graph = smoothGraphOptions(options);
    EXPECT_EQ(graph.minOpenComponentLength, 0.0);
    EXPECT_EQ(graph.maxBubbleLength, 7.0);
    EXPECT_EQ(options.graph.minOpenComponentLength, 12.0);
}

namespace {

/// Total length of the lines of a level.
double linesLength(const SmoothEdgeLevel& level)
{
    double length = 0.0;
    for (const Polyline& line : level.network.lines) {
        for (Eigen::Index i = 1; i < line.points.rows(); ++i) {
            length += (line.points.row(i) - line.points.row(i - 1)).norm();
        }
    }
    return length;
}

} // namespace

TEST(SmoothEdgeLevel, ACurvatureThatOnlyDriftsThroughTauHasNoLine)
{
    // Along a freeform surface the curvature drifts: here it rises evenly from 0 to 0.16 across
    // 80 spacings, with no step anywhere. tau = 0.08 crosses it at x = 40, with about 0.008 of
    // contrast within two fit radii, a tenth of tau: no fillet borders there.
    const RegionGeometry drift = latticeRegion(80, 60, [](double x, double) { return 0.002 * x; });
    EXPECT_TRUE(smoothEdgesAtThreshold(drift, 0.08).network.lines.empty());
    SmoothEdgeOptions noRelative;
    noRelative.minRelativeContrast = 0.0;
    EXPECT_GT(linesLength(smoothEdgesAtThreshold(drift, 0.08, noRelative)), 40.0)
        << "without the relative contrast the drift is parted along x = 40";

    // A fillet's border: the same levels 0 and 0.16 in one step, blurred over 3 spacings as
    // the quadric fit blurs it. Its line stays, along the whole region (about 52 spacings).
    const RegionGeometry fillet =
        latticeRegion(80, 60, [](double x, double) { return step(x, 40.0, 0.0, 0.16, 3.0); });
    const SmoothEdgeLevel border = smoothEdgesAtThreshold(fillet, 0.08);
    EXPECT_GT(linesLength(border), 40.0);
    for (const Polyline& line : border.network.lines) {
        for (Eigen::Index i = 0; i < line.points.rows(); ++i) {
            EXPECT_NEAR(line.points(i, 0), 40.0, 1.5);
        }
    }
}

TEST(SmoothEdgeLevel, AHigherLevelsLineRisesFromTheLevelBeneath)
{
    // A corner blend (0.16) beside a fillet (0.1), on a region whose lowest threshold parts the
    // fillet from its faces: the blend's border at tau = 0.13 rises 0.06 from the fillet's
    // level, less than half of tau but all of the step from the level beneath.
    const RegionGeometry g =
        latticeRegion(80, 60, [](double x, double) { return step(x, 40.0, 0.1, 0.16, 3.0); });
    EXPECT_GT(linesLength(smoothEdgesAtThreshold(g, 0.13, {}, {}, {}, 0.1)), 40.0);
    EXPECT_TRUE(smoothEdgesAtThreshold(g, 0.13).network.lines.empty())
        << "measured from a plane's level, the step is too small a share of tau";
    SmoothEdgeOptions negative;
    negative.minRelativeContrast = -1.0;
    EXPECT_THROW(smoothEdgesAtThreshold(g, 0.13, negative), std::invalid_argument);
    EXPECT_THROW(smoothEdgesAtThreshold(g, 0.13, {}, {}, {}, std::nan("")), std::invalid_argument);
    SmoothEdgeOptions noStrip;
    noStrip.ownScaleHalfWidth = 0.0;
    EXPECT_THROW(smoothEdgesAtThreshold(g, 0.13, noStrip), std::invalid_argument);
    noStrip.placeOwnScaleLines = false; // then the strip is not used
    EXPECT_NO_THROW(smoothEdgesAtThreshold(g, 0.13, noStrip));
}
