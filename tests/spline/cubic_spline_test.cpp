// tests/spline/cubic_spline_test.cpp — natural, clamped and periodic cubic
// splines, their Bézier and B-spline forms, and the lecture's interpolating
// Bézier spline through de Boor points (common/spline/cubic_spline.h).
//
// Expected values come from the end conditions themselves (ch. 1 §1.6),
// from properties (C2 at the nodes, reproduction of cubics and lines, one
// curve in every form), from the lecture's three-point Bézier-spline example
// (with numbers chosen here and worked by hand) and from the lecture's wing
// section remark, and from Holladay's minimum-norm theorem (exact Gauss-Legendre
// integrals of f''^2). The B-spline form is evaluated by the project's own
// B-spline code (bspline.h, The NURBS Book A3.1), the Bézier segments by a
// de Casteljau written here.
#include "spline/cubic_spline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "spline/bspline.h"
#include "spline/parameterization.h"
#include "spline/quadrature.h"

namespace gllab::spline {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// Two exact constructions of one curve agree to rounding, relative to the
/// size of the data (the brief: forms agree to 1e-12 relative).
constexpr double kExact = 1e-12;
/// Jumps of S, S', S'' across an interior node, relative to the largest
/// |S^(k)| at the nodes: the C2 conditions hold up to rounding.
constexpr double kC2JumpTolerance = 1e-12;
/// Hand-worked Bézier points of the lecture example are small integers.
constexpr double kHandTolerance = 1e-14;
/// At least this many parameters when two forms are compared.
constexpr int kSamples = 101;

void expect_error(const std::function<void()>& f, const std::string& part) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one containing \"" << part << "\"";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << "message: " << e.what();
  }
}

// --- data and small references -----------------------------------------------------

/// t_0 = start, then steps in [0.2, 2]: deliberately unequal intervals.
std::vector<double> random_nodes(std::size_t count, std::mt19937& rng, double start = 0) {
  std::uniform_real_distribution<double> step(0.2, 2);
  std::vector<double> t = {start};
  while (t.size() < count) t.push_back(t.back() + step(rng));
  return t;
}

std::vector<Vec3> random_points(std::size_t count, int dimension, std::mt19937& rng) {
  std::uniform_real_distribution<double> coordinate(-5, 5);
  std::vector<Vec3> P(count);
  for (Vec3& p : P) p = {coordinate(rng), coordinate(rng), dimension == 3 ? coordinate(rng) : 0.0};
  return P;
}

std::vector<double> random_values(std::size_t count, std::mt19937& rng) {
  std::uniform_real_distribution<double> value(-5, 5);
  std::vector<double> y(count);
  for (double& v : y) v = value(rng);
  return y;
}

double size_of(const std::vector<Vec3>& P) {
  double s = 1;
  for (Vec3 p : P) s = std::max({s, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return s;
}

double size_of(const std::vector<double>& y) {
  double s = 1;
  for (double v : y) s = std::max(s, std::abs(v));
  return s;
}

std::vector<double> samples(double a, double b, int count = kSamples) {
  std::vector<double> u;
  for (int k = 0; k < count; ++k) u.push_back(a + (b - a) * k / (count - 1));
  u.back() = b;
  return u;
}

/// de Casteljau on a cubic Bézier segment over [a, b] (ch. 1 §1.6).
Vec3 bezier_at(const BezierCurve& segment, double u) {
  const double s = (u - segment.a) / (segment.b - segment.a);
  std::vector<Vec3> b = segment.P;
  for (std::size_t r = 1; r < b.size(); ++r)
    for (std::size_t i = 0; i + r < b.size(); ++i) b[i] = lerp(b[i], b[i + 1], s);
  return b[0];
}

/// The largest |S^(k)(t_i)| over the nodes: the scale of a jump in S^(k).
double largest_derivative(const CubicSpline& s, int k) {
  double m = 1e-300;
  for (std::size_t i = 0; i < s.segments(); ++i) {
    m = std::max(m, norm(segment_derivative(s, i, s.t[i], k)));
    m = std::max(m, norm(segment_derivative(s, i, s.t[i + 1], k)));
  }
  return m;
}

/// Interpolation at every node and C2 at every interior node.
void expect_interpolating_c2(const CubicSpline& s, const std::vector<Vec3>& P) {
  const double scale = size_of(P);
  const std::size_t N = s.segments();
  for (std::size_t i = 0; i < P.size(); ++i)
    EXPECT_LE(norm(spline_point(s, s.t[i]) - P[i]), kExact * scale) << "node " << i;
  if (s.end == EndCondition::kPeriodic)
    EXPECT_LE(norm(spline_point(s, s.t[N]) - P[0]), kExact * scale) << "closing node";
  else
    EXPECT_LE(norm(segment_derivative(s, N - 1, s.t[N], 0) - P.back()), kExact * scale) << "last node";
  for (int k = 0; k <= 2; ++k) {
    const double size = largest_derivative(s, k);
    for (std::size_t i = 1; i < N; ++i) {
      const Vec3 left = segment_derivative(s, i - 1, s.t[i], k);
      const Vec3 right = segment_derivative(s, i, s.t[i], k);
      EXPECT_LE(norm(right - left), kC2JumpTolerance * size) << "derivative " << k << " jumps at t[" << i << "]";
    }
  }
}

/// The B-spline form and the Bézier segments equal the power form at
/// kSamples parameters over the whole domain.
void expect_forms_agree(const CubicSpline& s) {
  const double scale = std::max(largest_derivative(s, 0), 1.0);
  const BsplineCurve curve = bspline_curve(s);
  EXPECT_EQ(curve.U.size(), curve.P.size() + 4);
  const ParamInterval dom = domain(curve);
  EXPECT_EQ(dom.a, s.t.front());
  EXPECT_EQ(dom.b, s.t.back());
  const std::vector<BezierCurve> segments = bezier_segments(s);
  ASSERT_EQ(segments.size(), s.segments());
  for (double u : samples(s.t.front(), s.t.back())) {
    const Vec3 expected = spline_point(s, u);
    EXPECT_LE(norm(curve_point(curve, u) - expected), kExact * scale) << "B-spline form at u=" << u;
    EXPECT_LE(norm(bezier_at(segments[segment_index(s.t, u)], u) - expected), kExact * scale)
        << "Bezier form at u=" << u;
  }
}

/// The graph form of a function spline: curve_point(u) = (u, S(u), 0).
void expect_graph_agrees(const ScalarCubicSpline& s, const std::vector<double>& y) {
  const BsplineCurve graph = bspline_curve(s);
  EXPECT_EQ(graph.dimension, 2);
  const double t_size = std::max({1.0, std::abs(s.t.front()), std::abs(s.t.back())});
  for (double u : samples(s.t.front(), s.t.back())) {
    const Vec3 g = curve_point(graph, u);
    EXPECT_NEAR(g.x, u, kExact * t_size) << "u=" << u;
    EXPECT_NEAR(g.y, spline_value(s, u), kExact * size_of(y)) << "u=" << u;
    EXPECT_EQ(g.z, 0.0);
  }
}

// --- natural -----------------------------------------------------------------------------

// Ch. 1 §1.6: natural end conditions S''(t_0) = S''(t_N) = 0.
TEST(NaturalCubicSpline, SecondDerivativeIsZeroAtBothEnds) {
  std::mt19937 rng(1);  // fixed seed
  for (std::size_t count : {2u, 3u, 5u, 12u}) {
    const std::vector<double> t = random_nodes(count, rng);
    const CubicSpline s = natural_cubic_spline(t, random_points(count, 3, rng));
    const double size = largest_derivative(s, 2);
    EXPECT_LE(norm(spline_derivative(s, t.front(), 2)), kC2JumpTolerance * size) << count << " points";
    EXPECT_LE(norm(spline_derivative(s, t.back(), 2)), kC2JumpTolerance * size) << count << " points";
    const std::vector<double> y = random_values(count, rng);
    const ScalarCubicSpline f = natural_cubic_spline(t, y);
    EXPECT_NEAR(spline_derivative(f, t.front(), 2), 0, kExact * size_of(y));
    EXPECT_NEAR(spline_derivative(f, t.back(), 2), 0, kExact * size_of(y));
  }
}

TEST(NaturalCubicSpline, InterpolatesAndIsC2In2DAnd3D) {
  std::mt19937 rng(2);  // fixed seed
  for (int dimension : {2, 3}) {
    for (std::size_t count : {2u, 3u, 4u, 9u, 30u}) {
      const std::vector<double> t = random_nodes(count, rng, -3);
      const std::vector<Vec3> P = random_points(count, dimension, rng);
      const CubicSpline s = natural_cubic_spline(t, P);
      EXPECT_EQ(s.dimension, dimension);
      EXPECT_EQ(s.segments(), count - 1);
      expect_interpolating_c2(s, P);
      expect_forms_agree(s);
    }
  }
}

TEST(NaturalCubicSpline, FunctionGraphAsBsplineMatches) {
  std::mt19937 rng(3);  // fixed seed
  const std::vector<double> t = random_nodes(8, rng, 1);
  const std::vector<double> y = random_values(8, rng);
  const ScalarCubicSpline s = natural_cubic_spline(t, y);
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(spline_value(s, t[i]), y[i], kExact * size_of(y));
  expect_graph_agrees(s, y);
}

// A natural spline reproduces straight lines (they have S'' = 0 everywhere).
// Chordal nodes make the data linear in t, so X(t) = P_0 + t * direction exactly;
// uniform nodes still keep every point on the line (each coordinate is the
// same linear combination of the data).
TEST(NaturalCubicSpline, ReproducesStraightLines) {
  const Vec3 start = {1, -2, 0.5}, direction = normalized(Vec3{3, 4, 12});  // |(3,4,12)| = 13
  const std::vector<double> along = {0, 0.5, 2, 2.25, 6, 7};
  std::vector<Vec3> P;
  for (double s : along) P.push_back(start + s * direction);
  const CubicSpline chordal = natural_cubic_spline(parameters(P, Parameterization::kChordal), P);
  for (double u : samples(0, along.back()))
    EXPECT_LE(norm(spline_point(chordal, u) - (start + u * direction)), kExact * size_of(P)) << "u=" << u;
  const CubicSpline uniform = natural_cubic_spline(parameters(P, Parameterization::kUniform), P);
  for (double u : samples(0, uniform.t.back())) {
    const Vec3 off_line = cross(spline_point(uniform, u) - start, direction);
    EXPECT_LE(norm(off_line), kExact * size_of(P)) << "u=" << u;
  }
  // Two points: the spline is the segment between them.
  const CubicSpline two = natural_cubic_spline({0, 2}, {P[0], P[3]});
  EXPECT_LE(norm(spline_point(two, 1) - (P[0] + P[3]) / 2), kExact * size_of(P));
}

// --- minimum norm ------------------------------------------------------------------------------

/// Relative round-off allowed when two bending energies that are equal in exact arithmetic
/// are compared. Energies reach 1e10 (the node polynomial of degree 8 on [0, 14]); the
/// largest relative discrepancy measured here was about 3e-14, so 1e-9 is a wide margin
/// that still fails on any real loss of the identity.
constexpr double kEnergyTolerance = 1e-9;

/// J(f) = integral over [t_0, t_N] of (s'' + w'')^2, by an n-point Gauss-Legendre rule on
/// every segment: exact for (s'' + w'')^2 of degree <= 2n - 1 (quadrature.h). s'' is linear
/// per segment; w'' is the perturbation's second derivative (a polynomial, or zero).
double bending_energy(const ScalarCubicSpline& s, const std::vector<double>& w2, int n) {
  const GaussRule rule = gauss_legendre(n);
  double sum = 0;
  for (std::size_t i = 0; i < s.segments(); ++i) {
    const double lo = s.t[i], hi = s.t[i + 1], half = (hi - lo) / 2;
    for (std::size_t k = 0; k < rule.x.size(); ++k) {
      const double u = lo + half * (rule.x[k] + 1);
      double f2 = segment_derivative(s, i, u, 2), power = 1;
      for (double c : w2) f2 += c * power, power *= u;
      sum += rule.w[k] * half * f2 * f2;
    }
  }
  return sum;
}

/// w(t) = prod_i (t - t_i), vanishing at every node; returns the coefficients of w''
/// (ascending powers), exact polynomial arithmetic.
std::vector<double> node_polynomial_second_derivative(const std::vector<double>& t) {
  std::vector<double> w = {1};
  for (double ti : t) {
    std::vector<double> next(w.size() + 1, 0);
    for (std::size_t j = 0; j < w.size(); ++j) next[j + 1] += w[j], next[j] -= ti * w[j];
    w = next;
  }
  std::vector<double> w2;
  for (std::size_t j = 2; j < w.size(); ++j) w2.push_back(j * (j - 1.0) * w[j]);
  return w2;
}

// Property (Holladay's theorem; de Boor, "A Practical Guide to Splines", ch. V): among all
// C2 functions f through the data, the natural cubic spline s has the least integral of
// f''^2, and exactly J(f) = J(s) + J(f - s) because the cross term integral s''(f - s)''
// vanishes for natural ends. Perturbed interpolants: (a) clamped splines with other end
// slopes, (b) s + eps prod (t - t_i), a polynomial vanishing at every node. The integrals
// are exact (Gauss-Legendre with enough points per piece), so the identity holds to
// round-off and J(f) > J(s) whenever f differs from s.
TEST(NaturalCubicSpline, HasTheLeastBendingEnergyOfAllC2Interpolants) {
  std::mt19937 rng(19);  // fixed seed
  std::uniform_real_distribution<double> slope(-5, 5), eps(-0.5, 0.5);
  for (std::size_t count : {2u, 3u, 5u, 8u}) {
    for (int trial = 0; trial < 25; ++trial) {
      const std::vector<double> t = random_nodes(count, rng);
      const std::vector<double> y = random_values(count, rng);
      const ScalarCubicSpline s = natural_cubic_spline(t, y);
      const double js = bending_energy(s, {}, 2);
      // (a) clamped splines: f - s is a piecewise cubic, (f - s)''^2 quadratic per piece.
      const ScalarCubicSpline f = clamped_cubic_spline(t, y, slope(rng), slope(rng));
      ScalarCubicSpline diff = f;
      for (std::size_t i = 0; i < f.segments(); ++i) {
        diff.a[i] -= s.a[i], diff.b[i] -= s.b[i], diff.c[i] -= s.c[i], diff.d[i] -= s.d[i];
      }
      const double jf = bending_energy(f, {}, 2), jd = bending_energy(diff, {}, 2);
      EXPECT_GT(jf, js) << count << " nodes, trial " << trial;
      EXPECT_NEAR(jf, js + jd, kEnergyTolerance * std::max(1.0, jf)) << count << " nodes";
      // (b) s + e w with w = prod (t - t_i) of degree N + 1 = count: (s'' + e w'')^2 has
      // degree 2N - 2, so N Gauss points per piece are exact; N + 2 are used.
      // J = J(s) + e^2 J(w).
      const double e = eps(rng);
      std::vector<double> w2 = node_polynomial_second_derivative(t);
      const ScalarCubicSpline zero = natural_cubic_spline(t, std::vector<double>(count, 0.0));
      const int n = static_cast<int>(count) + 1;
      const double jw = bending_energy(zero, w2, n);
      for (double& c : w2) c *= e;
      const double jp = bending_energy(s, w2, n);
      EXPECT_GT(jp, js) << count << " nodes, trial " << trial;
      EXPECT_NEAR(jp, js + e * e * jw, kEnergyTolerance * std::max(1.0, jp)) << count;
    }
  }
  // The clamped spline whose end slopes are the natural spline's own is the natural spline.
  const std::vector<double> t = {0, 1, 2.5, 3}, y = {1, -1, 2, 0};
  const ScalarCubicSpline s = natural_cubic_spline(t, y);
  const ScalarCubicSpline f = clamped_cubic_spline(t, y, spline_derivative(s, 0, 1),
                                                   spline_derivative(s, 3, 1));
  EXPECT_NEAR(bending_energy(f, {}, 2), bending_energy(s, {}, 2),
              kEnergyTolerance * bending_energy(s, {}, 2));
}

// --- clamped -----------------------------------------------------------------------------------

// S'(t_0) and S'(t_N) are the given end derivatives.
TEST(ClampedCubicSpline, EndDerivativesMatch) {
  std::mt19937 rng(4);  // fixed seed
  for (std::size_t count : {2u, 3u, 7u, 20u}) {
    const std::vector<double> t = random_nodes(count, rng);
    const std::vector<Vec3> P = random_points(count, 3, rng);
    const Vec3 start = {1, -2, 3}, end = {-4, 0.5, 2};
    const CubicSpline s = clamped_cubic_spline(t, P, start, end);
    const double size = largest_derivative(s, 1);
    EXPECT_LE(norm(spline_derivative(s, t.front(), 1) - start), kExact * size) << count << " points";
    EXPECT_LE(norm(spline_derivative(s, t.back(), 1) - end), kExact * size) << count << " points";
    expect_interpolating_c2(s, P);
    expect_forms_agree(s);

    const std::vector<double> y = random_values(count, rng);
    const ScalarCubicSpline f = clamped_cubic_spline(t, y, 0.75, -2.5);
    EXPECT_NEAR(spline_derivative(f, t.front(), 1), 0.75, kExact * size_of(y));
    EXPECT_NEAR(spline_derivative(f, t.back(), 1), -2.5, kExact * size_of(y));
    expect_graph_agrees(f, y);
  }
}

// Property: a cubic polynomial is a cubic spline, so given its values at the
// nodes and its end derivatives the clamped spline is the polynomial itself,
// on any nodes.
TEST(ClampedCubicSpline, ReproducesACubicPolynomial) {
  std::mt19937 rng(5);  // fixed seed
  std::uniform_real_distribution<double> coefficient(-2, 2);
  for (int trial = 0; trial < 10; ++trial) {
    Vec3 c[4];
    for (Vec3& v : c) v = {coefficient(rng), coefficient(rng), coefficient(rng)};
    auto q = [&](double u) { return c[0] + u * (c[1] + u * (c[2] + u * c[3])); };
    auto dq = [&](double u) { return c[1] + u * (2.0 * c[2] + 3.0 * u * c[3]); };
    const std::vector<double> t = random_nodes(3 + static_cast<std::size_t>(trial), rng, -2);
    std::vector<Vec3> P;
    for (double u : t) P.push_back(q(u));
    const CubicSpline s = clamped_cubic_spline(t, P, dq(t.front()), dq(t.back()));
    for (double u : samples(t.front(), t.back()))
      EXPECT_LE(norm(spline_point(s, u) - q(u)), kExact * size_of(P)) << "trial " << trial << " u=" << u;
    // The scalar version on the x components.
    std::vector<double> x;
    for (Vec3 p : P) x.push_back(p.x);
    const ScalarCubicSpline f = clamped_cubic_spline(t, x, dq(t.front()).x, dq(t.back()).x);
    for (double u : samples(t.front(), t.back()))
      EXPECT_NEAR(spline_value(f, u), q(u).x, kExact * size_of(P)) << "trial " << trial << " u=" << u;
  }
}

// --- periodic ----------------------------------------------------------------------------------

// Ch. 1 §1.6: periodic conditions S(t_0) = S(t_N), S'(t_0) = S'(t_N), S''(t_0) = S''(t_N).
TEST(PeriodicCubicSpline, ValueSlopeAndCurvatureMatchAcrossTheSeam) {
  std::mt19937 rng(6);  // fixed seed
  for (int dimension : {2, 3}) {
    for (std::size_t count : {2u, 3u, 4u, 10u, 25u}) {
      const std::vector<Vec3> P = random_points(count, dimension, rng);
      const std::vector<double> t = random_nodes(count + 1, rng, 0.5);
      const CubicSpline s = periodic_cubic_spline(t, P);
      EXPECT_EQ(s.segments(), count);
      for (int k = 0; k <= 2; ++k) {
        const Vec3 at_start = spline_derivative(s, t.front(), k);
        const Vec3 at_end = spline_derivative(s, t.back(), k);
        EXPECT_LE(norm(at_end - at_start), kC2JumpTolerance * largest_derivative(s, k))
            << "derivative " << k << ", " << count << " points";
      }
      expect_interpolating_c2(s, P);
      expect_forms_agree(s);
    }
  }
}

// The periodic B-spline closes by itself: its last three control points are
// its first three, over the periodic knots.
TEST(PeriodicCubicSpline, BsplineFormRepeatsItsFirstThreeControlPoints) {
  std::mt19937 rng(7);  // fixed seed
  const std::vector<Vec3> P = random_points(6, 2, rng);
  const std::vector<double> t = parameters(P, Parameterization::kCentripetal, true);
  const BsplineCurve curve = bspline_curve(periodic_cubic_spline(t, P));
  const std::size_t n = curve.P.size() - 1;
  ASSERT_EQ(curve.P.size(), P.size() + 3);
  for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(curve.P[n - 2 + j], curve.P[j]);
  // Knot spacing repeats with the period: U[j+1] - U[j] = D_{(j-3) mod N}.
  for (std::size_t j = 0; j + 1 < curve.U.size(); ++j) {
    const std::size_t i = (j + 3 * P.size() - 3) % P.size();
    EXPECT_NEAR(curve.U[j + 1] - curve.U[j], t[i + 1] - t[i], kExact * t.back()) << "U[" << j << "]";
  }
  EXPECT_EQ(curve.dimension, 2);
}

// Property: a closed curve has no first point. Starting the same loop at P_1
// (nodes shifted along) gives the same curve.
TEST(PeriodicCubicSpline, DoesNotDependOnWhereTheLoopStarts) {
  std::mt19937 rng(8);  // fixed seed
  const std::vector<Vec3> P = random_points(7, 3, rng);
  const std::vector<double> t = random_nodes(8, rng);
  std::vector<Vec3> rotated(P.begin() + 1, P.end());
  rotated.push_back(P[0]);
  std::vector<double> shifted(t.begin() + 1, t.end());
  shifted.push_back(t.back() + (t[1] - t[0]));
  const CubicSpline s = periodic_cubic_spline(t, P), r = periodic_cubic_spline(shifted, rotated);
  for (double u : samples(t[1], t.back()))
    EXPECT_LE(norm(spline_point(r, u) - spline_point(s, u)), kExact * size_of(P)) << "u=" << u;
}

TEST(PeriodicCubicSpline, FunctionIsPeriodicAndItsGraphMatches) {
  std::mt19937 rng(9);  // fixed seed
  const std::vector<double> y = random_values(5, rng);
  const std::vector<double> t = random_nodes(6, rng);
  const ScalarCubicSpline s = periodic_cubic_spline(t, y);
  for (int k = 0; k <= 2; ++k)
    EXPECT_NEAR(spline_derivative(s, t.front(), k), spline_derivative(s, t.back(), k), kExact * 100 * size_of(y))
        << "derivative " << k;
  expect_graph_agrees(s, y);
}

// --- the lecture's interpolating Bézier spline ------------------------------------------------

// Ch. 1 §1.6, example: three points p_0, p_1, p_2, two segments with
// D_0 = D_1 = 1, b_0 = p_0, b_3 = p_1, b_6 = p_2; choose b_1 and b_5; solve
//     3 b_1 = 2 d_0 + d_1,  6 b_3 = d_0 + 4 d_1 + d_2,  3 b_5 = d_1 + 2 d_2;
// then b_2 and b_4. The lecture gives no numbers; these are chosen here:
//   p = (0,0), (3,3), (6,0);  b_1 = (1,2), b_5 = (5,2).
// By hand: d_0 = (3 b_1 - d_1)/2 and d_2 = (3 b_5 - d_1)/2, so the middle row
// reads 6 b_3 = 3/2 (b_1 + b_5) + 3 d_1, d_1 = 2 b_3 - (b_1 + b_5)/2 = (3,4);
// then d_0 = (0,1), d_2 = (6,1), and on the legs b_2 = (d_0 + 2 d_1)/3 = (2,3),
// b_4 = (2 d_1 + d_2)/3 = (4,3). Checks: b_2 + b_4 = 2 b_3 (C1) and
// b_1 - 2 b_2 + b_3 = (0,-1) = b_3 - 2 b_4 + b_5 (C2).
TEST(BezierSplineThrough, LectureThreePointExampleByHand) {
  const std::vector<double> t = {0, 1, 2};
  const std::vector<Vec3> P = {{0, 0, 0}, {3, 3, 0}, {6, 0, 0}};
  const Vec3 b1 = {1, 2, 0}, b5 = {5, 2, 0};
  const std::vector<BezierCurve> spline = bezier_spline_through(t, P, b1, b5);
  ASSERT_EQ(spline.size(), 2u);
  const std::vector<Vec3> expected = {{0, 0, 0}, {1, 2, 0}, {2, 3, 0}, {3, 3, 0}, {4, 3, 0}, {5, 2, 0}, {6, 0, 0}};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_LE(norm(spline[0].P[k] - expected[k]), kHandTolerance) << "b_" << k;
    EXPECT_LE(norm(spline[1].P[k] - expected[3 + k]), kHandTolerance) << "b_" << 3 + k;
  }
  EXPECT_EQ(spline[0].a, 0.0);
  EXPECT_EQ(spline[0].b, 1.0);
  EXPECT_EQ(spline[1].a, 1.0);
  EXPECT_EQ(spline[1].b, 2.0);
  EXPECT_EQ(spline[0].dimension, 2);
  // Our de Boor points use D_{-1} = D_2 = 0 (the lecture's general note), so the
  // end ones are b_1 and b_5; the middle one is the lecture's d_1 = (3,4).
  const std::vector<Vec3> d = de_boor_points_through(t, P, b1, b5);
  ASSERT_EQ(d.size(), 3u);
  EXPECT_LE(norm(d[0] - b1), kHandTolerance);
  EXPECT_LE(norm(d[1] - Vec3{3, 4, 0}), kHandTolerance);
  EXPECT_LE(norm(d[2] - b5), kHandTolerance);
  // The same curve as the clamped spline with S'(t_0) = 3 (b_1 - b_0) / D_0 = (3,6)
  // and S'(t_2) = 3 (b_6 - b_5) / D_1 = (3,-6) (Bézier end derivatives).
  const std::vector<BezierCurve> clamped = bezier_segments(clamped_cubic_spline(t, P, {3, 6, 0}, {3, -6, 0}));
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_LE(norm(clamped[0].P[k] - expected[k]), kHandTolerance) << "b_" << k;
    EXPECT_LE(norm(clamped[1].P[k] - expected[3 + k]), kHandTolerance) << "b_" << 3 + k;
  }
}

// The lecture's equations 1), 2) and 3) for an interpolating cubic Bézier spline
// (ch. 1 §1.6), checked at every interior node of unequal intervals:
//   1) b_{3(i+1)+1} = b_{3(i+1)} + D_{i+1}/D_i (b_{3(i+1)} - b_{3(i+1)-1})        (C1)
//   2) d_{i+1} = b_{3(i+1)-1} + D_{i+1}/D_i (b_{3(i+1)-1} - b_{3(i+1)-2})
//   3) b_{3(i+1)+2} = b_{3(i+1)+1} + D_{i+1}/D_i (b_{3(i+1)+1} - d_{i+1})        (with 1: C2)
TEST(BezierSplineThrough, SatisfiesTheLectureEquationsOneTwoThree) {
  std::mt19937 rng(10);  // fixed seed
  const std::vector<double> t = random_nodes(9, rng);
  const std::vector<Vec3> P = random_points(9, 3, rng);
  for (EndCondition end : {EndCondition::kNatural, EndCondition::kClamped}) {
    const Vec3 b1 = P[0] + Vec3{1, 1, 1}, b_last = P.back() - Vec3{0, 2, 1};
    const std::vector<BezierCurve> s =
        end == EndCondition::kNatural ? bezier_spline_through(t, P, end) : bezier_spline_through(t, P, b1, b_last);
    const std::vector<Vec3> d =
        end == EndCondition::kNatural ? de_boor_points_through(t, P, end) : de_boor_points_through(t, P, b1, b_last);
    const double scale = size_of(d);
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
      const double r = (t[i + 2] - t[i + 1]) / (t[i + 1] - t[i]);
      const Vec3 b_node = s[i].P[3], b_before = s[i].P[2], b_before2 = s[i].P[1];
      const Vec3 b_after = s[i + 1].P[1], b_after2 = s[i + 1].P[2];
      EXPECT_LE(norm(b_after - (b_node + r * (b_node - b_before))), kExact * scale) << "1) at node " << i + 1;
      EXPECT_LE(norm(d[i + 1] - (b_before + r * (b_before - b_before2))), kExact * scale) << "2) at node " << i + 1;
      EXPECT_LE(norm(b_after2 - (b_after + r * (b_after - d[i + 1]))), kExact * scale) << "3) at node " << i + 1;
    }
  }
}

// Two constructions of the same spline agree: the lecture's power-form
// algorithm (c_i system) and the lecture's de Boor point algorithm, for natural,
// clamped (b_1 = p_0 + D_0 S'(t_0) / 3) and periodic ends, on unequal intervals.
TEST(BezierSplineThrough, EqualsThePowerFormSpline) {
  std::mt19937 rng(11);  // fixed seed
  for (std::size_t count : {2u, 3u, 4u, 8u, 40u}) {
    const std::vector<Vec3> P = random_points(count, 3, rng);
    const std::vector<double> t = random_nodes(count, rng);
    const double scale = size_of(P);
    auto expect_same = [&](const std::vector<BezierCurve>& through, const CubicSpline& s, const char* what) {
      ASSERT_EQ(through.size(), s.segments()) << what;
      for (double u : samples(s.t.front(), s.t.back()))
        EXPECT_LE(norm(bezier_at(through[segment_index(s.t, u)], u) - spline_point(s, u)), kExact * scale)
            << what << ", " << count << " points, u=" << u;
    };
    expect_same(bezier_spline_through(t, P, EndCondition::kNatural), natural_cubic_spline(t, P), "natural");
    const Vec3 start = {2, -1, 0.5}, end = {-1, -1, 3};
    const double D0 = t[1] - t[0], DN = t.back() - t[t.size() - 2];
    expect_same(bezier_spline_through(t, P, P.front() + D0 / 3 * start, P.back() - DN / 3 * end),
                clamped_cubic_spline(t, P, start, end), "clamped");
    const std::vector<double> closed_t = random_nodes(count + 1, rng);
    expect_same(bezier_spline_through(closed_t, P, EndCondition::kPeriodic), periodic_cubic_spline(closed_t, P),
                "periodic");
  }
}

// The de Boor points of the lecture's algorithm are the control points of the
// B-spline form (clamped knots: Q_0 = p_0, Q_1..Q_{N+1} = d_0..d_N, Q_{N+2} = p_N;
// periodic: Q_1..Q_N = d_0..d_{N-1}).
TEST(BezierSplineThrough, DeBoorPointsAreTheBsplineControlPoints) {
  std::mt19937 rng(12);  // fixed seed
  const std::vector<Vec3> P = random_points(7, 2, rng);
  const std::vector<double> t = parameters(P, Parameterization::kChordal);
  const double scale = size_of(P);
  const std::vector<Vec3> d = de_boor_points_through(t, P, EndCondition::kNatural);
  const BsplineCurve curve = bspline_curve(natural_cubic_spline(t, P));
  ASSERT_EQ(curve.P.size(), d.size() + 2);
  EXPECT_EQ(curve.P.front(), P.front());
  EXPECT_EQ(curve.P.back(), P.back());
  for (std::size_t i = 0; i < d.size(); ++i) EXPECT_LE(norm(curve.P[i + 1] - d[i]), kExact * scale) << "d_" << i;

  const std::vector<double> closed_t = parameters(P, Parameterization::kChordal, true);
  const std::vector<Vec3> cd = de_boor_points_through(closed_t, P, EndCondition::kPeriodic);
  const BsplineCurve closed = bspline_curve(periodic_cubic_spline(closed_t, P));
  ASSERT_EQ(cd.size(), P.size());
  for (std::size_t i = 0; i < cd.size(); ++i) EXPECT_LE(norm(closed.P[i + 1] - cd[i]), kExact * scale) << "d_" << i;
}

// A doubt about the lecture, recorded as a test. The lecture's row for the node
// b_{3(i+1)} multiplies the whole equation by one sum S_i = D_{i-1} + D_i + D_{i+1}:
//   S_i (D_i + D_{i+1}) b_{3(i+1)} = D_{i+1} (D_{i+1} d_i + (D_{i-1} + D_i) d_{i+1})
//                                  + D_i ((D_{i+1} + D_{i+2}) d_{i+1} + D_i d_{i+2}),
// but the second bracket is S_{i+1} b_{3(i+1)+1}, so it must be divided by S_{i+1}:
//   (D_i + D_{i+1}) b_{3(i+1)} = D_{i+1} (...) / S_i + D_i (...) / S_{i+1}.
// Both agree when the intervals are equal (the lecture's special case
// 6 b_3 = d_0 + 4 d_1 + d_2). On unequal intervals only the second holds.
TEST(BezierSplineThrough, LectureNodeRowNeedsTwoDenominatorsOnUnequalIntervals) {
  const std::vector<double> t = {0, 1, 3, 3.5, 6};  // D = 1, 2, 0.5, 2.5
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}, {6, 1, 0}};
  const std::vector<Vec3> d = de_boor_points_through(t, P, EndCondition::kNatural);
  auto D = [&](long i) { return i < 0 || i + 1 >= static_cast<long>(t.size()) ? 0.0 : t[i + 1] - t[i]; };
  double lecture_row_miss = 0;
  for (long i = 0; i + 2 < static_cast<long>(t.size()); ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    const Vec3 node = P[k + 1];
    const Vec3 left = D(i + 1) * (D(i + 1) * d[k] + (D(i - 1) + D(i)) * d[k + 1]);
    const Vec3 right = D(i) * ((D(i + 1) + D(i + 2)) * d[k + 1] + D(i) * d[k + 2]);
    const double S_i = D(i - 1) + D(i) + D(i + 1), S_next = D(i) + D(i + 1) + D(i + 2);
    const Vec3 corrected = (D(i) + D(i + 1)) * node - (left / S_i + right / S_next);
    EXPECT_LE(norm(corrected), kExact * size_of(P)) << "node " << i + 1;
    const Vec3 as_printed = S_i * (D(i) + D(i + 1)) * node - (left + right);
    lecture_row_miss = std::max(lecture_row_miss, norm(as_printed));
  }
  EXPECT_GT(lecture_row_miss, 0.1);
}

// Ch. 1 §1.6: "If there are cusps (C0 transitions, e.g. the cross section
// of a wing of an airplane) then natural splines can be used with the cusp as
// start and end point." The lecture gives no coordinates; the section here is
// NACA 0012 (NACA Report 824: y_t = 5 tau (0.2969 sqrt x - 0.1260 x - 0.3516 x^2
// + 0.2843 x^3 - 0.1036 x^4), tau = 0.12, the closed-trailing-edge coefficient),
// traced from the trailing edge over the top to the nose and back underneath.
// Its trailing edge has an included angle of about 16.5 degrees.
TEST(CubicSplineWingSection, NaturalSplineKeepsTheTrailingEdgeCusp) {
  const int K = 12;  // points per surface, cosine spacing
  auto thickness = [](double x) {
    return 5 * 0.12 * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1036 * x * x * x * x);
  };
  std::vector<Vec3> P;
  for (int k = K; k >= 0; --k) {  // upper surface, trailing edge to nose
    const double x = (1 - std::cos(kPi * k / K)) / 2;
    P.push_back({x, thickness(x), 0});
  }
  for (int k = 1; k <= K; ++k) {  // lower surface, nose to trailing edge
    const double x = (1 - std::cos(kPi * k / K)) / 2;
    P.push_back({x, -thickness(x), 0});
  }
  P.back() = P.front();  // the cusp: start and end point (thickness(1) is 0 up to rounding)
  const CubicSpline natural = natural_cubic_spline(parameters(P, Parameterization::kChordal), P);
  const double t_end = natural.t.back();
  // Closed through the cusp ...
  EXPECT_LE(norm(spline_point(natural, t_end) - spline_point(natural, 0)), kExact);
  // ... with a C0 transition there: leaving along the top the curve heads
  // forward (-x), arriving along the bottom it heads back (+x). A smooth seam
  // would have the two tangents parallel (0 degrees apart).
  const Vec3 leaving = normalized(spline_derivative(natural, 0, 1));
  const Vec3 arriving = normalized(spline_derivative(natural, t_end, 1));
  EXPECT_LT(leaving.x, 0);
  EXPECT_GT(arriving.x, 0);
  EXPECT_GT(std::acos(dot(leaving, arriving)) * 180 / kPi, 90.0);

  // A periodic spline through the same points (the cusp given once) is C2 at
  // the trailing edge instead: it rounds the edge off. The section is
  // symmetric about the chord, so the rounded edge is crossed square to the
  // chord: x' = 0 and the tangent points up, from the bottom surface to the top.
  const std::vector<Vec3> once(P.begin(), P.end() - 1);
  const CubicSpline periodic = periodic_cubic_spline(parameters(once, Parameterization::kChordal, true), once);
  const Vec3 seam = normalized(spline_derivative(periodic, 0, 1));
  EXPECT_LE(std::abs(seam.x), kExact);
  EXPECT_GT(seam.y, 0);
  // The rounded edge stays within the section: no point lies behind x = 1.
  double periodic_back = 0;
  for (double u : samples(0, periodic.t.back(), 2001))
    periodic_back = std::max(periodic_back, spline_point(periodic, u).x);
  EXPECT_LE(periodic_back, 1 + kExact);
}

// --- evaluation ------------------------------------------------------------------------------------

// u == t_i belongs to segment i; u == t_N to the last segment.
TEST(SegmentIndex, NodesStartTheirSegmentAndTheEndStaysInTheLast) {
  const std::vector<double> t = {0, 1, 2.5, 4};
  EXPECT_EQ(segment_index(t, 0), 0u);
  EXPECT_EQ(segment_index(t, 0.999), 0u);
  EXPECT_EQ(segment_index(t, 1), 1u);
  EXPECT_EQ(segment_index(t, 2.5), 2u);
  EXPECT_EQ(segment_index(t, 4), 2u);
}

// A cubic's 4th and higher derivatives vanish; the 3rd is 6 d_i.
TEST(SplineDerivative, HigherOrdersOfACubic) {
  const CubicSpline s = natural_cubic_spline({0, 1, 2}, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}});
  EXPECT_EQ(spline_derivative(s, 0.5, 4), Vec3{});
  EXPECT_LE(norm(spline_derivative(s, 0.5, 3) - 6.0 * s.d[0]), kHandTolerance);
}

// --- errors -------------------------------------------------------------------------------------------

TEST(CubicSplineErrors, EmptyInputIsRejected) {
  expect_error([] { natural_cubic_spline({}, std::vector<Vec3>{}); }, "natural_cubic_spline: 0 points given");
  expect_error([] { periodic_cubic_spline({}, std::vector<double>{}); }, "periodic_cubic_spline: 0 points given");
  expect_error([] { bezier_spline_through({}, {}, EndCondition::kNatural); }, "0 points given");
}

TEST(CubicSplineErrors, OnePointIsRejected) {
  expect_error([] { natural_cubic_spline({0}, std::vector<double>{1}); }, "1 point given, at least 2 needed");
  expect_error([] { clamped_cubic_spline({0}, std::vector<Vec3>{{1, 2, 3}}, {}, {}); }, "1 point given");
  expect_error([] { periodic_cubic_spline({0, 1}, std::vector<Vec3>{{1, 2, 3}}); }, "1 point given");
}

TEST(CubicSplineErrors, NanIsRejectedWithItsName) {
  const double nan = std::nan("");
  expect_error([&] { natural_cubic_spline({0, 1, 2}, std::vector<Vec3>{{0, 0, 0}, {1, nan, 0}, {2, 0, 0}}); },
               "P[1]=(1, nan, 0) is not finite");
  expect_error([&] { natural_cubic_spline({0, 1, 2}, std::vector<double>{0, nan, 2}); }, "y[1]=nan is not finite");
  expect_error([&] { natural_cubic_spline({0, nan, 2}, std::vector<double>{0, 1, 2}); }, "t[1]=nan is not finite");
  expect_error([&] { clamped_cubic_spline({0, 1}, std::vector<double>{0, 1}, nan, 0); },
               "start derivative=nan is not finite");
}

// Coincident nodes: t must increase strictly (coincident points under a
// chordal parameterization are caught earlier, by parameters()).
TEST(CubicSplineErrors, CoincidentNodesAreRejected) {
  expect_error([] { natural_cubic_spline({0, 1, 1, 2}, std::vector<double>{0, 1, 2, 3}); },
               "t[2]=1 <= t[1]=1 (nodes must increase strictly)");
  expect_error([] { bezier_spline_through({0, 2, 1}, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, EndCondition::kNatural); },
               "t[2]=1 <= t[1]=2");
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 1, 0}, {1, 1, 0}};
  expect_error([&] { natural_cubic_spline(parameters(P, Parameterization::kChordal), P); },
               "P[1]=(1, 1, 0) and P[2]=(1, 1, 0) coincide");
}

TEST(CubicSplineErrors, NodeCountMustFitThePoints) {
  expect_error([] { natural_cubic_spline({0, 1}, std::vector<double>{0, 1, 2}); }, "2 nodes t for 3 points (3 needed)");
  expect_error([] { periodic_cubic_spline({0, 1, 2}, std::vector<double>{0, 1, 2}); },
               "3 nodes t for 3 points (4 needed: a closed spline has one more node than points)");
}

// A closed spline is given each point once.
TEST(CubicSplineErrors, PeriodicWithRepeatedFirstPointIsRejected) {
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}};
  expect_error([&] { periodic_cubic_spline({0, 1, 2, 3, 4}, P); }, "P[3]=(0, 0, 0) repeats P[0]");
  expect_error([&] { bezier_spline_through({0, 1, 2, 3, 4}, P, EndCondition::kPeriodic); }, "repeats P[0]");
}

TEST(CubicSplineErrors, EvaluationOutsideTheDomainIsRejected) {
  const CubicSpline s = natural_cubic_spline({0, 1, 2}, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}});
  expect_error([&] { spline_point(s, 2.5); }, "t=2.5 outside [0, 2]");
  expect_error([&] { spline_point(s, std::nan("")); }, "t=nan outside [0, 2]");
  expect_error([&] { spline_derivative(s, 1, -1); }, "derivative order k=-1");
}

TEST(CubicSplineErrors, ClampedBezierEndsNeedTheirPoints) {
  expect_error([] { bezier_spline_through({0, 1}, {{0, 0, 0}, {1, 0, 0}}, EndCondition::kClamped); },
               "clamped ends need the inner Bezier points");
}

}  // namespace
}  // namespace gllab::spline
