// SPDX-License-Identifier: LGPL-2.1-or-later
// Morton (Z-order) keys of points and their sort: the canonical order of the cloud
// (analyseCloud) and the cells of the neighbour search (nearestNeighbours).
// Design: docs/design/neighbourhoods.md.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "FeatureLines/PointCloud.h"

namespace featurelines {

/// Bits of a key per axis: 3 x 21 = 63 bits.
constexpr int mortonBitsPerAxis = 21;

/// Bits 0..20 of v spread to every third bit (bit b to bit 3 b).
inline std::uint64_t spreadBits(std::uint64_t v)
{
    v &= 0x1FFFFF;
    v = (v | v << 32) & 0x1F00000000FFFFULL;
    v = (v | v << 16) & 0x1F0000FF0000FFULL;
    v = (v | v << 8) & 0x100F00F00F00F00FULL;
    v = (v | v << 4) & 0x10C30C30C30C30C3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
}

/// The key of the cell with integer coordinates x, y, z (each below 2^21): bit b of x is bit
/// 3 b of the key, of y bit 3 b + 1, of z bit 3 b + 2.
inline std::uint64_t mortonKey(std::uint64_t x, std::uint64_t y, std::uint64_t z)
{
    return spreadBits(x) | spreadBits(y) << 1 | spreadBits(z) << 2;
}

/// The smallest size (largest side of the bounding box) of a cloud that is not one point:
/// squared distances of its neighbours stay far above the smallest double (2.2e-308).
constexpr double minimumCloudSize = 1e-100;
/// The farthest a cloud may lie from the origin, in multiples of its size: at 1e8 sizes a
/// double still resolves 1e-8 of the size, far below any point spacing of a scan.
constexpr double maximumOffsetInSizes = 1e8;

/// The quantisation of a cloud's keys: its bounding box from `low`, its largest side in
/// 2^21 - 1 steps (`scale` steps per length unit; 0 when every point coincides).
struct MortonGrid
{
    Eigen::RowVector3d low = Eigen::RowVector3d::Zero();
    double scale = 0.0;

    /// Throws std::invalid_argument, naming the problem, for a cloud whose coordinates the
    /// keys and the fits cannot resolve: a NaN or infinite coordinate, one beyond the float
    /// range (3.4e38), a size below minimumCloudSize, or coordinates farther from the origin
    /// than maximumOffsetInSizes times the size. Every stage's grid is built here.
    explicit MortonGrid(const PointMatrix& P);
    /// Position along an axis in steps (not rounded).
    double steps(double coordinate, int axis) const { return (coordinate - low[axis]) * scale; }
    /// The key of row i of P.
    std::uint64_t key(const PointMatrix& P, Eigen::Index i) const
    {
        return mortonKey(static_cast<std::uint64_t>(steps(P(i, 0), 0)),
                         static_cast<std::uint64_t>(steps(P(i, 1), 1)),
                         static_cast<std::uint64_t>(steps(P(i, 2), 2)));
    }
};

/// Sorts by key, stably (pairs of equal keys keep their order): a parallel radix sort, 11 bits
/// of the key a pass.
void sortByMortonKey(std::vector<std::pair<std::uint64_t, int>>& keyed);

} // namespace featurelines
