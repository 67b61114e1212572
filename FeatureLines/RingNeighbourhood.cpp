// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/RingNeighbourhood.h"

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

/// A neighbour projected onto the tangent plane, mapped to w = 2 q / |q|^2. The origin (the
/// point itself) takes part in the hull with index -1.
struct Candidate
{
    double x;
    double y;
    int index;
};

/// Projections closer to the point than this fraction of the neighbourhood's squared radius
/// count as coincident with it (a duplicate, or a neighbour straight above it): their
/// half-plane is undefined.
constexpr double coincidentFraction = 1e-12;

/// A hull turn whose cross product is below this fraction of the product of its edge lengths
/// is straight: the middle point is on an edge of the hull, not a vertex. This is a rounding
/// level; it makes the four co-circular diagonals of an exact square lattice non-neighbours.
constexpr double straightTurn = 1e-9;

int threadCount(int requested)
{
    return requested > 0 ? requested : omp_get_max_threads();
}

/// A cheap monotone stand-in for atan2(y, x): increases with the angle over (-pi, pi], in
/// [-2, 2].
double pseudoAngle(double x, double y)
{
    const double p = y / (std::abs(x) + std::abs(y)); // -1 to 1 over the half-plane x >= 0
    return x >= 0.0 ? p : (y >= 0.0 ? 2.0 - p : -2.0 - p);
}

/// True when o -> a -> b turns strictly left.
bool turnsLeft(const Candidate& o, const Candidate& a, const Candidate& b)
{
    const double ax = a.x - o.x, ay = a.y - o.y;
    const double bx = b.x - o.x, by = b.y - o.y;
    const double cross = ax * by - ay * bx;
    return cross > straightTurn * std::sqrt((ax * ax + ay * ay) * (bx * bx + by * by));
}

/// Strict vertices of the convex hull of `points` (Andrew's monotone chain), appended to
/// `hull` counter-clockwise. `points` is reordered.
void convexHull(std::vector<Candidate>& points, std::vector<Candidate>& hull)
{
    hull.clear();
    std::sort(points.begin(), points.end(), [](const Candidate& a, const Candidate& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    const std::size_t n = points.size();
    if (n < 3) {
        hull = points;
        return;
    }
    hull.resize(2 * n);
    std::size_t size = 0;
    for (std::size_t i = 0; i < n; ++i) { // lower chain
        while (size >= 2 && !turnsLeft(hull[size - 2], hull[size - 1], points[i])) {
            --size;
        }
        hull[size++] = points[i];
    }
    const std::size_t lower = size + 1;
    for (std::size_t i = n - 1; i-- > 0;) { // upper chain
        while (size >= lower && !turnsLeft(hull[size - 2], hull[size - 1], points[i])) {
            --size;
        }
        hull[size++] = points[i];
    }
    hull.resize(size - 1); // the last point repeats the first
}

} // namespace

RingNeighbourhoods ringNeighbourhoods(const PointMatrix& P, const NormalMatrix& normals,
                                      const Neighbourhoods& N, const RingOptions& options)
{
    if (N.size() != P.rows() || normals.rows() != P.rows()) {
        throw std::invalid_argument("ring neighbourhoods: points (" + std::to_string(P.rows()) +
                                    "), normals (" + std::to_string(normals.rows()) +
                                    ") and neighbourhoods (" + std::to_string(N.size()) +
                                    ") must describe the same cloud");
    }
    const Eigen::Index n = P.rows();
    const int k = N.k();
    // Rings first go to fixed rows of k slots, then are packed into the compressed rows.
    IndexMatrix slots(n, k);
    std::vector<int> counts(n, 0);

#pragma omp parallel num_threads(threadCount(options.threads))
    {
        std::vector<Candidate> candidates;
        std::vector<Candidate> hull;
#pragma omp for schedule(static, 4096)
        for (Eigen::Index i = 0; i < n; ++i) {
            const Eigen::Vector3d normal = normals.row(i).transpose();
            if (!(normal.norm() > 0.0) || !normal.allFinite()) {
                continue;
            }
            const Eigen::Vector3d w = normal.normalized();
            const Eigen::Vector3d u = w.unitOrthogonal();
            const Eigen::Vector3d v = w.cross(u);
            const double tooClose = coincidentFraction * N.squaredDistances(i, k - 1);

            // Floater and Reimers: q is a Delaunay neighbour of p (at the origin) iff its
            // half-plane {x : x.q <= |q|^2 / 2} bounds p's Voronoi cell, i.e. iff
            // 2 q / |q|^2 is a vertex of the convex hull of these points and the origin.
            candidates.clear();
            candidates.push_back({0.0, 0.0, -1});
            for (int j = 0; j < k; ++j) {
                const int q = N.indices(i, j);
                const Eigen::Vector3d d = (P.row(q) - P.row(i)).transpose();
                const double x = d.dot(u);
                const double y = d.dot(v);
                const double s = x * x + y * y;
                if (!(s > tooClose)) {
                    continue;
                }
                candidates.push_back({2.0 * x / s, 2.0 * y / s, q});
            }
            convexHull(candidates, hull);

            // The hull runs counter-clockwise, so its vertices are already in angular order
            // around the point, which lies inside or on it. A border point is a vertex of its
            // own hull: the ring then starts just after it and fans across the inside. Else it
            // starts at the direction closest to -u (angle -pi), as atan2 would sort it.
            const std::size_t size = hull.size();
            std::size_t start = 0;
            double smallest = std::numeric_limits<double>::infinity();
            for (std::size_t h = 0; h < size; ++h) {
                if (hull[h].index < 0) {
                    start = h + 1;
                    break;
                }
                const double angle = pseudoAngle(hull[h].x, hull[h].y);
                if (angle < smallest) {
                    smallest = angle;
                    start = h;
                }
            }
            int count = 0;
            for (std::size_t h = 0; h < size; ++h) {
                const Candidate& c = hull[(start + h) % size];
                if (c.index >= 0) {
                    slots(i, count++) = c.index;
                }
            }
            counts[i] = count;
        }
    }

    RingNeighbourhoods result;
    result.offsets.resize(n + 1);
    result.offsets[0] = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
        result.offsets[i + 1] = result.offsets[i] + counts[i];
    }
    result.indices.resize(result.offsets[n]);
#pragma omp parallel for schedule(static, 4096) num_threads(threadCount(options.threads))
    for (Eigen::Index i = 0; i < n; ++i) {
        for (int r = 0; r < counts[i]; ++r) {
            result.indices[result.offsets[i] + r] = slots(i, r);
        }
    }
    return result;
}

} // namespace featurelines
