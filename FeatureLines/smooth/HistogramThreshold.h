// SPDX-License-Identifier: LGPL-2.1-or-later
// Multi-resolution histogram thresholding of curvature values (Sec. 2.2-2.4).
// Design: docs/design/thresholds.md.
#pragma once

#include <vector>

namespace featurelines {

/// h: a 1D histogram of L equal bins on [minimum, maximum] (Sec. 2.1): value v falls in bin
/// floor((v - minimum) / binWidth); the last bin also counts v == maximum.
struct Histogram
{
    double minimum = 0.0;
    double maximum = 0.0;
    double binWidth = 0.0;
    std::vector<long> counts;

    int bins() const { return static_cast<int>(counts.size()); }
    /// Right end of bin i (0-based): minimum + (i + 1) * binWidth.
    double upperEdge(int i) const { return minimum + (i + 1) * binWidth; }
};

/// Histogram of `values` with `bins` bins. Throws std::invalid_argument for bins < 2, no
/// values, or NaN/Inf values. All values equal gives one full first bin.
Histogram buildHistogram(const std::vector<double>& values, int bins);

enum class ThresholdSearch
{
    /// Every start_curv and every k, the maximum of e(tau, start_curv) (Sec. 2.2, Fig. 3).
    AllStarts,
    /// start_curv = min(curv) only: the single-run pseudo-code of Sec. 2.2.
    SingleRun,
};

struct ThresholdOptions
{
    /// L_start, the bins of the start histogram, at least 2 (default 50, the paper's; Sec. 2.2).
    int bins = 50;
    /// Percent of the highest values removed first, 0 to below 100 (default 0; Sec. 2.4).
    double outlierPercent = 0.0;
    /// Smallest peak b1 a threshold may follow, percent of the values searched, 0 to 100
    /// (default 1; 0: the paper as is).
    double minPeakPercent = 1.0;
    /// The start_curv values weighed (default AllStarts).
    ThresholdSearch search = ThresholdSearch::AllStarts;
};

struct ThresholdResult
{
    /// tau: values <= threshold are low points, values above it high points.
    double threshold = 0.0;
    /// e(tau, start_curv) = b1 / b2 at the maximum (b1 when b2 = 0).
    double ratio = 0.0;
    /// The start of the peak bin run b1 (start_curv) and its width in bins (k).
    double startCurv = 0.0;
    int joinedBins = 0;
    /// b1 and b2 at the maximum.
    long peakCount = 0;
    long valleyCount = 0;
    /// Values above this were dropped as outliers (the maximum value when none were).
    double outlierCut = 0.0;
    /// The start histogram the search ran on (after outlier removal and range restriction).
    Histogram histogram;
};

/// One threshold of `values`: the tau and start_curv that maximise e(tau, start_curv).
/// Throws std::invalid_argument when fewer than 2 distinct values remain, or when no run of
/// bins below the last one holds minPeakPercent of the values (nothing to separate).
ThresholdResult findThreshold(const std::vector<double>& values,
                              const ThresholdOptions& options = {});

/// Sec. 2.3: the next lower threshold, searched on the values <= `threshold` only.
ThresholdResult findLowerThreshold(const std::vector<double>& values, double threshold,
                                   const ThresholdOptions& options = {});

/// Sec. 2.3: the next higher threshold, searched on the values > `threshold` only.
ThresholdResult findHigherThreshold(const std::vector<double>& values, double threshold,
                                    const ThresholdOptions& options = {});

} // namespace featurelines
