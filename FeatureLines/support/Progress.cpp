// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/support/Progress.h"

#include <algorithm>
#include <utility>

namespace featurelines {

ProgressReporter::ProgressReporter(ProgressCallback callback, double minInterval)
    : callback_(std::move(callback)), minInterval_(minInterval)
{
}

void ProgressReporter::stage(double done, const std::string& name)
{
    stage_ = name;
    if (active() && !tell(std::max(done, last_))) {
        throw ExtractionCancelled();
    }
}

bool ProgressReporter::within(double done)
{
    if (!active() || cancelled_) {
        return !cancelled_;
    }
    if (!(done > last_) ||
        std::chrono::duration<double>(Clock::now() - lastTime_).count() < minInterval_) {
        return true;
    }
    return tell(done);
}

bool ProgressReporter::tell(double done)
{
    last_ = done;
    lastTime_ = Clock::now();
    if (!callback_(done, stage_)) {
        cancelled_ = true;
    }
    return !cancelled_;
}

ProgressSpan ProgressSpan::part(double a, double b) const
{
    ProgressSpan p = *this;
    p.from_ = at(a);
    p.to_ = at(b);
    return p;
}

void ProgressSpan::report(double share) const
{
    if (reporter_ && !reporter_->within(at(std::min(1.0, std::max(0.0, share))))) {
        throw ExtractionCancelled();
    }
}

LoopProgress::LoopProgress(const ProgressSpan& span, std::int64_t count)
    : span_(span), count_(std::max<std::int64_t>(count, 1)),
      batch_(std::max<std::int64_t>(count / 64, 1)), owner_(std::this_thread::get_id())
{
}

void LoopProgress::tick()
{
    // The batch is counted as it starts: the share runs ahead by a batch per thread at most,
    // and stays under the span's end.
    const std::int64_t done = done_.fetch_add(batch_, std::memory_order_relaxed) + batch_;
    if (std::this_thread::get_id() != owner_) {
        return;
    }
    const double share = std::min(1.0, static_cast<double>(done) / static_cast<double>(count_));
    if (!span_.reporter()->within(span_.at(share))) {
        cancelled_.store(true, std::memory_order_relaxed);
    }
}

void LoopProgress::finish() const
{
    if (cancelled_.load(std::memory_order_relaxed)) {
        throw ExtractionCancelled();
    }
}

} // namespace featurelines
