// common/deform/volume.cpp — trivariate Bernstein and B-spline volumes
// (volume.h): one evaluator for both, A2.1 FindSpan and A2.3 DersBasisFuns
// per direction, then the triple sum by sum factorisation.
#include "deform/volume.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "deform/internal.h"
#include "spline/basis.h"
#include "spline/knots.h"

namespace gllab::deform {

namespace {

const char* const kAxis[3] = {"s", "t", "u"};

// Counts and degrees within the limits (volume.h).
void check_shape(const Volume& v) {
  for (int a = 0; a < 3; ++a) {
    const int n = v.count[a], p = v.degree[a];
    if (n < 2 || n > kMaxLatticePoints)
      throw std::invalid_argument("volume: " + std::to_string(n) + " control points along " +
                                  kAxis[a] + " (must be 2.." + std::to_string(kMaxLatticePoints) +
                                  ")");
    if (p < 1 || p > kMaxLatticeDegree || p >= n)
      throw std::invalid_argument("volume: degree " + std::to_string(p) + " along " + kAxis[a] +
                                  " with " + std::to_string(n) + " points (must be 1.." +
                                  std::to_string(kMaxLatticeDegree) + " and below the count)");
  }
}

// The identity of [0, 1]^3: control points at the Greville abscissae.
Volume identity_volume(int nx, int ny, int nz, std::array<int, 3> degree) {
  Volume v;
  v.count = {nx, ny, nz};
  v.degree = degree;
  check_shape(v);
  v.P.resize(static_cast<std::size_t>(nx) * ny * nz);
  std::array<std::vector<double>, 3> g;
  for (int a = 0; a < 3; ++a) g[a] = spline::greville_abscissae(degree[a], volume_knots(v, a));
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) v.point(i, j, k) = {g[0][i], g[1][j], g[2][k]};
  return v;
}

}  // namespace

namespace detail {

AxisBasis axis_basis(int count, int p, const std::vector<double>& U, double w) {
  AxisBasis b;
  const int span = spline::find_span(count - 1, p, w, U);  // A2.1
  double ders[2 * (kMaxLatticeDegree + 1)];
  spline::ders_basis_funs(span, w, p, 1, U, ders);  // A2.3: row 0 values, row 1 derivatives
  b.first = span - p;
  for (int r = 0; r <= p; ++r) b.N[r] = ders[r], b.dN[r] = ders[p + 1 + r];
  return b;
}

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace detail

using detail::axis_basis;
using detail::AxisBasis;

bool Volume::bernstein() const {
  return degree[0] == count[0] - 1 && degree[1] == count[1] - 1 && degree[2] == count[2] - 1;
}

Volume bernstein_volume(int nx, int ny, int nz) {
  return identity_volume(nx, ny, nz, {nx - 1, ny - 1, nz - 1});
}

Volume bspline_volume(int nx, int ny, int nz, int degree) {
  return identity_volume(nx, ny, nz, {degree, degree, degree});
}

std::vector<double> volume_knots(const Volume& v, int axis) {
  if (axis < 0 || axis > 2)
    throw std::invalid_argument("volume_knots: axis " + std::to_string(axis));
  // Clamped uniform; with degree = count - 1 that is {0 x (p + 1), 1 x (p + 1)}:
  // the B-spline basis is then the Bernstein basis.
  return spline::clamped_uniform_knots(v.count[axis] - 1, v.degree[axis]);
}

void validate(const Volume& v) {
  check_shape(v);
  const std::size_t expected = static_cast<std::size_t>(v.count[0]) * v.count[1] * v.count[2];
  if (v.P.size() != expected)
    throw std::invalid_argument("volume: " + std::to_string(v.P.size()) + " control points for " +
                                std::to_string(v.count[0]) + " x " + std::to_string(v.count[1]) +
                                " x " + std::to_string(v.count[2]) + " = " +
                                std::to_string(expected));
  for (std::size_t k = 0; k < v.P.size(); ++k)
    if (!std::isfinite(v.P[k].x) || !std::isfinite(v.P[k].y) || !std::isfinite(v.P[k].z))
      throw std::invalid_argument("volume: control point P[" + std::to_string(k) +
                                  "] is not finite");
}

VolumeEvaluator::VolumeEvaluator(const Volume& v) : v_(v) {
  validate(v_);
  for (int a = 0; a < 3; ++a) knots_[a] = volume_knots(v_, a);
}

// Sum factorisation: contract u (k) first, then t (j), then s (i). For each
// (i, j) the u-sums A = sum_k P N_k and Au = sum_k P N'_k; for each i the
// t-sums of those; then the s-sums. (p+1)^3 * 2 + (p+1)^2 * 3 + (p+1) * 4
// vector multiply-adds instead of (p+1)^3 * 4.
VolumeDerivs VolumeEvaluator::operator()(double s, double t, double u) const {
  const AxisBasis bs = axis_basis(v_.count[0], v_.degree[0], knots_[0], s);
  const AxisBasis bt = axis_basis(v_.count[1], v_.degree[1], knots_[1], t);
  const AxisBasis bu = axis_basis(v_.count[2], v_.degree[2], knots_[2], u);
  const int ps = v_.degree[0], pt = v_.degree[1], pu = v_.degree[2];
  VolumeDerivs d;
  for (int a = 0; a <= ps; ++a) {
    Vec3 B, Bt, Bu;  // sum over j, k at this i: X, d/dt, d/du
    for (int b = 0; b <= pt; ++b) {
      const Vec3* row = &v_.point(bs.first + a, bt.first + b, bu.first);
      Vec3 A, Au;  // sum over k: value and d/du
      for (int c = 0; c <= pu; ++c) {
        A += bu.N[c] * row[c];
        Au += bu.dN[c] * row[c];
      }
      B += bt.N[b] * A;
      Bt += bt.dN[b] * A;
      Bu += bt.N[b] * Au;
    }
    d.X += bs.N[a] * B;
    d.Xs += bs.dN[a] * B;
    d.Xt += bs.N[a] * Bt;
    d.Xu += bs.N[a] * Bu;
  }
  return d;
}

VolumeDerivs volume_derivs(const Volume& v, double s, double t, double u) {
  const double w[3] = {s, t, u};
  for (int a = 0; a < 3; ++a)
    if (!(w[a] >= 0 && w[a] <= 1))
      throw std::invalid_argument(std::string("volume: ") + kAxis[a] + " = " +
                                  detail::number_text(w[a]) + " outside [0, 1]");
  return VolumeEvaluator(v)(s, t, u);
}

Vec3 volume_point(const Volume& v, double s, double t, double u) {
  return volume_derivs(v, s, t, u).X;
}

}  // namespace gllab::deform
