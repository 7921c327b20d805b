#pragma once
// Files a graded program has no business reading, hidden from it where it
// runs isolated (isolation.hpp). Run by root, a program keeps the right to
// read every file (own_user.hpp), so that one under /root still runs: it
// could otherwise read /etc/shadow, the machine's SSH host keys or root's
// private keys and print them into its output, which the reports carry.
// Run by another user, it could read that user's own.

#include <filesystem>
#include <string>
#include <vector>

namespace simcheck {

// The entries that others may not read (no o+r) in /etc, /etc/ssh and
// /etc/ssl (its private keys), in
// root's and the grader's home directories, and in each home under /home
// (a home that others may not read, whole): files and directories, but
// none that holds, or is, one of `needed` (the program, the suite, the
// reference, the directories the runs use).
std::vector<std::string> private_entries(const std::vector<std::string>& needed);

// Whether `path` is `directory` or lies below it, both resolved: whether
// hiding `directory` would hide `path`.
bool lies_within(const std::filesystem::path& path, const std::filesystem::path& directory);

}  // namespace simcheck
