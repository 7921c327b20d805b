#include "core/assert.hpp"

#include <cstdio>
#include <cstdlib>

namespace particlesim {

void invariant_broken(const char* condition, const char* message, const char* file, int line) noexcept {
    std::fprintf(stderr, "particlesim: invariant broken at %s:%d: %s (%s)\n", file, line, message, condition);
    std::fflush(stderr);
    std::abort();
}

}  // namespace particlesim
