// SPDX-License-Identifier: LGPL-2.1-or-later
// Per-point feature flags from PCL, the baselines the extraction is compared with: they mark
// points near edges but give neither lines, nor types, nor closed networks.
#pragma once

#include <vector>

#include "FeatureLines/PointCloud.h"

namespace featurelines::bench {

struct BaselineOptions
{
    /// Neighbours per point for PCL's normal estimation and for the normal-angle test.
    int k = 16;
};

/// PCL NormalEstimation's "curvature" of every point of P (#P by 3): the surface variation
/// lambda0 / (lambda0 + lambda1 + lambda2) of the covariance of the point and its k nearest
/// neighbours; 0 on a plane, at most 1/3.
/// Throws std::invalid_argument when P has no more than k points or options.k < 3.
std::vector<double> surfaceVariation(const PointMatrix& P, const BaselineOptions& options = {});

/// For every point of P, the largest angle (degrees, 0 to 90) between its PCA normal (PCL
/// NormalEstimation) and the normals of its k nearest neighbours, normals taken unoriented.
/// Throws std::invalid_argument as surfaceVariation.
std::vector<double> normalAngleDegrees(const PointMatrix& P, const BaselineOptions& options = {});

/// The rows of P whose value exceeds `threshold`.
PointMatrix pointsAbove(const PointMatrix& P, const std::vector<double>& values, double threshold);

} // namespace featurelines::bench
