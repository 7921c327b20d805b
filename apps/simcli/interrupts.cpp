#include "interrupts.hpp"

#include <csignal>

namespace simcli {

namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void note_signal(int signal) { received = signal; }

}  // namespace

void catch_interrupts() {
    std::signal(SIGINT, note_signal);
    std::signal(SIGTERM, note_signal);
}

int pending_interrupt() { return received; }

std::string interruption_message(std::int64_t step, std::int64_t steps,
                                 const std::optional<std::string>& checkpoint_path,
                                 const std::optional<std::string>& output_path) {
    std::string message = "interrupted after step " + std::to_string(step) + " of " + std::to_string(steps);
    if (checkpoint_path) {
        return message + "; the output holds steps up to " + std::to_string(step) +
               "; continue with: simcli --resume " + *checkpoint_path;
    }
    return message + (output_path ? "; " + *output_path + " left as it was" : "");
}

}  // namespace simcli
