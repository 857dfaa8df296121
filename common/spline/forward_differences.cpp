// common/spline/forward_differences.cpp — a cubic by forward differences and by
// Horner's rule, in float or double (forward_differences.h).
#include "spline/forward_differences.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "spline/bspline.h"
#include "spline/errors.h"

namespace gllab::spline {

namespace {

void check_steps(int steps, const char* what) {
  if (steps < 1 || steps > kMaxForwardDifferenceSteps)
    fail(ErrorCode::kOutOfRange,
         std::string(what) + ": steps=" + std::to_string(steps) + " must lie in [1, " +
             std::to_string(kMaxForwardDifferenceSteps) + "]",
         {{"steps", steps}});
}

// One coordinate's coefficients, rounded to Real.
template <class Real>
std::array<Real, 4> coordinate(const std::array<Vec3, 4>& abcd, int axis) {
  std::array<Real, 4> c{};
  for (int i = 0; i < 4; ++i) c[i] = static_cast<Real>(axis == 0 ? abcd[i].x : axis == 1 ? abcd[i].y : abcd[i].z);
  return c;
}

}  // namespace

template <class Real>
std::vector<Vec3> cubic_by_forward_differences(const std::array<Vec3, 4>& abcd, int steps) {
  check_steps(steps, "forward differences");
  std::vector<Vec3> out(static_cast<std::size_t>(steps) + 1);
  const Real delta = Real(1) / static_cast<Real>(steps);
  const Real d2 = delta * delta, d3 = d2 * delta;
  for (int axis = 0; axis < 3; ++axis) {
    const auto [a, b, c, d] = coordinate<Real>(abcd, axis);
    Real q = d;
    Real diff1 = a * d3 + b * d2 + c * delta;
    Real diff2 = Real(6) * a * d3 + Real(2) * b * d2;
    const Real diff3 = Real(6) * a * d3;
    for (int k = 0; k <= steps; ++k) {
      (axis == 0 ? out[k].x : axis == 1 ? out[k].y : out[k].z) = static_cast<double>(q);
      q += diff1;
      diff1 += diff2;
      diff2 += diff3;
    }
  }
  return out;
}

template <class Real>
std::vector<Vec3> cubic_by_horner(const std::array<Vec3, 4>& abcd, int steps) {
  check_steps(steps, "horner");
  std::vector<Vec3> out(static_cast<std::size_t>(steps) + 1);
  for (int axis = 0; axis < 3; ++axis) {
    const auto [a, b, c, d] = coordinate<Real>(abcd, axis);
    for (int k = 0; k <= steps; ++k) {
      const Real t = static_cast<Real>(k) / static_cast<Real>(steps);
      (axis == 0 ? out[k].x : axis == 1 ? out[k].y : out[k].z) =
          static_cast<double>(((a * t + b) * t + c) * t + d);
    }
  }
  return out;
}

template std::vector<Vec3> cubic_by_forward_differences<float>(const std::array<Vec3, 4>&, int);
template std::vector<Vec3> cubic_by_forward_differences<double>(const std::array<Vec3, 4>&, int);
template std::vector<Vec3> cubic_by_horner<float>(const std::array<Vec3, 4>&, int);
template std::vector<Vec3> cubic_by_horner<double>(const std::array<Vec3, 4>&, int);

double cubic_plot_error(const std::array<Vec3, 4>& abcd, int steps, CubicMethod method) {
  check_steps(steps, "cubic plot error");
  std::vector<Vec3> got;
  switch (method) {
    case CubicMethod::kForwardFloat: got = cubic_by_forward_differences<float>(abcd, steps); break;
    case CubicMethod::kForwardDouble: got = cubic_by_forward_differences<double>(abcd, steps); break;
    case CubicMethod::kHornerFloat: got = cubic_by_horner<float>(abcd, steps); break;
    case CubicMethod::kHornerDouble: got = cubic_by_horner<double>(abcd, steps); break;
  }
  using Long = long double;
  double worst = 0;
  for (int k = 0; k <= steps; ++k) {
    const Long t = static_cast<Long>(k) / steps;
    const auto exact = [&](double a, double b, double c, double d) {
      return ((Long(a) * t + Long(b)) * t + Long(c)) * t + Long(d);
    };
    const Long dx = got[k].x - exact(abcd[0].x, abcd[1].x, abcd[2].x, abcd[3].x);
    const Long dy = got[k].y - exact(abcd[0].y, abcd[1].y, abcd[2].y, abcd[3].y);
    const Long dz = got[k].z - exact(abcd[0].z, abcd[1].z, abcd[2].z, abcd[3].z);
    worst = std::max(worst, static_cast<double>(std::sqrt(dx * dx + dy * dy + dz * dz)));
  }
  return worst;
}

std::vector<Vec3> plot_uniform_cubic_bspline(const std::vector<Vec3>& P, int steps) {
  if (P.size() < 4)
    fail(ErrorCode::kTooFewPoints,
         "uniform cubic B-spline plot: " + std::to_string(P.size()) + " points (needs at least 4)",
         {{"points", P.size()}});
  for (std::size_t i = 0; i < P.size(); ++i) require_finite(P[i], "uniform cubic B-spline plot", at("P", i));
  check_steps(steps, "uniform cubic B-spline plot");
  std::vector<Vec3> out;
  out.reserve((P.size() - 3) * steps + 1);
  for (std::size_t i = 3; i < P.size(); ++i) {  // the notes' "For (i=3 to m)"
    const std::vector<Vec3> segment =
        cubic_by_forward_differences<double>(uniform_cubic_coefficients(P[i - 3], P[i - 2], P[i - 1], P[i]), steps);
    out.insert(out.end(), segment.begin() + (i == 3 ? 0 : 1), segment.end());
  }
  return out;
}

}  // namespace gllab::spline
