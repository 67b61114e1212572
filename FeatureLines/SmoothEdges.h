// SPDX-License-Identifier: LGPL-2.1-or-later
// Smooth edges of one smooth region (Sec. 2-4 of the 2008 paper): optional smoothing, mean
// curvature, histogram thresholds, the low / inner / border labels, region growing on them, and
// the cluster graph that turns the single-point clusters into closed lines — one set of closed
// lines per threshold. Also the automatic choice of thresholds and the multi-step refinement
// inside one large cluster (Sec. 4, Fig. 13 e).
#pragma once

#include <vector>

#include "FeatureLines/ClusterGraph.h"
#include "FeatureLines/Curvature.h"
#include "FeatureLines/HistogramThreshold.h"
#include "FeatureLines/PointLabels.h"
#include "FeatureLines/RingNeighbourhood.h"
#include "FeatureLines/Smoothing.h"

namespace featurelines {

enum class SmoothingMode
{
    /// Smooth when the region's estimated noise exceeds SmoothEdgeOptions::noiseThreshold.
    Automatic,
    Always,
    Never,
};

/// The automatic mode, designed beyond the paper (which leaves the number of thresholds to
/// the user, Sec. 2.3): the first threshold of the region's histogram is searched; a threshold
/// is accepted when it is significant; the values below and above an accepted threshold are
/// searched again (the paper's "lower" and "higher" steps), until no valley is significant or
/// maxThresholds are accepted. A threshold is significant when all three hold:
///  - its valley ratio e(tau) = b1 / b2 is at least minRatio (a peak, then a valley);
///  - the points above it form patches: at least minInnerPoints inner points (Sec. 3 labels),
///    so scattered noise above a threshold in a single peak's tail is no patch;
///  - the curvature contrast (c_above + c_flat) / (c_below + c_flat), with c_above and c_below
///    the medians above tau and at or below it within the values searched, is at least
///    minContrast: two curvature levels, not one level split in two. c_flat = 1 / (flatRadius x
///    spacing) is the curvature that cannot be told from a plane at this sampling, so the
///    round-off values of a flat face (all ~0) never make a contrast.
struct AutomaticThresholdOptions
{
    int maxThresholds = 3;
    double minRatio = 2.0;
    /// 0: 2 k, two neighbourhoods' worth of points.
    int minInnerPoints = 0;
    /// A fillet (cylinder, |H| = 1 / 2r) against the corner that joins it (sphere, 1 / r) has
    /// contrast 2; 1.6 leaves room for the blur of the curvature across the tangent line.
    double minContrast = 1.6;
    /// x spacing. Over a neighbourhood of radius 2.5 spacings a sphere of radius 200 spacings
    /// departs from its tangent plane by 0.016 spacing, below any scanner's noise.
    double flatRadius = 200.0;
};

struct SmoothEdgeOptions
{
    SmoothingMode smoothing = SmoothingMode::Automatic;
    /// Noise level (x spacing) above which Automatic smoothing applies. The noise estimate is
    /// the median distance of a point from the centroid of its neighbours along its normal:
    /// about 0.8 sigma for normal noise sigma, and below 0.05 spacing on a clean surface whose
    /// radius of curvature is 10 spacings or more.
    double noiseThreshold = 0.08;
    /// Taubin passes when smoothing. Twenty passes of lambda|mu bring noise of 0.3 spacing
    /// below the curvature contrast of a fillet of radius 6 spacings.
    SmoothingOptions smoothingOptions{20, 0.5, -0.53};
    /// Passes of averaging the curvature over each point's neighbourhood, in smoothed regions
    /// only (beyond Sec. 2.4). Smoothing the points leaves the quadric fit a residual noise that
    /// still spreads a flat face's curvature over a fillet's; one pass of averaging over 17
    /// values cuts that spread by about four and moves a curvature step by less than a
    /// neighbourhood radius, symmetrically about the tangent line.
    int curvatureAveragingPasses = 1;
    CurvatureOptions curvature;
    /// L_start, outliers and search of Sec. 2.2-2.4. outlierPercent < 0 chooses: 1 % for a
    /// smoothed (noisy) region, none for a clean one (Sec. 2.4: outliers come with noise).
    ThresholdOptions histogram{50, -1.0};
    LabelOptions labels;
    /// Sec. 3: "small clusters" are the clusters of at most this many points (the single
    /// points met at a label change).
    int maxCandidateClusterSize = 1;
    ClusterGraphOptions graph;
    AutomaticThresholdOptions automatic;
    /// Seed of the random choice of growing seeds (Sec. 3).
    unsigned seed = 1;
};

/// One region's own geometry: its (possibly smoothed) points, their neighbourhoods within the
/// region, normals, 1-rings and mean curvature. Everything a threshold needs, computed once.
struct RegionGeometry
{
    int region = -1;
    /// Region point i is cloud point members[i].
    std::vector<int> members;
    PointMatrix points;
    Neighbourhoods neighbours;
    NormalMatrix normals;
    RingNeighbourhoods ring;
    Eigen::VectorXd curvature;
    /// Estimated noise (x spacing) before smoothing, and whether the region was smoothed.
    double noise = 0.0;
    bool smoothed = false;
    double spacing = 0.0;
};

/// Builds a region's geometry from the cloud's.
///   P, N        the cloud and its k nearest neighbours
///   region      #P region of every point (-1: none), members: the points of regionId
RegionGeometry analyseRegion(const PointMatrix& P, const Neighbourhoods& N,
                             const std::vector<int>& region, const std::vector<int>& members,
                             int regionId, double spacing, const SmoothEdgeOptions& options = {});

/// Median distance (x spacing) of each point from the centroid of its neighbours, along
/// its normal: the noise estimate of SmoothEdgeOptions::noiseThreshold.
double estimateNoise(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                     double spacing);

/// The closed lines at one threshold of a region.
struct SmoothEdgeLevel
{
    double threshold = 0.0;
    /// Per region point: its Sec. 3 label at this threshold and its label cluster.
    std::vector<PointLabel> labels;
    LabelClusters clusters;
    /// Lines on the region's (possibly smoothed) points.
    LineNetwork network;
    ClusterGraphCounts counts;
};

/// Sec. 3 at threshold tau over the whole region, or over `subset` (region point indices)
/// only, as the multi-step refinement does.
SmoothEdgeLevel smoothEdgesAtThreshold(const RegionGeometry& region, double threshold,
                                       const SmoothEdgeOptions& options = {},
                                       const std::vector<int>& subset = {});

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
    int innerPoints = 0;
    double contrast = 0.0;
};

/// The automatic mode (see AutomaticThresholdOptions): every threshold searched, in the order
/// searched, with its decision. The accepted ones, sorted from high to low, are the region's
/// thresholds. A region with no significant valley (a plane, a sphere) accepts none.
std::vector<ThresholdDecision> automaticThresholds(const RegionGeometry& region,
                                                   const SmoothEdgeOptions& options = {});

/// Sec. 4, Fig. 13 e: the histogram step applied again to one large label cluster of a level,
/// for a fillet no valley of the whole region shows. Returns the level found inside the
/// cluster (its threshold and lines), or throws std::invalid_argument when the cluster is not a
/// large cluster of that level or holds too few distinct curvature values.
SmoothEdgeLevel refineInCluster(const RegionGeometry& region, const SmoothEdgeLevel& level,
                                int cluster, const SmoothEdgeOptions& options = {});

} // namespace featurelines
