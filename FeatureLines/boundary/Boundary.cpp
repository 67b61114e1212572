// SPDX-License-Identifier: LGPL-2.1-or-later
// The boundary: points with a wide empty sector around them, chained by the cluster graph.
#include "FeatureLines/boundary/Boundary.h"
#include "FeatureLines/support/IdleThreads.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>
#include <omp.h>

namespace featurelines {

namespace {

constexpr double pi = 3.14159265358979323846;

/// The rings of neighbours a gap is confirmed over (BoundaryOptions::confirmationReach): the
/// point's neighbours, theirs and theirs again, as far as the reach.
constexpr int confirmationRings = 3;

/// A number in [0, 4) that grows with the angle of (x, y) from +x, anticlockwise (the
/// "diamond angle"): it orders directions like the angle does, without trigonometry.
double pseudoAngle(double x, double y)
{
    if (y >= 0.0) {
        return x >= 0.0 ? y / (x + y) : 1.0 - x / (y - x);
    }
    return x < 0.0 ? 2.0 - y / (-x - y) : 3.0 + x / (x - y);
}

/// Which of the eight 45 degree sectors bounded by the axes and the diagonals holds (x, y),
/// as a number 0..7 (signs of x and y, and whether |x| > |y|): no branches, which the
/// processor would mispredict half the time.
int octant(double x, double y)
{
    return (y >= 0.0 ? 4 : 0) | (x > 0.0 ? 2 : 0) | (std::abs(x) > std::abs(y) ? 1 : 0);
}

void requireValidInput(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                       const BoundaryOptions& options)
{
    const Eigen::Index n = P.rows();
    if (normals.rows() != n || N.size() != n) {
        throw std::invalid_argument(
            "boundary: the normals and neighbourhoods must have one row per point (" +
            std::to_string(n) + " points, " + std::to_string(normals.rows()) + " normals, " +
            std::to_string(N.size()) + " neighbourhoods)");
    }
    if (!(options.confirmationReach >= 0.0) || !std::isfinite(options.confirmationReach)) {
        throw std::invalid_argument("boundary: the confirmation reach must be 0 or more, not " +
                                    std::to_string(options.confirmationReach));
    }
    if (!(options.minGapAngle > 0.0 && options.minGapAngle < 360.0)) {
        throw std::invalid_argument(
            "boundary: the gap angle must be between 0 and 360 degrees, not " +
            std::to_string(options.minGapAngle));
    }
}

/// A point's neighbours seen from it in its tangent plane: their directions (xs, ys), those
/// not coinciding with the point (count), and which of the eight 45 degree sectors from +x
/// (sectors) and of the eight turned by 22.5 degrees (turned) they occupy.
struct TangentView
{
    explicit TangentView(int k) : xs(k), ys(k), order(k) {}
    void resize(std::size_t size)
    {
        xs.resize(size);
        ys.resize(size);
        order.resize(size);
    }

    std::vector<double> xs, ys;
    std::vector<std::pair<double, int>> order; // room for sorting the directions by angle
    std::vector<Eigen::Index> ring;            // the rings' points (viewOfRings)
    double tiny = 0.0;                         // shorter directions coincide with the point
    int count = 0;
    unsigned sectors = 0;
    unsigned turned = 0;
};

/// The view of point i's neighbours from point i.
void viewFromPoint(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                   Eigen::Index i, TangentView& view)
{
    const int k = N.k();
    const double cos22 = std::cos(pi / 8.0), sin22 = std::sin(pi / 8.0);
    std::vector<double>& xs = view.xs;
    std::vector<double>& ys = view.ys;
    // A frame of the tangent plane.
    const Eigen::Vector3d normal = normals.row(i).transpose();
    const Eigen::Vector3d helper =
        std::abs(normal.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d u = normal.cross(helper).normalized();
    const Eigen::Vector3d v = normal.cross(u);
    const double tiny = 1e-12 * (1.0 + P.row(i).cwiseAbs().maxCoeff());
    const double* p = P.data() + 3 * i;
    int count = 0;
    unsigned sectors = 0;
    unsigned turned = 0;
    for (int j = 0; j < k; ++j) {
        const double* q = P.data() + 3 * static_cast<Eigen::Index>(N.indices(i, j));
        const double dx = q[0] - p[0], dy = q[1] - p[1], dz = q[2] - p[2];
        xs[j] = dx * u.x() + dy * u.y() + dz * u.z();
        ys[j] = dx * v.x() + dy * v.y() + dz * v.z();
        if (std::abs(xs[j]) + std::abs(ys[j]) > tiny) {
            sectors |= 1u << octant(xs[j], ys[j]);
            turned |= 1u << octant(cos22 * xs[j] + sin22 * ys[j], cos22 * ys[j] - sin22 * xs[j]);
            ++count;
        }
    }
    view.tiny = tiny;
    view.count = count;
    view.sectors = sectors;
    view.turned = turned;
}

/// The directions of the view, ordered by angle, leave a gap wider than minGap (radians)
/// between consecutive ones; cosines are compared instead of angles.
bool hasGapWiderThan(TangentView& view, double minGap, double cosMinGap)
{
    const std::vector<double>& xs = view.xs;
    const std::vector<double>& ys = view.ys;
    std::vector<std::pair<double, int>>& order = view.order;
    const int k = static_cast<int>(xs.size());
    int count = 0;
    for (int j = 0; j < k; ++j) {
        if (std::abs(xs[j]) + std::abs(ys[j]) > view.tiny) {
            order[count++] = {pseudoAngle(xs[j], ys[j]), j};
        }
    }
    std::sort(order.begin(), order.begin() + count);
    bool wide = count == 1;
    for (int a = 0; a < count && !wide; ++a) {
        const int from = order[a].second;
        const int to = order[(a + 1) % count].second;
        const double dot = xs[from] * xs[to] + ys[from] * ys[to];
        const double cross = xs[from] * ys[to] - ys[from] * xs[to];
        const double lengths = std::sqrt((xs[from] * xs[from] + ys[from] * ys[from]) *
                                         (xs[to] * xs[to] + ys[to] * ys[to]));
        const double cosine = dot / lengths;
        if (a + 1 < count && cosine > 0.0 && std::abs(cross) <= 1e-9 * lengths) {
            // The same direction, the sign of the cross product only rounding: no gap.
            continue;
        }
        if (cross > 0.0) {
            // The gap is below 180 degrees: acos(cosine).
            wide = minGap < pi && cosine < cosMinGap;
        } else if (cross < 0.0 || cosine < 0.0 || a + 1 == count) {
            // At least 180 degrees: 2 pi - acos(cosine) (all the circle when the last
            // direction comes back onto the first).
            wide = minGap <= pi || cosine > cosMinGap;
        }
    }
    return wide;
}

/// The view from point i of the points within `reach` times its k-th neighbour distance that
/// confirmationRings rings of neighbours reach, in the frame of its own tangent plane.
void viewOfRings(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                 Eigen::Index i, double reach, TangentView& view)
{
    const int k = N.k();
    const Eigen::Vector3d normal = normals.row(i).transpose();
    const Eigen::Vector3d helper =
        std::abs(normal.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d u = normal.cross(helper).normalized();
    const Eigen::Vector3d v = normal.cross(u);
    const Eigen::Vector3d p = P.row(i).transpose();
    const double limit = reach * reach * N.squaredDistances(i, k - 1);
    std::size_t count = 0;
    auto add = [&](Eigen::Index q) {
        const Eigen::Vector3d d = P.row(q).transpose() - p;
        if (q != i && d.squaredNorm() <= limit) {
            view.xs[count] = d.dot(u);
            view.ys[count] = d.dot(v);
            ++count;
        }
    };
    std::vector<Eigen::Index>& ring = view.ring;
    ring.assign(1, i);
    for (int depth = 0; depth < confirmationRings; ++depth) {
        const std::size_t inner = ring.size();
        for (std::size_t r = 0; r < inner; ++r) {
            const Eigen::Index q = ring[r];
            if ((P.row(q) - P.row(i)).squaredNorm() > limit) {
                continue;
            }
            for (int m = 0; m < k; ++m) {
                ring.push_back(N.indices(q, m));
            }
        }
        std::sort(ring.begin(), ring.end());
        ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    }
    view.resize(ring.size());
    for (const Eigen::Index q : ring) {
        add(q);
    }
    view.resize(count);
    view.tiny = 1e-12 * (1.0 + P.row(i).cwiseAbs().maxCoeff());
}

} // namespace

std::vector<char> boundaryPoints(const PointMatrix& P, const NormalMatrix& normals,
                                 const Neighbourhoods& N, const BoundaryOptions& options)
{
    requireValidInput(P, normals, N, options);
    const Eigen::Index n = P.rows();
    const double minGap = options.minGapAngle * pi / 180.0;
    const double cosMinGap = std::cos(minGap);
    std::vector<char> boundary(n, 0);
#pragma omp parallel num_threads(threadCount(options.threads))
    {
        TangentView view(N.k());
#pragma omp for schedule(static, 4096)
        for (Eigen::Index i = 0; i < n; ++i) {
            viewFromPoint(P, normals, N, i, view);
            // A gap wider than 90 degrees contains a whole 45 degree sector, of the eight from
            // +x and of the eight turned by 22.5 degrees: with all eight occupied in either
            // there is none, and no angle needs computing (most points).
            if (view.count == 0 ||
                ((view.sectors == 0xFF || view.turned == 0xFF) && options.minGapAngle >= 90.0)) {
                continue;
            }
            boundary[i] = hasGapWiderThan(view, minGap, cosMinGap) ? 1 : 0;
        }
    }
    if (options.confirmationReach > 0.0) {
#pragma omp parallel num_threads(threadCount(options.threads))
        {
            TangentView ring(N.k());
#pragma omp for schedule(dynamic, 256)
            for (Eigen::Index i = 0; i < n; ++i) {
                if (boundary[i]) {
                    viewOfRings(P, normals, N, i, options.confirmationReach, ring);
                    boundary[i] = hasGapWiderThan(ring, minGap, cosMinGap) ? 1 : 0;
                }
            }
        }
    }
    return boundary;
}

Boundary extractBoundary(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                         double spacing, const BoundaryOptions& options)
{
    if (!(spacing > 0.0) || !std::isfinite(spacing)) {
        throw std::invalid_argument("boundary: the point spacing must be a positive number");
    }
    Boundary result;
    result.isBoundary = boundaryPoints(P, normals, N, options);
    // Every boundary point is a candidate cluster of its own; other points are left out.
    std::vector<int> cluster(result.isBoundary.size(), -1);
    int count = 0;
    for (std::size_t i = 0; i < cluster.size(); ++i) {
        if (result.isBoundary[i]) {
            cluster[i] = count++;
        }
    }
    const std::vector<char> candidate(count, 1);
    result.network = buildClusterGraph({P, N, cluster, candidate, spacing}, options.graph).network;
    return result;
}

} // namespace featurelines
