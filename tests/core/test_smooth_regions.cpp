// SPDX-License-Identifier: LGPL-2.1-or-later
// The cloud divided into smooth regions (Sec. 1.2): on hand-made neighbourhoods whose answer
// is known, every region point keeps a neighbourhood inside its region, so each region has the
// k-nearest-neighbour rows its curvature is fitted over.
#include <gtest/gtest.h>

#include "FeatureLines/SmoothRegions.h"

using namespace featurelines;

namespace {

/// Neighbourhoods of k = 8 given row by row; the squared distances grow along each row.
Neighbourhoods handMade(const std::vector<std::vector<int>>& rows)
{
    Neighbourhoods N;
    N.indices.resize(static_cast<Eigen::Index>(rows.size()), 8);
    N.squaredDistances.resize(static_cast<Eigen::Index>(rows.size()), 8);
    for (size_t i = 0; i < rows.size(); ++i) {
        for (int j = 0; j < 8; ++j) {
            N.indices(static_cast<Eigen::Index>(i), j) = rows[i][static_cast<size_t>(j)];
            N.squaredDistances(static_cast<Eigen::Index>(i), j) = 1.0 + j;
        }
    }
    return N;
}

} // namespace

TEST(SmoothRegions, PointLeftWithoutARegionNeighbourJoinsTheBand)
{
    // Point 0 sees eight eligible points 1..8 (enough at first); each of those sees point 0
    // and seven candidates 9..15 of the sharp stage, so all eight join the band and point 0 is
    // left with no neighbour in its region. Points 16..24 see only one another: a region.
    std::vector<std::vector<int>> rows(25);
    rows[0] = {1, 2, 3, 4, 5, 6, 7, 8};
    for (int i = 1; i <= 8; ++i) {
        rows[i] = {0, 9, 10, 11, 12, 13, 14, 15};
    }
    for (int i = 9; i <= 15; ++i) {
        rows[i] = {0, 1, 2, 3, 4, 5, 6, 7};
    }
    for (int i = 16; i <= 24; ++i) {
        for (int j = 16; j <= 24; ++j) {
            if (j != i) {
                rows[i].push_back(j);
            }
        }
    }
    const Neighbourhoods N = handMade(rows);
    PointMatrix P = PointMatrix::Zero(25, 3);
    for (Eigen::Index i = 0; i < 25; ++i) {
        P(i, 0) = static_cast<double>(i);
    }
    std::vector<char> candidate(25, 0);
    for (int i = 9; i <= 15; ++i) {
        candidate[static_cast<size_t>(i)] = 1;
    }
    SmoothRegionOptions options;
    options.minRegionNeighbours = 5;
    options.minRegionPoints = 1;
    const SmoothRegions regions = divideSmoothRegions(P, N, {}, candidate, 1.0, options);

    EXPECT_EQ(regions.region[0], -1) << "a point with no neighbour in its region";
    ASSERT_EQ(regions.count(), 1);
    EXPECT_EQ(regions.members[0].size(), 9u);
    EXPECT_EQ(regions.members[0].front(), 16);
    // Every region has its neighbourhoods (this threw for point 0 before).
    for (int r = 0; r < regions.count(); ++r) {
        EXPECT_NO_THROW(regionNeighbourhoods(N, regions.region, regions.members[r], r));
    }
}
