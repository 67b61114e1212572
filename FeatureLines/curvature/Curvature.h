// SPDX-License-Identifier: LGPL-2.1-or-later
// Mean curvature by a quadric fitted over each point's k nearest neighbours (Sec. 2.1).
// Design: docs/design/curvature.md, "Mean curvature".
#pragma once

#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/support/Progress.h"

namespace featurelines {

struct CurvatureOptions
{
    /// Neighbours in the fit, at most Neighbourhoods::k(); 0: all of them. Default 0.
    int k = 0;
    /// true: H signed along the normal; false: |H|, concave and convex blends alike. Default
    /// false.
    bool signedCurvature = false;
    /// Threads; 0: OpenMP's default. Default 0.
    int threads = 0;
};

/// H  #P mean curvature (1 / length unit) of the height function
/// z = a x^2 + b xy + c y^2 + d x + e y + f fitted by least squares in the frame of each point's
/// normal. A sphere of radius r gives 1/r, a cylinder 1/(2r), a plane 0. When signed, the sign
/// follows the given normal (positive where the surface bends away from it); 0 where the fit is
/// degenerate. `progress` is told as the fits go. Throws std::invalid_argument for sizes that
/// disagree or k outside [5, N.k()].
Eigen::VectorXd meanCurvature(const PointMatrix& P, const NormalMatrix& normals,
                              const Neighbourhoods& N, const CurvatureOptions& options = {},
                              const ProgressSpan& progress = {});

/// The largest principal curvature in magnitude (1 / length unit) at point i of the quadric of
/// meanCurvature() fitted over all N.k() neighbours: 1/r on a cylinder or a sphere of radius r,
/// 0 on a plane. NaN when the normal, the neighbourhood or the fit is degenerate.
double largestCurvature(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                        Eigen::Index i);

/// The height at point i of the quadric of meanCurvature() fitted to i's neighbours alone
/// (all N.k() of them, not i itself), in i's normal frame (length unit). On a smooth surface
/// the quadric predicts the point to third order, so what remains is the point's noise,
/// whatever the curvature. NaN when the normal, the neighbourhood or the fit is degenerate.
double quadricHeight(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                     Eigen::Index i);

} // namespace featurelines
