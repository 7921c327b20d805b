#pragma once
// SIGINT and SIGTERM do not kill simcli mid-write: they set a flag that the
// run checks after every step, so that it can stop cleanly (flush, write a
// checkpoint, remove an unfinished output) and exit 128 + the signal.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace simcli {

void catch_interrupts();
// The signal received (SIGINT or SIGTERM), or 0.
int pending_interrupt();

// What an interrupted run says: where it stopped, and where the output, the
// files written beside it (`side_files`: --observables, --trajectory) and
// the checkpoint (if any) leave the user.
std::string interruption_message(std::int64_t step, std::int64_t steps,
                                 const std::optional<std::string>& checkpoint_path,
                                 const std::optional<std::string>& output_path,
                                 const std::vector<std::string>& side_files = {});

}  // namespace simcli
