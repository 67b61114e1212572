// SPDX-License-Identifier: LGPL-2.1-or-later
// The lines file's line objects (FeatureLines/cli/LineOutput.h): every line carries "angle" and
// "blend_radius", the number where the extraction estimated one and null where it did not.
#include <gtest/gtest.h>

#include <string>

#include "FeatureLines/cli/LineOutput.h"

using featurelines::ExtractionResult;
using featurelines::FeatureLine;
using featurelines::LineType;
using featurelines::cli::lineJson;
using featurelines::cli::linesJson;

namespace {

FeatureLine lineOf(LineType type)
{
    FeatureLine l;
    l.type = type;
    l.points.resize(2, 3);
    l.points << 0, 0, 0, 1, 0, 0;
    return l;
}

bool has(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // namespace

TEST(CliLineOutput, SharpLineGivesItsAngleAndNoRadius)
{
    FeatureLine l = lineOf(LineType::Sharp);
    l.angle = 90.0;
    const std::string json = lineJson(l);
    EXPECT_TRUE(has(json, "\"angle\": 90,")) << json;
    EXPECT_TRUE(has(json, "\"blend_radius\": null,")) << json;
}

TEST(CliLineOutput, SmoothLineGivesItsRadiusAndNoAngle)
{
    FeatureLine l = lineOf(LineType::Smooth);
    l.region = 2;
    l.threshold = 0.25;
    l.blendRadius = 1.5;
    const std::string json = lineJson(l);
    EXPECT_TRUE(has(json, "\"angle\": null,")) << json;
    EXPECT_TRUE(has(json, "\"blend_radius\": 1.5,")) << json;
    EXPECT_TRUE(has(json, "\"region\": 2, \"threshold\": 0.25")) << json;
}

TEST(CliLineOutput, NotEstimatedIsNullOnEveryType)
{
    for (LineType type : {LineType::Sharp, LineType::Smooth, LineType::Boundary}) {
        const std::string json = lineJson(lineOf(type));
        EXPECT_TRUE(has(json, "\"angle\": null, \"blend_radius\": null")) << json;
    }
}

TEST(CliLineOutput, ValuesReadBackExactly)
{
    // The shortest text that reads back to the same double, as every number of the file.
    FeatureLine l = lineOf(LineType::Sharp);
    l.angle = 135.0 + 1.0 / 3.0;
    const std::string json = lineJson(l);
    const std::size_t at = json.find("\"angle\": ") + 9;
    EXPECT_EQ(std::stod(json.substr(at, json.find(',', at) - at)), l.angle) << json;
}

TEST(CliLineOutput, EveryLineOfTheResultCarriesBothKeys)
{
    ExtractionResult r;
    r.lines = {lineOf(LineType::Sharp), lineOf(LineType::Smooth), lineOf(LineType::Boundary)};
    r.lines[0].angle = 45.0;
    const std::string json = linesJson(r);
    std::size_t angles = 0, radii = 0;
    for (std::size_t at = 0; (at = json.find("\"angle\": ", at)) != std::string::npos; ++at) {
        ++angles;
    }
    for (std::size_t at = 0; (at = json.find("\"blend_radius\": ", at)) != std::string::npos;
         ++at) {
        ++radii;
    }
    EXPECT_EQ(angles, 3u);
    EXPECT_EQ(radii, 3u);
    EXPECT_TRUE(has(json, "\"angle\": 45,")) << json;
}
