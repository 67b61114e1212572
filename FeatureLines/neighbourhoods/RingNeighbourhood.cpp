// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/neighbourhoods/RingNeighbourhood.h"
#include "FeatureLines/support/IdleThreads.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <omp.h>

namespace featurelines {

namespace {

/// The neighbours of one point projected onto its tangent plane and mapped to w = 2 q / |q|^2,
/// in arrays (the sort and the hull move small indices, not the coordinates). Candidate 0 is
/// the origin (the point itself), index -1.
struct Candidates
{
    std::vector<double> x, y;
    std::vector<int> index;
    int count = 0;

    explicit Candidates(int capacity) : x(capacity), y(capacity), index(capacity) {}
    void clear() { count = 0; }
    void add(double cx, double cy, int i)
    {
        x[count] = cx;
        y[count] = cy;
        index[count] = i;
        ++count;
    }
};

/// Projections closer to the point than this fraction of the neighbourhood's squared radius
/// count as coincident with it (a duplicate, or a neighbour straight above it): their
/// half-plane is undefined.
constexpr double coincidentFraction = 1e-12;

/// A hull turn whose cross product is below this fraction of the product of its edge lengths
/// is straight: the middle point is on an edge of the hull, not a vertex. This is a rounding
/// level; it makes the four co-circular diagonals of an exact square lattice non-neighbours.
constexpr double straightTurn = 1e-9;

/// The hull is first built from the origin and the images of the nearest neighbours only,
/// this many. The others come by decreasing |w| (the neighbours are sorted nearest first) and
/// most lie well inside it: inside the largest disc about the origin that the hull holds (its
/// distance to the nearest hull edge; one test), or else inside the hull itself (a test per
/// edge), so they cannot change it and are dropped; the hull is built again when any is left.
/// On scan-like clouds the Delaunay neighbours are nearly always among the nearest 8; on a
/// smoothed noisy region half the points have a candidate outside the disc, most of them
/// inside the hull.
constexpr int firstCandidates = 8;

/// A candidate is dropped only when it lies inside that disc by this relative margin of its
/// squared radius, or inside every hull edge by this margin of the sine of its angle, far
/// above the rounding of the straightness test: a dropped candidate lies strictly inside the
/// hull, so the hull, vertex for vertex, is that of all the candidates.
constexpr double insideMargin = 1e-6;

/// A cheap monotone stand-in for atan2(y, x): increases with the angle over (-pi, pi], in
/// [-2, 2].
double pseudoAngle(double x, double y)
{
    const double p = y / (std::abs(x) + std::abs(y)); // -1 to 1 over the half-plane x >= 0
    return x >= 0.0 ? p : (y >= 0.0 ? 2.0 - p : -2.0 - p);
}

/// True when o -> a -> b turns strictly left (candidates o, a, b of the coordinates x, y).
inline bool turnsLeft(const double* x, const double* y, int o, int a, int b)
{
    const double ax = x[a] - x[o], ay = y[a] - y[o];
    const double bx = x[b] - x[o], by = y[b] - y[o];
    const double cross = ax * by - ay * bx;
    // A right turn or none needs no square root (the bound is not negative).
    return cross > 0.0 &&
           cross > straightTurn * std::sqrt((ax * ax + ay * ay) * (bx * bx + by * by));
}

/// Strict vertices of the convex hull of the candidates (Andrew's monotone chain), as
/// candidate numbers in `hull`, counter-clockwise. `order` is scratch space.
void convexHull(const Candidates& c, std::vector<int>& order, std::vector<int>& hull)
{
    const int n = c.count;
    const double* x = c.x.data();
    const double* y = c.y.data();
    // Sorted by x, then y; an insertion sort, fastest on so few, keeps exact ties in candidate
    // order.
    order.resize(static_cast<size_t>(n));
    for (int a = 0; a < n; ++a) {
        int b = a;
        while (b > 0) {
            const int prev = order[b - 1];
            if (!(x[a] < x[prev] || (x[a] == x[prev] && y[a] < y[prev]))) {
                break;
            }
            order[b] = prev;
            --b;
        }
        order[b] = a;
    }
    if (n < 3) {
        hull = order;
        return;
    }
    hull.resize(2 * static_cast<size_t>(n));
    int size = 0;
    for (int i = 0; i < n; ++i) { // lower chain
        while (size >= 2 && !turnsLeft(x, y, hull[size - 2], hull[size - 1], order[i])) {
            --size;
        }
        hull[size++] = order[i];
    }
    const int lower = size + 1;
    for (int i = n - 1; i-- > 0;) { // upper chain
        while (size >= lower && !turnsLeft(x, y, hull[size - 2], hull[size - 1], order[i])) {
            --size;
        }
        hull[size++] = order[i];
    }
    hull.resize(static_cast<size_t>(size - 1)); // the last point repeats the first
}

/// True when the point (x, y) lies inside the counter-clockwise hull, left of each of its
/// edges by more than the relative margin insideMargin: it cannot be a vertex of the hull of
/// these candidates and more.
bool strictlyInside(const Candidates& c, const std::vector<int>& hull, double x, double y)
{
    const std::size_t size = hull.size();
    if (size < 3) {
        return false;
    }
    for (std::size_t h = 0; h < size; ++h) {
        const int a = hull[h], b = hull[(h + 1) % size];
        const double ex = c.x[b] - c.x[a], ey = c.y[b] - c.y[a];
        const double px = x - c.x[a], py = y - c.y[a];
        const double cross = ex * py - ey * px;
        if (!(cross > 0.0) || cross * cross <= insideMargin * insideMargin * (ex * ex + ey * ey) *
                                                   (px * px + py * py)) {
            return false;
        }
    }
    return true;
}

/// The squared radius of the largest disc about the origin (candidate 0) inside the hull, or
/// 0 when the origin is not strictly inside it (a border point, or a degenerate hull).
double insideRadiusSquared(const Candidates& c, const std::vector<int>& hull)
{
    const std::size_t size = hull.size();
    if (size < 3) {
        return 0.0;
    }
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t h = 0; h < size; ++h) {
        const int a = hull[h], b = hull[(h + 1) % size];
        // The origin lies left of every edge of the counter-clockwise hull when it is inside.
        const double cross = c.x[a] * c.y[b] - c.y[a] * c.x[b];
        if (!(cross > 0.0)) {
            return 0.0;
        }
        const double ex = c.x[b] - c.x[a], ey = c.y[b] - c.y[a];
        smallest = std::min(smallest, cross * cross / (ex * ex + ey * ey));
    }
    return smallest;
}

/// The cloud the rings are built on.
struct RingInput
{
    const PointMatrix& P;
    const NormalMatrix& normals;
    const Neighbourhoods& N;
};

/// What one thread reuses from point to point.
struct RingWorker
{
    Candidates candidates, images;
    std::vector<int> order, hull;

    explicit RingWorker(int k) : candidates(k + 1), images(k) {}
};

/// The k nearest neighbours of point i projected onto the tangent plane (u, v) and mapped to
/// w = 2 q / |q|^2, those coincident with the point left out.
void tangentImages(const RingInput& in, Eigen::Index i, const Eigen::Vector3d& u,
                   const Eigen::Vector3d& v, Candidates& images)
{
    const int k = in.N.k();
    const double tooClose = coincidentFraction * in.N.squaredDistances(i, k - 1);
    images.clear();
    for (int j = 0; j < k; ++j) {
        const int q = in.N.indices(i, j);
        const Eigen::Vector3d d = (in.P.row(q) - in.P.row(i)).transpose();
        const double x = d.dot(u);
        const double y = d.dot(v);
        const double s = x * x + y * y;
        if (!(s > tooClose)) {
            continue;
        }
        images.add(2.0 * x / s, 2.0 * y / s, q);
    }
}

/// Floater and Reimers: q is a Delaunay neighbour of p (at the origin) iff its half-plane
/// {x : x.q <= |q|^2 / 2} bounds p's Voronoi cell, i.e. iff 2 q / |q|^2 is a vertex of the
/// convex hull of these points and the origin. The hull of the origin and the images, in
/// w.hull (candidate numbers of w.candidates): first of the nearest firstCandidates, then again
/// with the farther images that may change it.
void imageHull(RingWorker& w)
{
    Candidates& candidates = w.candidates;
    const Candidates& images = w.images;
    candidates.clear();
    candidates.add(0.0, 0.0, -1);
    const int first = std::min(images.count, firstCandidates);
    for (int c = 0; c < first; ++c) {
        candidates.add(images.x[c], images.y[c], images.index[c]);
    }
    convexHull(candidates, w.order, w.hull);
    if (first < images.count) {
        const double inside = insideRadiusSquared(candidates, w.hull) * (1.0 - insideMargin);
        for (int c = first; c < images.count; ++c) {
            const double x = images.x[c], y = images.y[c];
            if (!(x * x + y * y < inside) && !strictlyInside(candidates, w.hull, x, y)) {
                candidates.add(x, y, images.index[c]);
            }
        }
        if (candidates.count > first + 1) {
            convexHull(candidates, w.order, w.hull);
        }
    }
}

/// Appends the hull's neighbours to `rings` in angular order; returns their number. The hull
/// runs counter-clockwise, so its vertices are already in angular order around the point,
/// which lies inside or on it. A border point is a vertex of its own hull: the ring then starts
/// just after it and fans across the inside. Else it starts at the direction closest to -u
/// (angle -pi), as atan2 would sort it.
int appendRing(const Candidates& candidates, const std::vector<int>& hull, std::vector<int>& rings)
{
    const std::size_t size = hull.size();
    std::size_t start = 0;
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t h = 0; h < size; ++h) {
        const int c = hull[h];
        if (candidates.index[c] < 0) {
            start = h + 1;
            break;
        }
        const double angle = pseudoAngle(candidates.x[c], candidates.y[c]);
        if (angle < smallest) {
            smallest = angle;
            start = h;
        }
    }
    int count = 0;
    for (std::size_t h = 0; h < size; ++h) {
        const int q = candidates.index[hull[(start + h) % size]];
        if (q >= 0) {
            rings.push_back(q);
            ++count;
        }
    }
    return count;
}

/// The 1-ring of point i appended to `rings`; returns its size (0 where the normal is
/// undefined).
int ringOf(const RingInput& in, Eigen::Index i, RingWorker& w, std::vector<int>& rings)
{
    const Eigen::Vector3d normal = in.normals.row(i).transpose();
    if (!(normal.norm() > 0.0) || !normal.allFinite()) {
        return 0;
    }
    const Eigen::Vector3d n = normal.normalized();
    const Eigen::Vector3d u = n.unitOrthogonal();
    const Eigen::Vector3d v = n.cross(u);
    tangentImages(in, i, u, v, w.images);
    imageHull(w);
    return appendRing(w.candidates, w.hull, rings);
}

/// Each block of points first gathers its rings on its own, then the blocks are packed into
/// the compressed rows.
constexpr Eigen::Index ringBlock = 4096;

/// The blocks' rings packed into compressed rows (the blocks' storage is released).
RingNeighbourhoods packRings(std::vector<std::vector<int>>& blockRings,
                             const std::vector<int>& counts, int threads)
{
    const Eigen::Index n = static_cast<Eigen::Index>(counts.size());
    const Eigen::Index blocks = static_cast<Eigen::Index>(blockRings.size());
    RingNeighbourhoods result;
    result.offsets.resize(n + 1);
    result.offsets[0] = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
        result.offsets[i + 1] = result.offsets[i] + counts[i];
    }
    result.indices.resize(result.offsets[n]);
#pragma omp parallel for schedule(static, 1) num_threads(threads)
    for (Eigen::Index b = 0; b < blocks; ++b) {
        std::vector<int>& rings = blockRings[static_cast<size_t>(b)];
        auto from = rings.begin();
        for (Eigen::Index i = b * ringBlock; i < std::min(n, (b + 1) * ringBlock); ++i) {
            std::copy(from, from + counts[i], result.indices.begin() + result.offsets[i]);
            from += counts[i];
        }
        std::vector<int>().swap(rings);
    }
    return result;
}

} // namespace

RingNeighbourhoods ringNeighbourhoods(const PointMatrix& P, const NormalMatrix& normals,
                                      const Neighbourhoods& N, const RingOptions& options,
                                      const ProgressSpan& progress)
{
    if (N.size() != P.rows() || normals.rows() != P.rows()) {
        throw std::invalid_argument("ring neighbourhoods: points (" + std::to_string(P.rows()) +
                                    "), normals (" + std::to_string(normals.rows()) +
                                    ") and neighbourhoods (" + std::to_string(N.size()) +
                                    ") must describe the same cloud");
    }
    const RingInput in{P, normals, N};
    const Eigen::Index n = P.rows();
    const Eigen::Index blocks = (n + ringBlock - 1) / ringBlock;
    std::vector<std::vector<int>> blockRings(static_cast<size_t>(blocks));
    std::vector<int> counts(n, 0);
    LoopProgress loop(progress, blocks);
#pragma omp parallel num_threads(threadCount(options.threads))
    {
        RingWorker worker(N.k());
#pragma omp for schedule(static, 1)
        for (Eigen::Index b = 0; b < blocks; ++b) {
            if (!loop.next(b)) {
                continue;
            }
            std::vector<int>& rings = blockRings[static_cast<size_t>(b)];
            for (Eigen::Index i = b * ringBlock; i < std::min(n, (b + 1) * ringBlock); ++i) {
                counts[i] = ringOf(in, i, worker, rings);
            }
        }
    }
    loop.finish();
    return packRings(blockRings, counts, threadCount(options.threads));
}

} // namespace featurelines
