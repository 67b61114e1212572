// SPDX-License-Identifier: LGPL-2.1-or-later
// The curvature of a smooth region at a coarser scale (CurvatureScale.h, chosen in
// analyseRegion): the grid averaging, the carrying back, and the choice itself on shapes whose
// answer is known: a noisy plane and a noisy cylinder have one level at every scale, a dense
// noisy rounded cube hides its fillets in the noise at its own spacing and shows them coarser.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numeric>
#include <random>
#include <set>
#include <string>

#include "FeatureLines/Extraction.h"
#include "FeatureLines/curvature/CurvatureScale.h"
#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/smooth/AutomaticThresholds.h"
#include "FeatureLines/smooth/RegionGeometry.h"
#include "SampledShapes.h"

using namespace featurelines;

namespace {

RegionGeometry wholeCloud(const PointMatrix& P, const SmoothEdgeOptions& options = {})
{
    const Neighbourhoods N = nearestNeighbours(P);
    std::vector<int> members(static_cast<size_t>(P.rows()));
    std::iota(members.begin(), members.end(), 0);
    const std::vector<int> region(members.size(), 0);
    return analyseRegion(P, N, region, members, 0, meanSpacing(N), options);
}

} // namespace

TEST(CurvatureScale, GridCentroidsAreTheMeansOfTheirCells)
{
    // Four points in each unit cell of [0, 4)^2 at heights 0.2 and 0.4: centroids at the
    // cell centres, height 0.3.
    PointMatrix P(64, 3);
    Eigen::Index row = 0;
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            P.row(row++) << 0.25 + 0.5 * i, 0.25 + 0.5 * j, (i + j) % 2 ? 0.4 : 0.2;
        }
    }
    const GridCentroids grid = gridCentroids(P, 1.0);
    ASSERT_EQ(grid.points.rows(), 16);
    ASSERT_EQ(grid.cellOf.size(), 64u);
    std::vector<int> counts(16, 0);
    for (Eigen::Index p = 0; p < P.rows(); ++p) {
        const int c = grid.cellOf[static_cast<size_t>(p)];
        ++counts[static_cast<size_t>(c)];
        EXPECT_DOUBLE_EQ(grid.points(c, 0), std::floor(P(p, 0)) + 0.5);
        EXPECT_DOUBLE_EQ(grid.points(c, 1), std::floor(P(p, 1)) + 0.5);
        EXPECT_NEAR(grid.points(c, 2), 0.3, 1e-12);
    }
    for (int c : counts) {
        EXPECT_EQ(c, 4);
    }
    EXPECT_THROW(gridCentroids(P, 0.0), std::invalid_argument);
    EXPECT_THROW(gridCentroids(PointMatrix(0, 3), 1.0), std::invalid_argument);
}

// Points keyed by their grid cell: one key per cell, cells in Morton order, a cell's points in
// index order.
TEST(CurvatureScale, GridCellKeysGroupACellsPointsInIndexOrder)
{
    PointMatrix P(5, 3);
    P << 1.5, 0.2, 0.1, // cell (1, 0, 0)
        0.1, 0.1, 0.1,  // cell (0, 0, 0)
        1.9, 0.9, 0.5,  // cell (1, 0, 0)
        0.2, 1.2, 0.0,  // cell (0, 1, 0)
        0.9, 0.0, 0.9;  // cell (0, 0, 0)
    const auto keyed = gridCellKeys(P, Eigen::RowVector3d::Zero(), 1.0);
    ASSERT_EQ(keyed.size(), 5u);
    const std::vector<std::pair<std::uint64_t, int>> expected = {
        {0, 1}, {0, 4}, {1, 0}, {1, 2}, {2, 3}}; // Morton keys: x bit 0, y bit 1
    EXPECT_EQ(keyed, expected);
}

TEST(CurvatureScale, CarriedValuesFollowTheCoarseField)
{
    const shapes::Sample plane = shapes::plane(40.0, 0.5, 3);
    const GridCentroids grid = gridCentroids(plane.points, 2.0);
    const Neighbourhoods N = nearestNeighbours(grid.points);
    const double width = 0.5 * meanSpacing(N);
    // A constant stays what it is; a linear field is carried to within a tenth of a cell
    // (the Gaussian's weights are symmetric about the point where the cells surround it).
    const Eigen::VectorXd constant = Eigen::VectorXd::Constant(grid.points.rows(), 3.0);
    const Eigen::VectorXd c = valuesAtPoints(plane.points, grid, N, constant, width);
    EXPECT_NEAR(c.minCoeff(), 3.0, 1e-12);
    EXPECT_NEAR(c.maxCoeff(), 3.0, 1e-12);
    const Eigen::VectorXd linear = grid.points.col(0);
    const Eigen::VectorXd l = valuesAtPoints(plane.points, grid, N, linear, width);
    for (Eigen::Index p = 0; p < plane.size(); ++p) {
        if (plane.points.row(p).head<2>().cwiseAbs().maxCoeff() < 16.0) {
            EXPECT_NEAR(l[p], plane.points(p, 0), 0.2) << p;
        }
    }
    EXPECT_THROW(valuesAtPoints(plane.points, grid, N, constant, 0.0), std::invalid_argument);
}

// The coarse scales themselves make no level of a plane's noise: tried on a noisy plane (the
// plane tolerance, which spares faces the trials, set to 0), no scale accepts a threshold.
TEST(CurvatureScale, ANoisyPlaneHasOneLevelAtEveryScale)
{
    shapes::Sample plane = shapes::plane(60.0, 0.5, 5);
    shapes::addNormalNoise(plane, 0.3 * 0.5, 6);
    SmoothEdgeOptions options;
    options.scales.planeTolerance = 0.0;
    const RegionGeometry g = wholeCloud(plane.points, options);
    ASSERT_GE(g.scaleTrials.size(), 2u) << "the noise hides large radii: coarser scales tried";
    EXPECT_EQ(g.scaleTrials.front().acceptedThresholds, -1) << "own scale not weighed";
    for (size_t t = 1; t < g.scaleTrials.size(); ++t) {
        EXPECT_EQ(g.scaleTrials[t].acceptedThresholds, 0) << "scale " << g.scaleTrials[t].scale;
    }
    EXPECT_EQ(g.curvatureScale, 1.0);
    EXPECT_FALSE(g.coarse);
}

// Gaussian noise of standard deviation s about a plane: all but a thousandth of the points
// lie within 3.29 s of it (the normal distribution's two-sided 0.999 quantile), all within
// the noise's largest value; a half cylinder of radius r strays 2 r / pi from its plane.
TEST(CurvatureScale, PlaneDeviationIsTheNoiseOfAPlaneAndTheBulgeOfACylinder)
{
    const double sigma = 0.05;
    shapes::Sample plane = shapes::plane(60.0, 0.3, 7);
    shapes::addNormalNoise(plane, sigma, 8);
    // A tilted copy: the plane is fitted, not assumed to be z = 0.
    const Eigen::Matrix3d turn =
        (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, 0.5).normalized())).toRotationMatrix();
    const PointMatrix tilted =
        (plane.points * turn.transpose()).rowwise() + Eigen::RowVector3d(3.0, -2.0, 5.0);
    EXPECT_NEAR(planeDeviation(tilted, 0.001), 3.29 * sigma, 0.3 * sigma);
    EXPECT_NEAR(planeDeviation(tilted, 0.3173), sigma, 0.05 * sigma) << "one standard deviation";
    EXPECT_NEAR(planeDeviation(tilted, 0.0), plane.points.col(2).cwiseAbs().maxCoeff(),
                0.02 * sigma)
        << "the largest distance";
    // The same plane a million units away: the same distances to the digits left.
    const PointMatrix far = tilted.rowwise() + Eigen::RowVector3d(1e6, -1e6, 2e6);
    EXPECT_NEAR(planeDeviation(far, 0.001), planeDeviation(tilted, 0.001), 1e-6);

    const double r = 10.0;
    PointMatrix half(10000, 3); // 4 r long: its plane is the one through its two rims
    for (Eigen::Index i = 0; i < half.rows(); ++i) {
        const double t = M_PI * (static_cast<double>(i % 100) + 0.5) / 100.0;
        half.row(i) << r * std::cos(t), r * std::sin(t), 0.4 * static_cast<double>(i / 100);
    }
    // The plane passes at the mean height 2 r / pi: the rims lie 0.64 r from it.
    EXPECT_NEAR(planeDeviation(half, 0.001), 2.0 * r / M_PI, 0.02 * r);
    EXPECT_THROW(planeDeviation(half.topRows(2), 0.001), std::invalid_argument);
    EXPECT_THROW(planeDeviation(half, 1.0), std::invalid_argument);
}

// With the default tolerance a noisy face tries no coarser scale: nothing to find, and the
// trials' cost (a third of the region's) spared. The same plane with the tolerance at 0 tries
// them (ANoisyPlaneHasOneLevelAtEveryScale), and so does the cylinder below.
TEST(CurvatureScale, ANoisyFaceTriesNoCoarserScale)
{
    shapes::Sample plane = shapes::plane(60.0, 0.5, 5);
    shapes::addNormalNoise(plane, 0.3 * 0.5, 6);
    const RegionGeometry face = wholeCloud(plane.points);
    EXPECT_TRUE(face.scaleTrials.empty()) << face.scaleTrials.size() << " scales weighed";
    EXPECT_EQ(face.curvatureScale, 1.0);
}

// A noisy half cylinder cut off on all four sides by the region's rim: at the rim the fit and
// the smoothing see one side only, and at a coarse scale their bias would form a band of
// higher curvature along the rim, a level of its own. The rim's values are taken from the
// interior: one level at every scale.
TEST(CurvatureScale, ACylinderCutByTheRimHasOneLevelAtEveryScale)
{
    const double r = 12.0, height = 15.0, h = 0.35, sigma = 0.1;
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> jitter(-0.25, 0.25);
    std::normal_distribution<double> gauss(0.0, sigma);
    const int nu = static_cast<int>(M_PI * r / h), nz = static_cast<int>(height / h);
    PointMatrix P(nu * nz, 3);
    for (int a = 0; a < nu; ++a) {
        for (int b = 0; b < nz; ++b) {
            const double t = (a + 0.5 + jitter(rng)) * h / r, z = (b + 0.5 + jitter(rng)) * h;
            const double radius = r + gauss(rng);
            P.row(a * nz + b) << radius * std::cos(t), radius * std::sin(t), z;
        }
    }
    SmoothEdgeOptions options;
    options.scales.minPoints = 500; // the patch is small: let it go to coarse scales
    const RegionGeometry g = wholeCloud(P, options);
    ASSERT_GE(g.scaleTrials.size(), 2u);
    for (size_t t = 1; t < g.scaleTrials.size(); ++t) {
        EXPECT_EQ(g.scaleTrials[t].acceptedThresholds, 0) << "scale " << g.scaleTrials[t].scale;
    }
}

// Fillets of radius 32 spacings under noise of 0.3 spacing: their curvature 1 / (2 r) lies
// within a few noise floors of the faces' at the cloud's own spacing, where no threshold is
// significant (the paper's single scale finds no smooth edge). About three spacings coarser
// both levels of Fig. 7 stand clear: closed lines around the 8 corners and 6 closed face
// loops, each within three spacings of that scale of its true border.
TEST(CurvatureScale, ADenseNoisyRoundedCubeShowsItsFilletsAtACoarserScale)
{
    const double edge = 30.0, radius = 8.0, h = 0.25;
    shapes::Sample s = shapes::roundedCube(edge, radius, h, 5);
    shapes::addNormalNoise(s, 0.3 * h, 15);

    ExtractionOptions single;
    single.smooth.scales.maxScale = 1.0;
    const ExtractionResult one = extractFeatureLines(s.points, single);
    ASSERT_EQ(one.regions.size(), 1u);
    EXPECT_TRUE(one.regions[0].thresholds.empty());

    const ExtractionResult r = extractFeatureLines(s.points);
    ASSERT_EQ(r.regions.size(), 1u);
    const RegionReport& region = r.regions[0];
    EXPECT_GT(region.curvatureScale, 2.0);
    ASSERT_EQ(region.thresholds.size(), 2u) << "planes | fillets | corners";
    // The benchmark's 3 spacings (docs/ACCURACY.md), at the spacing the curvature was
    // computed at.
    const double tolerance = 3.0 * region.curvatureScale * r.spacing;
    const double half = edge / 2, a = half - radius;

    std::set<int> corners;
    int faces = 0;
    for (const FeatureLine& l : r.lines) {
        ASSERT_EQ(l.type, LineType::Smooth);
        const Eigen::RowVector3d c = l.points.colwise().mean();
        if (l.level == 0) {
            EXPECT_TRUE(l.closed || (l.startJunction >= 0 && l.endJunction >= 0)) << "no free end";
            // Around a spherical corner: on its sphere, near a corner|fillet tangent arc.
            const Eigen::RowVector3d centre(std::copysign(a, c.x()), std::copysign(a, c.y()),
                                            std::copysign(a, c.z()));
            for (Eigen::Index i = 0; i < l.points.rows(); ++i) {
                const Eigen::RowVector3d d = l.points.row(i) - centre;
                EXPECT_NEAR(d.norm(), radius, tolerance);
            }
            corners.insert((c.x() > 0) + 2 * (c.y() > 0) + 4 * (c.z() > 0));
        }
        if (l.level == 1) {
            EXPECT_TRUE(l.closed);
            ++faces;
            Eigen::Index axis;
            c.cwiseAbs().maxCoeff(&axis);
            const double side = c[axis] > 0 ? 1.0 : -1.0;
            for (Eigen::Index i = 0; i < l.points.rows(); ++i) {
                // Distance to the border of the flat square of that face.
                const Eigen::RowVector3d p = l.points.row(i);
                double across = 0.0;
                for (int t = 0; t < 3; ++t) {
                    if (t != axis) {
                        across = std::max(across, std::abs(p[t]));
                    }
                }
                EXPECT_LT(std::hypot(p[axis] - side * half, across - a), tolerance);
            }
        }
    }
    EXPECT_EQ(corners.size(), 8u) << "closed lines around every corner";
    EXPECT_EQ(faces, 6);
}

TEST(CurvatureScale, AbsurdScaleOptionsAreRefusedWithAMessage)
{
    const shapes::Sample plane = shapes::plane(10.0, 0.5, 4);
    for (const auto& set : std::vector<std::function<void(CurvatureScaleOptions&)>>{
             [](CurvatureScaleOptions& o) { o.maxScale = 0.5; },
             [](CurvatureScaleOptions& o) { o.maxScale = std::nan(""); },
             [](CurvatureScaleOptions& o) { o.carryWidth = 0.0; },
             [](CurvatureScaleOptions& o) { o.rimWidth = -1.0; },
             [](CurvatureScaleOptions& o) { o.minPoints = -5; },
             [](CurvatureScaleOptions& o) { o.planeTolerance = -1.0; },
             [](CurvatureScaleOptions& o) { o.planeTolerance = std::nan(""); }}) {
        SmoothEdgeOptions options;
        set(options.scales);
        try {
            wholeCloud(plane.points, options);
            ADD_FAILURE() << "accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("curvature scales"), std::string::npos)
                << e.what();
        }
    }
}
