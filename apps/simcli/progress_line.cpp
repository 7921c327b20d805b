#include "progress_line.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace simcli {

namespace {

constexpr double quiet_start_seconds = 2.0;
constexpr double terminal_interval_seconds = 0.25;
constexpr double plain_interval_seconds = 5.0;

// "42 s", "17 min", "3.5 h", "12 days", "2.9e+11 years": a person's units.
std::string duration_text(double seconds) {
    char text[48];
    if (seconds < 120.0) {
        std::snprintf(text, sizeof text, "%.0f s", seconds);
    } else if (seconds < 7200.0) {
        std::snprintf(text, sizeof text, "%.0f min", seconds / 60.0);
    } else if (seconds < 172800.0) {
        std::snprintf(text, sizeof text, "%.1f h", seconds / 3600.0);
    } else if (seconds < 3.16e7) {
        std::snprintf(text, sizeof text, "%.0f days", seconds / 86400.0);
    } else {
        std::snprintf(text, sizeof text, "%.3g years", seconds / 3.156e7);
    }
    return text;
}

}  // namespace

ProgressLine::ProgressLine(ProgressChoice choice, std::int64_t first_step, std::int64_t last_step,
                           std::optional<double> every)
    : on_terminal_(isatty(STDERR_FILENO) != 0),
      first_after_seconds_(every.value_or(quiet_start_seconds)),
      interval_seconds_(every.value_or(on_terminal_ ? terminal_interval_seconds : plain_interval_seconds)),
      first_step_(first_step),
      last_step_(last_step),
      start_(Clock::now()),
      last_drawn_(start_) {
    enabled_ = choice == ProgressChoice::forced || (choice == ProgressChoice::automatic && on_terminal_);
}

ProgressLine::~ProgressLine() {
    if (shown_ && on_terminal_) std::fputs("\r\033[K", stderr);
}

void ProgressLine::redraw(std::int64_t step) {
    const Clock::time_point now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double since_drawn = std::chrono::duration<double>(now - last_drawn_).count();
    const double done = static_cast<double>(step - first_step_);
    const double rate = elapsed > 0.0 ? done / elapsed : 0.0;
    // Read the clock again after about a tenth of the shortest drawing interval.
    countdown_ = std::clamp<std::int64_t>(
        static_cast<std::int64_t>(rate * 0.1 * std::min(interval_seconds_, terminal_interval_seconds)), 1, 1 << 20);
    if (elapsed < first_after_seconds_ || (shown_ && since_drawn < interval_seconds_)) return;
    last_drawn_ = now;
    shown_ = true;
    const double total = static_cast<double>(last_step_ - first_step_);
    const double left = rate > 0.0 ? (total - done) / rate : 0.0;
    std::fprintf(stderr, "%ssimcli: step %lld of %lld (%.1f %%), %.4g steps/s, about %s left%s",
                 on_terminal_ ? "\r\033[K" : "", static_cast<long long>(step), static_cast<long long>(last_step_),
                 total > 0.0 ? 100.0 * done / total : 100.0, rate, duration_text(left).c_str(),
                 on_terminal_ ? "" : "\n");
    std::fflush(stderr);
}

}  // namespace simcli
