// SPDX-License-Identifier: LGPL-2.1-or-later
// The random parts' aggregation (bench/cad/RandomBenchmark.h) on hand-made records whose
// means and worst tenths are known.
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "RandomBenchmark.h"

using namespace featurelines::bench;

namespace {

RandomPartRecord record(double sharpF1, double closedness)
{
    RandomPartRecord r;
    TypeScore& sharp = r.score.types[static_cast<size_t>(LineType::Sharp)];
    sharp.f1 = sharpF1;
    sharp.truthSamples = 10;
    r.score.closedness = closedness;
    return r;
}

} // namespace

TEST(RandomBenchmark, SeedListsAndGroups)
{
    EXPECT_EQ(parseSeedList("3-5,1000"), (std::vector<std::uint32_t>{3, 4, 5, 1000}));
    EXPECT_THROW(parseSeedList("5-3"), std::invalid_argument);
    EXPECT_THROW(parseSeedList("a"), std::invalid_argument);
    EXPECT_EQ(randomGroupOfSeed(199), "tuning");
    EXPECT_EQ(randomGroupOfSeed(1000), "held-out");
    EXPECT_EQ(randomGroupOfSeed(1199), "held-out");
    EXPECT_EQ(randomGroupOfSeed(500), "other");
}

TEST(RandomBenchmark, WorstTenthIsTheMeanOfTheLowestTenthAtLeastOne)
{
    // 20 values 1..20: the lowest two, mean 1.5; the highest two for distances, 19.5.
    std::vector<double> v;
    for (int i = 20; i >= 1; --i) {
        v.push_back(i);
    }
    EXPECT_DOUBLE_EQ(worstTenthMean(v), 1.5);
    EXPECT_DOUBLE_EQ(worstTenthMean(v, true), 19.5);
    // Three values: one of them; undefined values do not count.
    EXPECT_DOUBLE_EQ(worstTenthMean({0.9, std::nan(""), 0.4, 0.7}), 0.4);
    EXPECT_TRUE(std::isnan(worstTenthMean({std::nan("")})));
}

TEST(RandomBenchmark, FloorsFailOnlyBelow)
{
    const std::vector<RandomPartRecord> records = {record(0.8, 1.0), record(0.4, 0.5)};
    const RandomMeans means = randomMeans(records);
    EXPECT_DOUBLE_EQ(means.sharpF1, 0.6);
    EXPECT_DOUBLE_EQ(means.closedness, 0.75);
    // No part has smooth edges: its mean is undefined, and a floor on it fails.
    EXPECT_TRUE(std::isnan(means.smoothF1));
    EXPECT_TRUE(floorFailures(means, parseFloors("sharp=0.6,closed=0.7")).empty());
    EXPECT_EQ(floorFailures(means, parseFloors("sharp=0.61,closed=0.7")).size(), 1u);
    EXPECT_EQ(floorFailures(means, parseFloors("smooth=0.1")).size(), 1u);
    EXPECT_THROW(parseFloors("edges=0.5"), std::invalid_argument);
    EXPECT_THROW(parseFloors("sharp"), std::invalid_argument);
}
