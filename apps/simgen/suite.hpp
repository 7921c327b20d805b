#pragma once
// `simgen suite DIR`: a graded suite of scenes from tiny to large, each with
// its expected output and a manifest saying what each case exercises.

#include <cstdint>
#include <string>

namespace simgen {

// Writes NN-name.in, NN-name.out (brute-force search, one thread: the
// reference) and manifest.tsv into `directory` (created if missing).
// Throws std::runtime_error when a file cannot be written.
void write_suite(const std::string& directory, std::uint64_t seed);

}  // namespace simgen
