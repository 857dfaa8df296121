// common/deform/plane.cpp — deformations of the unit square (plane.h).
#include "deform/plane.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "deform/internal.h"
#include "spline/knots.h"

namespace gllab::deform {

namespace {

using detail::number_text;

std::string point_text(Vec2 p) { return "(" + number_text(p.x) + ", " + number_text(p.y) + ")"; }

bool finite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

void check_shape(const PlaneDeformation& f) {
  for (int a = 0; a < 2; ++a)
    if (f.count[a] < 2 || f.count[a] > kMaxLatticePoints)
      throw std::invalid_argument("plane deformation: " + std::to_string(f.count[a]) +
                                  " control points along " + (a ? "y" : "x") + " (must be 2.." +
                                  std::to_string(kMaxLatticePoints) + ")");
  if (f.degree < 1 || f.degree > kMaxLatticeDegree || f.degree >= std::min(f.count[0], f.count[1]))
    throw std::invalid_argument("plane deformation: degree " + std::to_string(f.degree) +
                                " with " + std::to_string(f.count[0]) + " x " +
                                std::to_string(f.count[1]) + " points (must be 1.." +
                                std::to_string(kMaxLatticeDegree) + " and below both counts)");
}

std::vector<double> knots(const PlaneDeformation& f, int axis) {
  return spline::clamped_uniform_knots(f.count[axis] - 1, f.degree);
}

}  // namespace

PlaneDeformation identity_plane(int nx, int ny, int degree) {
  PlaneDeformation f;
  f.count = {nx, ny};
  f.degree = degree;
  check_shape(f);
  const std::vector<double> gx = spline::greville_abscissae(degree, knots(f, 0));
  const std::vector<double> gy = spline::greville_abscissae(degree, knots(f, 1));
  f.P.resize(static_cast<std::size_t>(nx) * ny);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) f.point(i, j) = {gx[i], gy[j]};
  return f;
}

void validate(const PlaneDeformation& f) {
  check_shape(f);
  const std::size_t expected = static_cast<std::size_t>(f.count[0]) * f.count[1];
  if (f.P.size() != expected)
    throw std::invalid_argument("plane deformation: " + std::to_string(f.P.size()) +
                                " control points for " + std::to_string(f.count[0]) + " x " +
                                std::to_string(f.count[1]) + " = " + std::to_string(expected));
  for (std::size_t k = 0; k < f.P.size(); ++k)
    if (!finite(f.P[k]))
      throw std::invalid_argument("plane deformation: control point P[" + std::to_string(k) +
                                  "] is not finite");
}

PlaneEvaluator::PlaneEvaluator(const PlaneDeformation& f) : f_(f) {
  validate(f_);
  knots_ = {knots(f_, 0), knots(f_, 1)};
}

PlaneDerivs PlaneEvaluator::operator()(Vec2 x) const {
  const detail::AxisBasis bx = detail::axis_basis(f_.count[0], f_.degree, knots_[0], x.x);
  const detail::AxisBasis by = detail::axis_basis(f_.count[1], f_.degree, knots_[1], x.y);
  PlaneDerivs d;
  for (int a = 0; a <= f_.degree; ++a) {
    Vec2 A, Ay;  // the sums over j at this i: value and d/dy
    for (int b = 0; b <= f_.degree; ++b) {
      const Vec2& c = f_.point(bx.first + a, by.first + b);
      A += by.N[b] * c;
      Ay += by.dN[b] * c;
    }
    d.f += bx.N[a] * A;
    d.fx += bx.dN[a] * A;
    d.fy += bx.N[a] * Ay;
  }
  return d;
}

PlaneDerivs plane_derivs(const PlaneDeformation& f, Vec2 x) {
  if (!(x.x >= 0 && x.x <= 1 && x.y >= 0 && x.y <= 1))
    throw std::invalid_argument("plane deformation: x = " + point_text(x) + " outside [0, 1]^2");
  return PlaneEvaluator(f)(x);
}

std::optional<Vec2> inverse_point(const PlaneEvaluator& f2, double t, Vec2 y, Vec2 guess) {
  const auto clamp = [](Vec2 p) {
    return Vec2{std::clamp(p.x, 0.0, 1.0), std::clamp(p.y, 0.0, 1.0)};
  };
  // g(x) = f(t, x) - y with its Jacobian.
  const auto residual = [&](Vec2 x, Mat2* J) {
    const PlaneDerivs d = f2(x);
    if (J) *J = {(1 - t) * Vec2{1, 0} + t * d.fx, (1 - t) * Vec2{0, 1} + t * d.fy};
    return (1 - t) * x + t * d.f - y;
  };
  Vec2 x = clamp(guess);
  Mat2 J;
  Vec2 g = residual(x, &J);
  for (int k = 0; k < kInverseIterations; ++k) {
    if (norm(g) <= kInverseTolerance) return x;
    if (!(det(J) > 0)) return std::nullopt;  // folded here: no unique inverse
    Vec2 step = inverse(J) * g;
    // Halve the step until the residual decreases (a damped Newton step).
    for (int halvings = 0;; ++halvings) {
      const Vec2 next = clamp(x - step);
      Mat2 Jn;
      const Vec2 gn = residual(next, &Jn);
      if (norm(gn) < norm(g) || halvings == 30) {
        x = next, g = gn, J = Jn;
        break;
      }
      step = 0.5 * step;
    }
  }
  if (norm(g) <= kInverseTolerance) return x;
  return std::nullopt;
}

namespace {

// K x = b for a symmetric positive definite K stored as a band: K[r][c] for
// |r - c| <= w, kept as band[r][c - r + w]. Cholesky K = L L^T, then the two
// triangular solves; O(n w^2). The caller knows K is positive definite.
class BandCholesky {
 public:
  BandCholesky(std::vector<std::vector<double>> band, int w) : L_(std::move(band)), w_(w) {
    const int n = int(L_.size());
    for (int r = 0; r < n; ++r)
      for (int c = std::max(0, r - w_); c <= r; ++c) {
        double sum = at(r, c);
        for (int k = std::max(0, r - w_); k < c; ++k) sum -= at(r, k) * at(c, k);
        at(r, c) = c == r ? std::sqrt(sum) : sum / at(c, c);
      }
  }
  std::vector<double> solve(std::vector<double> b) const {
    const int n = int(L_.size());
    for (int r = 0; r < n; ++r) {  // L y = b
      for (int k = std::max(0, r - w_); k < r; ++k) b[r] -= at(r, k) * b[k];
      b[r] /= at(r, r);
    }
    for (int r = n - 1; r >= 0; --r) {  // L^T x = y
      for (int k = r + 1; k <= std::min(n - 1, r + w_); ++k) b[r] -= at(k, r) * b[k];
      b[r] /= at(r, r);
    }
    return b;
  }

 private:
  double& at(int r, int c) { return L_[r][c - r + w_]; }
  double at(int r, int c) const { return L_[r][c - r + w_]; }
  std::vector<std::vector<double>> L_;
  int w_;
};

}  // namespace

PlaneDeformation fit_features(const PlaneDeformation& base, const std::vector<Vec2>& from,
                              const std::vector<Vec2>& to) {
  validate(base);
  if (from.size() != to.size())
    throw std::invalid_argument("fit_features: " + std::to_string(from.size()) +
                                " feature points but " + std::to_string(to.size()) + " targets");
  for (std::size_t k = 0; k < from.size(); ++k)
    for (const Vec2 p : {from[k], to[k]})
      if (!(p.x > 0 && p.x < 1 && p.y > 0 && p.y < 1))
        throw std::invalid_argument("fit_features: feature " + std::to_string(k) + " at " +
                                    point_text(p) + " must lie inside (0, 1)^2");
  const std::size_t n = from.size();
  if (n == 0) return base;
  // The unknowns: the displacements d of the inner control points, numbered
  // row by row, c = (i - 1) * (ny - 2) + (j - 1); the border's stay 0.
  const int nx = base.count[0], ny = base.count[1], rows = ny - 2;
  const int m = (nx - 2) * rows;
  const auto unknown = [&](int i, int j) {
    return base.on_border(i, j) ? -1 : (i - 1) * rows + (j - 1);
  };
  // The membrane energy E(d) = sum over the grid's edges (a, b) of |d_a - d_b|^2
  // is d^T K d with K the grid's graph Laplacian on the inner points (border
  // d = 0): positive definite, a band of half-width `rows`.
  std::vector<std::vector<double>> band(m, std::vector<double>(2 * rows + 1));
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (const auto [di, dj] : {std::array<int, 2>{1, 0}, std::array<int, 2>{0, 1}}) {
        if (i + di >= nx || j + dj >= ny) continue;
        const int a = unknown(i, j), b = unknown(i + di, j + dj);
        if (a >= 0) band[a][rows] += 1;
        if (b >= 0) band[b][rows] += 1;
        if (a >= 0 && b >= 0) band[std::max(a, b)][std::min(a, b) - std::max(a, b) + rows] -= 1;
      }
  const BandCholesky K(std::move(band), rows);
  // W[k][c] = N_i(from_k.x) N_j(from_k.y): feature k's weight on unknown c;
  // r[k] = to[k] - base(from[k]), what the displacements must add there.
  const std::array<std::vector<double>, 2> U = {knots(base, 0), knots(base, 1)};
  const PlaneEvaluator eval(base);
  std::vector<std::vector<double>> W(n, std::vector<double>(m)), Z(n);
  std::vector<spline::Vec3> r(n);
  for (std::size_t k = 0; k < n; ++k) {
    const detail::AxisBasis bx = detail::axis_basis(nx, base.degree, U[0], from[k].x);
    const detail::AxisBasis by = detail::axis_basis(ny, base.degree, U[1], from[k].y);
    for (int a = 0; a <= base.degree; ++a)
      for (int b = 0; b <= base.degree; ++b) {
        const int c = unknown(bx.first + a, by.first + b);
        if (c >= 0) W[k][c] = bx.N[a] * by.N[b];
      }
    const Vec2 miss = to[k] - eval(from[k]).f;
    r[k] = {miss.x, miss.y, 0};
    Z[k] = K.solve(W[k]);  // K^-1 W^T, column k
  }
  // Minimise E subject to W d = r (Lagrange): d = K^-1 W^T lambda with
  // (W K^-1 W^T) lambda = r.
  std::vector<std::vector<double>> A(n, std::vector<double>(n));
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b)
      for (int c = 0; c < m; ++c) A[a][b] += W[a][c] * Z[b][c];
  // A is symmetric and positive semi-definite: Cholesky A = L L^T, the
  // features in their order. A feature whose pivot vanishes (relative to its
  // diagonal) adds no condition of its own: its weights are a combination of
  // the earlier features' (the same place; more features than inner points).
  // It gets lambda = 0, and the check below names it when its target is not
  // where the others put it (a repeated feature with the same target is met).
  constexpr double kDependent = 1e-10;
  std::vector<std::vector<double>> L(n, std::vector<double>(n));
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b <= a; ++b) {
      double sum = A[a][b];
      for (std::size_t k = 0; k < b; ++k) sum -= L[a][k] * L[b][k];
      if (b < a)
        L[a][b] = L[b][b] > 0 ? sum / L[b][b] : 0;
      else
        L[a][a] = sum > kDependent * A[a][a] ? std::sqrt(sum) : 0;
    }
  std::vector<spline::Vec3> lambda(n);
  for (std::size_t a = 0; a < n; ++a) {  // L y = r (y kept in lambda)
    spline::Vec3 sum = r[a];
    for (std::size_t k = 0; k < a; ++k) sum -= L[a][k] * lambda[k];
    lambda[a] = L[a][a] > 0 ? sum / L[a][a] : spline::Vec3{};
  }
  for (std::size_t a = n; a-- > 0;) {  // L^T lambda = y
    spline::Vec3 sum = lambda[a];
    for (std::size_t k = a + 1; k < n; ++k) sum -= L[k][a] * lambda[k];
    lambda[a] = L[a][a] > 0 ? sum / L[a][a] : spline::Vec3{};
  }
  PlaneDeformation f = base;
  for (int i = 1; i + 1 < nx; ++i)
    for (int j = 1; j + 1 < ny; ++j) {
      Vec2 d;
      for (std::size_t k = 0; k < n; ++k) d += Z[k][unknown(i, j)] * Vec2{lambda[k].x, lambda[k].y};
      f.point(i, j) += d;
    }
  // Met? A singular or nearly singular system leaves a feature where it was.
  const PlaneEvaluator fitted(f);
  for (std::size_t k = 0; k < n; ++k) {
    const double miss = norm(fitted(from[k]).f - to[k]);
    if (!(miss <= kFeatureTolerance))
      throw std::invalid_argument(
          "fit_features: feature " + std::to_string(k) + " " + point_text(from[k]) + " -> " +
          point_text(to[k]) + " is missed by " + number_text(miss) + ": the " +
          std::to_string(nx) + " x " + std::to_string(ny) +
          " grid cannot meet it together with the others (features too close, or too many)");
  }
  return f;
}

PlaneFold find_plane_fold(const PlaneDeformation& f, int samples) {
  if (samples < 1 || samples > 256)
    throw std::invalid_argument("find_plane_fold: samples = " + std::to_string(samples) +
                                " (must be 1..256)");
  const PlaneEvaluator eval(f);
  const int gx = samples * (f.count[0] - 1), gy = samples * (f.count[1] - 1);
  PlaneFold fold;
  fold.min_det = INFINITY;
  for (int i = 0; i <= gx; ++i)
    for (int j = 0; j <= gy; ++j) {
      const Vec2 x{double(i) / gx, double(j) / gy};
      const double d = det(eval(x).jacobian());
      if (d < fold.min_det) fold.min_det = d, fold.at = x;
    }
  fold.folds = fold.min_det <= 0;
  return fold;
}

std::string plane_fold_text(const PlaneFold& fold) {
  char buf[128];
  if (!fold.folds)
    std::snprintf(buf, sizeof buf, "no fold: det J >= %.3g", fold.min_det);
  else
    std::snprintf(buf, sizeof buf, "the grid folds: det J = %.3g at (x, y) = (%.2f, %.2f)",
                  fold.min_det, fold.at.x, fold.at.y);
  return buf;
}

}  // namespace gllab::deform
