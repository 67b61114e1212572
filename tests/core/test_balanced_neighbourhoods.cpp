// SPDX-License-Identifier: LGPL-2.1-or-later
// Scan rows far apart: every point's k nearest neighbours lie on its own row, so their PCA
// plane is undefined. Balanced, the neighbourhoods reach the rows on either side and give the
// surface's normal; an even sampling is left as it is.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "FeatureLines/boundary/Boundary.h"
#include "FeatureLines/neighbourhoods/BalancedNeighbourhoods.h"
#include "FeatureLines/neighbourhoods/Normals.h"

using namespace featurelines;

namespace {

/// Scan rows on the plane z = 0 turned by 30 degrees about x: rows along x, `step` apart
/// along a row, `rowGap` apart across, with a little jitter in every direction (noise along
/// the normal included), as a scanner leaves.
PointMatrix tiltedRows(int perRow, int rows, double step, double rowGap, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> jitter(0.0, 0.05 * step);
    const double c = std::cos(M_PI / 6.0), s = std::sin(M_PI / 6.0);
    PointMatrix P(perRow * rows, 3);
    for (int r = 0; r < rows; ++r) {
        for (int i = 0; i < perRow; ++i) {
            const double x = i * step + jitter(rng), y = r * rowGap + jitter(rng);
            const double z = jitter(rng);
            P.row(r * perRow + i) << x, c * y - s * z, s * y + c * z;
        }
    }
    return P;
}

double largestNormalError(const NormalMatrix& normals, const Eigen::Vector3d& truth)
{
    double largest = 0.0;
    for (Eigen::Index i = 0; i < normals.rows(); ++i) {
        const double cosine = std::min(1.0, std::abs(normals.row(i).dot(truth)));
        largest = std::max(largest, std::acos(cosine) * 180.0 / M_PI);
    }
    return largest;
}

} // namespace

TEST(BalancedNeighbourhoods, RowsFarApartGetTheSurfaceNormal)
{
    const int perRow = 300, rows = 40;
    const PointMatrix P = tiltedRows(perRow, rows, 1.0, 10.0, 3);
    const Eigen::Vector3d truth(0.0, -std::sin(M_PI / 6.0), std::cos(M_PI / 6.0));
    Neighbourhoods N = nearestNeighbours(P);
    // Unbalanced, the row alone decides the normal: the test below is not empty-handed.
    EXPECT_GT(largestNormalError(pcaNormals(P, N).normals, truth), 45.0);

    // Every neighbourhood but a few at the rows' ends, where the next rows are out of reach.
    const Eigen::VectorXd spread = pcaNormals(P, N).spread;
    EXPECT_GT(double(balanceCollinearNeighbourhoods(P, N, spread).size()), 0.95 * double(P.rows()));
    EXPECT_LT(largestNormalError(pcaNormals(P, N).normals, truth), 2.0);
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        for (int j = 1; j < N.k(); ++j) {
            ASSERT_LE(N.squaredDistances(i, j - 1), N.squaredDistances(i, j));
        }
        for (int j = 0; j < N.k(); ++j) {
            ASSERT_NE(N.indices(i, j), i);
            ASSERT_DOUBLE_EQ(N.squaredDistances(i, j),
                             (P.row(N.indices(i, j)) - P.row(i)).squaredNorm());
        }
    }
}

TEST(BalancedNeighbourhoods, RowsFarApartHaveTheirBorderOnlyAsBoundary)
{
    const int perRow = 300, rows = 40;
    const PointMatrix P = tiltedRows(perRow, rows, 1.0, 10.0, 4);
    Neighbourhoods N = nearestNeighbours(P);
    // Unbalanced, each row is a strip of its own and reads as boundary all along.
    const std::vector<char> rowsAlone = boundaryPoints(P, pcaNormals(P, N).normals, N);
    EXPECT_GT(std::count(rowsAlone.begin(), rowsAlone.end(), 1), P.rows() / 2);

    balanceCollinearNeighbourhoods(P, N, pcaNormals(P, N).spread);
    const std::vector<char> boundary = boundaryPoints(P, pcaNormals(P, N).normals, N);
    for (int r = 1; r + 1 < rows; ++r) {
        for (int i = 10; i + 10 < perRow; ++i) {
            EXPECT_FALSE(boundary[static_cast<size_t>(r * perRow + i)])
                << "row " << r << ", point " << i << " inside the scan read as boundary";
        }
    }
}

TEST(BalancedNeighbourhoods, EvenSamplingIsLeftAsItIs)
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 50.0);
    PointMatrix P(20000, 3);
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        P.row(i) << unit(rng), unit(rng), 0.0;
    }
    Neighbourhoods N = nearestNeighbours(P);
    const Neighbourhoods before = N;
    EXPECT_TRUE(balanceCollinearNeighbourhoods(P, N, pcaNormals(P, N).spread).empty());
    EXPECT_EQ(N.indices, before.indices);
}
