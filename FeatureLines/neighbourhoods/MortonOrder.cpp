// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/neighbourhoods/MortonOrder.h"

#include <algorithm>
#include <charconv>
#include <stdexcept>
#include <string>

#include <omp.h>

#include "FeatureLines/io/CloudIO.h"
#include "FeatureLines/support/HugePages.h"

namespace featurelines {

namespace {

/// A number for a message: shortest form that reads back the same ("1e-310", "1000000000000010").
std::string formatNumber(double value)
{
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

} // namespace

MortonGrid::MortonGrid(const PointMatrix& P)
{
    if (P.rows() == 0) {
        return;
    }
    checkFinite(P, "point cloud");
    checkFloatRange(P, "point cloud");
    low = P.colwise().minCoeff();
    const Eigen::RowVector3d high = P.colwise().maxCoeff();
    const double extent = (high - low).maxCoeff();
    if (extent > 0.0 && extent < minimumCloudSize) {
        throw std::invalid_argument("point cloud: its size (the largest side of its bounding box) "
                                    "is " +
                                    formatNumber(extent) +
                                    ", below the smallest supported, 1e-100: scale it up");
    }
    const double farthest = std::max(low.cwiseAbs().maxCoeff(), high.cwiseAbs().maxCoeff());
    if (extent > 0.0 && farthest > maximumOffsetInSizes * extent) {
        throw std::invalid_argument(
            "point cloud: its coordinates reach " + formatNumber(farthest) +
            ", more than 1e8 times its size (" + formatNumber(extent) +
            "): too far from the origin for double precision; move it nearer the origin");
    }
    scale = extent > 0.0 ? double((1 << mortonBitsPerAxis) - 1) / extent : 0.0;
}

void sortByMortonKey(std::vector<std::pair<std::uint64_t, int>>& keyed)
{
    constexpr int bits = 11, passes = 6; // 66 bits cover the 63 of the key
    constexpr std::size_t buckets = std::size_t(1) << bits;
    const std::size_t n = keyed.size();
    // Each thread counts and then moves one run of the array; the runs' items go to their
    // buckets in run order, so the sort is as stable as one sweep (a small array: one run).
    const int runs = n < (std::size_t(1) << 16) ? 1 : std::max(1, omp_get_max_threads());
    const auto runStart = [&](int r) { return n * static_cast<std::size_t>(r) / runs; };
    std::vector<std::size_t> start(static_cast<std::size_t>(runs) * buckets);
    auto other = hugePageVector<std::pair<std::uint64_t, int>>(n);
    for (int p = 0; p < passes && n > 0; ++p) {
        const auto digit = [&](const std::pair<std::uint64_t, int>& item) {
            return static_cast<std::size_t>((item.first >> (bits * p)) & (buckets - 1));
        };
        bool oneDigit = true;
        // A loop over the runs, not a team of that size: inside another parallel region the
        // team may be smaller.
#pragma omp parallel for num_threads(runs) schedule(static, 1) reduction(&& : oneDigit)
        for (int r = 0; r < runs; ++r) {
            std::size_t* count = start.data() + static_cast<std::size_t>(r) * buckets;
            std::fill(count, count + buckets, 0);
            const std::size_t first = runStart(r), last = runStart(r + 1);
            const std::size_t d0 = digit(keyed[0]);
            for (std::size_t i = first; i < last; ++i) {
                const std::size_t d = digit(keyed[i]);
                ++count[d];
                oneDigit = oneDigit && d == d0;
            }
        }
        if (oneDigit) {
            continue; // one digit for all: the order stays
        }
        // Bucket by bucket, run by run: where each run's items of each bucket go.
        std::size_t at = 0;
        for (std::size_t b = 0; b < buckets; ++b) {
            for (int r = 0; r < runs; ++r) {
                std::size_t& c = start[static_cast<std::size_t>(r) * buckets + b];
                const std::size_t items = c;
                c = at;
                at += items;
            }
        }
#pragma omp parallel for num_threads(runs) schedule(static, 1)
        for (int r = 0; r < runs; ++r) {
            std::size_t* to = start.data() + static_cast<std::size_t>(r) * buckets;
            for (std::size_t i = runStart(r); i < runStart(r + 1); ++i) {
                other[to[digit(keyed[i])]++] = keyed[i];
            }
        }
        keyed.swap(other);
    }
}

} // namespace featurelines
