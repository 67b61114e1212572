// SPDX-License-Identifier: LGPL-2.1-or-later
// CGAL's Voronoi covariance measure (VCM) as a per-point sharp-edge baseline beside PCL's
// (Baselines.h): Merigot, Ovsjanikov and Guibas, "Voronoi-based curvature and feature
// estimation from point clouds", IEEE TVCG 2011. CGAL's headers stay in VcmBaseline.cpp.
#pragma once

#include <vector>

#include "FeatureLines/PointCloud.h"

namespace featurelines::bench {

struct VcmOptions
{
    /// Mean point spacing of the cloud (model units, > 0): the unit of both radii.
    double spacing = 1.0;
    /// Offset radius R (spacings, > 0): each point's Voronoi cell is cut by the ball of radius
    /// R around it (Sec. 3); CGAL asks for about the smallest local feature size.
    double offsetRadius = 5.0;
    /// Convolution radius r (spacings, >= 0): each point's covariance is summed over the
    /// points within r (Sec. 4), against noise; it widens the flagged band to about r.
    double convolutionRadius = 2.0;
};

/// The threshold on vcmEdgeRatio of the benchmark's fixed VCM row (CGAL's edge example uses
/// 0.16 on a clean model).
constexpr double vcmDefaultThreshold = 0.16;

/// VCM's edge measure of every point of P (#P by 3): lambda1 / (lambda0 + lambda1 + lambda2)
/// of the convolved covariance's eigenvalues in increasing order, the ratio
/// CGAL::vcm_is_on_feature_edge compares with its threshold (a point lies on a feature edge
/// when the ratio is at least the threshold). From CGAL::compute_vcm.
/// Throws std::invalid_argument when P has fewer than 4 points or an option is out of range.
std::vector<double> vcmEdgeRatio(const PointMatrix& P, const VcmOptions& options);

/// CGAL::vcm_is_on_feature_edge(covariance, threshold) for every point of P (1 on an edge):
/// the documented test itself, equal to vcmEdgeRatio(P, options)[i] >= threshold.
std::vector<char> vcmFeatureEdgeFlags(const PointMatrix& P, const VcmOptions& options,
                                      double threshold);

} // namespace featurelines::bench
