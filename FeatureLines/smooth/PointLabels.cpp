// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/PointLabels.h"

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>

namespace featurelines {

namespace {

std::vector<char> regionMask(Eigen::Index count, const std::vector<int>& region)
{
    std::vector<char> inRegion(static_cast<size_t>(count), 0);
    for (int i : region) {
        if (i < 0 || i >= count) {
            throw std::invalid_argument("region point index " + std::to_string(i) +
                                        " is outside the cloud");
        }
        inRegion[static_cast<size_t>(i)] = 1;
    }
    return inRegion;
}

PointLabel growthLabel(PointLabel label)
{
    return label == PointLabel::Noisy ? PointLabel::Low : label;
}

} // namespace

std::vector<PointLabel> labelPoints(const Eigen::VectorXd& curvature, double threshold,
                                    const RingNeighbourhoods& ring, const std::vector<int>& region,
                                    const LabelOptions& options)
{
    const Eigen::Index n = curvature.size();
    if (static_cast<Eigen::Index>(ring.offsets.size()) != n + 1) {
        throw std::invalid_argument(
            "labelPoints: curvature and ring neighbourhoods differ in size");
    }
    if (options.minInnerNeighbours < 1) {
        throw std::invalid_argument("labelPoints: minInnerNeighbours must be at least 1");
    }
    const std::vector<char> inRegion = regionMask(n, region);
    std::vector<PointLabel> labels(static_cast<size_t>(n), PointLabel::Outside);
    auto high = [&](int i) { return curvature[i] > threshold; };

    // Sec. 3: inner points first, since border points are defined by their inner neighbours.
    const long m = static_cast<long>(region.size());
#pragma omp parallel for schedule(static, 4096)
    for (long r = 0; r < m; ++r) {
        const int i = region[static_cast<size_t>(r)];
        if (!high(i)) {
            labels[i] = PointLabel::Low;
            continue;
        }
        bool allHigh = true;
        int seen = 0;
        for (const int* q = ring.begin(i); q != ring.end(i); ++q) {
            if (!inRegion[*q]) {
                continue;
            }
            ++seen;
            if (!high(*q)) {
                allHigh = false;
                break;
            }
        }
        labels[i] = (allHigh && seen > 0) ? PointLabel::Inner : PointLabel::Noisy;
    }
    // Border points are found among the others with the inner labels final, then marked.
    std::vector<char> border(region.size(), 0);
#pragma omp parallel for schedule(static, 4096)
    for (long r = 0; r < m; ++r) {
        const int i = region[static_cast<size_t>(r)];
        if (labels[i] != PointLabel::Noisy) {
            continue;
        }
        int inner = 0;
        for (const int* q = ring.begin(i); q != ring.end(i); ++q) {
            if (inRegion[*q] && labels[*q] == PointLabel::Inner) {
                ++inner;
            }
        }
        border[static_cast<size_t>(r)] = inner >= options.minInnerNeighbours;
    }
    for (long r = 0; r < m; ++r) {
        if (border[static_cast<size_t>(r)]) {
            labels[region[static_cast<size_t>(r)]] = PointLabel::Border;
        }
    }
    return labels;
}

LabelClusters growLabelClusters(const std::vector<PointLabel>& labels,
                                const RingNeighbourhoods& ring, const std::vector<int>& region,
                                unsigned seed)
{
    const auto n = static_cast<Eigen::Index>(labels.size());
    if (static_cast<Eigen::Index>(ring.offsets.size()) != n + 1) {
        throw std::invalid_argument(
            "growLabelClusters: labels and ring neighbourhoods differ in size");
    }
    LabelClusters result;
    result.cluster.assign(labels.size(), -1);

    // Sec. 3: seeds are drawn at random among inner and low points.
    std::vector<int> seeds;
    seeds.reserve(region.size());
    for (int i : region) {
        if (labels[i] != PointLabel::Border && labels[i] != PointLabel::Outside) {
            seeds.push_back(i);
        }
    }
    std::mt19937 generator(seed);
    std::shuffle(seeds.begin(), seeds.end(), generator);

    auto newCluster = [&](int point, PointLabel label) {
        const int id = static_cast<int>(result.size.size());
        result.cluster[point] = id;
        result.size.push_back(1);
        result.label.push_back(label);
        return id;
    };

    std::vector<int> stack;
    for (int s : seeds) {
        if (result.cluster[s] >= 0) {
            continue;
        }
        const PointLabel label = growthLabel(labels[s]);
        const int id = newCluster(s, label);
        stack.assign(1, s);
        while (!stack.empty()) {
            const int p = stack.back();
            stack.pop_back();
            for (const int* q = ring.begin(p); q != ring.end(p); ++q) {
                if (labels[*q] == PointLabel::Outside || result.cluster[*q] >= 0) {
                    continue;
                }
                if (growthLabel(labels[*q]) == label) {
                    result.cluster[*q] = id;
                    ++result.size[id];
                    stack.push_back(*q);
                } else {
                    // A label change: the met point becomes a single-point cluster.
                    newCluster(*q, growthLabel(labels[*q]));
                }
            }
        }
    }
    for (int i : region) {
        if (result.cluster[i] < 0) {
            newCluster(i, growthLabel(labels[i]));
        }
    }
    return result;
}

} // namespace featurelines
