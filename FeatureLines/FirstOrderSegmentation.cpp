// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/FirstOrderSegmentation.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

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

FirstOrderSegmentation segmentByNormals(const PointMatrix& P, const NormalMatrix& normals,
                                        const Neighbourhoods& N, double spacing,
                                        const FirstOrderSegmentationOptions& options)
{
    const Eigen::Index n = P.rows();
    if (N.size() != n || normals.rows() != n) {
        throw std::invalid_argument(
            "first-order segmentation: the normals and neighbourhoods must have one row per "
            "point (" +
            std::to_string(n) + " points, " + std::to_string(normals.rows()) + " normals, " +
            std::to_string(N.size()) + " neighbourhoods)");
    }
    if (!(spacing > 0.0) || !std::isfinite(spacing)) {
        throw std::invalid_argument("first-order segmentation: the point spacing must be a "
                                    "positive number");
    }
    if (!(options.minFilletRadius > 0.0)) {
        throw std::invalid_argument("first-order segmentation: the smallest fillet radius must "
                                    "be positive");
    }
    if (!normals.allFinite()) {
        throw std::invalid_argument("first-order segmentation: a normal is NaN or infinite");
    }
    requireAngle(options.growAngle, "the grow angle");
    requireAngle(options.joinAngle, "the join angle");
    const int k = N.k();
    const double cosJoin = std::cos(options.joinAngle * pi / 180.0);
    auto similarity = [&](Eigen::Index a, Eigen::Index b) {
        // Unoriented normals: n and -n are the same plane.
        return std::abs(normals.row(a).dot(normals.row(b)));
    };

    FirstOrderSegmentation result;
    if (n == 0) {
        return result;
    }
    result.spread.resize(n);
    Eigen::VectorXd variation(n);
#pragma omp parallel for schedule(static, 4096) num_threads(threadCount(options.threads))
    for (Eigen::Index i = 0; i < n; ++i) {
        double lowest = 1.0;
        // Surface variation lambda0 / (lambda0 + lambda1 + lambda2) of the point and its
        // neighbours, with lambda0 read along the given normal: n^T C n / trace C.
        const Eigen::RowVector3d origin = P.row(i);
        const Eigen::RowVector3d normal = normals.row(i);
        Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
        double squares = 0.0;
        double heights = 0.0;
        double heightSquares = 0.0;
        for (int j = 0; j < k; ++j) {
            const int q = N.indices(i, j);
            lowest = std::min(lowest, similarity(i, q));
            const Eigen::RowVector3d d = P.row(q) - origin;
            const double h = d.dot(normal);
            sum += d;
            squares += d.squaredNorm();
            heights += h;
            heightSquares += h * h;
        }
        const double count = k + 1;
        const double trace = squares / count - (sum / count).squaredNorm();
        const double across = heightSquares / count - std::pow(heights / count, 2);
        variation(i) = trace > 0.0 ? std::max(0.0, across) / trace : 0.0;
        result.spread(i) = std::acos(std::min(1.0, lowest)) * 180.0 / pi;
    }

    // The excess of surface variation over the cloud's typical value. Noise along the normal
    // adds its variance to lambda0 everywhere, so the cloud's median (most points lie on
    // smooth patches) is the noise floor, and its spread (the median absolute deviation) how
    // far noise alone reaches above it.
    // Medians of an evenly strided sample of at most ~100 000 points are as good and cheap.
    const Eigen::Index stride = std::max<Eigen::Index>(1, n / 100000);
    auto median = [](std::vector<double>& v) {
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    };
    std::vector<double> sample;
    for (Eigen::Index i = 0; i < n; i += stride) {
        sample.push_back(variation(i));
    }
    const double floor = median(sample);
    result.planarityExcess = variation.array() - floor;
    for (double& v : sample) {
        v = std::abs(v - floor);
    }
    const double noiseDeviation = 1.4826 * median(sample); // the normal law's sigma from its MAD

    // A sphere of radius r sampled over a ball of radius R has surface variation
    // R^2 / (24 r^2) (heights rho^2 / 2r over the disc), a cylinder R^2 / (32 r^2); R is the
    // typical distance to the k-th neighbour.
    std::vector<double> reach;
    for (Eigen::Index i = 0; i < n; i += stride) {
        reach.push_back(N.squaredDistances(i, k - 1));
    }
    const double filletRadius = options.minFilletRadius * spacing;
    result.minExcess = std::max(median(reach) / (24.0 * filletRadius * filletRadius),
                                options.noiseMargin * noiseDeviation);

    std::vector<char> grows(n, 0);
    for (Eigen::Index i = 0; i < n; ++i) {
        grows[i] =
            result.spread(i) <= options.growAngle || result.planarityExcess(i) <= result.minExcess
                ? 1
                : 0;
    }

    // Growing points reached from one another form one cluster: the connected components of
    // the "grows and joins" relation, found with disjoint sets instead of a queue so the
    // result does not depend on the choice of seeds.
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    for (Eigen::Index i = 0; i < n; ++i) {
        if (!grows[i]) {
            continue;
        }
        int root = findRoot(parent, static_cast<int>(i));
        for (int j = 0; j < k; ++j) {
            const int q = N.indices(i, j);
            if (grows[q] && similarity(i, q) >= cosJoin) {
                const int other = findRoot(parent, q);
                if (other != root) {
                    // The smaller root survives, as i's root is looked up only once.
                    parent[std::max(root, other)] = std::min(root, other);
                    root = std::min(root, other);
                }
            }
        }
    }
    // A point that cannot grow joins the cluster of the growing neighbour whose normal is
    // closest to its own (the nearest such neighbour on a tie).
    std::vector<int> owner(n, -1);
#pragma omp parallel for schedule(static, 4096) num_threads(threadCount(options.threads))
    for (Eigen::Index i = 0; i < n; ++i) {
        if (grows[i]) {
            continue;
        }
        double best = cosJoin;
        for (int j = 0; j < k; ++j) {
            const int q = N.indices(i, j);
            const double s = similarity(i, q);
            if (grows[q] && (s > best || (s == best && owner[i] < 0))) {
                best = s;
                owner[i] = q;
            }
        }
    }

    // Cluster ids in the order of each cluster's first point. A point neither growing nor
    // joined stays alone: a cluster of one point.
    result.cluster.assign(n, -1);
    std::vector<int> idOfRoot(n, -1);
    for (Eigen::Index i = 0; i < n; ++i) {
        const int anchor = grows[i]        ? static_cast<int>(i)
                           : owner[i] >= 0 ? owner[i]
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
