#pragma once
// How long this process's threads have waited for a CPU while ready to run:
// the sum over its threads of the kernel's run-queue delay (Linux
// /proc/self/task/<tid>/schedstat, its second field, in nanoseconds). On a
// machine whose cores the threads have to themselves it barely grows; when
// another process takes turns on their cores it grows by a good part of the
// wall time. Unlike the process's CPU time, it does not fall where the
// threads wait for each other (a serial stretch, a sleeping idle thread).

#include <optional>

namespace particlesim {

// Seconds in all since the threads started; empty where the kernel does not
// tell (no /proc, or schedstat without its delay). Allocates nothing.
std::optional<double> process_run_queue_wait_seconds();

}  // namespace particlesim
