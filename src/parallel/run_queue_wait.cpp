#include "parallel/run_queue_wait.hpp"

#include <cstdint>

#if defined(__linux__)
#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstddef>
#include <cstdlib>
#include <cstring>
#endif

namespace particlesim {

#if defined(__linux__)

namespace {

// The tasks read at most: a host program's thousands of threads would make
// each reading cost more than the steps it watches.
constexpr int most_tasks_read = 256;

class FileDescriptor {
public:
    explicit FileDescriptor(int descriptor) : descriptor_(descriptor) {}
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor() {
        if (descriptor_ >= 0) close(descriptor_);
    }
    int get() const { return descriptor_; }

private:
    int descriptor_;
};

// The second number of "<run ns> <wait ns> <slices>\n", from a file in `directory`.
std::optional<std::uint64_t> read_wait_nanoseconds(int directory, const char* path) {
    const FileDescriptor file(openat(directory, path, O_RDONLY | O_CLOEXEC));
    if (file.get() < 0) return std::nullopt;
    char text[128];
    const ssize_t length = read(file.get(), text, sizeof text - 1);
    if (length <= 0) return std::nullopt;
    text[length] = '\0';
    char* end = nullptr;
    std::strtoull(text, &end, 10);
    if (end == text || *end != ' ') return std::nullopt;
    const char* wait = end + 1;
    const std::uint64_t nanoseconds = std::strtoull(wait, &end, 10);
    if (end == wait) return std::nullopt;
    return nanoseconds;
}

}  // namespace

std::optional<double> process_run_queue_wait_seconds() {
    const FileDescriptor tasks(open("/proc/self/task", O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (tasks.get() < 0) return std::nullopt;
    std::uint64_t total = 0;
    int listed_tasks = 0;
    int read_tasks = 0;
    // The kernel's directory records, read by the system call into a buffer
    // of our own (opendir would allocate one; glibc's getdents64 wrapper is
    // recent): each is an 8-byte inode, an 8-byte offset, a 2-byte record
    // length, a 1-byte type and the name, ended by '\0'.
    constexpr std::size_t record_length_at = 16;
    constexpr std::size_t name_at = 19;
    alignas(8) char entries[4096];
    for (;;) {
        const long length = syscall(SYS_getdents64, tasks.get(), entries, sizeof entries);
        if (length < 0) return std::nullopt;
        if (length == 0) break;
        for (long offset = 0; offset < length;) {
            const char* entry = entries + offset;
            unsigned short record_length = 0;
            std::memcpy(&record_length, entry + record_length_at, sizeof record_length);
            if (record_length == 0) return std::nullopt;  // never from the kernel; no endless loop either
            offset += record_length;
            const char* name = entry + name_at;
            if (name[0] < '0' || name[0] > '9') continue;  // "." and ".."
            char path[64];                                 // a task id of at most 32 digits, then "/schedstat"
            int written = 0;
            for (const char* c = name; *c != '\0' && written < 32; ++c) path[written++] = *c;
            for (const char* c = "/schedstat"; *c != '\0'; ++c) path[written++] = *c;
            path[written] = '\0';
            // A thread that ended since the listing has no file: skipped.
            if (const std::optional<std::uint64_t> wait = read_wait_nanoseconds(tasks.get(), path)) {
                total += *wait;
                ++read_tasks;
            }
            if (++listed_tasks == most_tasks_read) break;
        }
        if (listed_tasks == most_tasks_read) break;
    }
    if (read_tasks == 0) return std::nullopt;
    return 1e-9 * static_cast<double>(total);
}

#else

std::optional<double> process_run_queue_wait_seconds() { return std::nullopt; }

#endif

}  // namespace particlesim
