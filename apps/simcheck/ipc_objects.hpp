#pragma once
// System V shared memory segments, semaphore sets and message queues
// outlive the process that made them: a graded program could leave
// gigabytes of shared memory behind, run after run, that no limit of its
// own counts (RLIMIT_AS only bounds what it maps). Where it runs isolated,
// an IPC namespace of its own (isolation.hpp) takes them with its last
// process; run as a user of its own without namespaces, they are found by
// their owner and removed here when its run ends.

#include <sys/types.h>

#include <cstdint>

namespace simcheck {

// Removes every System V IPC object (shared memory segment, semaphore set,
// message queue) that `user` owns or made, as /proc/sysvipc lists them.
// Returns how many.
int remove_ipc_objects_of(uid_t user);

// The memory `user`'s shared memory segments (resident or swapped out)
// and message queues (their messages) hold now.
std::int64_t ipc_bytes_of(uid_t user);

}  // namespace simcheck
