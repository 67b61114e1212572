// SPDX-License-Identifier: LGPL-2.1-or-later
// The cluster graph: candidate clusters of a point cloud turned into a network of closed
// polylines (Demarsin et al. 2007: G_all, G_extended, pruned MST, branch pruning,
// reconnection; reused for smooth edges in Sec. 3 of the 2008 paper). Design and measurements:
// docs/design/network.md.
#pragma once

#include <vector>

#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/network/Polyline.h"

namespace featurelines {

/// Lengths are in multiples of the cloud's sampling spacing (samplingSpacing()), angles in degrees.
struct ClusterGraphOptions
{
    /// Candidate clusters gathered into nodes within this radius of a node's first cluster (0:
    /// one node per cluster). Spacings, 1.5.
    double nodeRadius = 1.5;
    /// G_extended: an edge between any two nodes closer than this. Spacings, 3.
    double extendedRadius = 3.0;
    /// G_pruned_mst: spanning-tree edges longer than this are cut. Spacings, 4.
    double maxEdgeLength = 4.0;
    /// G_pruned_branches: branches from a junction to a free end shorter than this are cut.
    /// Spacings, 6.
    double minBranchLength = 6.0;
    /// Reconnection: a free end joins the nearest node ahead within this distance. Must exceed
    /// minBranchLength + maxEdgeLength. Spacings, 12.
    double reconnectRadius = 12.0;
    /// Free ends ahead of each other within this distance are joined end to end (0: never).
    /// Spacings, 48.
    double facingEndsRadius = 48.0;
    /// "Ahead" of a free end: within this angle of its line's direction. Degrees, 50.
    double reconnectAngle = 50.0;
    /// Free ends left at the end are extended straight ahead up to this distance to the line
    /// they point at (0: never; the sharp stage turns it on). Spacings, 0.
    double extendReach = 0.0;
    /// "Points at" for extendReach: within this angle of the end's direction. Degrees, 10.
    double extendAngle = 10.0;
    /// With supporting points, a join longer than half maxEdgeLength needs this share of its
    /// steps supported. Share, 0.8.
    double minExtendSupport = 0.8;
    /// A step is supported by a candidate or supporting point within this distance. Spacings,
    /// 1.5.
    double supportRadius = 1.5;
    /// Free ends left at the very end are removed with their branch, and open pieces whole,
    /// when no longer than this (0: never; the sharp stage turns it on). Spacings, 0.
    double maxFreeEndLength = 0.0;
    /// A reconnection closing a cycle shorter than this many times the new edge is refused.
    /// Ratio, 3.
    double minCycleRatio = 3.0;
    /// Of two chains joining the same two junctions the longer is dropped when shorter than
    /// this (and a loop at one junction). Spacings, 18.
    double maxBubbleLength = 18.0;
    /// Junctions joined by a chain shorter than this become one. Spacings, 3.
    double junctionMergeLength = 3.0;
    /// Connected pieces shorter than this in total are dropped. Spacings, 6.
    double minComponentLength = 6.0;
    /// Connected pieces without a cycle shorter than this are dropped. Spacings, 15.
    double minOpenComponentLength = 15.0;
    /// Output lines are resampled at this step (0: one vertex per node). Spacings, 1.
    double resampleSpacing = 1.0;
    /// Lines are smoothed along their length over this distance (standard deviation; 0: not
    /// at all), junctions and free ends staying put. Spacings, 2.
    double smoothingLength = 2.0;
};

/// What each step of the graph processing did, for diagnostics and tests.
struct ClusterGraphCounts
{
    int nodes = 0;
    int allEdges = 0;       ///< G_all
    int extendedEdges = 0;  ///< edges G_extended adds to G_all
    int treeEdges = 0;      ///< minimum spanning forest of G_extended
    int overlongEdges = 0;  ///< tree edges cut for length
    int prunedBranches = 0; ///< short branches cut
    int reconnections = 0;  ///< edges added from free ends
    int extensions = 0;     ///< free ends extended to the line they point at
    int bubbles = 0;        ///< parallel chains dropped
    int mergedJunctions = 0;
    int droppedComponents = 0;
    int removedFreeEnds = 0; ///< branches and open pieces removed for a free end
    int freeEnds = 0;        ///< line ends left on no other line
};

/// What buildClusterGraph() works on.
struct ClusterGraphInput
{
    /// P  #P by 3 points.
    const PointMatrix& points;
    /// Their k nearest neighbours (the adjacency of clusters).
    const Neighbourhoods& neighbours;
    /// #P cluster id per point, 0 .. #C-1; -1 leaves a point out.
    const std::vector<int>& cluster;
    /// #C, nonzero for the clusters that become graph nodes.
    const std::vector<char>& candidateCluster;
    /// The cloud's sampling spacing (samplingSpacing(); every option length is a multiple of it).
    double spacing;
    /// Null or empty, or #C labels: nodes never mix labels and lines carry the majority label
    /// of their nodes.
    const std::vector<int>* clusterLabel = nullptr;
    /// Null or empty, or #P nonzero for the points a line may run through where it left no
    /// candidate (the sharp stage: points whose normals bend like a crease's); joins across
    /// gaps must then run along them or along candidates (minExtendSupport).
    const std::vector<char>* supportingPoint = nullptr;
};

struct ClusterGraph
{
    /// The lines, smoothed and resampled as the options say.
    LineNetwork network;
    /// C  #nodes by 3 node centres (mean of the node's points).
    PointMatrix nodes;
    /// #P node of each point, -1 for points of no candidate cluster.
    std::vector<int> nodeOfPoint;
    /// Per line of `network`: the nodes it runs through before smoothing and resampling
    /// (first and last are the junction nodes when the line has junctions).
    std::vector<std::vector<int>> lineNodes;
    /// Per junction of `network`: its node.
    std::vector<int> junctionNodes;
    ClusterGraphCounts counts;
};

/// Builds and processes the cluster graph. Throws std::invalid_argument when the sizes
/// disagree, a cluster id is out of range or the spacing is not a positive number.
ClusterGraph buildClusterGraph(const ClusterGraphInput& input,
                               const ClusterGraphOptions& options = {});

} // namespace featurelines
