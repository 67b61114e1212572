// SPDX-License-Identifier: LGPL-2.1-or-later
// Reading and writing point clouds.
#pragma once

#include <string>

#include "FeatureLines/PointCloud.h"

namespace featurelines {

/// Reads a point cloud. The format follows the file's extension (case-insensitive):
///  - .xyz .txt .asc .csv: one point per line, x y z separated by white space or commas;
///    further columns (normals, colours) are ignored; empty lines and lines starting with
///    '#', '//' or '%' are skipped; FreeCAD's .asc header lines are skipped.
///  - .ply (ascii, binary little and big endian) and .pcd through PCL.
/// Throws std::invalid_argument with a message naming the file, and the line or header field
/// where there is one, for: a missing or unreadable file, one that is not a regular file (a
/// FIFO, a device), an unknown extension, a non-numeric or short line, a row with decimal
/// commas ("1,5 2,25 3,125": white space between the numbers and a comma between digits), a
/// PLY or PCD file holding fewer or more data rows than its header says, NaN or infinite
/// coordinates, coordinates beyond the float range (|x| > 3.4e38), and a file with no point.
/// Bytes of the file quoted in a message are printable ASCII or written as \xNN.
PointMatrix readCloud(const std::string& path);

/// Writes P as text, one "x y z" line per point, full double precision.
void writeXyz(const std::string& path, const PointMatrix& P);

/// Throws std::invalid_argument naming `what` and the first such point when a coordinate of P
/// is beyond the float range: the core computes in double, but squared distances and
/// covariance sums of larger coordinates overflow, and PLY and PCD files store float.
void checkFloatRange(const PointMatrix& P, const std::string& what);

/// Throws std::invalid_argument naming `what` when P has a NaN or infinite coordinate
/// (reporting the first bad row) or has fewer than `minimumPoints` rows.
void checkFinite(const PointMatrix& P, const std::string& what, Eigen::Index minimumPoints = 1);

} // namespace featurelines
