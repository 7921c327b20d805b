#pragma once
// The progress of a long run on stderr: steps done, rate and time left,
// redrawn a few times a second once the run has lasted about two seconds
// (common/progress_timing.hpp: when, and the options that choose).

#include "common/progress_timing.hpp"

#include <cstdint>
#include <optional>

namespace simcli {

using apps_common::ProgressChoice;

class ProgressLine {
public:
    // `every`: the seconds between lines and before the first; none: about
    // two seconds before the first, then a few a second on a terminal or
    // one every five seconds off it.
    ProgressLine(ProgressChoice choice, std::int64_t first_step, std::int64_t last_step,
                 std::optional<double> every = std::nullopt);
    ~ProgressLine();  // clears the line on a terminal
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    // After each step; cheap when nothing is due.
    void update(std::int64_t step) {
        if (timing_.enabled() && --countdown_ <= 0) redraw(step);
    }

private:
    void redraw(std::int64_t step);

    apps_common::ProgressTiming timing_;
    std::int64_t first_step_;
    std::int64_t last_step_;
    std::int64_t countdown_ = 1;  // steps until the clock is read again
};

}  // namespace simcli
