// SPDX-License-Identifier: LGPL-2.1-or-later
// The external boundary of an open cloud: boundary points, chained into lines by the graph.
#pragma once

#include <vector>

#include "FeatureLines/network/ClusterGraph.h"

namespace featurelines {

/// Design note: docs/design/boundary.md (Sec. 1.2 and 4 of the 2008 paper; the test is ours).
struct BoundaryOptions
{
    /// Degrees: a point is on the boundary when its k neighbours leave an empty sector wider
    /// than this in its tangent plane, in (0, 360) (120).
    double minGapAngle = 120.0;
    /// A gap must persist among the points within this many times the point's k-th neighbour
    /// distance (reached over three rings of neighbours), else the point is not on the
    /// boundary: a chance gap of an irregular sampling is filled further out, a real border
    /// is not; 0 to judge by the k neighbours alone (2).
    double confirmationReach = 2.0;
    /// The chaining of boundary points into lines (ClusterGraphOptions' defaults).
    ClusterGraphOptions graph;
    /// Worker threads; 0: OpenMP's default (0).
    int threads = 0;
};

/// #P nonzero for the boundary points of the cloud.
///   P        #P by 3 points
///   normals  #P by 3 unit normals (their tangent planes are where the gaps are measured)
///   N        k nearest neighbours of every point
/// Neighbours coinciding with the point are ignored; a point whose neighbours all coincide
/// with it is not a boundary point. Throws std::invalid_argument when the sizes disagree or
/// the angle is not in (0, 360) or the reach is negative.
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
///   spacing  the cloud's sampling spacing, see samplingSpacing()
/// Throws std::invalid_argument for mismatched sizes or a spacing that is not positive.
Boundary extractBoundary(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                         double spacing, const BoundaryOptions& options = {});

} // namespace featurelines
