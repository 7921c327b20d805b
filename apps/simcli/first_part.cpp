#include "first_part.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <stdexcept>
#include <string>

namespace simcli {

namespace {

void cut_back(const KeptFile& file, std::int64_t step) {
    // Opened without following a link and checked on the descriptor: what is
    // cut is the file that was checked.
    const int fd = open(file.path.c_str(), O_RDWR | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return;  // moved or removed since: nothing to do
    struct stat now {};
    const bool same = fstat(fd, &now) == 0 && S_ISREG(now.st_mode) &&
                      static_cast<std::uint64_t>(now.st_dev) == file.device &&
                      static_cast<std::uint64_t>(now.st_ino) == file.inode;
    const auto size = static_cast<std::uint64_t>(now.st_size);
    if (same && size < file.bytes) {
        // `simcli --resume CK > FILE` has the shell empty FILE before simcli starts.
        struct stat output {};
        const bool is_stdout =
            fstat(STDOUT_FILENO, &output) == 0 && output.st_dev == now.st_dev && output.st_ino == now.st_ino;
        std::fprintf(stderr,
                     "simcli: warning: %s is shorter than at the checkpoint's step %lld (%llu bytes, not %llu)%s\n",
                     file.path.c_str(), static_cast<long long>(step), static_cast<unsigned long long>(size),
                     static_cast<unsigned long long>(file.bytes),
                     is_stdout ? ": standard output was redirected to it with > (which empties it), not >>" : "");
    } else if (same && size > file.bytes) {
        char last = '\n';
        const bool at_line_end =
            file.bytes == 0 || (pread(fd, &last, 1, static_cast<off_t>(file.bytes - 1)) == 1 && last == '\n');
        if (at_line_end && ftruncate(fd, static_cast<off_t>(file.bytes)) == 0 && fsync(fd) == 0) {
            std::fprintf(stderr, "simcli: %s cut back to the checkpoint's step %lld (%llu bytes written after it)\n",
                         file.path.c_str(), static_cast<long long>(step),
                         static_cast<unsigned long long>(size - file.bytes));
        } else {
            std::fprintf(stderr, "simcli: warning: could not cut %s back to the checkpoint's step %lld\n",
                         file.path.c_str(), static_cast<long long>(step));
        }
    }
    close(fd);
}

}  // namespace

void record_kept_file(FirstPart& part, const char* kind, const std::optional<OutputFile::Extent>& extent) {
    if (extent) part.files.push_back({kind, extent->path, extent->bytes, extent->device, extent->inode});
}

void require_first_part_at(const FirstPart& part, std::int64_t state_step) {
    if (part.recorded && part.step != state_step) {
        throw std::invalid_argument("not a checkpoint simcli can resume (its files are recorded at step " +
                                    std::to_string(part.step) + ", its state at step " + std::to_string(state_step) +
                                    ")");
    }
}

void refuse_writing_over_first_part(const FirstPart& part, std::initializer_list<ResumedOutput> outputs) {
    for (const ResumedOutput& output : outputs) {
        struct stat named {};
        // The name itself (lstat): a link is what a rename would replace, not the file it leads to.
        if (!output.path || lstat(output.path->c_str(), &named) != 0) continue;
        for (const KeptFile& file : part.files) {
            if (static_cast<std::uint64_t>(named.st_dev) == file.device &&
                static_cast<std::uint64_t>(named.st_ino) == file.inode) {
                throw std::invalid_argument(std::string(output.option) + " " + *output.path +
                                            " holds the first part of the run, up to step " +
                                            std::to_string(part.step) +
                                            ", and the resumed run would replace it with the rest: write the rest "
                                            "to another file and join the two");
            }
        }
    }
}

void cut_back_first_part(const FirstPart& part) {
    for (const KeptFile& file : part.files) cut_back(file, part.step);
}

}  // namespace simcli
