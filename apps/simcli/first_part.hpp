#pragma once
// A resumed run's first part: the files the run before it wrote, as its
// checkpoint recorded them. A run killed outright after a periodic
// checkpoint (SIGKILL, a lost node) wrote on past it; these files are cut
// back to the checkpoint's step, so that the first part and the resumed one
// join as the uninterrupted run's files.

#include "checkpoint.hpp"
#include "output_file.hpp"

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>

namespace simcli {

// Adds a file's extent at the checkpoint to `part` (nothing for stdout or a device).
void record_kept_file(FirstPart& part, const char* kind, const std::optional<OutputFile::Extent>& extent);

// A checkpoint's first part is recorded at its engine's step (there is none
// in the first format). Throws std::invalid_argument otherwise.
void require_first_part_at(const FirstPart& part, std::int64_t state_step);

// An output the resumed run would write, named by its option.
struct ResumedOutput {
    const char* option;  // "-o", "--trajectory" or "--observables"
    const std::optional<std::string>& path;
};

// A resumed run writes its files anew (renamed into place at the end), so
// one that names a file of the first part would replace that part with the
// rest alone. Throws std::invalid_argument naming it.
void refuse_writing_over_first_part(const FirstPart& part, std::initializer_list<ResumedOutput> outputs);

// Cuts each recorded file back to its length at the checkpoint, saying so on
// stderr. Only the very file recorded (the same path, device and inode), only
// when it is longer and the cut falls after a line's end; a file that was
// moved, replaced or shortened since is left alone (the last with a warning).
void cut_back_first_part(const FirstPart& part);

}  // namespace simcli
