// tests/deform/volume_test.cpp — trivariate Bernstein and B-spline volumes
// (common/deform/volume.cpp).
//
// Every expected value names its origin: linear precision of the Greville
// abscissae (de Boor, "A Practical Guide to Splines", ch. IX), Sederberg and
// Parry's triple sum written out with binomial coefficients (SIGGRAPH '86,
// eq. 2), the support of a B-spline (The NURBS Book, 2nd ed., property P2.1),
// the positivity of the Bernstein polynomials on (0, 1), or a central
// difference whose error is c h^2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "deform/volume.h"
#include "deform_checks.h"
#include "spline/basis.h"

namespace gllab::deform {
namespace {

using testing::error_of;
using testing::kOrderSlack;
using testing::kUlp;
using testing::max_abs;
using testing::observed_order;
using testing::Random;
using testing::record;

// ---- tolerances (named, never loosened to pass) -----------------------------

/// The identity lattice reproduces (s, t, u) to 1e-15 (the bound) up
/// to degree 3 (measured: at most 3.5 ulps, 7.8e-16). It is not attainable
/// at high degree: A2.2's basis values of degree p sum to 1 only within about
/// p/2 ulps (measured: 2 ulps at p = 3, 7 ulps = 1.6e-15 at p = 15, over 1e5
/// random u), and the sums over the two other directions multiply into each
/// coordinate. Hence max(1e-15, (p + 1) ulps): 16 ulps = 3.6e-15 at the cap
/// p = 15 (measured 9.5 ulps there).
double identity_bound(int max_degree) { return std::max(1e-15, (max_degree + 1) * kUlp); }

/// The identity's Jacobian [Xs Xt Xu] = I: the derivative basis functions
/// sum to 0 and are each up to p / (the knot spacing) in size, so the sum
/// cancels terms of that size: (p + 1) ulps of p / spacing per direction,
/// twice for the partition of unity of the other two directions.
double identity_jacobian_bound(int p, double spacing) { return 2 * (p + 1) * kUlp * p / spacing; }

/// Two ways to evaluate one Bernstein volume (de Boor-Cox through A2.3 against
/// the explicit products of binomials and powers): each term of either has a
/// handful of roundings, (p + 1)^3 terms of sizes summing to the control
/// net's size. 32 ulps of that size (the largest |P|, or l times it for a
/// derivative).
constexpr double kTwoFormulas = 32 * kUlp;

/// Random lattices: identity plus displacements up to this, well inside the
/// box: enough to make X''' clearly nonzero.
constexpr double kJiggle = 0.15;

// ---- helpers ----------------------------------------------------------------

double dist(Vec3 a, Vec3 b) { return max_abs(a - b); }

Volume jiggled(Volume v, unsigned seed) {
  Random r(seed);
  for (Vec3& p : v.P) p += r.vec3(-kJiggle, kJiggle);
  return v;
}

double net_size(const Volume& v) {
  double s = 0;
  for (const Vec3& p : v.P) s = std::max(s, max_abs(p));
  return s;
}

/// C(n, k), exactly (n <= 15 here).
double binomial(int n, int k) {
  double c = 1;
  for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
  return c;
}

/// The Bernstein polynomial B_i^n(w) = C(n, i) w^i (1 - w)^(n - i).
double bernstein(int n, int i, double w) {
  if (i < 0 || i > n) return 0;
  return binomial(n, i) * std::pow(w, i) * std::pow(1 - w, n - i);
}

/// Sederberg and Parry's eq. (2) written out: X = sum_ijk C(l,i)(1-s)^(l-i)s^i
/// C(m,j)(1-t)^(m-j)t^j C(n,k)(1-u)^(n-k)u^k P_ijk, and its s-derivative
/// l sum (P_{i+1,j,k} - P_ijk) B_i^{l-1}(s) B_j^m(t) B_k^n(u) (likewise t, u).
VolumeDerivs sederberg_parry(const Volume& v, double s, double t, double u) {
  const int l = v.count[0] - 1, m = v.count[1] - 1, n = v.count[2] - 1;
  VolumeDerivs d;
  for (int i = 0; i <= l; ++i)
    for (int j = 0; j <= m; ++j)
      for (int k = 0; k <= n; ++k) {
        const Vec3 P = v.point(i, j, k);
        d.X += bernstein(l, i, s) * bernstein(m, j, t) * bernstein(n, k, u) * P;
        if (i < l)
          d.Xs += l * bernstein(l - 1, i, s) * bernstein(m, j, t) * bernstein(n, k, u) *
                  (v.point(i + 1, j, k) - P);
        if (j < m)
          d.Xt += m * bernstein(l, i, s) * bernstein(m - 1, j, t) * bernstein(n, k, u) *
                  (v.point(i, j + 1, k) - P);
        if (k < n)
          d.Xu += n * bernstein(l, i, s) * bernstein(m, j, t) * bernstein(n - 1, k, u) *
                  (v.point(i, j, k + 1) - P);
      }
  return d;
}

/// Random parameters in [0, 1]^3, preceded by the 8 corners, the 6 face
/// centres and points on the edges (s = 0, s = 1, ...).
std::vector<Vec3> parameters(unsigned seed, int random_count) {
  std::vector<Vec3> w;
  for (int c = 0; c < 8; ++c) w.push_back({double(c & 1), double((c >> 1) & 1), double(c >> 2)});
  for (double a : {0.0, 1.0}) {
    w.push_back({a, 0.5, 0.5});
    w.push_back({0.5, a, 0.5});
    w.push_back({0.5, 0.5, a});
    w.push_back({a, 0.3, 1.0});
    w.push_back({0.0, a, 0.7});
  }
  Random r(seed);
  for (int n = 0; n < random_count; ++n) w.push_back(r.vec3(0, 1));
  return w;
}

// ---- the identity -----------------------------------------------------------

void expect_identity(const Volume& v, const std::string& what) {
  SCOPED_TRACE(what);
  const int p = std::max({v.degree[0], v.degree[1], v.degree[2]});
  double spacing = 1;
  for (int a = 0; a < 3; ++a) spacing = std::min(spacing, 1.0 / (v.count[a] - v.degree[a]));
  double worst = 0, worst_j = 0;
  for (const Vec3 w : parameters(7, 400)) {  // seed 7: random points of the unit cube
    const VolumeDerivs d = volume_derivs(v, w.x, w.y, w.z);
    worst = std::max(worst, dist(d.X, w));
    worst_j = std::max({worst_j, dist(d.Xs, {1, 0, 0}), dist(d.Xt, {0, 1, 0}),
                        dist(d.Xu, {0, 0, 1})});
  }
  EXPECT_LE(worst, identity_bound(p));
  EXPECT_LE(worst_j, identity_jacobian_bound(p, spacing));
  record(what + ": point ulps", worst / kUlp);
  record(what + ": jacobian", worst_j);
}

TEST(Volume, IdentityLatticeMapsEveryPointToItself) {
  // volume.h: control points at the Greville abscissae; X(s, t, u) = (s, t, u)
  // by linear precision, and so J = I.
  expect_identity(bernstein_volume(4, 4, 4), "Bernstein 4 x 4 x 4");
  expect_identity(bernstein_volume(2, 2, 2), "Bernstein 2 x 2 x 2 (degree 1, trilinear)");
  expect_identity(bernstein_volume(3, 5, 2), "Bernstein 3 x 5 x 2 (degrees 2, 4, 1)");
  expect_identity(bspline_volume(6, 6, 6, 3), "B-spline 6 x 6 x 6 cubic");
  expect_identity(bspline_volume(7, 5, 3, 1), "B-spline degree 1");
  expect_identity(bspline_volume(4, 4, 4, 3), "B-spline count = degree + 1");
  expect_identity(bspline_volume(9, 5, 12, 2), "B-spline quadratic, unequal counts");
}

TEST(Volume, IdentityAtTheCapsMapsEveryPointToItself) {
  // The largest lattices the header allows: kMaxLatticePoints per direction
  // (cubic) and degree kMaxLatticeDegree (a Bernstein lattice of 16 points and
  // a B-spline of degree 15 with interior knots).
  expect_identity(bspline_volume(kMaxLatticePoints, kMaxLatticePoints, kMaxLatticePoints, 3),
                  "64 x 64 x 64 cubic");
  const int cap = kMaxLatticeDegree + 1;
  expect_identity(bernstein_volume(cap, cap, cap), "Bernstein 16 x 16 x 16 (degree 15)");
  expect_identity(bspline_volume(20, 17, 16, kMaxLatticeDegree), "B-spline degree 15");
}

TEST(Volume, CornersAreTheCornerControlPointsExactly) {
  // Endpoint interpolation of clamped knots (The NURBS Book P2.3 / the
  // Bernstein basis at 0 and 1): at a corner one basis function is 1 and the
  // others 0, so X is that control point bit for bit.
  for (const Volume& v : {jiggled(bernstein_volume(4, 3, 5), 11),
                          jiggled(bspline_volume(6, 7, 5, 3), 12)}) {
    const int l = v.count[0] - 1, m = v.count[1] - 1, n = v.count[2] - 1;
    for (int c = 0; c < 8; ++c) {
      const int i = c & 1, j = (c >> 1) & 1, k = c >> 2;
      EXPECT_EQ(volume_point(v, i, j, k), v.point(i * l, j * m, k * n)) << "corner " << c;
    }
  }
}

TEST(Volume, BsplineWithCountDegreePlusOneIsTheBernsteinLattice) {
  // volume.h: degree count - 1 is Bernstein; the knots are then
  // {0 x (p + 1), 1 x (p + 1)} and the two constructors give the same volume.
  const Volume b = bernstein_volume(4, 4, 4), s = bspline_volume(4, 4, 4, 3);
  EXPECT_TRUE(b.bernstein());
  EXPECT_TRUE(s.bernstein());
  EXPECT_FALSE(bspline_volume(5, 4, 4, 3).bernstein());
  EXPECT_EQ(b.count, s.count);
  EXPECT_EQ(b.degree, s.degree);
  ASSERT_EQ(b.P.size(), s.P.size());
  for (std::size_t k = 0; k < b.P.size(); ++k) EXPECT_EQ(b.P[k], s.P[k]);
  EXPECT_EQ(volume_knots(b, 0), (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}));
}

TEST(Volume, KnotsAreClampedUniformWithCountPlusDegreePlusOneEntries) {
  // spline/knots.h clamped_uniform_knots: p + 1 zeros, j / (n - p + 1), p + 1 ones.
  const Volume v = bspline_volume(6, 5, 2, 1);
  EXPECT_EQ(volume_knots(v, 0), (std::vector<double>{0, 0, 0.2, 0.4, 0.6, 0.8, 1, 1}));
  EXPECT_EQ(volume_knots(v, 1), (std::vector<double>{0, 0, 0.25, 0.5, 0.75, 1, 1}));
  EXPECT_EQ(volume_knots(v, 2), (std::vector<double>{0, 0, 1, 1}));
  EXPECT_EQ(volume_knots(bspline_volume(6, 6, 6, 3), 0),
            (std::vector<double>{0, 0, 0, 0, 1.0 / 3, 2.0 / 3, 1, 1, 1, 1}));
}

// ---- the Bernstein volume is Sederberg and Parry's --------------------------

TEST(Volume, BernsteinVolumeEqualsSederbergParryTripleSum) {
  // The explicit triple sum with binomial coefficients (helper above) and its
  // derivatives, on jiggled lattices of several shapes; seeds 21..24.
  const Volume lattices[] = {jiggled(bernstein_volume(4, 4, 4), 21),
                             jiggled(bernstein_volume(2, 3, 5), 22),
                             jiggled(bernstein_volume(6, 2, 3), 23),
                             jiggled(bernstein_volume(16, 16, 16), 24)};
  for (const Volume& v : lattices) {
    const double size = net_size(v);
    const int p = std::max({v.degree[0], v.degree[1], v.degree[2]});
    for (const Vec3 w : parameters(25, 60)) {  // seed 25
      const VolumeDerivs a = volume_derivs(v, w.x, w.y, w.z);
      const VolumeDerivs b = sederberg_parry(v, w.x, w.y, w.z);
      EXPECT_LE(dist(a.X, b.X), kTwoFormulas * size * (p + 1));
      EXPECT_LE(dist(a.Xs, b.Xs), kTwoFormulas * size * (p + 1) * 2 * v.degree[0]);
      EXPECT_LE(dist(a.Xt, b.Xt), kTwoFormulas * size * (p + 1) * 2 * v.degree[1]);
      EXPECT_LE(dist(a.Xu, b.Xu), kTwoFormulas * size * (p + 1) * 2 * v.degree[2]);
    }
  }
}

// ---- affine maps ------------------------------------------------------------

TEST(Volume, AffineControlPointsGiveTheAffineMap) {
  // Linear precision and the partition of unity: with P_ijk = A g_ijk + b the
  // volume is X = A (s, t, u) + b and [Xs Xt Xu] = A (an affine map of the
  // control points commutes with the convex combination). Bound: the identity's
  // bound (above) times |A| (row sums, here < 3), plus the rounding of b.
  const Mat3 A{{1.1, 0.2, -0.3}, {-0.4, 0.9, 0.25}, {0.15, -0.35, 1.2}};
  const Vec3 b{0.3, -0.7, 0.45};
  const double a_norm = 3;
  for (Volume v : {bernstein_volume(4, 4, 4), bspline_volume(6, 6, 6, 3),
                   bspline_volume(5, 6, 7, 2)}) {
    for (Vec3& p : v.P) p = A * p + b;
    const int p = std::max({v.degree[0], v.degree[1], v.degree[2]});
    const double spacing = 1.0 / (v.count[0] - v.degree[0]);
    for (const Vec3 w : parameters(31, 300)) {  // seed 31
      const VolumeDerivs d = volume_derivs(v, w.x, w.y, w.z);
      EXPECT_LE(dist(d.X, A * w + b), a_norm * identity_bound(p) + kUlp);
      const Mat3 J = d.jacobian();
      const double bound = a_norm * identity_jacobian_bound(p, spacing);
      EXPECT_LE(dist(J.c0, A.c0), bound);
      EXPECT_LE(dist(J.c1, A.c1), bound);
      EXPECT_LE(dist(J.c2, A.c2), bound);
    }
  }
}

// ---- derivatives ------------------------------------------------------------

/// The central differences of X at w along each axis with step h, against the
/// partials: the largest error per axis.
Vec3 central_difference_errors(const Volume& v, Vec3 w, double h) {
  const VolumeDerivs d = volume_derivs(v, w.x, w.y, w.z);
  const auto cd = [&](Vec3 e) {
    return (volume_point(v, w.x + h * e.x, w.y + h * e.y, w.z + h * e.z) -
            volume_point(v, w.x - h * e.x, w.y - h * e.y, w.z - h * e.z)) /
           (2 * h);
  };
  return {dist(cd({1, 0, 0}), d.Xs), dist(cd({0, 1, 0}), d.Xt), dist(cd({0, 0, 1}), d.Xu)};
}

void expect_second_order(const Volume& v, Vec3 w, double h) {
  // Central differences: (X(w + h) - X(w - h)) / 2h = X' + h^2/6 X''' + O(h^4),
  // so the error falls by 4 when h halves (order 2), for as long as
  // truncation (about 1e-5 here) dwarfs rounding (ulps / h, about 1e-14).
  const Vec3 e1 = central_difference_errors(v, w, h);
  const Vec3 e2 = central_difference_errors(v, w, h / 2);
  const Vec3 e3 = central_difference_errors(v, w, h / 4);
  static int n = 0;
  record("order s " + std::to_string(++n), observed_order(e1.x, e2.x));
  record("order u h/2 " + std::to_string(n), observed_order(e2.z, e3.z));
  for (const auto& [a, b, c] : {std::array<double, 3>{e1.x, e2.x, e3.x}, {e1.y, e2.y, e3.y},
                                {e1.z, e2.z, e3.z}}) {
    EXPECT_NEAR(observed_order(a, b), 2.0, kOrderSlack) << "errors " << a << ", " << b;
    EXPECT_NEAR(observed_order(b, c), 2.0, kOrderSlack) << "errors " << b << ", " << c;
  }
}

TEST(Volume, PartialsAgreeWithCentralDifferencesAtSecondOrder) {
  // Bernstein 4 x 4 x 4 and 5 x 4 x 6 (X''' nonzero after jiggling), and a
  // cubic B-spline at points whose +-h stencil stays inside one knot span
  // (spans of 1/3: the points below are 0.05 or more from a knot).
  const Volume b = jiggled(bernstein_volume(4, 4, 4), 41);
  const Volume c = jiggled(bernstein_volume(5, 4, 6), 42);
  const Volume s = jiggled(bspline_volume(6, 6, 6, 3), 43);
  const double h = 0.02;
  for (const Vec3 w : {Vec3{0.3, 0.6, 0.45}, Vec3{0.1, 0.85, 0.7}, Vec3{0.5, 0.5, 0.5}}) {
    expect_second_order(b, w, h);
    expect_second_order(c, w, h);
  }
  for (const Vec3 w : {Vec3{0.15, 0.5, 0.8}, Vec3{0.45, 0.9, 0.25}, Vec3{0.55, 0.1, 0.6}})
    expect_second_order(s, w, h);
}

TEST(Volume, CentralDifferencesOfATrilinearVolumeAreExact) {
  // Degree 1: X is linear in each variable along each axis, so the central
  // difference has no truncation error at all; what is left is rounding:
  // 2 values of size <= 1 + kJiggle, each a few ulps off, divided by 2h.
  const Volume v = jiggled(bspline_volume(5, 4, 3, 1), 51);
  const double h = 0.01;
  for (const Vec3 w : {Vec3{0.1, 0.1, 0.1}, Vec3{0.33, 0.6, 0.7}, Vec3{0.9, 0.4, 0.2}}) {
    const Vec3 e = central_difference_errors(v, w, h);
    EXPECT_LE(max_abs(e), 2 * 8 * kUlp / (2 * h));
  }
}

// ---- local and global control -----------------------------------------------

TEST(Volume, BsplineControlPointMovesXOnlyInsideItsSupport) {
  // The NURBS Book P2.1: N_{i,p} is zero outside [U_i, U_{i+p+1}), so P_ijk
  // acts on the (p + 1)^3 knot spans of the box U_i..U_{i+4} x ... (cubic).
  // 10 control points, cubic: spans of 1/7. Moving P(4, 5, 3) by D changes X
  // by N_4(s) N_5(t) N_3(u) D exactly (A2.4 OneBasisFun, an independent
  // evaluation of one basis function); on the grid of step 1/28 (which hits
  // every knot) X is unchanged, bit for bit, outside the open support.
  const Volume before = jiggled(bspline_volume(10, 10, 10, 3), 61);
  Volume after = before;
  const Vec3 D{0.05, -0.08, 0.03};
  const int i = 4, j = 5, k = 3;
  after.point(i, j, k) += D;
  const std::vector<double> U = volume_knots(before, 0);  // the same in every direction
  const auto inside = [&](int first, double w) { return U[first] < w && w < U[first + 4]; };
  int changed = 0, unchanged = 0;
  for (int a = 0; a <= 28; ++a)
    for (int b = 0; b <= 28; ++b)
      for (int c = 0; c <= 28; ++c) {
        const double s = a / 28.0, t = b / 28.0, u = c / 28.0;
        const Vec3 diff = volume_point(after, s, t, u) - volume_point(before, s, t, u);
        if (inside(i, s) && inside(j, t) && inside(k, u)) {
          const double N = spline::one_basis_fun(i, s, 3, U) * spline::one_basis_fun(j, t, 3, U) *
                           spline::one_basis_fun(k, u, 3, U);
          ASSERT_GT(N, 0);
          EXPECT_LE(dist(diff, N * D), kTwoFormulas) << s << " " << t << " " << u;
          ++changed;
        } else {
          EXPECT_EQ(diff, Vec3{}) << s << " " << t << " " << u;
          ++unchanged;
        }
      }
  // The support is 15 of 28 steps in s and t (1/7..5/7, 2/7..6/7 open) and
  // 15 in u (0..4/7 open on the right, closed at 0 where N_3 = 0): all
  // counted, and most of the grid is outside.
  EXPECT_EQ(changed, 15 * 15 * 15);
  EXPECT_EQ(unchanged, 29 * 29 * 29 - 15 * 15 * 15);
}

TEST(Volume, BernsteinControlPointMovesXEverywhereInside) {
  // Global control: B_i^l(w) > 0 on (0, 1), so moving P_ijk by D changes X by
  // B_i^l(s) B_j^m(t) B_k^n(u) D != 0 at every point of the open cube, and by
  // nothing on the faces where one factor is 0 (i = 1 of 4: B_1^3(0) = B_1^3(1) = 0).
  const Volume before = jiggled(bernstein_volume(4, 4, 4), 62);
  Volume after = before;
  const Vec3 D{-0.04, 0.06, 0.02};
  after.point(1, 2, 1) += D;
  for (int a = 0; a <= 12; ++a)
    for (int b = 0; b <= 12; ++b)
      for (int c = 0; c <= 12; ++c) {
        const double s = a / 12.0, t = b / 12.0, u = c / 12.0;
        const Vec3 diff = volume_point(after, s, t, u) - volume_point(before, s, t, u);
        const double B = bernstein(3, 1, s) * bernstein(3, 2, t) * bernstein(3, 1, u);
        const bool open = a > 0 && a < 12 && b > 0 && b < 12 && c > 0 && c < 12;
        if (open) {
          EXPECT_GT(max_abs(diff), 0) << s << " " << t << " " << u;
          EXPECT_LE(dist(diff, B * D), kTwoFormulas) << s << " " << t << " " << u;
        } else {
          EXPECT_EQ(diff, Vec3{}) << s << " " << t << " " << u;
        }
      }
}

// ---- the evaluator ----------------------------------------------------------

TEST(Volume, EvaluatorGivesWhatVolumeDerivsGives) {
  // volume.h: the same evaluator for many points; bit for bit the same sums.
  const Volume v = jiggled(bspline_volume(7, 5, 6, 2), 71);
  const VolumeEvaluator eval(v);
  for (const Vec3 w : parameters(72, 100)) {  // seed 72
    const VolumeDerivs a = eval(w.x, w.y, w.z), b = volume_derivs(v, w.x, w.y, w.z);
    EXPECT_EQ(a.X, b.X);
    EXPECT_EQ(a.Xs, b.Xs);
    EXPECT_EQ(a.Xt, b.Xt);
    EXPECT_EQ(a.Xu, b.Xu);
  }
}

TEST(Volume, JacobianDeterminantIsTheTripleProductOfThePartials) {
  // volume.h: det [Xs Xt Xu] = Xs . (Xt x Xu); a scaling by (2, 3, 0.5) has
  // det 3 everywhere, a mirrored lattice det -1.
  Volume v = bernstein_volume(3, 3, 3);
  for (Vec3& p : v.P) p = {2 * p.x, 3 * p.y, 0.5 * p.z};
  const VolumeDerivs d = volume_derivs(v, 0.3, 0.4, 0.5);
  EXPECT_NEAR(volume_jacobian_det(d), 3.0, 8 * kUlp * 3);
  EXPECT_EQ(volume_jacobian_det(d), dot(d.Xs, cross(d.Xt, d.Xu)));
  for (Vec3& p : v.P) p.x = -p.x;
  EXPECT_NEAR(volume_jacobian_det(volume_derivs(v, 0.7, 0.1, 0.9)), -3.0, 8 * kUlp * 3);
}

// ---- bad input --------------------------------------------------------------

TEST(Volume, CountOutsideTheLimitsThrowsNamingIt) {
  // volume.h: 2..kMaxLatticePoints points per direction.
  EXPECT_EQ(error_of([] { bernstein_volume(1, 4, 4); }),
            "volume: 1 control points along s (must be 2..64)");
  EXPECT_EQ(error_of([] { bspline_volume(4, 65, 4, 3); }),
            "volume: 65 control points along t (must be 2..64)");
  EXPECT_EQ(error_of([] { bspline_volume(4, 4, -2, 1); }),
            "volume: -2 control points along u (must be 2..64)");
  EXPECT_NO_THROW(bspline_volume(2, 2, kMaxLatticePoints, 1));
}

TEST(Volume, DegreeOutsideTheLimitsThrowsNamingIt) {
  // volume.h: degree 1..kMaxLatticeDegree and below the count.
  EXPECT_EQ(error_of([] { bspline_volume(4, 4, 4, 0); }),
            "volume: degree 0 along s with 4 points (must be 1..15 and below the count)");
  EXPECT_EQ(error_of([] { bspline_volume(4, 4, 4, 4); }),
            "volume: degree 4 along s with 4 points (must be 1..15 and below the count)");
  EXPECT_EQ(error_of([] { bspline_volume(20, 20, 20, 16); }),
            "volume: degree 16 along s with 20 points (must be 1..15 and below the count)");
  EXPECT_EQ(error_of([] { bernstein_volume(4, 4, kMaxLatticeDegree + 2); }),
            "volume: degree 16 along u with 17 points (must be 1..15 and below the count)");
  EXPECT_NO_THROW(bernstein_volume(2, 2, kMaxLatticeDegree + 1));
}

TEST(Volume, WrongNumberOfControlPointsThrowsNamingIt) {
  Volume v = bernstein_volume(4, 4, 4);
  v.P.pop_back();
  EXPECT_EQ(error_of([&] { validate(v); }),
            "volume: 63 control points for 4 x 4 x 4 = 64");
  EXPECT_EQ(error_of([&] { volume_point(v, 0.5, 0.5, 0.5); }),
            "volume: 63 control points for 4 x 4 x 4 = 64");
  EXPECT_EQ(error_of([&] { VolumeEvaluator e(v); }),
            "volume: 63 control points for 4 x 4 x 4 = 64");
  v.P.clear();
  EXPECT_EQ(error_of([&] { validate(v); }), "volume: 0 control points for 4 x 4 x 4 = 64");
}

TEST(Volume, ControlPointNotFiniteThrowsNamingIt) {
  Volume v = bspline_volume(5, 5, 5, 2);
  v.P[17].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(error_of([&] { validate(v); }), "volume: control point P[17] is not finite");
  v.P[17].y = 0;
  v.P[124].z = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of([&] { validate(v); }), "volume: control point P[124] is not finite");
}

TEST(Volume, ParameterOutsideTheUnitCubeThrowsNamingIt) {
  // volume.h: (s, t, u) must lie in [0, 1]^3; the faces themselves are inside.
  const Volume v = bernstein_volume(3, 3, 3);
  EXPECT_EQ(error_of([&] { volume_derivs(v, 1.5, 0.5, 0.5); }), "volume: s = 1.5 outside [0, 1]");
  EXPECT_EQ(error_of([&] { volume_derivs(v, 0.5, -0.25, 0.5); }),
            "volume: t = -0.25 outside [0, 1]");
  EXPECT_EQ(error_of([&] { volume_point(v, 0.5, 0.5, NAN); }), "volume: u = nan outside [0, 1]");
  EXPECT_EQ(error_of([&] { volume_point(v, 1 + 2 * kUlp, 0, 0); }),
            "volume: s = 1.0000000000000004 outside [0, 1]");
  EXPECT_EQ(error_of([&] { volume_point(v, 0, -5e-324, 0); }),
            "volume: t = -4.9406564584124654e-324 outside [0, 1]");
  EXPECT_NO_THROW(volume_point(v, 0, 1, 0));
}

TEST(Volume, KnotsOfAnAxisOutsideZeroToTwoThrowNamingIt) {
  const Volume v = bernstein_volume(3, 3, 3);
  EXPECT_EQ(error_of([&] { volume_knots(v, 3); }), "volume_knots: axis 3");
  EXPECT_EQ(error_of([&] { volume_knots(v, -1); }), "volume_knots: axis -1");
}

}  // namespace
}  // namespace gllab::deform
