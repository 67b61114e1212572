// SPDX-License-Identifier: LGPL-2.1-or-later
// The featurelines tool's progress line (FeatureLines/cli/Progress.h): the share, the stage and
// the time left, which is the time so far scaled by the share still to do.
#include <gtest/gtest.h>

#include <sstream>

#include "FeatureLines/cli/Progress.h"

using featurelines::cli::progressLine;
using featurelines::cli::ProgressReport;
using featurelines::cli::timeLeftText;

TEST(CliProgress, TimeLeftIsElapsedTimesShareToDoOverShareDone)
{
    // 3 s for a quarter: three quarters take 9 s more.
    EXPECT_EQ(progressLine("a.xyz", 0.25, "normals", 3.0), "a.xyz: 25% normals, about 9 s left");
    // 40 s for 40%: 60 s more, said in minutes.
    EXPECT_EQ(progressLine("a.xyz", 0.4, "sharp edges", 40.0),
              "a.xyz: 40% sharp edges, about 1 min left");
}

TEST(CliProgress, NoEstimateBeforeOneSecondOrTwoPercent)
{
    EXPECT_EQ(progressLine("a", 0.5, "s", 0.5), "a: 50% s");
    EXPECT_EQ(progressLine("a", 0.01, "s", 10.0), "a: 1% s");
    EXPECT_EQ(progressLine("a", 1.0, "s", 10.0), "a: 100% s");
}

TEST(CliProgress, TimeLeftRoundsUp)
{
    EXPECT_EQ(timeLeftText(0.2), "about 1 s left");
    EXPECT_EQ(timeLeftText(12.1), "about 13 s left");
    EXPECT_EQ(timeLeftText(61.0), "about 2 min left");
}

TEST(CliProgress, LinesModeWritesOneLinePerStageAndAClosingLine)
{
    std::ostringstream out;
    ProgressReport report(out, "c.xyz", false);
    report(0.0, "neighbours");
    report(0.1, "neighbours"); // same stage, under a second later: no line
    report(0.3, "normals");
    report(1.0, "done"); // the closing line says it
    report.finish();
    const std::string text = out.str();
    EXPECT_EQ(text.rfind("featurelines: c.xyz: 0% neighbours\n"
                         "featurelines: c.xyz: 30% normals\n"
                         "featurelines: c.xyz: done in ",
                         0),
              0u)
        << text;
    EXPECT_EQ(text.back(), '\n');
}
