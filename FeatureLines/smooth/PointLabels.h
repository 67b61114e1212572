// SPDX-License-Identifier: LGPL-2.1-or-later
// Sec. 3: low / inner / border / noisy labels of a smooth region at one curvature threshold,
// and the region growing on those labels that rings each patch with single-point clusters.
// Design: docs/design/labels.md.
#pragma once

#include <cstdint>
#include <vector>

#include "FeatureLines/neighbourhoods/RingNeighbourhood.h"

namespace featurelines {

enum class PointLabel : std::uint8_t
{
    /// curvature <= tau (Sec. 2.1), and high points found to be noisy (Sec. 3).
    Low = 0,
    /// A high point whose 1-ring holds only high points.
    Inner = 1,
    /// Any other high point with at least `minInnerNeighbours` inner points in its 1-ring.
    Border = 2,
    /// A high point that is neither: isolated noise, counted as low afterwards (Sec. 3).
    Noisy = 3,
    /// Not in the region being labelled.
    Outside = 255,
};

struct LabelOptions
{
    /// Inner points a border point needs in its 1-ring (default 2, Sec. 3).
    int minInnerNeighbours = 2;
};

/// Labels the points of `region` (point indices) at threshold tau: curvature[i] > tau is high.
/// Ring neighbours outside the region are ignored, so a region's edge is not taken for low
/// points. Points not in the region get PointLabel::Outside.
std::vector<PointLabel> labelPoints(const Eigen::VectorXd& curvature, double threshold,
                                    const RingNeighbourhoods& ring, const std::vector<int>& region,
                                    const LabelOptions& options = {});

struct LabelClusters
{
    /// #P cluster id per point (-1 outside the region).
    std::vector<int> cluster;
    /// Points per cluster.
    std::vector<int> size;
    /// Label the cluster grew on (Low for low and noisy points, Inner, or Border for the
    /// single-point clusters met at a label change).
    std::vector<PointLabel> label;
};

/// Sec. 3 region growing on the labels over the 1-rings: a seed is drawn at random (seeded,
/// reproducible) among the unclustered inner and low points; the cluster takes every reachable
/// point of the seed's label; a point of another label that it meets becomes a cluster of its
/// own single point. Repeated until every point of the region belongs to a cluster (border points
/// no growth reaches become single-point clusters too). Noisy points count as low.
LabelClusters growLabelClusters(const std::vector<PointLabel>& labels,
                                const RingNeighbourhoods& ring, const std::vector<int>& region,
                                unsigned seed = 1);

} // namespace featurelines
