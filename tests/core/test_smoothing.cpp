// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cmath>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "FeatureLines/curvature/Smoothing.h"
#include "SampledShapes.h"

using namespace featurelines;

namespace {

/// Root mean square distance of the points to the sphere of radius r at the origin.
double rmsDistanceToSphere(const PointMatrix& P, double r)
{
    double sum = 0.0;
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        sum += std::pow(P.row(i).norm() - r, 2);
    }
    return std::sqrt(sum / P.rows());
}

double meanRadius(const PointMatrix& P)
{
    return P.rowwise().norm().mean();
}

std::vector<int> everyPoint(Eigen::Index n)
{
    std::vector<int> all(n);
    std::iota(all.begin(), all.end(), 0);
    return all;
}

} // namespace

TEST(Smoothing, TaubinRemovesNoiseWithoutShrinking)
{
    const double r = 20.0;
    shapes::Sample s = shapes::sphere(r, 1.0, 1);
    shapes::addNormalNoise(s, 0.2, 2);
    const Neighbourhoods N = nearestNeighbours(s.points, {16, 0});
    const PointMatrix smoothed = laplacianSmooth(s.points, N, everyPoint(s.size()));
    EXPECT_LT(rmsDistanceToSphere(smoothed, r), 0.5 * rmsDistanceToSphere(s.points, r));
    EXPECT_NEAR(meanRadius(smoothed), r, 0.01 * r);
}

TEST(Smoothing, PlainLaplacianShrinksMoreThanTaubin)
{
    const shapes::Sample s = shapes::sphere(20.0, 1.0, 3);
    const Neighbourhoods N = nearestNeighbours(s.points, {16, 0});
    SmoothingOptions plain;
    plain.mu = 0.0;
    const double taubin = meanRadius(laplacianSmooth(s.points, N, everyPoint(s.size())));
    const double laplacian = meanRadius(laplacianSmooth(s.points, N, everyPoint(s.size()), plain));
    EXPECT_LT(laplacian, taubin);
    EXPECT_LT(laplacian, 20.0);
}

TEST(Smoothing, SubsetIsNotPulledOverASharpEdge)
{
    // Face +x of a cube alone: its neighbours on the other faces are ignored, so even the
    // points next to the edges stay on the plane x = edge/2. Other points never move.
    const shapes::Sample s = shapes::cube(20.0, 1.0, 4);
    const Neighbourhoods N = nearestNeighbours(s.points, {16, 0});
    std::vector<int> face;
    for (Eigen::Index i = 0; i < s.size(); ++i) {
        if (s.part[i] == 0) {
            face.push_back(static_cast<int>(i));
        }
    }
    const PointMatrix smoothed = laplacianSmooth(s.points, N, face);
    std::vector<char> inFace(s.size(), 0);
    for (const int i : face) {
        inFace[i] = 1;
        EXPECT_NEAR(smoothed(i, 0), 10.0, 1e-12) << "point " << i;
    }
    for (Eigen::Index i = 0; i < s.size(); ++i) {
        if (!inFace[i]) {
            EXPECT_EQ(
                std::memcmp(smoothed.row(i).data(), s.points.row(i).data(), 3 * sizeof(double)), 0)
                << "point " << i << " outside the subset moved";
        }
    }
}

TEST(Smoothing, ZeroIterationsChangeNothing)
{
    const shapes::Sample s = shapes::sphere(5.0, 1.0, 5);
    const Neighbourhoods N = nearestNeighbours(s.points, {8, 0});
    SmoothingOptions none;
    none.iterations = 0;
    EXPECT_EQ(laplacianSmooth(s.points, N, everyPoint(s.size()), none), s.points);
}

TEST(Smoothing, BadSubsetThrows)
{
    const shapes::Sample s = shapes::sphere(5.0, 1.0, 6);
    const Neighbourhoods N = nearestNeighbours(s.points, {8, 0});
    EXPECT_THROW(laplacianSmooth(s.points, N, {0, 1, static_cast<int>(s.size())}),
                 std::invalid_argument);
    EXPECT_THROW(laplacianSmooth(s.points, N, {-1}), std::invalid_argument);
    EXPECT_THROW(laplacianSmooth(s.points, N, {3, 4, 3}), std::invalid_argument);
}
