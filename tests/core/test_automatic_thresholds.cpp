// SPDX-License-Identifier: LGPL-2.1-or-later
// AutomaticThresholds.h: the automatic thresholds on a lattice whose curvature is prescribed
// (levels, a drifting strip, noise).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "FeatureLines/smooth/AutomaticThresholds.h"
#include "RegionLattice.h"

using namespace featurelines;

namespace {

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

} // namespace

TEST(AutomaticThresholds, ValleyAboveTheTopPatchSendsTheSearchBelow)
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

TEST(AutomaticThresholds, StraysJustAboveAFilletDoNotUseUpTheSearch)
{
    // A plane (0) and a strip at 0.1 (a fillet, its sides blurred as in the test above), and
    // stray values above it as the fits at a clean region's edges give them: 20 spread from
    // 0.165 to 0.45, three at 0.12, one at 0.108 and one at 0.103. The first valleys found lie
    // above the strip, one group of strays after another; none holds a patch above it, and each
    // sends the search below it. Peeling off fewer values than a patch refuses no curvature
    // level and does not use up the search: it reaches plane | strip.
    int stray = 0;
    const RegionGeometry g = latticeRegion(70, 60, [&stray](double x, double y) {
        if (std::fmod(x * 7.0 + y * 13.0, 101.0) < 1.0 && stray < 25) {
            ++stray;
            return stray <= 20   ? 0.15 + 0.015 * stray
                   : stray <= 23 ? 0.12
                   : stray == 24 ? 0.108
                                 : 0.103;
        }
        const double wave = 3.0 * std::sin(y / 7.0);
        return x < 40.0 ? step(x, 25.0 + wave, 0.0, 0.1, 4.0) : step(x, 55.0 + wave, 0.1, 0.0, 4.0);
    });
    ASSERT_EQ(stray, 25);
    const std::vector<ThresholdDecision> d = automaticThresholds(g);
    ASSERT_GE(d.size(), 4u);
    for (int i = 0; i < 3; ++i) {
        EXPECT_FALSE(d[i].accepted) << i;
        EXPECT_GT(d[i].result.threshold, 0.1) << i;
    }
    const std::vector<double> taus = accepted(d);
    ASSERT_EQ(taus.size(), 1u);
    EXPECT_GT(taus[0], 0.0);
    EXPECT_LT(taus[0], 0.1);
}

TEST(AutomaticThresholds, ThreeLevelsGiveTwoThresholds)
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

TEST(AutomaticThresholds, CurvatureDriftingAlongAStripIsNotSplit)
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

TEST(AutomaticThresholds, LevelsCloserThanFourNoiseFloorsAreOne)
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
