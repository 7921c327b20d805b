#pragma once
// The environment a graded program gets. Not the grader's whole one: a
// grader's environment may hold secrets (a CI job's tokens, a grading
// service's keys) that a program could print into its output or stderr,
// which the reports carry. By default it gets what programs of this kind
// need: PATH, the locale, TMPDIR, LD_LIBRARY_PATH, the settings of OpenMP,
// of MPI's runtimes and of the sanitizers, and HOME set to its working
// directory (the only home it may write). More by name (--env), or all
// (--full-env).

#include <string>
#include <vector>

namespace simcheck {

struct EnvironmentChoice {
    bool full = false;                  // --full-env: the grader's whole environment, HOME too
    std::vector<std::string> passed;    // --env NAME: the grader's value of NAME
    std::vector<std::string> assigned;  // --env NAME=VALUE
};

// Reads one --env argument into `choice`: NAME (set in this process's
// environment) or NAME=VALUE. Throws std::invalid_argument with the reason.
void add_environment_option(const std::string& argument, EnvironmentChoice& choice);

// The program's environment, as NAME=VALUE entries (this process's
// environment read now); `home`: its working directory.
std::vector<std::string> program_environment(const EnvironmentChoice& choice, const std::string& home);

}  // namespace simcheck
