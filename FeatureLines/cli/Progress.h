// SPDX-License-Identifier: LGPL-2.1-or-later
// The featurelines tool's progress on standard error: the share done, the stage and the time
// left. Shown when standard error is a terminal (one line rewritten in place) or with
// --progress (a line when the stage changes, and every second within one, --progress-every);
// never with --quiet. The core reports within its long stages (support/Progress.h), so the
// share and the time left move within a stage too.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <string>
#include <utility>

namespace featurelines::cli {

/// "about 12 s left" / "about 3 min left" for `seconds`, rounded up to a whole unit.
inline std::string timeLeftText(double seconds)
{
    if (seconds < 60.0) {
        return "about " + std::to_string(std::max(1L, std::lround(std::ceil(seconds)))) + " s left";
    }
    return "about " + std::to_string(std::lround(std::ceil(seconds / 60.0))) + " min left";
}

/// The seconds still to go when `share` (0..1) of the work took `elapsedSeconds`: the time so
/// far scaled by the share still to do. NaN until a second has passed and 2% are done, before
/// which the rate says nothing, and once all is done. (The task panel shows it too.)
inline double secondsLeft(double share, double elapsedSeconds)
{
    if (!(share >= 0.02 && share < 1.0 && elapsedSeconds >= 1.0)) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    return elapsedSeconds * (1.0 - share) / share;
}

/// "NAME: 40% sharp edges, about 12 s left" (secondsLeft; no time before it is known).
inline std::string progressLine(const std::string& name, double done, const std::string& stage,
                                double elapsedSeconds)
{
    const double share = std::min(1.0, std::max(0.0, done));
    std::string line =
        name + ": " + std::to_string(static_cast<int>(std::floor(100.0 * share))) + "% " + stage;
    const double left = secondsLeft(share, elapsedSeconds);
    if (std::isfinite(left)) {
        line += ", " + timeLeftText(left);
    }
    return line;
}

/// The progress callback of one input's extraction (ExtractionOptions::progress).
class ProgressReport
{
public:
    using Clock = std::chrono::steady_clock;

    /// `terminal`: rewrite one line in place (carriage return), at most ten times a second;
    /// else write a line when the stage changes or `lineInterval` seconds after the last one.
    ProgressReport(std::ostream& out, std::string name, bool terminal, double lineInterval = 1.0)
        : out_(out), name_(std::move(name)), terminal_(terminal), lineInterval_(lineInterval),
          start_(Clock::now())
    {
    }

    bool operator()(double done, const std::string& stage)
    {
        if (done >= 1.0) {
            return true; // finish() writes the last line, with the time taken
        }
        const Clock::time_point now = Clock::now();
        const double sinceLast = std::chrono::duration<double>(now - last_).count();
        const bool stageChanged = stage != stage_;
        if (written_ &&
            !(terminal_ ? sinceLast >= 0.1 : stageChanged || sinceLast >= lineInterval_)) {
            return true;
        }
        show(progressLine("featurelines: " + name_, done, stage, seconds(now)));
        last_ = now;
        stage_ = stage;
        return true;
    }

    /// The last line: "NAME: done in 2.3 s" (the terminal's line ended).
    void finish()
    {
        char text[32];
        std::snprintf(text, sizeof text, "%.1f", seconds(Clock::now()));
        show("featurelines: " + name_ + ": done in " + text + " s");
        if (terminal_) {
            out_ << '\n';
        }
        out_.flush();
    }

    /// Ends the terminal's line before an error message is written under it.
    void abandon()
    {
        if (terminal_ && written_) {
            out_ << '\n';
            out_.flush();
        }
    }

private:
    double seconds(Clock::time_point now) const
    {
        return std::chrono::duration<double>(now - start_).count();
    }

    void show(const std::string& line)
    {
        if (terminal_) {
            // Spaces cover the rest of a longer previous line.
            const std::size_t pad = width_ > line.size() ? width_ - line.size() : 0;
            out_ << '\r' << line << std::string(pad, ' ');
            width_ = line.size();
        } else {
            out_ << line << '\n';
        }
        out_.flush();
        written_ = true;
    }

    std::ostream& out_;
    std::string name_;
    bool terminal_;
    double lineInterval_;
    Clock::time_point start_;
    Clock::time_point last_{};
    std::string stage_;
    std::size_t width_ = 0;
    bool written_ = false;
};

} // namespace featurelines::cli
