// SPDX-License-Identifier: LGPL-2.1-or-later
// RegionGeometry.h: the noise estimate and the curvature noise floor on planes, spheres and
// cylinders, whose noise is the noise added.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/smooth/RegionGeometry.h"
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

} // namespace

TEST(RegionGeometry, NoiseEstimateIgnoresCurvatureAndFollowsTheNoise)
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

TEST(RegionGeometry, CurvatureNoiseFloorIsTheSpreadOfANoisyPlane)
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

TEST(RegionGeometry, NoiseEstimateOfACylinderIsTheNoiseAdded)
{
    // A cylinder of radius 20 spacings, clean and with normal noise of sigma spacings: the
    // estimate (a median of heights over the fitted quadric) is below a hundredth of a spacing
    // on the clean surface, whatever its curvature, and near sigma on the noisy one.
    const double spacing = 0.5;
    for (double sigma : {0.0, 0.1, 0.3}) {
        shapes::Sample cylinder = shapes::cylinder(10.0, 30.0, spacing, 4);
        if (sigma > 0.0) {
            shapes::addNormalNoise(cylinder, sigma * spacing, 8);
        }
        const Neighbourhoods N = nearestNeighbours(cylinder.points);
        const NormalMatrix normals = pcaNormals(cylinder.points, N).normals;
        const double noise = estimateNoise(cylinder.points, normals, N, meanSpacing(N));
        if (sigma == 0.0) {
            EXPECT_LT(noise, 0.01);
        } else {
            EXPECT_GT(noise, 0.7 * sigma) << sigma;
            EXPECT_LT(noise, 1.1 * sigma) << sigma;
        }
    }
}
