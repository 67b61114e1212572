// SPDX-License-Identifier: LGPL-2.1-or-later
// The random part generator (PartFamilies.h): seeds map to families, same seed same part,
// every part a valid shape with typed edges, drawn numbers within their stated ranges, parts
// sized for their point count at spacing 1, and the truth scoring itself perfectly.
#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "LineScore.h"
#include "PartFamilies.h"
#include "ShapeSampling.h"

namespace featurelines::bench {
namespace {

int countOf(const TopoDS_Shape& shape, TopAbs_ShapeEnum type)
{
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(shape, type, map);
    return map.Extent();
}

double volumeOrArea(const RandomPart& part)
{
    GProp_GProps props;
    if (part.closed) {
        BRepGProp::VolumeProperties(part.shape, props);
    } else {
        BRepGProp::SurfaceProperties(part.shape, props);
    }
    return props.Mass();
}

/// The ranges issue 16 states, by the names the generator records them under.
void expectIssueRange(const DrawnValue& v)
{
    const std::string& n = v.name;
    const bool radius = n == "fillet_radius" || n == "fillet_radius_end" ||
                        n == "chamfer_distance" || n == "bend_radius" || n == "corner_radius" ||
                        n == "bottom_radius";
    if (radius) {
        EXPECT_GE(v.value, 1.0) << n;
        EXPECT_LE(v.value, 40.0) << n;
    }
    if (n.find("dihedral") != std::string::npos) {
        EXPECT_GE(v.value, 10.0) << n;
        EXPECT_LE(v.value, 170.0) << n;
    }
    if (n == "wall") {
        EXPECT_GE(v.value, 1.5);
        EXPECT_LE(v.value, 10.0);
    }
    if (n == "feature_gap") {
        EXPECT_GE(v.value, 2.0);
        EXPECT_LE(v.value, 30.0);
    }
    if (n == "points") {
        EXPECT_GE(v.value, 1e4);
        EXPECT_LE(v.value, 1e6);
    }
}

TEST(PartFamilies, EveryEightConsecutiveSeedsGiveEveryFamily)
{
    for (std::uint32_t start : {0u, 5u, 1000u, 1197u}) {
        std::set<PartFamily> seen;
        for (std::uint32_t s = start; s < start + 8; ++s) {
            seen.insert(partFamilyOfSeed(s));
        }
        EXPECT_EQ(seen.size(), static_cast<size_t>(partFamilyCount)) << start;
    }
    EXPECT_EQ(partFamilyOfSeed(0), PartFamily::PrismaticBlock);
    EXPECT_EQ(partFamilyOfSeed(6), PartFamily::SheetMetal);
    EXPECT_EQ(partFamilyOfSeed(1007), PartFamily::Freeform);
    EXPECT_EQ(partFamilyName(PartFamily::ThinShell), "thin_shell");
}

TEST(PartFamilies, SameSeedSamePart)
{
    for (std::uint32_t seed : {2u, 6u, 7u, 21u}) {
        const RandomPart a = makeRandomPart(seed);
        const RandomPart b = makeRandomPart(seed);
        EXPECT_EQ(a.parameters, b.parameters) << seed;
        EXPECT_EQ(a.fallbacks, b.fallbacks) << seed;
        EXPECT_EQ(countOf(a.shape, TopAbs_FACE), countOf(b.shape, TopAbs_FACE)) << seed;
        EXPECT_EQ(countOf(a.shape, TopAbs_EDGE), countOf(b.shape, TopAbs_EDGE)) << seed;
        EXPECT_DOUBLE_EQ(volumeOrArea(a), volumeOrArea(b)) << seed;
    }
    // Another seed of the same family is another part.
    EXPECT_NE(makeRandomPart(2).parameters, makeRandomPart(10).parameters);
}

TEST(PartFamilies, SeedsZeroToFifteenAreValidPartsOfEveryFamily)
{
    std::set<PartFamily> seen;
    for (std::uint32_t seed = 0; seed < 16; ++seed) {
        const RandomPart part = makeRandomPart(seed);
        SCOPED_TRACE("seed " + std::to_string(seed) + " " + part.familyName + ": " +
                     part.parameters + " [" + part.fallbacks + "]");
        seen.insert(part.family);
        EXPECT_EQ(part.family, partFamilyOfSeed(seed));
        EXPECT_EQ(part.familyName, partFamilyName(part.family));
        EXPECT_TRUE(BRepCheck_Analyzer(part.shape).IsValid());
        EXPECT_EQ(part.closed, part.family != PartFamily::SheetMetal);
        EXPECT_EQ(countOf(part.shape, TopAbs_SOLID), part.closed ? 1 : 0);
        EXPECT_GT(volumeOrArea(part), 0.0);
        EXPECT_DOUBLE_EQ(part.spacing, 1.0);
        EXPECT_DOUBLE_EQ(part.samplingRadius, 0.9);
        EXPECT_GE(part.targetPoints, 1e4);
        EXPECT_LE(part.targetPoints, 1e6);
        if (part.smallestRadius > 0.0) {
            EXPECT_GE(part.smallestRadius, 1.0);
        }
        for (const DrawnValue& v : part.drawn) {
            EXPECT_GE(v.value, v.lo) << v.name;
            EXPECT_LE(v.value, v.hi) << v.name;
            expectIssueRange(v);
        }
        // The area is sized for the point count at spacing 1 (0.7 samples per square
        // spacing); features and the sizing's rough area formulas keep it within a factor 2.
        const double expected = 0.7 * shapeArea(part.shape);
        EXPECT_GT(expected, 0.5 * part.targetPoints);
        EXPECT_LT(expected, 2.0 * part.targetPoints);
        // Typed truth: boundaries exactly on the open part, sharp edges on every part.
        TruthOptions truth;
        int counts[lineTypeCount] = {0, 0, 0};
        for (const TypedPolyline& l : truthEdges(part.shape, truth)) {
            ++counts[static_cast<int>(l.type)];
        }
        EXPECT_GT(counts[static_cast<int>(LineType::Sharp)] +
                      counts[static_cast<int>(LineType::Smooth)],
                  0);
        EXPECT_EQ(counts[static_cast<int>(LineType::Boundary)] > 0, !part.closed);
    }
    EXPECT_EQ(seen.size(), static_cast<size_t>(partFamilyCount));
}

// The hollowing of a thin shell gives its solid's edges in an order that changes from build
// to build; the edges to round are picked in an order of their geometry, so the same seed
// rounds the same edges each time. Part 165 at 50 000 points came out in three different
// shapes over eight runs when they were picked in the shape's own order.
TEST(PartFamilies, HollowedShellIsTheSamePartEveryBuild)
{
    RandomPartOptions options;
    options.points = 50000.0;
    const RandomPart first = makeRandomPart(165, options);
    ASSERT_EQ(first.familyName, "thin_shell");
    for (int build = 0; build < 5; ++build) {
        const RandomPart again = makeRandomPart(165, options);
        EXPECT_EQ(again.fallbacks, first.fallbacks) << build;
        EXPECT_EQ(countOf(again.shape, TopAbs_FACE), countOf(first.shape, TopAbs_FACE)) << build;
        EXPECT_EQ(countOf(again.shape, TopAbs_EDGE), countOf(first.shape, TopAbs_EDGE)) << build;
        EXPECT_DOUBLE_EQ(volumeOrArea(again), volumeOrArea(first)) << build;
    }
}

TEST(PartFamilies, FixedPointCountAndRanges)
{
    RandomPartOptions options;
    options.points = 30000.0;
    options.minWall = 4.0;
    options.maxWall = 4.0;
    for (std::uint32_t seed : {5u, 13u}) {
        const RandomPart part = makeRandomPart(seed, options);
        EXPECT_DOUBLE_EQ(part.targetPoints, 30000.0);
        bool wall = false;
        for (const DrawnValue& v : part.drawn) {
            if (v.name == "wall") {
                EXPECT_DOUBLE_EQ(v.value, 4.0);
                wall = true;
            }
        }
        EXPECT_TRUE(wall);
    }
}

// Fillets and chamfers of 30 spacings on a block 26 spacings high cannot be made: every try
// fails, the part keeps those edges sharp, says so, and is still a valid solid.
TEST(PartFamilies, RoundingsThatCannotBeMadeAreLeftOutAndReported)
{
    RandomPartOptions options;
    options.points = 10000.0;
    options.minRadius = 30.0;
    options.maxRadius = 30.0;
    const RandomPart part = makeRandomPart(0, options);
    ASSERT_EQ(part.family, PartFamily::PrismaticBlock);
    EXPECT_NE(part.fallbacks.find("left out (4 tries)"), std::string::npos) << part.fallbacks;
    EXPECT_TRUE(BRepCheck_Analyzer(part.shape).IsValid());
    EXPECT_EQ(countOf(part.shape, TopAbs_SOLID), 1);
    EXPECT_DOUBLE_EQ(part.smallestRadius, 0.0);
}

TEST(PartFamilies, BadOptionsThrow)
{
    RandomPartOptions options;
    options.minRadius = 0.0;
    EXPECT_THROW(makeRandomPart(0, options), std::invalid_argument);
    options = {};
    options.maxDihedralDegrees = 180.0;
    EXPECT_THROW(makeRandomPart(0, options), std::invalid_argument);
    options = {};
    options.minWall = 5.0;
    options.maxWall = 2.0;
    EXPECT_THROW(makeRandomPart(0, options), std::invalid_argument);
}

// The truth lines taken as a detector's lines score 1 on every type the part has: the check
// of the chain (sampling, truth, metric) that the accuracy benchmark runs on its own parts.
TEST(PartFamilies, TruthAsDetectorScoresOneOnEveryFamily)
{
    RandomPartOptions options;
    options.points = 15000.0;
    for (std::uint32_t seed = 16; seed < 24; ++seed) {
        const RandomPart part = makeRandomPart(seed, options);
        SCOPED_TRACE("seed " + std::to_string(seed) + " " + part.familyName);
        SamplingOptions sampling;
        sampling.radius = part.samplingRadius;
        sampling.seed = seed;
        const SampledCloud cloud = sampleShape(part.shape, sampling);
        const double spacing = meanNearestSpacing(cloud.points);
        // Built in spacings: the sampler at the part's radius gives spacing 1 and about the
        // target point count.
        EXPECT_NEAR(spacing, 1.0, 0.05);
        EXPECT_GT(cloud.points.rows(), 0.5 * options.points);
        EXPECT_LT(cloud.points.rows(), 2.0 * options.points);
        TruthOptions truthOptions;
        truthOptions.step = 0.5 * spacing;
        const auto truth = truthEdges(part.shape, truthOptions);
        LineScoreOptions scoring;
        scoring.spacing = spacing;
        const LineScore score = scoreLines(truth, truth, scoring);
        int typesPresent = 0;
        for (int t = 0; t < lineTypeCount; ++t) {
            const TypeScore& ts = score.types[static_cast<size_t>(t)];
            if (ts.truthSamples > 0) {
                ++typesPresent;
                EXPECT_DOUBLE_EQ(ts.f1, 1.0) << lineTypeName(static_cast<LineType>(t));
            }
        }
        EXPECT_GT(typesPresent, 0);
    }
}

} // namespace
} // namespace featurelines::bench
