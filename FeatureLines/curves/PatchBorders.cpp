// SPDX-License-Identifier: LGPL-2.1-or-later
// The border loops of each surface patch: the network edges along the patch, walked into
// closed loops through their shared vertices (docs/design/curves.md, "Patch borders").
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "FeatureLines/curves/CurveFit.h"
#include "FeatureLines/curves/CurveNetwork.h"
#include "FeatureLines/network/NodeGraph.h"

namespace featurelines {

namespace {

/// Per edge, the patches it borders (PatchBorderOptions). The pieces a line's stretch between
/// junctions was cut into at its corners (NetworkEdge::run) are counted as one: a corner adds
/// vertices to a border, it does not change which patches the line borders (near a corner a
/// short piece can lie along a second patch, where two lines run side by side into it).
std::vector<std::vector<int>> patchesAlongEdges(const CurveNetwork& net,
                                                const std::vector<Eigen::Vector3d>& patchPoints,
                                                const std::vector<int>& patchOfPoint,
                                                double spacing, const PatchBorderOptions& options)
{
    const double reach = options.reach * spacing;
    const clustergraph::NodeGrid grid(patchPoints, reach);
    std::vector<std::vector<int>> out(net.edges.size());
    // Per run: the samples used, and per patch the samples that see it.
    std::map<long, std::pair<long, std::map<int, long>>> runs;
    const auto runOf = [&](size_t i) {
        return net.edges[i].run >= 0 ? static_cast<long>(net.edges[i].run)
                                     : -2 - static_cast<long>(i);
    };
    for (size_t i = 0; i < net.edges.size(); ++i) {
        const NetworkEdge& e = net.edges[i];
        PointMatrix samples = sampleCurve(e.curve, spacing);
        if (e.curve.kind == CurveKind::Segment) {
            // A segment samples its two ends only: once per spacing along it.
            const int n = std::max(2, static_cast<int>(std::ceil(curveLength(e.curve) / spacing)));
            samples.resize(n + 1, 3);
            for (int k = 0; k <= n; ++k) {
                samples.row(k) = curvePoint(e.curve, double(k) / n).transpose();
            }
        }
        // Near its vertices an edge passes the patches of the other edges there too.
        const double endZone = std::min(reach, 0.25 * curveLength(e.curve));
        std::vector<Eigen::Vector3d> used;
        for (Eigen::Index k = 0; k < samples.rows(); ++k) {
            const Eigen::Vector3d s = samples.row(k).transpose();
            if ((s - e.curve.start).norm() > endZone && (s - e.curve.end).norm() > endZone) {
                used.push_back(s);
            }
        }
        if (used.empty()) {
            for (Eigen::Index k = 0; k < samples.rows(); ++k) {
                used.push_back(samples.row(k).transpose());
            }
        }
        auto& [usedInRun, seen] = runs[runOf(i)];
        usedInRun += static_cast<long>(used.size());
        const double margin = options.margin * spacing;
        for (const Eigen::Vector3d& s : used) {
            std::map<int, double> nearest;
            double closest = std::numeric_limits<double>::infinity();
            grid.forEachWithin(s, reach, [&](int p) {
                const double d = (patchPoints[static_cast<size_t>(p)] - s).norm();
                auto [it, added] = nearest.emplace(patchOfPoint[static_cast<size_t>(p)], d);
                if (!added) {
                    it->second = std::min(it->second, d);
                }
                closest = std::min(closest, d);
            });
            for (const auto& [patch, d] : nearest) {
                if (d <= closest + margin) {
                    ++seen[patch];
                }
            }
        }
    }
    for (size_t i = 0; i < net.edges.size(); ++i) {
        const auto& [used, seen] = runs[runOf(i)];
        for (const auto& [patch, count] : seen) {
            if (static_cast<double>(count) >= options.share * static_cast<double>(used)) {
                out[i].push_back(patch);
            }
        }
    }
    return out;
}

/// The loops of the edges `edges` (rows of net.edges): the edges that close no loop (an end on
/// a vertex no other of them meets, repeatedly) go to `open`; the rest are walked into loops
/// from edge to edge through their shared vertices.
void walkLoops(const CurveNetwork& net, std::vector<int> edges, PatchBorder& border)
{
    std::map<int, int> degree;
    for (int e : edges) {
        ++degree[net.edges[e].startVertex];
        ++degree[net.edges[e].endVertex];
    }
    for (bool pruned = true; pruned;) {
        pruned = false;
        for (size_t k = 0; k < edges.size(); ++k) {
            const NetworkEdge& e = net.edges[edges[k]];
            if (degree[e.startVertex] == 1 || degree[e.endVertex] == 1) {
                --degree[e.startVertex];
                --degree[e.endVertex];
                border.openEdges.push_back(edges[k]);
                edges.erase(edges.begin() + static_cast<long>(k));
                pruned = true;
                break;
            }
        }
    }
    std::vector<bool> used(edges.size(), false);
    std::vector<std::pair<double, std::vector<LoopEdge>>> loops;
    for (size_t first = 0; first < edges.size(); ++first) {
        if (used[first]) {
            continue;
        }
        used[first] = true;
        const NetworkEdge& e0 = net.edges[edges[first]];
        std::vector<LoopEdge> loop{{edges[first], false}};
        std::vector<size_t> taken{first};
        int at = e0.endVertex;
        while (at != e0.startVertex) {
            size_t next = edges.size();
            for (size_t k = 0; k < edges.size() && next == edges.size(); ++k) {
                const NetworkEdge& e = net.edges[edges[k]];
                if (!used[k] && (e.startVertex == at || e.endVertex == at)) {
                    next = k;
                }
            }
            if (next == edges.size()) {
                break;
            }
            used[next] = true;
            taken.push_back(next);
            const NetworkEdge& e = net.edges[edges[next]];
            const bool reversed = e.startVertex != at;
            loop.push_back({edges[next], reversed});
            at = reversed ? e.startVertex : e.endVertex;
        }
        if (at != e0.startVertex) {
            for (size_t k : taken) {
                border.openEdges.push_back(edges[k]);
            }
            continue;
        }
        double length = 0.0;
        for (const LoopEdge& le : loop) {
            length += curveLength(net.edges[le.edge].curve);
        }
        loops.emplace_back(length, std::move(loop));
    }
    // The outer loop is the longest; the others are holes.
    std::stable_sort(loops.begin(), loops.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    for (auto& [length, loop] : loops) {
        border.loops.push_back(std::move(loop));
    }
    std::sort(border.openEdges.begin(), border.openEdges.end());
}

} // namespace

std::vector<PatchBorder> patchBorders(const CurveNetwork& network, const ExtractionResult& result,
                                      const PointMatrix& points, const PatchBorderOptions& options)
{
    if (static_cast<Eigen::Index>(result.patch.size()) != points.rows()) {
        throw std::invalid_argument("the cloud has " + std::to_string(points.rows()) +
                                    " points but the extraction result " +
                                    std::to_string(result.patch.size()));
    }
    if (!(options.reach > 0) || !(options.margin >= 0) || !(options.share > 0) ||
        options.share > 1) {
        throw std::invalid_argument("the patch border reach and margin must be positive and "
                                    "the share in (0, 1]");
    }
    if (!network.edges.empty() && !(result.spacing > 0)) {
        throw std::invalid_argument("the extraction result has no point spacing");
    }
    std::vector<Eigen::Vector3d> patchPoints;
    std::vector<int> patchOfPoint;
    int patches = 0;
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        const int p = result.patch[static_cast<size_t>(i)];
        if (p >= 0) {
            patchPoints.push_back(points.row(i).transpose());
            patchOfPoint.push_back(p);
            patches = std::max(patches, p + 1);
        }
    }
    std::vector<std::vector<int>> edgesOfPatch(static_cast<size_t>(patches));
    if (!network.edges.empty() && !patchPoints.empty()) {
        const std::vector<std::vector<int>> along =
            patchesAlongEdges(network, patchPoints, patchOfPoint, result.spacing, options);
        for (size_t e = 0; e < along.size(); ++e) {
            for (int p : along[e]) {
                edgesOfPatch[static_cast<size_t>(p)].push_back(static_cast<int>(e));
            }
        }
    }
    std::vector<int> size(static_cast<size_t>(patches), 0);
    for (int p : patchOfPoint) {
        ++size[static_cast<size_t>(p)];
    }
    std::vector<PatchBorder> borders;
    for (int p = 0; p < patches; ++p) {
        if (size[static_cast<size_t>(p)] < std::max(1, options.minPoints)) {
            continue;
        }
        PatchBorder b;
        b.patch = p;
        walkLoops(network, edgesOfPatch[static_cast<size_t>(p)], b);
        borders.push_back(std::move(b));
    }
    return borders;
}

} // namespace featurelines
