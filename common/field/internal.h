// common/field/internal.h — helpers the field .cpp files share (not part of
// the API): how the core says no. Bad input throws std::invalid_argument
// with one line that names the offending value, e.g.
//   "marching_cubes: spacing.y=0 (must be positive)".
#pragma once

#include <charconv>
#include <stdexcept>
#include <string>

namespace gllab::field::detail {

/// The shortest text that reads back as v ("0.1", "nan", "inf").
inline std::string num(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

[[noreturn]] inline void fail(const std::string& message) { throw std::invalid_argument(message); }

}  // namespace gllab::field::detail
