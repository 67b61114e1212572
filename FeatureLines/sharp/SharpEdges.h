// SPDX-License-Identifier: LGPL-2.1-or-later
// The sharp stage: closed sharp lines on the raw cloud, in one network with its boundary.
#pragma once

#include <vector>

#include "FeatureLines/boundary/Boundary.h"
#include "FeatureLines/network/ClusterGraph.h"
#include "FeatureLines/sharp/FirstOrderSegmentation.h"
#include "FeatureLines/sharp/ProfileTyping.h"

namespace featurelines {

/// Design note: docs/design/sharp-edges.md (Demarsin 2007; Sec. 1.2 of the 2008 paper).

/// Polyline::label of the lines extractSharpEdges() returns.
constexpr int sharpLineLabel = 0;
constexpr int boundaryLineLabel = 1;

/// The graph options of the sharp stage: ClusterGraphOptions' defaults, with free ends extended
/// up to 48 spacings straight ahead and removed with branches of up to 48 spacings.
inline ClusterGraphOptions sharpGraphOptions()
{
    ClusterGraphOptions o;
    o.extendReach = 48.0;
    o.maxFreeEndLength = 48.0;
    return o;
}

struct SharpEdgeOptions
{
    FirstOrderSegmentationOptions segmentation;
    /// The graph processing; its smoothing and resampling apply to boundary lines only.
    ClusterGraphOptions graph = sharpGraphOptions();
    /// Join the boundary of an open cloud into the graph (true).
    bool includeBoundary = true;
    /// How boundary points are found; its graph options are not used.
    BoundaryOptions boundary;

    // Crease placement (CreasePlacement.h):
    /// Spacings: each large cluster within this radius of a node is fitted with a plane (5).
    double fitRadius = 5.0;
    /// Points a cluster needs within fitRadius to be fitted, at least 3 (6).
    int minFitPoints = 6;
    /// Degrees: two fitted planes closer to parallel than this define no crease line (15).
    double minCreaseAngle = 15.0;
    /// Spacings: a node moves onto a crease line at most this far, a junction onto a corner at
    /// most fitRadius (2.5).
    double maxCreaseShift = 2.5;
    /// Spacings: sharp lines are resampled at this step after placement; 0: not resampled (1).
    double resampleSpacing = 1.0;
    /// The typing by profile after placement: blends become two border lines, every sharp
    /// line gets its angle.
    ProfileTypingOptions profile;
};

struct SharpEdges
{
    /// Sharp lines (label sharpLineLabel), the borders of the blends typed by profile (label
    /// blendBorderLabel) and, for an open cloud, boundary lines (label boundaryLineLabel), in
    /// one network: a sharp line reaching the boundary ends on a junction of it.
    LineNetwork network;
    /// Per line of `network`: what its profile told (ProfileTyping.h); empty when the network
    /// did not come from extractSharpEdges().
    std::vector<LineProfile> profiles;
    /// #P nonzero for the points of small clusters of the segmentation.
    std::vector<char> isSharpCandidate;
    /// #P nonzero for boundary points (all zero unless includeBoundary).
    std::vector<char> isBoundary;
    FirstOrderSegmentation segmentation;
    ClusterGraphCounts counts;
};

/// Extracts the closed sharp edges of a cloud: segmentByNormals(), boundaryPoints() (for
/// includeBoundary), the cluster graph of the small clusters and the boundary points, then
/// placeOnCreases().
///   P        #P by 3 points
///   normals  #P by 3 unit normals over N (e.g. pcaNormals()), unoriented
///   N        k nearest neighbours of every point
///   spacing  sampling spacing (samplingSpacing()); every length option is a multiple of it
/// A plane, a sphere or any surface whose normals turn slowly gives no sharp line.
/// Throws std::invalid_argument when the sizes disagree, the spacing is not positive, or the
/// points lie on a line (no surface to have edges).
SharpEdges extractSharpEdges(const PointMatrix& P, const NormalMatrix& normals,
                             const Neighbourhoods& N, double spacing,
                             const SharpEdgeOptions& options = {});

} // namespace featurelines
