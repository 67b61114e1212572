// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/SmoothRegions.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "FeatureLines/smooth/LineBand.h"
#include "FeatureLines/support/DisjointSets.h"

namespace featurelines {

namespace {

void checkInput(const SmoothRegionInput& in, const SmoothRegionOptions& options)
{
    const Eigen::Index n = in.points.rows();
    if (in.neighbours.size() != n) {
        throw std::invalid_argument(
            "divideSmoothRegions: points and neighbourhoods differ in size");
    }
    if (!in.sharpCandidate.empty() && static_cast<Eigen::Index>(in.sharpCandidate.size()) != n) {
        throw std::invalid_argument(
            "divideSmoothRegions: points and candidate flags differ in size");
    }
    if (!(in.spacing > 0.0) || !std::isfinite(in.spacing)) {
        throw std::invalid_argument("divideSmoothRegions: the point spacing must be positive");
    }
    if (!(options.bandWidth >= 0.0) || options.minRegionNeighbours < 5 ||
        options.minRegionNeighbours > in.neighbours.k() || options.minRegionPoints < 0) {
        throw std::invalid_argument(
            "divideSmoothRegions: band width must be >= 0, region neighbours in [5, k], "
            "region points >= 0");
    }
}

/// The least size of a region: minRegionPoints, or twice the neighbourhood size k for 0.
int minRegionPoints(const SmoothRegionOptions& options, int k)
{
    return options.minRegionPoints > 0 ? options.minRegionPoints : 2 * k;
}

/// Per point: off the band and not a sharp candidate.
std::vector<char> eligiblePoints(const SmoothRegionInput& in, const LineBand& band)
{
    const Eigen::Index n = in.points.rows();
    std::vector<char> eligible(static_cast<size_t>(n), 1);
#pragma omp parallel for schedule(static)
    for (Eigen::Index i = 0; i < n; ++i) {
        const bool candidate = !in.sharpCandidate.empty() && in.sharpCandidate[i];
        eligible[i] = !candidate && (band.empty() || !band.contains(in.points.row(i)));
    }
    return eligible;
}

/// Connected components over the eligible points.
struct Components
{
    /// #P component of each point, -1 where it has none.
    std::vector<int> component;
    /// Points per component.
    std::vector<int> sizes;
};

/// The connected components of the kNN graph over the eligible points, its edges taken both
/// ways (q among p's neighbours joins p and q, whichever of them is visited first), numbered in
/// the order of their first points. Where the sampling is sparse a neighbour can lie farther
/// than the band is wide; such a long edge must not jump the band across a crease: it joins
/// only when its middle lies off the band too.
Components connect(const SmoothRegionInput& in, const std::vector<char>& eligible,
                   const LineBand& band, double bandWidth)
{
    const PointMatrix& P = in.points;
    const Neighbourhoods& N = in.neighbours;
    const Eigen::Index n = P.rows();
    const double longEdge2 = std::pow(bandWidth, 2);
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
    const std::vector<int> root = sets.representatives();
    Components c;
    c.component.assign(static_cast<size_t>(n), -1);
    for (Eigen::Index p = 0; p < n; ++p) {
        if (!eligible[p]) {
            c.component[p] = -1;
            continue;
        }
        if (root[p] == p) {
            c.component[p] = static_cast<int>(c.sizes.size());
            c.sizes.push_back(0);
        } else {
            c.component[p] = c.component[root[p]];
        }
        ++c.sizes[c.component[p]];
    }
    return c;
}

/// Points that see fewer than minRegionNeighbours of their own component leave it (their
/// eligibility too). They may have been the only link between two parts (a thin bridge of
/// points where the band around a crease is narrow): the components are then found again
/// without them, so that every region is connected.
void dropThinPoints(const SmoothRegionInput& in, const SmoothRegionOptions& options,
                    const LineBand& band, std::vector<char>& eligible, Components& c)
{
    const Neighbourhoods& N = in.neighbours;
    const Eigen::Index n = in.points.rows();
    std::vector<char> tooFewInside(static_cast<size_t>(n), 0);
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < n; ++i) {
        if (c.component[i] < 0) {
            continue;
        }
        int inside = 0;
        for (int j = 0; j < N.k(); ++j) {
            inside += c.component[N.indices(i, j)] == c.component[i] ? 1 : 0;
        }
        tooFewInside[i] = inside < options.minRegionNeighbours;
    }
    const bool removed =
        std::find(tooFewInside.begin(), tooFewInside.end(), 1) != tooFewInside.end();
    for (Eigen::Index i = 0; i < n; ++i) {
        eligible[i] = eligible[i] && !tooFewInside[i];
    }
    if (removed) {
        c = connect(in, eligible, band, options.bandWidth * in.spacing);
    }
}

/// A point that saw enough of its region may see none of it once those neighbours have gone (a
/// scrap a few points wide between close sharp lines): it has no neighbourhood in its region
/// and leaves it too, until no such point is left.
void dropPointsSeeingNoRegion(const Neighbourhoods& N, Components& c)
{
    const Eigen::Index n = N.size();
    std::vector<char> seesNone(static_cast<size_t>(n), 0);
    for (bool changed = true; changed;) {
        changed = false;
#pragma omp parallel for schedule(static, 4096)
        for (Eigen::Index i = 0; i < n; ++i) {
            bool seesRegion = c.component[i] < 0;
            for (int j = 0; j < N.k() && !seesRegion; ++j) {
                seesRegion = c.component[N.indices(i, j)] == c.component[i];
            }
            seesNone[i] = !seesRegion;
        }
        for (Eigen::Index i = 0; i < n; ++i) {
            if (seesNone[i]) {
                --c.sizes[c.component[i]];
                c.component[i] = -1;
                changed = true;
            }
        }
    }
}

/// The components of at least minPoints points as regions, numbered by decreasing size.
SmoothRegions numberRegions(const Components& c, int minPoints)
{
    const std::vector<int>& sizes = c.sizes;
    std::vector<int> order(sizes.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return sizes[a] > sizes[b]; });
    std::vector<int> renumber(sizes.size(), -1);
    SmoothRegions result;
    for (int k : order) {
        if (sizes[k] >= minPoints) {
            renumber[k] = result.count();
            result.members.emplace_back();
            result.members.back().reserve(static_cast<size_t>(sizes[k]));
        }
    }
    const size_t n = c.component.size();
    result.region.assign(n, -1);
    for (size_t i = 0; i < n; ++i) {
        if (c.component[i] >= 0 && renumber[c.component[i]] >= 0) {
            result.region[i] = renumber[c.component[i]];
            result.members[result.region[i]].push_back(static_cast<int>(i));
        }
    }
    return result;
}

} // namespace

SmoothRegions divideSmoothRegions(const SmoothRegionInput& in, const SmoothRegionOptions& options)
{
    checkInput(in, options);
    const LineBand band(in.sharpLines, options.bandWidth * in.spacing);
    std::vector<char> eligible = eligiblePoints(in, band);
    Components c = connect(in, eligible, band, options.bandWidth * in.spacing);
    dropThinPoints(in, options, band, eligible, c);
    dropPointsSeeingNoRegion(in.neighbours, c);
    return numberRegions(c, minRegionPoints(options, in.neighbours.k()));
}

} // namespace featurelines
