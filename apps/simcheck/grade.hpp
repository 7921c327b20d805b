#pragma once
// simcheck grade SUITE_DIR [OPTIONS] -- PROGRAM [ARGS...]: runs a program on
// every scene of a suite (simgen suite, or any directory of *.in files) in
// the sandbox, judges each output, times it against simcli on the same
// scene, and reports a table (and --json, --markdown). docs/checking.md.

namespace simcheck {

// argv[0] is "grade". Exit 0 when every scene conforms, 1 otherwise, 2 on bad usage.
int grade_main(int argc, char** argv);

}  // namespace simcheck
