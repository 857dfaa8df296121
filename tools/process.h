// tools/process.h — run a program and collect what it says.
#pragma once

#include <string>
#include <vector>

namespace gllab {

struct ProcessResult {
  int exit_status = -1;  // exit code, or 128 + signal number when killed
  std::string out, err;
  bool started = true;   // false when the program could not be executed
  bool timed_out = false; // killed (SIGKILL) because it ran longer than the timeout
};

/// Runs argv[0] with arguments argv[1..] (no shell), waits, returns its exit
/// status and output. extra_env entries "NAME=value" are added to the
/// environment. Never throws for a failing program.
ProcessResult run_process(const std::vector<std::string>& argv,
                          const std::vector<std::string>& extra_env = {});

/// The same, but a program still running after timeout_seconds (> 0) is
/// killed with SIGKILL: exit_status 137, timed_out true. A grader must not
/// hang on a student's endless loop.
ProcessResult run_process(const std::vector<std::string>& argv, const std::vector<std::string>& extra_env,
                          double timeout_seconds);

/// The first line of text, without the newline (for one-line reports).
std::string first_line(const std::string& text);

}  // namespace gllab
