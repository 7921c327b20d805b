#include "interrupts.hpp"

#include <signal.h>
#include <unistd.h>

#include <csignal>
#include <cstring>

namespace simcli {

namespace {

volatile std::sig_atomic_t received = 0;
volatile std::sig_atomic_t stopping = 0;  // the run has seen the signal and stops in order: let it finish

// The unfinished files a forced stop removes, in storage the signal handler
// may read: a slot's path is complete whenever its flag is set.
constexpr int most_temporaries = 8;
constexpr std::size_t longest_temporary = 4096;
char temporary_paths[most_temporaries][longest_temporary];
volatile std::sig_atomic_t temporary_listed[most_temporaries];

volatile std::sig_atomic_t some_file_in_place = 0;

constexpr char forced_message[] =
    "simcli: stopped at once by a second signal; every file it was writing is left as it was "
    "(the unfinished copies are removed)\n";
constexpr char forced_message_after_checkpoint[] =
    "simcli: stopped at once by a second signal; the files a checkpoint put in place hold every step up to it "
    "(simcli --resume cuts them back to it), the others are left as they were\n";

// The first signal is noted for the run to see after its step; a second one
// before the run has seen it (a step may take minutes) removes the
// unfinished files and ends the process by the signal, with only
// async-signal-safe calls.
extern "C" void note_signal(int signal) {
    if (received == 0) {
        received = signal;
        return;
    }
    if (stopping) return;
    for (int k = 0; k < most_temporaries; ++k) {
        if (temporary_listed[k]) unlink(temporary_paths[k]);
    }
    [[maybe_unused]] const ssize_t written =
        some_file_in_place
            ? write(STDERR_FILENO, forced_message_after_checkpoint, sizeof forced_message_after_checkpoint - 1)
            : write(STDERR_FILENO, forced_message, sizeof forced_message - 1);
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

// note_signal() for SIGINT, SIGTERM and SIGHUP, except one the process was
// started ignoring (nohup; a shell's background job ignores SIGINT): that
// stays ignored. `flags` say whether a write the signal cut short is resumed
// (SA_RESTART).
void note_interrupts(int flags) {
    struct sigaction action {};
    action.sa_handler = note_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = flags;
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction current {};
        sigaction(signal, nullptr, &current);
        if (current.sa_handler != SIG_IGN) sigaction(signal, &action, nullptr);
    }
}

}  // namespace

void catch_interrupts() { note_interrupts(SA_RESTART); }

int pending_interrupt() {
    const int signal = received;
    if (signal != 0) stopping = 1;
    return signal;
}

bool interrupt_received() { return received != 0; }

void let_interrupts_end_blocked_writes() { note_interrupts(0); }

int list_unfinished_file(const std::string& path) {
    if (path.size() >= longest_temporary) return -1;
    for (int k = 0; k < most_temporaries; ++k) {
        if (temporary_listed[k]) continue;
        std::memcpy(temporary_paths[k], path.c_str(), path.size() + 1);
        temporary_listed[k] = 1;
        return k;
    }
    return -1;
}

void unlist_unfinished_file(int slot) {
    if (slot >= 0 && slot < most_temporaries) temporary_listed[slot] = 0;
}

void note_file_in_place() { some_file_in_place = 1; }

std::string interruption_message(std::int64_t step, std::int64_t steps,
                                 const std::optional<std::string>& checkpoint_path,
                                 const std::optional<std::string>& output_path,
                                 const std::vector<std::string>& side_files) {
    std::string message = "interrupted after step " + std::to_string(step) + " of " + std::to_string(steps);
    // "a", "a and b", "a, b and c"
    const auto listed = [](const std::vector<std::string>& names) {
        std::string text;
        for (std::size_t k = 0; k < names.size(); ++k) {
            if (k > 0) text += k + 1 == names.size() ? " and " : ", ";
            text += names[k];
        }
        return text;
    };
    if (checkpoint_path) {
        std::vector<std::string> kept{"the output"};
        kept.insert(kept.end(), side_files.begin(), side_files.end());
        return message + "; " + listed(kept) + (kept.size() == 1 ? " holds" : " hold") + " steps up to " +
               std::to_string(step) + "; continue with: simcli --resume " + *checkpoint_path;
    }
    std::vector<std::string> left;
    if (output_path) left.push_back(*output_path);
    left.insert(left.end(), side_files.begin(), side_files.end());
    if (left.empty()) return message;
    return message + "; " + listed(left) + (left.size() == 1 ? " left as it was" : " left as they were");
}

std::string forwarded_output_interruption_message(std::int64_t step, std::int64_t steps,
                                                  const std::optional<std::string>& checkpoint_path) {
    const std::string message = "interrupted after step " + std::to_string(step) + " of " + std::to_string(steps) +
                                "; standard output went through the MPI launcher, which stops forwarding it when "
                                "it is signalled: it may stop anywhere in the steps up to " +
                                std::to_string(step) + " (-o FILE keeps whole steps)";
    if (!checkpoint_path) return message;
    return message + "; the checkpoint holds step " + std::to_string(step) + ": continue with: simcli --resume " +
           *checkpoint_path;
}

}  // namespace simcli
