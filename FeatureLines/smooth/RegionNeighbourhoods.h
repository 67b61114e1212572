// SPDX-License-Identifier: LGPL-2.1-or-later
// A smooth region as a sub-cloud: its points' k nearest neighbours within the region (Sec. 2.1
// fits each region's curvature over neighbours of its own). Design: docs/design/smooth-regions.md.
#pragma once

#include <vector>

#include "FeatureLines/neighbourhoods/Neighbours.h"

namespace featurelines {

/// Whether region `regionId` is the whole cloud: `members` lists every point of the cloud
/// (`region`, one label per point) in row order and each is labelled regionId. Its
/// neighbourhoods are then the cloud's own.
bool holdsEveryPoint(const std::vector<int>& region, const std::vector<int>& members, int regionId);

/// The k nearest neighbours of a region's points within the region, as indices into the
/// region's member list (a sub-cloud). Neighbours outside the region are replaced by repeating
/// the in-region ones nearest first, so every row still has k entries.
///   N         the cloud's neighbourhoods
///   region    #P region label of every point
///   members   the region's point indices, ascending
/// Throws std::invalid_argument where a member has no neighbour in the region or a neighbour
/// labelled regionId is missing from `members`.
Neighbourhoods regionNeighbourhoods(const Neighbourhoods& N, const std::vector<int>& region,
                                    const std::vector<int>& members, int regionId);

} // namespace featurelines
