#pragma once
// What the command-line tests read and change in simcli's checkpoint text:
// the run's S cut short (a resumed test run then ends soon), and the step
// its first part is recorded at, and how many files it records.

#include "run_process.hpp"

#include <cstdint>
#include <fstream>
#include <string>

namespace checkpoint_text {

// Rewrites the checkpoint's S from `from` to `to`; false when its S is not `from`.
inline bool set_steps(const std::string& checkpoint, std::int64_t from, std::int64_t to) {
    std::string saved = run_process::slurp(checkpoint);
    const std::string old_steps = " steps " + std::to_string(from) + " ";
    const std::size_t at = saved.find(old_steps);
    if (at == std::string::npos) return false;
    saved.replace(at, old_steps.size(), " steps " + std::to_string(to) + " ");
    std::ofstream(checkpoint, std::ios::binary | std::ios::trunc) << saved;
    return true;
}

// The step its first part is recorded at ("first-part K"), or -1.
inline std::int64_t first_part_step(const std::string& checkpoint) {
    const std::string saved = run_process::slurp(checkpoint);
    const std::size_t at = saved.find("\nfirst-part ");
    return at == std::string::npos ? -1 : std::stoll(saved.substr(at + 12));
}

// How many files its first part records ("first-part K files N"), or -1.
inline int first_part_files(const std::string& checkpoint) {
    const std::string saved = run_process::slurp(checkpoint);
    const std::size_t at = saved.find("\nfirst-part ");
    const std::size_t files = at == std::string::npos ? at : saved.find(" files ", at);
    return files == std::string::npos ? -1 : std::stoi(saved.substr(files + 7));
}

}  // namespace checkpoint_text
