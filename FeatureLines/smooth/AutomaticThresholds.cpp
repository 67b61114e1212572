// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/AutomaticThresholds.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "FeatureLines/smooth/PointValues.h"
#include "FeatureLines/support/DisjointSets.h"

namespace featurelines {

namespace {

using detail::allIndices;
using detail::median;

ThresholdOptions histogramOptions(const RegionGeometry& region, const SmoothEdgeOptions& options)
{
    ThresholdOptions h = options.histogram;
    if (h.outlierPercent < 0.0) {
        // Sec. 2.4: outliers of the curvature come with noise; a clean region keeps them all.
        h.outlierPercent = region.smoothed ? 1.0 : 0.0;
    }
    return h;
}

std::vector<double> valuesOf(const RegionGeometry& region, const std::vector<int>& subset)
{
    std::vector<double> values;
    if (subset.empty()) {
        values.assign(region.curvature.data(), region.curvature.data() + region.curvature.size());
    } else {
        values.reserve(subset.size());
        for (int i : subset) {
            values.push_back(region.curvature[i]);
        }
    }
    return values;
}

/// The middle of the valley that starts at a threshold: Sec. 2.2 puts tau right after the peak
/// b1 (the end of its run of k bins), where the valley starts; the valley ends where the
/// histogram rises to the next peak: k bins holding twice the valley's floor so far (the least
/// k bins from b2 on; b2 itself may still lie on the lower peak's slope) and at least
/// minPeakPercent of the values (the least peak Sec. 2.2 may follow). Where no such rise
/// follows (a noisy valley whose next level is a low plateau, or the top of the histogram),
/// tau stays: there the lower peak's noise tail already reaches to the middle. The
/// quadric fit blurs a curvature step symmetrically, so the middle of the values between the
/// two levels crosses on the tangent line, while the valley's start can lie up to a
/// neighbourhood radius off it, onto the flatter side (a clean plane's values are one spike
/// at 0, and the valley starts one bin above it).
double valleyMiddle(const ThresholdResult& t, double minPeakPercent)
{
    const Histogram& h = t.histogram;
    const int L = h.bins();
    const int k = std::max(1, t.joinedBins);
    if (L == 0 || !(h.binWidth > 0.0)) {
        return t.threshold;
    }
    const int first = static_cast<int>(std::lround((t.threshold - h.minimum) / h.binWidth));
    const double values =
        static_cast<double>(std::accumulate(h.counts.begin(), h.counts.end(), 0L));
    const double minPeak = std::max(minPeakPercent / 100.0 * values, 1.0);
    // The valley's floor so far: the least of its windows of k bins, from b2 at its start on.
    double floor = static_cast<double>(t.valleyCount);
    double end = t.threshold;
    for (int j = std::max(first, 0); j < L; ++j) {
        const int last = std::min(L, j + k);
        double count = 0.0;
        for (int b = j; b < last; ++b) {
            count += static_cast<double>(h.counts[b]);
        }
        count *= static_cast<double>(k) / (last - j);
        if (count > std::max(2.0 * floor, minPeak)) {
            end = h.minimum + j * h.binWidth;
            break;
        }
        floor = std::min(floor, count);
    }
    return 0.5 * (t.threshold + std::max(end, t.threshold));
}

/// The share of the border points of a labelling (at most `samples` of them, evenly strided)
/// that have a point of curvature at most `low` or above `high` within `reach` fit radii
/// (the k-th neighbour's distance; found breadth first over the neighbourhoods).
double straddleShare(const RegionGeometry& g, const std::vector<PointLabel>& labels, int samples,
                     double low, double high, double reach)
{
    std::vector<int> border;
    for (size_t i = 0; i < labels.size(); ++i) {
        if (labels[i] == PointLabel::Border) {
            border.push_back(static_cast<int>(i));
        }
    }
    if (border.empty() || (std::isinf(low) && std::isinf(high))) {
        return 0.0;
    }
    const size_t stride =
        samples > 0 ? std::max<size_t>(1, (border.size() + samples - 1) / samples) : 1;
    const long count = static_cast<long>((border.size() + stride - 1) / stride);
    const Neighbourhoods& N = g.neighbours;
    long straddling = 0;
#pragma omp parallel reduction(+ : straddling)
    {
        // The sample that last queued each point: the queue's membership test in O(1).
        std::vector<long> queuedBy(labels.size(), -1);
        std::vector<int> queue;
#pragma omp for schedule(dynamic, 16)
        for (long s = 0; s < count; ++s) {
            const int p = border[static_cast<size_t>(s) * stride];
            const double reach2 = reach * reach * N.squaredDistances(p, N.k() - 1);
            // Breadth first over the neighbourhoods, within the reach.
            queue.assign(1, p);
            queuedBy[static_cast<size_t>(p)] = s;
            bool outside = false;
            for (size_t head = 0; head < queue.size() && !outside; ++head) {
                const int q = queue[head];
                for (int j = 0; j < N.k() && !outside; ++j) {
                    const int r = N.indices(q, j);
                    if (queuedBy[static_cast<size_t>(r)] == s ||
                        (g.points.row(r) - g.points.row(p)).squaredNorm() > reach2) {
                        continue;
                    }
                    const double v = g.curvature[r];
                    outside = v <= low || v > high;
                    queue.push_back(r);
                    queuedBy[static_cast<size_t>(r)] = s;
                }
            }
            straddling += outside ? 1 : 0;
        }
    }
    return static_cast<double>(straddling) / static_cast<double>(count);
}

/// Per set root of `root` (a representative per point), its number of points; points whose
/// `state` is `outside` count not. Counted in runs of points of one set (rows in Morton order:
/// long runs).
std::vector<int> setSizes(const std::vector<int>& root, const std::vector<char>& state,
                          char outside)
{
    const Eigen::Index n = static_cast<Eigen::Index>(root.size());
    std::vector<int> size(static_cast<size_t>(n), 0);
#pragma omp parallel
    {
        int current = -1, run = 0;
#pragma omp for schedule(static, 4096)
        for (Eigen::Index i = 0; i < n; ++i) {
            const int r = state[i] == outside ? -1 : root[i];
            if (r != current) {
                if (run > 0) {
#pragma omp atomic
                    size[current] += run;
                }
                current = r;
                run = 0;
            }
            run += r >= 0 ? 1 : 0;
        }
        if (run > 0) {
#pragma omp atomic
            size[current] += run;
        }
    }
    return size;
}

/// The largest patches of the curvature levels (low, tau] and (tau, high]: points with values
/// in the level whose whole 1-ring is in it too (the inner points of Sec. 3 for that level),
/// connected through the 1-rings; returns their numbers of points, {above, below}. Both levels
/// are searched in one sweep: a patch never leaves its level.
std::pair<int, int> largestPatches(const Eigen::VectorXd& curvature, double low, double tau,
                                   double high, const RingNeighbourhoods& ring)
{
    const Eigen::Index n = curvature.size();
    constexpr char outside = 0, above = 1, below = 2;
    const auto levelOf = [&](int i) {
        const double c = curvature[i];
        return c > tau && c <= high ? above : (c > low && c <= tau ? below : outside);
    };
    // Per point: its level, then the level it is an interior point of, or outside.
    std::vector<char> levels(static_cast<size_t>(n));
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < n; ++i) {
        levels[i] = levelOf(static_cast<int>(i));
    }
    std::vector<char> state(static_cast<size_t>(n), outside);
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < n; ++i) {
        const char level = levels[i];
        if (level == outside || ring.size(i) == 0) {
            continue;
        }
        bool interior = true;
        for (const int* q = ring.begin(i); q != ring.end(i) && interior; ++q) {
            interior = levels[*q] == level;
        }
        state[i] = interior ? level : outside;
    }
    // The patches: interior points of one level joined through the 1-rings (both ways).
    DisjointSets sets(static_cast<int>(n));
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < n; ++i) {
        if (state[i] == outside) {
            continue;
        }
        int root = static_cast<int>(i);
        for (const int* q = ring.begin(i); q != ring.end(i); ++q) {
            if (state[*q] == state[i]) {
                root = sets.join(root, *q);
            }
        }
    }
    const std::vector<int> root = sets.representatives();
    const std::vector<int> size = setSizes(root, state, outside);
    int largestAbove = 0, largestBelow = 0;
#pragma omp parallel for schedule(static, 4096) reduction(max : largestAbove, largestBelow)
    for (Eigen::Index i = 0; i < n; ++i) {
        if (root[i] == i && state[i] == above) {
            largestAbove = std::max(largestAbove, size[i]);
        } else if (root[i] == i && state[i] == below) {
            largestBelow = std::max(largestBelow, size[i]);
        }
    }
    return {largestAbove, largestBelow};
}

} // namespace

std::pair<int, int> largestLevelPatches(const RegionGeometry& region, double low, double tau,
                                        double high)
{
    const double inf = std::numeric_limits<double>::infinity();
    return largestPatches(region.curvature, std::isnan(low) ? -inf : low, tau,
                          std::isnan(high) ? inf : high, region.ring);
}

int minimumPatchPoints(const RegionGeometry& region, const AutomaticThresholdOptions& options)
{
    return options.minInnerPoints > 0 ? options.minInnerPoints : 2 * region.neighbours.k();
}

ThresholdResult regionThreshold(const RegionGeometry& region, const SmoothEdgeOptions& options,
                                const std::vector<int>& subset)
{
    return findThreshold(valuesOf(region, subset), histogramOptions(region, options));
}

ThresholdResult regionLowerThreshold(const RegionGeometry& region, double threshold,
                                     const SmoothEdgeOptions& options)
{
    return findLowerThreshold(valuesOf(region, {}), threshold, histogramOptions(region, options));
}

ThresholdResult regionHigherThreshold(const RegionGeometry& region, double threshold,
                                      const SmoothEdgeOptions& options)
{
    return findHigherThreshold(valuesOf(region, {}), threshold, histogramOptions(region, options));
}

namespace {

/// A range of values (low, high] still to search, and the patches a threshold found in it is
/// weighed against: the values between the nearest accepted thresholds on either side
/// (patchLow, patchHigh], not only the values of the range searched.
struct Range
{
    double low, high;
    double patchLow, patchHigh;
    bool first;
    int misses; // thresholds refused on the way to this range
};

/// What the automatic rule weighs every threshold of a region with.
struct AutomaticSearch
{
    const RegionGeometry& region;
    const SmoothEdgeOptions& options;
    /// AutomaticThresholdOptions::minInnerPoints, 0 resolved.
    int minInner;
    /// The curvature of AutomaticThresholdOptions::flatRadius.
    double flat;
    ThresholdOptions histogram;
    std::vector<double> all;
    std::vector<int> everyPoint;
};

/// How a threshold fared on the tests of AutomaticThresholdOptions.
struct ThresholdTests
{
    bool valley, patch, patchBelow, levels;
};

void requireAutomaticOptions(const AutomaticThresholdOptions& a)
{
    if (a.maxThresholds < 0 || a.maxSearches < 0 || a.maxMisses < 0 || a.minRatio < 1.0 ||
        a.minInnerPoints < 0 || a.minContrast < 1.0 || !(a.flatRadius > 0.0) ||
        !(a.minSeparation >= 0.0) || !(a.maxStraddle >= 0.0) || a.straddleSamples < 0) {
        throw std::invalid_argument("automatic thresholds: the limits are out of range");
    }
}

AutomaticSearch automaticSearch(const RegionGeometry& region, const SmoothEdgeOptions& options)
{
    const AutomaticThresholdOptions& a = options.automatic;
    const int minInner = minimumPatchPoints(region, a);
    const double flat = 1.0 / (a.flatRadius * region.spacing);
    return {region,
            options,
            minInner,
            flat,
            histogramOptions(region, options),
            valuesOf(region, {}),
            allIndices(region.points.rows())};
}

/// The region's values in the range; none when a range searched after a threshold cannot hold
/// two levels.
std::vector<double> valuesToSplit(const AutomaticSearch& s, const Range& range)
{
    const AutomaticThresholdOptions& a = s.options.automatic;
    std::vector<double> values;
    for (double v : s.all) {
        if (v > range.low && v <= range.high) {
            values.push_back(v);
        }
    }
    if (values.empty() || range.first) {
        return values;
    }
    // A range whose values cannot hold two levels (contrast, separation) is not split.
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    if ((*hi + s.flat) / (*lo + s.flat) < a.minContrast ||
        *hi - *lo < a.minSeparation * s.region.curvatureNoise) {
        return {};
    }
    return values;
}

/// The histogram options of a range: the first is the whole histogram with its outliers
/// (Sec. 2.4); the ranges after it lie between thresholds and keep all their values.
ThresholdOptions rangeHistogramOptions(const AutomaticSearch& s, const Range& range)
{
    ThresholdOptions h = s.histogram;
    if (!range.first) {
        h.outlierPercent = 0.0;
    }
    return h;
}

/// Weighs the threshold d.result found in the range with histogram options h: fills in the rest
/// of d and returns how it fared on each test.
ThresholdTests weighThreshold(const AutomaticSearch& s, const Range& range,
                              const ThresholdOptions& h, ThresholdDecision& d)
{
    const AutomaticThresholdOptions& a = s.options.automatic;
    const RegionGeometry& region = s.region;
    constexpr double infinity = std::numeric_limits<double>::infinity();
    const double tau =
        a.centreThresholds ? valleyMiddle(d.result, h.minPeakPercent) : d.result.threshold;
    d.applied = tau;
    std::tie(d.largestPatch, d.largestPatchBelow) =
        largestPatches(region.curvature, range.patchLow, tau, range.patchHigh, region.ring);
    std::vector<double> below, above;
    for (double v : s.all) {
        if (v > range.patchLow && v <= range.patchHigh) {
            (v <= tau ? below : above).push_back(v);
        }
    }
    d.medianBelow = median(std::move(below));
    d.medianAbove = median(std::move(above));
    const std::vector<PointLabel> labels =
        labelPoints(region.curvature, tau, region.ring, s.everyPoint, s.options.labels);
    d.innerPoints = static_cast<int>(std::count(labels.begin(), labels.end(), PointLabel::Inner));
    d.straddle = straddleShare(region, labels, a.straddleSamples, range.patchLow, range.patchHigh,
                               a.straddleReach);
    d.contrast = (d.medianAbove + s.flat) / (d.medianBelow + s.flat);
    d.separation = region.curvatureNoise > 0.0
                       ? (d.medianAbove - d.medianBelow) / region.curvatureNoise
                       : infinity;
    ThresholdTests t;
    t.patch = d.largestPatch >= s.minInner;
    t.patchBelow = d.largestPatchBelow >= s.minInner;
    t.levels = d.contrast >= a.minContrast && d.separation >= a.minSeparation &&
               d.straddle <= a.maxStraddle;
    // The valley must follow a peak of a patch's worth of values: e = b1 / b2 of a few
    // stray values before an empty bin (b2 = 0) is no valley.
    t.valley = d.result.ratio >= a.minRatio && d.result.peakCount >= static_cast<long>(s.minInner);
    d.accepted = t.valley && t.patch && t.patchBelow && t.levels;
    return t;
}

/// The ranges searched after decision d on the range (pushed on the depth-first stack).
/// `strays`: the values above tau are fewer than a patch's worth.
void queueNextRanges(const Range& range, const ThresholdDecision& d, const ThresholdTests& t,
                     bool strays, int maxMisses, std::vector<Range>& ranges)
{
    const double tau = d.applied;
    // Sec. 2.4: the outliers leave the histogram, not the patches.
    const double searchHigh = range.first ? d.result.outlierCut : range.high;
    if (d.accepted) {
        // Searched next: the higher values first, then the lower (Sec. 2.3 offers both).
        ranges.push_back({range.patchLow, tau, range.patchLow, tau, false, 0});
        ranges.push_back({tau, searchHigh, tau, range.patchHigh, false, 0});
    } else if (range.misses >= maxMisses) {
        return;
    } else if (!t.patch) {
        // No patch above tau: the valley found lies above the highest patch of the range
        // (e.g. after a fillet peak at the top of the histogram); the patches' own valley
        // is lower down (Sec. 2.3, "lower threshold").
        // When the values above tau are strays (fewer than a patch's worth, as the fits at a
        // clean region's edges give them), no level was refused: peeling them off is no miss,
        // or a few groups of strays above a clean fillet's level would end the search before
        // it reached the fillet. A scattered tail of more values (noise) is a miss.
        ranges.push_back({range.low, d.result.threshold, range.patchLow, range.patchHigh, false,
                          range.misses + (strays ? 0 : 1)});
    } else if (!t.levels || !t.patchBelow) {
        // tau splits one curvature level in two (a peak and its own noise tail), or cuts
        // the transition between two levels short of the lower one; a second level, if
        // any, lies higher up (Sec. 4, Fig. 9 a: "the desired threshold is located after
        // the second peak").
        ranges.push_back({d.result.threshold, searchHigh, range.patchLow, range.patchHigh, false,
                          range.misses + 1});
    }
}

} // namespace

std::vector<ThresholdDecision> automaticThresholds(const RegionGeometry& region,
                                                   const SmoothEdgeOptions& options)
{
    if (region.coarse) {
        // Decided at the region's curvature scale, where its patches and reaches are counted
        // in its own sampling; the values are the region's carried-back curvature's.
        return automaticThresholds(*region.coarse, options);
    }
    const AutomaticThresholdOptions& a = options.automatic;
    requireAutomaticOptions(a);
    const AutomaticSearch search = automaticSearch(region, options);
    constexpr double infinity = std::numeric_limits<double>::infinity();
    std::vector<ThresholdDecision> decisions;
    int accepted = 0;
    // Ranges of values still to search, depth first. The first is the whole histogram with its
    // outliers (Sec. 2.4); an accepted tau opens the ranges below and above it (the paper's
    // "lower" and "higher" steps, Sec. 2.3).
    std::vector<Range> ranges{{-infinity, infinity, -infinity, infinity, true, 0}};
    while (!ranges.empty() && accepted < a.maxThresholds &&
           static_cast<int>(decisions.size()) < a.maxSearches) {
        const Range range = ranges.back();
        ranges.pop_back();
        const std::vector<double> values = valuesToSplit(search, range);
        if (values.empty()) {
            continue;
        }
        const ThresholdOptions h = rangeHistogramOptions(search, range);
        ThresholdDecision d;
        try {
            d.result = findThreshold(values, h);
        } catch (const std::invalid_argument&) {
            continue; // too few distinct values in this range: nothing to split
        }
        const ThresholdTests tests = weighThreshold(search, range, h, d);
        decisions.push_back(d);
        accepted += d.accepted ? 1 : 0;
        const auto above = std::count_if(values.begin(), values.end(),
                                         [&](double v) { return v > d.result.threshold; });
        queueNextRanges(range, d, tests, above < search.minInner, a.maxMisses, ranges);
    }
    return decisions;
}

} // namespace featurelines
