#pragma once
// A tiny check library: named test cases, CHECK macros that count and report
// failures with the case and any context in force, a command-line filter,
// and a summary line in the form CI understands ("N passed, N failed").
//
//   int main(int argc, char** argv) {
//       return check::run(argc, argv, "test_name", {{"case one", case_one}, {"case two", case_two}});
//   }
//
// `test_name FILTER` runs only the cases whose name contains FILTER;
// `test_name --list` lists them.

#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

namespace check {

// A build under AddressSanitizer (the test command's second pass). A test
// that repeats one check over many inputs may take fewer of them there: the
// Release pass runs them all, and memory errors show on a few.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool sanitized = true;
#else
inline constexpr bool sanitized = false;
#endif

struct Tally {
    int passed = 0;
    int failed = 0;
    const char* current_case = "";
    std::vector<std::string> context;  // innermost last
};

inline Tally& tally() {
    static Tally t;
    return t;
}

inline void record(bool ok, const char* file, int line, const std::string& what) {
    Tally& t = tally();
    if (ok) {
        ++t.passed;
        return;
    }
    ++t.failed;
    std::fprintf(stderr, "%s:%d: FAILED in [%s]: %s\n", file, line, t.current_case, what.c_str());
    for (const std::string& c : t.context) std::fprintf(stderr, "    while %s\n", c.c_str());
}

// Text shown with every failure while it is alive (which scene, which option).
class Context {
public:
    template <typename... Parts>
    explicit Context(const Parts&... parts) {
        std::ostringstream text;
        text.precision(17);
        (text << ... << parts);
        tally().context.push_back(text.str());
    }
    ~Context() { tally().context.pop_back(); }
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
};

template <typename A, typename B>
std::string describe(const char* expression, const A& a, const B& b) {
    std::ostringstream out;
    out.precision(17);
    out << expression << " (" << a << " vs " << b << ")";
    return out.str();
}

struct Case {
    const char* name;
    std::function<void()> body;
};

// Runs the cases that match the filter (argv[1]) and returns the exit code.
// A run that checks nothing fails: a filter that matches no case is a mistake.
inline int run(int argc, char** argv, const char* suite, std::initializer_list<Case> cases) {
    const char* filter = argc > 1 ? argv[1] : "";
    if (std::strcmp(filter, "--list") == 0) {
        for (const Case& c : cases) std::printf("%s\n", c.name);
        return 0;
    }
    for (const Case& c : cases) {
        if (std::strstr(c.name, filter) == nullptr) continue;
        tally().current_case = c.name;
        const int failed_before = tally().failed;
        c.body();
        if (tally().failed != failed_before) std::fprintf(stderr, "case [%s] failed\n", c.name);
    }
    std::printf("%s: %d passed, %d failed\n", suite, tally().passed, tally().failed);
    return tally().failed == 0 && tally().passed > 0 ? 0 : 1;
}

}  // namespace check

// Each operand is evaluated once, and the message is built only on failure.
#define CHECK(condition) ::check::record(static_cast<bool>(condition), __FILE__, __LINE__, #condition)
#define CHECK_EQ(a, b)                                                                                    \
    do {                                                                                                  \
        const auto check_a_ = (a);                                                                        \
        const auto check_b_ = (b);                                                                        \
        const bool check_ok_ = check_a_ == check_b_;                                                      \
        ::check::record(check_ok_, __FILE__, __LINE__,                                                    \
                        check_ok_ ? std::string() : ::check::describe(#a " == " #b, check_a_, check_b_)); \
    } while (false)
#define CHECK_NEAR(a, b, tolerance)                                                                       \
    do {                                                                                                  \
        const double check_a_ = (a);                                                                      \
        const double check_b_ = (b);                                                                      \
        const bool check_ok_ = std::fabs(check_a_ - check_b_) <= (tolerance);                             \
        ::check::record(check_ok_, __FILE__, __LINE__,                                                    \
                        check_ok_ ? std::string() : ::check::describe(#a " ~= " #b, check_a_, check_b_)); \
    } while (false)
