// SPDX-License-Identifier: LGPL-2.1-or-later
// The matrix types every stage of the core library takes and returns.
#pragma once

#include <Eigen/Core>

namespace featurelines {

/// P  #P by 3 point positions, one row per point. Row-major, so the three coordinates of a
/// point are contiguous (the neighbour search and the per-point loops read them that way).
using PointMatrix = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// N  #P by 3 unit normals, row i belongs to point i.
using NormalMatrix = PointMatrix;

/// I  #P by k point indices, row i lists the neighbours of point i.
using IndexMatrix = Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

} // namespace featurelines
