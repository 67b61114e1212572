// SPDX-License-Identifier: LGPL-2.1-or-later
// The external boundary of an open cloud (a sheet, a scan of one side of a part). The 2008
// paper extracts it and includes it in the graph so that the sharp lines and the boundary
// together enclose the smooth regions (Sec. 1.2, Fig. 1 "c = external boundary"; Sec. 4).
// How boundary points are found is designed here: the paper does not say.
#pragma once

#include <vector>

#include "FeatureLines/network/ClusterGraph.h"

namespace featurelines {

struct BoundaryOptions
{
    /// Degrees. A point is on the boundary when, seen from the point in its tangent plane,
    /// its k neighbours leave an empty sector wider than this. On a straight border the gap is
    /// ~180 degrees, at a convex corner more, and one row in from the border the border row
    /// itself fills the view (gap ~45). Inside a cloud the widest gap between 16 neighbours
    /// depends on how regular the sampling is: 30-60 degrees on a blue-noise or scan-line
    /// sampling, but on an irregular one (a thinned or merged scan, independent uniform
    /// points) it passes 90 degrees at about a fifth of the points (16 directions at random:
    /// 16 (3/4)^15 = 0.21) and 120 degrees at 4 % (16 (2/3)^15), scattered, too few to chain
    /// into lines. 90 made a 70 % random thinning of the benchmark parts grow false boundary
    /// lines on every closed part; 120 keeps them closed and finds the open sheet's border as
    /// before (docs/ACCURACY.md).
    double minGapAngle = 120.0;
    /// The chaining of boundary points into lines (each boundary point is one candidate
    /// cluster). The defaults of ClusterGraphOptions suit a band one or two points wide.
    ClusterGraphOptions graph;
    /// Worker threads (0: OpenMP's default).
    int threads = 0;
};

/// #P nonzero for the boundary points of the cloud.
///   P        #P by 3 points
///   normals  #P by 3 unit normals (their tangent planes are where the gaps are measured)
///   N        k nearest neighbours of every point
/// Neighbours coinciding with the point are ignored; a point whose neighbours all coincide
/// with it is not a boundary point. Throws std::invalid_argument when the sizes disagree or
/// the angle is not in (0, 360).
std::vector<char> boundaryPoints(const PointMatrix& P, const NormalMatrix& normals,
                                 const Neighbourhoods& N, const BoundaryOptions& options = {});

struct Boundary
{
    /// The boundary as closed loops, or lines joined at junctions where boundaries touch.
    LineNetwork network;
    /// #P nonzero for boundary points.
    std::vector<char> isBoundary;
};

/// The boundary points of the cloud chained into lines by the cluster graph (every boundary
/// point a candidate cluster of its own). A closed surface gives an empty network.
///   spacing  the cloud's mean point spacing, see meanSpacing()
/// Throws std::invalid_argument for mismatched sizes or a spacing that is not positive.
Boundary extractBoundary(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                         double spacing, const BoundaryOptions& options = {});

} // namespace featurelines
