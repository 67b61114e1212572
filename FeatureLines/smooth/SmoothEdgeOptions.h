// SPDX-License-Identifier: LGPL-2.1-or-later
// The options of the smooth-edge stage (Sec. 2-4 of the 2008 paper), one struct read by its
// steps: RegionGeometry.h, AutomaticThresholds.h, SmoothEdgeLevel.h, ClusterRefinement.h.
// Design and the evidence for each default: docs/design/smooth-edges.md.
#pragma once

#include "FeatureLines/curvature/Curvature.h"
#include "FeatureLines/curvature/CurvatureScale.h"
#include "FeatureLines/curvature/Smoothing.h"
#include "FeatureLines/network/ClusterGraph.h"
#include "FeatureLines/smooth/HistogramThreshold.h"
#include "FeatureLines/smooth/LinePlacement.h"
#include "FeatureLines/smooth/PointLabels.h"

namespace featurelines {

enum class SmoothingMode
{
    /// Smooth when the region's estimated noise exceeds SmoothEdgeOptions::noiseThreshold.
    Automatic,
    Always,
    Never,
};

/// The automatic mode (automaticThresholds): which thresholds of a region are significant.
struct AutomaticThresholdOptions
{
    /// Thresholds accepted at most.
    int maxThresholds = 3;
    /// Thresholds weighed at most (accepted or not): each costs a labelling of the region.
    int maxSearches = 16;
    /// Refused thresholds in a row after which a range is given up (a valley with no patch
    /// above it, whose values are strays, is no refusal).
    int maxMisses = 2;
    /// Least valley ratio e(tau) = b1 / b2 (Sec. 2.2).
    double minRatio = 2.0;
    /// Points of a patch (connected inner points of a level) and of the peak b1; 0: 2 k.
    int minInnerPoints = 0;
    /// Least contrast (c_above + c_flat) / (c_below + c_flat) of the patches' median curvatures.
    double minContrast = 1.3;
    /// x spacing: the radius whose curvature c_flat cannot be told from a plane.
    double flatRadius = 200.0;
    /// Least c_above - c_below, in curvature noise floors (RegionGeometry::curvatureNoise).
    double minSeparation = 4.0;
    /// Apply each accepted threshold in the middle of its valley, not at its start.
    bool centreThresholds = true;
    /// Border points looked at for the straddle share (evenly strided).
    int straddleSamples = 2000;
    /// Largest share of the border points near a level outside the two patches.
    double maxStraddle = 0.5;
    /// x the fit radius (the k-th neighbour's distance): "near" for the straddle share.
    double straddleReach = 2.0;
};

/// The flat patch the curvature noise floor is measured on (RegionGeometry::curvatureNoise).
struct SyntheticNoiseOptions
{
    /// Points per side of the jittered square grid.
    int patchSide = 80;
    /// Seed of the grid's jitter and heights.
    unsigned seed = 1;
};

struct SmoothEdgeOptions
{
    /// Whether the region's points are smoothed (Sec. 2.4).
    SmoothingMode smoothing = SmoothingMode::Automatic;
    /// x spacing: estimated noise (estimateNoise) above which Automatic smoothing applies.
    double noiseThreshold = 0.02;
    /// Taubin passes when smoothing: iterations, lambda, mu.
    SmoothingOptions smoothingOptions{20, 0.5, -0.53};
    /// Passes of averaging the signed curvature over each neighbourhood, smoothed regions only.
    int curvatureAveragingPasses = 2;
    /// Points sampled for the noise estimate (every n-th, at most this many; 0: all).
    int noiseSamples = 20000;
    /// The flat patch of the curvature noise floor.
    SyntheticNoiseOptions noiseFloor;
    /// The quadric fit of the mean curvature (Sec. 2.1).
    CurvatureOptions curvature;
    /// L_start, outliers and search of Sec. 2.2-2.4; outlierPercent < 0: 1 % smoothed, else 0.
    ThresholdOptions histogram{50, -1.0};
    /// The low / inner / border labels (Sec. 3).
    LabelOptions labels;
    /// Curvature noise floors: a piece on one side of tau this close to it joins the other side.
    double islandMargin = 1.5;
    /// Curvature noise floors: least contrast across a line (lineContrast); weaker lines go.
    double minLineContrast = 2.0;
    /// Least contrast across a line (lineContrast), as a share of the step from the level
    /// beneath to tau (smoothEdgesAtThreshold's `below`; 0 beneath a region's lowest threshold).
    /// A fillet's border parts that level from the fillet's, above tau: its contrast is about
    /// the step or more. A curvature that only drifts through tau, as along a freeform surface,
    /// leaves a fraction of it however clean the cloud. 0: no such test (0.5).
    double minRelativeContrast = 0.5;
    /// Points: the "small clusters" of Sec. 3, the graph's candidates.
    int maxCandidateClusterSize = 1;
    /// The graph of Sec. 3 (see smoothGraphOptions(): open pieces are dropped after anchoring).
    ClusterGraphOptions graph;
    /// x spacing: candidates this close to an anchor (sharp or boundary) line are left out.
    double anchorBand = 2.5;
    /// x spacing: a free line end this close to an anchor line is extended to it.
    double anchorReach = 5.0;
    /// Degrees: largest angle between a line's end direction and the way to its anchor.
    double anchorAngle = 90.0;
    /// The automatic thresholds.
    AutomaticThresholdOptions automatic;
    /// Move lines drawn at a coarser curvature scale onto the region's curvature steps.
    bool placeCoarseLines = true;
    /// How they are moved (LinePlacement.h).
    LinePlacementOptions placement;
    /// Move lines drawn at the region's own scale onto its curvature steps too, in strips of
    /// the fixed half width ownScaleHalfWidth, by at most ownScaleMaxShift, without
    /// recentring: such a line lies within a spacing or two of the border, and a strip widened
    /// to the fillet's radius can reach the fillet's far border instead.
    bool placeOwnScaleLines = true;
    /// x spacing: the half width of those strips (6).
    double ownScaleHalfWidth = 6.0;
    /// x spacing: the farthest a vertex moves across there (1.5). Where both sides of a border
    /// are curved (a spherical corner beside a fillet) the step model's straight side does not
    /// hold, and under noise its best position can lie farther off than the line.
    double ownScaleMaxShift = 1.5;
    /// The scales the curvature may be read at (CurvatureScale.h, beyond the paper).
    CurvatureScaleOptions scales;
    /// Seed of the random choice of growing seeds (Sec. 3).
    unsigned seed = 1;
};

} // namespace featurelines
