// SPDX-License-Identifier: LGPL-2.1-or-later
// Progress within a stage (FeatureLines/support/Progress.h): a long loop tells the share of its
// items done, rising, from the thread that runs the stages only, and a cancel from the callback
// stops the loop and the run; the extraction reports many times within one long stage.
#include <gtest/gtest.h>

#include <atomic>
#include <map>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "FeatureLines/Extraction.h"
#include "FeatureLines/support/Progress.h"
#include "SampledShapes.h"

#include <omp.h>

using namespace featurelines;

namespace {

/// `n` worker threads while it lives: only the calling thread tells the callback, so the
/// number of reports within a loop falls with the threads (about 64 / threads, and fewer
/// where a loop's dynamic schedule gives the calling thread fewer batches, as on a loaded
/// machine).
struct Threads
{
    int before = omp_get_max_threads();
    explicit Threads(int n) { omp_set_num_threads(n); }
    ~Threads() { omp_set_num_threads(before); }
};

struct Call
{
    double done;
    std::string stage;
    std::thread::id thread;
};

/// A callback that records its calls and cancels at call `cancelAt` (0: never).
ProgressCallback recorder(std::vector<Call>& calls, size_t cancelAt = 0)
{
    return [&calls, cancelAt](double done, const std::string& stage) {
        calls.push_back({done, stage, std::this_thread::get_id()});
        return cancelAt == 0 || calls.size() < cancelAt;
    };
}

/// A parallel loop over n items with progress in [0.2, 0.6] of the run, counting in `worked`
/// the items whose work ran; returns their number.
long parallelLoop(ProgressReporter& reporter, long n, std::atomic<long>& worked)
{
    LoopProgress loop(ProgressSpan(reporter, 0.2, 0.6), n);
#pragma omp parallel for schedule(static, 64)
    for (long i = 0; i < n; ++i) {
        if (!loop.next(i)) {
            continue;
        }
        ++worked;
    }
    loop.finish();
    return worked;
}

long parallelLoop(ProgressReporter& reporter, long n)
{
    std::atomic<long> worked{0};
    return parallelLoop(reporter, n, worked);
}

} // namespace

TEST(Progress, ALoopTellsRisingSharesWithinItsSpanFromTheCallingThread)
{
    const Threads threads(2);
    std::vector<Call> calls;
    ProgressReporter reporter(recorder(calls), 0.0);
    reporter.stage(0.2, "loop");
    EXPECT_EQ(parallelLoop(reporter, 64000), 64000);
    // Every 1/64 of the items: the stage's start and more than 32 shares within it.
    ASSERT_GT(calls.size(), 32u);
    for (size_t c = 1; c < calls.size(); ++c) {
        EXPECT_GT(calls[c].done, calls[c - 1].done) << c;
        EXPECT_EQ(calls[c].stage, "loop");
    }
    EXPECT_GE(calls.front().done, 0.2);
    EXPECT_LE(calls.back().done, 0.6);
    for (const Call& c : calls) {
        EXPECT_EQ(c.thread, std::this_thread::get_id());
    }
}

TEST(Progress, WithinAStageTheIntervalSpacesTheCalls)
{
    std::vector<Call> calls;
    ProgressReporter reporter(recorder(calls), 3600.0);
    reporter.stage(0.2, "loop");
    parallelLoop(reporter, 64000);
    reporter.stage(0.6, "next");
    // The stages' starts only: no share within the stage comes an hour after the last.
    ASSERT_EQ(calls.size(), 2u);
    EXPECT_EQ(calls[1].stage, "next");
}

TEST(Progress, ACancelStopsTheLoopAndThrows)
{
    const Threads threads(2);
    std::vector<Call> calls;
    ProgressReporter reporter(recorder(calls, 5), 0.0);
    reporter.stage(0.2, "loop");
    std::atomic<long> worked{0};
    const long n = 64000;
    EXPECT_THROW(parallelLoop(reporter, n, worked), ExtractionCancelled);
    EXPECT_EQ(calls.size(), 5u); // none after the cancelling one
    EXPECT_LT(worked.load(), n);
    EXPECT_TRUE(reporter.cancelled());
}

TEST(Progress, NoCallbackTellsNothingAndNeverCancels)
{
    ProgressReporter reporter;
    EXPECT_FALSE(reporter.active());
    EXPECT_EQ(parallelLoop(reporter, 1000), 1000);
    EXPECT_NO_THROW(ProgressSpan().report(0.5));
}

TEST(Progress, TheExtractionReportsManyTimesWithinItsLongStages)
{
    const shapes::Sample cube = shapes::roundedCube(40.0, 6.0, 0.5, 7);
    ExtractionOptions options;
    options.progressInterval = 0.0;
    // Two threads: every report from the calling thread, rising over the run and strictly
    // within a stage. One thread: the calling thread runs every batch of every loop, so the
    // counts per stage do not depend on how busy the machine is.
    std::vector<Call> calls;
    std::map<std::string, int> perStage;
    ExtractionResult withProgress;
    for (int threadCount : {2, 1}) {
        SCOPED_TRACE(threadCount);
        const Threads threads(threadCount);
        calls.clear();
        options.progress = recorder(calls);
        ExtractionResult result = extractFeatureLines(cube.points, options);
        if (threadCount == 2) {
            withProgress = std::move(result);
        }
        perStage.clear();
        for (size_t c = 0; c < calls.size(); ++c) {
            ++perStage[calls[c].stage];
            if (c > 0) {
                EXPECT_GE(calls[c].done, calls[c - 1].done) << calls[c].stage;
                if (calls[c].stage == calls[c - 1].stage) {
                    EXPECT_GT(calls[c].done, calls[c - 1].done) << calls[c].stage;
                }
            }
            EXPECT_EQ(calls[c].thread, std::this_thread::get_id());
        }
        EXPECT_EQ(calls.back().stage, "done");
        EXPECT_EQ(calls.back().done, 1.0);
    }
    EXPECT_GT(perStage["neighbours"], 10);
    EXPECT_GT(perStage["normals"], 10);
    EXPECT_GT(perStage["curvature of smooth region 1"], 20);

    // The reports change nothing of the result.
    const ExtractionResult without = extractFeatureLines(cube.points);
    ASSERT_EQ(withProgress.lines.size(), without.lines.size());
    for (size_t l = 0; l < without.lines.size(); ++l) {
        EXPECT_EQ(withProgress.lines[l].points, without.lines[l].points);
    }
    EXPECT_EQ(withProgress.patch, without.patch);
}

TEST(Progress, ACancelWithinAStageStopsTheExtractionThere)
{
    const Threads threads(2);
    const shapes::Sample cube = shapes::roundedCube(40.0, 6.0, 0.5, 7);
    std::vector<Call> calls;
    const std::string stage = "curvature of smooth region 1";
    int withinStage = 0;
    ExtractionOptions options;
    options.progressInterval = 0.0;
    options.progress = [&](double done, const std::string& name) {
        calls.push_back({done, name, std::this_thread::get_id()});
        // The tenth report within the stage cancels.
        return !(name == stage && ++withinStage == 10);
    };
    EXPECT_THROW(extractFeatureLines(cube.points, options), ExtractionCancelled);
    ASSERT_FALSE(calls.empty());
    EXPECT_EQ(calls.back().stage, stage); // nothing after the cancel
    EXPECT_EQ(withinStage, 10);
    EXPECT_LT(calls.back().done, 0.85); // the stage's end
}
