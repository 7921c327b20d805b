// PARTICLESIM_ASSERT: in a validating build a broken invariant aborts with
// its file, line, condition and message; otherwise the condition is not even
// evaluated (the checks cost nothing).
#include "check.hpp"
#include "core/assert.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <string>

namespace {

struct ChildEnd {
    int signal = 0;  // 0: exited
    std::string err;
};

// Runs `body` in a child process, with its standard error captured.
template <typename Body>
ChildEnd in_child(Body body) {
    int pipe_ends[2];
    CHECK(pipe(pipe_ends) == 0);
    const pid_t child = fork();
    if (child == 0) {
        dup2(pipe_ends[1], STDERR_FILENO);
        close(pipe_ends[0]);
        body();
        _exit(0);
    }
    close(pipe_ends[1]);
    ChildEnd end;
    char buffer[512];
    for (ssize_t got; (got = read(pipe_ends[0], buffer, sizeof buffer)) > 0;) end.err.append(buffer, buffer + got);
    close(pipe_ends[0]);
    int status = 0;
    waitpid(child, &status, 0);
    end.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    return end;
}

void broken_invariant() {
    const ChildEnd end = in_child([] {
        const int particles = 3;
        PARTICLESIM_ASSERT(particles == 4, "four particles");
    });
    if constexpr (particlesim::validating) {
        CHECK_EQ(end.signal, SIGABRT);
        CHECK(end.err.find("particlesim: invariant broken at ") == 0);
        CHECK(end.err.find("test_assert.cpp:") != std::string::npos);
        CHECK(end.err.find("four particles (particles == 4)") != std::string::npos);
    } else {
        CHECK_EQ(end.signal, 0);
        CHECK(end.err.empty());
    }
}

void kept_invariant() {
    const ChildEnd end = in_child([] { PARTICLESIM_ASSERT(2 + 2 == 4, "arithmetic"); });
    CHECK_EQ(end.signal, 0);
    CHECK(end.err.empty());
}

void condition_evaluated_only_when_validating() {
    int evaluations = 0;
    PARTICLESIM_ASSERT(++evaluations > 0, "counts its evaluations");
    CHECK_EQ(evaluations, particlesim::validating ? 1 : 0);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_assert",
                      {{"broken invariant", broken_invariant},
                       {"kept invariant", kept_invariant},
                       {"condition evaluated only when validating", condition_evaluated_only_when_validating}});
}
