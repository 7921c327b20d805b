#pragma once
// The progress of a long run on stderr: steps done, rate and time left,
// redrawn a few times a second once the run has lasted about two seconds.
// Shown on a terminal unless --quiet; forced by --progress (then, off a
// terminal, as plain lines, one every few seconds) or --progress-every
// (a line every so many seconds, the first after as many).

#include <chrono>
#include <cstdint>
#include <optional>

namespace simcli {

enum class ProgressChoice { automatic, forced, silenced };

class ProgressLine {
public:
    // `every`: the seconds between lines and before the first; none: about
    // two seconds before the first, then a few a second on a terminal or
    // one every five seconds off it.
    ProgressLine(ProgressChoice choice, std::int64_t first_step, std::int64_t last_step,
                 std::optional<double> every = std::nullopt);
    ~ProgressLine();  // clears the line on a terminal

    // After each step; cheap when nothing is due.
    void update(std::int64_t step) {
        if (enabled_ && --countdown_ <= 0) redraw(step);
    }

private:
    using Clock = std::chrono::steady_clock;
    void redraw(std::int64_t step);

    bool enabled_ = false;
    bool on_terminal_ = false;
    bool shown_ = false;
    double first_after_seconds_;
    double interval_seconds_;
    std::int64_t first_step_;
    std::int64_t last_step_;
    std::int64_t countdown_ = 1;  // steps until the clock is read again
    Clock::time_point start_;
    Clock::time_point last_drawn_;
};

}  // namespace simcli
