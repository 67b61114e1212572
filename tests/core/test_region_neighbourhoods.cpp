// SPDX-License-Identifier: LGPL-2.1-or-later
// A region's neighbourhoods within the region, as rows of its member list.
#include <gtest/gtest.h>

#include <stdexcept>

#include "FeatureLines/smooth/RegionNeighbourhoods.h"

using namespace featurelines;

namespace {

/// Four points, k = 3; squared distances as given.
Neighbourhoods fourPoints()
{
    Neighbourhoods N;
    N.indices.resize(4, 3);
    N.squaredDistances.resize(4, 3);
    N.indices << 1, 2, 3, //
        0, 2, 3,          //
        1, 3, 0,          //
        2, 1, 0;
    N.squaredDistances << 1, 4, 9, //
        1, 1, 4,                   //
        1, 1, 4,                   //
        1, 4, 9;
    return N;
}

} // namespace

TEST(RegionNeighbourhoods, HoldsEveryPointOnlyForTheWholeCloudInRowOrder)
{
    EXPECT_TRUE(holdsEveryPoint({0, 0, 0}, {0, 1, 2}, 0));
    EXPECT_FALSE(holdsEveryPoint({0, 0, 0}, {0, 2}, 0));
    EXPECT_FALSE(holdsEveryPoint({0, 1, 0}, {0, 1, 2}, 0));
    EXPECT_FALSE(holdsEveryPoint({1, 1, 1}, {0, 1, 2}, 0));
}

TEST(RegionNeighbourhoods, OutsideNeighboursAreReplacedByTheNearestInside)
{
    const Neighbourhoods N = fourPoints();
    // Region 0 is points 0, 1 and 3 (rows 0, 1, 2 of the sub-cloud); point 2 lies outside.
    const Neighbourhoods sub = regionNeighbourhoods(N, {0, 0, 1, 0}, {0, 1, 3}, 0);
    ASSERT_EQ(sub.size(), 3);
    ASSERT_EQ(sub.k(), 3);
    IndexMatrix indices(3, 3);
    indices << 1, 2, 1, //
        0, 2, 0,        //
        1, 0, 1;
    EXPECT_TRUE(sub.indices == indices) << sub.indices;
    EXPECT_EQ(sub.squaredDistances(0, 1), 9.0);
    EXPECT_EQ(sub.squaredDistances(0, 2), 1.0);
    EXPECT_EQ(sub.squaredDistances(1, 1), 4.0);
    EXPECT_EQ(sub.squaredDistances(2, 0), 4.0);
    EXPECT_EQ(sub.squaredDistances(2, 2), 4.0);
}

TEST(RegionNeighbourhoods, TheWholeCloudKeepsItsNeighbourhoods)
{
    const Neighbourhoods N = fourPoints();
    const Neighbourhoods sub = regionNeighbourhoods(N, {2, 2, 2, 2}, {0, 1, 2, 3}, 2);
    EXPECT_TRUE(sub.indices == N.indices);
    EXPECT_TRUE(sub.squaredDistances == N.squaredDistances);
}

TEST(RegionNeighbourhoods, BadInputIsRefused)
{
    const Neighbourhoods N = fourPoints();
    EXPECT_THROW(regionNeighbourhoods(N, {0, 0, 0}, {0, 1, 2}, 0), std::invalid_argument);
    // Point 2's neighbours 1, 3 and 0 all lie in region 1.
    EXPECT_THROW(regionNeighbourhoods(N, {1, 1, 0, 1}, {2}, 0), std::invalid_argument);
    // Point 3 is labelled 0 but missing from the members.
    EXPECT_THROW(regionNeighbourhoods(N, {0, 0, 1, 0}, {0, 1}, 0), std::invalid_argument);
}
