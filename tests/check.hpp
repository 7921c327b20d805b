#pragma once
// A tiny check library: CHECK macros that count and report failures, and a
// summary line in the form CI understands ("N passed, N failed").

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace check {

struct Tally {
    int passed = 0;
    int failed = 0;
};

inline Tally& tally() {
    static Tally t;
    return t;
}

inline void record(bool ok, const char* file, int line, const std::string& what) {
    if (ok) {
        ++tally().passed;
        return;
    }
    ++tally().failed;
    std::fprintf(stderr, "%s:%d: FAILED: %s\n", file, line, what.c_str());
}

template <typename A, typename B>
std::string describe(const char* expression, const A& a, const B& b) {
    std::ostringstream out;
    out.precision(17);
    out << expression << " (" << a << " vs " << b << ")";
    return out.str();
}

// Prints the summary and returns the process exit code.
inline int summary(const char* suite) {
    std::printf("%s: %d passed, %d failed\n", suite, tally().passed, tally().failed);
    return tally().failed == 0 && tally().passed > 0 ? 0 : 1;
}

}  // namespace check

// Each operand is evaluated once, and the message is built only on failure.
#define CHECK(condition) ::check::record(static_cast<bool>(condition), __FILE__, __LINE__, #condition)
#define CHECK_EQ(a, b)                                                                                   \
    do {                                                                                                 \
        const auto check_a_ = (a);                                                                       \
        const auto check_b_ = (b);                                                                       \
        const bool check_ok_ = check_a_ == check_b_;                                                     \
        ::check::record(check_ok_, __FILE__, __LINE__,                                                   \
                        check_ok_ ? std::string() : ::check::describe(#a " == " #b, check_a_, check_b_)); \
    } while (false)
#define CHECK_NEAR(a, b, tolerance)                                                                          \
    do {                                                                                                     \
        const double check_a_ = (a);                                                                         \
        const double check_b_ = (b);                                                                         \
        const bool check_ok_ = std::fabs(check_a_ - check_b_) <= (tolerance);                                \
        ::check::record(check_ok_, __FILE__, __LINE__,                                                       \
                        check_ok_ ? std::string() : ::check::describe(#a " ~= " #b, check_a_, check_b_));     \
    } while (false)
