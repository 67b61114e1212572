// SPDX-License-Identifier: LGPL-2.1-or-later
// Histogram thresholding (Sec. 2.1-2.4) on histograms with known valleys and on a sampled
// rounded cube whose three patches have known mean curvature (Fig. 2-5 of the paper).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "FeatureLines/curvature/Curvature.h"
#include "FeatureLines/smooth/HistogramThreshold.h"
#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/curvature/Smoothing.h"
#include "SampledShapes.h"

using namespace featurelines;

namespace {

/// n seeded normal samples of mean `mean` and deviation `sigma`, appended to `values`.
void addGaussian(std::vector<double>& values, double mean, double sigma, int n, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> gauss(mean, sigma);
    for (int i = 0; i < n; ++i) {
        values.push_back(gauss(rng));
    }
}

/// Values whose histogram with counts.size() bins on [0, counts.size()] is exactly `counts`:
/// each value sits at its bin's centre, and 0 and counts.size() pin the range (counted in the
/// first and last bin, which therefore must be at least 1).
std::vector<double> valuesWithCounts(const std::vector<long>& counts)
{
    std::vector<double> values{0.0, static_cast<double>(counts.size())};
    for (std::size_t bin = 0; bin < counts.size(); ++bin) {
        const long pinned = (bin == 0 || bin + 1 == counts.size()) ? 1 : 0;
        for (long j = 0; j < counts[bin] - pinned; ++j) {
            values.push_back(static_cast<double>(bin) + 0.5);
        }
    }
    return values;
}

long countAtMost(const std::vector<double>& values, double threshold)
{
    return std::count_if(values.begin(), values.end(), [&](double v) { return v <= threshold; });
}

/// Reference search written straight from Sec. 2.2 with sums recomputed for every (i, k) and the
/// same tie rule as the library (larger e, then smaller tau, then smaller start).
struct Reference
{
    double ratio = -1.0;
    int start = 0;
    int k = 0;
};

Reference bruteForce(const std::vector<long>& h, bool allStarts, double minPeak)
{
    const int L = static_cast<int>(h.size());
    Reference best;
    for (int i = 0; i <= (allStarts ? L - 2 : 0); ++i) {
        for (int k = 1; k <= (L - i) / 2; ++k) {
            const long b1 = std::accumulate(h.begin() + i, h.begin() + i + k, 0L);
            const long b2 = std::accumulate(h.begin() + i + k, h.begin() + i + 2 * k, 0L);
            if (b1 < minPeak) {
                continue;
            }
            const double e = b2 != 0 ? double(b1) / double(b2) : double(b1);
            const bool better =
                e > best.ratio ||
                (e == best.ratio &&
                 (i + k < best.start + best.k || (i + k == best.start + best.k && i < best.start)));
            if (better) {
                best = {e, i, k};
            }
        }
    }
    return best;
}

} // namespace

// ---- Sec. 2.1: the histogram ---------------------------------------------------------------

TEST(HistogramThreshold, BinRuleLowerEdgeInclusiveAndMaximumInLastBin)
{
    // [0, 4] in 4 bins of width 1: 1.0 starts bin 1, 4.0 (the maximum) joins the last bin.
    const Histogram h = buildHistogram({0.0, 0.5, 1.0, 1.999, 2.0, 3.5, 4.0}, 4);
    EXPECT_DOUBLE_EQ(h.minimum, 0.0);
    EXPECT_DOUBLE_EQ(h.maximum, 4.0);
    EXPECT_DOUBLE_EQ(h.binWidth, 1.0);
    EXPECT_EQ(h.counts, (std::vector<long>{2, 2, 1, 2}));
    EXPECT_DOUBLE_EQ(h.upperEdge(1), 2.0);
}

TEST(HistogramThreshold, AllEqualValuesFillOneBin)
{
    const Histogram h = buildHistogram(std::vector<double>(7, 0.25), 5);
    EXPECT_EQ(h.counts, (std::vector<long>{7, 0, 0, 0, 0}));
    EXPECT_DOUBLE_EQ(h.binWidth, 0.0);
    EXPECT_THROW(findThreshold(std::vector<double>(7, 0.25)), std::invalid_argument);
}

TEST(HistogramThreshold, CountsSumToTheValues)
{
    std::vector<double> values;
    addGaussian(values, 0.0, 1.0, 10000, 7);
    for (int bins : {2, 3, 50, 997, 10000}) {
        const Histogram h = buildHistogram(values, bins);
        EXPECT_EQ(std::accumulate(h.counts.begin(), h.counts.end(), 0L), 10000) << bins;
    }
}

TEST(HistogramThreshold, ManyValuesAreBinnedByTheRule)
{
    // 300 000 values (the threads count them) on the grid k / 1000, k = 0 .. 4000, in [0, 4]:
    // with 8 bins of width 0.5, bin b holds the k with 500 b <= k < 500 (b + 1), the last
    // also k = 4000. Each k appears (k mod 7) + 71 times, in a seeded shuffled order.
    std::vector<double> values;
    std::vector<long> expected(8, 0);
    for (int k = 0; k <= 4000; ++k) {
        const int copies = k % 7 + 71;
        values.insert(values.end(), static_cast<std::size_t>(copies), k / 1000.0);
        expected[static_cast<std::size_t>(std::min(k / 500, 7))] += copies;
    }
    std::shuffle(values.begin(), values.end(), std::mt19937(3));
    ASSERT_GE(values.size(), 280000u);
    const Histogram h = buildHistogram(values, 8);
    EXPECT_DOUBLE_EQ(h.minimum, 0.0);
    EXPECT_DOUBLE_EQ(h.maximum, 4.0);
    EXPECT_EQ(h.counts, expected);
    // The first value that is not finite is the one named, wherever the threads meet them.
    values[150000] = std::numeric_limits<double>::quiet_NaN();
    values[170000] = std::numeric_limits<double>::infinity();
    values[290000] = std::numeric_limits<double>::quiet_NaN();
    try {
        buildHistogram(values, 8);
        ADD_FAILURE() << "no error for NaN values";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("value 150000 is NaN"), std::string::npos) << e.what();
    }
}

// ---- Sec. 2.2: the search ------------------------------------------------------------------

TEST(HistogramThreshold, IncrementalSumsEqualTheDefinition)
{
    // The O(L^2) search updates b1 and b2 incrementally (the paper's
    // b2 = b2_prev - h_k + h_{2k-1} + h_{2k}); it must find the same maximum as recomputing
    // both sums for every (start_curv, k), on many random histograms.
    std::mt19937 rng(2008);
    std::uniform_int_distribution<int> binsDist(2, 40);
    std::uniform_int_distribution<long> countDist(0, 30);
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<long> counts(static_cast<std::size_t>(binsDist(rng)));
        for (long& c : counts) {
            c = countDist(rng);
        }
        counts.front() = std::max(counts.front(), 1L);
        counts.back() = std::max(counts.back(), 1L);
        const std::vector<double> values = valuesWithCounts(counts);
        for (auto search : {ThresholdSearch::AllStarts, ThresholdSearch::SingleRun}) {
            ThresholdOptions options;
            options.bins = static_cast<int>(counts.size());
            options.search = search;
            options.minPeakPercent = (trial % 2) ? 0.0 : 5.0;
            const double minPeak = options.minPeakPercent / 100.0 * double(values.size());
            const Reference ref = bruteForce(counts, search == ThresholdSearch::AllStarts, minPeak);
            if (ref.k == 0) {
                EXPECT_THROW(findThreshold(values, options), std::invalid_argument);
                continue;
            }
            const ThresholdResult r = findThreshold(values, options);
            ASSERT_EQ(r.histogram.counts, counts);
            EXPECT_EQ(r.ratio, ref.ratio) << "trial " << trial;
            EXPECT_EQ(r.joinedBins, ref.k) << "trial " << trial;
            EXPECT_DOUBLE_EQ(r.startCurv, ref.start) << "trial " << trial;
            EXPECT_DOUBLE_EQ(r.threshold, ref.start + ref.k) << "trial " << trial;
        }
    }
}

TEST(HistogramThreshold, TwoGaussiansThresholdInTheGap)
{
    std::vector<double> low, high;
    addGaussian(low, 0.1, 0.02, 6000, 1);
    addGaussian(high, 0.5, 0.02, 3000, 2);
    std::vector<double> values(low);
    values.insert(values.end(), high.begin(), high.end());
    const ThresholdResult r = findThreshold(values);
    // Between the two samples: every value of the first peak is low, every other one high.
    EXPECT_GE(r.threshold, *std::max_element(low.begin(), low.end()));
    EXPECT_LT(r.threshold, *std::min_element(high.begin(), high.end()));
    EXPECT_EQ(r.valleyCount, 0);
    EXPECT_DOUBLE_EQ(r.ratio, double(r.peakCount));
    EXPECT_DOUBLE_EQ(r.outlierCut, *std::max_element(values.begin(), values.end()));
}

TEST(HistogramThreshold, SingleRunAgreesWithAllStartsOnACleanBimodalCase)
{
    std::vector<double> values;
    addGaussian(values, 0.1, 0.02, 6000, 3);
    addGaussian(values, 0.5, 0.02, 3000, 4);
    ThresholdOptions single;
    single.search = ThresholdSearch::SingleRun;
    const ThresholdResult a = findThreshold(values);
    const ThresholdResult s = findThreshold(values, single);
    // Both put the same values on the low side: the whole first peak.
    EXPECT_EQ(countAtMost(values, a.threshold), 6000);
    EXPECT_EQ(countAtMost(values, s.threshold), 6000);
    EXPECT_DOUBLE_EQ(s.startCurv, s.histogram.minimum);
}

TEST(HistogramThreshold, ThreePeaksFirstThresholdAndRefinementFindBothValleys)
{
    // Proportions of a rounded cube: flat areas, fillets, corners (Fig. 2(b)).
    std::vector<double> flat, fillet, corner;
    addGaussian(flat, 0.0, 0.01, 9000, 5);
    addGaussian(fillet, 0.3, 0.02, 4000, 6);
    addGaussian(corner, 0.6, 0.02, 800, 7);
    std::vector<double> values(flat);
    values.insert(values.end(), fillet.begin(), fillet.end());
    values.insert(values.end(), corner.begin(), corner.end());
    // A valley is the gap between the samples of two neighbouring peaks.
    const auto between = [](const std::vector<double>& a, const std::vector<double>& b) {
        const double lo = *std::max_element(a.begin(), a.end());
        const double hi = *std::min_element(b.begin(), b.end());
        return [lo, hi](double t) { return t >= lo && t < hi; };
    };
    const auto inValley1 = between(flat, fillet);
    const auto inValley2 = between(fillet, corner);
    for (auto search : {ThresholdSearch::AllStarts, ThresholdSearch::SingleRun}) {
        ThresholdOptions options;
        options.search = search;
        const ThresholdResult first = findThreshold(values, options);
        ASSERT_TRUE(inValley1(first.threshold) || inValley2(first.threshold)) << first.threshold;
        if (inValley1(first.threshold)) {
            const ThresholdResult higher = findHigherThreshold(values, first.threshold, options);
            EXPECT_TRUE(inValley2(higher.threshold)) << higher.threshold;
            EXPECT_GT(higher.histogram.minimum, first.threshold);
        } else {
            const ThresholdResult lower = findLowerThreshold(values, first.threshold, options);
            EXPECT_TRUE(inValley1(lower.threshold)) << lower.threshold;
            EXPECT_LE(lower.histogram.maximum, first.threshold);
        }
    }
}

TEST(HistogramThreshold, SinglePeakThresholdFollowsThePeak)
{
    // Sec. 2.3: one large peak, the threshold right after it; the peak is on the low side.
    std::vector<double> values;
    addGaussian(values, 1.0, 0.1, 20000, 8);
    const ThresholdResult r = findThreshold(values);
    EXPECT_GT(r.threshold, 1.0);
    EXPECT_GT(countAtMost(values, r.threshold), 20000 / 2);
}

TEST(HistogramThreshold, OutliersAreDroppedBeforeTheHistogram)
{
    // Sec. 2.4: a few huge values squeeze the peaks into the first bins; dropping them brings
    // the valley back.
    std::vector<double> values;
    addGaussian(values, 0.1, 0.02, 6000, 9);
    addGaussian(values, 0.5, 0.02, 3000, 10);
    for (int i = 0; i < 45; ++i) {
        values.push_back(50.0 + i);
    }
    ThresholdOptions options;
    options.outlierPercent = 0.5; // floor(9045 * 0.005) = 45 values
    const ThresholdResult r = findThreshold(values, options);
    EXPECT_LT(r.outlierCut, 1.0);
    EXPECT_LT(r.histogram.maximum, 1.0);
    EXPECT_EQ(std::accumulate(r.histogram.counts.begin(), r.histogram.counts.end(), 0L), 9000);
    EXPECT_EQ(countAtMost(values, r.threshold), 6000);

    // A higher threshold searches the values above tau, still without the outliers.
    const ThresholdResult higher = findHigherThreshold(values, r.threshold, options);
    EXPECT_LT(higher.histogram.maximum, 1.0);
}

TEST(HistogramThreshold, MinimumPeakKeepsStrayValuesFromBeatingAShallowValley)
{
    // Bins 0-5: six stray low values around an empty bin 2; bins 6-10 a peak of 200 per bin,
    // bins 11-14 a shallow valley of 140 per bin (e = 1.43), bins 15-19 a second peak. Read
    // literally, the 3 strays of bins 0-1 over the 1 of bins 2-3 give e = 3 and win (as would
    // 2 strays before an empty bin, e = b1 when b2 = 0); a peak must hold 1% of the values.
    std::vector<long> counts{1, 2, 0, 1, 1, 1};
    counts.insert(counts.end(), 5, 200);
    counts.insert(counts.end(), 4, 140);
    counts.insert(counts.end(), 5, 200);
    const std::vector<double> values = valuesWithCounts(counts);
    ThresholdOptions options;
    options.bins = static_cast<int>(counts.size());

    options.minPeakPercent = 0.0;
    const ThresholdResult literal = findThreshold(values, options);
    EXPECT_DOUBLE_EQ(literal.threshold, 2.0);
    EXPECT_EQ(literal.peakCount, 3);

    options.minPeakPercent = 1.0;
    const ThresholdResult r = findThreshold(values, options);
    EXPECT_DOUBLE_EQ(r.threshold, 11.0);
    EXPECT_NEAR(r.ratio, 200.0 / 140.0, 1e-12);
    // On equal e, the smaller tau, then the wider peak (start_curv 7, k 4; Sec. 2.2 ties).
    EXPECT_DOUBLE_EQ(r.startCurv, 7.0);
    EXPECT_EQ(r.joinedBins, 4);
}

TEST(HistogramThreshold, TiesPreferTheSmallerThreshold)
{
    // Two identical peaks, each followed by an identical valley: e ties, tau after the first.
    const std::vector<long> counts{1, 100, 10, 10, 100, 10, 10, 1};
    const std::vector<double> values = valuesWithCounts(counts);
    for (auto search : {ThresholdSearch::AllStarts, ThresholdSearch::SingleRun}) {
        ThresholdOptions options;
        options.bins = static_cast<int>(counts.size());
        options.search = search;
        const ThresholdResult r = findThreshold(values, options);
        EXPECT_DOUBLE_EQ(r.threshold, 2.0);
    }
}

// ---- bad input -----------------------------------------------------------------------------

TEST(HistogramThreshold, BadInputThrowsWithAReason)
{
    const std::vector<double> good{0.0, 1.0, 2.0, 3.0};
    const auto message = [](auto&& call) -> std::string {
        try {
            call();
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
        return "no exception";
    };
    EXPECT_NE(message([&] { buildHistogram(good, 1); }).find("bins"), std::string::npos);
    EXPECT_NE(message([&] { buildHistogram({}, 10); }).find("no values"), std::string::npos);
    EXPECT_NE(message([&] { buildHistogram({0.0, NAN}, 10); }).find("NaN"), std::string::npos);
    EXPECT_NE(message([&] {
                  buildHistogram({INFINITY, 0.0}, 10);
              }).find("infinite"),
              std::string::npos);

    ThresholdOptions options;
    options.bins = 0;
    EXPECT_NE(message([&] { findThreshold(good, options); }).find("bins"), std::string::npos);
    for (double pct : {-1.0, 100.0, 150.0, double(NAN)}) {
        options = {};
        options.outlierPercent = pct;
        EXPECT_NE(message([&] { findThreshold(good, options); }).find("outlier"), std::string::npos)
            << pct;
    }
    options = {};
    options.minPeakPercent = -1.0;
    EXPECT_NE(message([&] { findThreshold(good, options); }).find("peak"), std::string::npos);

    EXPECT_NE(message([&] { findThreshold({}); }).find("no values"), std::string::npos);
    EXPECT_NE(message([&] { findThreshold({1.0, NAN}); }).find("NaN"), std::string::npos);
    EXPECT_NE(message([&] { findThreshold({2.0, 2.0, 2.0}); }).find("equal"), std::string::npos);
    EXPECT_NE(message([&] { findLowerThreshold(good, -1.0); }).find("no values"),
              std::string::npos);
    EXPECT_NE(message([&] { findHigherThreshold(good, 2.5); }).find("equal"), std::string::npos);
    EXPECT_NE(message([&] { findLowerThreshold(good, NAN); }).find("threshold"), std::string::npos);

    // One stray low value under a single spike at the top: no peak to put a threshold after.
    std::vector<double> spike(999, 1.0);
    spike.push_back(0.0);
    EXPECT_NE(message([&] { findThreshold(spike); }).find("peak"), std::string::npos);
    options = {};
    options.minPeakPercent = 0.0;
    EXPECT_NO_THROW(findThreshold(spike, options));
}

// ---- Fig. 4: the rounded cube --------------------------------------------------------------

namespace {

struct CubeCurvature
{
    std::vector<double> values;
    /// 0 flat, 1 fillet, 2 corner (shapes::roundedCube).
    std::vector<int> part;
    double radius = 0.0;
};

/// |H| of a rounded cube (edge 40, fillet radius 6, spacing 0.5: about 33000 points) from k = 16
/// neighbours, PCA normals and the quadric fit of Sec. 2.1; with `smoothingPasses` > 0 after
/// Gaussian noise of 0.2 spacing across the surface and that many Taubin passes (Sec. 2.4).
CubeCurvature roundedCubeCurvature(int smoothingPasses)
{
    const double edge = 40.0, radius = 6.0, spacing = 0.5;
    shapes::Sample s = shapes::roundedCube(edge, radius, spacing, 11);
    NeighbourOptions nopt;
    nopt.k = 16;
    if (smoothingPasses > 0) {
        shapes::addNormalNoise(s, 0.2 * spacing, 12);
        const Neighbourhoods noisy = nearestNeighbours(s.points, nopt);
        std::vector<int> all(static_cast<std::size_t>(s.size()));
        std::iota(all.begin(), all.end(), 0);
        SmoothingOptions sopt;
        sopt.iterations = smoothingPasses;
        s.points = laplacianSmooth(s.points, noisy, all, sopt);
    }
    const Neighbourhoods N = nearestNeighbours(s.points, nopt);
    const NormalEstimate normals = pcaNormals(s.points, N);
    const Eigen::VectorXd H = meanCurvature(s.points, normals.normals, N);
    return {std::vector<double>(H.data(), H.data() + H.size()), s.part, radius};
}

/// Fig. 4: for each L_start, tau1 (between the fillets' 1/(2r) and the corners' 1/r) and tau2
/// (between the flat 0 and 1/(2r)) are the first threshold and one refinement towards the other
/// (which of the two comes first depends on L_start). Between them the two thresholds give at
/// least 80% of each patch its own label: only points within about one neighbourhood radius of
/// a patch border (about 14% of the flat areas) see both patches in their quadric fit.
void expectBothThresholds(const CubeCurvature& c, const ThresholdOptions& base)
{
    const double fillet = 1.0 / (2.0 * c.radius), corner = 1.0 / c.radius;
    const auto isTau1 = [&](double t) { return t > fillet && t < corner; };
    const auto isTau2 = [&](double t) { return t > 0.0 && t < fillet; };
    for (int bins : {20, 50, 100, 1000, static_cast<int>(c.values.size())}) {
        ThresholdOptions options = base;
        options.bins = bins;
        const ThresholdResult first = findThreshold(c.values, options);
        SCOPED_TRACE(testing::Message() << "L_start " << bins << ", first tau " << first.threshold);
        double tau1 = first.threshold, tau2 = first.threshold;
        if (isTau1(first.threshold)) {
            tau2 = findLowerThreshold(c.values, first.threshold, options).threshold;
            EXPECT_TRUE(isTau2(tau2)) << "lower tau " << tau2;
        } else {
            ASSERT_TRUE(isTau2(first.threshold));
            tau1 = findHigherThreshold(c.values, first.threshold, options).threshold;
            EXPECT_TRUE(isTau1(tau1)) << "higher tau " << tau1;
        }
        long total[3] = {0, 0, 0}, right[3] = {0, 0, 0};
        for (std::size_t i = 0; i < c.values.size(); ++i) {
            const double v = c.values[i];
            const int label = v <= tau2 ? 0 : v <= tau1 ? 1 : 2;
            ++total[c.part[i]];
            right[c.part[i]] += label == c.part[i] ? 1 : 0;
        }
        for (int part = 0; part < 3; ++part) {
            EXPECT_GE(right[part], 0.8 * total[part])
                << "part " << part << ": " << right[part] << " of " << total[part];
        }
    }
}

} // namespace

TEST(HistogramThreshold, RoundedCubeThresholdsSeparateFlatsFilletsAndCorners)
{
    expectBothThresholds(roundedCubeCurvature(0), {});
}

TEST(HistogramThreshold, NoisyRoundedCubeAfterSmoothingAndOutlierRemoval)
{
    // sigma = 0.2 spacing leaves |H| noise of the order of 1/(2r) after the default 5 passes
    // (the patches' histograms overlap and no valley is left); 20 passes bring the valleys back.
    ThresholdOptions options;
    options.outlierPercent = 1.0;
    expectBothThresholds(roundedCubeCurvature(20), options);
}
