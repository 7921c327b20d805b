#pragma once
// How many of its threads a step uses, when the user did not say. On a small
// scene a step takes tens of microseconds and a second thread gains little:
// on a quiet machine two threads are faster, but when the second core is
// taken by something else one thread is (docs/benchmarks.md). Which holds
// changes with the machine and over minutes, so it is measured: short
// trials that alternate blocks of steps on one thread and on all of them,
// then a longer stretch with the faster, and a trial again. Every thread
// count gives the same bytes, so only the speed depends on the choice.
//
// On a large scene two threads win by a wide margin on a quiet machine, and
// a trial's steps on one thread would cost a short run a good part of its
// time. So its steps take all the threads while the process's threads get
// a CPU as soon as they are ready to run (parallel/run_queue_wait.hpp, read
// at the start and end of each watch of steps). When they wait for one,
// another process is taking turns on their cores: a few steps on one thread
// are then timed against all the watch's steps on every thread, and the
// faster runs a stretch (all the threads only by a margin).

#include "stepped/stepped_tuning.hpp"

#include <cstdint>
#include <optional>

namespace particlesim {

enum class ThreadPolicy : std::uint8_t {
    all,                    // every step takes every thread
    trials,                 // trials from the start, and again after each stretch
    trials_when_contended,  // every thread while the threads do not wait for a CPU
};

// A trial alternates blocks of trial_block_steps on one thread and on all of
// them, the first step of each block not counted (it pays for the switch: a
// thread woken, caches filled on the other core); then trial_run_steps run
// with the faster before the next trial. Where waits for a CPU start the
// trials, the trial is contended_trial_steps on one thread, and the watching
// starts again after the stretch (stepped_tuning.hpp).
class ThreadChoice {
public:
    // `threads`: the most a step may use.
    ThreadChoice(int threads, ThreadPolicy policy)
        : most_(threads), policy_(threads > 1 ? policy : ThreadPolicy::all) {}

    // For the next step.
    [[nodiscard]] int threads() const {
        switch (stage_) {
        case Stage::trying: return on_one_thread(step_) ? 1 : most_;
        case Stage::timing_one: return 1;
        case Stage::running: return running_;
        default: return most_;
        }
    }

    // Whether the step just recorded starts or ends a watch,
    // whose run-queue wait read_waits() wants now.
    [[nodiscard]] bool reading_due() const { return reading_due_; }

    // The process's run-queue wait in all, in seconds (empty: unknown, and
    // then every step keeps every thread).
    void read_waits(std::optional<double> total_seconds) {
        reading_due_ = false;
        if (!total_seconds) {
            policy_ = ThreadPolicy::all;
            start(Stage::watching);
            return;
        }
        if (stage_ == Stage::watching && step_ > 0) {
            const bool waited =
                *total_seconds - last_wait_seconds_ > stepped_tuning::contended_wait_share * watched_seconds_;
            start(waited ? Stage::timing_one : Stage::watching);
            reading_due_ = false;  // this reading is also the next watch's start
        }
        last_wait_seconds_ = *total_seconds;
    }

    // The step just run (with threads()) took `seconds`.
    void record(double seconds) {
        if (policy_ == ThreadPolicy::all) return;
        one_thread_steps_ += threads() == 1 ? 1 : 0;
        ++step_;
        switch (stage_) {
        case Stage::warming:  // the first steps fill caches and pages: not a fair trial
            if (step_ == stepped_tuning::trial_warm_up_steps) start(after_stretch());
            break;
        case Stage::watching:
            watched_seconds_ += seconds;
            reading_due_ = step_ >= stepped_tuning::contention_watch_steps &&
                           watched_seconds_ >= stepped_tuning::contention_watch_seconds;
            break;
        case Stage::trying:
            if ((step_ - 1) % stepped_tuning::trial_block_steps != 0)
                (on_one_thread(step_ - 1) ? one_seconds_ : most_seconds_) += seconds;
            if (step_ == stepped_tuning::trial_blocks * stepped_tuning::trial_block_steps) {
                // Ties keep all the threads (the choice when nothing is measured).
                run_stretch(most_seconds_ <= one_seconds_);
            }
            break;
        case Stage::timing_one:
            if (step_ > 1) one_seconds_ += seconds;
            if (step_ == stepped_tuning::contended_trial_steps) {
                const double one_mean = one_seconds_ / (stepped_tuning::contended_trial_steps - 1);
                const double most_mean = watched_seconds_ / static_cast<double>(watched_steps_);
                run_stretch(most_mean <= stepped_tuning::contended_trial_margin * one_mean);
            }
            break;
        case Stage::running:
            if (step_ == stepped_tuning::trial_run_steps) start(after_stretch());
            break;
        }
    }

    // Steps recorded that ran on one thread.
    [[nodiscard]] std::int64_t steps_on_one_thread() const { return one_thread_steps_; }
    // Trials started.
    [[nodiscard]] std::int64_t trials() const { return trials_; }

private:
    enum class Stage : std::uint8_t { warming, watching, trying, timing_one, running };

    // Within a trial: which steps run on one thread.
    static bool on_one_thread(std::int64_t step) { return (step / stepped_tuning::trial_block_steps) % 2 == 0; }

    // What follows the warm-up and each stretch with the trial's choice.
    Stage after_stretch() const {
        return policy_ == ThreadPolicy::trials_when_contended ? Stage::watching : Stage::trying;
    }

    void run_stretch(bool every_thread) {
        running_ = every_thread ? most_ : 1;
        start(Stage::running);
    }

    void start(Stage stage) {
        if (stage == Stage::timing_one) watched_steps_ = step_;  // what the watch's mean is over
        stage_ = stage;
        step_ = 0;
        one_seconds_ = most_seconds_ = 0.0;
        trials_ += stage == Stage::trying || stage == Stage::timing_one ? 1 : 0;
        if (stage == Stage::watching) {
            watched_seconds_ = 0.0;
            // A watch starts from a reading taken now.
            reading_due_ = policy_ != ThreadPolicy::all;
        }
    }

    int most_;
    ThreadPolicy policy_;
    Stage stage_ = Stage::warming;
    std::int64_t step_ = 0;  // within the stage
    int running_ = 0;
    double one_seconds_ = 0.0;
    double most_seconds_ = 0.0;
    double watched_seconds_ = 0.0;    // the watch's steps
    std::int64_t watched_steps_ = 0;  // kept for the trial that follows it
    double last_wait_seconds_ = 0.0;  // at the watch's start
    bool reading_due_ = false;
    std::int64_t one_thread_steps_ = 0;
    std::int64_t trials_ = 0;
};

}  // namespace particlesim
