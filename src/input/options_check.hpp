#pragma once
// Checks of an options struct where it enters an engine: a bad value throws
// std::invalid_argument naming the struct, the option and the value.

#include "particlesim/world.hpp"

#include <stdexcept>
#include <string>

namespace particlesim {

class OptionsCheck {
public:
    explicit OptionsCheck(const char* options_name) : name_(options_name) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw std::invalid_argument(std::string(name_) + ": " + what);
    }
    void at_least(const char* option, long long value, long long min) const {
        if (value < min)
            fail(std::string(option) + " must be >= " + std::to_string(min) + ", not " + std::to_string(value));
    }
    void in_range(const char* option, long long value, long long min, long long max) const {
        if (value < min || value > max) {
            fail(std::string(option) + " must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], not " +
                 std::to_string(value));
        }
    }
    // A Boundary cast from a number that names neither box.
    void known_boundary(const char* option, Boundary value) const {
        if (value != Boundary::walls && value != Boundary::periodic) {
            fail(std::string(option) + " must be Boundary::walls or Boundary::periodic, not " +
                 std::to_string(static_cast<int>(value)));
        }
    }

private:
    const char* name_;
};

}  // namespace particlesim
