#pragma once
// The memory a graded program's processes hold together. RLIMIT_AS caps
// each process's address space, not how many processes there are, nor the
// kernel's buffers: a program forking a few processes of a gigabyte each,
// or queueing gigabytes in socket pairs (ten thousand pairs hold about
// 3 GB), would take the machine's memory within its time limit. The grader
// measures these bytes while the program runs and stops it once they pass
// `--memory`.

#include <sys/types.h>

#include <cstdint>

namespace simcheck {

struct MemoryHeld {
    std::int64_t resident = 0;  // its processes' private resident memory (each /proc/PID/statm's resident less shared)
    std::int64_t queued = 0;    // what waits in the pipes and sockets they hold open, each counted once
    std::int64_t ipc = 0;       // its System V shared memory and message queues (`ipc_too` only)
    [[nodiscard]] std::int64_t bytes() const { return resident + queued + ipc; }
};

// The program's processes are its user's (`user` not 0), or else its
// process group `group`'s. A pipe counts a page for each byte waiting in
// it (FIONREAD), up to its capacity (F_GETPIPE_SZ), a socket the memory the kernel accounts to it (SO_MEMINFO:
// received, sent and not yet taken, queued to send), read through a copy
// of the descriptor (pidfd_getfd, Linux 5.6, with the right to trace the
// process: where that is refused, its pipes and sockets count nothing).
// Files, in /dev/shm too, are counted with the files (files_held.hpp), and
// mapped shared memory is not counted here; `ipc_too`: the System V objects
// `user` owns (a user of its own without an IPC namespace of its own;
// isolated, the namespace's limits cap them, isolation.hpp).
MemoryHeld memory_held(uid_t user, pid_t group, bool ipc_too);

}  // namespace simcheck
