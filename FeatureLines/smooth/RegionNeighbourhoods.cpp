// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/RegionNeighbourhoods.h"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace featurelines {

namespace {

/// Row of each member in the sub-cloud: a table over the members' index range when the region
/// fills a good part of it (a few large regions, the usual case), else a hash map (a small
/// region spread over a large cloud).
class MemberRows
{
public:
    explicit MemberRows(const std::vector<int>& members)
    {
        const auto [lowest, highest] = std::minmax_element(members.begin(), members.end());
        first_ = members.empty() ? 0 : *lowest;
        range_ = members.empty() ? 0 : static_cast<size_t>(*highest - first_) + 1;
        dense_ = range_ <= 8 * members.size() + 1024;
        table_.assign(dense_ ? range_ : 0, -1);
        if (!dense_) {
            map_.reserve(members.size() * 2);
        }
        for (size_t m = 0; m < members.size(); ++m) {
            if (dense_) {
                table_[static_cast<size_t>(members[m] - first_)] = static_cast<int>(m);
            } else {
                map_.emplace(members[m], static_cast<int>(m));
            }
        }
    }

    /// The row of point q, -1 when it is no member.
    int operator()(int q) const
    {
        if (dense_) {
            const size_t at = static_cast<size_t>(q - first_);
            return q >= first_ && at < range_ ? table_[at] : -1;
        }
        const auto it = map_.find(q);
        return it == map_.end() ? -1 : it->second;
    }

private:
    int first_ = 0;
    size_t range_ = 0;
    bool dense_ = true;
    std::vector<int> table_;
    std::unordered_map<int, int> map_;
};

} // namespace

bool holdsEveryPoint(const std::vector<int>& region, const std::vector<int>& members, int regionId)
{
    bool every = members.size() == region.size();
    for (size_t m = 0; m < members.size() && every; ++m) {
        every = members[m] == static_cast<int>(m) && region[m] == regionId;
    }
    return every;
}

Neighbourhoods regionNeighbourhoods(const Neighbourhoods& N, const std::vector<int>& region,
                                    const std::vector<int>& members, int regionId)
{
    if (static_cast<Eigen::Index>(region.size()) != N.size()) {
        throw std::invalid_argument(
            "regionNeighbourhoods: region labels and neighbourhoods differ in size");
    }
    // A region of every point (a cloud without sharp edges) keeps every neighbourhood whole: a
    // copy of N, at the speed of a copy.
    if (holdsEveryPoint(region, members, regionId)) {
        return N;
    }
    const MemberRows local(members);
    const int k = N.k();
    Neighbourhoods sub;
    sub.allocate(static_cast<Eigen::Index>(members.size()), k);
    bool isolated = false; // a member with no neighbour in the region
    bool unlisted = false; // a neighbour labelled regionId but not among the members
#pragma omp parallel for schedule(static, 4096) reduction(|| : isolated, unlisted)
    for (long m = 0; m < static_cast<long>(members.size()); ++m) {
        const int p = members[static_cast<size_t>(m)];
        int filled = 0;
        for (int j = 0; j < k; ++j) {
            const int q = N.indices(p, j);
            if (region[q] == regionId) {
                const int row = local(q);
                unlisted = unlisted || row < 0;
                sub.indices(m, filled) = row;
                sub.squaredDistances(m, filled) = N.squaredDistances(p, j);
                ++filled;
            }
        }
        if (filled == 0) {
            isolated = true;
            continue;
        }
        // Sec. 2.1 fits over k neighbours; repeating the nearest in-region ones keeps the
        // row shape and only re-weights a point whose neighbourhood the band cut.
        for (int j = filled, r = 0; j < k; ++j, r = (r + 1) % filled) {
            sub.indices(m, j) = sub.indices(m, r);
            sub.squaredDistances(m, j) = sub.squaredDistances(m, r);
        }
    }
    if (isolated) {
        throw std::invalid_argument(
            "regionNeighbourhoods: a region point has no neighbour in its region");
    }
    if (unlisted) {
        throw std::invalid_argument("regionNeighbourhoods: a point labelled with the region is "
                                    "missing from its member list");
    }
    return sub;
}

} // namespace featurelines
