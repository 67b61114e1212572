// SPDX-License-Identifier: LGPL-2.1-or-later
// Resampling and smoothing along a polyline on lines whose answer is exact: a straight line
// and a square.
#include <gtest/gtest.h>

#include "FeatureLines/network/Polyline.h"

using namespace featurelines;

TEST(Polyline, ResamplingIsEvenAndKeepsTheEnds)
{
    PointMatrix line(3, 3);
    line << 0, 0, 0, 4, 0, 0, 10, 0, 0;
    const PointMatrix open = resamplePolyline(line, false, 1.0);
    ASSERT_EQ(open.rows(), 11);
    for (Eigen::Index i = 0; i < open.rows(); ++i) {
        EXPECT_NEAR(open(i, 0), static_cast<double>(i), 1e-12);
    }
    PointMatrix square(4, 3);
    square << 0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0;
    const PointMatrix loop = resamplePolyline(square, true, 0.5);
    ASSERT_EQ(loop.rows(), 16) << "perimeter 8 at step 0.5, first vertex not repeated";
    for (Eigen::Index i = 0; i < loop.rows(); ++i) {
        EXPECT_NEAR((loop.row((i + 1) % loop.rows()) - loop.row(i)).norm(), 0.5, 1e-12);
    }
}

TEST(Polyline, SmoothingKeepsAStraightLineStraightAndItsEndsInPlace)
{
    PointMatrix line(4, 3);
    line << 0, 0, 0, 1, 0, 0, 7, 0, 0, 10, 0, 0;
    const PointMatrix smoothed = smoothPolyline(line, false, 2.0);
    ASSERT_GE(smoothed.rows(), 3);
    EXPECT_EQ(smoothed.row(0), line.row(0));
    EXPECT_EQ(smoothed.row(smoothed.rows() - 1), line.row(3));
    for (Eigen::Index i = 0; i < smoothed.rows(); ++i) {
        EXPECT_EQ(smoothed(i, 1), 0.0);
        EXPECT_EQ(smoothed(i, 2), 0.0);
        EXPECT_GE(smoothed(i, 0), 0.0);
        EXPECT_LE(smoothed(i, 0), 10.0);
    }
    EXPECT_EQ(smoothPolyline(line, false, 0.0), line) << "length 0: not smoothed";
}
