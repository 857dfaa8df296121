// common/spline/errors.h — how the spline core says no.
//
// Bad input throws std::invalid_argument whose message names the values
// involved, e.g. "knot vector: U[5]=0.4 < U[4]=0.6 (must be non-decreasing)".
// These helpers keep those messages uniform across the core.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "spline/vec.h"

namespace gllab::spline {

/// Shortest text that reads back as the same double: 40, 0.4, 1e-07, nan, inf.
inline std::string num(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);  // shortest round trip
  return std::string(buffer, result.ptr);
}

inline std::string num(Vec3 p) { return "(" + num(p.x) + ", " + num(p.y) + ", " + num(p.z) + ")"; }
inline std::string num(Vec2 p) { return "(" + num(p.x) + ", " + num(p.y) + ")"; }

[[noreturn]] inline void fail(const std::string& message) { throw std::invalid_argument(message); }

/// Throws "<what>: <name>=<value> is not finite" for NaN or infinity.
inline void require_finite(double v, const std::string& what, const std::string& name) {
  if (!std::isfinite(v)) fail(what + ": " + name + "=" + num(v) + " is not finite");
}
inline void require_finite(Vec3 p, const std::string& what, const std::string& name) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    fail(what + ": " + name + "=" + num(p) + " is not finite");
}
inline void require_finite(Vec2 p, const std::string& what, const std::string& name) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail(what + ": " + name + "=" + num(p) + " is not finite");
}

/// "P[3]" style names for messages.
inline std::string at(const std::string& array, std::size_t i) { return array + "[" + std::to_string(i) + "]"; }

}  // namespace gllab::spline
