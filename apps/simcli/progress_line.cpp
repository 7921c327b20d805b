#include "progress_line.hpp"

#include "common/duration_text.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

namespace simcli {

ProgressLine::ProgressLine(ProgressChoice choice, std::int64_t first_step, std::int64_t last_step,
                           std::optional<double> every)
    : timing_(choice, every), first_step_(first_step), last_step_(last_step) {}

ProgressLine::~ProgressLine() { timing_.clear(); }

void ProgressLine::redraw(std::int64_t step) {
    const auto now = apps_common::ProgressTiming::Clock::now();
    const double elapsed = timing_.seconds_since_start(now);
    const double done = static_cast<double>(step - first_step_);
    const double rate = elapsed > 0.0 ? done / elapsed : 0.0;
    // Read the clock again after about a tenth of the shortest drawing interval.
    const double shortest =
        std::min(timing_.interval_seconds(), apps_common::ProgressTiming::terminal_interval_seconds);
    countdown_ = std::clamp<std::int64_t>(static_cast<std::int64_t>(rate * 0.1 * shortest), 1, 1 << 20);
    if (!timing_.due(now)) return;
    const double total = static_cast<double>(last_step_ - first_step_);
    const double left = rate > 0.0 ? (total - done) / rate : 0.0;
    std::fprintf(stderr, "%ssimcli: step %lld of %lld (%.1f %%), %.4g steps/s, about %s left%s", timing_.line_start(),
                 static_cast<long long>(step), static_cast<long long>(last_step_),
                 total > 0.0 ? 100.0 * done / total : 100.0, rate, apps_common::duration_text(left).c_str(),
                 timing_.line_end());
    std::fflush(stderr);
}

}  // namespace simcli
