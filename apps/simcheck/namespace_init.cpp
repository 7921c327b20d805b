#include "namespace_init.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstring>

namespace simcheck {

namespace {

// Whether /proc/PID/stat (`pid` its directory's name) names a process that
// has not yet ended (not a zombie). Async-signal-safe.
bool is_running(const char* pid) {
    char path[64] = "/proc/";
    const std::size_t length = std::strlen(pid);
    if (length > 20) return false;
    std::memcpy(path + 6, pid, length);
    std::memcpy(path + 6 + length, "/stat", 6);
    const int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;  // ended meanwhile
    char text[512];
    const ssize_t got = read(fd, text, sizeof text - 1);
    close(fd);
    if (got <= 0) return false;
    text[got] = '\0';
    // The state follows the command's closing parenthesis (the command may hold one too).
    const char* name_end = std::strrchr(text, ')');
    return name_end != nullptr && name_end[1] == ' ' && name_end[2] != 'Z' && name_end[2] != 'X';
}

// The processes of this PID namespace but its init that have not ended, as
// its /proc lists them (getdents64: opendir allocates). Async-signal-safe.
int processes_besides_init() {
    const int proc = open("/proc", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (proc < 0) return 0;
    int running = 0;
    alignas(8) char entries[4096];
    for (long got; (got = syscall(SYS_getdents64, proc, entries, sizeof entries)) > 0;) {
        for (long offset = 0; offset < got;) {
            // struct linux_dirent64: inode (8 bytes), offset (8), record length (2), type (1), name.
            unsigned short record = 0;
            std::memcpy(&record, entries + offset + 16, sizeof record);
            const char* name = entries + offset + 19;
            if (name[0] >= '1' && name[0] <= '9' && std::strcmp(name, "1") != 0 && is_running(name)) ++running;
            offset += record;
        }
    }
    close(proc);
    return running;
}

}  // namespace

void split_off_program(int report) {
    const auto program = static_cast<pid_t>(syscall(SYS_clone, SIGCHLD, nullptr, nullptr, nullptr, nullptr));
    if (program == 0) return;
    if (program < 0) {
        constexpr char message[] = "simcheck grade: cannot start the program in its PID namespace\n";
        [[maybe_unused]] const auto written = write(2, message, sizeof message - 1);
        _exit(127);
    }
    // The program's streams and stdin are its own: the grader sees its
    // output end when the program and what it started close them.
    for (int fd = 0; fd < 3; ++fd) close(fd);
    if (report > 3) close_range(3, static_cast<unsigned>(report) - 1, 0);
    close_range(static_cast<unsigned>(report) + 1, ~0U, 0);
    ProgramEnd end;
    for (;;) {
        int status = 0;
        const pid_t ended = waitpid(-1, &status, 0);
        if (ended == program) {
            end.wait_status = status;
            break;
        }
        if (ended < 0 && errno != EINTR) _exit(127);  // no child left, the program not among them: not expected
    }
    end.left_running = processes_besides_init();
    [[maybe_unused]] const auto written = write(report, &end, sizeof end);
    // kill(-1) from a namespace's init reaches every other process in it.
    kill(-1, SIGKILL);
    for (;;) {
        if (waitpid(-1, nullptr, 0) < 0 && errno != EINTR) break;
    }
    _exit(0);
}

}  // namespace simcheck
