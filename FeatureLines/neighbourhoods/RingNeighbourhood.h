// SPDX-License-Identifier: LGPL-2.1-or-later
// The meshless 1-ring neighbourhood of Floater and Reimers (2001), on which Sec. 3 labels inner
// and border points. Design: docs/design/neighbourhoods.md.
#pragma once

#include <vector>

#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/support/Progress.h"

namespace featurelines {

struct RingNeighbourhoods
{
    /// Compressed rows: the ring of point i is indices[offsets[i] .. offsets[i+1]), ordered by
    /// angle around the normal. offsets has #P + 1 entries.
    std::vector<int> offsets;
    std::vector<int> indices;

    int size(Eigen::Index i) const { return offsets[i + 1] - offsets[i]; }
    const int* begin(Eigen::Index i) const { return indices.data() + offsets[i]; }
    const int* end(Eigen::Index i) const { return indices.data() + offsets[i + 1]; }
};

struct RingOptions
{
    /// Worker threads, 0 for OpenMP's default (default 0).
    int threads = 0;
};

/// The 1-ring of every point: the neighbours q of p whose projection onto p's tangent plane is
/// a Delaunay neighbour of p among the projected k nearest neighbours. A point at the border
/// of an open cloud keeps its neighbours on the convex side. Typically 5 or 6 per point.
/// `progress` is told as the rings go.
RingNeighbourhoods ringNeighbourhoods(const PointMatrix& P, const NormalMatrix& normals,
                                      const Neighbourhoods& N, const RingOptions& options = {},
                                      const ProgressSpan& progress = {});

} // namespace featurelines
