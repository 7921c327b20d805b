#pragma once
// A long compression's progress on stderr (simgen compressed): the area
// fraction the growing disks fill and the time so far, redrawn a few times a
// second once it has lasted about two seconds (common/progress_timing.hpp:
// when, and the options that choose). No time left is guessed: growth slows
// as the disks near a jam.

#include "common/progress_timing.hpp"

#include <optional>

namespace simgen {

class CompressionProgress {
public:
    CompressionProgress(apps_common::ProgressChoice choice, std::optional<double> every) : timing_(choice, every) {}
    ~CompressionProgress() { timing_.clear(); }
    CompressionProgress(const CompressionProgress&) = delete;
    CompressionProgress& operator=(const CompressionProgress&) = delete;

    [[nodiscard]] bool enabled() const { return timing_.enabled(); }
    // The area fraction reached and the one grown to; cheap to call every
    // few thousand events.
    void update(double reached, double target);

private:
    apps_common::ProgressTiming timing_;
};

}  // namespace simgen
