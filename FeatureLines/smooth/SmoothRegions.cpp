// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/SmoothRegions.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "FeatureLines/support/DisjointSets.h"

namespace featurelines {

namespace {

/// Samples of the sharp lines in a uniform hash grid, to tell which points lie in the band.
class LineBand
{
public:
    LineBand(const std::vector<Polyline>& lines, double width) : width_(width)
    {
        const double step = 0.5 * width;
        for (const Polyline& line : lines) {
            const Eigen::Index n = line.points.rows();
            const Eigen::Index segments = line.closed ? n : n - 1;
            if (n == 1) {
                insert(line.points.row(0));
            }
            for (Eigen::Index s = 0; s < segments; ++s) {
                const Eigen::RowVector3d a = line.points.row(s);
                const Eigen::RowVector3d b = line.points.row((s + 1) % n);
                const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step)));
                for (int j = 0; j <= pieces; ++j) {
                    insert(a + (b - a) * (static_cast<double>(j) / pieces));
                }
            }
        }
        // The cells next to a sample cell: a point in none of them is farther than the width
        // from every sample, which one look-up tells (most points of a cloud are).
        for (const auto& [c, samples] : cells_) {
            for (int dx = -1; dx <= 1; ++dx) {
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dz = -1; dz <= 1; ++dz) {
                        near_.insert(Key{c.x + dx, c.y + dy, c.z + dz});
                    }
                }
            }
        }
    }

    bool contains(const Eigen::RowVector3d& p) const
    {
        const Key c = cell(p);
        if (near_.find(c) == near_.end()) {
            return false;
        }
        for (int dx = -1; dx <= 1; ++dx) {
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dz = -1; dz <= 1; ++dz) {
                    auto it = cells_.find(Key{c.x + dx, c.y + dy, c.z + dz});
                    if (it == cells_.end()) {
                        continue;
                    }
                    for (const Eigen::RowVector3d& s : it->second) {
                        if ((s - p).squaredNorm() < width_ * width_) {
                            return true;
                        }
                    }
                }
            }
        }
        return false;
    }

    bool empty() const { return cells_.empty(); }

private:
    struct Key
    {
        long long x, y, z;
        bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
    };
    struct KeyHash
    {
        size_t operator()(const Key& k) const
        {
            return static_cast<size_t>(k.x * 73856093LL ^ k.y * 19349663LL ^ k.z * 83492791LL);
        }
    };

    Key cell(const Eigen::RowVector3d& p) const
    {
        return Key{static_cast<long long>(std::floor(p.x() / width_)),
                   static_cast<long long>(std::floor(p.y() / width_)),
                   static_cast<long long>(std::floor(p.z() / width_))};
    }
    void insert(const Eigen::RowVector3d& p) { cells_[cell(p)].push_back(p); }

    double width_;
    std::unordered_map<Key, std::vector<Eigen::RowVector3d>, KeyHash> cells_;
    std::unordered_set<Key, KeyHash> near_;
};

} // namespace

SmoothRegions divideSmoothRegions(const PointMatrix& P, const Neighbourhoods& N,
                                  const std::vector<Polyline>& sharpLines,
                                  const std::vector<char>& sharpCandidate, double spacing,
                                  const SmoothRegionOptions& options)
{
    const Eigen::Index n = P.rows();
    if (N.size() != n) {
        throw std::invalid_argument(
            "divideSmoothRegions: points and neighbourhoods differ in size");
    }
    if (!sharpCandidate.empty() && static_cast<Eigen::Index>(sharpCandidate.size()) != n) {
        throw std::invalid_argument(
            "divideSmoothRegions: points and candidate flags differ in size");
    }
    if (!(spacing > 0.0) || !std::isfinite(spacing)) {
        throw std::invalid_argument("divideSmoothRegions: the point spacing must be positive");
    }
    if (!(options.bandWidth >= 0.0) || options.minRegionNeighbours < 5 ||
        options.minRegionNeighbours > N.k() || options.minRegionPoints < 0) {
        throw std::invalid_argument(
            "divideSmoothRegions: band width must be >= 0, region neighbours in [5, k], "
            "region points >= 0");
    }

    // 1. Eligible points: off the band and not sharp candidates.
    std::vector<int> label(static_cast<size_t>(n), -1);
    const LineBand band(sharpLines, options.bandWidth * spacing);
    std::vector<char> eligible(static_cast<size_t>(n), 1);
#pragma omp parallel for schedule(static)
    for (Eigen::Index i = 0; i < n; ++i) {
        const bool candidate = !sharpCandidate.empty() && sharpCandidate[i];
        eligible[i] = !candidate && (band.empty() || !band.contains(P.row(i)));
    }

    // 2. Connected components of the kNN graph over the eligible points, its edges taken both
    // ways (q among p's neighbours joins p and q, whichever of them is visited first). Where
    // the sampling is sparse a neighbour can lie farther than the band is wide; such a long
    // edge must not jump the band across a crease: it joins only when its middle lies off the
    // band too.
    const double longEdge2 = std::pow(options.bandWidth * spacing, 2);
    std::vector<int> component(static_cast<size_t>(n), -1);
    std::vector<int> sizes;
    const auto connect = [&]() {
        DisjointSets sets(static_cast<int>(n));
#pragma omp parallel for schedule(static, 4096)
        for (Eigen::Index p = 0; p < n; ++p) {
            if (!eligible[p]) {
                continue;
            }
            int root = static_cast<int>(p);
            for (int j = 0; j < N.k(); ++j) {
                const int q = N.indices(p, j);
                // The band is looked up only for an edge that would join two sets.
                if (eligible[q] && sets.find(q) != sets.find(root) &&
                    !(N.squaredDistances(p, j) > longEdge2 &&
                      band.contains(0.5 * (P.row(p) + P.row(q))))) {
                    root = sets.join(root, q);
                }
            }
        }
        // Components numbered in the order of their first points.
        const std::vector<int> root = sets.representatives();
        sizes.clear();
        for (Eigen::Index p = 0; p < n; ++p) {
            if (!eligible[p]) {
                component[p] = -1;
                continue;
            }
            if (root[p] == p) {
                component[p] = static_cast<int>(sizes.size());
                sizes.push_back(0);
            } else {
                component[p] = component[root[p]];
            }
            ++sizes[component[p]];
        }
    };
    connect();

    // 3. Points that see too few of their own region leave it. They may have been the only
    // link between two parts (a thin bridge of points where the band around a crease is
    // narrow): the components are then found again without them, so that every region is
    // connected.
    std::vector<char> tooFewInside(static_cast<size_t>(n), 0);
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < n; ++i) {
        if (component[i] < 0) {
            continue;
        }
        int inside = 0;
        for (int j = 0; j < N.k(); ++j) {
            inside += component[N.indices(i, j)] == component[i] ? 1 : 0;
        }
        tooFewInside[i] = inside < options.minRegionNeighbours;
    }
    const bool removed =
        std::find(tooFewInside.begin(), tooFewInside.end(), 1) != tooFewInside.end();
    for (Eigen::Index i = 0; i < n; ++i) {
        eligible[i] = eligible[i] && !tooFewInside[i];
    }
    if (removed) {
        connect();
    }
    // A point that saw enough of its region may see none of it once those neighbours have
    // gone (a scrap a few points wide between close sharp lines): it has no neighbourhood in
    // its region and joins the band too, until no such point is left.
    for (bool changed = true; changed;) {
        changed = false;
#pragma omp parallel for schedule(static, 4096)
        for (Eigen::Index i = 0; i < n; ++i) {
            bool seesRegion = component[i] < 0;
            for (int j = 0; j < N.k() && !seesRegion; ++j) {
                seesRegion = component[N.indices(i, j)] == component[i];
            }
            tooFewInside[i] = !seesRegion;
        }
        for (Eigen::Index i = 0; i < n; ++i) {
            if (tooFewInside[i]) {
                --sizes[component[i]];
                component[i] = -1;
                changed = true;
            }
        }
    }
    // Then regions too small to be regions.
    const int minPoints = options.minRegionPoints > 0 ? options.minRegionPoints : 2 * N.k();
    std::vector<int> order(sizes.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return sizes[a] > sizes[b]; });
    std::vector<int> renumber(sizes.size(), -1);
    SmoothRegions result;
    for (int c : order) {
        if (sizes[c] >= minPoints) {
            renumber[c] = result.count();
            result.members.emplace_back();
            result.members.back().reserve(static_cast<size_t>(sizes[c]));
        }
    }
    result.region.assign(static_cast<size_t>(n), -1);
    for (Eigen::Index i = 0; i < n; ++i) {
        if (component[i] >= 0 && renumber[component[i]] >= 0) {
            result.region[i] = renumber[component[i]];
            result.members[result.region[i]].push_back(static_cast<int>(i));
        }
    }
    return result;
}

std::vector<char> pointsNearLines(const PointMatrix& P, const std::vector<int>& points,
                                  const std::vector<Polyline>& lines, double distance)
{
    std::vector<char> near(points.size(), 0);
    if (lines.empty() || !(distance > 0.0)) {
        return near;
    }
    const LineBand band(lines, distance);
#pragma omp parallel for schedule(static)
    for (long i = 0; i < static_cast<long>(points.size()); ++i) {
        near[static_cast<size_t>(i)] = band.contains(P.row(points[static_cast<size_t>(i)]));
    }
    return near;
}

bool holdsEveryPoint(const std::vector<int>& region, const std::vector<int>& members,
                     int regionId)
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
    // Row of each member in the sub-cloud: a table over the members' index range when the
    // region fills a good part of it (a few large regions, the usual case), else a hash map
    // (a small region spread over a large cloud).
    const auto [lowest, highest] = std::minmax_element(members.begin(), members.end());
    const int first = members.empty() ? 0 : *lowest;
    const size_t range = members.empty() ? 0 : static_cast<size_t>(*highest - first) + 1;
    const bool dense = range <= 8 * members.size() + 1024;
    std::vector<int> localTable(dense ? range : 0, -1);
    std::unordered_map<int, int> localMap;
    if (!dense) {
        localMap.reserve(members.size() * 2);
    }
    for (size_t m = 0; m < members.size(); ++m) {
        if (dense) {
            localTable[static_cast<size_t>(members[m] - first)] = static_cast<int>(m);
        } else {
            localMap.emplace(members[m], static_cast<int>(m));
        }
    }
    const auto local = [&](int q) {
        if (dense) {
            const size_t at = static_cast<size_t>(q - first);
            return q >= first && at < range ? localTable[at] : -1;
        }
        const auto it = localMap.find(q);
        return it == localMap.end() ? -1 : it->second;
    };

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
