#include "interruptible_output.hpp"

#include "interrupts.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstddef>

namespace simcli {

#ifdef __GLIBC__

namespace {

// Writes all of `data` unless a signal has been received: then it stops at
// the first write the descriptor does not take whole.
ssize_t write_until_interrupted(void*, const char* data, std::size_t size) {
    std::size_t done = 0;
    while (done < size) {
        const ssize_t written = write(STDOUT_FILENO, data + done, size - done);
        if (written > 0) {
            done += static_cast<std::size_t>(written);
            if (done < size && interrupt_received()) break;
            continue;
        }
        if (written < 0 && errno == EINTR && !interrupt_received()) continue;
        break;
    }
    if (done == 0 && size > 0) return -1;
    return static_cast<ssize_t>(done);
}

}  // namespace

InterruptibleOutput open_interruptible_standard_output() {
    cookie_io_functions_t functions{};
    functions.write = write_until_interrupted;
    std::FILE* stream = fopencookie(nullptr, "w", functions);
    if (stream != nullptr) std::setvbuf(stream, nullptr, _IONBF, 0);  // the writers buffer their own
    return InterruptibleOutput(stream);
}

#else

InterruptibleOutput open_interruptible_standard_output() { return nullptr; }

#endif

}  // namespace simcli
