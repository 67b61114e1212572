// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/MortonOrder.h"

#include "FeatureLines/IdleThreads.h"

namespace featurelines {

MortonGrid::MortonGrid(const PointMatrix& P)
{
    if (P.rows() == 0) {
        return;
    }
    low = P.colwise().minCoeff();
    const double extent = (P.colwise().maxCoeff() - low).maxCoeff();
    scale = extent > 0.0 ? double((1 << mortonBitsPerAxis) - 1) / extent : 0.0;
}

void sortByMortonKey(std::vector<std::pair<std::uint64_t, int>>& keyed)
{
    releaseIdleThreads();                // a serial sweep of the pairs per pass
    constexpr int bits = 11, passes = 6; // 66 bits cover the 63 of the key
    constexpr std::size_t buckets = std::size_t(1) << bits;
    const std::size_t n = keyed.size();
    std::vector<std::size_t> count(passes * buckets, 0);
    for (const auto& item : keyed) {
        for (int p = 0; p < passes; ++p) {
            ++count[p * buckets + ((item.first >> (bits * p)) & (buckets - 1))];
        }
    }
    std::vector<std::pair<std::uint64_t, int>> other(n);
    for (int p = 0; p < passes && n > 0; ++p) {
        std::size_t* start = count.data() + p * buckets;
        if (start[(keyed[0].first >> (bits * p)) & (buckets - 1)] == n) {
            continue; // one digit for all: the order stays
        }
        std::size_t at = 0;
        for (std::size_t b = 0; b < buckets; ++b) {
            const std::size_t c = start[b];
            start[b] = at;
            at += c;
        }
        for (const auto& item : keyed) {
            other[start[(item.first >> (bits * p)) & (buckets - 1)]++] = item;
        }
        keyed.swap(other);
    }
}

} // namespace featurelines
