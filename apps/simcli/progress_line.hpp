#pragma once
// The progress of a long run on stderr: steps done, rate and time left,
// redrawn a few times a second once the run has lasted about two seconds.
// Shown on a terminal unless --quiet; forced by --progress (then, off a
// terminal, as plain lines, one every few seconds).

#include <chrono>
#include <cstdint>

namespace simcli {

enum class ProgressChoice { automatic, forced, silenced };

class ProgressLine {
public:
    ProgressLine(ProgressChoice choice, std::int64_t first_step, std::int64_t last_step);
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
    std::int64_t first_step_;
    std::int64_t last_step_;
    std::int64_t countdown_ = 1;  // steps until the clock is read again
    Clock::time_point start_;
    Clock::time_point last_drawn_;
};

}  // namespace simcli
