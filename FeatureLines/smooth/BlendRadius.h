// SPDX-License-Identifier: LGPL-2.1-or-later
// The radius of the blend a smooth line borders, from the curvature beside it (beyond the
// papers, issue 17: every smooth line carries its blend radius). Design:
// docs/design/smooth-edges.md, "Blend radius".
#pragma once

#include <vector>

#include "FeatureLines/smooth/SmoothEdgeLevel.h"

namespace featurelines {

struct BlendRadiusOptions
{
    /// x the region's spacing and curvature scale: the blend's points within this distance of
    /// a line are its witnesses (3).
    double reach = 3.0;
    /// Witnesses a line needs for a radius (8).
    int minPoints = 8;
};

/// Per line of `level.network`: the radius of the blend on its high side, 1 / the median of
/// the largest principal curvature (largestCurvature()) over the witnesses, the inner points
/// of `level` (PointLabel::Inner) within reach of the line and nearer to it than to any other
/// line of the level. A fillet of radius r gives r (its principal curvatures are 1/r and 0),
/// a spherical corner of radius r too. NaN for a line with fewer than options.minPoints
/// witnesses (a blend too narrow to hold inner points).
std::vector<double> blendRadii(const RegionGeometry& region, const SmoothEdgeLevel& level,
                               const BlendRadiusOptions& options = {});

} // namespace featurelines
