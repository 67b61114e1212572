// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/SmoothEdges.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "FeatureLines/Normals.h"
#include "FeatureLines/SmoothRegions.h"

namespace featurelines {

namespace {

std::vector<int> allIndices(Eigen::Index n)
{
    std::vector<int> all(static_cast<size_t>(n));
    std::iota(all.begin(), all.end(), 0);
    return all;
}

ThresholdOptions histogramOptions(const RegionGeometry& region, const SmoothEdgeOptions& options)
{
    ThresholdOptions h = options.histogram;
    if (h.outlierPercent < 0.0) {
        // Sec. 2.4: outliers of the curvature come with noise; a clean region keeps them all.
        h.outlierPercent = region.smoothed ? 1.0 : 0.0;
    }
    return h;
}

std::vector<double> valuesOf(const RegionGeometry& region, const std::vector<int>& subset)
{
    std::vector<double> values;
    if (subset.empty()) {
        values.assign(region.curvature.data(), region.curvature.data() + region.curvature.size());
    }
    else {
        values.reserve(subset.size());
        for (int i : subset) {
            values.push_back(region.curvature[i]);
        }
    }
    return values;
}

Eigen::VectorXd averageOverNeighbours(const Eigen::VectorXd& values, const Neighbourhoods& N)
{
    Eigen::VectorXd averaged(values.size());
#pragma omp parallel for schedule(static)
    for (Eigen::Index i = 0; i < values.size(); ++i) {
        double sum = values[i];
        for (int j = 0; j < N.k(); ++j) {
            sum += values[N.indices(i, j)];
        }
        averaged[i] = sum / (N.k() + 1);
    }
    return averaged;
}

double median(std::vector<double> v)
{
    if (v.empty()) {
        return 0.0;
    }
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

} // namespace

double estimateNoise(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                     double spacing)
{
    const Eigen::Index n = P.rows();
    if (n == 0 || N.size() != n || normals.rows() != n || !(spacing > 0.0)) {
        throw std::invalid_argument("estimateNoise: empty or mismatched input");
    }
    std::vector<double> offsets(static_cast<size_t>(n));
#pragma omp parallel for schedule(static)
    for (Eigen::Index i = 0; i < n; ++i) {
        Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
        for (int j = 0; j < N.k(); ++j) {
            centroid += P.row(N.indices(i, j));
        }
        centroid /= N.k();
        offsets[i] = std::abs((P.row(i) - centroid).dot(normals.row(i)));
    }
    return median(std::move(offsets)) / spacing;
}

RegionGeometry analyseRegion(const PointMatrix& P, const Neighbourhoods& N,
                             const std::vector<int>& region, const std::vector<int>& members,
                             int regionId, double spacing, const SmoothEdgeOptions& options)
{
    if (options.curvatureAveragingPasses < 0) {
        throw std::invalid_argument("curvature averaging passes must not be negative");
    }
    if (members.size() <= static_cast<size_t>(N.k())) {
        throw std::invalid_argument("smooth region " + std::to_string(regionId) + " has " +
                                    std::to_string(members.size()) +
                                    " points, too few for its curvature");
    }
    RegionGeometry g;
    g.region = regionId;
    g.members = members;
    g.spacing = spacing;
    g.neighbours = regionNeighbourhoods(N, region, members, regionId);
    g.points.resize(static_cast<Eigen::Index>(members.size()), 3);
    for (size_t i = 0; i < members.size(); ++i) {
        g.points.row(static_cast<Eigen::Index>(i)) = P.row(members[i]);
    }
    g.normals = pcaNormals(g.points, g.neighbours).normals;
    g.noise = estimateNoise(g.points, g.normals, g.neighbours, spacing);
    g.smoothed = options.smoothing == SmoothingMode::Always ||
                 (options.smoothing == SmoothingMode::Automatic && g.noise > options.noiseThreshold);
    if (g.smoothed) {
        // Sec. 2.4: smoothing inside the region only, after the sharp edges are found, so it
        // cannot round them off.
        g.points = laplacianSmooth(g.points, g.neighbours, allIndices(g.points.rows()),
                                   options.smoothingOptions);
        g.normals = pcaNormals(g.points, g.neighbours).normals;
    }
    g.ring = ringNeighbourhoods(g.points, g.normals, g.neighbours);
    g.curvature = meanCurvature(g.points, g.normals, g.neighbours, options.curvature);
    if (g.smoothed) {
        for (int pass = 0; pass < options.curvatureAveragingPasses; ++pass) {
            g.curvature = averageOverNeighbours(g.curvature, g.neighbours);
        }
    }
    return g;
}

ThresholdResult regionThreshold(const RegionGeometry& region, const SmoothEdgeOptions& options,
                                const std::vector<int>& subset)
{
    return findThreshold(valuesOf(region, subset), histogramOptions(region, options));
}

ThresholdResult regionLowerThreshold(const RegionGeometry& region, double threshold,
                                     const SmoothEdgeOptions& options)
{
    return findLowerThreshold(valuesOf(region, {}), threshold, histogramOptions(region, options));
}

ThresholdResult regionHigherThreshold(const RegionGeometry& region, double threshold,
                                      const SmoothEdgeOptions& options)
{
    return findHigherThreshold(valuesOf(region, {}), threshold, histogramOptions(region, options));
}

SmoothEdgeLevel smoothEdgesAtThreshold(const RegionGeometry& region, double threshold,
                                       const SmoothEdgeOptions& options,
                                       const std::vector<int>& subset)
{
    if (!std::isfinite(threshold)) {
        throw std::invalid_argument("the curvature threshold must be a finite number");
    }
    if (options.maxCandidateClusterSize < 1) {
        throw std::invalid_argument("the largest candidate cluster must hold at least one point");
    }
    const std::vector<int> points = subset.empty() ? allIndices(region.points.rows()) : subset;
    SmoothEdgeLevel level;
    level.threshold = threshold;
    level.labels = labelPoints(region.curvature, threshold, region.ring, points, options.labels);
    level.clusters = growLabelClusters(level.labels, region.ring, points, options.seed);

    // Sec. 3: the small clusters ring the patches; the graph of neighbouring small clusters
    // is processed as for the sharp edges [4].
    std::vector<char> candidate(level.clusters.size.size(), 0);
    for (size_t c = 0; c < candidate.size(); ++c) {
        candidate[c] = level.clusters.size[c] <= options.maxCandidateClusterSize;
    }
    const ClusterGraph graph = buildClusterGraph(region.points, region.neighbours,
                                                 level.clusters.cluster, candidate,
                                                 region.spacing, options.graph);
    level.network = graph.network;
    level.counts = graph.counts;
    return level;
}

std::vector<ThresholdDecision> automaticThresholds(const RegionGeometry& region,
                                                   const SmoothEdgeOptions& options)
{
    const AutomaticThresholdOptions& a = options.automatic;
    if (a.maxThresholds < 0 || a.minRatio < 1.0 || a.minInnerPoints < 0 || a.minContrast < 1.0 ||
        !(a.flatRadius > 0.0)) {
        throw std::invalid_argument("automatic thresholds: the limits are out of range");
    }
    const int minInner = a.minInnerPoints > 0 ? a.minInnerPoints : 2 * region.neighbours.k();
    const double flat = 1.0 / (a.flatRadius * region.spacing);
    const ThresholdOptions histogram = histogramOptions(region, options);
    const std::vector<double> all = valuesOf(region, {});
    const std::vector<int> everyPoint = allIndices(region.points.rows());

    std::vector<ThresholdDecision> decisions;
    int accepted = 0;
    // Ranges of values (low, high] still to search, depth first; the first is the whole
    // histogram with its outliers (Sec. 2.4), the next ones below and above each accepted tau.
    struct Range
    {
        double low, high;
        bool first;
    };
    std::vector<Range> ranges{{-std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::infinity(), true}};
    while (!ranges.empty() && accepted < a.maxThresholds) {
        const Range range = ranges.back();
        ranges.pop_back();
        std::vector<double> values;
        for (double v : all) {
            if (v > range.low && v <= range.high) {
                values.push_back(v);
            }
        }
        ThresholdOptions h = histogram;
        if (!range.first) {
            h.outlierPercent = 0.0;
        }
        ThresholdDecision d;
        try {
            d.result = findThreshold(values, h);
        }
        catch (const std::invalid_argument&) {
            continue; // too few distinct values in this range: nothing to split
        }
        const double tau = d.result.threshold;
        std::vector<double> below, above;
        for (double v : values) {
            (v <= tau ? below : above).push_back(v);
        }
        const double medBelow = median(below);
        const double medAbove = median(above);
        d.contrast = (medAbove + flat) / (medBelow + flat);
        const std::vector<PointLabel> labels =
            labelPoints(region.curvature, tau, region.ring, everyPoint, options.labels);
        d.innerPoints = static_cast<int>(std::count(labels.begin(), labels.end(), PointLabel::Inner));
        d.accepted = d.result.ratio >= a.minRatio && d.innerPoints >= minInner &&
                     d.contrast >= a.minContrast;
        decisions.push_back(d);
        if (d.accepted) {
            ++accepted;
            const double high = range.first ? d.result.outlierCut : range.high;
            // Searched next: the higher values first, then the lower (Sec. 2.3 offers both).
            ranges.push_back({range.low, tau, false});
            ranges.push_back({tau, high, false});
        }
    }
    return decisions;
}

SmoothEdgeLevel refineInCluster(const RegionGeometry& region, const SmoothEdgeLevel& level,
                                int cluster, const SmoothEdgeOptions& options)
{
    if (cluster < 0 || cluster >= static_cast<int>(level.clusters.size.size()) ||
        level.clusters.size[cluster] <= options.maxCandidateClusterSize) {
        throw std::invalid_argument("cluster " + std::to_string(cluster) +
                                    " is not a large cluster of this threshold");
    }
    std::vector<int> subset;
    subset.reserve(static_cast<size_t>(level.clusters.size[cluster]));
    for (size_t i = 0; i < level.clusters.cluster.size(); ++i) {
        if (level.clusters.cluster[i] == cluster) {
            subset.push_back(static_cast<int>(i));
        }
    }
    const ThresholdResult t = regionThreshold(region, options, subset);
    return smoothEdgesAtThreshold(region, t.threshold, options, subset);
}

} // namespace featurelines
