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

}  // namespace simcli
