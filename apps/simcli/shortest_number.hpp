#pragma once
// A number appended in the shortest text that reads back to the same
// double, for the files simcli writes beside its output (trajectories,
// observables).

#include <charconv>
#include <string>

namespace simcli {

inline void append_shortest(std::string& text, double value) {
    char digits[32];
    text.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
}

}  // namespace simcli
