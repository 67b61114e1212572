// SPDX-License-Identifier: LGPL-2.1-or-later
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#if defined(__linux__)
#include <sys/prctl.h>
#endif

#include "FeatureLines/support/HugePages.h"
#include "FeatureLines/neighbourhoods/Neighbours.h"

using namespace featurelines;

namespace {

/// The kernel's transparent huge page mode ("always", "madvise", "never"), or "" where the
/// system does not say (not Linux, /sys not mounted).
std::string hugePageMode()
{
    std::ifstream file("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string line;
    if (!std::getline(file, line)) {
        return "";
    }
    const std::size_t open = line.find('['), close = line.find(']');
    return open == std::string::npos || close == std::string::npos
               ? ""
               : line.substr(open + 1, close - open - 1);
}

/// The process's anonymous memory on transparent huge pages, in kB (-1 when not known).
long anonHugePagesKb()
{
    std::ifstream file("/proc/self/smaps_rollup");
    std::string key;
    long value = 0;
    std::string unit;
    while (file >> key) {
        if (key == "AnonHugePages:" && (file >> value >> unit)) {
            return value;
        }
        std::getline(file, unit);
    }
    return -1;
}

} // namespace

TEST(HugePages, AdviceLeavesEveryByteAsWritten)
{
    // Sizes below, at and across the 2 MiB pages, at unaligned starts; advice before and after
    // the writes.
    for (const std::size_t size : {std::size_t(0), std::size_t(1), std::size_t(4095),
                                   (std::size_t(2) << 20) + 17, std::size_t(9) << 20}) {
        for (const std::size_t offset : {std::size_t(0), std::size_t(3)}) {
            std::vector<unsigned char> buffer(size + offset);
            adviseHugePages(buffer.data() + offset, size);
            for (std::size_t i = 0; i < buffer.size(); ++i) {
                buffer[i] = static_cast<unsigned char>(i * 131 + 7);
            }
            adviseHugePages(buffer.data() + offset, size);
            bool same = true;
            for (std::size_t i = 0; i < buffer.size(); ++i) {
                same = same && buffer[i] == static_cast<unsigned char>(i * 131 + 7);
            }
            EXPECT_TRUE(same) << size << " bytes at offset " << offset;
        }
    }
    adviseHugePages(nullptr, 0);
    adviseHugePages(nullptr, std::size_t(4) << 20);
}

TEST(HugePages, VectorHoldsTheCopies)
{
    const std::vector<std::pair<std::uint64_t, int>> v =
        hugePageVector<std::pair<std::uint64_t, int>>(300000, {7, -2});
    ASSERT_EQ(v.size(), 300000u);
    EXPECT_EQ(v.front(), (std::pair<std::uint64_t, int>{7, -2}));
    EXPECT_EQ(v.back(), (std::pair<std::uint64_t, int>{7, -2}));
    EXPECT_TRUE(hugePageVector<int>(0).empty());
}

TEST(HugePages, NeighbourListsOfAMillionPointsLieOnHugePages)
{
    const std::string mode = hugePageMode();
    if (mode != "always" && mode != "madvise") {
        GTEST_SKIP() << "transparent huge pages are '" << mode << "' here";
    }
#if defined(__linux__) && defined(PR_GET_THP_DISABLE)
    if (prctl(PR_GET_THP_DISABLE, 0, 0, 0, 0) == 1) {
        GTEST_SKIP() << "transparent huge pages are switched off for this process";
    }
#endif
    const long before = anonHugePagesKb();
    if (before < 0) {
        GTEST_SKIP() << "/proc/self/smaps_rollup does not say";
    }
    Neighbourhoods N;
    N.allocate(1 << 20, 16); // 64 MiB of indices, 128 MiB of distances
    ASSERT_EQ(N.size(), 1 << 20);
    ASSERT_EQ(N.k(), 16);
    N.indices.setConstant(1);
    N.squaredDistances.setConstant(2.0);
    const long after = anonHugePagesKb();
    // At least one of the ~95 whole 2 MiB pages; the kernel may give small pages for some
    // where memory is fragmented.
    EXPECT_GE(after - before, 2048) << "mode " << mode;
    EXPECT_EQ(N.indices.sum(), 16 << 20);
}
