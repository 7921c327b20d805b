#pragma once
// The lane count a vectorised test runs (PathLines, GridSearch): the one
// asked for, or with 0 the widest of 16, 8 and 4 that the processor has; a
// count it does not have is refused, so that tests can force each width.

#include <stdexcept>
#include <string>

namespace particlesim {

// `supports(lanes)`: whether this processor runs that width; `what` names
// the test in the refusal.
template <typename Supports>
int chosen_lanes(int asked, Supports&& supports, const char* what) {
    if (asked == 0) {
        for (const int widest : {16, 8, 4}) {
            if (supports(widest)) return widest;
        }
        return 4;
    }
    if (!supports(asked)) {
        throw std::invalid_argument(std::string(what) + ": no " + std::to_string(asked) +
                                    "-lane test on this processor");
    }
    return asked;
}

}  // namespace particlesim
