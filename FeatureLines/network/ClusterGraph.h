// SPDX-License-Identifier: LGPL-2.1-or-later
// The graph of candidate clusters turned into closed polylines: G_all, G_extended, the pruned
// minimum spanning tree, pruning of short branches and reconnection of line ends (Demarsin et
// al. 2007, reused for smooth edges in Sec. 3 of the 2008 paper: "a graph is built connecting
// neighboring clusters ... processed using similar operations as for the sharp edges").
//
// The stage is generic: it knows nothing of normals or curvature. Its input is a partition of
// the cloud into clusters, some of which are marked as candidates (the small clusters of the
// first-order segmentation, the border points of the label growing, the boundary points of an
// open cloud); its output is a network of polylines through those candidates that close on
// themselves or end on other lines.
//
// The steps, in order (the paper names the graphs; what each step does is designed here):
// candidate clusters gathered into nodes; G_all (nodes adjacent through the k nearest
// neighbours); G_extended (plus nodes within extendedRadius); its minimum spanning forest
// with overlong edges cut (G_pruned_mst); short branches cut (G_pruned_branches); free ends
// reconnected to the nearest node ahead, then facing free ends joined across longer gaps and
// ends heading for one corner joined there; bubbles (parallel chains) removed; close
// junctions merged; short pieces dropped; free ends still left extended straight ahead to
// the line they point at, and what still ends in nothing removed up to a length (both off by
// default, on in the sharp stage: sharpGraphOptions() in SharpEdges.h); lines read off as
// chains between nodes of degree other than 2, and cycles.
#pragma once

#include <vector>

#include "FeatureLines/neighbourhoods/Neighbours.h"

namespace featurelines {

/// One polyline of a LineNetwork.
struct Polyline
{
    /// V  #V by 3 vertices in order. A closed line does not repeat its first vertex at the end.
    PointMatrix points;
    bool closed = false;
    /// Row of LineNetwork::junctions the first / last vertex sits on, -1 when that end is free
    /// (a dangling end) or the line is closed without junction.
    int startJunction = -1;
    int endJunction = -1;
    /// The caller's label of the candidate clusters the line runs through (the majority along
    /// it), 0 when the caller gave no labels. SharpEdges.h names its labels.
    int label = 0;
};

/// Lines meeting at junctions: every junction is a point where three or more line ends meet.
struct LineNetwork
{
    std::vector<Polyline> lines;
    /// J  #J by 3 junction positions.
    PointMatrix junctions;
};

/// Every length is a multiple of the cloud's mean point spacing (see meanSpacing()), so the
/// defaults hold on any unit and sampling density. What the 2007 paper leaves open, and so
/// what these defaults design, is described per option.
struct ClusterGraphOptions
{
    /// Candidate clusters are gathered into graph nodes no wider than this radius around the
    /// node's first cluster (0: one node per cluster). A band of single-point candidates
    /// two or three points wide then becomes a chain one node wide, so the spanning tree runs
    /// along the band instead of zigzagging across it. 1.5 covers the 3-spacing-wide bands the
    /// segmentations produce.
    double nodeRadius = 1.5;
    /// G_extended adds an edge between any two nodes closer than this, bridging the gaps of
    /// one or two missing candidates that G_all (clusters adjacent through the k nearest
    /// neighbours) leaves open.
    double extendedRadius = 3.0;
    /// Edges of the spanning tree longer than this are cut (G_pruned_mst): such edges join
    /// two separate features rather than two pieces of one.
    double maxEdgeLength = 4.0;
    /// Branches from a junction to a free end shorter than this are cut (G_pruned_branches):
    /// the tree of a band several nodes wide grows short spurs across it. A band's spurs are
    /// at most its width plus one node spacing, about 4; where three bands meet at a corner,
    /// up to 5-6 (at 5, 3 of 30 seeded cubes kept one; at 6, none of them).
    double minBranchLength = 6.0;
    /// A free end is joined to the nearest node ahead of it within this distance
    /// (reconnection), so lines close or end on other lines. It must exceed
    /// minBranchLength + maxEdgeLength: the spanning tree breaks every cycle of the feature
    /// network somewhere, and branch pruning may shorten the broken end by up to
    /// minBranchLength. 12 also bridges the gaps of a few spacings that noise leaves in the
    /// candidates along a shallow crease.
    double reconnectRadius = 12.0;
    /// Two free ends still left that lie ahead of each other, within half reconnectAngle and
    /// this distance, are joined (0: never). Noise thins the candidates along a shallow crease
    /// into pieces with gaps longer than reconnectRadius; a line continued in its own
    /// direction onto a line coming the other way is safe that far, where a join to just any
    /// node would not be. On the noisy chamfered box of the benchmark, 24 / 36 / 48 spacings
    /// gave sharp F1 0.89 / 0.92 / 0.94 at precision 0.996. With supporting points the whole
    /// reconnectAngle counts (the ends of an arc broken over a gap meet its chord at half the
    /// arc's angle), and the join must be supported along the curve the two ends continue
    /// into each other on.
    double facingEndsRadius = 48.0;
    /// Degrees: "ahead" is within this angle of the line's direction at its end.
    double reconnectAngle = 50.0;
    /// A free end still left after the joins above and the dropping of short pieces is
    /// extended straight ahead, up to this distance, to the first node of a line it points at
    /// (0: never); its direction is read over minBranchLength, then a half and a quarter of
    /// it (an end just past a bend of its line). An end within half maxEdgeLength of another
    /// line's node is joined to it whatever its direction: it stops beside that line. When
    /// the caller gives supporting points, an end with nothing ahead is joined to the nearest
    /// node within twice reconnectRadius in any direction whose way there is supported (an
    /// end at a corner whose other edges left no candidates).
    double extendReach = 0.0;
    /// Degrees: "points at" for extendReach: the node lies within this angle of the end's
    /// direction (plus half maxEdgeLength sideways, for the node's own offset).
    double extendAngle = 10.0;
    /// When the caller gives supporting points (buildClusterGraph), every join longer than
    /// half maxEdgeLength (reconnection, facing and converging ends, extension) needs this
    /// share of the steps (one spacing apart) along it to have a candidate or supporting
    /// point within supportRadius: most of the way, as a crease's normals bend all along it
    /// (noise leaves a step without support now and then), while a way across a face finds
    /// support only near its ends.
    double minExtendSupport = 0.8;
    /// x spacing: the half width of a band of candidates, nodeRadius.
    double supportRadius = 1.5;
    /// Free ends left at the very end are removed with their branch up to the first junction,
    /// and open pieces ending in nothing on both sides go whole, when the branch or piece is
    /// no longer than this (0: never): every line left closes or ends on other lines, unless
    /// it is too long to be anything but a real, broken edge. Off here because the
    /// smooth-edge stage anchors its free ends on the sharp lines after the graph
    /// (SmoothEdges.h); the sharp stage turns it on (sharpGraphOptions()).
    double maxFreeEndLength = 0.0;
    /// A reconnection is refused when it would close a cycle shorter than this many times the
    /// new edge: joining an end back onto its own line a little behind it only makes a loop.
    double minCycleRatio = 3.0;
    /// Of two chains joining the same two junctions, the longer is dropped when it is shorter
    /// than this (and so is a loop shorter than this leaving a junction and returning to it):
    /// where a band is two nodes wide the tree can run two parallel chains, which the
    /// reconnection joins into a bubble. Three times minBranchLength.
    double maxBubbleLength = 18.0;
    /// Junctions joined by a chain shorter than this become one junction: where three bands
    /// meet the tree often forks twice, a node or two apart.
    double junctionMergeLength = 3.0;
    /// Connected pieces of the final graph whose total length is below this are dropped: a few
    /// candidates gathered by noise are not a feature line.
    double minComponentLength = 6.0;
    /// Connected pieces without any cycle (a lone open line or a tree) shorter than this are
    /// dropped too. Feature lines of a part close on themselves or end on other lines, so a
    /// short piece ending in nothing on both sides is noise gathered along a curved surface
    /// rather than a feature; a longer one is kept (a broken feature still marks an edge).
    double minOpenComponentLength = 15.0;
    /// Output lines are resampled at this step; 0 keeps one vertex per node.
    double resampleSpacing = 1.0;
    /// Lines are smoothed along their length over about this distance (the standard deviation
    /// of the equivalent Gaussian; 0: not at all), junctions and free ends staying put. Node
    /// centres wander across a band a few points wide with wavelengths of 2-6 spacings: 2
    /// spacings damp that to a few percent (1 leaves a ring's length 7 % long) and round a
    /// right-angled corner by one or two spacings. Sharp lines are not smoothed but placed on
    /// the crease (SharpEdges.h).
    double smoothingLength = 2.0;
};

/// What each stage of the graph processing did, for diagnostics and tests.
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

/// Builds and processes the cluster graph.
///   P                 #P by 3 points
///   N                 their k nearest neighbours (adjacency of clusters)
///   cluster           #P cluster id per point, 0 .. #C-1; -1 leaves a point out
///   candidateCluster  #C, nonzero for the clusters that become graph nodes
///   spacing           the cloud's mean point spacing (every option length is a multiple of it)
///   clusterLabel      empty, or #C labels; nodes never mix labels and lines carry the
///                     majority label of their nodes
///   supportingPoint   empty, or #P nonzero for the points a line may run through where it
///                     left no candidate (the sharp stage: points whose normals bend like a
///                     crease's); joins across gaps must then run along them or along
///                     candidates (minExtendSupport)
/// Throws std::invalid_argument when the sizes disagree, a cluster id is out of range or the
/// spacing is not a positive number.
ClusterGraph buildClusterGraph(const PointMatrix& P, const Neighbourhoods& N,
                               const std::vector<int>& cluster,
                               const std::vector<char>& candidateCluster, double spacing,
                               const ClusterGraphOptions& options = {},
                               const std::vector<int>& clusterLabel = {},
                               const std::vector<char>& supportingPoint = {});

/// The polyline smoothed along its length over `length` (the standard deviation of the
/// equivalent Gaussian): resampled at a quarter of `length`, then eight passes of (1/4, 1/2,
/// 1/4) weights, which is what makes a smoothing by vertex count one by length. The ends of an
/// open line stay put; the result has the fine vertices (resample it after).
PointMatrix smoothPolyline(const PointMatrix& points, bool closed, double length);

/// The polyline `points` resampled at equal arc-length steps as close to `step` as the length
/// allows; an open line keeps its two end points exactly, a closed line gets at least three
/// vertices. Lines shorter than a step keep their ends only.
PointMatrix resamplePolyline(const PointMatrix& points, bool closed, double step);

} // namespace featurelines
