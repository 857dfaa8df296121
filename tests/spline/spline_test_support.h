// tests/spline/spline_test_support.h — checks several spline tests share.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

#include "spline/vec.h"

namespace gllab::spline::testing {

// ---- tolerances several tests share (named, never loosened to pass) --------

/// Textbook fractions and values recomputed in a few floating-point operations.
inline constexpr double kRounding = 1e-15;
/// An operation that must not change the curve (insertion, refinement,
/// elevation, splitting, decomposition, batching): relative to the size of the
/// control polygon.
inline constexpr double kSameCurve = 1e-12;

/// The message of the std::invalid_argument f throws ("" and a failure if none).
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected std::invalid_argument";
  return "";
}

/// EXPECT_ERROR_HAS(call, text): the call throws std::invalid_argument whose
/// message contains text. (Use inside namespace gllab::spline with error_of in
/// scope.)
#define EXPECT_ERROR_HAS(call, text) EXPECT_NE(error_of([&] { (void)(call); }).find(text), std::string::npos) \
    << "message: \"" << error_of([&] { (void)(call); }) << "\", expected to contain \"" << (text) << "\""

inline void expect_contains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "\"" << text << "\" should contain \"" << part << "\"";
}

inline void expect_near_vec(Vec3 a, Vec3 b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

}  // namespace gllab::spline::testing
