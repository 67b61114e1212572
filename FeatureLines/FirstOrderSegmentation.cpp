// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/FirstOrderSegmentation.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include <omp.h>

namespace featurelines {

namespace {

constexpr double pi = 3.14159265358979323846;

int threadCount(int requested)
{
    return requested > 0 ? requested : omp_get_max_threads();
}

void requireAngle(double degrees, const char* name)
{
    if (!(degrees > 0.0 && degrees <= 90.0)) {
        throw std::invalid_argument(std::string("first-order segmentation: ") + name +
                                    " must be an angle in degrees between 0 and 90, not " +
                                    std::to_string(degrees));
    }
}

int findRoot(std::vector<int>& parent, int a)
{
    while (parent[a] != a) {
        parent[a] = parent[parent[a]];
        a = parent[a];
    }
    return a;
}

} // namespace

FirstOrderSegmentation segmentByNormals(const NormalMatrix& normals, const Neighbourhoods& N,
                                        const FirstOrderSegmentationOptions& options)
{
    const Eigen::Index n = normals.rows();
    if (N.size() != n) {
        throw std::invalid_argument(
            "first-order segmentation: the neighbourhoods were computed for another cloud (" +
            std::to_string(N.size()) + " rows for " + std::to_string(n) + " normals)");
    }
    if (!normals.allFinite()) {
        throw std::invalid_argument("first-order segmentation: a normal is NaN or infinite");
    }
    requireAngle(options.growAngle, "the grow angle");
    requireAngle(options.joinAngle, "the join angle");
    const int k = N.k();
    const double cosGrow = std::cos(options.growAngle * pi / 180.0);
    const double cosJoin = std::cos(options.joinAngle * pi / 180.0);
    auto similarity = [&](Eigen::Index a, Eigen::Index b) {
        // Unoriented normals: n and -n are the same plane.
        return std::abs(normals.row(a).dot(normals.row(b)));
    };

    FirstOrderSegmentation result;
    result.spread.resize(n);
    std::vector<char> grows(n, 0);
#pragma omp parallel for schedule(static, 4096) num_threads(threadCount(options.threads))
    for (Eigen::Index i = 0; i < n; ++i) {
        double lowest = 1.0;
        for (int j = 0; j < k; ++j) {
            lowest = std::min(lowest, similarity(i, N.indices(i, j)));
        }
        grows[i] = lowest >= cosGrow ? 1 : 0;
        result.spread(i) = std::acos(std::min(1.0, lowest)) * 180.0 / pi;
    }

    // Growing points reached from one another form one cluster: the connected components of
    // the "grows and joins" relation, found with disjoint sets instead of a queue so the
    // result does not depend on the choice of seeds.
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    // Points that cannot grow join the cluster of the growing neighbour whose normal is
    // closest to theirs (the first such neighbour on a tie).
    std::vector<double> bestSimilarity(n, -1.0);
    std::vector<int> owner(n, -1);
    for (Eigen::Index i = 0; i < n; ++i) {
        if (!grows[i]) {
            continue;
        }
        for (int j = 0; j < k; ++j) {
            const int q = N.indices(i, j);
            const double s = similarity(i, q);
            if (s < cosJoin) {
                continue;
            }
            if (grows[q]) {
                int a = findRoot(parent, static_cast<int>(i));
                int b = findRoot(parent, q);
                if (a != b) {
                    parent[std::max(a, b)] = std::min(a, b);
                }
            } else if (s > bestSimilarity[q]) {
                bestSimilarity[q] = s;
                owner[q] = static_cast<int>(i);
            }
        }
    }

    // Cluster ids in the order of each cluster's first point. A point neither growing nor
    // joined stays alone: a cluster of one point.
    result.cluster.assign(n, -1);
    std::vector<int> idOfRoot(n, -1);
    for (Eigen::Index i = 0; i < n; ++i) {
        const int anchor = grows[i] ? static_cast<int>(i) : owner[i] >= 0 ? owner[i]
                                                                            : static_cast<int>(i);
        const int root = findRoot(parent, anchor);
        if (idOfRoot[root] < 0) {
            idOfRoot[root] = static_cast<int>(result.clusterSize.size());
            result.clusterSize.push_back(0);
        }
        result.cluster[i] = idOfRoot[root];
        ++result.clusterSize[idOfRoot[root]];
    }

    // Small clusters: fewer than minInteriorPoints points whose whole neighbourhood is inside.
    std::vector<char> interior(n, 0);
#pragma omp parallel for schedule(static, 4096) num_threads(threadCount(options.threads))
    for (Eigen::Index i = 0; i < n; ++i) {
        bool inside = true;
        for (int j = 0; j < k && inside; ++j) {
            inside = result.cluster[N.indices(i, j)] == result.cluster[i];
        }
        interior[i] = inside ? 1 : 0;
    }
    std::vector<int> interiorCount(result.clusterSize.size(), 0);
    for (Eigen::Index i = 0; i < n; ++i) {
        interiorCount[result.cluster[i]] += interior[i];
    }
    result.smallCluster.resize(result.clusterSize.size());
    for (std::size_t c = 0; c < interiorCount.size(); ++c) {
        result.smallCluster[c] = interiorCount[c] < options.minInteriorPoints ? 1 : 0;
    }
    return result;
}

} // namespace featurelines
