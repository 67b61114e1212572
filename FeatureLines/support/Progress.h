// SPDX-License-Identifier: LGPL-2.1-or-later
// Progress of a long run told to one callback, which may cancel it: each stage owns a span of
// the run's share (0..1), and the long loops within a stage report the share of their items
// done, so that the share rises within a stage too. Design: docs/design/pipeline.md,
// "Progress".
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>

namespace featurelines {

/// Called with the share of the whole run done (0..1) and the stage's name; returning false
/// cancels the run (ExtractionCancelled is thrown).
using ProgressCallback = std::function<bool(double, const std::string&)>;

struct ExtractionCancelled : std::runtime_error
{
    ExtractionCancelled() : std::runtime_error("the feature line extraction was cancelled") {}
};

/// The callback of one run and what it was last told. A stage's start is always told; within a
/// stage a share is told only when it is higher than the last one told and at least
/// `minInterval` seconds after it. Used by the thread that runs the stages only.
class ProgressReporter
{
public:
    /// An empty callback: nothing is told and nothing cancels.
    explicit ProgressReporter(ProgressCallback callback = {}, double minInterval = 0.2);

    bool active() const { return static_cast<bool>(callback_); }

    /// A stage starts at `done`: told at once. Throws ExtractionCancelled when the callback
    /// cancels.
    void stage(double done, const std::string& name);

    /// `done` within the current stage: false when the callback cancels (then, and after, the
    /// run is cancelled).
    bool within(double done);

    bool cancelled() const { return cancelled_; }

private:
    using Clock = std::chrono::steady_clock;
    bool tell(double done);

    ProgressCallback callback_;
    double minInterval_;
    std::string stage_;
    double last_ = -1.0;
    Clock::time_point lastTime_{};
    bool cancelled_ = false;
};

/// The stretch [from, to] of a run's share that one step owns. A default one tells nothing.
class ProgressSpan
{
public:
    ProgressSpan() = default;
    ProgressSpan(ProgressReporter& reporter, double from, double to)
        : reporter_(reporter.active() ? &reporter : nullptr), from_(from), to_(to)
    {
    }

    bool active() const { return reporter_ != nullptr; }

    /// The part [a, b] (shares of this span, 0 <= a <= b <= 1) of this span.
    ProgressSpan part(double a, double b) const;

    /// `share` (0..1) of this span done, from the thread that runs the stages, outside a
    /// parallel region. Throws ExtractionCancelled when the callback cancels.
    void report(double share) const;

    /// The run's share at `share` of this span.
    double at(double share) const { return from_ + share * (to_ - from_); }

    ProgressReporter* reporter() const { return reporter_; }

private:
    ProgressReporter* reporter_ = nullptr;
    double from_ = 0.0;
    double to_ = 1.0;
};

/// The progress of one loop over `count` items, parallel (OpenMP, any schedule) or not: every
/// thread counts its items in batches of about 1/64 of them (an atomic counter), and only the
/// thread that made this object (the one running the stages) tells the span, so the callback
/// never runs on a worker thread. A cancel makes next() false on every thread: the loop skips
/// its remaining items and finish() throws.
///
///     LoopProgress loop(span, n);
///     #pragma omp parallel for
///     for (i = 0; i < n; ++i) { if (!loop.next(i)) continue; ... }
///     loop.finish();
class LoopProgress
{
public:
    LoopProgress(const ProgressSpan& span, std::int64_t count);

    /// Once per item i (0 <= i < count), before its work: false once the run is cancelled.
    bool next(std::int64_t i)
    {
        if (!span_.active()) {
            return true;
        }
        if (cancelled_.load(std::memory_order_relaxed)) {
            return false;
        }
        if (i % batch_ == 0) {
            tick();
        }
        return true;
    }

    /// After the loop, on the thread that made this object: throws ExtractionCancelled when
    /// the run was cancelled during it.
    void finish() const;

private:
    void tick();

    ProgressSpan span_;
    std::int64_t count_;
    std::int64_t batch_;
    std::thread::id owner_;
    std::atomic<std::int64_t> done_{0};
    std::atomic<bool> cancelled_{false};
};

} // namespace featurelines
