#include "output_file.hpp"

#include "interrupts.hpp"

#include "particlesim/state_writer.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>

namespace simcli {

namespace {

using particlesim::OutputError;

std::string temporary_beside(const std::string& path) {
    const std::size_t slash = path.rfind('/');
    const std::string directory = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    return directory + "." + name + ".simcli-" + std::to_string(getpid()) + ".tmp";
}

[[noreturn]] void fail(const std::string& path, const char* doing) {
    throw OutputError(path + ": cannot " + doing + ": " + std::strerror(errno));
}

bool same_file(const struct stat& a, const struct stat& b) { return a.st_dev == b.st_dev && a.st_ino == b.st_ino; }

// The file that standard output or standard error is redirected to.
bool is_standard_output_or_error(const struct stat& file) {
    for (const int fd : {STDOUT_FILENO, STDERR_FILENO}) {
        struct stat standard {};
        if (fstat(fd, &standard) == 0 && same_file(standard, file)) return true;
    }
    return false;
}

// The absolute path of the file open on `fd`, where the system names it
// (Linux's /proc); nothing for a file removed since or a system without it.
std::optional<std::string> path_of_descriptor(int fd) {
    const std::string link = "/proc/self/fd/" + std::to_string(fd);
    char target[PATH_MAX];
    const ssize_t length = readlink(link.c_str(), target, sizeof target);
    if (length <= 0 || static_cast<std::size_t>(length) >= sizeof target || target[0] != '/') return std::nullopt;
    std::string path(target, static_cast<std::size_t>(length));
    struct stat named {};
    struct stat opened {};
    // A removed file's link ends in " (deleted)"; whatever it names, the name must lead to this very file.
    if (stat(path.c_str(), &named) != 0 || fstat(fd, &opened) != 0 || !same_file(named, opened)) return std::nullopt;
    return path;
}

}  // namespace

OutputFile::OutputFile(const std::optional<std::string>& path) {
    if (!path) {
        stream_ = stdout;
        return;
    }
    path_ = *path;
    struct stat existing {};
    const bool exists = stat(path_.c_str(), &existing) == 0;
    if (exists && !S_ISREG(existing.st_mode)) {
        stream_ = std::fopen(path_.c_str(), "wb");  // a device, a pipe, a terminal: in place
        if (stream_ == nullptr) fail(path_, "open for writing");
        return;
    }
    if (exists && is_standard_output_or_error(existing)) {
        // `-o /dev/stdout > out.txt`: the file the shell opened, written on
        // where it ends (as `>>` leaves it), never renamed over (that would
        // replace /dev/stdout itself, or a file the shell holds).
        stream_ = std::fopen(path_.c_str(), "ab");
        if (stream_ == nullptr) fail(path_, "open for writing");
        return;
    }
    temporary_ = temporary_beside(path_);
    const int fd =
        open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, exists ? existing.st_mode & 07777 : 0666);
    if (fd < 0) fail(path_, "create a temporary file beside it");
    listed_slot_ = list_unfinished_file(temporary_);
    if (exists) fchmod(fd, existing.st_mode & 07777);  // the umask must not narrow what the user had
    stream_ = fdopen(fd, "wb");
    if (stream_ == nullptr) {
        close(fd);
        unlink(temporary_.c_str());
        unlist_unfinished_file(listed_slot_);
        fail(path_, "open for writing");
    }
}

OutputFile::~OutputFile() {
    unlist_unfinished_file(listed_slot_);  // removed below, or renamed by commit()
    if (committed_ || stream_ == stdout || stream_ == nullptr) return;
    std::fclose(stream_);
    if (!temporary_.empty()) unlink(temporary_.c_str());
}

void OutputFile::write(std::string_view text, const char* what) {
    if (std::fwrite(text.data(), 1, text.size(), stream_) != text.size()) {
        fail(path_.empty() ? "the output" : path_, (std::string("write the ") + what).c_str());
    }
}

void OutputFile::commit() {
    if (stream_ == stdout) {
        if (std::fflush(stdout) != 0) fail("the output", "write");
        committed_ = true;
        return;
    }
    committed_ = true;
    // On disk before the rename, so that a crash cannot leave FILE empty.
    const bool written =
        std::fflush(stream_) == 0 && ((temporary_.empty() && !in_place_) || fsync(fileno(stream_)) == 0);
    const int write_error = errno;
    const bool closed = std::fclose(stream_) == 0;
    if (!written || !closed) {
        if (!temporary_.empty()) unlink(temporary_.c_str());
        errno = written ? errno : write_error;
        fail(path_, "write");
    }
    if (!temporary_.empty() && std::rename(temporary_.c_str(), path_.c_str()) != 0) {
        const int rename_error = errno;
        unlink(temporary_.c_str());
        errno = rename_error;
        fail(path_, "replace with the finished output");
    }
    unlist_unfinished_file(listed_slot_);
    listed_slot_ = -1;
}

std::optional<OutputFile::Extent> OutputFile::keep_so_far() {
    if (committed_) return std::nullopt;
    const std::string name = path_.empty() ? "the output" : path_;
    struct stat file {};
    if (std::fflush(stream_) != 0 || fstat(fileno(stream_), &file) != 0) fail(name, "write");
    if (!S_ISREG(file.st_mode)) return std::nullopt;  // a device, a pipe, the terminal
    if (fsync(fileno(stream_)) != 0) fail(name, "write");
    if (!temporary_.empty()) {
        if (std::rename(temporary_.c_str(), path_.c_str()) != 0) fail(path_, "put the output so far in place");
        temporary_.clear();  // from now on the stream writes into FILE itself
        in_place_ = true;
        unlist_unfinished_file(listed_slot_);
        listed_slot_ = -1;
        note_file_in_place();
    }
    struct stat errors {};
    // Lines of stderr in the same file (`> log 2>&1`, `-o /dev/stdout > log 2>&1`) would be cut with the output.
    if (fstat(STDERR_FILENO, &errors) == 0 && same_file(file, errors)) return std::nullopt;
    // Where the file is now; nothing when it was moved or removed since (it could not be found again). Standard
    // output redirected to a file (`> out.txt`) is found through its descriptor: the shell opened it.
    std::optional<std::string> where;
    if (path_.empty()) {
        where = path_of_descriptor(fileno(stream_));
    } else if (char absolute[PATH_MAX]; realpath(path_.c_str(), absolute) != nullptr) {
        where = absolute;
    }
    if (!where) return std::nullopt;
    return Extent{*where, static_cast<std::uint64_t>(file.st_size), static_cast<std::uint64_t>(file.st_dev),
                  static_cast<std::uint64_t>(file.st_ino)};
}

void require_can_create(const std::string& path) {
    const OutputFile probe(path);  // never committed: its temporary file is removed
}

}  // namespace simcli
