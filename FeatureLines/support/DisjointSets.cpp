// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/support/DisjointSets.h"

#include <stdexcept>
#include <string>

namespace featurelines {

DisjointSets::DisjointSets(int n) : n_(n)
{
    if (n < 0) {
        throw std::invalid_argument("disjoint sets: " + std::to_string(n) + " elements");
    }
    parent_.reset(new std::atomic<int>[static_cast<size_t>(n)]);
#pragma omp parallel for schedule(static, 4096)
    for (int i = 0; i < n; ++i) {
        parent_[i].store(i, std::memory_order_relaxed);
    }
}

std::vector<int> DisjointSets::representatives() const
{
    std::vector<int> root(static_cast<size_t>(n_));
#pragma omp parallel for schedule(static, 4096)
    for (int i = 0; i < n_; ++i) {
        root[static_cast<size_t>(i)] = find(i);
    }
    return root;
}

} // namespace featurelines
