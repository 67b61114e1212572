// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/ClusterRefinement.h"

#include <stdexcept>
#include <string>

#include "FeatureLines/smooth/AutomaticThresholds.h"

namespace featurelines {

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
    return smoothEdgesAtThreshold(region, t.threshold, options, subset, {}, level.threshold);
}

} // namespace featurelines
