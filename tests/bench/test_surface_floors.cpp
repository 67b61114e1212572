// SPDX-License-Identifier: LGPL-2.1-or-later
// The surfaces' floors of the accuracy benchmark (--surface-floor): the totals over the parts,
// and a measure failing only past its floor.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "SurfaceScore.h"

using namespace featurelines::bench;

namespace {

SurfaceQuality part(bool solid, int trueFaces, int rightKind, double toTruth)
{
    SurfaceQuality q;
    q.solid = solid;
    q.valid = solid;
    q.trueFaces = trueFaces;
    q.rightKind = rightKind;
    q.toTruthMean = toTruth;
    return q;
}

TEST(SurfaceFloors, TotalsAddThePartsAndFailOnlyPastTheirFloor)
{
    // Two parts: 6 of 8 and 3 of 4 true faces of their kind (9 of 12), one valid solid; a third
    // without faces leaves the distance's mean alone.
    const SurfaceTotals t =
        surfaceTotals({part(true, 8, 6, 0.02), part(false, 4, 3, 0.06), part(false, 2, 0, NAN)});
    EXPECT_EQ(t.parts, 3);
    EXPECT_EQ(t.validSolids, 1);
    EXPECT_DOUBLE_EQ(t.rightKindShare(), 9.0 / 14.0);
    EXPECT_DOUBLE_EQ(t.toTruthMean, 0.04);
    EXPECT_TRUE(surfaceFloorFailures(t, parseSurfaceFloors("kinds=0.64,solids=1,truth=0.04"))
                    .empty());
    EXPECT_EQ(surfaceFloorFailures(t, parseSurfaceFloors("kinds=0.65")).size(), 1u);
    EXPECT_EQ(surfaceFloorFailures(t, parseSurfaceFloors("solids=2")).size(), 1u);
    EXPECT_EQ(surfaceFloorFailures(t, parseSurfaceFloors("truth=0.039")).size(), 1u);
    EXPECT_TRUE(surfaceFloorFailures(t, SurfaceFloors{}).empty());
    // No faces at all: every judged measure is past its floor.
    EXPECT_EQ(surfaceFloorFailures(surfaceTotals({}), parseSurfaceFloors("kinds=0,truth=1")).size(),
              2u);
    EXPECT_THROW(parseSurfaceFloors("faces=3"), std::invalid_argument);
    EXPECT_THROW(parseSurfaceFloors("kinds"), std::invalid_argument);
}

} // namespace
