#pragma once
// The files simcli writes (-o or standard output, --checkpoint,
// --trajectory, --observables, --animate, --snapshot) are each a file of
// their own, none of them the scene or checkpoint it reads: two writers
// into one file leave neither's content, and a file that replaces what it
// was read from loses it. Devices and pipes (/dev/null for several) are
// not files and may be shared. A resumed run may checkpoint into the
// checkpoint it resumed: that is read whole before anything is written.

#include "cli_options.hpp"

namespace simcli {

// Throws BadInput naming the two options that name one file.
void require_distinct_files(const CliOptions& options);

}  // namespace simcli
