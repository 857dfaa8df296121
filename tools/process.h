// tools/process.h — run a program and collect what it says.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace gllab {

/// The most a tool keeps of one output stream (stdout or stderr) of a
/// renderer it runs: 64 MiB. The largest real output is a lab's six views in
/// one run, six raw 512x512 RGBA frames (6,291,870 bytes); stderr is empty
/// or one line. A renderer that writes more is killed and its render fails.
inline constexpr std::size_t kMaxRendererOutputBytes = std::size_t{64} << 20;

/// The longest timeout run_process honours: a larger one (1e18) is this,
/// about 31 years, so that the deadline never overflows the clock's type.
inline constexpr double kMaxProcessTimeoutSeconds = 1e9;

struct ProcessResult {
  int exit_status = -1;  // exit code, or 128 + signal number when killed
  std::string out, err;
  bool started = true;   // false when the program could not be executed
  bool timed_out = false; // killed (SIGKILL) because it ran longer than the timeout
  // Killed (SIGKILL) because stdout or stderr passed ProcessLimits::max_output_bytes;
  // out and err then hold the first max_output_bytes of each.
  bool output_exceeded = false;
  // Set by a caller that ran the program in the sandbox (sandbox.h): the limit
  // it reached, named ("process limit of 128 reached"), or "".
  std::string limit_hit;
};

/// What a run may take: time and output. 0 is no limit.
struct ProcessLimits {
  double timeout_seconds = 0;  // kill after this long (> 0; capped at kMaxProcessTimeoutSeconds)
  std::size_t max_output_bytes = 0;  // kill when stdout or stderr passes this many bytes
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

/// The same with both limits: a program that runs too long or writes too
/// much is killed with SIGKILL (timed_out or output_exceeded). Once it is
/// killed its pipes are closed, so a child it left behind cannot hold the
/// caller up.
ProcessResult run_process(const std::vector<std::string>& argv,
                          const std::vector<std::string>& extra_env, const ProcessLimits& limits);

/// The first line of text, without the newline (for one-line reports).
std::string first_line(const std::string& text);

}  // namespace gllab
