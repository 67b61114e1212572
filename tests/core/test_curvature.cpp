// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "FeatureLines/curvature/Curvature.h"
#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/curvature/Smoothing.h"
#include "SampledShapes.h"

using namespace featurelines;

namespace {

/// Largest relative error |H - truth| / truth over the points where `keep` is true.
double worstRelativeError(const Eigen::VectorXd& H, double truth,
                          const std::vector<char>& keep = {})
{
    double worst = 0.0;
    for (Eigen::Index i = 0; i < H.size(); ++i) {
        if (keep.empty() || keep[i]) {
            worst = std::max(worst, std::abs(H(i) - truth) / truth);
        }
    }
    return worst;
}

double median(std::vector<double> values)
{
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

/// Curvature of a sample with k = 16 neighbours and PCA normals, as the pipeline does it.
Eigen::VectorXd curvatureOf(const PointMatrix& P, const CurvatureOptions& options = {})
{
    const Neighbourhoods N = nearestNeighbours(P, {16, 0});
    return meanCurvature(P, pcaNormals(P, N).normals, N, options);
}

} // namespace

TEST(Curvature, PlaneIsFlat)
{
    const shapes::Sample s = shapes::plane(30.0, 1.0, 1);
    EXPECT_LT(curvatureOf(s.points).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(Curvature, SphereIsOneOverRadius)
{
    // r = 20 spacings: every point within 2% of 1/r.
    const shapes::Sample s = shapes::sphere(20.0, 1.0, 2);
    EXPECT_LT(worstRelativeError(curvatureOf(s.points), 1.0 / 20.0), 0.02);
}

TEST(Curvature, EachPointIsFittedOnItsOwn)
{
    // The points are fitted two at a time; a point without a normal gives 0 and changes
    // nothing for the point beside it. An odd number of points: the last is fitted alone.
    shapes::Sample s = shapes::sphere(20.0, 1.0, 2);
    const Eigen::Index n = s.points.rows() % 2 == 1 ? s.points.rows() : s.points.rows() - 1;
    const PointMatrix P = s.points.topRows(n);
    const Neighbourhoods N = nearestNeighbours(P, {16, 0});
    const NormalMatrix normals = pcaNormals(P, N).normals;
    const Eigen::VectorXd H = meanCurvature(P, normals, N);
    EXPECT_LT(worstRelativeError(H, 1.0 / 20.0), 0.02);
    NormalMatrix some = normals;
    const std::vector<Eigen::Index> without{0, 5, 8, 9, n - 1};
    for (const Eigen::Index i : without) {
        some.row(i).setZero();
    }
    const Eigen::VectorXd G = meanCurvature(P, some, N);
    for (Eigen::Index i = 0; i < n; ++i) {
        const bool zeroed = std::find(without.begin(), without.end(), i) != without.end();
        EXPECT_EQ(G(i), zeroed ? 0.0 : H(i)) << "point " << i;
    }
}

TEST(Curvature, SphereOfOtherUnitScalesInversely)
{
    // The same sphere in a unit 1000 times smaller: curvature 1000 times larger.
    const shapes::Sample s = shapes::sphere(20.0, 1.0, 2);
    const PointMatrix small = s.points * 1e-3;
    EXPECT_LT(worstRelativeError(curvatureOf(small), 1.0 / 20e-3), 0.02);
}

TEST(Curvature, CylinderIsOneOverTwiceRadius)
{
    // Open ends included: a one-sided neighbourhood still fits the same quadric.
    const shapes::Sample s = shapes::cylinder(20.0, 60.0, 1.0, 3);
    EXPECT_LT(worstRelativeError(curvatureOf(s.points), 1.0 / 40.0), 0.02);
}

TEST(Curvature, LargestPrincipalCurvatureIsOneOverRadiusOnSphereAndCylinderAlike)
{
    // What tells a blend's radius: 1/r on a cylinder (where H is 1/(2r)) as on a sphere; a
    // plane gives 0.
    const shapes::Sample sphere = shapes::sphere(20.0, 1.0, 2);
    const shapes::Sample cylinder = shapes::cylinder(20.0, 60.0, 1.0, 3);
    const shapes::Sample plane = shapes::plane(30.0, 1.0, 1);
    for (const shapes::Sample* s : {&sphere, &cylinder, &plane}) {
        const Neighbourhoods N = nearestNeighbours(s->points, {16, 0});
        const NormalMatrix normals = pcaNormals(s->points, N).normals;
        Eigen::VectorXd kappa(s->points.rows());
        for (Eigen::Index i = 0; i < kappa.size(); ++i) {
            kappa(i) = largestCurvature(s->points, normals, N, i);
        }
        if (s == &plane) {
            EXPECT_LT(kappa.cwiseAbs().maxCoeff(), 1e-9);
        } else {
            EXPECT_LT(worstRelativeError(kappa, 1.0 / 20.0), 0.02);
        }
    }
    // A point without a normal has no fit.
    const Neighbourhoods N = nearestNeighbours(sphere.points, {16, 0});
    NormalMatrix normals = pcaNormals(sphere.points, N).normals;
    normals.row(7).setZero();
    EXPECT_TRUE(std::isnan(largestCurvature(sphere.points, normals, N, 7)));
}

TEST(Curvature, SignFollowsTheNormal)
{
    const shapes::Sample s = shapes::sphere(20.0, 1.0, 4);
    const Neighbourhoods N = nearestNeighbours(s.points, {16, 0});
    CurvatureOptions options;
    options.signedCurvature = true;
    // Outward normals: the sphere bends away from them, H = +1/r; inward: -1/r.
    const Eigen::VectorXd outward = meanCurvature(s.points, s.normals, N, options);
    const Eigen::VectorXd inward = meanCurvature(s.points, -s.normals, N, options);
    EXPECT_LT(worstRelativeError(outward, 1.0 / 20.0), 0.02);
    EXPECT_LT(worstRelativeError(-inward, 1.0 / 20.0), 0.02);
}

TEST(Curvature, NoisySphereAfterSmoothing)
{
    // Noise sigma = 0.2 spacing along the normal, then Taubin smoothing (10 passes). A looser
    // bound than noise-free: the median of |H| within 5% of 1/r and the median per-point
    // error below 25%, less than half the error before smoothing.
    shapes::Sample s = shapes::sphere(20.0, 1.0, 5);
    shapes::addNormalNoise(s, 0.2, 6);
    const double truth = 1.0 / 20.0;
    const Neighbourhoods N = nearestNeighbours(s.points, {16, 0});
    std::vector<int> all(s.size());
    std::iota(all.begin(), all.end(), 0);
    SmoothingOptions smoothing;
    smoothing.iterations = 10;
    const PointMatrix smoothed = laplacianSmooth(s.points, N, all, smoothing);

    const Eigen::VectorXd before = curvatureOf(s.points);
    const Eigen::VectorXd after = curvatureOf(smoothed);
    std::vector<double> errorBefore, errorAfter, valueAfter;
    for (Eigen::Index i = 0; i < s.size(); ++i) {
        errorBefore.push_back(std::abs(before(i) - truth) / truth);
        errorAfter.push_back(std::abs(after(i) - truth) / truth);
        valueAfter.push_back(after(i));
    }
    EXPECT_NEAR(median(valueAfter), truth, 0.05 * truth);
    EXPECT_LT(median(errorAfter), 0.25);
    EXPECT_LT(median(errorAfter), 0.5 * median(errorBefore));
}

TEST(Curvature, CollinearNeighboursGiveZeroNotNaN)
{
    // Points on a line: no quadric is determined; the answer is 0, finite.
    PointMatrix P(40, 3);
    for (int i = 0; i < 40; ++i) {
        P.row(i) << 0.5 * i, 0.25 * i, -0.1 * i;
    }
    const Neighbourhoods N = nearestNeighbours(P, {8, 0});
    NormalMatrix normals(40, 3);
    normals.rowwise() = Eigen::RowVector3d(0.0, 0.0, 1.0);
    const Eigen::VectorXd H = meanCurvature(P, normals, N);
    EXPECT_TRUE(H.allFinite());
    EXPECT_EQ(H.cwiseAbs().maxCoeff(), 0.0);
}

TEST(Curvature, QuadricHeightIsAPointsOffsetFromItsNeighboursSurface)
{
    // On a sphere of radius 20 spacings the quadric through a point's neighbours passes
    // through the point to third order; points lifted by 0.3 spacing along their outward
    // normal sit 0.3 above it: the quadric lies 0.3 below them, whatever the curvature.
    shapes::Sample s = shapes::sphere(20.0, 1.0, 8);
    const Neighbourhoods N = nearestNeighbours(s.points, {16, 0});
    const std::vector<Eigen::Index> lifted{3, 100, 777};
    for (const Eigen::Index i : lifted) {
        s.points.row(i) += 0.3 * s.normals.row(i);
    }
    // Elsewhere (away from the lifted points and the neighbourhoods they are in).
    const auto touched = [&](Eigen::Index i) {
        for (const Eigen::Index l : lifted) {
            if (i == l || (N.indices.row(i).array() == static_cast<int>(l)).any()) {
                return true;
            }
        }
        return false;
    };
    int checked = 0;
    for (Eigen::Index i = 0; i < s.size(); i += 7) {
        if (!touched(i)) {
            EXPECT_NEAR(quadricHeight(s.points, s.normals, N, i), 0.0, 0.02) << "point " << i;
            ++checked;
        }
    }
    EXPECT_GT(checked, 100);
    for (const Eigen::Index i : lifted) {
        // (A fit through the point itself too would give about 16 / 17 of it.)
        EXPECT_NEAR(quadricHeight(s.points, s.normals, N, i), -0.3, 0.005) << "point " << i;
        // The fit reads the normal's line, not its sign.
        EXPECT_NEAR(quadricHeight(s.points, -s.normals, N, i), 0.3, 0.005) << "point " << i;
    }
    // No normal, or neighbours on a line: no height.
    NormalMatrix none = s.normals;
    none.row(5).setZero();
    EXPECT_TRUE(std::isnan(quadricHeight(s.points, none, N, 5)));
    PointMatrix line(40, 3);
    for (int i = 0; i < 40; ++i) {
        line.row(i) << 0.5 * i, 0.25 * i, -0.1 * i;
    }
    NormalMatrix up(40, 3);
    up.rowwise() = Eigen::RowVector3d(0.0, 0.0, 1.0);
    EXPECT_TRUE(std::isnan(quadricHeight(line, up, nearestNeighbours(line, {8, 0}), 20)));
}

TEST(Curvature, BadInputThrows)
{
    const shapes::Sample s = shapes::plane(10.0, 1.0, 7);
    const Neighbourhoods N = nearestNeighbours(s.points, {8, 0});
    EXPECT_THROW(meanCurvature(s.points, s.normals, N, {4, false, 0}), std::invalid_argument);
    EXPECT_THROW(meanCurvature(s.points, s.normals, N, {9, false, 0}), std::invalid_argument);
    EXPECT_THROW(meanCurvature(s.points, s.normals.topRows(5), N), std::invalid_argument);
}
