// SPDX-License-Identifier: LGPL-2.1-or-later
// Laplacian smoothing of a subset of the cloud (Sec. 2.4), used per smooth region before its
// curvature histogram is built. Design: docs/design/curvature.md, "Smoothing".
#pragma once

#include <vector>

#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/support/Progress.h"

namespace featurelines {

struct SmoothingOptions
{
    /// Smoothing passes; 0 leaves the points where they are. Default 5.
    int iterations = 5;
    /// Taubin's shrinking step: x the Laplacian, per pass. Default 0.5.
    double lambda = 0.5;
    /// Taubin's inflating step after it (< -lambda); 0: plain Laplacian smoothing. Default -0.53.
    double mu = -0.53;
};

/// Returns P with the points of `subset` smoothed; points outside it are copied unchanged and
/// never act as neighbours, so a smooth region is not pulled over its sharp edges.
/// `subset` holds point indices (any order, no duplicates). `progress` is told after each
/// iteration. Throws std::invalid_argument for
/// neighbourhoods of another cloud, an index outside the cloud or listed twice, or options out of
/// range.
PointMatrix laplacianSmooth(const PointMatrix& P, const Neighbourhoods& N,
                            const std::vector<int>& subset, const SmoothingOptions& options = {},
                            const ProgressSpan& progress = {});

} // namespace featurelines
