// SPDX-License-Identifier: LGPL-2.1-or-later
// The interactive thresholding of Sec. 2.3 (Demarsin et al. 2008) as the task panel drives it:
// a smooth region's curvature histogram, the candidate threshold between the thresholds accepted
// so far, and the Sec. 3 labels and the patches a candidate gives. All of it is computed on the
// cached analysis of the cloud (ExtractionCache.h), without recomputing the document object: the
// user sees a candidate's division of the points before any line is built.
#pragma once

#include <Base/Matrix.h>

#include <cstdint>
#include <vector>

#include "ExtractionCache.h"
#include "ExtractionParameters.h"
#include "FeatureLines/Extraction.h"

namespace FeatureLines {

class Extraction;

/// What an analysis of an Extraction object needs, gathered in the GUI thread so that the
/// analysis itself can run in a worker: the source's points (its own coordinates), their
/// content hash, the options of the object's properties with `changes` applied over them, and
/// the source's placement.
struct ExtractionInput
{
    featurelines::PointMatrix points;
    std::uint64_t cloudHash = 0;
    featurelines::ExtractionOptions options;
    Base::Matrix4D toWorld;
};

/// Throws std::invalid_argument with a message for the user when the object has no Source, the
/// Source is not a Points object, or a value of `changes` is out of range.
ExtractionInput extractionInput(const Extraction& extraction, const ParameterValues& changes = {});

/// The geometry of smooth region `region`. Throws std::invalid_argument when the cloud has no
/// such region (or smooth edges are off, so no region was analysed).
const featurelines::RegionGeometry& regionGeometry(const CloudAnalysis& analysis, int region);

/// A region's curvature histogram as the threshold search starts from it (Sec. 2.2: L_start =
/// options.histogram.bins bins over the values it searches). Where outliers were dropped
/// (Sec. 2.4) the bins go on a tenth of the range past the cut, so that a view can show the
/// cut and some of what lies beyond it.
struct RegionHistogram
{
    /// Bin i counts the values in [minimum + i binWidth, minimum + (i + 1) binWidth).
    std::vector<long> counts;
    double minimum = 0.0;
    double binWidth = 0.0;
    /// Values above it were dropped as outliers; NaN when none were.
    double outlierCut = 0.0;
};

RegionHistogram regionHistogram(const featurelines::RegionGeometry& region,
                                const featurelines::SmoothEdgeOptions& options);

/// Sec. 2.3: the threshold of the region's values in (lower, upper] (NaN: no bound), after the
/// region's outliers are dropped from all its values (Sec. 2.4, the rule of the core's
/// regionThreshold: SmoothEdgeOptions::histogram.outlierPercent, or 1 % for a smoothed region
/// when it is negative). With no bound it is the region's first threshold; with an upper bound
/// only, the next lower threshold; with a lower bound only, the next higher one; with both, a
/// threshold between two accepted ones. Throws std::invalid_argument when those values have no
/// valley (the core's message).
featurelines::ThresholdResult searchThreshold(const featurelines::RegionGeometry& region,
                                              const featurelines::SmoothEdgeOptions& options,
                                              double lower, double upper);

/// The accepted threshold whose lines `candidate` would repeat, NaN when it adds a patch of its
/// own. Accepting the candidate splits the level between the accepted thresholds next to it;
/// when one of the two parts holds no patch of at least minimumPatchPoints inner points (the
/// automatic mode's patch test, AutomaticThresholds.h), the candidate only shaves a band off a
/// patch the accepted threshold on that side already bounds: the same patches, and lines beside
/// that threshold's. So does a candidate whose open side (no accepted threshold beyond it) holds
/// no patch: it repeats the accepted threshold on its other side. A candidate equal to an
/// accepted threshold repeats it; with none accepted nothing is repeated.
double repeatedThreshold(const featurelines::RegionGeometry& region,
                         const featurelines::SmoothEdgeOptions& options, double candidate,
                         const std::vector<double>& accepted);

/// The thresholds the Automatic mode gives the region (Extraction's ThresholdMode Automatic),
/// high to low; empty when it finds no significant valley.
std::vector<double> automaticRegionThresholds(const featurelines::RegionGeometry& region,
                                              const featurelines::SmoothEdgeOptions& options);

/// Sec. 3 labels of the region's points at `threshold` (low, inner, border, noisy), per region
/// point: the labels of the paper's Fig. 7 a, before the core levels noise islands for its lines.
std::vector<featurelines::PointLabel> regionLabels(const featurelines::RegionGeometry& region,
                                                   double threshold,
                                                   const featurelines::SmoothEdgeOptions& options);

/// Per input point of the cloud (CloudGeometry::inputToPoint: duplicates share a point), the
/// value of its point in `region` (`perRegionPoint`, one per region point), `outside` for the
/// points not in the region. `perInputPoint` must hold one entry per input point; only the
/// region's points are written.
void scatterToInputPoints(const featurelines::CloudGeometry& cloud,
                          const featurelines::RegionGeometry& region,
                          const std::vector<int>& perRegionPoint, std::vector<int>& perInputPoint);

} // namespace FeatureLines
