// SPDX-License-Identifier: LGPL-2.1-or-later
// Multi-resolution histogram thresholding (Demarsin et al. 2008, Sec. 2.2-2.4).
#include "FeatureLines/smooth/HistogramThreshold.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace featurelines {

namespace {

std::string number(double v)
{
    std::ostringstream out;
    out.precision(std::numeric_limits<double>::max_digits10);
    out << v;
    return out.str();
}

void checkBins(int bins)
{
    if (bins < 2) {
        throw std::invalid_argument("histogram: the number of bins must be at least 2, got " +
                                    std::to_string(bins));
    }
}

/// Values from this many on are swept by the threads.
constexpr long parallelValues = 65536;

void checkValues(const std::vector<double>& values)
{
    if (values.empty()) {
        throw std::invalid_argument("histogram: there are no values to build it from");
    }
    const long n = static_cast<long>(values.size());
    long first = n; // the first value that is not finite
#pragma omp parallel for schedule(static, 16384) reduction(min : first) if (n >= parallelValues)
    for (long i = 0; i < n; ++i) {
        if (!std::isfinite(values[static_cast<std::size_t>(i)])) {
            first = std::min(first, i);
        }
    }
    if (first < n) {
        const double v = values[static_cast<std::size_t>(first)];
        throw std::invalid_argument("histogram: value " + std::to_string(first) + " is " +
                                    (std::isnan(v) ? "NaN" : "infinite"));
    }
}

/// The least and the largest value (finite values).
std::pair<double, double> valueRange(const std::vector<double>& values)
{
    const long n = static_cast<long>(values.size());
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static, 16384) reduction(min : lo) reduction(max : hi)
    for (long i = 0; i < n; ++i) {
        lo = std::min(lo, values[static_cast<std::size_t>(i)]);
        hi = std::max(hi, values[static_cast<std::size_t>(i)]);
    }
    return {lo, hi};
}

void checkOptions(const ThresholdOptions& options)
{
    checkBins(options.bins);
    if (!(options.outlierPercent >= 0.0 && options.outlierPercent < 100.0)) {
        throw std::invalid_argument(
            "threshold: the outlier percentage must be at least 0 and below 100, got " +
            number(options.outlierPercent));
    }
    if (!(options.minPeakPercent >= 0.0 && options.minPeakPercent <= 100.0)) {
        throw std::invalid_argument(
            "threshold: the minimum peak percentage must be between 0 and 100, got " +
            number(options.minPeakPercent));
    }
}

/// Sec. 2.4: removes the given percentage of the highest values. The cut is the largest kept
/// value; values equal to it are all kept, so ties may keep slightly more than asked.
std::vector<double> dropOutliers(const std::vector<double>& values, double percent, double& cut)
{
    const std::size_t n = values.size();
    const auto dropped = static_cast<std::size_t>(std::floor(n * percent / 100.0));
    if (dropped == 0) {
        cut = valueRange(values).second;
        return values;
    }
    std::vector<double> sorted(values);
    const auto nth = sorted.begin() + static_cast<std::ptrdiff_t>(n - dropped - 1);
    std::nth_element(sorted.begin(), nth, sorted.end());
    cut = *nth;
    std::vector<double> kept;
    kept.reserve(n - dropped);
    for (double v : values) {
        if (v <= cut) {
            kept.push_back(v);
        }
    }
    return kept;
}

/// The histogram of finite values whose least and largest are lo and hi.
Histogram histogramOf(const std::vector<double>& values, int bins, double lo, double hi)
{
    Histogram h;
    h.minimum = lo;
    h.maximum = hi;
    h.counts.assign(static_cast<std::size_t>(bins), 0);
    if (h.maximum == h.minimum) {
        h.counts[0] = static_cast<long>(values.size());
        return h;
    }
    if (!std::isfinite(h.maximum - h.minimum)) {
        throw std::invalid_argument("histogram: the values span more than a double can hold (" +
                                    number(h.minimum) + " to " + number(h.maximum) + ")");
    }
    // Sec. 2.1: bin i holds min + i |bin| <= v < min + (i+1) |bin|; the last also holds max.
    h.binWidth = (h.maximum - h.minimum) / bins;
    if (!(h.binWidth > 0.0)) {
        throw std::invalid_argument("histogram: the values " + number(h.minimum) + " to " +
                                    number(h.maximum) + " are too close to split into " +
                                    std::to_string(bins) + " bins");
    }
    const auto binOf = [&](double v) {
        const double position = std::floor((v - h.minimum) / h.binWidth);
        return std::clamp(static_cast<int>(std::min(position, double(bins))), 0, bins - 1);
    };
    const long n = static_cast<long>(values.size());
    // Many values into not too many bins: each thread counts into bins of its own.
    if (n >= parallelValues && bins <= n / 16) {
#pragma omp parallel
        {
            std::vector<long> own(static_cast<std::size_t>(bins), 0);
#pragma omp for schedule(static, 16384) nowait
            for (long i = 0; i < n; ++i) {
                ++own[static_cast<std::size_t>(binOf(values[static_cast<std::size_t>(i)]))];
            }
#pragma omp critical
            for (int b = 0; b < bins; ++b) {
                h.counts[static_cast<std::size_t>(b)] += own[static_cast<std::size_t>(b)];
            }
        }
        return h;
    }
    for (double v : values) {
        ++h.counts[static_cast<std::size_t>(binOf(v))];
    }
    return h;
}

struct Candidate
{
    double ratio = -1.0;
    int start = 0;
    int k = 0;
    long b1 = 0;
    long b2 = 0;
};

/// The better of two candidates: the larger e; on equal e the smaller tau (the threshold right
/// after the first of two equally good peaks, as the single-run pseudo-code's strict '>' keeps
/// the smallest k); on equal tau the smaller start_curv, i.e. the peak joined over more bins.
bool better(const Candidate& c, const Candidate& best)
{
    if (c.ratio != best.ratio) {
        return c.ratio > best.ratio;
    }
    if (c.start + c.k != best.start + best.k) {
        return c.start + c.k < best.start + best.k;
    }
    return c.start < best.start;
}

/// Sec. 2.2 for one start_curv (bin `start`): k = 1 .. floor((L - start) / 2) joined bins,
/// b1 the k bins from `start`, b2 the k bins after them, both updated in O(1) per k.
void scanStart(const std::vector<long>& h, int start, double minPeak, Candidate& best)
{
    const int L = static_cast<int>(h.size());
    long b1 = 0;
    long b2 = 0;
    for (int k = 1; k <= (L - start) / 2; ++k) {
        // The peak run gains bin start+k-1. The valley run was bins [start+k-1, start+2k-2);
        // it loses that bin to the peak and gains bins start+2k-2 and start+2k-1, so it is
        // again exactly the k bins [start+k, start+2k). This is the paper's
        // b2 = b2_prev - h_k + h_{2k-1} + h_{2k} (1-based, start_curv = min).
        b1 += h[start + k - 1];
        b2 += h[start + 2 * k - 2] + h[start + 2 * k - 1] - h[start + k - 1];
        if (static_cast<double>(b1) < minPeak) {
            continue;
        }
        Candidate c;
        // e = b1 / b2, and b1 when the valley is empty (Sec. 2.2).
        c.ratio =
            b2 != 0 ? static_cast<double>(b1) / static_cast<double>(b2) : static_cast<double>(b1);
        c.start = start;
        c.k = k;
        c.b1 = b1;
        c.b2 = b2;
        if (better(c, best)) {
            best = c;
        }
    }
}

enum class Range
{
    All,
    AtMost,
    Above,
};

ThresholdResult search(const std::vector<double>& values, const ThresholdOptions& options,
                       Range range, double bound)
{
    checkOptions(options);
    checkValues(values);
    if (range != Range::All && !std::isfinite(bound)) {
        throw std::invalid_argument("threshold: the previous threshold is not a finite number");
    }

    ThresholdResult result;
    // Sec. 2.4 first, on all values, so a higher threshold (Sec. 2.3) is not drawn to them.
    std::vector<double> kept = dropOutliers(values, options.outlierPercent, result.outlierCut);
    if (range != Range::All) {
        // Sec. 2.3: only the values below (or above) the previous threshold.
        const auto outside = [&](double v) {
            return range == Range::AtMost ? !(v <= bound) : !(v > bound);
        };
        kept.erase(std::remove_if(kept.begin(), kept.end(), outside), kept.end());
    }

    const char* where = range == Range::All      ? ""
                        : range == Range::AtMost ? " at or below the previous threshold"
                                                 : " above the previous threshold";
    if (kept.empty()) {
        throw std::invalid_argument(std::string("threshold: there are no values") + where);
    }
    const auto [lo, hi] = valueRange(kept);
    if (lo == hi) {
        throw std::invalid_argument(std::string("threshold: all values") + where + " are equal (" +
                                    number(lo) + "), there is no valley to put a threshold in");
    }

    result.histogram = histogramOf(kept, options.bins, lo, hi);
    const std::vector<long>& h = result.histogram.counts;
    const int L = result.histogram.bins();
    const double minPeak = options.minPeakPercent / 100.0 * static_cast<double>(kept.size());

    Candidate best;
    if (options.search == ThresholdSearch::SingleRun) {
        scanStart(h, 0, minPeak, best);
    } else {
        for (int start = 0; start <= L - 2; ++start) {
            scanStart(h, start, minPeak, best);
        }
    }
    if (best.k == 0) {
        throw std::invalid_argument(
            "threshold: no peak below the highest bin holds " + number(options.minPeakPercent) +
            "% of the " + std::to_string(kept.size()) + " values" + where +
            "; they form one peak at the top of their range (lower the minimum peak percentage)");
    }

    result.threshold = result.histogram.minimum + (best.start + best.k) * result.histogram.binWidth;
    result.ratio = best.ratio;
    result.startCurv = result.histogram.minimum + best.start * result.histogram.binWidth;
    result.joinedBins = best.k;
    result.peakCount = best.b1;
    result.valleyCount = best.b2;
    return result;
}

} // namespace

Histogram buildHistogram(const std::vector<double>& values, int bins)
{
    checkBins(bins);
    checkValues(values);
    const auto [lo, hi] = valueRange(values);
    return histogramOf(values, bins, lo, hi);
}

ThresholdResult findThreshold(const std::vector<double>& values, const ThresholdOptions& options)
{
    return search(values, options, Range::All, 0.0);
}

ThresholdResult findLowerThreshold(const std::vector<double>& values, double threshold,
                                   const ThresholdOptions& options)
{
    return search(values, options, Range::AtMost, threshold);
}

ThresholdResult findHigherThreshold(const std::vector<double>& values, double threshold,
                                    const ThresholdOptions& options)
{
    return search(values, options, Range::Above, threshold);
}

} // namespace featurelines
