// tests/spline/surface_test.cpp — tensor-product surfaces (common/spline/surface.cpp).
//
// Expected values come from the lecture (ch. 1 §1.6/§1.7, notes "Higher Order Surfaces"), from
// The NURBS Book, or from properties that hold for every surface (partition of
// unity, corner interpolation, convex hull, affine invariance, agreement of two
// independent evaluation routes, central finite differences). Random surfaces
// use fixed seeds, so every run checks the same cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "spline/bezier.h"
#include "spline/bspline.h"
#include "spline/errors.h"
#include "spline/interpolation.h"
#include "spline/nurbs.h"
#include "spline/surface.h"
#include "spline/tessellate.h"

namespace gllab::spline {
namespace {

// ---- tolerances -------------------------------------------------------------------
/// Two routes to the same value on coordinates of size ~10 (round-off only).
constexpr double kSameValue = 1e-11;
/// The lecture's Bézier interpolation example solves a 2 x 2 system whose
/// coefficients it rounds to two decimals (0.36, 0.07, 0.41, 0.33): that moves
/// its printed b_2 by 0.09 from the exact solution for its own t values.
constexpr double kLectureExampleRounding = 0.1;
/// Central differences, step kStep: truncation O(h^2) plus round-off eps/h,
/// relative to the size of the derivative.
constexpr double kStep = 1e-5;
constexpr double kFiniteDifference = 1e-6;
/// The exact NURBS circle/sphere: distance from the centre equals the radius.
constexpr double kExactRadius = 1e-14;
/// |N| == 1 and N orthogonal to the unit tangents.
constexpr double kUnitLength = 1e-14;
constexpr double kOrthogonal = 1e-11;
/// Two normals of one point computed along different routes (angle, radians).
constexpr double kSameDirection = 1e-9;
/// A degenerate normal compared with the limit taken numerically nearby.
constexpr double kLimitDirection = 1e-4;

// ---- helpers ------------------------------------------------------------------------

testing::AssertionResult Near(Vec3 a, Vec3 b, double tol) {
  const double d = norm(a - b);
  if (d <= tol) return testing::AssertionSuccess();
  return testing::AssertionFailure() << num(a) << " vs " << num(b) << ": distance " << d << " > " << tol;
}

/// |a - b| <= tol * max(1, |b|): relative for large vectors, absolute near 0.
testing::AssertionResult RelNear(Vec3 a, Vec3 b, double tol) { return Near(a, b, tol * std::max(1.0, norm(b))); }

std::string What(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

double Uniform(std::mt19937& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
int UniformInt(std::mt19937& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
Vec3 RandomPoint(std::mt19937& rng) { return {Uniform(rng, -5, 5), Uniform(rng, -5, 5), Uniform(rng, -5, 5)}; }

BezierSurface RandomBezier(std::mt19937& rng, int n, int m, bool unit_square = false) {
  BezierSurface s;
  s.n = n;
  s.m = m;
  for (int k = 0; k < (n + 1) * (m + 1); ++k) s.P.push_back(RandomPoint(rng));
  if (!unit_square) {
    s.a = Uniform(rng, -2, 2);
    s.b = s.a + Uniform(rng, 0.5, 3);
    s.c = Uniform(rng, -2, 2);
    s.d = s.c + Uniform(rng, 0.5, 3);
  }
  return s;
}

/// Clamped knots for `count` points of degree p on [lo, hi] with random simple
/// interior knots (the surface is C^{p-1}).
std::vector<double> RandomKnots(std::mt19937& rng, int count, int p, double lo, double hi) {
  std::vector<double> interior;
  for (int k = 0; k < count - p - 1; ++k) interior.push_back(Uniform(rng, lo + 0.05, hi - 0.05));
  std::sort(interior.begin(), interior.end());
  std::vector<double> U(static_cast<std::size_t>(p) + 1, lo);
  U.insert(U.end(), interior.begin(), interior.end());
  U.insert(U.end(), static_cast<std::size_t>(p) + 1, hi);
  return U;
}

BsplineSurface RandomBspline(std::mt19937& rng, int p, int q, int nu, int nv, bool rational) {
  BsplineSurface s;
  s.p = p;
  s.q = q;
  s.nu = nu;
  s.nv = nv;
  const double u0 = Uniform(rng, -1, 1), v0 = Uniform(rng, -1, 1);
  s.U = RandomKnots(rng, nu, p, u0, u0 + Uniform(rng, 1, 3));
  s.V = RandomKnots(rng, nv, q, v0, v0 + Uniform(rng, 1, 3));
  for (int k = 0; k < nu * nv; ++k) {
    s.P.push_back(RandomPoint(rng));
    if (rational) s.w.push_back(Uniform(rng, 0.3, 3));
  }
  return s;
}

double InDomain(std::mt19937& rng, ParamInterval d) { return Uniform(rng, d.a, d.b); }

/// The sphere of radius R about the origin: nurbs.h's circle turned into the
/// xz-plane and revolved about z (it covers the sphere twice; the poles are
/// at the profile's axis points u = 1/4 and 3/4).
BsplineSurface Sphere(double R) {
  BsplineCurve profile = circle(Vec3{}, R);
  for (Vec3& P : profile.P) P = {P.x, 0, P.y};
  profile.dimension = 3;
  return revolved_surface(profile);
}

// ==== lecture examples =====================================================================

// ch. 1 §1.6 "Example (de Casteljau algorithm)": polygon (0,0), (2,4.5),
// (8.5,6.5), (11,2) at t = 0.6. Extruded along v (b_ij = (x_i, y_i, j)), the
// surface's u-steps repeat the lecture's table and X(0.6, v) = (X(0.6), v).
BezierSurface LectureExtrusion() {
  const Vec3 polygon[] = {{0, 0, 0}, {2, 4.5, 0}, {8.5, 6.5, 0}, {11, 2, 0}};
  BezierSurface s;
  s.n = 3;
  s.m = 1;
  for (const Vec3& b : polygon) {
    s.P.push_back(b);
    s.P.push_back(b + Vec3{0, 0, 1});
  }
  return s;
}

TEST(BezierSurfaceDeCasteljau, LectureExampleTableAlongU) {
  const BezierSurfaceConstruction c = de_casteljau(LectureExtrusion(), 0.6, 0.25);
  ASSERT_EQ(c.nets.size(), 5u);  // 3 steps along u, 1 along v
  // The lecture's table, column by column (ch. 1 §1.6), in row 0 of each net (z = 0).
  EXPECT_TRUE(Near(c.nets[1].point(0, 0), {1.2, 2.7, 0}, kSameValue));
  EXPECT_TRUE(Near(c.nets[1].point(1, 0), {5.9, 5.7, 0}, kSameValue));
  EXPECT_TRUE(Near(c.nets[1].point(2, 0), {10, 3.8, 0}, kSameValue));
  EXPECT_TRUE(Near(c.nets[2].point(0, 0), {4.02, 4.5, 0}, kSameValue));
  EXPECT_TRUE(Near(c.nets[2].point(1, 0), {8.36, 4.56, 0}, kSameValue));
  // The lecture prints X(0.6) = (6.63, 4.54), but its own last step gives
  // 0.4 (4.02, 4.5) + 0.6 (8.36, 4.56) = (6.624, 4.536): 6.624 is 6.62 to
  // two decimals. The exact value is the one to trust.
  EXPECT_TRUE(Near(c.point, {6.624, 4.536, 0.25}, kSameValue));
  // X'(0.6) = 3 (b_3^2 - b_2^2) = (13.02, 0.18), ch. 1 §1.6 "Example (continued)".
  EXPECT_TRUE(Near(c.partials.Su, {13.02, 0.18, 0}, kSameValue));
  EXPECT_TRUE(Near(c.partials.Sv, {0, 0, 1}, kSameValue));
  EXPECT_TRUE(Near(c.partials.Suv, {0, 0, 0}, kSameValue));
}

TEST(BezierSurfaceDerivs, LectureExampleSecondDerivativeAlongU) {
  // X''(0.6) = 6 (b_3^1 - 2 b_2^1 + b_1^1) = (-3.6, -29.4) (ch. 1 §1.6).
  const auto D = surface_derivs(LectureExtrusion(), 0.6, 0.7, 2);
  EXPECT_TRUE(Near(D[0][0], {6.624, 4.536, 0.7}, kSameValue));
  EXPECT_TRUE(Near(D[1][0], {13.02, 0.18, 0}, kSameValue));
  EXPECT_TRUE(Near(D[2][0], {-3.6, -29.4, 0}, kSameValue));
  EXPECT_TRUE(Near(D[0][2], {0, 0, 0}, kSameValue));  // linear along v
}

TEST(BezierSurfaceDerivs, LectureCornerFormulasOfBicubicPatch) {
  // ch. 1 §1.7 "Example: bicubic Bézier surface": Xs(0,0) = 3 (b10 - b00),
  // Xt(0,0) = 3 (b01 - b00), Xst(0,0) = 9 (b11 - b10 - b01 + b00); notes "Higher Order Surfaces"
  // writes the twist n^2 (p00 - p01 - p10 + p11). The other corners mirror it.
  std::mt19937 rng(1701);
  for (int trial = 0; trial < 20; ++trial) {
    const BezierSurface s = RandomBezier(rng, 3, 3, true);
    auto b = [&s](int i, int j) { return s.point(i, j); };
    const SurfacePartials c00 = surface_partials(s, 0, 0);
    EXPECT_TRUE(Near(c00.S, b(0, 0), kSameValue));
    EXPECT_TRUE(Near(c00.Su, 3 * (b(1, 0) - b(0, 0)), kSameValue));
    EXPECT_TRUE(Near(c00.Sv, 3 * (b(0, 1) - b(0, 0)), kSameValue));
    EXPECT_TRUE(Near(c00.Suv, 9 * (b(1, 1) - b(1, 0) - b(0, 1) + b(0, 0)), kSameValue));
    const SurfacePartials c11 = surface_partials(s, 1, 1);
    EXPECT_TRUE(Near(c11.S, b(3, 3), kSameValue));
    EXPECT_TRUE(Near(c11.Su, 3 * (b(3, 3) - b(2, 3)), kSameValue));
    EXPECT_TRUE(Near(c11.Sv, 3 * (b(3, 3) - b(3, 2)), kSameValue));
    EXPECT_TRUE(Near(c11.Suv, 9 * (b(3, 3) - b(2, 3) - b(3, 2) + b(2, 2)), kSameValue));
    const SurfacePartials c10 = surface_partials(s, 1, 0);
    EXPECT_TRUE(Near(c10.Suv, 9 * (b(3, 1) - b(2, 1) - b(3, 0) + b(2, 0)), kSameValue));
    // The same corner values out of the de Casteljau scheme.
    const SurfacePartials dc = de_casteljau(s, 0, 0).partials;
    EXPECT_TRUE(Near(dc.Suv, c00.Suv, kSameValue));
  }
}

TEST(InterpolatingBezierSurface, LectureCurveExampleExtrudedAlongV) {
  // ch. 1 §1.6 "Interpolating with Bézier segments": P = (1,2), (2,1), (4,2),
  // (6,6) at the chordal t = 0, 1.42, 3.66, 8.13 gives b_1 = (2.5, -1.51),
  // b_2 = (6.86, 5.27). With two rows (z = 0 and z = 1) at v = 0, 1 the
  // surface's first step is the lecture's system, and its net repeats the answer.
  const Vec3 P[] = {{1, 2, 0}, {2, 1, 0}, {4, 2, 0}, {6, 6, 0}};
  std::vector<Vec3> grid;
  for (const Vec3& p : P) {
    grid.push_back(p);
    grid.push_back(p + Vec3{0, 0, 1});
  }
  const BezierSurface s = interpolating_bezier_surface({0, 1.42, 3.66, 8.13}, {0, 1}, grid);
  EXPECT_EQ(s.n, 3);
  EXPECT_EQ(s.m, 1);
  EXPECT_EQ(s.a, 0);
  EXPECT_EQ(s.b, 8.13);
  EXPECT_TRUE(Near(s.point(0, 0), {1, 2, 0}, kSameValue));
  EXPECT_TRUE(Near(s.point(1, 0), {2.5, -1.51, 0}, kLectureExampleRounding));
  EXPECT_TRUE(Near(s.point(2, 0), {6.86, 5.27, 0}, kLectureExampleRounding));
  EXPECT_TRUE(Near(s.point(2, 1), {6.86, 5.27, 1}, kLectureExampleRounding));
  EXPECT_TRUE(Near(s.point(3, 0), {6, 6, 0}, kSameValue));
}

// ==== Bézier surfaces: properties over random nets ========================================

TEST(BezierSurface, DeCasteljauEqualsBernsteinEqualsClampedBspline) {
  // Three routes to one point: ch. 1 §1.7 de Casteljau (both orders), the
  // Bernstein sum, and A3.5 on the patch as a B-spline with knots a^(n+1) b^(n+1).
  std::mt19937 rng(42);
  for (int trial = 0; trial < 60; ++trial) {
    const BezierSurface s = RandomBezier(rng, UniformInt(rng, 1, 5), UniformInt(rng, 1, 5));
    const BsplineSurface bs = to_bspline(s);
    for (int k = 0; k < 15; ++k) {
      const double u = Uniform(rng, s.a, s.b), v = Uniform(rng, s.c, s.d);
      const Vec3 X = surface_point(s, u, v);
      EXPECT_TRUE(Near(bernstein_surface_point(s, u, v), X, kSameValue));
      EXPECT_TRUE(Near(surface_point(bs, u, v), X, kSameValue));
      EXPECT_TRUE(Near(de_casteljau(s, u, v, SurfaceDirection::U).point, X, kSameValue));
      EXPECT_TRUE(Near(de_casteljau(s, u, v, SurfaceDirection::V).point, X, kSameValue));
    }
  }
}

TEST(BezierSurface, ConstructionNetsHaveTheLecturesShapes) {
  std::mt19937 rng(7);
  const BezierSurface s = RandomBezier(rng, 3, 2);
  const BezierSurfaceConstruction cu = de_casteljau(s, s.a + 0.3 * (s.b - s.a), s.c + 0.6 * (s.d - s.c));
  ASSERT_EQ(cu.nets.size(), 6u);  // b^{00}, b^{10}, b^{20}, b^{30}, b^{31}, b^{32}
  EXPECT_EQ(cu.nets[0].rows, 4);
  EXPECT_EQ(cu.nets[3].rows, 1);
  EXPECT_EQ(cu.nets[3].cols, 3);
  EXPECT_EQ(cu.nets[5].cols, 1);
  EXPECT_EQ(cu.last_quad.rows, 2);
  EXPECT_EQ(cu.last_quad.cols, 2);
  const BezierSurfaceConstruction cv = de_casteljau(s, s.a + 0.3 * (s.b - s.a), s.c + 0.6 * (s.d - s.c),
                                                    SurfaceDirection::V);
  EXPECT_EQ(cv.nets[2].rows, 4);  // b^{02}: 4 x 1
  EXPECT_EQ(cv.nets[2].cols, 1);
  EXPECT_NEAR(cu.s, 0.3, kSameValue);
  EXPECT_NEAR(cu.t, 0.6, kSameValue);
}

TEST(BezierSurface, PartitionOfUnityCornersAndConvexHull) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 40; ++trial) {
    BezierSurface s = RandomBezier(rng, UniformInt(rng, 1, 5), UniformInt(rng, 1, 5));
    // Corners of the net are corners of the surface (ch. 1 §1.7, property 3).
    EXPECT_TRUE(Near(surface_point(s, s.a, s.c), s.point(0, 0), kSameValue));
    EXPECT_TRUE(Near(surface_point(s, s.b, s.c), s.point(s.n, 0), kSameValue));
    EXPECT_TRUE(Near(surface_point(s, s.a, s.d), s.point(0, s.m), kSameValue));
    EXPECT_TRUE(Near(surface_point(s, s.b, s.d), s.point(s.n, s.m), kSameValue));
    // Convex hull (property 1): inside the net's bounding box.
    Vec3 lo = s.P[0], hi = s.P[0];
    for (const Vec3& p : s.P) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    for (int k = 0; k < 20; ++k) {
      const Vec3 X = surface_point(s, Uniform(rng, s.a, s.b), Uniform(rng, s.c, s.d));
      EXPECT_TRUE(X.x >= lo.x - kSameValue && X.x <= hi.x + kSameValue);
      EXPECT_TRUE(X.y >= lo.y - kSameValue && X.y <= hi.y + kSameValue);
      EXPECT_TRUE(X.z >= lo.z - kSameValue && X.z <= hi.z + kSameValue);
    }
    // Partition of unity: a net of one repeated point gives that point everywhere.
    const Vec3 c = RandomPoint(rng);
    std::fill(s.P.begin(), s.P.end(), c);
    EXPECT_TRUE(Near(bernstein_surface_point(s, Uniform(rng, s.a, s.b), Uniform(rng, s.c, s.d)), c, kSameValue));
  }
}

// ch. 1 §1.7 "Bézier tensor product": the biquadratic monomial basis is the (2 + 1)^2 = 9
// products s^p t^q, {1, s, t, st, s^2, t^2, s^2 t, s t^2, s^2 t^2}; the notes list eight, without
// s^2 t. A biquadratic patch makes s^2 t: in degree 2 Bernstein coefficients s^2 is (0, 0, 1) and
// t is (0, 1/2, 1) (t = B_1^2/2 + B_2^2), so z_ij = [i == 2] j/2 gives z = s^2 t, and
// x_ij = i/2, y_ij = j/2 give x = s, y = t.
TEST(BezierSurface, BiquadraticPatchMakesS2TNotesSlip) {
  BezierSurface S;
  S.n = S.m = 2;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) S.P.push_back({i / 2.0, j / 2.0, i == 2 ? j / 2.0 : 0.0});
  for (int a = 0; a <= 10; ++a)
    for (int b = 0; b <= 10; ++b) {
      const double s = a / 10.0, t = b / 10.0;
      const Vec3 X = surface_point(S, s, t);
      EXPECT_NEAR(X.x, s, kSameValue);
      EXPECT_NEAR(X.y, t, kSameValue);
      EXPECT_NEAR(X.z, s * s * t, kSameValue) << "s=" << s << " t=" << t;
    }
}

// ch. 1 §1.7 "Properties of Bézier surfaces", property 2: b_ij has the greatest influence at
// (s, t) = (i/m, j/n); the notes print (i/m, i/n). Its weight B_i^m(s) B_j^n(t) is a product
// whose factors peak at i/m and j/n (ch. 1 §1.6, "Properties of Bézier segments", property 8).
// With m = 3, n = 2 the two differ for every i != 0: b_10 weighs B_1^3(1/3) = 4/9 at (1/3, 0)
// and 4/9 x 1/4 = 1/9 at (1/3, 1/2). Grid step 1/60 holds every i/3 and j/2.
TEST(BezierSurface, WeightOfBijPeaksAtIOverMJOverNNotesSlip) {
  const int m = 3, n = 2, steps = 60;
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j) {
      int best_a = 0, best_b = 0;
      double best = -1;
      for (int a = 0; a <= steps; ++a)
        for (int b = 0; b <= steps; ++b) {
          const double w = bernstein(i, m, double(a) / steps) * bernstein(j, n, double(b) / steps);
          if (w > best) best = w, best_a = a, best_b = b;
        }
      EXPECT_EQ(best_a, i * steps / m) << "b_" << i << j;
      EXPECT_EQ(best_b, j * steps / n) << "b_" << i << j;
    }
  EXPECT_NEAR(bernstein(1, 3, 1.0 / 3) * bernstein(0, 2, 0.0), 4.0 / 9, kSameValue);
  EXPECT_NEAR(bernstein(1, 3, 1.0 / 3) * bernstein(0, 2, 0.5), 1.0 / 9, kSameValue);
}

TEST(BezierSurface, AffineInvariance) {
  // notes "Higher Order Surfaces", "Affine Invariance": Phi(sum p_ij b_i b_j) = sum Phi(p_ij) b_i b_j.
  std::mt19937 rng(11);
  const double A[3][3] = {{0.8, -1.2, 0.3}, {0.5, 2.0, -0.7}, {-1.1, 0.4, 1.5}};
  const Vec3 t{3, -2, 7};
  auto phi = [&](Vec3 p) {
    return Vec3{A[0][0] * p.x + A[0][1] * p.y + A[0][2] * p.z, A[1][0] * p.x + A[1][1] * p.y + A[1][2] * p.z,
                A[2][0] * p.x + A[2][1] * p.y + A[2][2] * p.z} +
           t;
  };
  for (int trial = 0; trial < 20; ++trial) {
    const BezierSurface s = RandomBezier(rng, UniformInt(rng, 1, 4), UniformInt(rng, 1, 4));
    BezierSurface moved = s;
    for (Vec3& p : moved.P) p = phi(p);
    for (int k = 0; k < 10; ++k) {
      const double u = Uniform(rng, s.a, s.b), v = Uniform(rng, s.c, s.d);
      EXPECT_TRUE(Near(surface_point(moved, u, v), phi(surface_point(s, u, v)), kSameValue));
    }
  }
}

TEST(BezierSurface, PartialsMatchCentralDifferencesAndEachOther) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 30; ++trial) {
    const BezierSurface s = RandomBezier(rng, UniformInt(rng, 1, 5), UniformInt(rng, 1, 5));
    const double hu = kStep * (s.b - s.a), hv = kStep * (s.d - s.c);
    for (int k = 0; k < 10; ++k) {
      const double u = Uniform(rng, s.a + hu, s.b - hu), v = Uniform(rng, s.c + hv, s.d - hv);
      const SurfacePartials d = surface_partials(s, u, v);
      const Vec3 fu = (surface_point(s, u + hu, v) - surface_point(s, u - hu, v)) / (2 * hu);
      const Vec3 fv = (surface_point(s, u, v + hv) - surface_point(s, u, v - hv)) / (2 * hv);
      const Vec3 fuv = (surface_partials(s, u, v + hv).Su - surface_partials(s, u, v - hv).Su) / (2 * hv);
      EXPECT_TRUE(RelNear(d.Su, fu, kFiniteDifference));
      EXPECT_TRUE(RelNear(d.Sv, fv, kFiniteDifference));
      EXPECT_TRUE(RelNear(d.Suv, fuv, kFiniteDifference));
      // The lecture's de Casteljau partials and the Delta^{kl} derivative
      // surfaces (ch. 1 §1.7) give the same vectors.
      const SurfacePartials dc = de_casteljau(s, u, v).partials;
      EXPECT_TRUE(RelNear(dc.Su, d.Su, kSameValue));
      EXPECT_TRUE(RelNear(dc.Sv, d.Sv, kSameValue));
      EXPECT_TRUE(RelNear(dc.Suv, d.Suv, kSameValue));
      EXPECT_TRUE(RelNear(surface_point(derivative_surface(s, 1, 1), u, v), d.Suv, kSameValue));
      const auto D = surface_derivs(s, u, v, 3);
      EXPECT_TRUE(RelNear(surface_point(derivative_surface(s, 2, 1), u, v), D[2][1], kSameValue));
      EXPECT_TRUE(RelNear(surface_point(derivative_surface(s, 0, 3), u, v), D[0][3], kSameValue));
    }
  }
}

TEST(BezierSurface, NormalsAreUnitAndOrthogonalToTheTangents) {
  std::mt19937 rng(9);
  for (int trial = 0; trial < 30; ++trial) {
    const BezierSurface s = RandomBezier(rng, UniformInt(rng, 1, 4), UniformInt(rng, 1, 4));
    for (int k = 0; k < 10; ++k) {
      const double u = Uniform(rng, s.a, s.b), v = Uniform(rng, s.c, s.d);
      const SurfacePartials d = surface_partials(s, u, v);
      const Vec3 N = surface_normal(s, u, v);
      EXPECT_NEAR(norm(N), 1, kUnitLength);
      EXPECT_NEAR(dot(N, normalized(d.Su)), 0, kOrthogonal);
      EXPECT_NEAR(dot(N, normalized(d.Sv)), 0, kOrthogonal);
      EXPECT_GT(dot(N, cross(d.Su, d.Sv)), 0);  // N = (Xs x Xt) / |Xs x Xt| (ch. 1 §1.7)
    }
  }
}

TEST(BezierSurface, IsoCurvesLieOnTheSurface) {
  // ch. 1 §1.7: X(s, t0) and X(s0, t) are Bézier curves of degree n and m.
  std::mt19937 rng(13);
  for (int trial = 0; trial < 20; ++trial) {
    const BezierSurface s = RandomBezier(rng, UniformInt(rng, 1, 5), UniformInt(rng, 1, 5));
    const double u0 = Uniform(rng, s.a, s.b), v0 = Uniform(rng, s.c, s.d);
    const BezierCurve cu = iso_curve_u(s, u0), cv = iso_curve_v(s, v0);
    EXPECT_EQ(static_cast<int>(cu.P.size()), s.m + 1);
    EXPECT_EQ(static_cast<int>(cv.P.size()), s.n + 1);
    for (int k = 0; k <= 10; ++k) {
      const double v = s.c + k * (s.d - s.c) / 10, u = s.a + k * (s.b - s.a) / 10;
      EXPECT_TRUE(Near(bezier_point(cu, v), surface_point(s, u0, v), kSameValue));
      EXPECT_TRUE(Near(bezier_point(cv, u), surface_point(s, u, v0), kSameValue));
    }
    // Edge curves are the edge rows of the net (ch. 1 §1.7, property 4).
    const BezierCurve edge = iso_curve_v(s, s.c);
    for (int i = 0; i <= s.n; ++i) EXPECT_TRUE(Near(edge.P[static_cast<std::size_t>(i)], s.point(i, 0), kSameValue));
  }
}

TEST(BezierSurface, DegreeZeroDirectionIsACurve) {
  std::mt19937 rng(17);
  const BezierSurface s = RandomBezier(rng, 0, 3);  // one row: a curve along v
  BezierCurve row;
  row.P = s.P;
  row.a = s.c;
  row.b = s.d;
  const double u = 0.5 * (s.a + s.b), v = s.c + 0.3 * (s.d - s.c);
  EXPECT_TRUE(Near(surface_point(s, u, v), bezier_point(row, v), kSameValue));
  const SurfacePartials d = de_casteljau(s, u, v).partials;
  EXPECT_TRUE(Near(d.Su, {}, 0));
  EXPECT_TRUE(Near(d.Sv, bezier_derivative_at(row, v), kSameValue));
}

// ==== C0 / C1 / C2 continuation (ch. 1 §1.7 "Spline surfaces") ===========================

TEST(ContinuationRows, SatisfyTheLecturesConditions) {
  std::mt19937 rng(23);
  const BezierSurface a = RandomBezier(rng, 3, 3);
  const double ds0 = a.b - a.a, ds1 = 0.7;
  const auto rows = continuation_rows(a, 2, ds1);
  ASSERT_EQ(rows.size(), 3u);
  for (int i = 0; i <= a.m; ++i) {
    const std::size_t j = static_cast<std::size_t>(i);
    const Vec3 an = a.point(3, i), an1 = a.point(2, i), an2 = a.point(1, i);
    EXPECT_TRUE(Near(rows[0][j], an, kSameValue));  // C0: a_{m,i} = b_{0,i}
    EXPECT_TRUE(RelNear((an - an1) / ds0, (rows[1][j] - rows[0][j]) / ds1, kSameValue));  // C1
    EXPECT_TRUE(RelNear((an - 2 * an1 + an2) / (ds0 * ds0),
                        (rows[2][j] - 2 * rows[1][j] + rows[0][j]) / (ds1 * ds1), kSameValue));  // C2
  }
}

TEST(JoinedPatch, CrossDerivativesMatchAcrossTheEdgeUpToOrderK) {
  std::mt19937 rng(29);
  for (int trial = 0; trial < 10; ++trial) {
    for (SurfaceDirection dir : {SurfaceDirection::U, SurfaceDirection::V}) {
      const bool along_u = dir == SurfaceDirection::U;
      const BezierSurface a = RandomBezier(rng, 3, 3);
      BezierSurface next = RandomBezier(rng, 3, 3);
      if (along_u) {
        next.c = a.c;
        next.d = a.d;
      } else {
        next.a = a.a;
        next.b = a.b;
      }
      for (int k = 0; k <= 3; ++k) {
        const BezierSurface b = joined_patch(a, next, k, dir);
        EXPECT_EQ(along_u ? b.a : b.c, along_u ? a.b : a.d);
        for (int e = 0; e <= 8; ++e) {
          // A point of the shared edge, in both patches' parameters.
          const double x = along_u ? a.c + e * (a.d - a.c) / 8 : a.a + e * (a.b - a.a) / 8;
          const auto Da = along_u ? surface_derivs(a, a.b, x, 3) : surface_derivs(a, x, a.d, 3);
          const auto Db = along_u ? surface_derivs(b, b.a, x, 3) : surface_derivs(b, x, b.c, 3);
          for (int r = 0; r <= k; ++r) {
            // C^r: the r-th cross derivative (and its derivatives along the edge) agree.
            const std::size_t cr = static_cast<std::size_t>(r);
            const Vec3 ca = along_u ? Da[cr][0] : Da[0][cr], cb = along_u ? Db[cr][0] : Db[0][cr];
            EXPECT_TRUE(RelNear(cb, ca, kSameValue)) << "k=" << k << " r=" << r;
            if (r < 3) {
              const Vec3 ta = along_u ? Da[cr][1] : Da[1][cr], tb = along_u ? Db[cr][1] : Db[1][cr];
              EXPECT_TRUE(RelNear(tb, ta, kSameValue)) << "k=" << k << " r=" << r;
            }
          }
        }
      }
    }
  }
}

TEST(JoinedPatch, RejectsMismatchedDegreesAndEdges) {
  std::mt19937 rng(31);
  const BezierSurface a = RandomBezier(rng, 3, 3);
  BezierSurface next = RandomBezier(rng, 3, 2);
  EXPECT_NE(What([&] { joined_patch(a, next, 1); }).find("degrees (3, 2) of next differ from (3, 3)"),
            std::string::npos);
  EXPECT_NE(What([&] { continuation_rows(a, 4, 1.0); }).find("k=4 must lie in [0, 3]"), std::string::npos);
  EXPECT_NE(What([&] { continuation_rows(a, 1, 0.0); }).find("next_length=0 must be > 0"), std::string::npos);
}

// ==== interpolating Bézier surfaces and Lagrange surfaces ==================================

// ==== Zero and constant twist (ch. 1 §1.7 "The twist vector") =======================

BezierCurve RandomEdge(std::mt19937& rng, int degree, Vec3 start, double a, double b) {
  BezierCurve e;
  e.P.push_back(start);
  for (int i = 1; i <= degree; ++i) e.P.push_back(RandomPoint(rng));
  e.a = a, e.b = b;
  return e;
}

TEST(ConstantTwistPatch, TwistIsTheGivenVectorEverywhereAndTheEdgesAreCopied) {
  std::mt19937 rng(71);
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 corner = RandomPoint(rng), twist = trial % 4 == 0 ? Vec3{} : RandomPoint(rng);
    const double a = Uniform(rng, -1, 1), b = a + Uniform(rng, 0.5, 2), c = Uniform(rng, -1, 1),
                 d = c + Uniform(rng, 0.5, 2);
    const BezierCurve eu = RandomEdge(rng, UniformInt(rng, 1, 4), corner, a, b);
    const BezierCurve ev = RandomEdge(rng, UniformInt(rng, 1, 4), corner, c, d);
    const BezierSurface s = constant_twist_patch(eu, ev, twist);
    for (int i = 0; i <= s.n; ++i) EXPECT_EQ(s.point(i, 0), eu.P[static_cast<std::size_t>(i)]);
    for (int j = 0; j <= s.m; ++j) EXPECT_EQ(s.point(0, j), ev.P[static_cast<std::size_t>(j)]);
    // Lecture: X_st(0,0) = n m (b_11 - b_10 - b_01 + b_00) / interval lengths, at every (u, v).
    for (int k = 0; k <= 10; ++k)
      for (int l = 0; l <= 10; ++l) {
        const double u = a + (b - a) * k / 10, v = c + (d - c) * l / 10;
        EXPECT_TRUE(RelNear(surface_partials(s, u, v).Suv, twist, kSameValue)) << trial << " at " << u << "," << v;
      }
    if (twist == Vec3{}) {
      // Zero twist: the translational surface X(u, v) = X(u, c) + X(a, v) - X(a, c).
      for (int k = 0; k <= 10; ++k) {
        const double u = a + (b - a) * k / 10, v = c + (d - c) * (10 - k) / 10;
        EXPECT_TRUE(RelNear(surface_point(s, u, v), bezier_point(eu, u) + bezier_point(ev, v) - corner, kSameValue));
      }
    }
  }
}

TEST(ConstantTwistPatch, ErrorsNameTheCornersAndDegrees) {
  BezierCurve eu, ev;
  eu.P = {{0, 0, 0}, {1, 0, 0}};
  ev.P = {{0, 0, 1}, {0, 1, 0}};
  EXPECT_NE(What([&] { constant_twist_patch(eu, ev, {}); })
                .find("constant_twist_patch: the edges start at different corners: edge_u (0, 0, 0), edge_v (0, 0, 1)"),
            std::string::npos);
  ev.P = {{0, 0, 0}};
  EXPECT_NE(What([&] { constant_twist_patch(eu, ev, {}); }).find("degrees (1, 0)"), std::string::npos);
}

TEST(InterpolatingBezierSurface, ReproducesItsGridAndEqualsTheLagrangeSurface) {
  // ch. 1 §1.7 "Proof": f(s_k, t_l) = p_kl. The interpolating polynomial is
  // unique, so the Lagrange surface through the same grid is the same surface.
  std::mt19937 rng(37);
  for (int trial = 0; trial < 30; ++trial) {
    const int rows = UniformInt(rng, 2, 6), cols = UniformInt(rng, 2, 6);
    std::vector<double> us, vs;
    for (int i = 0; i < rows; ++i) us.push_back(i + Uniform(rng, 0.1, 0.9));
    for (int j = 0; j < cols; ++j) vs.push_back(0.5 * j + Uniform(rng, 0.05, 0.45));
    std::shuffle(us.begin(), us.end(), rng);  // the parameters need not be sorted
    std::vector<Vec3> grid;
    for (int k = 0; k < rows * cols; ++k) grid.push_back(RandomPoint(rng));
    const BezierSurface s = interpolating_bezier_surface(us, vs, grid);
    const LagrangeSurface L{us, vs, grid};
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) {
        const Vec3 p = grid[static_cast<std::size_t>(i * cols + j)];
        const double u = us[static_cast<std::size_t>(i)], v = vs[static_cast<std::size_t>(j)];
        EXPECT_TRUE(RelNear(surface_point(s, u, v), p, 1e-9));  // Gauss on Bernstein matrices up to degree 5
        EXPECT_TRUE(Near(surface_point(L, u, v), p, kSameValue));
      }
    for (int k = 0; k < 10; ++k) {
      const double u = Uniform(rng, s.a, s.b), v = Uniform(rng, s.c, s.d);
      EXPECT_TRUE(RelNear(surface_point(L, u, v), surface_point(s, u, v), 1e-8));
    }
  }
}

TEST(LagrangeSurface, InterpolatesItsGrid) {
  // ch. 1 §1.7 "Lagrange surfaces": f(s_i, t_j) = c_ij (L_i(s_k) = delta_ik).
  std::mt19937 rng(109);
  LagrangeSurface L{{-1, 0.5, 2, 2.25}, {0, 1, 3}, {}};
  for (int k = 0; k < 12; ++k) L.c.push_back(RandomPoint(rng));
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      EXPECT_TRUE(Near(surface_point(L, L.u_nodes[i], L.v_nodes[j]), L.c[i * 3 + j], kSameValue));
}

TEST(LagrangeSurface, RowAndColumnCurvesLieOnTheSurface) {
  // ch. 1 §1.7: c_j(s) = sum_i c_ij L_i(s) and c-bar_i(t) are part of the surface.
  std::mt19937 rng(41);
  LagrangeSurface L{{0, 1, 2, 3}, {0, 0.5, 1}, {}};  // the lecture's example size m = 3, n = 2
  for (int k = 0; k < 12; ++k) L.c.push_back(RandomPoint(rng));
  for (int j = 0; j < 3; ++j) {
    std::vector<Vec3> column;
    for (int i = 0; i < 4; ++i) column.push_back(L.c[static_cast<std::size_t>(i * 3 + j)]);
    const double u = Uniform(rng, 0, 3);
    EXPECT_TRUE(Near(surface_point(L, u, L.v_nodes[static_cast<std::size_t>(j)]),
                     lagrange_value(L.u_nodes, column, u), kSameValue));
  }
}

// ==== Hermite and Hermite–Lagrange surfaces ===============================================

HermitePatch RandomHermite(std::mt19937& rng) {
  HermitePatch h;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      h.point[a][b] = RandomPoint(rng);
      h.du[a][b] = RandomPoint(rng);
      h.dv[a][b] = RandomPoint(rng);
      h.twist[a][b] = RandomPoint(rng);
    }
  return h;
}

TEST(HermitePatch, ReproducesCornersPartialsAndTwists) {
  // ch. 1 §1.7 "Hermite surfaces": the patch interpolates the corner points,
  // the partial derivatives and the twist vectors.
  std::mt19937 rng(43);
  for (int trial = 0; trial < 20; ++trial) {
    const HermitePatch h = RandomHermite(rng);
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        const SurfacePartials d = surface_partials(h, a, b);
        EXPECT_TRUE(Near(surface_point(h, a, b), h.point[a][b], kSameValue));
        EXPECT_TRUE(Near(d.S, h.point[a][b], kSameValue));
        EXPECT_TRUE(Near(d.Su, h.du[a][b], kSameValue));
        EXPECT_TRUE(Near(d.Sv, h.dv[a][b], kSameValue));
        EXPECT_TRUE(Near(d.Suv, h.twist[a][b], kSameValue));
      }
  }
}

TEST(HermitePatch, EqualsItsBezierFormAndFiniteDifferences) {
  std::mt19937 rng(47);
  for (int trial = 0; trial < 20; ++trial) {
    const HermitePatch h = RandomHermite(rng);
    const BezierSurface b = to_bezier(h);
    for (int k = 0; k < 10; ++k) {
      const double u = Uniform(rng, kStep, 1 - kStep), v = Uniform(rng, kStep, 1 - kStep);
      const SurfacePartials dh = surface_partials(h, u, v), db = surface_partials(b, u, v);
      EXPECT_TRUE(RelNear(dh.S, db.S, kSameValue));
      EXPECT_TRUE(RelNear(dh.Su, db.Su, kSameValue));
      EXPECT_TRUE(RelNear(dh.Sv, db.Sv, kSameValue));
      EXPECT_TRUE(RelNear(dh.Suv, db.Suv, kSameValue));
      const Vec3 fu = (surface_point(h, u + kStep, v) - surface_point(h, u - kStep, v)) / (2 * kStep);
      EXPECT_TRUE(RelNear(dh.Su, fu, kFiniteDifference));
      const Vec3 N = surface_normal(h, u, v);
      EXPECT_NEAR(norm(N), 1, kUnitLength);
      EXPECT_NEAR(dot(N, normalized(dh.Su)), 0, kOrthogonal);
    }
  }
}

TEST(HermiteLagrangeSurface, InterpolatesItsHermiteAndLagrangeCurves) {
  // ch. 1 §1.7 "Hermite–Lagrange tensor product": along u the cubic Hermite
  // segment of each node v_j, along v the Lagrange curves through p0 and p1.
  std::mt19937 rng(53);
  HermiteLagrangeSurface s;
  s.v_nodes = {0, 0.4, 1.3};
  for (int j = 0; j < 3; ++j) {
    s.p0.push_back(RandomPoint(rng));
    s.p1.push_back(RandomPoint(rng));
    s.du0.push_back(RandomPoint(rng));
    s.du1.push_back(RandomPoint(rng));
  }
  for (int j = 0; j < 3; ++j) {
    const std::size_t J = static_cast<std::size_t>(j);
    const double u = Uniform(rng, 0, 1);
    EXPECT_TRUE(Near(surface_point(s, u, s.v_nodes[J]), hermite_point(s.p0[J], s.du0[J], s.p1[J], s.du1[J], u),
                     kSameValue));
    // dX/du at u = 0 is du0_j (central difference one-sided at the end: use a forward one).
    const Vec3 fu = (surface_point(s, kStep, s.v_nodes[J]) - surface_point(s, 0, s.v_nodes[J])) / kStep;
    EXPECT_TRUE(RelNear(fu, s.du0[J], 1e-4));  // forward difference: O(h) truncation
  }
  const double v = Uniform(rng, 0, 1.3);
  EXPECT_TRUE(Near(surface_point(s, 0, v), lagrange_value(s.v_nodes, s.p0, v), kSameValue));
  EXPECT_TRUE(Near(surface_point(s, 1, v), lagrange_value(s.v_nodes, s.p1, v), kSameValue));
}

// ==== B-spline and NURBS surfaces ============================================================

TEST(BsplineSurface, PartitionOfUnityAndLocalConvexHull) {
  std::mt19937 rng(59);
  for (int trial = 0; trial < 30; ++trial) {
    const int p = UniformInt(rng, 1, 4), q = UniformInt(rng, 1, 4);
    BsplineSurface s = RandomBspline(rng, p, q, p + UniformInt(rng, 1, 5), q + UniformInt(rng, 1, 5), trial % 2);
    const ParamInterval du = domain_u(s), dv = domain_v(s);
    for (int k = 0; k < 20; ++k) {
      const double u = InDomain(rng, du), v = InDomain(rng, dv);
      const Vec3 S = surface_point(s, u, v);
      // Strong convex hull (The NURBS Book P3.10 / P4.9): inside the box of the
      // (p+1) x (q+1) points that act on the span.
      const int su = find_span(s.nu - 1, p, u, s.U), sv = find_span(s.nv - 1, q, v, s.V);
      Vec3 lo = s.point(su, sv), hi = lo;
      for (int i = su - p; i <= su; ++i)
        for (int j = sv - q; j <= sv; ++j) {
          const Vec3 P = s.point(i, j);
          lo = {std::min(lo.x, P.x), std::min(lo.y, P.y), std::min(lo.z, P.z)};
          hi = {std::max(hi.x, P.x), std::max(hi.y, P.y), std::max(hi.z, P.z)};
        }
      EXPECT_TRUE(S.x >= lo.x - kSameValue && S.x <= hi.x + kSameValue);
      EXPECT_TRUE(S.y >= lo.y - kSameValue && S.y <= hi.y + kSameValue);
      EXPECT_TRUE(S.z >= lo.z - kSameValue && S.z <= hi.z + kSameValue);
    }
    // Partition of unity (rational basis too): one repeated point everywhere.
    const Vec3 c = RandomPoint(rng);
    std::fill(s.P.begin(), s.P.end(), c);
    EXPECT_TRUE(Near(surface_point(s, InDomain(rng, du), InDomain(rng, dv)), c, kSameValue));
    EXPECT_TRUE(Near(surface_derivs(s, InDomain(rng, du), InDomain(rng, dv), 1)[1][0], {}, kSameValue));
  }
}

TEST(BsplineSurface, ClampedCornersAndDomainEnds) {
  // Edges: u == U[p] and u == U[nu] (the end of the domain, where find_span
  // takes the last span) interpolate the corner control points.
  std::mt19937 rng(61);
  for (int trial = 0; trial < 20; ++trial) {
    const BsplineSurface s = RandomBspline(rng, 3, 2, 6, 5, trial % 2);
    const ParamInterval du = domain_u(s), dv = domain_v(s);
    EXPECT_EQ(du.a, s.U[3]);
    EXPECT_EQ(du.b, s.U[6]);
    EXPECT_TRUE(Near(surface_point(s, du.a, dv.a), s.point(0, 0), kSameValue));
    EXPECT_TRUE(Near(surface_point(s, du.b, dv.a), s.point(5, 0), kSameValue));
    EXPECT_TRUE(Near(surface_point(s, du.a, dv.b), s.point(0, 4), kSameValue));
    EXPECT_TRUE(Near(surface_point(s, du.b, dv.b), s.point(5, 4), kSameValue));
    // The derivative at the end equals the one-sided difference quotient.
    const double h = kStep * (du.b - du.a), v = InDomain(rng, dv);
    const Vec3 back = (surface_point(s, du.b, v) - surface_point(s, du.b - h, v)) / h;
    EXPECT_TRUE(RelNear(surface_partials(s, du.b, v).Su, back, 1e-3));  // O(h) one-sided
  }
}

TEST(BsplineSurface, UnclampedAndRepeatedKnotsMatchTheCurveCore) {
  // P_ij = C_i + D_j gives S(u, v) = C(u) + D(v) (partition of unity along
  // each direction), so bspline.h's curve_point / curve_derivs are an
  // independent reference, also at u == U[p] and u == U[nu] of unclamped
  // (uniform) knots and at a knot of multiplicity p (a C0 crease).
  std::mt19937 rng(113);
  BsplineCurve C, D;
  C.p = 3;
  C.U = uniform_knots(6, 3);  // 0, 1, ..., 10: domain [3, 7]
  D.p = 2;
  D.U = {0, 0, 0, 0.3, 0.6, 0.6, 1, 1, 1};  // 0.6 has multiplicity p = 2
  for (int i = 0; i < 7; ++i) C.P.push_back(RandomPoint(rng));
  for (int j = 0; j < 6; ++j) D.P.push_back(RandomPoint(rng));
  BsplineSurface s;
  s.p = C.p;
  s.q = D.p;
  s.U = C.U;
  s.V = D.U;
  s.nu = 7;
  s.nv = 6;
  for (const Vec3& Ci : C.P)
    for (const Vec3& Dj : D.P) s.P.push_back(Ci + Dj);
  EXPECT_EQ(domain_u(s).a, 3);
  EXPECT_EQ(domain_u(s).b, 7);
  for (double u : {3.0, 4.0, 5.5, 7.0})
    for (double v : {0.0, 0.3, 0.6, 0.8, 1.0}) {
      const auto SKL = surface_derivs(s, u, v, 2);
      const auto Cd = curve_derivs(C, u, 2), Dd = curve_derivs(D, v, 2);
      EXPECT_TRUE(RelNear(SKL[0][0], Cd[0] + Dd[0], kSameValue)) << "u=" << u << " v=" << v;
      EXPECT_TRUE(RelNear(SKL[1][0], Cd[1], kSameValue)) << "u=" << u << " v=" << v;
      EXPECT_TRUE(RelNear(SKL[0][1], Dd[1], kSameValue)) << "u=" << u << " v=" << v;  // right limit at 0.6
      EXPECT_TRUE(RelNear(SKL[2][0], Cd[2], kSameValue)) << "u=" << u << " v=" << v;
      EXPECT_TRUE(Near(SKL[1][1], {}, kSameValue));  // no twist in a sum of curves
    }
  // The batched grid agrees at the same parameters.
  std::vector<Vec3> points;
  surface_grid(s, {3, 7}, {0, 0.6, 1}, points, nullptr);
  EXPECT_TRUE(RelNear(points[1], curve_point(C, 3) + curve_point(D, 0.6), kSameValue));
  EXPECT_TRUE(RelNear(points[5], curve_point(C, 7) + curve_point(D, 1), kSameValue));
}

TEST(BsplineSurface, AffineInvarianceOfNurbs) {
  std::mt19937 rng(67);
  for (int trial = 0; trial < 10; ++trial) {
    const BsplineSurface s = RandomBspline(rng, 3, 3, 6, 5, true);
    BsplineSurface moved = s;
    auto phi = [](Vec3 p) { return Vec3{2 * p.x - p.y + 1, 0.5 * p.y + 3 * p.z - 2, p.x + p.z + 4}; };
    for (Vec3& P : moved.P) P = phi(P);
    for (int k = 0; k < 10; ++k) {
      const double u = InDomain(rng, domain_u(s)), v = InDomain(rng, domain_v(s));
      EXPECT_TRUE(RelNear(surface_point(moved, u, v), phi(surface_point(s, u, v)), kSameValue));
    }
  }
}

TEST(BsplineSurface, DerivativesMatchCentralDifferences) {
  // A3.6 / A4.4 against finite differences of the point (Su, Sv) and of the
  // lower derivatives (Suv, Suu, Svv, third order). Degree >= 3 and simple
  // knots keep the surface C^2, so the differences may cross knots.
  std::mt19937 rng(71);
  for (int trial = 0; trial < 30; ++trial) {
    const BsplineSurface s = RandomBspline(rng, UniformInt(rng, 3, 5), UniformInt(rng, 3, 5), 8, 7, trial % 2);
    const ParamInterval du = domain_u(s), dv = domain_v(s);
    const double hu = kStep * (du.b - du.a), hv = kStep * (dv.b - dv.a);
    for (int k = 0; k < 10; ++k) {
      const double u = Uniform(rng, du.a + hu, du.b - hu), v = Uniform(rng, dv.a + hv, dv.b - hv);
      const auto D = surface_derivs(s, u, v, 3);
      const auto Dup = surface_derivs(s, u + hu, v, 2), Ddn = surface_derivs(s, u - hu, v, 2);
      const auto Dvp = surface_derivs(s, u, v + hv, 2), Dvn = surface_derivs(s, u, v - hv, 2);
      EXPECT_TRUE(RelNear(D[1][0], (Dup[0][0] - Ddn[0][0]) / (2 * hu), kFiniteDifference));
      EXPECT_TRUE(RelNear(D[0][1], (Dvp[0][0] - Dvn[0][0]) / (2 * hv), kFiniteDifference));
      EXPECT_TRUE(RelNear(D[1][1], (Dvp[1][0] - Dvn[1][0]) / (2 * hv), kFiniteDifference));  // twist
      EXPECT_TRUE(RelNear(D[1][1], (Dup[0][1] - Ddn[0][1]) / (2 * hu), kFiniteDifference));  // symmetric
      EXPECT_TRUE(RelNear(D[2][0], (Dup[1][0] - Ddn[1][0]) / (2 * hu), kFiniteDifference));
      EXPECT_TRUE(RelNear(D[0][2], (Dvp[0][1] - Dvn[0][1]) / (2 * hv), kFiniteDifference));
      EXPECT_TRUE(RelNear(D[2][1], (Dvp[2][0] - Dvn[2][0]) / (2 * hv), 10 * kFiniteDifference));
      EXPECT_TRUE(RelNear(D[1][2], (Dup[0][2] - Ddn[0][2]) / (2 * hu), 10 * kFiniteDifference));
      const SurfacePartials P = surface_partials(s, u, v);
      EXPECT_TRUE(Near(P.Suv, D[1][1], 0));
      EXPECT_TRUE(Near(surface_twist(s, u, v), D[1][1], 0));
    }
  }
}

TEST(BsplineSurface, NormalsAreUnitAndOrthogonal) {
  std::mt19937 rng(73);
  for (int trial = 0; trial < 20; ++trial) {
    const BsplineSurface s = RandomBspline(rng, UniformInt(rng, 1, 4), UniformInt(rng, 1, 4), 6, 6, trial % 2);
    for (int k = 0; k < 20; ++k) {
      const double u = InDomain(rng, domain_u(s)), v = InDomain(rng, domain_v(s));
      const SurfacePartials d = surface_partials(s, u, v);
      const Vec3 N = surface_normal(s, u, v);
      EXPECT_NEAR(norm(N), 1, kUnitLength);
      EXPECT_NEAR(dot(N, normalized(d.Su)), 0, kOrthogonal);
      EXPECT_NEAR(dot(N, normalized(d.Sv)), 0, kOrthogonal);
    }
  }
}

TEST(NurbsSurface, AllWeightsOneEqualsThePolynomialSurface) {
  std::mt19937 rng(79);
  for (int trial = 0; trial < 20; ++trial) {
    const BsplineSurface poly = RandomBspline(rng, UniformInt(rng, 1, 4), UniformInt(rng, 1, 4), 6, 5, false);
    BsplineSurface rat = poly;
    rat.w.assign(poly.P.size(), 1.0);
    for (int k = 0; k < 10; ++k) {
      const double u = InDomain(rng, domain_u(poly)), v = InDomain(rng, domain_v(poly));
      const auto Dp = surface_derivs(poly, u, v, 3), Dr = surface_derivs(rat, u, v, 3);
      for (int a = 0; a <= 3; ++a)
        for (int b = 0; a + b <= 3; ++b)
          EXPECT_TRUE(RelNear(Dr[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)],
                              Dp[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)], kSameValue));
    }
  }
}

TEST(NurbsSurface, ScalingAllWeightsChangesNothing) {
  // Homogeneous coordinates: (c w P, c w) projects to the same point (A4.3).
  std::mt19937 rng(83);
  const BsplineSurface s = RandomBspline(rng, 3, 2, 6, 5, true);
  BsplineSurface scaled = s;
  for (double& w : scaled.w) w *= 7.5;
  for (int k = 0; k < 20; ++k) {
    const double u = InDomain(rng, domain_u(s)), v = InDomain(rng, domain_v(s));
    EXPECT_TRUE(RelNear(surface_point(scaled, u, v), surface_point(s, u, v), kSameValue));
    EXPECT_TRUE(RelNear(surface_partials(scaled, u, v).Suv, surface_partials(s, u, v).Suv, kSameValue));
  }
}

TEST(NurbsSurface, RevolvedCircleIsAnExactSphere) {
  // The NURBS Book §7.5 circle revolved by A8.1: every point lies at distance R.
  const double R = 2.5;
  const BsplineSurface sphere = Sphere(R);
  EXPECT_EQ(sphere.nu, 9);
  EXPECT_EQ(sphere.nv, 9);
  for (int a = 0; a <= 40; ++a)
    for (int b = 0; b <= 40; ++b) {
      const double u = a / 40.0, v = b / 40.0;
      const Vec3 S = surface_point(sphere, u, v);
      EXPECT_NEAR(norm(S), R, kExactRadius * R) << "u=" << u << " v=" << v;
      // The normal is radial: N = +-S / R, at the poles (u = 1/4, 3/4) too,
      // where Sv = 0 and the fallback takes over.
      const Vec3 N = surface_normal(sphere, u, v);
      EXPECT_NEAR(norm(N), 1, kUnitLength);
      EXPECT_NEAR(std::fabs(dot(N, S / R)), 1, kSameDirection) << "u=" << u << " v=" << v;
    }
}

TEST(NurbsSurface, RevolvedLineIsAnExactCylinder) {
  const double R = 1.75;
  BsplineCurve line;
  line.p = 1;
  line.U = {0, 0, 1, 1};
  line.P = {{R, 0, -1}, {R, 0, 2}};
  const BsplineSurface cylinder = revolved_surface(line);
  std::mt19937 rng(89);
  for (int k = 0; k < 200; ++k) {
    const Vec3 S = surface_point(cylinder, Uniform(rng, 0, 1), Uniform(rng, 0, 1));
    EXPECT_NEAR(std::hypot(S.x, S.y), R, kExactRadius * R);
    EXPECT_GE(S.z, -1 - kSameValue);
    EXPECT_LE(S.z, 2 + kSameValue);
  }
}

TEST(SurfaceNormal, DegenerateNormalAtThePoleIsTheLimit) {
  // At the pole u = 1/4 every v maps to (0, 0, R): Sv = 0 there. The normal
  // is the limit from inside (u slightly larger: the side find_span uses).
  const BsplineSurface sphere = Sphere(1);
  for (double v : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
    const SurfacePartials d = surface_partials(sphere, 0.25, v);
    EXPECT_NEAR(norm(d.Sv), 0, kSameValue);
    const Vec3 N = surface_normal(sphere, 0.25, v);
    const Vec3 nearby = surface_normal(sphere, 0.25 + 1e-6, v);
    EXPECT_TRUE(Near(N, nearby, kLimitDirection)) << "v=" << v;
    EXPECT_TRUE(Near(N, {0, 0, 1}, kSameDirection)) << "v=" << v;  // outward at u > 1/4 (x < 0 half)
  }
}

TEST(SurfaceNormal, CollapsedEdgeOfABezierPatchAndACollapsedSurface) {
  std::mt19937 rng(97);
  BezierSurface s = RandomBezier(rng, 3, 3, true);
  for (int j = 0; j <= 3; ++j) s.point(0, j) = {1, 2, 3};  // the edge u = 0 is one point
  for (double v : {0.0, 0.3, 0.8, 1.0}) {
    const Vec3 N = surface_normal(s, 0, v);
    EXPECT_NEAR(norm(N), 1, kUnitLength);
    EXPECT_TRUE(Near(N, surface_normal(s, 1e-7, v), kLimitDirection)) << "v=" << v;
  }
  std::fill(s.P.begin(), s.P.end(), Vec3{1, 2, 3});  // no tangent plane anywhere
  EXPECT_TRUE(Near(surface_normal(s, 0.5, 0.5), {}, 0));
}

TEST(IsoCurve, EqualsSurfaceAlongTheLine) {
  std::mt19937 rng(101);
  for (int trial = 0; trial < 20; ++trial) {
    const BsplineSurface s = RandomBspline(rng, UniformInt(rng, 1, 4), UniformInt(rng, 1, 4), 7, 6, trial % 2);
    const ParamInterval du = domain_u(s), dv = domain_v(s);
    // Random parameters, an interior knot, and both ends of the domain.
    for (double u0 : {InDomain(rng, du), s.U[static_cast<std::size_t>(s.p) + 1], du.a, du.b}) {
      const BsplineCurve c = iso_curve_u(s, u0);
      EXPECT_EQ(c.p, s.q);
      EXPECT_EQ(c.rational(), s.rational());
      for (int k = 0; k <= 10; ++k) {
        const double v = dv.a + k * (dv.b - dv.a) / 10;
        EXPECT_TRUE(RelNear(curve_point(c, v), surface_point(s, u0, v), kSameValue));
      }
    }
    for (double v0 : {InDomain(rng, dv), dv.a, dv.b}) {
      const BsplineCurve c = iso_curve_v(s, v0);
      EXPECT_EQ(c.p, s.p);
      for (int k = 0; k <= 10; ++k) {
        const double u = du.a + k * (du.b - du.a) / 10;
        EXPECT_TRUE(RelNear(curve_point(c, u), surface_point(s, u, v0), kSameValue));
      }
    }
  }
}

TEST(SurfaceGrid, EqualsPerPointEvaluation) {
  std::mt19937 rng(103);
  for (int trial = 0; trial < 12; ++trial) {
    const BsplineSurface s = trial == 0 ? Sphere(1.5)
                                        : RandomBspline(rng, UniformInt(rng, 1, 4), UniformInt(rng, 1, 4),
                                                        UniformInt(rng, 5, 9), UniformInt(rng, 5, 9), trial % 2);
    const ParamInterval du = domain_u(s), dv = domain_v(s);
    std::vector<double> us{du.a}, vs{dv.a};
    for (int k = 1; k < 17; ++k) us.push_back(du.a + k * (du.b - du.a) / 17);
    for (int k = 1; k < 13; ++k) vs.push_back(dv.a + k * (dv.b - dv.a) / 13);
    us.push_back(du.b);
    vs.push_back(dv.b);
    us.push_back(s.U[static_cast<std::size_t>(s.p) + 1]);  // an interior knot, out of order
    std::vector<Vec3> points, normals, points_only;
    surface_grid(s, us, vs, points, &normals);
    surface_grid(s, us, vs, points_only, nullptr);
    ASSERT_EQ(points.size(), us.size() * vs.size());
    ASSERT_EQ(normals.size(), points.size());
    EXPECT_EQ(points_only, points);
    std::vector<Vec3> none{Vec3{}}, no_normals{Vec3{}};
    surface_grid(s, {}, vs, none, &no_normals);  // an empty grid is empty, not an error
    EXPECT_TRUE(none.empty());
    EXPECT_TRUE(no_normals.empty());
    for (std::size_t a = 0; a < us.size(); ++a)
      for (std::size_t b = 0; b < vs.size(); ++b) {
        const std::size_t k = a * vs.size() + b;
        EXPECT_TRUE(RelNear(points[k], surface_point(s, us[a], vs[b]), kSameValue));
        EXPECT_TRUE(Near(normals[k], surface_normal(s, us[a], vs[b]), kSameDirection))
            << "trial " << trial << " u=" << us[a] << " v=" << vs[b];
      }
  }
}

TEST(SurfaceEvaluator, EqualsPointNormalAndPartialsAndOutlivesTheSurface) {
  std::mt19937 rng(107);
  SurfaceEvaluator evaluate;
  BsplineSurface copy;
  {
    const BsplineSurface s = RandomBspline(rng, 3, 3, 6, 6, true);
    copy = s;
    evaluate = surface_evaluator(s);
  }
  const UvDomain dom = uv_domain(copy);
  EXPECT_EQ(dom.u0, domain_u(copy).a);
  EXPECT_EQ(dom.v1, domain_v(copy).b);
  for (int k = 0; k < 20; ++k) {
    const double u = Uniform(rng, dom.u0, dom.u1), v = Uniform(rng, dom.v0, dom.v1);
    const SurfaceSample x = evaluate(u, v);
    const SurfacePartials d = surface_partials(copy, u, v);
    EXPECT_TRUE(RelNear(x.point, d.S, kSameValue));
    EXPECT_TRUE(RelNear(x.du, d.Su, kSameValue));
    EXPECT_TRUE(RelNear(x.dv, d.Sv, kSameValue));
    EXPECT_TRUE(Near(x.normal, surface_normal(copy, u, v), kSameDirection));
  }
  EXPECT_NE(What([&] { evaluate(5, 0.5); }).find("u=5 is outside the domain"), std::string::npos);
  // The pole of the sphere: a unit normal from surface_normal's fallback.
  const SurfaceSample pole = surface_evaluator(Sphere(1))(0.25, 0.3);
  EXPECT_TRUE(Near(pole.normal, {0, 0, 1}, kSameDirection));
}

TEST(SurfaceEvaluator, TessellatedSphereHasVerticesAtTheRadius) {
  // The adapter feeds tessellate.h: every vertex of the mesh lies on the sphere
  // and its normal is radial.
  const double R = 1.25;
  const BsplineSurface sphere = Sphere(R);
  const Mesh mesh = tessellate_surface(surface_evaluator(sphere), uv_domain(sphere),
                                       TessellationOptions::fixed_steps(16, 12));
  ASSERT_FALSE(mesh.positions.empty());
  for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
    EXPECT_NEAR(norm(mesh.positions[k]), R, kExactRadius * R);
    EXPECT_NEAR(std::fabs(dot(mesh.normals[k], mesh.positions[k] / R)), 1, kSameDirection);
  }
}

TEST(ToHomogeneous, PremultipliesByTheWeight) {
  BsplineSurface s = to_bspline(LectureExtrusion());
  s.w = {1, 2, 3, 4, 5, 6, 7, 8};
  const std::vector<Vec4> Pw = to_homogeneous(s);
  ASSERT_EQ(Pw.size(), 8u);
  EXPECT_EQ(Pw[3], (Vec4{4 * 2, 4 * 4.5, 4 * 1, 4}));  // P(1, 1) = (2, 4.5, 1), w = 4
}

// ==== errors name the values ===================================================================

BsplineSurface SmallSurface() {
  BsplineSurface s;
  s.p = 2;
  s.q = 1;
  s.nu = 4;
  s.nv = 3;
  s.U = {0, 0, 0, 0.5, 1, 1, 1};
  s.V = {0, 0, 0.5, 1, 1};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) s.P.push_back({double(i), double(j), double(i * j)});
  return s;
}

TEST(ValidateSurface, ErrorsNameTheValues) {
  EXPECT_NO_THROW(validate(SmallSurface()));
  {
    BsplineSurface s = SmallSurface();
    s.P.pop_back();
    EXPECT_EQ(What([&] { validate(s); }), "B-spline surface: P.size()=11 != nu*nv = 4*3 = 12");
  }
  {
    BsplineSurface s = SmallSurface();
    s.w.assign(12, 1.0);
    s.w[1 * 3 + 2] = 0;
    EXPECT_EQ(What([&] { validate(s); }), "B-spline surface: weight w(1, 2)=0 must be > 0");
    s.w[1 * 3 + 2] = -0.5;
    EXPECT_EQ(What([&] { validate(s); }), "B-spline surface: weight w(1, 2)=-0.5 must be > 0");
    s.w[1 * 3 + 2] = std::nan("");
    EXPECT_EQ(What([&] { validate(s); }), "B-spline surface: weight w(1, 2)=nan is not finite");
    s.w.pop_back();
    EXPECT_NE(What([&] { validate(s); }).find("w.size()=11 != nu*nv = 12"), std::string::npos);
  }
  {
    BsplineSurface s = SmallSurface();
    s.point(2, 1).y = std::nan("");
    EXPECT_EQ(What([&] { validate(s); }), "B-spline surface: P(2, 1)=(2, nan, 2) is not finite");
  }
  {
    BsplineSurface s = SmallSurface();
    s.V[2] = 2;  // decreasing
    EXPECT_EQ(What([&] { validate(s); }).rfind("V knot vector", 0), 0u);
    // The message names the V array, not U.
    EXPECT_NE(What([&] { validate(s); }).find("V[3]="), std::string::npos) << What([&] { validate(s); });
    EXPECT_EQ(What([&] { validate(s); }).find("U["), std::string::npos) << What([&] { validate(s); });
    s = SmallSurface();
    s.U.pop_back();
    EXPECT_EQ(What([&] { validate(s); }).rfind("U knot vector", 0), 0u);
  }
  {
    BsplineSurface s = SmallSurface();
    s.nu = 1;  // one control row for degree 2
    s.U = {0, 0, 0, 1};
    s.P.resize(3);
    EXPECT_EQ(What([&] { validate(s); }),
              "U knot vector: degree p=2 needs at least p + 1 = 3 control points, has 1");
  }
  {
    BsplineSurface s = SmallSurface();
    s.nu = 0;
    EXPECT_NE(What([&] { validate(s); }).find("(nu, nv)=(0, 3)"), std::string::npos);
  }
}

TEST(ValidateSurface, ParametersOutsideTheDomain) {
  const BsplineSurface s = SmallSurface();
  EXPECT_EQ(What([&] { surface_point(s, 1.5, 0.5); }), "surface_point: u=1.5 is outside the domain [0, 1]");
  EXPECT_EQ(What([&] { surface_point(s, 0.5, -0.25); }), "surface_point: v=-0.25 is outside the domain [0, 1]");
  EXPECT_EQ(What([&] { surface_normal(s, std::nan(""), 0.5); }), "surface_normal: u=nan is not finite");
  EXPECT_EQ(What([&] { surface_derivs(s, 0.5, 0.5, -1); }), "surface_derivs: derivative order d=-1 is negative");
  std::vector<Vec3> points;
  EXPECT_EQ(What([&] { surface_grid(s, {0, 0.5, 2}, {0.5}, points, nullptr); }),
            "surface_grid: us[2]=2 is outside the domain [0, 1]");
  EXPECT_EQ(What([&] { iso_curve_v(s, 3); }), "iso_curve_v: v0=3 is outside the domain [0, 1]");
}

TEST(ValidateSurface, BezierLagrangeHermiteErrors) {
  BezierSurface b;
  b.n = 2;
  b.m = 1;
  b.P.assign(5, Vec3{});
  EXPECT_EQ(What([&] { validate(b); }), "Bezier surface: P.size()=5 != (n+1)*(m+1) = 3*2 = 6");
  b.P.assign(6, Vec3{});
  b.d = b.c;
  EXPECT_EQ(What([&] { validate(b); }), "Bezier surface: v interval [c, d] = [0, 0] is empty (need c < d)");
  b.d = 1;
  EXPECT_EQ(What([&] { surface_point(b, 1.25, 0); }),
            "surface_point (Bezier): u=1.25 is outside the u interval [0, 1] (above)");
  // A parameter that misses the interval by round-off only is snapped onto it (bezier.h's rule).
  EXPECT_NO_THROW(surface_point(b, 1 + 1e-16, 0));
  b.n = 0;
  b.m = 0;
  b.P.assign(1, Vec3{});
  EXPECT_NE(What([&] { to_bspline(b); }).find("degree >= 1"), std::string::npos);
  EXPECT_EQ(What([&] { interpolating_bezier_surface({0, 1}, {0, 1}, {Vec3{}}); }),
            "interpolating_bezier_surface: points.size()=1 != us.size()*vs.size() = 2*2");
  EXPECT_NE(What([&] { interpolating_bezier_surface({0, 0}, {0, 1}, std::vector<Vec3>(4)); }).find("coincide"),
            std::string::npos);
  const LagrangeSurface L{{0, 1, 1}, {0}, std::vector<Vec3>(3)};
  EXPECT_EQ(What([&] { validate(L); }),
            "Lagrange surface: u_nodes[1]=1 and u_nodes[2]=1 coincide (nodes must be pairwise distinct)");
  HermitePatch h;
  h.twist[1][0].z = INFINITY;
  EXPECT_EQ(What([&] { validate(h); }), "Hermite patch: twist(1, 0)=(0, 0, inf) is not finite");
  HermiteLagrangeSurface hl{{0, 1}, {Vec3{}, Vec3{}}, {Vec3{}}, {Vec3{}, Vec3{}}, {Vec3{}, Vec3{}}};
  EXPECT_EQ(What([&] { validate(hl); }), "Hermite-Lagrange surface: p1.size()=1 != v_nodes.size()=2");
}

}  // namespace
}  // namespace gllab::spline
