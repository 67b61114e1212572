// SPDX-License-Identifier: LGPL-2.1-or-later
// The steps that cut the node graph: short branches, bubbles, close junctions, short pieces,
// free ends left.
#include "FeatureLines/network/GraphPruning.h"

#include <algorithm>
#include <map>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "FeatureLines/support/DisjointSets.h"

namespace featurelines::clustergraph {

/// G_pruned_branches: cuts branches from a junction to a free end shorter than minLength,
/// repeatedly, but never more than leaves the junction two branches: at the end of a line
/// that forks into two short tips the longer tip stays, so the line keeps its length.
int pruneShortBranches(Graph& g, double minLength)
{
    int pruned = 0;
    for (bool changed = true; changed;) {
        changed = false;
        // (junction, length, chain without the junction)
        std::vector<std::tuple<int, double, std::vector<int>>> branches;
        for (int v = 0; v < g.size(); ++v) {
            if (g.degree(v) != 1) {
                continue;
            }
            auto [chain, length] = g.chainFrom(v, g.neighbours(v)[0]);
            const int end = chain.back();
            if (g.degree(end) >= 3) {
                chain.pop_back();
                branches.emplace_back(end, length, std::move(chain));
            }
        }
        std::sort(branches.begin(), branches.end(), [](const auto& a, const auto& b) {
            return std::tie(std::get<0>(a), std::get<1>(a), std::get<2>(a)) <
                   std::tie(std::get<0>(b), std::get<1>(b), std::get<2>(b));
        });
        for (const auto& [junction, length, chain] : branches) {
            // The degree is read now, so cuts made at this junction in this round count.
            if (length >= minLength || g.degree(junction) <= 2) {
                continue;
            }
            // A branch met from both of its ends (two junctions joined through free ends)
            // cannot occur: a chain that starts at a free end ends at the first node of
            // another degree.
            for (int v : chain) {
                g.isolate(v);
            }
            ++pruned;
            changed = true;
        }
    }
    return pruned;
}

/// Bubbles: where a band is two nodes wide, the tree may run two parallel chains that the
/// reconnection then joins at both ends. Of two chains joining the same two junctions (or a
/// chain leaving a junction and returning to it) the longer is dropped when it is shorter
/// than maxLength; a real face is bounded by more junctions or by longer lines.
int removeBubbles(Graph& g, double maxLength)
{
    int removed = 0;
    for (bool changed = true; changed;) {
        changed = false;
        std::map<std::pair<int, int>, std::vector<std::pair<double, std::vector<int>>>> chains;
        for (int j = 0; j < g.size() && !changed; ++j) {
            if (g.degree(j) < 3) {
                continue;
            }
            for (int first : g.neighbours(j)) {
                auto [chain, length] = g.chainFrom(j, first);
                const int end = chain.back();
                if (g.degree(end) < 3 || length >= maxLength) {
                    continue;
                }
                if (end == j) {
                    // A short loop hanging at one junction.
                    for (std::size_t i = 1; i + 1 < chain.size(); ++i) {
                        g.isolate(chain[i]);
                    }
                    if (chain.size() == 2) {
                        g.removeEdge(j, first);
                    }
                    ++removed;
                    changed = true;
                    break;
                }
                if (j < end) {
                    chains[{j, end}].emplace_back(length, std::move(chain));
                }
            }
        }
        if (changed) {
            continue;
        }
        for (auto& [ends, list] : chains) {
            if (list.size() < 2) {
                continue;
            }
            std::sort(list.begin(), list.end());
            const std::vector<int>& drop = list[1].second;
            if (drop.size() == 2) {
                g.removeEdge(drop[0], drop[1]);
            }
            for (std::size_t i = 1; i + 1 < drop.size(); ++i) {
                g.isolate(drop[i]);
            }
            ++removed;
            changed = true;
            break;
        }
    }
    return removed;
}

/// Junctions joined by a short chain (and short loops hanging at one junction) become one
/// junction at the mean of the merged nodes.
int mergeCloseJunctions(Graph& g, double maxLength)
{
    DisjointSets sets(g.size());
    int merged = 0;
    for (int j = 0; j < g.size(); ++j) {
        if (g.degree(j) < 3) {
            continue;
        }
        for (int first : g.neighbours(j)) {
            auto [chain, length] = g.chainFrom(j, first);
            if (length < maxLength && g.degree(chain.back()) >= 3) {
                for (int v : chain) {
                    merged += sets.unite(j, v) ? 1 : 0;
                }
            }
        }
    }
    if (merged == 0) {
        return 0;
    }
    std::unordered_map<int, std::vector<int>> groups;
    for (int v = 0; v < g.size(); ++v) {
        if (g.degree(v) > 0 && sets.find(v) != v) {
            groups[sets.find(v)].push_back(v);
        }
    }
    std::vector<std::pair<int, int>> edges;
    for (auto& [root, members] : groups) {
        Eigen::Vector3d sum = g.centre(root);
        for (int v : members) {
            sum += g.centre(v);
            for (int u : g.neighbours(v)) {
                edges.emplace_back(v, u);
            }
            g.isolate(v);
        }
        g.centres()[root] = sum / static_cast<double>(members.size() + 1);
    }
    for (const auto& [a, b] : edges) {
        g.addEdge(sets.find(a), sets.find(b)); // self loops are ignored
    }
    return merged;
}

/// Drops connected pieces whose total length is below minLength, and those without a cycle
/// (open lines and trees) whose length is below minOpenLength.
int dropShortComponents(Graph& g, double minLength, double minOpenLength)
{
    std::vector<char> seen(g.size(), 0);
    int dropped = 0;
    for (int s = 0; s < g.size(); ++s) {
        if (seen[s] || g.degree(s) == 0) {
            continue;
        }
        std::vector<int> component{s};
        seen[s] = 1;
        double length = 0.0;
        std::size_t edgeEnds = 0;
        for (std::size_t i = 0; i < component.size(); ++i) {
            const int v = component[i];
            edgeEnds += g.neighbours(v).size();
            for (int u : g.neighbours(v)) {
                length += 0.5 * g.length(v, u);
                if (!seen[u]) {
                    seen[u] = 1;
                    component.push_back(u);
                }
            }
        }
        const bool hasCycle = edgeEnds / 2 >= component.size();
        if (length < minLength || (!hasCycle && length < minOpenLength)) {
            for (int v : component) {
                g.isolate(v);
            }
            ++dropped;
        }
    }
    return dropped;
}

/// The free ends no join reached are removed with their branch, up to the first junction
/// (an open piece ending in nothing on both sides goes whole), when the branch or piece is no
/// longer than maxLength: what cannot close is not a boundary of a patch. Repeated, because
/// cutting a fork can leave the line it ended as a new free end.
int removeFreeEnds(Graph& g, double maxLength)
{
    int removed = 0;
    for (bool changed = true; changed;) {
        changed = false;
        std::vector<std::pair<std::vector<int>, double>> branches;
        for (int v = 0; v < g.size(); ++v) {
            if (g.degree(v) == 1) {
                branches.push_back(g.chainFrom(v, g.neighbours(v)[0]));
            }
        }
        for (const auto& [chain, length] : branches) {
            const int end = chain.back();
            if (g.degree(chain.front()) != 1 || length > maxLength) {
                continue; // removed with an open piece from its other end, or long
            }
            if (g.degree(end) == 2) {
                continue; // a junction an earlier cut of this round left with two lines
            }
            for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
                g.isolate(chain[i]);
            }
            if (g.degree(end) == 1) {
                g.isolate(end); // the other end of an open piece
            }
            ++removed;
            changed = true;
        }
    }
    return removed;
}

} // namespace featurelines::clustergraph
