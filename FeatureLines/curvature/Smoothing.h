// SPDX-License-Identifier: LGPL-2.1-or-later
// Laplacian smoothing of a subset of the cloud (Sec. 2.4), used per smooth region before its
// curvature histogram is built.
#pragma once

#include <vector>

#include "FeatureLines/neighbourhoods/Neighbours.h"

namespace featurelines {

struct SmoothingOptions
{
    /// Smoothing passes; 0 leaves the points where they are.
    int iterations = 5;
    /// Taubin's lambda|mu pair: each pass moves a point by lambda times its Laplacian, then by
    /// mu times the new Laplacian, which removes noise without the shrinkage (and curvature
    /// bias) of plain Laplacian smoothing. mu = 0 gives plain Laplacian smoothing.
    double lambda = 0.5;
    double mu = -0.53;
};

/// Returns P with the points of `subset` smoothed; points outside it are copied unchanged and
/// never act as neighbours, so a smooth region is not pulled over its sharp edges.
/// `subset` holds point indices (any order, no duplicates).
PointMatrix laplacianSmooth(const PointMatrix& P, const Neighbourhoods& N,
                            const std::vector<int>& subset, const SmoothingOptions& options = {});

} // namespace featurelines
