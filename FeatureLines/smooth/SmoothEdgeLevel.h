// SPDX-License-Identifier: LGPL-2.1-or-later
// The closed lines of a region at one curvature threshold (Sec. 3 of the 2008 paper): the
// low / inner / border labels, region growing on them, and the cluster graph that turns the
// single-point clusters into lines, anchored on the sharp and boundary lines around.
// Design: docs/design/smooth-edges.md, "The lines at one threshold".
#pragma once

#include <vector>

#include "FeatureLines/network/ClusterGraph.h"
#include "FeatureLines/smooth/PointLabels.h"
#include "FeatureLines/smooth/RegionGeometry.h"

namespace featurelines {

/// The closed lines at one threshold of a region.
struct SmoothEdgeLevel
{
    double threshold = 0.0;
    /// Per region point: its Sec. 3 label at this threshold and its label cluster.
    std::vector<PointLabel> labels;
    LabelClusters clusters;
    /// Lines on the region's (possibly smoothed) points.
    LineNetwork network;
    ClusterGraphCounts counts;
};

/// The graph options of the smooth stage: options.graph without its open-piece filter
/// (minOpenComponentLength = 0). smoothEdgesAtThreshold applies that filter once the line ends
/// are anchored on the lines that bound the region: a fillet border running from one sharp
/// edge to another is short but complete.
inline ClusterGraphOptions smoothGraphOptions(const SmoothEdgeOptions& options)
{
    ClusterGraphOptions graph = options.graph;
    graph.minOpenComponentLength = 0.0;
    return graph;
}

/// Sec. 3 at threshold tau over the whole region, or over `subset` (region point indices)
/// only, as the multi-step refinement does. Noise islands are levelled before the labels
/// (SmoothEdgeOptions::islandMargin); lines without contrast across them are dropped
/// (minLineContrast, and minRelativeContrast of tau - `below`, where `below` is the threshold
/// of the level beneath: the region's next lower threshold, 0 for its lowest); free line ends
/// are anchored on the `anchors` (the sharp and boundary lines around the region, see
/// anchorLineEnds); short spurs and open pieces shorter than
/// options.graph.minOpenComponentLength with an end on nothing are then dropped.
SmoothEdgeLevel smoothEdgesAtThreshold(const RegionGeometry& region, double threshold,
                                       const SmoothEdgeOptions& options = {},
                                       const std::vector<int>& subset = {},
                                       const std::vector<Polyline>& anchors = {},
                                       double below = 0.0);

/// The contrast across a line at threshold tau (1 / length unit; minLineContrast): the median
/// over the line's `points` (region point indices) of the local contrast, the median curvature
/// above tau minus that at or below it within two fit radii; points with values on one side
/// only count not, and 0 when none is left. At a coarser curvature scale (RegionGeometry::
/// coarse) it is taken there, at the cells the points were averaged into.
double lineContrast(const RegionGeometry& region, const Eigen::VectorXd& curvature, double tau,
                    const std::vector<int>& points);

} // namespace featurelines
