// SPDX-License-Identifier: LGPL-2.1-or-later
// A thin wall: a plate 1.5 to 3 spacings thick, whose top and bottom are two sheets a point's
// k nearest neighbours reach across. Separated, no neighbourhood holds points of both; a cube's
// creases and a noisy plane are no sheets; end to end, a 2-spacing plate gives its outline and
// no line on its faces.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "FeatureLines/Extraction.h"
#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/neighbourhoods/SheetNeighbourhoods.h"
#include "tests/support/SampledShapes.h"

using namespace featurelines;

namespace {

/// A plate `length` x `width` (x, y) and `thickness` (z), centred: prism parts 0-3 are the
/// rims, 4 the top (+z), 5 the bottom.
shapes::Sample plate(double length, double width, double thickness, unsigned seed)
{
    const double a = length / 2.0, b = width / 2.0;
    return shapes::prism({{-a, -b}, {a, -b}, {a, b}, {-a, b}}, thickness, 1.0, seed);
}

/// Two parallel sheets `width` x `depth` (x, y), `thickness` apart along z, each of
/// width x depth points at random positions (spacing about 1: a scan's irregular sampling,
/// clumps and gaps, not a grid whose points lie above one another), moved along z by noise of
/// standard deviation `sigma`. part: 4 the top sheet, 5 the bottom (as plate's caps), no rim.
shapes::Sample randomSheets(double width, double depth, double thickness, double sigma,
                            unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> x(-width / 2.0, width / 2.0);
    std::uniform_real_distribution<double> y(-depth / 2.0, depth / 2.0);
    std::normal_distribution<double> noise(0.0, sigma > 0.0 ? sigma : 1.0);
    const int perSheet = static_cast<int>(width * depth);
    shapes::Sample s;
    s.points.resize(2 * perSheet, 3);
    s.normals.resize(2 * perSheet, 3);
    for (int i = 0; i < 2 * perSheet; ++i) {
        const bool top = i < perSheet;
        const double z = (top ? thickness / 2.0 : -thickness / 2.0) +
                         (sigma > 0.0 ? noise(rng) : 0.0);
        s.points.row(i) << x(rng), y(rng), z;
        s.normals.row(i) << 0.0, 0.0, top ? 1.0 : -1.0;
        s.part.push_back(top ? 4 : 5);
    }
    return s;
}

/// Length of the lines of `r` farther than `margin` inside the outline of sheets
/// width x depth: on the faces, where no edge is.
double lengthOnTheFaces(const ExtractionResult& r, double width, double depth, double margin)
{
    double length = 0.0;
    for (const FeatureLine& line : r.lines) {
        for (Eigen::Index v = 1; v < line.points.rows(); ++v) {
            const Eigen::RowVector3d m = 0.5 * (line.points.row(v - 1) + line.points.row(v));
            if (std::abs(m.x()) < width / 2.0 - margin && std::abs(m.y()) < depth / 2.0 - margin) {
                length += (line.points.row(v) - line.points.row(v - 1)).norm();
            }
        }
    }
    return length;
}

/// Neighbours of top points on the bottom and of bottom points on the top, among the points at
/// least `margin` inside the outline (x within +-xMax - margin, y within +-yMax - margin). At
/// the rim the wall's two sheets turn into its narrow side face: a point there has the rim's
/// points in its plane fit, and the sheets meet.
int neighboursAcross(const shapes::Sample& s, const Neighbourhoods& N, double margin = 0.0)
{
    const double xMax = s.points.col(0).cwiseAbs().maxCoeff() - margin;
    const double yMax = s.points.col(1).cwiseAbs().maxCoeff() - margin;
    int across = 0;
    for (Eigen::Index i = 0; i < s.size(); ++i) {
        const int part = s.part[static_cast<size_t>(i)];
        if (part < 4 || std::abs(s.points(i, 0)) > xMax || std::abs(s.points(i, 1)) > yMax) {
            continue;
        }
        for (int j = 0; j < N.k(); ++j) {
            const int other = s.part[static_cast<size_t>(N.indices(i, j))];
            across += (other >= 4 && other != part) ? 1 : 0;
        }
    }
    return across;
}

} // namespace

TEST(SheetNeighbourhoods, PlateOneAndAHalfSpacingsThickKeepsItsSheetsApart)
{
    const shapes::Sample s = plate(40.0, 30.0, 1.5, 3);
    Neighbourhoods N = nearestNeighbours(s.points);
    const int before = neighboursAcross(s, N, 2.0);
    ASSERT_GT(before, 1000) << "the k nearest neighbours reach the other sheet";
    const std::vector<int> rows = separateSheets(s.points, N, samplingSpacing(N));
    EXPECT_GT(rows.size(), s.points.rows() / 2);
    EXPECT_LT(neighboursAcross(s, N, 2.0), before / 50);
    // Every row still holds k distinct neighbours, sorted by distance, none the point itself.
    for (Eigen::Index i = 0; i < N.size(); ++i) {
        std::set<int> seen;
        for (int j = 0; j < N.k(); ++j) {
            EXPECT_NE(N.indices(i, j), i);
            seen.insert(N.indices(i, j));
            if (j > 0) {
                EXPECT_LE(N.squaredDistances(i, j - 1), N.squaredDistances(i, j));
            }
        }
        EXPECT_EQ(seen.size(), static_cast<size_t>(N.k()));
    }
}

TEST(SheetNeighbourhoods, NoisyPlateThreeSpacingsThickLosesMostCrossings)
{
    shapes::Sample s = plate(40.0, 30.0, 3.0, 5);
    shapes::addNormalNoise(s, 0.3, 6);
    NeighbourOptions options;
    options.k = 32; // reaches 3 spacings across
    Neighbourhoods N = nearestNeighbours(s.points, options);
    const int before = neighboursAcross(s, N, 3.0);
    ASSERT_GT(before, 1000);
    separateSheets(s.points, N, samplingSpacing(N));
    // Noise of 0.3 spacing tilts the few-point planes the test reads: about a fifth of the
    // crossings stay (docs/design/neighbourhoods.md, "Thin walls").
    EXPECT_LT(neighboursAcross(s, N, 3.0), before / 4);
}

// Creases turn the planes; noise along one sheet raises the gap: neither is a second sheet.
TEST(SheetNeighbourhoods, CubeCreasesAndNoisyPlaneAreOneSheet)
{
    const shapes::Sample cube = shapes::cube(20.0, 1.0, 7);
    Neighbourhoods N = nearestNeighbours(cube.points);
    EXPECT_TRUE(separateSheets(cube.points, N, samplingSpacing(N)).empty());

    shapes::Sample plane = shapes::plane(40.0, 1.0, 8);
    shapes::addNormalNoise(plane, 0.5, 9);
    Neighbourhoods M = nearestNeighbours(plane.points);
    const std::vector<int> rows = separateSheets(plane.points, M, samplingSpacing(M));
    // Read as two sheets, most rows would be rebuilt. A row is rebuilt where a neighbour lies
    // three deviations of the noise off the plane (minAcross 1): under 1 in 50 rows.
    EXPECT_LT(rows.size(), static_cast<size_t>(plane.size() / 50));
}

TEST(SheetNeighbourhoods, OffKeepsTheNeighbourhoods)
{
    const shapes::Sample s = plate(20.0, 20.0, 1.5, 3);
    Neighbourhoods N = nearestNeighbours(s.points);
    const IndexMatrix before = N.indices;
    SheetOptions off;
    off.separate = false;
    EXPECT_TRUE(separateSheets(s.points, N, samplingSpacing(N), off).empty());
    EXPECT_EQ(N.indices, before);
    SheetOptions bad;
    bad.maxTurnDegrees = 90.0;
    EXPECT_THROW(separateSheets(s.points, N, 1.0, bad), std::invalid_argument);
    EXPECT_THROW(separateSheets(s.points, N, 0.0), std::invalid_argument);
}

// Issue 17: "a 2-spacing wall gives its two faces' outlines and nothing on the faces". The
// plate's rim is a face of 2 spacings, two rows of points: its two outlines come out as one
// closed line along the rim, within 1.5 spacings of both (docs/design/neighbourhoods.md,
// "Thin walls"). Without the separation the faces are tiled with lines.
int verticesOffOutline(const ExtractionResult& r, double a, double b, double t, double tolerance,
                       int& vertices)
{
    vertices = 0;
    int off = 0;
    for (const FeatureLine& line : r.lines) {
        for (Eigen::Index v = 0; v < line.points.rows(); ++v) {
            const Eigen::Vector3d p = line.points.row(v).transpose();
            // Distance to the nearest rim edge of the top or bottom outline.
            const double dx = std::max(0.0, std::abs(p.x()) - a);
            const double dy = std::max(0.0, std::abs(p.y()) - b);
            const double inX = a - std::abs(p.x()), inY = b - std::abs(p.y());
            const double rim = (dx > 0.0 || dy > 0.0) ? std::hypot(dx, dy)
                                                     : std::max(0.0, std::min(inX, inY));
            const double dz = std::abs(std::abs(p.z()) - t / 2.0);
            ++vertices;
            off += std::hypot(rim, dz) > tolerance ? 1 : 0;
        }
    }
    return off;
}

TEST(SheetNeighbourhoods, TwoSpacingPlateGivesItsOutlineAndNothingOnItsFaces)
{
    const double a = 20.0, b = 15.0, t = 2.0;
    const shapes::Sample s = plate(2.0 * a, 2.0 * b, t, 4);
    const ExtractionResult r = extractFeatureLines(s.points);
    int vertices = 0;
    EXPECT_EQ(verticesOffOutline(r, a, b, t, 2.5, vertices), 0) << "of " << vertices;
    ASSERT_GT(vertices, 0);
    EXPECT_LE(verticesOffOutline(r, a, b, t, 1.5, vertices), vertices / 30) << "of " << vertices;
    EXPECT_EQ(r.countLines(LineType::Boundary), 0);
    // Every line closed or ending on a junction of the network.
    for (const FeatureLine& line : r.lines) {
        if (line.closed) {
            continue;
        }
        for (const Eigen::Index end : {Eigen::Index(0), line.points.rows() - 1}) {
            double nearest = std::numeric_limits<double>::infinity();
            for (Eigen::Index j = 0; j < r.junctions.rows(); ++j) {
                nearest = std::min(nearest, (r.junctions.row(j) - line.points.row(end)).norm());
            }
            EXPECT_LT(nearest, 1e-6) << "a free end";
        }
    }
    // Every stretch of the rim has a line within 1.5 spacings.
    int rimSamples = 0, found = 0;
    for (double u = -1.0; u < 1.0; u += 0.02) {
        for (const Eigen::Vector3d q : {Eigen::Vector3d(u * a, b, 0.0), Eigen::Vector3d(u * a, -b, 0.0),
                                         Eigen::Vector3d(a, u * b, 0.0), Eigen::Vector3d(-a, u * b, 0.0)}) {
            ++rimSamples;
            bool near = false;
            for (const FeatureLine& line : r.lines) {
                for (Eigen::Index v = 0; v < line.points.rows() && !near; ++v) {
                    near = (line.points.row(v).transpose() - q).norm() <= 1.5 + t / 2.0;
                }
            }
            found += near ? 1 : 0;
        }
    }
    EXPECT_GE(found, 0.95 * rimSamples) << found << " of " << rimSamples;

    ExtractionOptions together;
    together.neighbours.sheets.separate = false;
    int before = 0;
    EXPECT_GT(verticesOffOutline(extractFeatureLines(s.points, together), a, b, t, 2.5, before),
              before / 4);
}

// Issue 17, item 2, on a scan's irregular sampling: two random sheets' points do not lie
// above one another, so a point's nearest few often hold one of the other sheet, which tilts
// their least-squares plane or, at half, turns it across the wall; the sheet's direction is
// then read from the neighbours' planes (docs/design/neighbourhoods.md, "Thin walls"). Without
// that, the three cases kept 83, 31 and 74 % of their crossings.
TEST(SheetNeighbourhoods, RandomSheetsKeepApartDownToOneAndAHalfSpacings)
{
    struct Case
    {
        double thickness, sigma;
        unsigned seed;
    };
    for (const Case c : {Case{1.5, 0.0, 11}, Case{2.0, 0.1, 12}, Case{3.0, 0.3, 13}}) {
        const shapes::Sample s = randomSheets(40.0, 30.0, c.thickness, c.sigma, c.seed);
        Neighbourhoods N = nearestNeighbours(s.points);
        const int before = neighboursAcross(s, N, 3.0);
        ASSERT_GT(before, 200) << "thickness " << c.thickness;
        separateSheets(s.points, N, samplingSpacing(N));
        EXPECT_LT(neighboursAcross(s, N, 3.0), before / 20)
            << "thickness " << c.thickness << ", noise " << c.sigma << ", before " << before;
    }
}

// End to end, the faces of noisy random sheets 3 spacings apart (noise 0.3 spacing) and clean
// ones 2 spacings apart hold no line (without the plane read again: 124 and 77 spacings of it).
TEST(SheetNeighbourhoods, RandomSheetsHoldNoLineOnTheirFaces)
{
    for (const auto& [thickness, sigma] : {std::pair{3.0, 0.3}, std::pair{2.0, 0.0}}) {
        const shapes::Sample s = randomSheets(40.0, 30.0, thickness, sigma, 21);
        const ExtractionResult r = extractFeatureLines(s.points);
        EXPECT_EQ(lengthOnTheFaces(r, 40.0, 30.0, 4.0), 0.0)
            << "thickness " << thickness << ", noise " << sigma;
    }
}
