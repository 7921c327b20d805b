#pragma once
// Standard output as a stream whose writes end at a signal. stdio resumes a
// write that a signal cut short and waits for the rest, so a process whose
// reader has stopped reading would wait there until it is killed. Under an
// MPI launcher that is what happens: mpirun stops forwarding its ranks'
// standard output when it is signalled, signals them a second later and
// kills them a second after that. Written through this stream, rank 0's
// output ends at the signal instead, and the checkpoint still gets written.

#include <cstdio>
#include <memory>

namespace simcli {

struct ClosesStream {
    void operator()(std::FILE* stream) const { std::fclose(stream); }
};
using InterruptibleOutput = std::unique_ptr<std::FILE, ClosesStream>;

// An unbuffered stream onto file descriptor 1 (which it leaves open): a write
// returns short, as a failed write, once SIGINT, SIGTERM or SIGHUP has been received
// (interrupts.hpp) and the descriptor does not take all of it. Null where the
// C library cannot make such a stream (then stdout is all there is).
InterruptibleOutput open_interruptible_standard_output();

}  // namespace simcli
