// SPDX-License-Identifier: LGPL-2.1-or-later
// The true edges' angle and radius (ShapeSampling.h, truthEdges), against which the lines'
// estimates are measured: the demo part's fillets have the radii it was built with (6 and
// 12 mm) and its creases are right angles; the wedge has its 30 degree knife edge and its 150
// degree shallow crease.
#include <cmath>

#include <gtest/gtest.h>

#include "CadShapes.h"
#include "ShapeSampling.h"

using namespace featurelines::bench;

TEST(TruthEdges, FilletsCarryTheirRadiusAndCreasesTheirAngle)
{
    TruthOptions options;
    options.step = 1.0;
    int six = 0, twelve = 0, sharp = 0;
    for (const TypedPolyline& e : truthEdges(makeCadShape("boss_blend").shape, options)) {
        if (e.type == LineType::Smooth) {
            EXPECT_TRUE(std::isnan(e.angle));
            const bool isSix = std::abs(e.radius - 6.0) < 1e-3;
            const bool isTwelve = std::abs(e.radius - 12.0) < 1e-3;
            EXPECT_TRUE(isSix || isTwelve) << "a fillet of radius " << e.radius;
            six += isSix ? 1 : 0;
            twelve += isTwelve ? 1 : 0;
        } else if (e.type == LineType::Sharp) {
            EXPECT_NEAR(e.angle, 90.0, 1e-3);
            EXPECT_TRUE(std::isnan(e.radius));
            ++sharp;
        }
    }
    EXPECT_GT(six, 0);
    EXPECT_GT(twelve, 0);
    EXPECT_GT(sharp, 0);
}

TEST(TruthEdges, TheWedgeHasItsKnifeEdgeAndItsShallowCrease)
{
    TruthOptions options;
    options.step = 1.0;
    bool knife = false, shallow = false;
    for (const TypedPolyline& e : truthEdges(makeCadShape("wedge").shape, options)) {
        ASSERT_EQ(e.type, LineType::Sharp);
        ASSERT_TRUE(e.angle > 0.0 && e.angle < 180.0) << e.angle;
        knife = knife || std::abs(e.angle - 30.0) < 0.01;
        shallow = shallow || std::abs(e.angle - 150.0) < 0.01;
    }
    EXPECT_TRUE(knife);
    EXPECT_TRUE(shallow);
}
