#pragma once
// A file of the suite appears whole or not at all: it is written beside its
// path as PATH.partial and renamed over PATH once closed, so that a simgen
// stopped halfway (Ctrl-C, a job's time limit) never leaves a truncated
// expected output for the grader to trust, and an old file stays as it was.
// SIGINT, SIGTERM and SIGHUP remove the partial file before simgen ends as
// the signal asks.

#include <cstdio>
#include <functional>
#include <string>

namespace simgen {

// Calls `write` on the open PATH.partial, then puts it in place. Throws
// std::runtime_error naming PATH where it cannot be written.
void write_whole_file(const std::string& path, const std::function<void(std::FILE*)>& write);

}  // namespace simgen
