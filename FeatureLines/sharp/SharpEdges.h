// SPDX-License-Identifier: LGPL-2.1-or-later
// Closed sharp edges on the raw cloud (Demarsin et al. 2007; Sec. 1.2 of the 2008 paper):
// first-order segmentation, the graph of the small clusters, and the placement of every line
// on the crease between the two surfaces it separates. The external boundary of an open cloud
// joins the same graph, so sharp lines end on it and the two together enclose the smooth
// regions.
#pragma once

#include <vector>

#include "FeatureLines/boundary/Boundary.h"
#include "FeatureLines/network/ClusterGraph.h"
#include "FeatureLines/sharp/FirstOrderSegmentation.h"

namespace featurelines {

/// Polyline::label of the lines extractSharpEdges() returns.
constexpr int sharpLineLabel = 0;
constexpr int boundaryLineLabel = 1;

/// The graph options of the sharp stage: ClusterGraphOptions' defaults, with the network
/// closed (Sec. 1.2 of the 2008 paper: the sharp lines and the boundary enclose the smooth
/// regions). Every join across a gap must run along candidates or points whose normals bend
/// beyond the segmentation's limit and beyond what noise gives (extractSharpEdges gives those
/// to the graph; FirstOrderSegmentationOptions::noiseSpreadTail), so no join crosses a face. A free
/// end left after the joins is extended straight ahead to the line it points at within extendReach
/// = 48 spacings, as far as facing ends are joined (facingEndsRadius): noise thins the candidates
/// of a crease most near the corner where it ends, and the crease runs on straight to that corner.
/// On the benchmark's noisy chamfered box sharp recall goes from 0.90 to 0.97 (a reach of 30:
/// 0.95). An end that reaches no line is removed with its branch when that is no longer than
/// maxFreeEndLength = 48 spacings; a longer piece is a real edge broken by noise and keeps its end
/// (removing every free-ended piece drops the noisy chamfered box's sharp recall from 0.91 to 0.83
/// on another seed).
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
    /// The graph processing. Its smoothing and resampling apply to the boundary lines; sharp
    /// lines are placed on the crease and resampled at resampleSpacing instead.
    ClusterGraphOptions graph = sharpGraphOptions();
    /// Join the boundary of an open cloud into the graph (Sec. 1.2 of the 2008 paper). A
    /// closed surface has no boundary points, so this costs one pass over the cloud there.
    bool includeBoundary = true;
    /// How boundary points are found; its graph options are not used (the boundary points
    /// join the sharp graph above).
    BoundaryOptions boundary;
    /// Crease placement, designed here: around every node of a sharp line the points of the
    /// large clusters within this radius (x spacing) are fitted with one plane per cluster,
    /// and the node moves onto the intersection of two of them (three at a junction, whose
    /// search reaches maxCreaseShift farther). The candidate band is 3-4 spacings wide, so 5
    /// leaves each face a strip of 3 spacings: on a clean cube the lines then lie on the edges
    /// (3.5: a quarter of a spacing off on average, some nodes unfitted), with noise of 0.3
    /// spacing within 0.3-0.4 on average. A curved face bends away from its plane by r^2/2R
    /// (R its radius): half a spacing on a hole of radius 12 spacings (the fit's mean sits
    /// half way).
    double fitRadius = 5.0;
    /// A cluster needs this many points within fitRadius to be fitted (a plane of 3 points
    /// fits anything).
    int minFitPoints = 6;
    /// Degrees: two fitted planes closer to parallel than this do not define a crease line.
    double minCreaseAngle = 15.0;
    /// A node moves onto a crease line at most this far (x spacing), a junction onto a corner
    /// at most fitRadius; farther, the fitted planes belong to another edge and the node
    /// stays where it is.
    double maxCreaseShift = 2.5;
    /// Sharp lines are resampled at this step (x spacing) after placement.
    double resampleSpacing = 1.0;
};

struct SharpEdges
{
    /// Sharp lines (label sharpLineLabel) and, for an open cloud, boundary lines (label
    /// boundaryLineLabel), in one network: a sharp line reaching the boundary ends on a
    /// junction of it.
    LineNetwork network;
    /// #P nonzero for the points of small clusters of the segmentation.
    std::vector<char> isSharpCandidate;
    /// #P nonzero for boundary points (all zero unless includeBoundary).
    std::vector<char> isBoundary;
    FirstOrderSegmentation segmentation;
    ClusterGraphCounts counts;
};

/// Extracts the closed sharp edges of a cloud.
///   P        #P by 3 points
///   normals  #P by 3 unit normals over N (e.g. pcaNormals()), unoriented
///   N        k nearest neighbours of every point
///   spacing  mean point spacing (meanSpacing()); every length option is a multiple of it
/// A plane, a sphere or any surface whose normals turn slowly gives no sharp line.
/// Throws std::invalid_argument when the sizes disagree, the spacing is not positive, or the
/// points lie on a line (no surface to have edges).
SharpEdges extractSharpEdges(const PointMatrix& P, const NormalMatrix& normals,
                             const Neighbourhoods& N, double spacing,
                             const SharpEdgeOptions& options = {});

} // namespace featurelines
