// SPDX-License-Identifier: LGPL-2.1-or-later
// Two small pieces the smooth-edge stage's sources share (not part of the API): the indices of
// every point of a region, and the median of values.
#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

#include <Eigen/Core>

namespace featurelines::detail {

inline std::vector<int> allIndices(Eigen::Index n)
{
    std::vector<int> all(static_cast<size_t>(n));
    std::iota(all.begin(), all.end(), 0);
    return all;
}

inline double median(std::vector<double> v)
{
    if (v.empty()) {
        return 0.0;
    }
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

} // namespace featurelines::detail
