// bench/prototype_plain.cpp — PROTOTYPE variant P, NOT the own core (see
// prototype_eval.h): the same arithmetic as common/spline/bspline.cpp
// curve_points, with a check that builds no strings. Project flags only.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "prototype_eval.h"
#include "spline/bspline.h"

namespace gllab::bench::prototype {

using spline::Vec3;
using spline::Vec4;

namespace {

// Finite, non-decreasing, inside the domain: plain comparisons; a message is
// built only when a check fails.
void check_params(const std::vector<double>& u, spline::ParamInterval dom) {
  for (std::size_t k = 0; k < u.size(); ++k) {
    const bool bad = !std::isfinite(u[k]) || (k > 0 && u[k] < u[k - 1]) || u[k] < dom.a || u[k] > dom.b;
    if (bad)
      throw std::invalid_argument("curve_points_plain: u[" + std::to_string(k) + "]=" + std::to_string(u[k]) +
                                  " is not finite, decreases, or leaves the domain");
  }
}

// A2.2 BasisFuns (The NURBS Book, p. 70), as in the core; with the degree
// p - 1 functions kept for the first derivative (eq. 3.8).
void basis(int i, double u, int p, const double* U, double* N, double* Nlow) {
  double left[spline::kMaxDegree + 1], right[spline::kMaxDegree + 1];
  N[0] = 1.0;
  if (Nlow && p == 1) Nlow[0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[i + 1 - j];
    right[j] = U[i + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double temp = N[r] / (right[r + 1] + left[j - r]);
      N[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    N[j] = saved;
    if (Nlow && j == p - 1) std::copy(N, N + j + 1, Nlow);
  }
}

void plain(const spline::BsplineCurve& curve, const std::vector<double>& u, std::vector<Vec3>& out,
           std::vector<Vec3>* derivs) {
  spline::validate(curve);
  const int p = curve.p, n = curve.n();
  check_params(u, spline::domain(p, curve.U));
  out.resize(u.size());
  if (derivs) derivs->resize(u.size());
  if (u.empty()) return;
  const double* U = curve.U.data();
  std::vector<Vec4> Pw(curve.P.size()), Qw(curve.P.size());
  for (std::size_t i = 0; i < Pw.size(); ++i) Pw[i] = spline::homogeneous(curve.P[i], curve.rational() ? curve.w[i] : 1);
  for (int i = 0; i < n; ++i) {  // derivative control points, eq. 3.8, in homogeneous space
    const double du = U[i + p + 1] - U[i + 1];
    Qw[std::size_t(i)] = du > 0 ? (p / du) * (Pw[std::size_t(i) + 1] - Pw[std::size_t(i)]) : Vec4{};
  }
  int last = n;
  while (U[last] == U[last + 1]) --last;
  int span = spline::find_span(n, p, u.front(), curve.U);
  double N[spline::kMaxDegree + 1], Nlow[spline::kMaxDegree + 1];
  for (std::size_t k = 0; k < u.size(); ++k) {
    while (span < last && u[k] >= U[span + 1]) ++span;
    basis(span, u[k], p, U, N, derivs ? Nlow : nullptr);
    Vec4 A;
    for (int j = 0; j <= p; ++j) A += N[j] * Pw[std::size_t(span - p + j)];
    const Vec3 C = spline::project(A);
    out[k] = C;
    if (derivs) {
      Vec4 dA;
      for (int j = 0; j < p; ++j) dA += Nlow[j] * Qw[std::size_t(span - p + j)];
      (*derivs)[k] = (spline::xyz(dA) - dA.w * C) / A.w;
    }
  }
}

}  // namespace

void curve_points_plain(const spline::BsplineCurve& curve, const std::vector<double>& sorted_u,
                        std::vector<Vec3>& out) {
  plain(curve, sorted_u, out, nullptr);
}
void curve_points_plain(const spline::BsplineCurve& curve, const std::vector<double>& sorted_u,
                        std::vector<Vec3>& out, std::vector<Vec3>& derivs) {
  plain(curve, sorted_u, out, &derivs);
}

}  // namespace gllab::bench::prototype
