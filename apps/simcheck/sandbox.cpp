#include "sandbox.hpp"

#include "files_held.hpp"
#include "ipc_objects.hpp"
#include "landlock_domain.hpp"
#include "memory_held.hpp"
#include "namespace_init.hpp"
#include "own_user.hpp"
#include "process_list.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <thread>

namespace simcheck {

namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t stderr_kept = 4096;
// After the program exits, how long its output may still take to arrive
// (from a pipe's buffer, or a child that ignored the group's SIGKILL).
constexpr double drain_seconds = 1.0;
// The largest file a program may write is its stdout cap, but never less:
// MPI's runtime (PMIx, shared memory) makes files of several megabytes in
// /dev/shm and /tmp whatever the output's size, and an mpirun run under a
// smaller limit dies of SIGXFSZ.
constexpr std::int64_t smallest_file_limit = std::int64_t{1} << 30;

// The largest file it may write (RLIMIT_FSIZE), and the most its files may hold together.
std::int64_t file_limit(const SandboxLimits& limits) { return std::max(limits.output_bytes, smallest_file_limit); }
// How often the bytes its files and its processes hold are measured while
// it runs (a walk of its directory and the scratch places' top level, and
// of its processes' descriptors): a program writing or allocating at a few
// GB/s passes a cap by at most a few hundred megabytes. Less often where
// one walk takes longer (a program that makes very many files).
constexpr double measure_seconds = 0.1;
constexpr double measure_share = 0.05;  // the most of the grader's time the walks take
// The descriptors each process may hold open: the usual default, which
// bounds the walk of its descriptors, and the pipes and sockets it can fill
// between two walks.
constexpr rlim_t most_open_files = 1024;

class Fd {
public:
    explicit Fd(int fd = -1) : fd_(fd) {}
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    ~Fd() { close(); }
    void close() {
        if (fd_ >= 0) ::close(fd_);
        fd_ = -1;
    }
    [[nodiscard]] int get() const { return fd_; }

private:
    int fd_;
};

std::string temporary_directory() {
    const char* base = std::getenv("TMPDIR");
    std::string path = std::string(base && *base ? base : "/tmp") + "/simcheck-grade-XXXXXX";
    if (!mkdtemp(path.data()))
        throw std::runtime_error("cannot make a working directory: " + std::string(std::strerror(errno)));
    return path;
}

void set_limit(int resource, rlim_t value) {
    const rlimit limit{value, value};
    setrlimit(resource, &limit);
}

// In the child, between fork and exec: async-signal-safe calls only.
// `user`: the user of its own it runs as, or 0 to stay this process's.
// `init_report`: the child of fork_into_pid_namespace(), which stays the
// namespace's init and tells its end there (namespace_init.hpp); else -1.
[[noreturn]] void start_child(char* const* argv, const char* directory, const char* stdin_path, int out, int err,
                              const SandboxLimits& limits, rlim_t tasks, uid_t user, int capability,
                              const HiddenPaths* hidden, const IpcMemoryCap& ipc, bool read_only, int init_report,
                              const LandlockDomain& domain, char* const* environment) {
    // setsid(), not just setpgid(): it then has no controlling terminal,
    // so it can neither write on the grader's (open /dev/tty) nor push
    // input into it for the shell to run after the grade (TIOCSTI). Its
    // process group is numbered by its pid all the same.
    setsid();
    dup2(err, 2);
    dup2(out, 1);
    const int in = open(stdin_path, O_RDONLY);
    if (hidden && !hidden->isolate(read_only, init_report >= 0, &ipc)) {
        constexpr char message[] = "simcheck grade: cannot isolate the program (namespaces)\n";
        [[maybe_unused]] const auto written = write(2, message, sizeof message - 1);
        _exit(127);
    }
    if (in < 0 || dup2(in, 0) < 0 || chdir(directory) != 0) {
        constexpr char message[] = "simcheck grade: cannot set up the program's stdin or working directory\n";
        [[maybe_unused]] const auto written = write(2, message, sizeof message - 1);
        _exit(127);
    }
    if (init_report >= 0) split_off_program(init_report);
    if (close_range(3, ~0U, 0) != 0) {
        for (int fd = 3; fd < 1024; ++fd) ::close(fd);
    }
    signal(SIGPIPE, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    set_limit(RLIMIT_CORE, 0);
    if (limits.memory_bytes > 0) set_limit(RLIMIT_AS, static_cast<rlim_t>(limits.memory_bytes));
    set_limit(RLIMIT_FSIZE, static_cast<rlim_t>(file_limit(limits)));
    set_limit(RLIMIT_NPROC, tasks);
    set_limit(RLIMIT_NOFILE, most_open_files);
    set_limit(RLIMIT_CPU, static_cast<rlim_t>(limits.seconds) + 2);
    if (user != 0 && !become_own_user(user, capability)) {
        constexpr char message[] = "simcheck grade: cannot run the program as a user of its own\n";
        [[maybe_unused]] const auto written = write(2, message, sizeof message - 1);
        _exit(127);
    }
    if (!domain.enter()) {
        constexpr char message[] = "simcheck grade: cannot enter the program's Landlock domain\n";
        [[maybe_unused]] const auto written = write(2, message, sizeof message - 1);
        _exit(127);
    }
    if (environment) {
        execvpe(argv[0], argv, environment);
    } else {
        execvp(argv[0], argv);
    }
    constexpr char message[] = "simcheck grade: cannot run the program\n";
    [[maybe_unused]] const auto written = write(2, message, sizeof message - 1);
    _exit(127);
}

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// A program can leave its process group (setsid, a daemon's double fork),
// and then the group's SIGKILL misses what it left behind. simcheck is
// made the subreaper of everything it runs, so that such a process, once
// its parent is gone, becomes simcheck's child instead of init's and is
// found and killed when a run ends.
//
// Which run an adopted process came from cannot be told (unless each runs
// as a user of its own), so with runs side by side (--jobs) it is killed
// only once no run is going (at the latest when the last one ends): killing
// it earlier could take a helper from a program still running. The
// programs running now and their process groups are never touched: their
// leaders are registered under this lock from the fork on, and a sweep
// holds it while it reads and kills.
std::mutex running_mutex;
std::set<pid_t> running_leaders;

// Set by interrupt_runs(), from a signal handler.
std::atomic<int> interrupting_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

void become_subreaper() {
    static std::once_flag once;
    std::call_once(once, [] { prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0); });
}

// The processes of process group `group` that are not yet zombies.
int live_members(pid_t group) {
    int members = 0;
    for_each_process([&](const char* pid) {
        ProcessStat stat;
        if (read_process_stat(pid, stat) && stat.group == group && stat.state != 'Z') ++members;
    });
    return members;
}

struct Killed {
    std::vector<pid_t> pids;     // to be reaped
    std::vector<pid_t> escaped;  // of those killed, live ones outside the run's group
    bool any = false;            // whether anything was killed
};

// Kills what the run of `leader` left behind: its user's processes, when
// it ran as a user of its own (`user`, else 0), and the children of this
// process that were adopted from its group and, when runs have no users of
// their own and no other run is going, every other adopted process
// (zombies are reaped whenever).
Killed kill_adopted(pid_t leader, uid_t user) {
    const pid_t self = getpid();
    Killed killed;
    const std::lock_guard<std::mutex> lock(running_mutex);
    const bool others_running = !running_leaders.empty();
    for_each_process([&](const char* name) {
        ProcessStat stat;
        if (!read_process_stat(name, stat)) return;
        const auto pid = static_cast<pid_t>(std::atol(name));
        const bool its_user = user != 0 && process_owner(name) == user;
        if (!its_user) {
            if (stat.parent != self) return;
            if (running_leaders.count(pid) != 0 || running_leaders.count(stat.group) != 0) return;
            // Another run's live process: with users of their own, that run's sweep finds it (and counts
            // it); without, it is killed only when no run is going.
            if (stat.group != leader && stat.state != 'Z' && (user != 0 || others_running)) return;
        }
        kill(pid, SIGKILL);
        if (stat.parent == self) killed.pids.push_back(pid);
        // With users of their own, another run's adopted process is not this one's.
        if ((user == 0 || its_user) && stat.group != leader && stat.state != 'Z') killed.escaped.push_back(pid);
        killed.any = true;
    });
    return killed;
}

// After a run: its group's members gone, and what left a group killed as
// kill_adopted() allows, each reaped; returns how many live processes outside
// the group were killed. Bounded: a process stuck in the kernel is left for a
// later sweep.
int sweep_after(pid_t leader, uid_t user) {
    // By pid: one killed but not yet dead (not this process's child, so not
    // waited for) is seen again.
    std::set<pid_t> escaped;
    const Clock::time_point start = Clock::now();
    while (seconds_since(start) < 2.0) {
        kill(-leader, SIGKILL);
        const bool group_gone = kill(-leader, 0) != 0 && errno == ESRCH;
        const Killed killed = kill_adopted(leader, user);
        escaped.insert(killed.escaped.begin(), killed.escaped.end());
        for (const pid_t pid : killed.pids) waitpid(pid, nullptr, 0);
        if (group_gone && !killed.any) break;
        if (killed.pids.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return static_cast<int>(escaped.size());
}

// The tasks (processes and threads) the user of this process runs now.
int tasks_of_this_user() {
    const uid_t user = getuid();
    int tasks = 0;
    for_each_process([&](const char* pid) {
        const std::string task_dir = std::string("/proc/") + pid + "/task";
        struct stat info {};
        if (stat(task_dir.c_str(), &info) != 0 || info.st_uid != user) return;
        if (DIR* threads = opendir(task_dir.c_str())) {
            while (const dirent* thread = readdir(threads)) tasks += thread->d_name[0] != '.' ? 1 : 0;
            closedir(threads);
        }
    });
    return tasks;
}

}  // namespace

bool runs_programs_as_own_users() {
    static const bool own_users = can_run_as_own_users();
    return own_users;
}

bool runs_programs_isolated() { return can_isolate(); }

bool runs_programs_read_only() {
    return (runs_programs_isolated() && can_make_read_only()) || landlock_limits_writes();
}

bool runs_programs_with_signals_confined() { return landlock_scopes_signals() || runs_programs_with_own_processes(); }

bool runs_programs_with_own_processes() { return can_give_own_processes(); }  // only where isolated

void interrupt_runs(int signal) noexcept { interrupting_signal.store(signal); }

int runs_interrupted() noexcept { return interrupting_signal.load(); }

SandboxRun run_sandboxed(const std::vector<std::string>& arguments, const std::string& stdin_path,
                         const std::string& stdout_path, const SandboxLimits& limits) {
    if (runs_interrupted() != 0) throw SandboxInterrupted();
    const std::string directory = temporary_directory();
    struct RemoveDirectory {
        const std::string& path;
        ~RemoveDirectory() {
            std::error_code ignored;
            std::filesystem::remove_all(path, ignored);
        }
    } remove_directory{directory};

    Fd output(open(stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
    if (output.get() < 0) throw std::runtime_error(stdout_path + ": cannot write: " + std::strerror(errno));
    int out_pipe[2], err_pipe[2];
    if (pipe2(out_pipe, O_CLOEXEC) != 0) throw std::runtime_error("cannot make a pipe");
    Fd out_read(out_pipe[0]), out_write(out_pipe[1]);
    if (pipe2(err_pipe, O_CLOEXEC) != 0) throw std::runtime_error("cannot make a pipe");
    Fd err_read(err_pipe[0]), err_write(err_pipe[1]);

    std::vector<char*> argv;
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    // A user of its own runs nothing else: the limit is the program and what it may add.
    uid_t user = 0;
    if (runs_programs_as_own_users()) {
        const std::optional<uid_t> claimed = claim_own_user();
        if (!claimed) throw std::runtime_error("no unused user id is left to run the program as");
        user = *claimed;
    }
    struct ReleaseUser {
        uid_t user;
        ~ReleaseUser() {
            if (user != 0) release_own_user(user);
        }
    } release_user{user};
    if (user != 0 && chown(directory.c_str(), user, user) != 0)
        throw std::runtime_error("cannot give the working directory to the program's user: " +
                                 std::string(std::strerror(errno)));
    // Its stdout and stderr too: opening /dev/stdout (a shell's `> /dev/stdout`)
    // opens the pipe again, as its user, which a pipe of root's (mode 0600) refuses.
    if (user != 0 && (fchown(out_write.get(), user, user) != 0 || fchown(err_write.get(), user, user) != 0))
        throw std::runtime_error("cannot give the output pipes to the program's user: " +
                                 std::string(std::strerror(errno)));
    const int capability = user != 0 ? kept_capability() : 0;  // found before the fork
    static const HiddenPaths nothing_hidden;
    const HiddenPaths* hidden = runs_programs_isolated() ? (limits.hidden ? limits.hidden : &nothing_hidden) : nullptr;
    const bool read_only = can_make_read_only();
    // In a PID namespace of its own, the program's leader is the namespace's init, which tells the program's
    // end through this pipe (namespace_init.hpp).
    const bool own_processes = hidden && can_give_own_processes();
    int report_pipe[2] = {-1, -1};
    if (own_processes && pipe2(report_pipe, O_CLOEXEC | O_NONBLOCK) != 0)
        throw std::runtime_error("cannot make a pipe");
    Fd report_read(report_pipe[0]), report_write(report_pipe[1]);
    static const LandlockDomain domain;
    // A user of its own, or a user namespace of its own, holds the program's tasks alone: the program, and in a
    // user namespace the init of its PID namespace too (a user of its own's init is root's).
    const bool in_user_namespace = hidden && isolates_in_user_namespace();
    const int counted_before_it_adds = in_user_namespace && own_processes ? 2 : 1;
    const rlim_t tasks = static_cast<rlim_t>(user != 0 || in_user_namespace ? counted_before_it_adds + limits.processes
                                                                            : tasks_of_this_user() + limits.processes);

    // Its environment, made before the fork: the child may not allocate.
    std::vector<std::string> environment_entries;
    std::vector<char*> environment;
    if (limits.environment) {
        environment_entries = program_environment(*limits.environment, directory);
        for (std::string& entry : environment_entries) environment.push_back(entry.data());
        environment.push_back(nullptr);
    }

    // Isolated, its System V objects are capped by its IPC namespace's settings (made before the fork).
    const IpcMemoryCap ipc_cap(limits.memory_bytes);

    become_subreaper();
    const Clock::time_point start = Clock::now();
    pid_t pid = 0;
    {
        // Registered before any sweep can see it as a child.
        const std::lock_guard<std::mutex> lock(running_mutex);
        pid = own_processes ? fork_into_pid_namespace() : fork();
        if (pid == 0) {
            start_child(argv.data(), directory.c_str(), stdin_path.c_str(), out_write.get(), err_write.get(), limits,
                        tasks, user, capability, hidden, ipc_cap, read_only, own_processes ? report_write.get() : -1,
                        domain, limits.environment ? environment.data() : nullptr);
        }
        if (pid > 0) running_leaders.insert(pid);
    }
    if (pid < 0) throw std::runtime_error("cannot fork: " + std::string(std::strerror(errno)));
    // The run ends with its leader unregistered and a sweep, also when it throws.
    struct Unregister {
        pid_t leader;
        uid_t user;
        bool done = false;
        int finish() {
            done = true;
            {
                const std::lock_guard<std::mutex> lock(running_mutex);
                running_leaders.erase(leader);
            }
            return sweep_after(leader, user);
        }
        ~Unregister() {
            if (!done) finish();
        }
    } unregister{pid, user};
    // No setpgid(pid, pid) here as well (the usual guard against the race):
    // a group leader cannot call setsid(). Until the child's setsid(), a
    // kill of its group misses it; stop() kills it by its pid too.
    out_write.close();
    err_write.close();
    report_write.close();
    // Told at once when the program ends, where the kernel can (pidfd).
    Fd exited(static_cast<int>(syscall(SYS_pidfd_open, pid, 0)));

    SandboxRun run;
    bool reaped = false;
    bool stopped = false;  // by a limit: nothing it leaves then counts as left running
    int status = 0;
    Clock::time_point drain_until{};
    const auto reap = [&](bool wait) {
        if (reaped) return;
        if (waitpid(pid, &status, wait ? 0 : WNOHANG) == pid) {
            reaped = true;
            run.seconds = seconds_since(start);
            if (!stopped) run.left_running += live_members(pid);
            kill(-pid, SIGKILL);  // whatever it left behind, holding stdout open or not
            drain_until = Clock::now() +
                          std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(drain_seconds));
        }
    };
    const auto stop = [&](SandboxRun::End end) {
        stopped = true;
        kill(-pid, SIGKILL);
        kill(pid, SIGKILL);
        const bool was_reaped = reaped;
        reap(true);
        if (!was_reaped) run.seconds = seconds_since(start);
        run.end = end;
    };

    char buffer[1 << 16];
    bool ended_by_limit = false;
    bool interrupted = false;
    // Its files together get the cap each of them has (RLIMIT_FSIZE).
    run.files_limit = file_limit(limits);
    run.memory_limit = limits.memory_bytes;
    // Run as a user of its own without an IPC namespace, its System V objects are found by their owner.
    const bool ipc_by_owner = user != 0 && !hidden;
    Clock::time_point next_measure = start;
    while (!ended_by_limit) {
        // Noticed within a second: no poll below waits longer.
        if (runs_interrupted() != 0) {
            stop(SandboxRun::End::timeout);
            interrupted = ended_by_limit = true;
            break;
        }
        reap(false);
        const bool out_open = out_read.get() >= 0, err_open = err_read.get() >= 0;
        if (reaped && ((!out_open && !err_open) || Clock::now() >= drain_until)) break;
        const double left = limits.seconds - seconds_since(start);
        if (!reaped && left <= 0.0) {
            stop(SandboxRun::End::timeout);
            ended_by_limit = true;
            break;
        }
        if (!reaped && Clock::now() >= next_measure) {
            const Clock::time_point walk_start = Clock::now();
            const FilesHeld held = files_held(user, pid, directory);
            run.files_bytes = held.bytes;
            run.files_too_deep = held.too_deep;
            if (run.files_bytes > run.files_limit || run.files_too_deep) {
                stop(SandboxRun::End::files_limit);
                ended_by_limit = true;
                break;
            }
            if (run.memory_limit > 0) {
                run.memory_bytes = memory_held(user, pid, ipc_by_owner).bytes();
                if (run.memory_bytes > run.memory_limit) {
                    stop(SandboxRun::End::memory_limit);
                    ended_by_limit = true;
                    break;
                }
            }
            const double walk = seconds_since(walk_start);
            next_measure = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                                              std::max(measure_seconds, walk / measure_share)));
        }
        pollfd fds[3] = {
            {out_read.get(), POLLIN, 0}, {err_read.get(), POLLIN, 0}, {reaped ? -1 : exited.get(), POLLIN, 0}};
        const double until_measure = std::max(0.0, std::chrono::duration<double>(next_measure - Clock::now()).count());
        const int wait_ms =
            exited.get() >= 0 && !reaped ? static_cast<int>(std::min({left, 1.0, until_measure}) * 1000.0) + 1 : 10;
        if (poll(fds, 3, wait_ms) < 0 && errno != EINTR) break;
        if (fds[0].revents != 0) {
            const ssize_t got = read(out_read.get(), buffer, sizeof buffer);
            if (got <= 0) {
                out_read.close();
            } else {
                run.output_bytes += got;
                if (run.output_bytes > limits.output_bytes) {
                    stop(SandboxRun::End::output_limit);
                    ended_by_limit = true;
                    break;
                }
                for (ssize_t done = 0; done < got;) {
                    const ssize_t wrote = write(output.get(), buffer + done, static_cast<std::size_t>(got - done));
                    if (wrote <= 0) throw std::runtime_error(stdout_path + ": cannot write: " + std::strerror(errno));
                    done += wrote;
                }
            }
        }
        if (fds[1].revents != 0) {
            const ssize_t got = read(err_read.get(), buffer, sizeof buffer);
            if (got <= 0) {
                err_read.close();
            } else if (run.stderr_head.size() < stderr_kept) {
                run.stderr_head.append(buffer,
                                       std::min(static_cast<std::size_t>(got), stderr_kept - run.stderr_head.size()));
            }
        }
    }
    if (!ended_by_limit) {
        reap(true);
        // The leader was its PID namespace's init: the program's own end is the one the init told, with what
        // it left running there (killed by then).
        ProgramEnd told;
        if (own_processes && read(report_read.get(), &told, sizeof told) == static_cast<ssize_t>(sizeof told)) {
            status = told.wait_status;
            run.left_running += told.left_running;
        }
        if (WIFSIGNALED(status)) {
            run.end = SandboxRun::End::signalled;
            run.signal = WTERMSIG(status);
        } else {
            run.end = SandboxRun::End::exited;
            run.exit_status = WEXITSTATUS(status);
        }
    }
    kill(-pid, SIGKILL);
    const int escaped = unregister.finish();
    if (!stopped && (limits.runs_alone || user != 0)) run.left_running += escaped;
    // Nothing of its user runs any more: what it wrote outside its directory goes too.
    if (user != 0) {
        run.left_files = remove_files_of(user, directory);
        run.left_ipc = remove_ipc_objects_of(user);
    }
    // Its directory is removed, and its user released, as the exception leaves.
    if (interrupted) throw SandboxInterrupted();
    return run;
}

}  // namespace simcheck
