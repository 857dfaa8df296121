// tests/fuzz/fuzz_common.h — what the fuzzers share: the rule for errors and a check
// that stops the run with a message (tests/fuzz/README.md).
//
// A fuzzer feeds arbitrary bytes to a reader. The reader may refuse them, but only
// the documented way: an exception of the documented type whose what() is ONE
// non-empty line. Anything else (a crash, a sanitizer report, another exception
// type, a message of several lines, a failed round trip) is a finding: check()
// prints it and aborts, and libFuzzer saves the input.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace gllab::fuzz {

[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

inline void check(bool ok, const std::string& what) {
  if (!ok) fail(what);
}

/// The one-line rule for an error message (common/io/README.md, the issue's
/// "every error is one line that names its value").
inline void check_one_line(const std::exception& e, const char* where) {
  const std::string m = e.what();
  check(!m.empty(), std::string(where) + ": empty error message");
  check(m.find('\n') == std::string::npos, std::string(where) + ": message of several lines: " + m);
}

}  // namespace gllab::fuzz
