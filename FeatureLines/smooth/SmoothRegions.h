// SPDX-License-Identifier: LGPL-2.1-or-later
// Sec. 1.2: the cloud divided into smooth regions, the subsets enclosed by sharp edges (and the
// external boundary), each then treated on its own. Design: docs/design/smooth-regions.md.
#pragma once

#include <vector>

#include "FeatureLines/network/ClusterGraph.h"

namespace featurelines {

struct SmoothRegionOptions
{
    /// Points closer than this to a sharp line belong to no region (x spacing). Default 2.5.
    double bandWidth = 2.5;
    /// Least number of a region point's k neighbours inside its own region, else it joins the
    /// band; in [5, k]. Default 8.
    int minRegionNeighbours = 8;
    /// Least points of a region, else its points join the band; 0: twice the neighbourhood
    /// size k. Default 0.
    int minRegionPoints = 0;
};

/// The cloud and what divides it (references: what they name must outlive the struct).
struct SmoothRegionInput
{
    /// #P by 3 points.
    const PointMatrix& points;
    /// Their k nearest neighbours.
    const Neighbourhoods& neighbours;
    /// The sharp lines only (boundary lines do not divide a region).
    const std::vector<Polyline>& sharpLines;
    /// Empty, or #P nonzero for the candidate points of the sharp stage.
    const std::vector<char>& sharpCandidate;
    /// Mean point spacing (length unit).
    double spacing;
};

struct SmoothRegions
{
    /// #P region of every point, -1 for points of the band around sharp lines.
    std::vector<int> region;
    /// Per region: its point indices, ascending.
    std::vector<std::vector<int>> members;

    int count() const { return static_cast<int>(members.size()); }
};

/// Divides the cloud by its sharp lines: the points farther than bandWidth from every sharp
/// line and not sharp candidates themselves, grouped into the connected components of the
/// k-nearest-neighbour graph (its edges taken both ways). With no sharp line the whole cloud is
/// one region. Regions are numbered by decreasing size. Throws std::invalid_argument for sizes
/// that disagree, a spacing that is not positive, or options out of range.
SmoothRegions divideSmoothRegions(const SmoothRegionInput& input,
                                  const SmoothRegionOptions& options = {});

} // namespace featurelines
