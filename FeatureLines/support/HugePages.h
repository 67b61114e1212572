// SPDX-License-Identifier: LGPL-2.1-or-later
// Transparent huge pages for the large arrays (neighbour lists, point copies): fewer page
// faults and TLB misses on large clouds. Design: docs/design/pipeline.md (Support).
#pragma once

#include <cstddef>
#include <vector>

namespace featurelines {

/// Asks the kernel to back the whole 2 MiB pages inside [data, data + bytes) with transparent
/// huge pages, before the memory is first written. Only a hint: it does nothing where the
/// kernel has huge pages switched off, below 2 MiB, or on systems other than Linux. The memory
/// must come from the allocator (not the stack).
void adviseHugePages(void* data, std::size_t bytes);

/// adviseHugePages over the coefficients of an Eigen matrix (allocated, not yet written).
template <class Array> void adviseHugePagesOf(Array& array)
{
    adviseHugePages(array.data(),
                    static_cast<std::size_t>(array.size()) * sizeof(typename Array::value_type));
}

/// A vector of n copies of `value` whose storage is advised onto huge pages before it is
/// written.
template <class T> std::vector<T> hugePageVector(std::size_t n, const T& value = T())
{
    std::vector<T> v;
    v.reserve(n);
    adviseHugePages(v.data(), n * sizeof(T));
    v.assign(n, value);
    return v;
}

} // namespace featurelines
