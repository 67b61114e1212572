// SPDX-License-Identifier: LGPL-2.1-or-later
// One smooth region's own geometry (Sec. 2.1, 2.4 of the 2008 paper): its points, optionally
// smoothed, their neighbourhoods, normals, 1-rings and mean curvature; the noise estimate that
// decides the smoothing, the curvature noise floor and the scale the curvature is read at.
#pragma once

#include <memory>
#include <vector>

#include "FeatureLines/PointCloud.h"
#include "FeatureLines/neighbourhoods/RingNeighbourhood.h"
#include "FeatureLines/smooth/SmoothEdgeOptions.h"

namespace featurelines {

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
    /// The curvature noise floor (1 / length unit): the standard deviation of the curvature a
    /// flat face of this region's noise shows after the region's smoothing, fit and averaging.
    double curvatureNoise = 0.0;
    double spacing = 0.0;
    /// The spacing of the sampling the curvature was computed at, x spacing: 1, or the
    /// coarser scale chosen for the region (see analyseRegion). Lengths that depend on the fit
    /// (the flat radius, the reach of the contrast and straddle tests) scale with it.
    double curvatureScale = 1.0;

    /// At a coarser scale: the region averaged onto that scale's grid, with its own smoothing,
    /// 1-rings, curvature and noise floor. The automatic thresholds are decided on it (its
    /// patches and reaches are in its own sampling); the curvature above is its curvature
    /// carried back to the region's points, on which the lines are drawn. Null at scale 1.
    std::shared_ptr<const RegionGeometry> coarse;
    /// At a coarser scale: per point of the region, its row in `coarse` (the centroid of the
    /// cell it was averaged into). Empty at scale 1.
    std::vector<int> coarseRowOf;
    /// Every scale weighed for the region: its spacing (x the region's), its number of points
    /// and the thresholds the automatic rule accepts there; -1 at the region's own scale when
    /// no coarser one accepted any (it was not weighed: it keeps the region whatever it finds).
    struct ScaleTrial
    {
        double scale = 1.0;
        int points = 0;
        double noise = 0.0;
        int acceptedThresholds = -1;
        /// The least separation (noise floors, ThresholdDecision::separation) among them.
        double separation = 0.0;
    };
    std::vector<ScaleTrial> scaleTrials;
};

/// Builds a region's geometry from the cloud's.
///   P, N        the cloud and its k nearest neighbours
///   region      #P region of every point (-1: none), members: the points of regionId
RegionGeometry analyseRegion(const PointMatrix& P, const Neighbourhoods& N,
                             const std::vector<int>& region, const std::vector<int>& members,
                             int regionId, double spacing, const SmoothEdgeOptions& options = {});

/// The same, given the cloud's normals over N (pcaNormals): a region point whose k nearest
/// neighbours all lie in the region keeps its cloud normal (the same fit); only the points
/// whose neighbourhood the region cuts are fitted again.
RegionGeometry analyseRegion(const PointMatrix& P, const Neighbourhoods& N,
                             const NormalMatrix& normals, const std::vector<int>& region,
                             const std::vector<int>& members, int regionId, double spacing,
                             const SmoothEdgeOptions& options = {});

/// The same for a region of every point of P (no sharp edge or boundary band cuts the cloud),
/// taking over P's neighbourhoods N, which are the region's own: the one-shot extraction and the
/// coarse curvature scales spare their copy (190 MiB per million points at k = 16). normals may
/// be empty (fitted here).
RegionGeometry analyseRegion(const PointMatrix& P, Neighbourhoods&& N, const NormalMatrix& normals,
                             int regionId, double spacing, const SmoothEdgeOptions& options = {});

/// The noise estimate of SmoothEdgeOptions::noiseThreshold (x spacing): the median distance of
/// a point from the quadric fitted to its neighbours (in its normal's frame, the point itself
/// left out). Insensitive to curvature; about 0.9 sigma for normal noise sigma. At most
/// maxSamples points are fitted (every n-th; 0: all).
double estimateNoise(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                     double spacing, int maxSamples = 0);

} // namespace featurelines
