// SPDX-License-Identifier: LGPL-2.1-or-later
// The Morton (Z-order) code of a cell of a cubic grid: the bits of its three coordinates
// interleaved, so that cells close in space mostly get close codes. The canonical order of a
// cloud (Extraction.cpp) and the cells of a coarser curvature scale (CurvatureScale.cpp) sort
// by it.
#pragma once

#include <cstdint>

namespace featurelines {

/// The code of cell (x, y, z), each coordinate taken to its 21 low bits: bit b of x goes to
/// bit 3 b, of y to 3 b + 1, of z to 3 b + 2.
inline std::uint64_t mortonCode(std::uint64_t x, std::uint64_t y, std::uint64_t z)
{
    const auto spread = [](std::uint64_t v) {
        v &= 0x1FFFFF;
        v = (v | v << 32) & 0x1F00000000FFFFULL;
        v = (v | v << 16) & 0x1F0000FF0000FFULL;
        v = (v | v << 8) & 0x100F00F00F00F00FULL;
        v = (v | v << 4) & 0x10C30C30C30C30C3ULL;
        v = (v | v << 2) & 0x1249249249249249ULL;
        return v;
    };
    return spread(x) | spread(y) << 1 | spread(z) << 2;
}

} // namespace featurelines
