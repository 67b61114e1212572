// SPDX-License-Identifier: LGPL-2.1-or-later
// The curvature step across a strip: a straight side joined to a parabola with the same value
// and slope is placed at the join; one curvature across the whole strip has no step.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "FeatureLines/smooth/StripFit.h"

using namespace featurelines;

namespace {

/// Points on a grid u in [-3, 3], a in [-2, 2] at height profile(u) plus normal noise 0.001.
std::vector<StripPoint> strip(const std::function<double(double)>& profile)
{
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.001);
    std::vector<StripPoint> s;
    for (int i = -30; i <= 30; ++i) {
        for (int j = -4; j <= 4; ++j) {
            const double u = 0.1 * i + 0.013, a = 0.5 * j;
            s.push_back({u, a, profile(u) + noise(rng)});
        }
    }
    return s;
}

const StepSearch search{2.0, 0.25, 25.0, 12};

} // namespace

TEST(StripFit, AFaceMeetingAFilletIsPlacedAtTheJoin)
{
    for (double join : {-1.0, 0.5}) {
        std::vector<StripPoint> s = strip(
            [&](double u) { return 0.2 * u + (u > join ? 0.3 * (u - join) * (u - join) : 0); });
        const StepFit fit = curvatureStep(s, search);
        EXPECT_DOUBLE_EQ(fit.u, join);
        EXPECT_EQ(fit.edge, 0);
    }
    // The parabola on the low side.
    std::vector<StripPoint> s =
        strip([](double u) { return u < 0.25 ? -0.3 * (0.25 - u) * (0.25 - u) : 0.0; });
    EXPECT_DOUBLE_EQ(curvatureStep(s, search).u, 0.25);
}

TEST(StripFit, APlaneHasNoStep)
{
    std::vector<StripPoint> s = strip([](double u) { return 0.1 * u; });
    EXPECT_TRUE(std::isnan(curvatureStep(s, search).u));
}

TEST(StripFit, TooFewPointsNoStep)
{
    std::vector<StripPoint> s = {{-1, 0, 0}, {0, 0, 0}, {1, 0, 1}, {2, 0, 4}};
    const StepFit fit = curvatureStep(s, search);
    EXPECT_TRUE(std::isnan(fit.u));
    EXPECT_EQ(fit.edge, 0);
}
