#include "whole_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <stdexcept>

namespace simgen {

namespace {

// The partial file being written, for the signal handler (which may only
// read it: the flag says when the path is whole).
char partial_path[PATH_MAX];
volatile sig_atomic_t partial_listed = 0;

extern "C" void remove_partial_and_end(int signal_number) {
    if (partial_listed) unlink(partial_path);
    // End as the signal asks: the default action, raised again.
    struct sigaction default_action {};
    default_action.sa_handler = SIG_DFL;
    sigemptyset(&default_action.sa_mask);
    sigaction(signal_number, &default_action, nullptr);
    raise(signal_number);
}

void install_handlers_once() {
    static const bool installed = [] {
        for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
            struct sigaction current {};
            sigaction(signal_number, nullptr, &current);
            if (current.sa_handler == SIG_IGN) continue;  // started ignoring it (nohup): keep that
            struct sigaction action {};
            action.sa_handler = remove_partial_and_end;
            sigemptyset(&action.sa_mask);
            sigaction(signal_number, &action, nullptr);
        }
        return true;
    }();
    (void)installed;
}

[[noreturn]] void fail(const std::string& path, const char* what) {
    throw std::runtime_error(path + ": " + what + ": " + std::strerror(errno));
}

}  // namespace

void write_whole_file(const std::string& path, const std::function<void(std::FILE*)>& write) {
    install_handlers_once();
    const std::string partial = path + ".partial";
    if (partial.size() >= sizeof partial_path) {
        errno = ENAMETOOLONG;
        fail(path, "cannot write");
    }
    std::memcpy(partial_path, partial.c_str(), partial.size() + 1);
    partial_listed = 1;
    // Every way out but the rename removes the partial file, keeping errno for the message.
    const auto abandon = [&] {
        const int error = errno;
        std::remove(partial.c_str());
        partial_listed = 0;
        errno = error;
    };
    std::FILE* file = std::fopen(partial.c_str(), "wb");
    if (!file) {
        abandon();
        fail(path, "cannot write");
    }
    try {
        write(file);
    } catch (...) {
        std::fclose(file);
        abandon();
        throw;
    }
    const bool written = !std::ferror(file);
    if (std::fclose(file) != 0 || !written) {
        abandon();
        fail(path, "cannot write");
    }
    if (std::rename(partial.c_str(), path.c_str()) != 0) {
        abandon();
        fail(path, "cannot put in place");
    }
    partial_listed = 0;
}

}  // namespace simgen
