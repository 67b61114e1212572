// SPDX-License-Identifier: LGPL-2.1-or-later
// Smooth lines found at a coarse curvature scale moved across onto the curvature step in the
// points under them (beyond the paper). Design: docs/design/line-placement.md.
#pragma once

#include "FeatureLines/PointCloud.h"
#include "FeatureLines/network/ClusterGraph.h"

namespace featurelines {

/// Lengths are in fit spacings (LinePlacementInput::fitSpacing) unless stated otherwise.
struct LinePlacementOptions
{
    /// Least half width of the strip across the line whose points are fitted. Default 3.
    double halfWidth = 3.0;
    /// The strip's half width grows to this share of the radius of the fillet the line borders
    /// (r = 1 / (4 threshold)) where that is wider. Share of r; default 0.4.
    double radiusShare = 0.4;
    /// Least half length of the strip along the line (it is made at least as long as wide).
    /// Default 2.
    double halfLength = 2.0;
    /// Farthest shift of a vertex per strip, x the strip's half width. Default 0.5.
    double maxShift = 0.5;
    /// Strips re-centred on the edge of that range, at most, when the border lies beyond it;
    /// 0: one strip only. Default 2.
    int recentres = 2;
    /// Step of the border positions tried, x the region's own spacing. Default 0.25.
    double step = 0.25;
    /// Drop in the residual sum of squares a border must bring over no border, in residual
    /// variances (chi-square, one degree of freedom). Default 25 (5 sigma).
    double minEvidence = 25.0;
    /// Least number of points on each side of a border position. Default 12.
    int minPointsPerSide = 12;
    /// Distance along the line between two fitted vertices, x the strip's half length; the
    /// vertices between move by interpolation. Default 0.5.
    double fitStride = 0.5;
    /// Fitted vertices on each side whose shifts enter the median a vertex moves by. Default 2.
    int medianHalfWindow = 2;
};

/// The region the lines were found in (references: what they name must outlive the struct).
struct LinePlacementInput
{
    /// #P by 3 region points.
    const PointMatrix& points;
    /// #P by 3 their unit normals (unoriented).
    const NormalMatrix& normals;
    /// Empty, or #P the points' mean curvature (the values the lines were drawn on): where
    /// given, a strip narrows to radiusShare of the radius of the fillet its high side shows.
    const Eigen::VectorXd& curvature;
    /// The region's mean point spacing (length unit).
    double spacing;
    /// The spacing the lines were found at, >= spacing (length unit).
    double fitSpacing;
    /// The curvature threshold the lines part (|H|, 1 / length unit); 0: unknown, the strip
    /// keeps halfWidth.
    double threshold;
};

/// Moves the inner vertices of every line of `network` across the line onto the curvature
/// step found in the points under it; vertices where no step is found with the evidence asked,
/// and the two end vertices of an open line (a junction or an anchor), stay. Returns the number
/// of vertices moved. Throws std::invalid_argument for sizes that disagree, a spacing that is
/// not positive, or options out of range.
int placeOnCurvatureSteps(LineNetwork& network, const LinePlacementInput& input,
                          const LinePlacementOptions& options = {});

} // namespace featurelines
