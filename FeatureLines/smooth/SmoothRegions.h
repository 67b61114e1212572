// SPDX-License-Identifier: LGPL-2.1-or-later
// Sec. 1.2: the cloud divided into smooth regions, the subsets enclosed by sharp edges (and the
// external boundary). Each region is then treated on its own: its own smoothing, curvature
// histogram and thresholds.
#pragma once

#include <vector>

#include "FeatureLines/network/ClusterGraph.h"

namespace featurelines {

struct SmoothRegionOptions
{
    /// Points closer than this to a sharp line (x spacing) belong to no region: their k nearest
    /// neighbours straddle the crease, so their normals and curvature describe the edge, not
    /// a surface. 2.5 spacings is about the radius of a 16-point neighbourhood.
    double bandWidth = 2.5;
    /// A region point needs this many of its k neighbours inside its own region; fewer and its
    /// quadric fit would lean on one side only, so it joins the band. Must be >= 5 (a quadric
    /// with six coefficients needs the point and five neighbours).
    int minRegionNeighbours = 8;
    /// Regions with fewer points are not regions but scraps between close sharp lines: their
    /// points join the band. 0: twice the neighbourhood size k.
    int minRegionPoints = 0;
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
/// one region. Regions are numbered by decreasing size.
///   P               #P by 3 points
///   N               their k nearest neighbours
///   sharpLines      the sharp lines only (boundary lines do not divide a region)
///   sharpCandidate  empty, or #P nonzero for the candidate points of the sharp stage
///   spacing         mean point spacing
SmoothRegions divideSmoothRegions(const PointMatrix& P, const Neighbourhoods& N,
                                  const std::vector<Polyline>& sharpLines,
                                  const std::vector<char>& sharpCandidate, double spacing,
                                  const SmoothRegionOptions& options = {});

/// Per listed point (rows of P): nonzero when it lies within `distance` of one of the lines.
std::vector<char> pointsNearLines(const PointMatrix& P, const std::vector<int>& points,
                                  const std::vector<Polyline>& lines, double distance);

/// Whether region `regionId` is the whole cloud: `members` lists every point of the cloud
/// (`region`, one label per point) in row order and each is labelled regionId. Its
/// neighbourhoods are then the cloud's own.
bool holdsEveryPoint(const std::vector<int>& region, const std::vector<int>& members,
                     int regionId);

/// The k nearest neighbours of a region's points within the region, as indices into the
/// region's member list (a sub-cloud). Neighbours outside the region are replaced by repeating
/// the in-region ones nearest first, so every row still has k entries.
Neighbourhoods regionNeighbourhoods(const Neighbourhoods& N, const std::vector<int>& region,
                                    const std::vector<int>& members, int regionId);

} // namespace featurelines
