// SPDX-License-Identifier: LGPL-2.1-or-later
// The accuracy benchmark's metric (bench/cad/LineScore.h) on hand-made polylines whose score
// is known exactly.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "LineScore.h"

using featurelines::PointMatrix;
using namespace featurelines::bench;

namespace {

constexpr double spacing = 0.5;

/// A straight polyline from a to b with `n` vertices.
TypedPolyline segment(LineType type, const Eigen::Vector3d& a, const Eigen::Vector3d& b, int n)
{
    TypedPolyline line;
    line.type = type;
    line.points.resize(n, 3);
    for (int i = 0; i < n; ++i) {
        line.points.row(i) = (a + (b - a) * (double(i) / (n - 1))).transpose();
    }
    return line;
}

/// A closed square of side `side` in the plane z = 0, one vertex per corner.
TypedPolyline square(LineType type, double side)
{
    TypedPolyline line;
    line.type = type;
    line.closed = true;
    line.points.resize(4, 3);
    line.points << 0, 0, 0, side, 0, 0, side, side, 0, 0, side, 0;
    return line;
}

LineScoreOptions options()
{
    LineScoreOptions o;
    o.spacing = spacing;
    return o;
}

const TypeScore& of(const LineScore& s, LineType t)
{
    return s.types[static_cast<size_t>(t)];
}

} // namespace

TEST(LineScore, PerfectLinesScoreOne)
{
    const std::vector<TypedPolyline> truth = {square(LineType::Sharp, 20.0),
                                              segment(LineType::Smooth, {0, 0, 5}, {20, 0, 5}, 41)};
    // The detector's lines have other vertices but the same geometry.
    const std::vector<TypedPolyline> detected = {
        square(LineType::Sharp, 20.0), segment(LineType::Smooth, {0, 0, 5}, {20, 0, 5}, 7)};
    const LineScore s = scoreLines(detected, truth, options());
    EXPECT_DOUBLE_EQ(of(s, LineType::Sharp).precision, 1.0);
    EXPECT_DOUBLE_EQ(of(s, LineType::Sharp).recall, 1.0);
    EXPECT_DOUBLE_EQ(of(s, LineType::Sharp).f1, 1.0);
    EXPECT_DOUBLE_EQ(of(s, LineType::Smooth).f1, 1.0);
    // No boundary in the model: recall and F1 are undefined, not 0 or 1.
    EXPECT_TRUE(std::isnan(of(s, LineType::Boundary).f1));
    EXPECT_EQ(s.lineCount, 2);
}

TEST(LineScore, LineShiftedByFiveSpacingsScoresZero)
{
    const std::vector<TypedPolyline> truth = {segment(LineType::Sharp, {0, 0, 0}, {30, 0, 0}, 2)};
    const std::vector<TypedPolyline> detected = {
        segment(LineType::Sharp, {0, 5 * spacing, 0}, {30, 5 * spacing, 0}, 2)};
    const LineScore s = scoreLines(detected, truth, options());
    EXPECT_DOUBLE_EQ(of(s, LineType::Sharp).precision, 0.0);
    EXPECT_DOUBLE_EQ(of(s, LineType::Sharp).recall, 0.0);
    EXPECT_DOUBLE_EQ(of(s, LineType::Sharp).f1, 0.0);
}

TEST(LineScore, WrongTypeDoesNotCount)
{
    const std::vector<TypedPolyline> truth = {segment(LineType::Sharp, {0, 0, 0}, {30, 0, 0}, 2)};
    const std::vector<TypedPolyline> detected = {
        segment(LineType::Smooth, {0, 0, 0}, {30, 0, 0}, 2)};
    const LineScore s = scoreLines(detected, truth, options());
    EXPECT_DOUBLE_EQ(of(s, LineType::Sharp).f1, 0.0);
    EXPECT_DOUBLE_EQ(of(s, LineType::Smooth).precision, 0.0);
}

TEST(LineScore, HalfTheEdgeFoundGivesRecallOneHalf)
{
    const std::vector<TypedPolyline> truth = {segment(LineType::Sharp, {0, 0, 0}, {100, 0, 0}, 2)};
    const std::vector<TypedPolyline> detected = {
        segment(LineType::Sharp, {0, 0, 0}, {50, 0, 0}, 2)};
    const LineScore s = scoreLines(detected, truth, options());
    EXPECT_DOUBLE_EQ(of(s, LineType::Sharp).precision, 1.0);
    // Truth samples up to 50 + tolerance match: recall is 1/2 up to the tolerance's share.
    const double tolShare = 3 * spacing / 100.0;
    EXPECT_NEAR(of(s, LineType::Sharp).recall, 0.5 + tolShare, 0.01);
}

TEST(LineScore, OpenLineWithAFreeEndIsNotClosed)
{
    const std::vector<TypedPolyline> truth = {square(LineType::Sharp, 20.0)};
    // Three sides of the square as one open line: both ends are free.
    TypedPolyline open = square(LineType::Sharp, 20.0);
    open.closed = false;
    const LineScore s = scoreLines({open}, truth, options());
    EXPECT_DOUBLE_EQ(s.closedness, 0.0);

    const LineScore closed = scoreLines({square(LineType::Sharp, 20.0)}, truth, options());
    EXPECT_DOUBLE_EQ(closed.closedness, 1.0);
}

TEST(LineScore, LineEndingOnAnotherLineIsJoined)
{
    // A closed square and a line from its side outwards to a second closed square: the
    // connecting line ends on both squares, so all three lines count.
    TypedPolyline inner = square(LineType::Sharp, 20.0);
    TypedPolyline outer = square(LineType::Sharp, 60.0);
    outer.points.rowwise() -= Eigen::RowVector3d(20, 20, 0);
    const TypedPolyline bridge = segment(LineType::Smooth, {10, 0, 0}, {10, -20, 0}, 5);
    LineScore s = scoreLines({inner, outer, bridge}, {inner, outer, bridge}, options());
    EXPECT_DOUBLE_EQ(s.closedness, 1.0);

    // The same connecting line stopping halfway has one free end.
    const TypedPolyline stub = segment(LineType::Smooth, {10, 0, 0}, {10, -10, 0}, 5);
    s = scoreLines({inner, outer, stub}, {inner, outer, bridge}, options());
    EXPECT_NEAR(s.closedness, 2.0 / 3.0, 1e-12);
}

TEST(LineScore, SharpClosednessCountsSharpLinesEndingOnLinesOfAnyType)
{
    // A sharp square; a sharp line from it to a smooth square (both ends joined, one on a
    // smooth line); a smooth stub with a free end; a sharp stub with a free end.
    TypedPolyline inner = square(LineType::Sharp, 20.0);
    TypedPolyline outer = square(LineType::Smooth, 60.0);
    outer.points.rowwise() -= Eigen::RowVector3d(20, 20, 0);
    const TypedPolyline bridge = segment(LineType::Sharp, {10, 0, 0}, {10, -20, 0}, 5);
    const TypedPolyline smoothStub = segment(LineType::Smooth, {0, 10, 0}, {-10, 10, 0}, 5);
    const TypedPolyline sharpStub = segment(LineType::Sharp, {20, 10, 0}, {30, 10, 0}, 5);
    LineScore s = scoreLines({inner, outer, bridge, smoothStub}, {inner, outer}, options());
    EXPECT_DOUBLE_EQ(s.sharpClosedness, 1.0);
    EXPECT_NEAR(s.closedness, 3.0 / 4.0, 1e-12);
    s = scoreLines({inner, outer, bridge, smoothStub, sharpStub}, {inner, outer}, options());
    EXPECT_NEAR(s.sharpClosedness, 2.0 / 3.0, 1e-12);
    // No sharp line: undefined.
    s = scoreLines({outer}, {outer}, options());
    EXPECT_TRUE(std::isnan(s.sharpClosedness));
}

TEST(LineScore, OpenLineThatReturnsToItsStartIsJoined)
{
    // A square given as an open polyline whose last vertex repeats the first.
    TypedPolyline loop = square(LineType::Sharp, 20.0);
    loop.closed = false;
    loop.points.conservativeResize(5, 3);
    loop.points.row(4) = loop.points.row(0);
    const LineScore s = scoreLines({loop}, {square(LineType::Sharp, 20.0)}, options());
    EXPECT_DOUBLE_EQ(s.closedness, 1.0);
}

TEST(LineScore, FlaggedPointsNearAnotherTypeLeaveThePrecisionDenominator)
{
    const std::vector<TypedPolyline> truth = {
        segment(LineType::Sharp, {0, 0, 0}, {10, 0, 0}, 2),
        segment(LineType::Smooth, {0, 20, 0}, {10, 20, 0}, 2)};
    PointMatrix flagged(3, 3);
    flagged << 5, 0.2, 0, // on the sharp edge
        5, 20.2, 0,       // on the smooth edge: not a false sharp detection
        5, 10, 0;         // near nothing: a false detection of every type
    const LineScore s = scoreFlaggedPoints(flagged, truth, options());
    EXPECT_DOUBLE_EQ(of(s, LineType::Sharp).precision, 0.5);
    EXPECT_DOUBLE_EQ(of(s, LineType::Smooth).precision, 0.5);
    EXPECT_TRUE(std::isnan(s.closedness));
}

TEST(LineScore, BadInputIsRejected)
{
    LineScoreOptions o = options();
    o.spacing = 0.0;
    EXPECT_THROW(scoreLines({}, {}, o), std::invalid_argument);
    TypedPolyline bad = square(LineType::Sharp, 1.0);
    bad.points(1, 1) = std::nan("");
    EXPECT_THROW(scoreLines({bad}, {}, options()), std::invalid_argument);
    EXPECT_THROW(lineTypeFromName("crease"), std::invalid_argument);
}

TEST(LineQuality, LineParallelToTheEdgeSitsAtItsOffset)
{
    // A circle of radius 10 as truth (a curved edge, coarse vertices) and a detected circle of
    // radius 10.25 (half a spacing out), densely sampled: the distance to the true polyline's
    // segments is the offset, up to the chord's sagitta of the true polygon.
    const auto circle = [](LineType type, double r, int n) {
        TypedPolyline line;
        line.type = type;
        line.closed = true;
        line.points.resize(n, 3);
        for (int i = 0; i < n; ++i) {
            const double a = 2.0 * M_PI * i / n;
            line.points.row(i) << r * std::cos(a), r * std::sin(a), 0.0;
        }
        return line;
    };
    const std::vector<TypedPolyline> truth = {circle(LineType::Smooth, 10.0, 720)};
    const std::vector<TypedPolyline> detected = {circle(LineType::Smooth, 10.25, 2000)};
    const LineQuality q = measureLineQuality(detected, truth, options());
    // 0.25 model units = half a spacing; the true polygon's resampling chords (step 0.25)
    // lie inside the circle by at most 0.25^2 / 80, under 1e-3 units.
    EXPECT_NEAR(q.medianDistance, 0.5, 0.01);
    EXPECT_NEAR(q.p95Distance, 0.5, 0.01);
    EXPECT_DOUBLE_EQ(q.matchedShare, 1.0);
    EXPECT_EQ(q.freeEnds, 0);
    EXPECT_DOUBLE_EQ(q.linesPerTrueEdge, 1.0);
}

TEST(LineQuality, LineOnTheEdgeHasDistanceZero)
{
    // Vertices of the detected line fall between the true line's resampled vertices: the
    // distance is to the segments, so it is 0, not up to half a resampling step.
    const std::vector<TypedPolyline> truth = {segment(LineType::Sharp, {0, 0, 0}, {10, 0, 0}, 2)};
    const std::vector<TypedPolyline> detected = {
        segment(LineType::Sharp, {0.1, 0, 0}, {9.9, 0, 0}, 37)};
    const LineQuality q = measureLineQuality(detected, truth, options());
    EXPECT_NEAR(q.medianDistance, 0.0, 1e-12);
    EXPECT_NEAR(q.p95Distance, 0.0, 1e-12);
}

TEST(LineQuality, SharpEdgeFoundAsSmoothIsConfused)
{
    // One true sharp edge; the detector finds its first half as a smooth line and misses the
    // second half (more than the tolerance of 1.5 units away from the smooth line's end).
    const std::vector<TypedPolyline> truth = {segment(LineType::Sharp, {0, 0, 0}, {20, 0, 0}, 2)};
    const std::vector<TypedPolyline> detected = {
        segment(LineType::Smooth, {0, 0, 0}, {10, 0, 0}, 2)};
    const LineQuality q = measureLineQuality(detected, truth, options());
    const double asSmooth = q.confusionShare(LineType::Sharp, LineType::Smooth);
    const double asSharp = q.confusionShare(LineType::Sharp, LineType::Sharp);
    // Samples every 0.25 on [0, 20]: those up to 10 + 1.5 are found (smooth), the rest missed.
    EXPECT_NEAR(asSmooth, 11.5 / 20.0, 0.02);
    EXPECT_DOUBLE_EQ(asSharp, 0.0);
    EXPECT_TRUE(std::isnan(q.confusionShare(LineType::Smooth, LineType::Smooth)));
}

TEST(LineQuality, FragmentsAndBoundaryLengthAreCounted)
{
    // A true closed square of side 20 (one edge), found as four straight pieces with gaps of
    // 4 units (8 spacings) at the corners, plus a boundary line of 5 units on the closed part.
    const std::vector<TypedPolyline> truth = {square(LineType::Sharp, 20.0)};
    const std::vector<TypedPolyline> detected = {
        segment(LineType::Sharp, {2, 0, 0}, {18, 0, 0}, 2),
        segment(LineType::Sharp, {20, 2, 0}, {20, 18, 0}, 2),
        segment(LineType::Sharp, {18, 20, 0}, {2, 20, 0}, 2),
        segment(LineType::Sharp, {0, 18, 0}, {0, 2, 0}, 2),
        segment(LineType::Boundary, {5, 5, 0}, {10, 5, 0}, 3)};
    const LineQuality q = measureLineQuality(detected, truth, options());
    EXPECT_DOUBLE_EQ(q.linesPerTrueEdge, 5.0);
    // Eight sharp ends in the gaps, two boundary ends inside the face.
    EXPECT_EQ(q.freeEnds, 10);
    EXPECT_NEAR(q.boundaryLength, 10.0, 1e-12); // 5 units = 10 spacings
}

TEST(LineQuality, EstimatesAreComparedWithTheEdgeTheyLieOn)
{
    // A true crease of 90 degrees and, 10 units away, a true fillet border of radius 4; a third
    // true edge, sharp, has no detected line. The detector gives the crease 80 degrees on its
    // first half and no angle on its second, and the border a radius of 5.
    TypedPolyline crease = segment(LineType::Sharp, {0, 0, 0}, {20, 0, 0}, 2);
    crease.angle = 90.0;
    TypedPolyline border = segment(LineType::Smooth, {0, 10, 0}, {20, 10, 0}, 2);
    border.radius = 4.0;
    TypedPolyline far = segment(LineType::Sharp, {0, 40, 0}, {20, 40, 0}, 2);
    far.angle = 120.0;
    TypedPolyline first = segment(LineType::Sharp, {0, 0, 0}, {10, 0, 0}, 2);
    first.angle = 80.0;
    TypedPolyline second = segment(LineType::Sharp, {10.25, 0, 0}, {20, 0, 0}, 2);
    TypedPolyline smooth = segment(LineType::Smooth, {0, 10.2, 0}, {20, 10.2, 0}, 2);
    smooth.radius = 5.0;
    // A sharp line on the smooth edge is no sample of either estimate.
    TypedPolyline wrongType = segment(LineType::Sharp, {0, 10, 1}, {20, 10, 1}, 2);
    wrongType.angle = 10.0;
    const LineQuality q = measureLineQuality({first, second, smooth, wrongType},
                                             {crease, border, far}, options());
    EXPECT_DOUBLE_EQ(q.medianAngleError, 10.0);
    EXPECT_DOUBLE_EQ(q.medianRadiusError, 0.25);
    // Samples every 0.25: 41 on the first half with an angle, 40 on the second without.
    EXPECT_NEAR(q.angleEstimatedShare, 41.0 / 81.0, 1e-12);
    EXPECT_DOUBLE_EQ(q.radiusEstimatedShare, 1.0);
    // Without estimates on either side: undefined, not zero.
    const LineQuality none = measureLineQuality({second}, {crease}, options());
    EXPECT_TRUE(std::isnan(none.medianAngleError));
    EXPECT_TRUE(std::isnan(none.medianRadiusError));
    EXPECT_DOUBLE_EQ(none.angleEstimatedShare, 0.0);
}
