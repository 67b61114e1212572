// SPDX-License-Identifier: LGPL-2.1-or-later
// The sharp stage: segmentation, the graph of its small clusters and the boundary, placement.
#include "FeatureLines/sharp/SharpEdges.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>

#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/sharp/CreasePlacement.h"

namespace featurelines {

namespace {

void requireSurface(const PointMatrix& P, double spacing)
{
    // Over an even stride of at most ~100 000 points.
    const Eigen::Index stride = std::max<Eigen::Index>(1, P.rows() / 100000);
    const Eigen::Matrix3d covariance = covarianceOf(P, stride);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance, Eigen::EigenvaluesOnly);
    // The middle eigenvalue is the spread across the cloud's main direction.
    if (std::sqrt(std::max(0.0, solver.eigenvalues()(1))) < spacing) {
        throw std::invalid_argument("sharp edges: the points lie on a line (or a strip narrower "
                                    "than the point spacing); there is no surface to have edges");
    }
}

void requireValidInput(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                       double spacing, const SharpEdgeOptions& options)
{
    const Eigen::Index n = P.rows();
    if (normals.rows() != n || N.size() != n) {
        throw std::invalid_argument(
            "sharp edges: the normals and neighbourhoods must have one row per point (" +
            std::to_string(n) + " points, " + std::to_string(normals.rows()) + " normals, " +
            std::to_string(N.size()) + " neighbourhoods)");
    }
    if (!(spacing > 0.0) || !std::isfinite(spacing)) {
        throw std::invalid_argument("sharp edges: the point spacing must be a positive number");
    }
    if (!(options.fitRadius > 0.0) || options.minFitPoints < 3 ||
        !(options.resampleSpacing >= 0.0)) {
        throw std::invalid_argument(
            "sharp edges: the fit radius must be positive, the fit needs "
            "at least 3 points and the resampling step must not be negative");
    }
    requireSurface(P, spacing);
}

/// The graph options the sharp graph is built with: the caller's, without smoothing and
/// resampling, as the lines are placed on the crease first (placeOnCreases smooths and
/// resamples them after).
ClusterGraphOptions unplacedGraphOptions(const ClusterGraphOptions& graph)
{
    ClusterGraphOptions graphOptions = graph;
    graphOptions.smoothingLength = 0.0;
    graphOptions.resampleSpacing = 0.0;
    return graphOptions;
}

/// #P nonzero for the points a join across a gap may run along.
std::vector<char> bendingPoints(const FirstOrderSegmentation& s)
{
    // Free ends are extended only along points whose normals spread as a crease's do: a
    // crease that left too few candidates (noise thins them) still bends the normals. Beyond
    // the segmentation's limit and beyond what noise gives (noiseSpreadTail): above noise of
    // about 0.3 spacing the limit is clamped below the noise's own spread, a third of a
    // plane's points pass it, and every way across a face found support.
    const Eigen::Index n = s.spread.size();
    const double supportAngle = std::max(s.growAngle, s.noiseSpreadLimit);
    std::vector<char> bending(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        bending[i] = s.spread(i) > supportAngle ? 1 : 0;
    }
    return bending;
}

/// The graph of the small clusters and of the boundary points, lines neither smoothed nor
/// resampled.
ClusterGraph sharpGraph(const PointMatrix& P, const Neighbourhoods& N, double spacing,
                        const SharpEdges& result, const SharpEdgeOptions& options)
{
    const FirstOrderSegmentation& s = result.segmentation;
    // The graph's clusters: the segmentation's, with every boundary point taken out into a
    // candidate cluster of its own, labelled as boundary.
    std::vector<int> cluster = s.cluster;
    std::vector<char> candidate = s.smallCluster;
    std::vector<int> label(candidate.size(), sharpLineLabel);
    for (std::size_t i = 0; i < result.isBoundary.size(); ++i) {
        if (result.isBoundary[i]) {
            cluster[i] = static_cast<int>(candidate.size());
            candidate.push_back(1);
            label.push_back(boundaryLineLabel);
        }
    }
    const ClusterGraphOptions graphOptions = unplacedGraphOptions(options.graph);
    const std::vector<char> bending = bendingPoints(s);
    ClusterGraphInput graphInput{P, N, cluster, candidate, spacing};
    graphInput.clusterLabel = &label;
    graphInput.supportingPoint = &bending;
    return buildClusterGraph(graphInput, graphOptions);
}

} // namespace

SharpEdges extractSharpEdges(const PointMatrix& P, const NormalMatrix& normals,
                             const Neighbourhoods& N, double spacing,
                             const SharpEdgeOptions& options)
{
    requireValidInput(P, normals, N, spacing, options);
    const Eigen::Index n = P.rows();
    SharpEdges result;
    result.segmentation = segmentByNormals(P, normals, N, spacing, options.segmentation);
    result.isSharpCandidate.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        result.isSharpCandidate[i] = result.segmentation.isCandidate(i) ? 1 : 0;
    }
    result.isBoundary.assign(n, 0);
    if (options.includeBoundary) {
        result.isBoundary = boundaryPoints(P, normals, N, options.boundary);
    }
    const ClusterGraph graph = sharpGraph(P, N, spacing, result, options);
    result.counts = graph.counts;
    ProfileTyping typed = typeByProfile(P, normals, result.segmentation, result.isBoundary,
                                        placeOnCreases({P, N, graph, result, spacing, &normals}, options),
                                        spacing, options.profile);
    result.network = std::move(typed.network);
    result.profiles = std::move(typed.profiles);
    return result;
}

} // namespace featurelines
