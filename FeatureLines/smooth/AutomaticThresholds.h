// SPDX-License-Identifier: LGPL-2.1-or-later
// The thresholds of a region (Sec. 2.2-2.4 of the 2008 paper): the histogram search on its
// curvature, and the automatic mode that searches and weighs thresholds until the region's
// curvature levels are parted.
// Design: docs/design/smooth-edges.md, "Thresholds".
#pragma once

#include <utility>
#include <vector>

#include "FeatureLines/smooth/HistogramThreshold.h"
#include "FeatureLines/smooth/RegionGeometry.h"

namespace featurelines {

/// The histogram search on the region's curvature (or on `subset`'s) with the region's outlier
/// rule: the first threshold, and the next lower / higher one (Sec. 2.2-2.3).
ThresholdResult regionThreshold(const RegionGeometry& region, const SmoothEdgeOptions& options = {},
                                const std::vector<int>& subset = {});
ThresholdResult regionLowerThreshold(const RegionGeometry& region, double threshold,
                                     const SmoothEdgeOptions& options = {});
ThresholdResult regionHigherThreshold(const RegionGeometry& region, double threshold,
                                      const SmoothEdgeOptions& options = {});

/// Why a threshold was accepted or refused by the automatic rule, for reports and tests.
struct ThresholdDecision
{
    ThresholdResult result;
    bool accepted = false;
    /// The threshold applied when accepted (AutomaticThresholdOptions::centreThresholds).
    double applied = 0.0;
    /// Inner points at tau (Sec. 3). The largest patches of the levels above and below tau:
    /// connected points of the level whose whole 1-ring is in the level too.
    int innerPoints = 0;
    int largestPatch = 0;
    int largestPatchBelow = 0;
    /// Median curvature of the patches below and above tau (between the nearest accepted
    /// thresholds), their contrast and their separation in curvature noise floors.
    double medianBelow = 0.0;
    double medianAbove = 0.0;
    double contrast = 0.0;
    double separation = 0.0;
    /// Share of the border points at tau within two fit radii of a level outside the two
    /// patches (AutomaticThresholdOptions::maxStraddle).
    double straddle = 0.0;
};

/// The largest patches of the region's curvature levels (low, tau] and (tau, high] (NaN: no
/// bound): points of the level whose whole 1-ring is in it too, connected through the 1-rings;
/// their numbers of points, {above, below}. The automatic mode's patch test, and the task
/// panel's test that a threshold adds a patch to the accepted ones.
std::pair<int, int> largestLevelPatches(const RegionGeometry& region, double low, double tau,
                                        double high);

/// Points a patch needs to count (AutomaticThresholdOptions::minInnerPoints; 0: 2 k).
int minimumPatchPoints(const RegionGeometry& region, const AutomaticThresholdOptions& options);

/// The automatic mode (see AutomaticThresholdOptions): every threshold searched, in the order
/// searched, with its decision. The accepted ones' applied values, sorted from high to low,
/// are the region's thresholds. A region with no significant valley (a plane, a sphere) accepts
/// none.
std::vector<ThresholdDecision> automaticThresholds(const RegionGeometry& region,
                                                   const SmoothEdgeOptions& options = {});

} // namespace featurelines
