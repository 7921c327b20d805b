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

}  // namespace simcli
