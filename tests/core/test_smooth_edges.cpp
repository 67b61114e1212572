// SPDX-License-Identifier: LGPL-2.1-or-later
// The parts of the smooth-edge stage with an exact answer: the noise estimate and the
// curvature noise floor on planes and spheres, the automatic thresholds on a lattice whose
// curvature is prescribed (levels, a drifting strip, noise), and the line-end processing on
// hand-made networks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <random>

#include "FeatureLines/curvature/CurvatureScale.h"
#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/smooth/SmoothEdges.h"
#include "SampledShapes.h"

using namespace featurelines;

namespace {

double median(std::vector<double> v)
{
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

RegionGeometry wholeCloud(const PointMatrix& P, const SmoothEdgeOptions& options = {})
{
    const Neighbourhoods N = nearestNeighbours(P);
    std::vector<int> members(static_cast<size_t>(P.rows()));
    for (size_t i = 0; i < members.size(); ++i) {
        members[i] = static_cast<int>(i);
    }
    const std::vector<int> region(members.size(), 0);
    return analyseRegion(P, N, region, members, 0, meanSpacing(N), options);
}

/// A triangular lattice of unit spacing in the plane z = 0, nx by ny points, with the
/// curvature field given (the region's own geometry, no fit): the automatic rule sees exactly
/// the levels drawn.
RegionGeometry latticeRegion(int nx, int ny, const std::function<double(double, double)>& field,
                             double curvatureNoise = 0.0)
{
    RegionGeometry g;
    g.region = 0;
    g.points.resize(nx * ny, 3);
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            g.points.row(j * nx + i) << i + 0.5 * (j % 2), j * std::sqrt(3.0) / 2.0, 0.0;
        }
    }
    g.members.resize(static_cast<size_t>(nx * ny));
    for (size_t i = 0; i < g.members.size(); ++i) {
        g.members[i] = static_cast<int>(i);
    }
    g.neighbours = nearestNeighbours(g.points);
    g.normals = pcaNormals(g.points, g.neighbours).normals;
    g.ring = ringNeighbourhoods(g.points, g.normals, g.neighbours);
    g.spacing = meanSpacing(g.neighbours);
    g.curvature.resize(nx * ny);
    for (Eigen::Index p = 0; p < g.points.rows(); ++p) {
        g.curvature[p] = field(g.points(p, 0), g.points(p, 1));
    }
    g.curvatureNoise = curvatureNoise;
    return g;
}

std::vector<double> accepted(const std::vector<ThresholdDecision>& decisions)
{
    std::vector<double> taus;
    for (const ThresholdDecision& d : decisions) {
        if (d.accepted) {
            taus.push_back(d.applied);
        }
    }
    std::sort(taus.begin(), taus.end());
    return taus;
}

/// A level that steps from `low` to `high` across x = edge, blurred over `ramp` spacings as
/// the quadric fit blurs a step.
double step(double x, double edge, double low, double high, double ramp)
{
    const double t = std::clamp((x - edge) / ramp + 0.5, 0.0, 1.0);
    return low + t * (high - low);
}

Polyline line(std::initializer_list<Eigen::RowVector3d> vertices, int start = -1, int end = -1)
{
    Polyline l;
    l.points.resize(static_cast<Eigen::Index>(vertices.size()), 3);
    Eigen::Index i = 0;
    for (const Eigen::RowVector3d& v : vertices) {
        l.points.row(i++) = v;
    }
    l.startJunction = start;
    l.endJunction = end;
    return l;
}

Polyline straight(const Eigen::RowVector3d& a, const Eigen::RowVector3d& b, int start = -1,
                  int end = -1)
{
    return line({a, 0.5 * (a + b), b}, start, end);
}

} // namespace

TEST(SmoothEdges, NoiseEstimateIgnoresCurvatureAndFollowsTheNoise)
{
    // A clean sphere of radius 25 spacings: a quadric predicts every point, whatever the
    // curvature (the centroid of the neighbours would lie 0.1 spacing inside).
    const shapes::Sample sphere = shapes::sphere(10.0, 0.4, 1);
    EXPECT_LT(wholeCloud(sphere.points).noise, 0.01);
    // Normal noise of sigma: the point's distance from the quadric of its neighbours is
    // sigma times a little more than one (the fit's own error), its median 0.67 of that.
    for (double sigma : {0.1, 0.3}) {
        shapes::Sample plane = shapes::plane(30.0, 0.5, 2);
        shapes::addNormalNoise(plane, sigma * 0.5, 3);
        SmoothEdgeOptions never;
        never.smoothing = SmoothingMode::Never;
        const RegionGeometry g = wholeCloud(plane.points, never);
        EXPECT_GT(g.noise, 0.7 * sigma) << sigma;
        EXPECT_LT(g.noise, 1.1 * sigma) << sigma;
    }
}

TEST(SmoothEdges, CurvatureNoiseFloorIsTheSpreadOfANoisyPlane)
{
    // On a plane every curvature value is noise: |H| is folded normal noise whose median is
    // 0.674 standard deviations. The floor, measured on a synthetic patch, must predict it.
    for (double sigma : {0.05, 0.3}) {
        shapes::Sample plane = shapes::plane(40.0, 0.5, 5);
        shapes::addNormalNoise(plane, sigma * 0.5, 6);
        const RegionGeometry g = wholeCloud(plane.points);
        std::vector<double> inner;
        for (Eigen::Index i = 0; i < g.points.rows(); ++i) {
            if (g.points.row(i).head<2>().cwiseAbs().maxCoeff() < 14.0) { // off the rim
                inner.push_back(std::abs(g.curvature[i]));
            }
        }
        const double spread = median(inner) / 0.6745;
        EXPECT_TRUE(g.smoothed) << sigma;
        EXPECT_GT(g.curvatureNoise, 0.75 * spread) << sigma;
        EXPECT_LT(g.curvatureNoise, 1.33 * spread) << sigma;
    }
    const shapes::Sample clean = shapes::plane(20.0, 0.5, 7);
    EXPECT_LT(wholeCloud(clean.points).curvatureNoise, 1e-6);
}

TEST(SmoothEdges, ValleyAboveTheTopPatchSendsTheSearchBelow)
{
    // A plane (0) with a strip at 0.1 (a fillet) whose sides are blurred over 4 spacings (and
    // wave, so the blur's values spread over the valley), and a few isolated points at 0.3
    // (stray values of a clean region: no outliers are dropped). The largest ratio lies after
    // the strip's spike, where the gap up to the strays is empty (b2 = 0): above that
    // threshold lies no patch, so the search goes below it and finds plane | strip.
    const RegionGeometry g = latticeRegion(70, 60, [](double x, double y) {
        const double wave = 3.0 * std::sin(y / 7.0);
        if (std::fmod(x * 7.0 + y * 13.0, 50.0) < 0.5) {
            return 0.3;
        }
        return x < 40.0 ? step(x, 25.0 + wave, 0.0, 0.1, 4.0) : step(x, 55.0 + wave, 0.1, 0.0, 4.0);
    });
    const std::vector<ThresholdDecision> d = automaticThresholds(g);
    ASSERT_GE(d.size(), 2u);
    EXPECT_FALSE(d[0].accepted);
    EXPECT_GT(d[0].result.threshold, 0.1);
    EXPECT_LT(d[0].largestPatch, 2 * g.neighbours.k()) << "no patch above the first valley";
    const std::vector<double> taus = accepted(d);
    ASSERT_EQ(taus.size(), 1u);
    // Applied in the middle of the valley: the blur crosses it on the strip's tangent lines.
    EXPECT_GT(taus[0], 0.03);
    EXPECT_LT(taus[0], 0.07);
}

TEST(SmoothEdges, ThreeLevelsGiveTwoThresholds)
{
    // Plane 0, strip 0.1, and inside the strip a core at 0.2 (fillet and corner levels).
    const RegionGeometry g = latticeRegion(80, 60, [](double x, double) {
        const double outer = x < 40.0 ? step(x, 20.0, 0.0, 0.1, 4.0) : step(x, 60.0, 0.1, 0.0, 4.0);
        return outer + (x < 40.0 ? step(x, 32.0, 0.0, 0.1, 4.0) : step(x, 48.0, 0.1, 0.0, 4.0));
    });
    const std::vector<double> taus = accepted(automaticThresholds(g));
    ASSERT_EQ(taus.size(), 2u);
    EXPECT_GT(taus[0], 0.0);
    EXPECT_LT(taus[0], 0.1);
    EXPECT_GT(taus[1], 0.1);
    EXPECT_LT(taus[1], 0.2);
}

TEST(SmoothEdges, CurvatureDriftingAlongAStripIsNotSplit)
{
    // A strip whose level drifts from 0.05 to 0.15 along its length (a variable-radius
    // fillet): where the drift speeds up, its values thin out after a peak at 0.05, so a
    // valley shows; but the strip's upper part is bordered along both sides by the slope down
    // to the plane, not by the strip's lower part: it is no patch of its own.
    for (int power : {1, 2, 3}) {
        const RegionGeometry g = latticeRegion(60, 100, [power](double x, double y) {
            // The drift runs a little askew (by up to half a row), so a lattice row's values
            // spread as a scan's would instead of stacking into one histogram bin each.
            const double along = std::clamp((y + 0.5 * std::sin(2.1 * x)) / 86.0, 0.0, 1.0);
            const double level = 0.05 + 0.1 * std::pow(along, power);
            return x < 30.0 ? step(x, 20.0, 0.0, level, 4.0) : step(x, 40.0, level, 0.0, 4.0);
        });
        const std::vector<double> taus = accepted(automaticThresholds(g));
        ASSERT_EQ(taus.size(), 1u) << "plane | strip only, drift as t^" << power;
        EXPECT_LT(taus[0], 0.05);
    }
}

TEST(SmoothEdges, LevelsCloserThanFourNoiseFloorsAreOne)
{
    std::mt19937 rng(11);
    std::normal_distribution<double> noise(0.0, 1.0);
    const double floor = 0.01;
    for (double level : {0.0, 0.025, 0.1}) {
        // A strip at `level` in a plane, both with curvature noise of one floor; |H|, as the
        // fit gives it. 2.5 floors apart the levels are one noisy level; 10 floors apart, two.
        std::vector<double> draws(60 * 60);
        for (double& v : draws) {
            v = floor * noise(rng);
        }
        int next = 0;
        const RegionGeometry g = latticeRegion(
            60, 60,
            [&](double x, double) {
                const double inStrip = x > 20.0 && x < 40.0 ? level : 0.0;
                return std::abs(inStrip + draws[static_cast<size_t>(next++)]);
            },
            floor);
        const size_t expected = level > 4 * floor ? 1u : 0u;
        EXPECT_EQ(accepted(automaticThresholds(g)).size(), expected) << "level " << level;
    }
}

TEST(SmoothEdges, IslandsSmallerThanAPatchOfTheCurvaturesScaleAreLevelled)
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

TEST(SmoothEdges, FreeEndsAreAnchoredOnTheLineAheadOnly)
{
    LineNetwork network;
    network.lines.push_back(straight({0, 0, 0}, {10, 0, 0}));     // heads for x = 13
    network.lines.push_back(straight({0, 20, 0}, {10, 20, 0}));   // too far: 12 away
    network.lines.push_back(straight({14, -10, 0}, {14, -4, 0})); // beside the anchor's end
    const std::vector<Polyline> anchors{straight({13, -2, 0}, {13, 8, 0}),
                                        straight({30, 5, 0}, {30, 6, 0})};
    const std::vector<char> anchored = anchorLineEnds(network, anchors, 5.0, 90.0);
    ASSERT_EQ(anchored.size(), 6u);
    EXPECT_FALSE(anchored[0]);
    EXPECT_TRUE(anchored[1]);
    const Polyline& first = network.lines[0];
    EXPECT_TRUE(first.points.bottomRows(1).isApprox(Eigen::RowVector3d(13, 0, 0)));
    EXPECT_FALSE(anchored[2] || anchored[3]);
    // Its end at (14, -4) is 2.2 from the anchor's end (13, -2), to the side but ahead of it:
    // taken. Its start at (14, -10) is 8 from it: not.
    EXPECT_FALSE(anchored[4]);
    EXPECT_TRUE(anchored[5]);
}

TEST(SmoothEdges, ShortSpursArePrunedAndTheirLoopClosed)
{
    // A loop leaving junction 0 and returning to it, a spur of 4 from it to nothing, and a
    // long branch of 30 from it to nothing.
    LineNetwork network;
    network.junctions.resize(1, 3);
    network.junctions.row(0) << 0, 0, 0;
    network.lines.push_back(
        line({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {0, 0, 0}}, 0, 0));
    network.lines.push_back(straight({0, 0, 0}, {-4, 0, 0}, 0, -1));
    std::vector<char> anchored(4, 0);
    EXPECT_EQ(pruneDanglingLines(network, anchored, 15.0), 1);
    ASSERT_EQ(network.lines.size(), 1u);
    EXPECT_TRUE(network.lines[0].closed);
    EXPECT_EQ(network.lines[0].points.rows(), 4)
        << "a closed line does not repeat its first vertex";
    EXPECT_EQ(network.lines[0].startJunction, -1);

    // The same spur anchored on another line is part of the network: kept.
    LineNetwork kept;
    kept.junctions = network.junctions;
    kept.lines.push_back(line({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {0, 0, 0}}, 0, 0));
    kept.lines.push_back(straight({0, 0, 0}, {-4, 0, 0}, 0, -1));
    std::vector<char> spurAnchored{0, 0, 0, 1};
    EXPECT_EQ(pruneDanglingLines(kept, spurAnchored, 15.0), 0);
    EXPECT_EQ(kept.lines.size(), 2u);
}

TEST(SmoothEdges, ShortOpenPiecesGoUnlessBothEndsAreOnLines)
{
    LineNetwork network;
    network.lines.push_back(straight({0, 0, 0}, {10, 0, 0}));   // short, free: dropped
    network.lines.push_back(straight({0, 5, 0}, {10, 5, 0}));   // short, anchored both ends
    network.lines.push_back(straight({0, 10, 0}, {30, 10, 0})); // long enough
    const std::vector<char> anchored{0, 0, 1, 1, 0, 0};
    EXPECT_EQ(dropOpenPieces(network, anchored, 15.0), 1);
    ASSERT_EQ(network.lines.size(), 2u);
    EXPECT_DOUBLE_EQ(network.lines[0].points(0, 1), 5.0);
    EXPECT_DOUBLE_EQ(network.lines[1].points(0, 1), 10.0);
}

// A curvature step of height 1 read on a grid of 8 spacings and carried back to a square
// lattice: the carried values cross tau = 0.5 over the coarse fit's width, so within two fit
// radii of the lattice's own sampling a line along the step shows only part of it; at the
// coarse cells its points were averaged into, the whole step.
TEST(SmoothEdges, ALineAtACoarserScaleIsJudgedByTheContrastThere)
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
