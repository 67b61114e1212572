// SPDX-License-Identifier: LGPL-2.1-or-later
// One smooth region's own geometry (Sec. 2.1, 2.4 of the 2008 paper): its points, optionally
// smoothed, their neighbourhoods, normals, 1-rings and mean curvature; the noise estimate that
// decides the smoothing, the curvature noise floor and the scale the curvature is read at.
// Design: docs/design/smooth-edges.md, "Region geometry".
#pragma once

#include <memory>
#include <vector>

#include "FeatureLines/PointCloud.h"
#include "FeatureLines/neighbourhoods/RingNeighbourhood.h"
#include "FeatureLines/smooth/SmoothEdgeOptions.h"
#include "FeatureLines/support/Progress.h"

namespace featurelines {

/// Everything a threshold needs of a region, computed once.
struct RegionGeometry
{
    int region = -1;
    /// Region point i is cloud point members[i].
    std::vector<int> members;
    /// #members by 3, smoothed when `smoothed`.
    PointMatrix points;
    /// The neighbourhoods within the region.
    Neighbourhoods neighbours;
    NormalMatrix normals;
    RingNeighbourhoods ring;
    /// |H| per point (1 / length unit), at the scale curvatureScale.
    Eigen::VectorXd curvature;
    /// Estimated noise (x spacing) before smoothing, and whether the region was smoothed.
    double noise = 0.0;
    bool smoothed = false;
    /// The curvature noise floor (1 / length unit): the standard deviation of the curvature a
    /// flat face of this region's noise shows after the region's smoothing, fit and averaging.
    double curvatureNoise = 0.0;
    double spacing = 0.0;
    /// x spacing: the sampling the curvature was computed at, 1 or a coarser scale.
    double curvatureScale = 1.0;
    /// At a coarser scale: the region averaged onto that scale's grid, on which the automatic
    /// thresholds are decided; `curvature` is its curvature carried back. Null at scale 1.
    std::shared_ptr<const RegionGeometry> coarse;
    /// At a coarser scale: per point, its row (cell) in `coarse`. Empty at scale 1.
    std::vector<int> coarseRowOf;
    /// Every scale weighed for the region.
    struct ScaleTrial
    {
        /// x the region's spacing.
        double scale = 1.0;
        int points = 0;
        double noise = 0.0;
        /// Thresholds the automatic rule accepts there; -1: not weighed (the region's own
        /// scale, when no coarser one accepted any).
        int acceptedThresholds = -1;
        /// The least separation (noise floors, ThresholdDecision::separation) among them.
        double separation = 0.0;
    };
    std::vector<ScaleTrial> scaleTrials;
};

/// Builds a region's geometry from the cloud's.
///   P, N        the cloud and its k nearest neighbours
///   region      #P region of every point (-1: none), members: the points of regionId
///   progress    told as the steps and their loops go (each overload)
RegionGeometry analyseRegion(const PointMatrix& P, const Neighbourhoods& N,
                             const std::vector<int>& region, const std::vector<int>& members,
                             int regionId, double spacing, const SmoothEdgeOptions& options = {},
                             const ProgressSpan& progress = {});

/// The same, given the cloud's normals over N (pcaNormals): only the points whose neighbourhood
/// the region cuts are fitted again.
RegionGeometry analyseRegion(const PointMatrix& P, const Neighbourhoods& N,
                             const NormalMatrix& normals, const std::vector<int>& region,
                             const std::vector<int>& members, int regionId, double spacing,
                             const SmoothEdgeOptions& options = {},
                             const ProgressSpan& progress = {});

/// The same for a region of every point of P, taking over P's neighbourhoods N (the region's
/// own). normals may be empty (fitted here).
RegionGeometry analyseRegion(const PointMatrix& P, Neighbourhoods&& N, const NormalMatrix& normals,
                             int regionId, double spacing, const SmoothEdgeOptions& options = {},
                             const ProgressSpan& progress = {});

/// The noise (x spacing): the median distance of a point from the quadric fitted to its
/// neighbours, about 0.9 sigma for normal noise sigma, whatever the curvature. At most
/// maxSamples points are fitted (every n-th; 0: all).
double estimateNoise(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                     double spacing, int maxSamples = 0);

} // namespace featurelines
