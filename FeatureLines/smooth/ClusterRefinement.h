// SPDX-License-Identifier: LGPL-2.1-or-later
// The multi-step refinement inside one large cluster (Sec. 4, Fig. 13 e of the 2008 paper).
// Design: docs/design/smooth-edges.md, "Refinement inside one large cluster".
#pragma once

#include "FeatureLines/smooth/RegionGeometry.h"
#include "FeatureLines/smooth/SmoothEdgeLevel.h"

namespace featurelines {

/// Sec. 4, Fig. 13 e: the histogram step applied again to one large label cluster of a level,
/// for a fillet no valley of the whole region shows. Returns the level found inside the
/// cluster (its threshold and lines), or throws std::invalid_argument when the cluster is not a
/// large cluster of that level or holds too few distinct curvature values.
SmoothEdgeLevel refineInCluster(const RegionGeometry& region, const SmoothEdgeLevel& level,
                                int cluster, const SmoothEdgeOptions& options = {});

} // namespace featurelines
