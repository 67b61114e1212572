// SPDX-License-Identifier: LGPL-2.1-or-later
// requireSurfaceCloud: the check extract makes, shared with the curvature tools, refuses what
// the extraction refuses with the same message and lets through what it reads.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "FeatureLines/Extraction.h"
#include "SampledShapes.h"

using namespace featurelines;

namespace {

std::string refusal(const PointMatrix& P, int k)
{
    try {
        requireSurfaceCloud(P, k);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

std::string extractionRefusal(const PointMatrix& P, int k)
{
    ExtractionOptions options;
    options.neighbours.k = k;
    try {
        extractFeatureLines(P, options);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(RequireSurfaceCloud, RefusesWhatTheExtractionRefusesWithItsMessage)
{
    const PointMatrix duplicates = PointMatrix::Ones(40, 3);
    EXPECT_EQ(refusal(duplicates, 16),
              "point cloud: 1 distinct points (39 duplicates merged); at least 17 are needed "
              "for 16 neighbours per point");
    EXPECT_EQ(refusal(duplicates, 16), extractionRefusal(duplicates, 16));

    PointMatrix line(40, 3);
    for (int i = 0; i < 40; ++i) {
        line.row(i) << i, 0.0, 0.0;
    }
    EXPECT_NE(refusal(line, 16).find("the points lie on a line"), std::string::npos);
    EXPECT_EQ(refusal(line, 16), extractionRefusal(line, 16));

    // A sampled plane: a surface with enough points for 16 neighbours, not for as many
    // neighbours as it has points.
    const PointMatrix plane = shapes::plane(5.0, 0.5, 1).points;
    EXPECT_EQ(refusal(plane, 16), "");
    EXPECT_NE(refusal(plane, static_cast<int>(plane.rows())).find("at least"), std::string::npos);
}
