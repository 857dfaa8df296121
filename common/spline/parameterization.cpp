// common/spline/parameterization.cpp — uniform, chordal, centripetal, Foley
// and Nielson parameter values (ch. 1 §1.6, "Parameterizations").
#include "spline/parameterization.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "space/symmetric_eigen.h"
#include "spline/errors.h"

namespace gllab::spline {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Eigenvalues below this fraction of the largest count as zero when the
/// covariance is inverted: the points then span only a plane or a line.
constexpr double kRankTolerance = 1e-12;

using Matrix3 = double[3][3];

double component(Vec3 v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }

/// u^T M v: the inner product of the metric M (3 x 3, row by row).
double metric_dot(const std::vector<double>& M, Vec3 u, Vec3 v) {
  double sum = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) sum += component(u, i) * M[static_cast<std::size_t>(3 * i + j)] * component(v, j);
  return sum;
}

/// The point after i on a closed or open polygon of N points.
std::size_t next(std::size_t i, std::size_t N) { return i + 1 < N ? i + 1 : 0; }

}  // namespace

const char* parameterization_name(Parameterization method) {
  switch (method) {
    case Parameterization::kUniform: return "uniform";
    case Parameterization::kChordal: return "chordal";
    case Parameterization::kCentripetal: return "centripetal";
    case Parameterization::kFoley: return "Foley";
    case Parameterization::kNielson: return "Nielson";
  }
  return "unknown";
}

/// Ch. 1 §1.6, "Nielson metric". The lecture writes, for 2D points,
///     |(x, y)|_N^2 = (x, y) [ Sy2/D  -Sxy/D ; -Sxy/D  Sx2/D ] (x, y)^T,
///     D = Sx2 Sy2 - Sxy^2,
/// with the variances Sx2, Sy2 and covariance Sxy of the N points (1/N sums
/// around the mean). That matrix is the inverse of the covariance matrix
/// [ Sx2 Sxy ; Sxy Sy2 ]. (The lecture prints +Sxy/D in the top-right corner; the
/// off-diagonal entries of an inverse symmetric matrix are equal, and with
/// opposite signs they would cancel in the quadratic form and lose the
/// affine invariance the lecture claims.) Here the same inverse is taken in 3D,
/// through the eigen-decomposition C = sum lambda_k e_k e_k^T, as
///     M = sum over lambda_k > 0 of (1 / lambda_k) e_k e_k^T,
/// the pseudo-inverse, so that 2D points (z = 0) and collinear points, whose
/// C is singular, are measured within the plane or line they span.
/// Why affine invariant: for Q_i = A P_i + b the covariance becomes A C A^T, and
/// (A v)^T (A C A^T)^-1 (A v) = v^T C^-1 v.
std::vector<double> nielson_metric(const std::vector<Vec3>& points) {
  const std::string what = "nielson_metric";
  if (points.empty()) fail(ErrorCode::kEmptyInput, what + ": no points given", {{"points", 0}});
  for (std::size_t i = 0; i < points.size(); ++i) require_finite(points[i], what, at("P", i));
  const double N = static_cast<double>(points.size());
  Vec3 mean;
  for (Vec3 p : points) mean += p / N;
  Matrix3 C = {};
  for (Vec3 p : points) {
    const Vec3 e = p - mean;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) C[i][j] += component(e, i) * component(e, j) / N;
  }
  // The eigen-decomposition by the cyclic Jacobi method (space/symmetric_eigen.h).
  const space::SymmetricEigen e = space::symmetric_eigen(C);
  const double largest = e.values[0];
  if (!(largest > 0))
    fail(ErrorCode::kCoincidentPoints,
         what + ": all " + std::to_string(points.size()) + " points coincide at " + num(points[0]) +
             " (no covariance to normalize by)",
         {{"points", points.size()}, {"P[0]", points[0]}});
  std::vector<double> M(9, 0.0);
  for (int k = 0; k < 3; ++k) {
    const double lambda = e.values[k];
    if (lambda <= kRankTolerance * largest) continue;  // a direction the points do not span
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) M[static_cast<std::size_t>(3 * i + j)] += e.vectors[i][k] * e.vectors[j][k] / lambda;
  }
  return M;
}

double metric_length(const std::vector<double>& M, Vec3 v) {
  if (M.size() != 9)
    fail(ErrorCode::kSizeMismatch, "metric_length: the metric has " + std::to_string(M.size()) + " entries, 9 expected",
         {{"entries", M.size()}, {"expected", 9}});
  return std::sqrt(std::max(0.0, metric_dot(M, v, v)));
}

std::vector<double> parameters(const std::vector<Vec3>& points, Parameterization method, bool closed) {
  const std::string what = std::string("parameters (") + parameterization_name(method) + ")";
  const std::size_t N = points.size();  // n + 1 points P_0..P_n
  if (N < 2)
    fail(ErrorCode::kTooFewPoints, what + ": " + std::to_string(N) + (N == 1 ? " point" : " points") +
         " given, at least 2 needed", {{"points", N}});
  for (std::size_t i = 0; i < N; ++i) require_finite(points[i], what, at("P", i));

  // The chords: P_i -> P_{i+1}, and for a closed curve also P_n -> P_0.
  const std::size_t chords = closed ? N : N - 1;
  auto chord = [&](std::size_t i) { return points[next(i, N)] - points[i]; };
  for (std::size_t i = 0; i < chords; ++i)
    if (method != Parameterization::kUniform && chord(i) == Vec3{})
      fail(ErrorCode::kCoincidentPoints,
           what + ": " + at("P", i) + "=" + num(points[i]) + " and " + at("P", next(i, N)) + "=" +
               num(points[next(i, N)]) + " coincide (a zero chord gives no parameter step)",
           {{"i", i}, {"j", next(i, N)}, {at("P", i), points[i]}});

  // dt[i] = t_{i+1} - t_i, one step per chord.
  std::vector<double> dt(chords);
  switch (method) {
    case Parameterization::kUniform:
      // Equidistant: the same time for every chord (ch. 1 §1.6, "Equidistant parameterization").
      for (double& step : dt) step = 1.0;
      break;
    case Parameterization::kChordal:
      // Time proportional to distance (ch. 1 §1.6, "Chordal parameterization").
      for (std::size_t i = 0; i < chords; ++i) dt[i] = norm(chord(i));
      break;
    case Parameterization::kCentripetal:
      // Square root of the distance: approximately minimizes the centripetal
      // acceleration (ch. 1 §1.6, "Centripetal parameterization", [Lee 1975]).
      for (std::size_t i = 0; i < chords; ++i) dt[i] = std::sqrt(norm(chord(i)));
      break;
    case Parameterization::kNielson: {
      // Chordal, with lengths in the affine-invariant Nielson metric
      // (ch. 1 §1.6, "Nielson metric"; figure 3 c, "affine invariant chord").
      const std::vector<double> M = nielson_metric(points);
      for (std::size_t i = 0; i < chords; ++i) dt[i] = metric_length(M, chord(i));
      break;
    }
    case Parameterization::kFoley: {
      // Foley–Nielson (ch. 1 §1.6, "Foley parameterization", [Foley 1989]):
      //   dt_i = d_i (1 + 1.5 phi^_i d_{i-1} / (d_{i-1} + d_i)
      //                 + 1.5 phi^_{i+1} d_{i+1} / (d_i + d_{i+1})),
      //   phi^_i = min(pi - phi_i, pi / 2),
      // where d_i is the length of chord i and phi_i the angle at P_i between
      // the chords to P_{i-1} and P_{i+1}: a straight run (phi = pi) adds
      // nothing, a sharp turn adds up to half again on each side. Lengths and
      // angles are taken in the Nielson metric, so the result is affine
      // invariant (figure 3 d, "affine invariant angle"). An open polygon has
      // no chord before the first or after the last: d_{-1} = d_n = 0.
      const std::vector<double> M = nielson_metric(points);
      std::vector<double> d(chords);
      for (std::size_t i = 0; i < chords; ++i) d[i] = metric_length(M, chord(i));
      // phi^ at point k, between chord k-1 (into P_k) and chord k (out of P_k).
      auto phi_hat = [&](std::size_t k) {
        const Vec3 back = points[(k + N - 1) % N] - points[k];
        const Vec3 ahead = points[next(k, N)] - points[k];
        const double cosine = metric_dot(M, back, ahead) / (metric_length(M, back) * metric_length(M, ahead));
        const double phi = std::acos(std::clamp(cosine, -1.0, 1.0));
        return std::min(kPi - phi, kPi / 2);
      };
      for (std::size_t i = 0; i < chords; ++i) {
        double factor = 1.0;
        const bool has_before = closed || i > 0;
        const bool has_after = closed || i + 1 < chords;
        if (has_before) {
          const double d_before = d[(i + chords - 1) % chords];
          factor += 1.5 * phi_hat(i) * d_before / (d_before + d[i]);
        }
        if (has_after) {
          const double d_after = d[(i + 1) % chords];
          factor += 1.5 * phi_hat(next(i, N)) * d_after / (d[i] + d_after);
        }
        dt[i] = d[i] * factor;
      }
      break;
    }
  }

  std::vector<double> t(chords + 1, 0.0);
  for (std::size_t i = 0; i < chords; ++i) {
    // A chord that is not zero can still have no length in the Nielson metric
    // when it leaves the span of the points by less than rounding: say so.
    if (!(dt[i] > 0) || !std::isfinite(dt[i]))
      fail(ErrorCode::kDegenerate,
           what + ": chord " + at("P", i) + "=" + num(points[i]) + " -> " + at("P", next(i, N)) + "=" +
               num(points[next(i, N)]) + " has step " + num(dt[i]) + " (must be positive)",
           {{"i", i}, {"j", next(i, N)}, {"step", dt[i]}});
    t[i + 1] = t[i] + dt[i];
  }
  return t;
}

std::vector<double> unit_interval_parameters(const std::vector<double>& t) {
  const std::string what = "unit_interval_parameters";
  if (t.size() < 2)
    fail(ErrorCode::kTooFewPoints, what + ": " + std::to_string(t.size()) + " values given, at least 2 needed",
         {{"values", t.size()}});
  for (std::size_t i = 0; i < t.size(); ++i) require_finite(t[i], what, at("t", i));
  const double length = t.back() - t.front();
  if (length == 0)
    fail(ErrorCode::kEmptyDomain, what + ": t[0] = t[" + std::to_string(t.size() - 1) + "] = " + num(t.front()),
         {{"t[0]", t.front()}, {at("t", t.size() - 1), t.back()}});
  std::vector<double> unit(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) unit[i] = (t[i] - t.front()) / length;
  unit.back() = 1.0;  // exactly, whatever the rounding
  return unit;
}

}  // namespace gllab::spline
