// SPDX-License-Identifier: LGPL-2.1-or-later
// Random CAD parts for a benchmark that cannot be tuned to its parts (issue 16): one seed, one
// part, from eight families whose every dimension is drawn within stated ranges
// (docs/ACCURACY.md, "Random parts"). Lengths are in point spacings: the part is built in
// units where the intended mean point spacing is 1.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>

namespace featurelines::bench {

enum class PartFamily
{
    PrismaticBlock = 0, ///< block with pockets, slots, a step, through and blind holes
    Bracket = 1,        ///< L- or U-bracket with holes in its base
    RibbedPlate = 2,    ///< plate with drafted ribs and grooves on top
    BossPlate = 3,      ///< plate with bosses, counterbores and countersinks
    Revolved = 4,       ///< shaft with shoulders, grooves, cones and a bore
    ThinShell = 5,      ///< hollowed tray with thin walls, holes in a wall
    SheetMetal = 6,     ///< open shell: flanges joined by bends, holes (no solid)
    Freeform = 7        ///< extruded or lofted B-spline profile with tangent joins
};
constexpr int partFamilyCount = 8;

/// "prismatic_block", "bracket", "ribbed_plate", "boss_plate", "revolved", "thin_shell",
/// "sheet_metal" or "freeform".
std::string partFamilyName(PartFamily family);

/// The family a seed builds: seed % 8, so any 8 consecutive seeds give every family once.
PartFamily partFamilyOfSeed(std::uint32_t seed);

struct RandomPartOptions
{
    /// Target point count; 0 draws it log-uniformly in [minPoints, maxPoints].
    double points = 0.0;
    double minPoints = 1e4;
    double maxPoints = 1e6;
    /// Poisson-disk radius (ShapeSampling.h) per intended spacing: the sampler's mean spacing
    /// comes out 1.11 r on these parts, so r = 0.9 gives spacing 1.
    double radiusPerSpacing = 0.9;
    /// Samples per square spacing the part's area is sized for: the sampler's 0.57 / r^2 at
    /// r = radiusPerSpacing.
    double pointsPerSquareSpacing = 0.7;
    /// Fillet radii, chamfer distances and sheet-metal bend radii (spacings), drawn
    /// log-uniformly in [min, max], the max lowered where the family's features are smaller.
    double minRadius = 1.0;
    double maxRadius = 40.0;
    /// Edges rounded or chamfered per part: between 1 and this many, picked at random among
    /// the sharp edges.
    int maxRoundedEdges = 6;
    /// Only edges whose faces' normals differ by at least this (degrees) are picked: tangent
    /// joins (fillet borders, the freeform's B-spline joins) cannot be rounded.
    double minCreaseDegrees = 5.0;
    /// Probability that a picked edge is chamfered rather than filleted.
    double chamferShare = 0.3;
    /// Probability that a fillet's radius varies linearly along its edge.
    double variableFilletShare = 0.3;
    /// Attempts per rounding step: the drawn sizes, then halved, then half the edges (a
    /// quarter, ...), the last try each edge alone at minRadius; when all fail the part keeps
    /// those edges sharp (reported in RandomPart::fallbacks).
    int roundingTries = 4;
    /// Dihedral angles drawn for slanted faces, bends and drafts (degrees).
    double minDihedralDegrees = 10.0;
    double maxDihedralDegrees = 170.0;
    /// Wall thickness of the thin-shell family (spacings).
    double minWall = 1.5;
    double maxWall = 10.0;
    /// Smallest radius step between neighbouring shaft sections of the revolved family
    /// (spacings): closer radii are pushed apart to it.
    double minShoulder = 2.0;
    /// Gap between neighbouring ribs or grooves of the ribbed plate (spacings).
    double minRibGap = 2.0;
    double maxRibGap = 30.0;
};

/// One drawn number, with the range it was drawn from (lo = hi for a derived value).
struct DrawnValue
{
    std::string name;
    double value = 0.0;
    double lo = 0.0;
    double hi = 0.0;
};

struct RandomPart
{
    std::uint32_t seed = 0;
    PartFamily family = PartFamily::PrismaticBlock;
    std::string familyName;
    /// Every drawn number in draw order, and the same as "name=value" words for reports.
    std::vector<DrawnValue> drawn;
    std::string parameters;
    /// A solid, or an open shell (sheet metal), in spacings.
    TopoDS_Shape shape;
    bool closed = true;
    /// Smallest fillet or bend radius on the part (spacings), 0 without one.
    double smallestRadius = 0.0;
    /// The mean point spacing the part is sized for (model units): 1.
    double spacing = 1.0;
    /// The Poisson-disk radius that samples the part at that spacing (spacing times
    /// options.radiusPerSpacing).
    double samplingRadius = 0.9;
    /// The point count the part's area was sized for.
    double targetPoints = 0.0;
    /// Steps that failed and were left out (a feature, a rounding), empty when none.
    std::string fallbacks;
};

/// Builds the part of `seed`: the family from partFamilyOfSeed, then through one
/// std::mt19937 seeded with `seed` the point count and every dimension. Same seed and
/// options, same part. OpenCASCADE failures on a drawn combination are retried smaller or
/// left out (RandomPart::fallbacks); every returned shape passes BRepCheck_Analyzer. Throws
/// std::invalid_argument for inconsistent options and std::runtime_error when not even the
/// family's plain body can be built.
RandomPart makeRandomPart(std::uint32_t seed, const RandomPartOptions& options = {});

} // namespace featurelines::bench
