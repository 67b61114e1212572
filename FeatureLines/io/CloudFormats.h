// SPDX-License-Identifier: LGPL-2.1-or-later
// The readers of each cloud format on the file's bytes in memory: what readCloud dispatches
// to, and what the fuzz targets (tests/fuzz) feed directly. Internal to the io stage.
// Why the project parses PLY and PCD itself: docs/RELIABILITY.md, "The readers".
#pragma once

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "FeatureLines/PointCloud.h"

namespace featurelines::detail {

/// The bytes of a point cloud file named `name` (used in messages and for its extension), read
/// as readCloud reads the file: the format from the extension, then the finite and float-range
/// checks. Throws std::invalid_argument naming `name` on anything else.
PointMatrix parseCloud(std::string_view bytes, const std::string& name);

/// .xyz .txt .asc .csv: one point per line (CloudIO.h).
PointMatrix parseTextCloud(std::string_view bytes, const std::string& name);
/// PLY: ascii, binary little and big endian; x, y, z of the element "vertex".
PointMatrix parsePlyCloud(std::string_view bytes, const std::string& name);
/// PCD v0.5-0.7: ascii, binary and binary_compressed; the fields x, y, z.
PointMatrix parsePcdCloud(std::string_view bytes, const std::string& name);

/// One token for a message: at most 20 bytes, those outside printable ASCII written as \xNN,
/// so a binary file gives a readable line and sends no escape sequence to the terminal.
std::string quoted(std::string_view token);

/// A scalar type of a PLY property or a PCD field.
struct ScalarType
{
    enum Kind
    {
        Signed,
        Unsigned,
        Float
    } kind = Signed;
    int size = 0; ///< bytes: 1, 2, 4 or 8; 0 for no valid type
};

/// The value of a scalar stored at `data` in little (or big) endian byte order.
double readScalar(const unsigned char* data, ScalarType type, bool bigEndian);

/// A line of a header: from `at` to the next '\n' (a final '\r' dropped); `at` moves past it.
/// False at the end of `bytes`.
bool nextLine(std::string_view bytes, std::size_t& at, std::string_view& line);

/// The words of a header line, split on blanks.
std::vector<std::string_view> wordsOf(std::string_view line);

/// True when `text` holds only line ends and blanks: what some writers leave after the last
/// binary row (a final newline), which is no data row. NUL bytes are data (a zero float).
bool onlyPadding(std::string_view text);

/// The unsigned integer in `word`, or false when it is not one (or beyond 2^64 - 1).
bool parseCount(std::string_view word, std::uint64_t& value);

/// The number in `token` (a leading '+' allowed; nan and inf read as such, to be refused by
/// checkFinite with the point's index). Throws naming `where` and the token otherwise.
double parseNumber(std::string_view token, const std::string& where);

/// An ascii value as a field of `type` holds it: a float field keeps a float's precision, as
/// the binary form of the same file would. A value beyond the float range is kept, for
/// checkFloatRange to name.
inline double storedAs(double value, ScalarType type)
{
    const bool isFloat = type.kind == ScalarType::Float && type.size == 4;
    return isFloat && std::abs(value) <= FLT_MAX ? double(float(value)) : value;
}

} // namespace featurelines::detail
