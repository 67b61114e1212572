// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/SmoothEdgeLevel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "FeatureLines/network/LineNetworkEdits.h"
#include "FeatureLines/smooth/PointValues.h"
#include "FeatureLines/smooth/LineBand.h"
#include "FeatureLines/smooth/RegionNeighbourhoods.h"

namespace featurelines {

namespace {

using detail::allIndices;
using detail::median;

/// The smallest piece of one level that counts as a patch, in the region's points, when the
/// curvature was computed at a coarser scale: a patch's worth of its samples
/// (AutomaticThresholdOptions::minInnerPoints), each standing for curvatureScale^2 of the
/// region's points. A smaller piece of the smooth carried-back field is a blob of the coarse
/// samples' noise. At the region's own scale there is no such size: a piece of a few points can
/// be a real patch's end (a fillet border running into a corner), and noise islands there are
/// told by their values (islandMargin).
int minIslandPoints(const RegionGeometry& region, const SmoothEdgeOptions& options)
{
    if (!(region.curvatureScale > 1.0)) {
        return 0;
    }
    const int inner = options.automatic.minInnerPoints > 0 ? options.automatic.minInnerPoints
                                                           : 2 * region.neighbours.k();
    return static_cast<int>(std::lround(inner * region.curvatureScale * region.curvatureScale));
}

/// The curvature with the noise islands of threshold tau levelled: connected pieces (over the
/// 1-rings) of points above tau whose 90th percentile stays below tau + margin, or that hold
/// fewer than minPoints points, are set to tau (low); pieces at or below tau whose 10th
/// percentile stays above tau - margin, or that hold fewer than minPoints, are set just above
/// it (high). Only the points of `points` are looked at.
Eigen::VectorXd withoutNoiseIslands(const Eigen::VectorXd& curvature, double tau,
                                    const RingNeighbourhoods& ring, const std::vector<int>& points,
                                    double margin, int minPoints)
{
    Eigen::VectorXd result = curvature;
    if (!(margin > 0.0) && minPoints <= 1) {
        return result;
    }
    const Eigen::Index n = curvature.size();
    std::vector<char> inSet(static_cast<size_t>(n), 0);
    for (int i : points) {
        inSet[static_cast<size_t>(i)] = 1;
    }
    std::vector<char> seen(static_cast<size_t>(n), 0);
    std::vector<int> piece, stack;
    std::vector<double> values;
    const double above = std::nextafter(tau, std::numeric_limits<double>::infinity());
    for (int s : points) {
        if (seen[static_cast<size_t>(s)]) {
            continue;
        }
        const bool high = curvature[s] > tau;
        piece.assign(1, s);
        stack.assign(1, s);
        seen[static_cast<size_t>(s)] = 1;
        while (!stack.empty()) {
            const int p = stack.back();
            stack.pop_back();
            for (const int* q = ring.begin(p); q != ring.end(p); ++q) {
                if (inSet[static_cast<size_t>(*q)] && !seen[static_cast<size_t>(*q)] &&
                    (curvature[*q] > tau) == high) {
                    seen[static_cast<size_t>(*q)] = 1;
                    piece.push_back(*q);
                    stack.push_back(*q);
                }
            }
        }
        values.clear();
        for (int p : piece) {
            values.push_back(curvature[p]);
        }
        const size_t at = high ? values.size() * 9 / 10 : values.size() / 10;
        std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(at),
                         values.end());
        const double extreme = values[at];
        if (static_cast<int>(piece.size()) < minPoints ||
            (margin > 0.0 && (high ? extreme < tau + margin : extreme > tau - margin))) {
            for (int p : piece) {
                result[p] = high ? tau : above;
            }
        }
    }
    return result;
}

/// The local contrast across threshold tau at point p of the geometry g: among the points
/// within two fit radii (two hops of the neighbourhoods), the median curvature of those above
/// tau minus that of those at or below it; NaN when they lie on one side only.
double localContrast(const RegionGeometry& g, const Eigen::VectorXd& curvature, double tau, int p)
{
    const Neighbourhoods& N = g.neighbours;
    const double reach2 = 4.0 * N.squaredDistances(p, N.k() - 1);
    std::vector<int> near{p};
    for (int j = 0; j < N.k(); ++j) {
        const int q = N.indices(p, j);
        near.push_back(q);
        for (int l = 0; l < N.k(); ++l) {
            near.push_back(N.indices(q, l));
        }
    }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    std::vector<double> high, low;
    for (int q : near) {
        if ((g.points.row(q) - g.points.row(p)).squaredNorm() <= reach2) {
            (curvature[q] > tau ? high : low).push_back(curvature[q]);
        }
    }
    if (high.empty() || low.empty()) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    return median(std::move(high)) - median(std::move(low));
}

} // namespace

double lineContrast(const RegionGeometry& g, const Eigen::VectorXd& curvature, double tau,
                    const std::vector<int>& points)
{
    const bool coarse = g.coarse && g.coarseRowOf.size() == static_cast<size_t>(g.points.rows());
    std::vector<int> at;
    if (coarse) {
        for (int p : points) {
            at.push_back(g.coarseRowOf[static_cast<size_t>(p)]);
        }
        std::sort(at.begin(), at.end());
        at.erase(std::unique(at.begin(), at.end()), at.end());
    }
    const std::vector<int>& where = coarse ? at : points;
    std::vector<double> contrasts(where.size(), std::numeric_limits<double>::quiet_NaN());
#pragma omp parallel for schedule(dynamic, 16)
    for (long s = 0; s < static_cast<long>(where.size()); ++s) {
        const int p = where[static_cast<size_t>(s)];
        contrasts[static_cast<size_t>(s)] =
            coarse ? localContrast(*g.coarse, g.coarse->curvature, tau, p)
                   : localContrast(g, curvature, tau, p);
    }
    contrasts.erase(
        std::remove_if(contrasts.begin(), contrasts.end(), [](double c) { return std::isnan(c); }),
        contrasts.end());
    return contrasts.empty() ? 0.0 : median(std::move(contrasts));
}

namespace {

void requireLevelOptions(double threshold, const SmoothEdgeOptions& options)
{
    if (!std::isfinite(threshold)) {
        throw std::invalid_argument("the curvature threshold must be a finite number");
    }
    if (!(options.minRelativeContrast >= 0.0)) {
        throw std::invalid_argument("the least relative line contrast must not be negative");
    }
    if (options.placeOwnScaleLines &&
        !(options.ownScaleHalfWidth > 0.0 && options.ownScaleMaxShift > 0.0 &&
          std::isfinite(options.ownScaleHalfWidth + options.ownScaleMaxShift))) {
        throw std::invalid_argument(
            "the own scale's strip half width and largest shift must be positive numbers");
    }
    if (options.maxCandidateClusterSize < 1) {
        throw std::invalid_argument("the largest candidate cluster must hold at least one point");
    }
    if (!(options.anchorReach >= 0.0) || !(options.anchorAngle >= 0.0) ||
        !(options.anchorBand >= 0.0)) {
        throw std::invalid_argument("the anchoring reach and angle must not be negative");
    }
}

/// Per label cluster of the level: a candidate of the graph (Sec. 3: a small cluster), unless
/// its points lie within the anchor band of the lines that bound the region.
std::vector<char> candidateClusters(const RegionGeometry& region, const SmoothEdgeLevel& level,
                                    const std::vector<int>& points,
                                    const std::vector<Polyline>& anchors,
                                    const SmoothEdgeOptions& options)
{
    // Sec. 3: the small clusters ring the patches; the graph of neighbouring small clusters
    // is processed as for the sharp edges [4].
    std::vector<char> candidate(level.clusters.size.size(), 0);
    for (size_t c = 0; c < candidate.size(); ++c) {
        candidate[c] = level.clusters.size[c] <= options.maxCandidateClusterSize;
    }
    // Next to the lines that bound the region (an open cloud's boundary runs through it) the
    // neighbourhoods are one-sided: no candidates there; the lines are anchored across.
    if (!anchors.empty() && options.anchorBand > 0.0) {
        std::vector<int> candidatePoints;
        for (int i : points) {
            const int c = level.clusters.cluster[i];
            if (c >= 0 && candidate[c]) {
                candidatePoints.push_back(i);
            }
        }
        const std::vector<char> near = pointsNearLines(region.points, candidatePoints, anchors,
                                                       options.anchorBand * region.spacing);
        for (size_t j = 0; j < candidatePoints.size(); ++j) {
            if (near[j]) {
                candidate[level.clusters.cluster[candidatePoints[j]]] = 0;
            }
        }
    }
    return candidate;
}

/// Per line of the graph's network: the region points of the nodes it runs through.
std::vector<std::vector<int>> pointsOfLines(const ClusterGraph& graph, size_t lineCount)
{
    std::vector<std::vector<int>> pointsOfNode(static_cast<size_t>(graph.nodes.rows()));
    for (size_t i = 0; i < graph.nodeOfPoint.size(); ++i) {
        if (graph.nodeOfPoint[i] >= 0) {
            pointsOfNode[static_cast<size_t>(graph.nodeOfPoint[i])].push_back(static_cast<int>(i));
        }
    }
    std::vector<std::vector<int>> linePoints(lineCount);
    for (size_t l = 0; l < graph.lineNodes.size() && l < lineCount; ++l) {
        for (int v : graph.lineNodes[l]) {
            if (v >= 0 && v < static_cast<int>(pointsOfNode.size())) {
                const auto& ps = pointsOfNode[static_cast<size_t>(v)];
                linePoints[l].insert(linePoints[l].end(), ps.begin(), ps.end());
            }
        }
    }
    return linePoints;
}

/// A line must part two levels where it runs: across it, within two fit radii, the curvature
/// on its high side must exceed that on its low side by minLineContrast noise floors (the
/// median over the line's candidate points). The edge of a noise island, or a drifting
/// curvature crossing tau, has about one floor across it. The contrast must also reach
/// minRelativeContrast of the step from the level beneath (`below`) to tau: a fillet's border
/// parts that level from the fillet's, beyond tau, where a curvature drifting through tau along
/// a freeform surface shows a fraction of it within two fit radii, at any noise. Drops the
/// lines that do not.
void dropLinesWithoutContrast(const RegionGeometry& region, const ClusterGraph& graph,
                              const Eigen::VectorXd& curvature, const SmoothEdgeOptions& options,
                              double below, SmoothEdgeLevel& level)
{
    const bool floors = options.minLineContrast > 0.0 && region.curvatureNoise > 0.0;
    const double relative = options.minRelativeContrast;
    if (!floors && !(relative > 0.0)) {
        return;
    }
    const std::vector<std::vector<int>> linePoints =
        pointsOfLines(graph, level.network.lines.size());
    std::vector<char> weak(level.network.lines.size(), 0);
    for (size_t l = 0; l < graph.lineNodes.size() && l < weak.size(); ++l) {
        const double contrast = lineContrast(region, curvature, level.threshold, linePoints[l]);
        weak[l] = (floors && contrast < options.minLineContrast * region.curvatureNoise) ||
                  contrast < relative * (level.threshold - below);
    }
    level.counts.droppedComponents += static_cast<int>(std::count(weak.begin(), weak.end(), 1));
    std::vector<char> anchored; // none yet: the ends are anchored after
    dropLines(level.network, anchored, weak);
}

/// The graph's lines as the region keeps them: moved onto the curvature steps (in strips
/// widened to the fillet at a coarser scale, of a fixed width at the region's own), free ends
/// anchored on the lines around, then short spurs and open pieces with an end on nothing
/// dropped (SmoothEdgeOptions::graph.minOpenComponentLength).
void finishLines(const RegionGeometry& region, const std::vector<Polyline>& anchors,
                 const SmoothEdgeOptions& options, SmoothEdgeLevel& level)
{
    const bool coarse = region.curvatureScale > 1.0;
    if (coarse ? options.placeCoarseLines : options.placeOwnScaleLines) {
        LinePlacementOptions placement = options.placement;
        if (!coarse) {
            placement.halfWidth = options.ownScaleHalfWidth;
            placement.radiusShare = 0.0;
            placement.maxShift = options.ownScaleMaxShift / options.ownScaleHalfWidth;
            placement.recentres = 0;
        }
        placeOnCurvatureSteps(level.network,
                              {region.points, region.normals, region.curvature, region.spacing,
                               region.curvatureScale * region.spacing, level.threshold},
                              placement);
    }
    std::vector<char> anchored = anchorLineEnds(
        level.network, anchors, options.anchorReach * region.spacing, options.anchorAngle);
    const double minOpen = options.graph.minOpenComponentLength * region.spacing;
    level.counts.prunedBranches += pruneDanglingLines(level.network, anchored, minOpen);
    level.counts.droppedComponents += dropOpenPieces(level.network, anchored, minOpen);
}

} // namespace

SmoothEdgeLevel smoothEdgesAtThreshold(const RegionGeometry& region, double threshold,
                                       const SmoothEdgeOptions& options,
                                       const std::vector<int>& subset,
                                       const std::vector<Polyline>& anchors, double below)
{
    requireLevelOptions(threshold, options);
    if (!std::isfinite(below)) {
        throw std::invalid_argument("the curvature level beneath the threshold must be a finite number");
    }
    const std::vector<int> points = subset.empty() ? allIndices(region.points.rows()) : subset;
    SmoothEdgeLevel level;
    level.threshold = threshold;
    // Islands of one side whose values stay within a few noise floors of tau are noise of
    // the level around them, not patches: they join that level before the labels are drawn.
    const Eigen::VectorXd curvature = withoutNoiseIslands(
        region.curvature, threshold, region.ring, points,
        options.islandMargin * region.curvatureNoise, minIslandPoints(region, options));
    level.labels = labelPoints(curvature, threshold, region.ring, points, options.labels);
    level.clusters = growLabelClusters(level.labels, region.ring, points, options.seed);
    const std::vector<char> candidate = candidateClusters(region, level, points, anchors, options);
    const ClusterGraphOptions graphOptions = smoothGraphOptions(options);
    const ClusterGraph graph = buildClusterGraph(
        {region.points, region.neighbours, level.clusters.cluster, candidate, region.spacing},
        graphOptions);
    level.network = graph.network;
    level.counts = graph.counts;
    dropLinesWithoutContrast(region, graph, curvature, options, below, level);
    finishLines(region, anchors, options, level);
    return level;
}

} // namespace featurelines
