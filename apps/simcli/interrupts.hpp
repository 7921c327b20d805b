#pragma once
// SIGINT, SIGTERM and SIGHUP do not kill simcli mid-write: they set a flag that the
// run checks after every step, so that it can stop cleanly (flush, write a
// checkpoint, remove an unfinished output) and exit 128 + the signal. A
// second signal before the run has seen the first (a step that takes too
// long to wait for) stops the process at once: it removes the unfinished
// files listed here (each output's temporary; the files they would replace
// stay as they were) and ends by the signal.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace simcli {

void catch_interrupts();
// The signal received (SIGINT, SIGTERM or SIGHUP), or 0. Once it has returned a
// signal, the run stops in order and a second signal no longer forces it.
int pending_interrupt();
// Whether a signal has been received, without marking the run as stopping.
bool interrupt_received();
// From now on a signal also ends a write blocked on a pipe or terminal
// (EINTR) instead of resuming it: for an output whose reader stops reading
// once it is signalled itself (mpirun stops forwarding its ranks' standard
// output a second before it signals them, and kills them a second later).
void let_interrupts_end_blocked_writes();

// Lists a file for a forced stop to remove; returns its slot, or -1 when the
// path is too long or eight are listed (then it stays behind).
int list_unfinished_file(const std::string& path);
void unlist_unfinished_file(int slot);
// An output was put in place early by a periodic checkpoint: a forced stop
// leaves it, and says so.
void note_file_in_place();

// What an interrupted run says: where it stopped, and where the output, the
// files written beside it (`side_files`: --observables, --trajectory) and
// the checkpoint (if any) leave the user.
std::string interruption_message(std::int64_t step, std::int64_t steps,
                                 const std::optional<std::string>& checkpoint_path,
                                 const std::optional<std::string>& output_path,
                                 const std::vector<std::string>& side_files = {});

// The same for an output on standard output that the MPI launcher forwards
// and stops forwarding when it is signalled: it may end anywhere.
std::string forwarded_output_interruption_message(std::int64_t step, std::int64_t steps,
                                                  const std::optional<std::string>& checkpoint_path);

}  // namespace simcli
