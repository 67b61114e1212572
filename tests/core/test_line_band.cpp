// SPDX-License-Identifier: LGPL-2.1-or-later
// The band around lines: a point is in it when it lies closer than the width to a line (up to
// the sampling of the lines at half the width, so the tests keep clear of the rim).
#include <gtest/gtest.h>

#include <utility>

#include "FeatureLines/smooth/LineBand.h"

using namespace featurelines;

namespace {

/// The line through the rows of V.
Polyline polyline(PointMatrix V, bool closed)
{
    Polyline line;
    line.points = std::move(V);
    line.closed = closed;
    return line;
}

/// The segment from the origin to (10, 0, 0).
Polyline segment()
{
    PointMatrix V(2, 3);
    V << 0, 0, 0, 10, 0, 0;
    return polyline(V, false);
}

} // namespace

TEST(LineBand, PointsWithinTheWidthOfASegmentAreInside)
{
    const LineBand band({segment()}, 1.0);
    EXPECT_FALSE(band.empty());
    EXPECT_TRUE(band.contains({5.0, 0.5, 0.0}));
    EXPECT_TRUE(band.contains({3.3, 0.0, -0.6}));
    EXPECT_TRUE(band.contains({10.5, 0.0, 0.0})) << "past the end, within the width";
    EXPECT_FALSE(band.contains({5.0, 1.2, 0.0}));
    EXPECT_FALSE(band.contains({11.2, 0.0, 0.0}));
    EXPECT_FALSE(band.contains({-40.0, 7.0, 3.0}));
}

TEST(LineBand, AClosedLineHasItsClosingSegment)
{
    PointMatrix corners(4, 3);
    corners << 0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0;
    const Polyline square = polyline(corners, true);
    Polyline open = square;
    open.closed = false;
    const Eigen::RowVector3d onClosingSegment(0.3, 2.0, 0.0);
    EXPECT_TRUE(LineBand({square}, 0.5).contains(onClosingSegment));
    EXPECT_FALSE(LineBand({open}, 0.5).contains(onClosingSegment));
    EXPECT_FALSE(LineBand({square}, 0.5).contains({2.0, 2.0, 0.0})) << "the square's middle";
}

TEST(LineBand, NoLinesNoBand)
{
    const LineBand band({}, 1.0);
    EXPECT_TRUE(band.empty());
    EXPECT_FALSE(band.contains({0.0, 0.0, 0.0}));
}

TEST(LineBand, PointsNearLinesAnswersForTheListedPoints)
{
    PointMatrix P(4, 3);
    P << 5, 0.5, 0, //
        5, 3, 0,    //
        0, 0, 0,    //
        9, -0.2, 0.1;
    const std::vector<Polyline> lines = {segment()};
    EXPECT_EQ(pointsNearLines(P, {3, 1, 0}, lines, 1.0), (std::vector<char>{1, 0, 1}));
    EXPECT_EQ(pointsNearLines(P, {0, 3}, {}, 1.0), (std::vector<char>{0, 0}));
    EXPECT_EQ(pointsNearLines(P, {0, 3}, lines, 0.0), (std::vector<char>{0, 0}));
}
