// tests/deform/deform_checks.h — what the volume, ffd, plane and morph tests
// share: the message of an exception, random numbers with a fixed seed, the
// observed order of a convergence.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>

#include "spline/vec.h"

namespace gllab::deform::testing {

/// One rounding of a value of size 1 (2^-52): the unit rounding bounds count in.
inline constexpr double kUlp = 0x1p-52;

/// The message of the std::invalid_argument f throws; a failure (and
/// "(no exception)") when it throws none.
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected std::invalid_argument";
  return "(no exception)";
}

/// EXPECT_THROW_NAMING(call, text): call throws std::invalid_argument and its
/// message contains text (the value it names).
#define EXPECT_THROW_NAMING(call, text)                                            \
  do {                                                                             \
    const std::string message_ = ::gllab::deform::testing::error_of([&] { call; }); \
    EXPECT_NE(message_.find(text), std::string::npos)                              \
        << "message \"" << message_ << "\" should name \"" << (text) << "\"";      \
  } while (0)

/// Uniform reals from a fixed seed (each test states its seed).
struct Random {
  std::mt19937 rng;
  explicit Random(unsigned seed) : rng(seed) {}
  double real(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
  int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); }
  spline::Vec3 vec3(double a, double b) { return {real(a, b), real(a, b), real(a, b)}; }
};

/// The observed order of convergence between two step sizes h and h / 2:
/// log2(e(h) / e(h / 2)); 2 for an error c h^2.
inline double observed_order(double e_h, double e_half) { return std::log2(e_h / e_half); }

/// An order of 2 is observed within this: the next term of the expansion
/// (h^4 against h^2 for a central difference) and rounding shift the ratio of
/// two errors a little from 4 at the step sizes the tests use. 2 +- 0.1 is a
/// ratio between 3.73 and 4.29: far from order 1 (ratio 2) or 3 (ratio 8).
inline constexpr double kOrderSlack = 0.1;

/// Records a measured number in the test's XML report (--gtest_output=xml):
/// the orders, errors and distances the report quotes, without printing.
inline void record(const std::string& key, double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  ::testing::Test::RecordProperty(key, text);
}

inline double max_abs(spline::Vec3 v) {
  return std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z)));
}

}  // namespace gllab::deform::testing
