#pragma once
// When the apps' progress lines on stderr are due, and how they are drawn:
// quiet for about two seconds, then a few lines a second on a terminal (each
// drawn over the last) or one every five seconds off it. --progress forces
// them off a terminal, --quiet silences them, and --progress-every draws one
// every so many seconds, the first after as many.

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <optional>

namespace apps_common {

enum class ProgressChoice { automatic, forced, silenced };

// --progress-every's range: a millisecond to a year.
inline bool is_progress_interval(double seconds) { return seconds >= 0.001 && seconds <= 3.2e7; }

// Why --progress, --quiet and --progress-every cannot be given together, or
// nullptr where they can.
inline const char* progress_contradiction(bool progress, bool quiet, bool every) {
    if (quiet && progress) return "--progress and --quiet contradict each other";
    if (quiet && every) return "--progress-every and --quiet contradict each other";
    return nullptr;
}

// What they choose together (progress_contradiction() first).
inline ProgressChoice progress_choice(bool progress, bool quiet, bool every) {
    if (quiet) return ProgressChoice::silenced;
    return progress || every ? ProgressChoice::forced : ProgressChoice::automatic;
}

class ProgressTiming {
public:
    using Clock = std::chrono::steady_clock;
    static constexpr double quiet_start_seconds = 2.0;
    static constexpr double terminal_interval_seconds = 0.25;
    static constexpr double plain_interval_seconds = 5.0;

    // `every`: the seconds between lines and before the first.
    ProgressTiming(ProgressChoice choice, std::optional<double> every)
        : on_terminal_(isatty(STDERR_FILENO) != 0),
          first_after_seconds_(every.value_or(quiet_start_seconds)),
          interval_seconds_(every.value_or(on_terminal_ ? terminal_interval_seconds : plain_interval_seconds)),
          start_(Clock::now()),
          last_drawn_(start_) {
        enabled_ = choice == ProgressChoice::forced || (choice == ProgressChoice::automatic && on_terminal_);
    }

    [[nodiscard]] bool enabled() const { return enabled_; }
    [[nodiscard]] double interval_seconds() const { return interval_seconds_; }
    [[nodiscard]] double seconds_since_start(Clock::time_point now) const {
        return std::chrono::duration<double>(now - start_).count();
    }
    // Whether a line is due at `now`; if it is, it counts as drawn.
    bool due(Clock::time_point now) {
        const double since_drawn = std::chrono::duration<double>(now - last_drawn_).count();
        if (seconds_since_start(now) < first_after_seconds_ || (shown_ && since_drawn < interval_seconds_))
            return false;
        last_drawn_ = now;
        shown_ = true;
        return true;
    }
    // What a line begins and ends with: over the last one on a terminal, a line of its own off it.
    [[nodiscard]] const char* line_start() const { return on_terminal_ ? "\r\033[K" : ""; }
    [[nodiscard]] const char* line_end() const { return on_terminal_ ? "" : "\n"; }
    // Takes a line drawn on a terminal away again.
    void clear() {
        if (shown_ && on_terminal_) std::fputs(line_start(), stderr);
        shown_ = false;
    }

private:
    bool enabled_ = false;
    bool on_terminal_ = false;
    bool shown_ = false;
    double first_after_seconds_;
    double interval_seconds_;
    Clock::time_point start_;
    Clock::time_point last_drawn_;
};

}  // namespace apps_common
