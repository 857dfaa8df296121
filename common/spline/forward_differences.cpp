// common/spline/forward_differences.cpp — a cubic by forward differences and by
// Horner's rule, in float or double (forward_differences.h).
#include "spline/forward_differences.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

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

// Points k = first..steps of the cubic into out[0..], by forward differences in
// Real. The three coordinates step together: three independent chains of
// additions, so the processor overlaps them (one after the other, each
// addition would wait for the one before it).
template <class Real>
void forward_into(const std::array<Vec3, 4>& abcd, int steps, int first, Vec3* out) {
  const Real delta = Real(1) / static_cast<Real>(steps);
  const Real d2 = delta * delta, d3 = d2 * delta;
  Real q[3], diff1[3], diff2[3], diff3[3];
  for (int axis = 0; axis < 3; ++axis) {
    const auto pick = [axis](const Vec3& v) { return static_cast<Real>(axis == 0 ? v.x : axis == 1 ? v.y : v.z); };
    const Real a = pick(abcd[0]), b = pick(abcd[1]), c = pick(abcd[2]), d = pick(abcd[3]);
    q[axis] = d;
    diff1[axis] = a * d3 + b * d2 + c * delta;
    diff2[axis] = Real(6) * a * d3 + Real(2) * b * d2;
    diff3[axis] = Real(6) * a * d3;
  }
  for (int k = 0; k <= steps; ++k) {
    if (k >= first) *out++ = {static_cast<double>(q[0]), static_cast<double>(q[1]), static_cast<double>(q[2])};
    for (int axis = 0; axis < 3; ++axis) {
      q[axis] += diff1[axis];
      diff1[axis] += diff2[axis];
      diff2[axis] += diff3[axis];
    }
  }
}

// The same points by Horner's rule, each from t = k / steps afresh.
template <class Real>
void horner_into(const std::array<Vec3, 4>& abcd, int steps, int first, Vec3* out) {
  Real a[3], b[3], c[3], d[3];
  for (int axis = 0; axis < 3; ++axis) {
    const auto pick = [axis](const Vec3& v) { return static_cast<Real>(axis == 0 ? v.x : axis == 1 ? v.y : v.z); };
    a[axis] = pick(abcd[0]), b[axis] = pick(abcd[1]), c[axis] = pick(abcd[2]), d[axis] = pick(abcd[3]);
  }
  for (int k = first; k <= steps; ++k) {
    const Real t = static_cast<Real>(k) / static_cast<Real>(steps);
    Real v[3];
    for (int axis = 0; axis < 3; ++axis) v[axis] = ((a[axis] * t + b[axis]) * t + c[axis]) * t + d[axis];
    *out++ = {static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2])};
  }
}

void cubic_into(const std::array<Vec3, 4>& abcd, int steps, int first, CubicMethod method, Vec3* out) {
  switch (method) {
    case CubicMethod::kForwardFloat: return forward_into<float>(abcd, steps, first, out);
    case CubicMethod::kForwardDouble: return forward_into<double>(abcd, steps, first, out);
    case CubicMethod::kHornerFloat: return horner_into<float>(abcd, steps, first, out);
    case CubicMethod::kHornerDouble: return horner_into<double>(abcd, steps, first, out);
  }
}

std::vector<Vec3> cubic_by(const std::array<Vec3, 4>& abcd, int steps, CubicMethod method) {
  std::vector<Vec3> out(static_cast<std::size_t>(steps) + 1);
  cubic_into(abcd, steps, 0, method, out.data());
  return out;
}

}  // namespace

template <class Real>
std::vector<Vec3> cubic_by_forward_differences(const std::array<Vec3, 4>& abcd, int steps) {
  check_steps(steps, "forward differences");
  return cubic_by(abcd, steps, std::is_same_v<Real, float> ? CubicMethod::kForwardFloat : CubicMethod::kForwardDouble);
}

template <class Real>
std::vector<Vec3> cubic_by_horner(const std::array<Vec3, 4>& abcd, int steps) {
  check_steps(steps, "horner");
  return cubic_by(abcd, steps, std::is_same_v<Real, float> ? CubicMethod::kHornerFloat : CubicMethod::kHornerDouble);
}

template std::vector<Vec3> cubic_by_forward_differences<float>(const std::array<Vec3, 4>&, int);
template std::vector<Vec3> cubic_by_forward_differences<double>(const std::array<Vec3, 4>&, int);
template std::vector<Vec3> cubic_by_horner<float>(const std::array<Vec3, 4>&, int);
template std::vector<Vec3> cubic_by_horner<double>(const std::array<Vec3, 4>&, int);

double cubic_plot_error(const std::array<Vec3, 4>& abcd, int steps, CubicMethod method) {
  check_steps(steps, "cubic plot error");
  const std::vector<Vec3> got = cubic_by(abcd, steps, method);
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

std::vector<Vec3> plot_uniform_cubic_bspline(const std::vector<Vec3>& P, int steps, CubicMethod method) {
  if (P.size() < 4)
    fail(ErrorCode::kTooFewPoints,
         "uniform cubic B-spline plot: " + std::to_string(P.size()) + " points (needs at least 4)",
         {{"points", P.size()}});
  for (std::size_t i = 0; i < P.size(); ++i) require_finite(P[i], "uniform cubic B-spline plot", at("P", i));
  check_steps(steps, "uniform cubic B-spline plot");
  const std::size_t total = (P.size() - 3) * static_cast<std::size_t>(steps) + 1;
  if (total > static_cast<std::size_t>(kMaxForwardDifferenceSteps) + 1)
    fail(ErrorCode::kOutOfRange,
         "uniform cubic B-spline plot: " + std::to_string(P.size() - 3) + " segments x steps=" +
             std::to_string(steps) + " would make " + std::to_string(total) + " points (at most " +
             std::to_string(kMaxForwardDifferenceSteps + 1) + ")",
         {{"steps", steps}, {"points", P.size()}});
  std::vector<Vec3> out(total);
  Vec3* next = out.data();
  for (std::size_t i = 3; i < P.size(); ++i) {  // the notes' "For (i=3 to m)"
    const int first = i == 3 ? 0 : 1;
    cubic_into(uniform_cubic_coefficients(P[i - 3], P[i - 2], P[i - 1], P[i]), steps, first, method, next);
    next += steps + 1 - first;
  }
  return out;
}

}  // namespace gllab::spline
