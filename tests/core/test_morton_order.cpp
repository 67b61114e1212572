// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "FeatureLines/neighbourhoods/MortonOrder.h"

using namespace featurelines;

namespace {

using Keyed = std::vector<std::pair<std::uint64_t, int>>;

/// n pairs (key, position) with keys drawn from `distinct` values spread over the 63 bits
/// (many equal keys: the stability shows).
Keyed randomKeys(int n, int distinct, unsigned seed)
{
    std::mt19937_64 rng(seed);
    std::vector<std::uint64_t> values(static_cast<size_t>(distinct));
    for (std::uint64_t& v : values) {
        v = rng() >> 1;
    }
    std::uniform_int_distribution<int> pick(0, distinct - 1);
    Keyed keyed(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        keyed[static_cast<size_t>(i)] = {values[static_cast<size_t>(pick(rng))], i};
    }
    return keyed;
}

Keyed stableSorted(Keyed keyed)
{
    std::stable_sort(keyed.begin(), keyed.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    return keyed;
}

} // namespace

TEST(MortonOrder, SortIsStableLargeAndSmall)
{
    // 300 000 pairs take the threads' runs, 1000 one sweep.
    for (int n : {300000, 1000}) {
        Keyed keyed = randomKeys(n, n / 10, 3);
        const Keyed expected = stableSorted(keyed);
        sortByMortonKey(keyed);
        EXPECT_EQ(keyed, expected) << n << " pairs";
    }
}

TEST(MortonOrder, SortInsideAParallelRegion)
{
    // Called from a thread of a team, the sort gets a team of one: every run is still moved.
    Keyed keyed = randomKeys(200000, 5000, 4);
    const Keyed expected = stableSorted(keyed);
#pragma omp parallel num_threads(2)
    {
#pragma omp single
        sortByMortonKey(keyed);
    }
    EXPECT_EQ(keyed, expected);
}

TEST(MortonOrder, SortOfEqualAndOfNoKeys)
{
    Keyed same(100000);
    for (int i = 0; i < 100000; ++i) {
        same[static_cast<size_t>(i)] = {42, 100000 - i};
    }
    const Keyed expected = same;
    sortByMortonKey(same);
    EXPECT_EQ(same, expected);
    Keyed none;
    sortByMortonKey(none);
    EXPECT_TRUE(none.empty());
}
