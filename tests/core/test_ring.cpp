// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/neighbourhoods/RingNeighbourhood.h"
#include "SampledShapes.h"

using namespace featurelines;

namespace {

/// Triangular lattice of n rows and n columns, spacing 1, in the plane z = 0: row r is
/// shifted by r/2, rows sqrt(3)/2 apart. Row 0 lies on y = 0.
PointMatrix triangularLattice(int n)
{
    PointMatrix P(n * n, 3);
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c) {
            P.row(r * n + c) << c + 0.5 * (r % 2), r * std::sqrt(3.0) / 2.0, 0.0;
        }
    }
    return P;
}

/// Square lattice, spacing 1, each point moved by up to +-jitter in x and y (seeded).
PointMatrix squareLattice(int n, double jitter, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> offset(-jitter, jitter);
    PointMatrix P(n * n, 3);
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c) {
            P.row(r * n + c) << c + offset(rng), r + offset(rng), 0.0;
        }
    }
    return P;
}

RingNeighbourhoods ringsOf(const PointMatrix& P)
{
    const Neighbourhoods N = nearestNeighbours(P, {16, 0});
    return ringNeighbourhoods(P, pcaNormals(P, N).normals, N);
}

/// True when point i lies at least `margin` inside the bounding box in x and y.
bool interior(const PointMatrix& P, Eigen::Index i, double margin)
{
    const Eigen::RowVector3d low = P.colwise().minCoeff();
    const Eigen::RowVector3d high = P.colwise().maxCoeff();
    return P(i, 0) > low(0) + margin && P(i, 0) < high(0) - margin && P(i, 1) > low(1) + margin &&
           P(i, 1) < high(1) - margin;
}

} // namespace

TEST(Ring, TriangularLatticeHasTheSixNearest)
{
    const PointMatrix P = triangularLattice(15);
    const RingNeighbourhoods R = ringsOf(P);
    ASSERT_EQ(R.offsets.size(), static_cast<std::size_t>(P.rows() + 1));
    int checked = 0;
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        if (!interior(P, i, 2.0)) {
            continue;
        }
        ++checked;
        ASSERT_EQ(R.size(i), 6) << "point " << i;
        for (int j = 0; j < 6; ++j) {
            const Eigen::RowVector3d d = P.row(R.begin(i)[j]) - P.row(i);
            const Eigen::RowVector3d next = P.row(R.begin(i)[(j + 1) % 6]) - P.row(i);
            EXPECT_NEAR(d.norm(), 1.0, 1e-12);
            // Ordered by angle around the normal (+z, the sign PCA picks here): each next
            // neighbour is 60 degrees further counter-clockwise.
            EXPECT_NEAR(std::atan2(d.x() * next.y() - d.y() * next.x(), d.dot(next)),
                        std::acos(-1.0) / 3.0, 1e-9);
        }
    }
    EXPECT_GT(checked, 50);
}

TEST(Ring, ExactSquareLatticeHasFourNeighbours)
{
    // The Voronoi cells are squares: the diagonal points touch p's cell at a corner only.
    const PointMatrix P = squareLattice(12, 0.0, 1);
    const RingNeighbourhoods R = ringsOf(P);
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        if (interior(P, i, 1.5)) {
            EXPECT_EQ(R.size(i), 4) << "point " << i;
        }
    }
}

TEST(Ring, JitteredSquareLatticeIsADelaunayTriangulation)
{
    // Each lattice square gets one of its diagonals: 4 edges to the axis neighbours plus 0 to
    // 4 diagonals, 6 on average (Euler's formula for a triangulation).
    const PointMatrix P = squareLattice(30, 0.05, 2);
    const RingNeighbourhoods R = ringsOf(P);
    double total = 0.0;
    int count = 0;
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        if (!interior(P, i, 1.5)) {
            continue;
        }
        EXPECT_GE(R.size(i), 4);
        EXPECT_LE(R.size(i), 8);
        int axisNeighbours = 0;
        for (const int* q = R.begin(i); q != R.end(i); ++q) {
            axisNeighbours += (P.row(*q) - P.row(i)).norm() < 1.2;
        }
        EXPECT_EQ(axisNeighbours, 4) << "point " << i;
        total += R.size(i);
        ++count;
    }
    EXPECT_NEAR(total / count, 6.0, 0.25);
}

TEST(Ring, UniformRandomPointsHaveEveryDelaunayNeighbourAmongTheirNeighbours)
{
    // Uniform random points (no lattice: the Delaunay neighbours are often beyond the nearest
    // 8, so the hull is built from more than the first candidates). The reference, for each
    // interior point p: q among p's 16 neighbours is a Delaunay neighbour of p iff the image
    // w = 2 (q - p) / |q - p|^2 is a vertex of the convex hull of the origin and all the
    // images, i.e. lies in no triangle of three other of those points (points in general
    // position: no three on a line).
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coordinate(0.0, 40.0);
    const int n = 1600;
    PointMatrix P(n, 3);
    for (int i = 0; i < n; ++i) {
        P.row(i) << coordinate(rng), coordinate(rng), 0.0;
    }
    const Neighbourhoods N = nearestNeighbours(P, {16, 0});
    NormalMatrix up(n, 3);
    up.rowwise() = Eigen::RowVector3d(0.0, 0.0, 1.0);
    const RingNeighbourhoods R = ringNeighbourhoods(P, up, N);
    const auto inTriangle = [](const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                               const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
        const auto side = [](const Eigen::Vector2d& o, const Eigen::Vector2d& u,
                             const Eigen::Vector2d& v) {
            return (u - o).x() * (v - o).y() - (u - o).y() * (v - o).x();
        };
        const double s1 = side(a, b, p), s2 = side(b, c, p), s3 = side(c, a, p);
        return (s1 > 0 && s2 > 0 && s3 > 0) || (s1 < 0 && s2 < 0 && s3 < 0);
    };
    int checked = 0, beyondEight = 0;
    for (int i = 0; i < n; ++i) {
        if (!interior(P, i, 4.0)) {
            continue;
        }
        std::vector<Eigen::Vector2d> w{Eigen::Vector2d::Zero()};
        for (int j = 0; j < N.k(); ++j) {
            const Eigen::Vector2d d = (P.row(N.indices(i, j)) - P.row(i)).head<2>().transpose();
            w.push_back(2.0 * d / d.squaredNorm());
        }
        std::vector<int> expected;
        for (int j = 1; j <= N.k(); ++j) {
            bool vertex = true;
            for (size_t a = 0; a < w.size() && vertex; ++a) {
                for (size_t b = a + 1; b < w.size() && vertex; ++b) {
                    for (size_t c = b + 1; c < w.size() && vertex; ++c) {
                        const bool others = a != size_t(j) && b != size_t(j) && c != size_t(j);
                        vertex = !(others && inTriangle(w[j], w[a], w[b], w[c]));
                    }
                }
            }
            if (vertex) {
                expected.push_back(N.indices(i, j - 1));
                beyondEight += j > 8 ? 1 : 0;
            }
        }
        std::vector<int> ring(R.begin(i), R.end(i));
        std::sort(ring.begin(), ring.end());
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(ring, expected) << "point " << i;
        ++checked;
    }
    EXPECT_GT(checked, 1000);
    // The case the shortcut must get right does occur.
    EXPECT_GT(beyondEight, 20);
}

TEST(Ring, BorderPointsKeepNeighboursOnOneSide)
{
    // Row 0 of the triangular lattice is its lower border: those rings never reach y < 0.
    // Inside the border each point has its two border neighbours and two above.
    const int n = 15;
    const PointMatrix P = triangularLattice(n);
    const RingNeighbourhoods R = ringsOf(P);
    for (int c = 0; c < n; ++c) {
        ASSERT_GE(R.size(c), 2) << "border point " << c;
        for (const int* q = R.begin(c); q != R.end(c); ++q) {
            EXPECT_GE(P(*q, 1), 0.0);
        }
        if (c >= 2 && c < n - 2) {
            EXPECT_EQ(R.size(c), 4) << "border point " << c;
        }
    }
}

TEST(Ring, DuplicatePointIsSkipped)
{
    // A copy of an interior point: neither copy lists the other, both keep the six nearest.
    const PointMatrix lattice = triangularLattice(11);
    const Eigen::Index centre = 5 * 11 + 5;
    PointMatrix P(lattice.rows() + 1, 3);
    P << lattice, lattice.row(centre);
    const RingNeighbourhoods R = ringsOf(P);
    for (const Eigen::Index i : {centre, P.rows() - 1}) {
        ASSERT_EQ(R.size(i), 6);
        for (const int* q = R.begin(i); q != R.end(i); ++q) {
            EXPECT_NEAR((P.row(*q) - P.row(i)).norm(), 1.0, 1e-12);
        }
    }
}

TEST(Ring, SphereRingsSurroundEveryPoint)
{
    // A closed surface has no border: every ring goes all the way round (no gap over 180
    // degrees between consecutive neighbours), about six on average.
    const shapes::Sample s = shapes::sphere(10.0, 1.0, 3);
    const RingNeighbourhoods R = ringsOf(s.points);
    const double pi = std::acos(-1.0);
    double total = 0.0;
    for (Eigen::Index i = 0; i < s.size(); ++i) {
        ASSERT_GE(R.size(i), 3);
        const Eigen::Vector3d n = s.normals.row(i).transpose();
        const Eigen::Vector3d u = n.unitOrthogonal();
        const Eigen::Vector3d v = n.cross(u);
        std::vector<double> angles;
        for (const int* q = R.begin(i); q != R.end(i); ++q) {
            const Eigen::Vector3d d = (s.points.row(*q) - s.points.row(i)).transpose();
            angles.push_back(std::atan2(d.dot(v), d.dot(u)));
        }
        std::sort(angles.begin(), angles.end());
        double widestGap = angles.front() + 2 * pi - angles.back();
        for (std::size_t j = 1; j < angles.size(); ++j) {
            widestGap = std::max(widestGap, angles[j] - angles[j - 1]);
        }
        EXPECT_LT(widestGap, pi) << "point " << i;
        total += R.size(i);
    }
    EXPECT_NEAR(total / s.size(), 6.0, 0.25);
}

TEST(Ring, MismatchedInputThrows)
{
    const PointMatrix P = triangularLattice(6);
    const Neighbourhoods N = nearestNeighbours(P, {8, 0});
    NormalMatrix normals(P.rows() - 1, 3);
    normals.setZero();
    EXPECT_THROW(ringNeighbourhoods(P, normals, N), std::invalid_argument);
}
