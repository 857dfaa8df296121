// tests/io/tool_test_support.h — what the tests of the command-line tools (isotool,
// csgtool) share: a command line as text, and the check of a run that must fail: its exit
// status, one line on stderr that starts with the tool's name and holds the expected text,
// and nothing on stdout.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "process.h"

namespace gllab::io::testing {

inline std::string joined(const std::vector<std::string>& args) {
  std::string out;
  for (const std::string& a : args) out += a + " ";
  return out;
}

struct BadRun {
  std::vector<std::string> args;
  int status;
  std::string expected;  // a substring of the one line on stderr
};

inline void expect_bad_run(const ProcessResult& r, const BadRun& run, const std::string& tool) {
  const std::string line = joined(run.args);
  EXPECT_EQ(r.exit_status, run.status) << line << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << line << "\n" << r.err;
  EXPECT_EQ(r.err.rfind(tool, 0), 0u) << line << "\n" << r.err;
  EXPECT_NE(r.err.find(run.expected), std::string::npos) << line << "\n" << r.err;
  EXPECT_EQ(r.out, "") << line;
}

}  // namespace gllab::io::testing
