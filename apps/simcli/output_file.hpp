#pragma once
// Where simcli writes its states. A regular file (or a new path) is written
// to a temporary file beside it and renamed over it only by commit(): a run
// that fails or is interrupted never leaves a truncated FILE, and an old FILE
// stays as it was. Anything else (stdout, /dev/null, a pipe, a terminal) is
// written directly: a rename must never replace a device.
//
// With periodic checkpoints, keep_so_far() puts FILE in place early, at the
// first checkpoint, and writing goes on into it: a run killed outright
// after a checkpoint (SIGKILL, a lost node) leaves FILE holding at least
// every step up to that checkpoint, which records where they end. Standard
// output redirected to a file of its own (`> out.txt`) is recorded the same
// way; the shell opened it, so it is never renamed.

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

namespace simcli {

class OutputFile {
public:
    // stdout when `path` is empty. Throws particlesim::OutputError.
    explicit OutputFile(const std::optional<std::string>& path);
    ~OutputFile();  // without commit(): closes and removes the temporary file
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    [[nodiscard]] std::FILE* stream() const { return stream_; }
    // The path it writes, as given (empty for stdout).
    [[nodiscard]] const std::string& path() const { return path_; }
    // Writes all of `text`; throws particlesim::OutputError naming the file and `what` it holds.
    void write(std::string_view text, const char* what);
    // Closes the output and puts it in place. Throws particlesim::OutputError.
    void commit();

    // Where a regular file's output ends now, on disk, and which file holds
    // it (the path made absolute, the device and inode).
    struct Extent {
        std::string path;
        std::uint64_t bytes = 0;
        std::uint64_t device = 0;
        std::uint64_t inode = 0;
    };
    // Flushes the output to disk and puts FILE in place (once); writing goes
    // on into it. Nothing for a device, a pipe or the terminal, nor for
    // stdout shared with stderr. Throws particlesim::OutputError.
    std::optional<Extent> keep_so_far();

private:
    std::FILE* stream_ = nullptr;
    std::string path_;       // empty for stdout
    std::string temporary_;  // empty when written directly
    int listed_slot_ = -1;   // the temporary's slot among the files a forced stop removes (interrupts.hpp)
    bool in_place_ = false;  // put in place by keep_so_far(), written on there
    bool committed_ = false;
};

// Makes and removes what writing FILE would make first (its temporary file
// beside it), so that a file written late in a run, a checkpoint hours in,
// fails before the run instead. Throws particlesim::OutputError.
void require_can_create(const std::string& path);

}  // namespace simcli
