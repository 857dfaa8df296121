// tools/cli.h — what splinetool and isotool share on the command line: their
// exit statuses, their two kinds of error, and option values read as numbers
// with a one-line error naming the option and the text.
#pragma once

#include <cerrno>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace gllab::cli {

constexpr int kOk = 0;
constexpr int kFailed = 1;    // an output could not be written (or an internal error)
constexpr int kBadInput = 2;  // bad arguments or a bad input file

/// Bad arguments: exit 2 with one line.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// An output that cannot be written: exit 1 with one line.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The whole of `text` as a finite number; `what` names the option.
inline double parse_number(const std::string& text, const std::string& what) {
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() ||
      std::isspace(static_cast<unsigned char>(text[0])))
    throw UsageError(what + ": '" + text + "' is not a number");
  if (!std::isfinite(x)) throw UsageError(what + ": '" + text + "' is not finite");
  return x;
}

/// The whole of `text` as a whole number in lo..hi.
inline int parse_count(const std::string& text, const std::string& what, int lo, int hi) {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || end != text.c_str() + text.size() ||
      std::isspace(static_cast<unsigned char>(text[0])))
    throw UsageError(what + ": '" + text + "' is not a whole number");
  if (errno == ERANGE || v < lo || v > hi)
    throw UsageError(what + ": " + text + " (must be " + std::to_string(lo) + ".." +
                     std::to_string(hi) + ")");
  return static_cast<int>(v);
}

}  // namespace gllab::cli
