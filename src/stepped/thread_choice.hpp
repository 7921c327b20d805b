#pragma once
// How many of its threads a step uses, when the user did not say. On a small
// scene a step takes tens of microseconds and a second thread gains little:
// on a quiet machine two threads are faster, but when the second core is
// taken by something else one thread is (docs/benchmarks.md). Which holds
// changes with the machine and over minutes, so it is measured: short
// trials that alternate blocks of steps on one thread and on all of them,
// then a longer stretch with the faster, and a trial again. Every thread
// count gives the same bytes, so only the speed depends on the choice.

#include "stepped/stepped_tuning.hpp"

#include <cstdint>

namespace particlesim {

// A trial alternates blocks of trial_block_steps on one thread and on all of
// them, the first step of each block not counted (it pays for the switch: a
// thread woken, caches filled on the other core); then trial_run_steps run
// with the faster before the next trial (stepped_tuning.hpp).
class ThreadChoice {
public:
    // `threads`: the most a step may use. Without `measured`, every step uses them all.
    ThreadChoice(int threads, bool measured) : most_(threads), measured_(measured && threads > 1) {}

    // For the next step.
    [[nodiscard]] int threads() const {
        if (!measured_ || stage_ == Stage::warming) return most_;
        if (stage_ == Stage::running) return running_;
        return on_one_thread(step_) ? 1 : most_;
    }

    // The step just run (with threads()) took `seconds`.
    void record(double seconds) {
        if (!measured_) return;
        one_thread_steps_ += threads() == 1 ? 1 : 0;
        ++step_;
        switch (stage_) {
        case Stage::warming:  // the first steps fill caches and pages: not a fair trial
            if (step_ == stepped_tuning::trial_warm_up_steps) start(Stage::trying);
            break;
        case Stage::trying:
            if ((step_ - 1) % stepped_tuning::trial_block_steps != 0)
                (on_one_thread(step_ - 1) ? one_seconds_ : most_seconds_) += seconds;
            if (step_ == stepped_tuning::trial_blocks * stepped_tuning::trial_block_steps) {
                // Ties keep all the threads (the choice when nothing is measured).
                running_ = one_seconds_ < most_seconds_ ? 1 : most_;
                start(Stage::running);
            }
            break;
        case Stage::running:
            if (step_ == stepped_tuning::trial_run_steps) start(Stage::trying);
            break;
        }
    }

    // Steps recorded that ran on one thread.
    [[nodiscard]] std::int64_t steps_on_one_thread() const { return one_thread_steps_; }

private:
    enum class Stage : std::uint8_t { warming, trying, running };

    // Within a trial: which steps run on one thread.
    static bool on_one_thread(int step) { return (step / stepped_tuning::trial_block_steps) % 2 == 0; }

    void start(Stage stage) {
        stage_ = stage;
        step_ = 0;
        one_seconds_ = 0.0;
        most_seconds_ = 0.0;
    }

    int most_;
    bool measured_;
    Stage stage_ = Stage::warming;
    int step_ = 0;  // within the stage
    int running_ = 0;
    double one_seconds_ = 0.0;
    double most_seconds_ = 0.0;
    std::int64_t one_thread_steps_ = 0;
};

}  // namespace particlesim
