#pragma once
// `simgen suite DIR`: a graded suite of scenes from tiny to large, each with
// its expected output and a manifest saying what each case exercises.

#include <cstdint>
#include <string>
#include <vector>

namespace simgen {

// The cases' names in the suite's order (case NN is the NN-th).
std::vector<std::string> suite_case_names();

// Writes NN-name.in, NN-name.out (brute-force search, one thread: the
// reference) and manifest.tsv into `directory` (created if missing): every
// case, or those named in `only` (each keeps its number).
// Throws std::runtime_error when a file cannot be written.
void write_suite(const std::string& directory, std::uint64_t seed, const std::vector<std::string>& only = {});

}  // namespace simgen
