// tests/deform/plane_test.cpp — deformations of the unit square, their
// inverse and the feature fit (common/deform/plane.cpp).
//
// Every expected value names its origin: linear precision of the Greville
// abscissae, an affine map of the control points, central differences whose
// error is c h^2, the residual of the equation inverse_point solves, the
// membrane-energy minimiser written out as a dense Lagrange system, the
// discrete harmonic property away from the features, or the support of a
// B-spline (The NURBS Book P2.1).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "deform/plane.h"
#include "deform/volume.h"
#include "deform_checks.h"
#include "spline/basis.h"
#include "spline/interpolation.h"
#include "spline/knots.h"

namespace gllab::deform {
namespace {

using testing::error_of;
using testing::kOrderSlack;
using testing::kUlp;
using testing::observed_order;
using testing::Random;
using testing::record;

// ---- tolerances (named, never loosened to pass) -----------------------------

/// The identity reproduces x to 1e-15 up to degree 3; at high degree A2.2's
/// basis values sum to 1 only within about p/2 ulps (volume_test.cpp), so
/// max(1e-15, (p + 1) ulps), as for the volume.
double identity_bound(int p) { return std::max(1e-15, (p + 1) * kUlp); }
/// J of the identity or an affine map: derivative basis values of size
/// p / spacing cancel; (p + 1) ulps of that per direction, twice, times the
/// net's size (as volume_test.cpp).
double jacobian_bound(int p, double spacing, double size) {
  return 2 * (p + 1) * kUlp * p / spacing * size;
}
/// fit_features meets its features to this (the bound; the solve's
/// residual is a few ulps of the displacements times the condition of W W^T).
constexpr double kFeatureMet = 1e-12;
/// Two solvers of one linear system (the core's band Cholesky and Schur
/// complement, the test's dense elimination): relative to the largest
/// displacement, the condition of the systems (about 1e3 here) times ulps.
constexpr double kTwoSolvers = 1e-12;

// ---- helpers ----------------------------------------------------------------

double dist(Vec2 a, Vec2 b) { return std::max(std::fabs(a.x - b.x), std::fabs(a.y - b.y)); }

/// 12 features on a 4 x 3 pattern over the square, each moved by up to 0.04
/// in a seeded random direction; from and to well inside (0, 1)^2 and 0.2
/// apart, so the grid of 9 x 9 cubic points meets them comfortably.
struct Features {
  std::vector<Vec2> from, to;
};
Features twelve_features(unsigned seed) {
  Random r(seed);
  Features f;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec2 p{0.2 + 0.2 * i + r.real(-0.03, 0.03), 0.25 + 0.25 * j + r.real(-0.03, 0.03)};
      f.from.push_back(p);
      f.to.push_back(p + Vec2{r.real(-0.04, 0.04), r.real(-0.04, 0.04)});
    }
  return f;
}

PlaneDeformation fitted(unsigned seed) {
  const Features f = twelve_features(seed);
  return fit_features(identity_plane(9, 9, 3), f.from, f.to);
}

/// (1 - t) x + t f2(x): the morph's in-between map, evaluated independently.
Vec2 blend(const PlaneDeformation& f2, double t, Vec2 x) {
  return (1 - t) * x + t * plane_derivs(f2, x).f;
}

// ---- the identity and affine maps -------------------------------------------

void expect_identity(const PlaneDeformation& f) {
  SCOPED_TRACE(std::to_string(f.count[0]) + " x " + std::to_string(f.count[1]) + " degree " +
               std::to_string(f.degree));
  const double spacing = 1.0 / (std::min(f.count[0], f.count[1]) - f.degree);
  Random r(211);  // seed 211: random points of the square, then its corners and edges
  std::vector<Vec2> xs = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0, 0.3}, {1, 0.6}, {0.2, 0}, {0.7, 1}};
  for (int n = 0; n < 500; ++n) xs.push_back({r.real(0, 1), r.real(0, 1)});
  for (const Vec2 x : xs) {
    const PlaneDerivs d = plane_derivs(f, x);
    EXPECT_LE(dist(d.f, x), identity_bound(f.degree)) << x.x << " " << x.y;
    EXPECT_LE(dist(d.fx, {1, 0}), jacobian_bound(f.degree, spacing, 1));
    EXPECT_LE(dist(d.fy, {0, 1}), jacobian_bound(f.degree, spacing, 1));
  }
}

TEST(Plane, IdentityPlaneMapsEveryPointToItself) {
  // plane.h: c_ij at the Greville abscissae, f = identity (linear precision).
  expect_identity(identity_plane(7, 7, 3));
  expect_identity(identity_plane(2, 2, 1));
  expect_identity(identity_plane(4, 4, 3));  // count = degree + 1: Bernstein
  expect_identity(identity_plane(5, 9, 2));
  expect_identity(identity_plane(kMaxLatticePoints, kMaxLatticePoints, 3));
  expect_identity(identity_plane(16, 20, kMaxLatticeDegree));
}

TEST(Plane, IdentityControlPointsAreTheGrevilleAbscissae) {
  // spline/knots.h: clamped uniform knots 0,0,0,1/4,1/2,3/4,1,1,1 for 6
  // quadratic points: g = (0, 1/8, 3/8, 5/8, 7/8, 1).
  const PlaneDeformation f = identity_plane(6, 2, 1);
  EXPECT_EQ(f.point(0, 0), (Vec2{0, 0}));
  EXPECT_EQ(f.point(5, 1), (Vec2{1, 1}));
  const PlaneDeformation q = identity_plane(6, 6, 2);
  const double g[6] = {0, 0.125, 0.375, 0.625, 0.875, 1};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) EXPECT_EQ(q.point(i, j), (Vec2{g[i], g[j]}));
  EXPECT_TRUE(q.on_border(0, 3));
  EXPECT_TRUE(q.on_border(5, 5));
  EXPECT_FALSE(q.on_border(1, 4));
}

TEST(Plane, AffineControlPointsGiveTheAffineMap) {
  // An affine map of the control points commutes with the convex
  // combination: f = A x + b, J = A. Bounds: (p + 3) ulps of the net's size
  // (the identity's p + 1 and the rounding of A c + b) and jacobian_bound.
  const Mat2 A{{1.2, -0.3}, {0.4, 0.8}};
  const Vec2 b{-0.25, 0.6};
  for (PlaneDeformation f : {identity_plane(7, 7, 3), identity_plane(4, 6, 2)}) {
    for (Vec2& c : f.P) c = A * c + b;
    double size = 0;
    for (const Vec2 c : f.P) size = std::max({size, std::fabs(c.x), std::fabs(c.y)});
    const double spacing = 1.0 / (std::min(f.count[0], f.count[1]) - f.degree);
    Random r(221);  // seed 221
    for (int n = 0; n < 300; ++n) {
      const Vec2 x{r.real(0, 1), r.real(0, 1)};
      const PlaneDerivs d = plane_derivs(f, x);
      EXPECT_LE(dist(d.f, A * x + b), (f.degree + 3) * kUlp * size);
      EXPECT_LE(dist(d.fx, A.c0), jacobian_bound(f.degree, spacing, size));
      EXPECT_LE(dist(d.fy, A.c1), jacobian_bound(f.degree, spacing, size));
    }
  }
}

TEST(Plane, EvaluatorGivesWhatPlaneDerivsGives) {
  const PlaneDeformation f = fitted(231);
  const PlaneEvaluator eval(f);
  for (const Vec2 x : {Vec2{0, 0}, Vec2{0.3, 0.7}, Vec2{1, 0.5}, Vec2{0.999, 0.001}}) {
    const PlaneDerivs a = eval(x), b = plane_derivs(f, x);
    EXPECT_EQ(a.f, b.f);
    EXPECT_EQ(a.fx, b.fx);
    EXPECT_EQ(a.fy, b.fy);
  }
}

// ---- derivatives ------------------------------------------------------------

Vec2 cd_errors(const PlaneDeformation& f, Vec2 x, double h) {
  const PlaneDerivs d = plane_derivs(f, x);
  const auto at = [&](Vec2 y) { return plane_derivs(f, y).f; };
  const Vec2 cx = (at(x + Vec2{h, 0}) - at(x - Vec2{h, 0})) / (2 * h);
  const Vec2 cy = (at(x + Vec2{0, h}) - at(x - Vec2{0, h})) / (2 * h);
  return {dist(cx, d.fx), dist(cy, d.fy)};
}

TEST(Plane, PartialsAgreeWithCentralDifferencesAtSecondOrder) {
  // Central differences: error h^2/6 f''' + O(h^4), ratio 4 per halving. The
  // fitted 9 x 9 cubic (knots at multiples of 1/6) at points whose stencils
  // (h <= 0.02) stay inside one knot span.
  const PlaneDeformation f = fitted(241);
  const double h = 0.02;
  for (const Vec2 x : {Vec2{0.25, 0.6}, Vec2{0.42, 0.09}, Vec2{0.75, 0.92}}) {
    const Vec2 e1 = cd_errors(f, x, h), e2 = cd_errors(f, x, h / 2), e3 = cd_errors(f, x, h / 4);
    static int n = 0;
    record("order x " + std::to_string(++n), observed_order(e1.x, e2.x));
    record("order y h/2 " + std::to_string(n), observed_order(e2.y, e3.y));
    EXPECT_NEAR(observed_order(e1.x, e2.x), 2.0, kOrderSlack) << e1.x << " " << e2.x;
    EXPECT_NEAR(observed_order(e2.x, e3.x), 2.0, kOrderSlack) << e2.x << " " << e3.x;
    EXPECT_NEAR(observed_order(e1.y, e2.y), 2.0, kOrderSlack) << e1.y << " " << e2.y;
    EXPECT_NEAR(observed_order(e2.y, e3.y), 2.0, kOrderSlack) << e2.y << " " << e3.y;
  }
}

// ---- the inverse ------------------------------------------------------------

TEST(Plane, InversePointSolvesTheBlendForManyPointsAndTimes) {
  // plane.h: x with |(1 - t) x + t f2(x) - y| <= kInverseTolerance, in the
  // square. f2 from 12 features (nothing folds); 400 random y (seed 251) and
  // the square's corners and edges, t = 0, 1/4, 1/2, 3/4, 1. The residual is
  // computed here again with plane_derivs (the same sums in the same order
  // as the solver's, so the same number).
  const PlaneDeformation f2 = fitted(252);
  const PlaneEvaluator eval(f2);
  Random r(251);
  std::vector<Vec2> ys = {{0, 0}, {1, 1}, {0, 1}, {1, 0}, {0, 0.4}, {1, 0.7}, {0.35, 0}, {0.5, 1}};
  for (int n = 0; n < 400; ++n) ys.push_back({r.real(0, 1), r.real(0, 1)});
  double worst = 0;
  for (const double t : {0.0, 0.25, 0.5, 0.75, 1.0})
    for (const Vec2 y : ys) {
      const std::optional<Vec2> x = inverse_point(eval, t, y, y);
      ASSERT_TRUE(x.has_value()) << "t " << t << " y " << y.x << " " << y.y;
      EXPECT_GE(x->x, 0);
      EXPECT_LE(x->x, 1);
      EXPECT_GE(x->y, 0);
      EXPECT_LE(x->y, 1);
      EXPECT_LE(norm(blend(f2, t, *x) - y), kInverseTolerance) << "t " << t;
      worst = std::max(worst, norm(blend(f2, t, *x) - y));
    }
  record("largest residual", worst);
}

TEST(Plane, InverseAtTimeZeroIsThePointItself) {
  // f(0, x) = x: from the guess y the residual is 0 at once; x = y bit for bit.
  const PlaneEvaluator eval(fitted(261));
  for (const Vec2 y : {Vec2{0.3, 0.8}, Vec2{0, 1}, Vec2{0.123456789, 0.5}})
    EXPECT_EQ(*inverse_point(eval, 0, y, y), y);
}

TEST(Plane, InverseFromAFarGuessStillConverges) {
  // The damped Newton step: from the opposite corner of the square.
  const PlaneDeformation f2 = fitted(271);
  const PlaneEvaluator eval(f2);
  for (const Vec2 y : {Vec2{0.1, 0.15}, Vec2{0.9, 0.8}, Vec2{0.5, 0.5}}) {
    const std::optional<Vec2> x = inverse_point(eval, 1, y, Vec2{1, 1} - y);
    ASSERT_TRUE(x.has_value());
    EXPECT_LE(norm(blend(f2, 1, *x) - y), kInverseTolerance);
  }
}

TEST(Plane, InverseHasNoAnswerOutsideTheImageOrFromAFold) {
  // plane.h: x kept in the square. Where y has no preimage in the square (a
  // map that shrinks the square to its middle half: f2 = 1/4 + x/2), there
  // is none; and a guess where f folds (det J <= 0) gives none either.
  PlaneDeformation shrink = identity_plane(2, 2, 1);
  for (Vec2& c : shrink.P) c = Vec2{0.25, 0.25} + 0.5 * c;
  EXPECT_FALSE(inverse_point(PlaneEvaluator(shrink), 1, {0.1, 0.5}, {0.5, 0.5}).has_value());
  EXPECT_TRUE(inverse_point(PlaneEvaluator(shrink), 1, {0.3, 0.5}, {0.5, 0.5}).has_value());
  PlaneDeformation folded = identity_plane(7, 7, 2);
  folded.point(3, 3).x = 0.85;  // past its neighbour at 0.7
  const PlaneFold fold = find_plane_fold(folded);
  ASSERT_TRUE(fold.folds);
  EXPECT_FALSE(inverse_point(PlaneEvaluator(folded), 1, {0.2, 0.2}, fold.at).has_value());
}

// ---- the feature fit --------------------------------------------------------

TEST(Plane, FitFeaturesMeetsEveryFeatureAndKeepsTheBorder) {
  // plane.h fit_features: f2(from[k]) = to[k] for all 12 features; the
  // border's control points stay (bit for bit), so the border maps onto
  // itself (the identity's bound); the fit does not fold.
  for (const unsigned seed : {281u, 282u, 283u}) {
    const Features f = twelve_features(seed);
    const PlaneDeformation base = identity_plane(9, 9, 3);
    const PlaneDeformation f2 = fit_features(base, f.from, f.to);
    double worst = 0;
    for (std::size_t k = 0; k < f.from.size(); ++k) {
      EXPECT_LE(norm(plane_derivs(f2, f.from[k]).f - f.to[k]), kFeatureMet) << "feature " << k;
      worst = std::max(worst, norm(plane_derivs(f2, f.from[k]).f - f.to[k]));
    }
    record("largest miss " + std::to_string(seed), worst);
    int moved = 0;
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j) {
        if (base.on_border(i, j)) {
          EXPECT_EQ(f2.point(i, j), base.point(i, j)) << i << " " << j;
        } else {
          moved += f2.point(i, j) != base.point(i, j);
        }
      }
    EXPECT_GT(moved, 0);
    for (const double w : {0.0, 0.3, 0.77, 1.0}) {
      EXPECT_LE(dist(plane_derivs(f2, {0, w}).f, {0, w}), identity_bound(3));
      EXPECT_LE(dist(plane_derivs(f2, {1, w}).f, {1, w}), identity_bound(3));
      EXPECT_LE(dist(plane_derivs(f2, {w, 0}).f, {w, 0}), identity_bound(3));
      EXPECT_LE(dist(plane_derivs(f2, {w, 1}).f, {w, 1}), identity_bound(3));
    }
    EXPECT_FALSE(find_plane_fold(f2).folds);
  }
}

/// The membrane energy's minimiser written out densely (an independent
/// solver): K the grid's Laplacian on the inner points (4 on the diagonal:
/// every inner point of a grid has 4 neighbours; -1 for each inner
/// neighbour), W[k][c] = N_i(from_k.x) N_j(from_k.y) by A2.4 OneBasisFun, and
/// the Lagrange system [K W^T; W 0] [d; mu] = [0; r] solved by Gaussian
/// elimination with partial pivoting (spline::gauss_solve). Returns the
/// displacements d of the inner points, row by row.
std::vector<Vec2> dense_fit(const PlaneDeformation& base, const Features& f) {
  const int nx = base.count[0], ny = base.count[1], p = base.degree;
  const int m = (nx - 2) * (ny - 2), n = int(f.from.size());
  const auto c = [&](int i, int j) { return (i - 1) * (ny - 2) + (j - 1); };
  std::vector<std::vector<double>> M(m + n, std::vector<double>(m + n));
  for (int i = 1; i + 1 < nx; ++i)
    for (int j = 1; j + 1 < ny; ++j) {
      M[c(i, j)][c(i, j)] = 4;
      for (const auto& [di, dj] : {std::array<int, 2>{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
        if (!base.on_border(i + di, j + dj)) M[c(i, j)][c(i + di, j + dj)] = -1;
    }
  const std::vector<double> Ux = spline::clamped_uniform_knots(nx - 1, p);
  const std::vector<double> Uy = spline::clamped_uniform_knots(ny - 1, p);
  std::vector<spline::Vec3> rhs(m + n);
  for (int k = 0; k < n; ++k) {
    for (int i = 1; i + 1 < nx; ++i)
      for (int j = 1; j + 1 < ny; ++j) {
        const double w = spline::one_basis_fun(i, f.from[k].x, p, Ux) *
                         spline::one_basis_fun(j, f.from[k].y, p, Uy);
        M[m + k][c(i, j)] = M[c(i, j)][m + k] = w;
      }
    const Vec2 r = f.to[k] - plane_derivs(base, f.from[k]).f;
    rhs[m + k] = {r.x, r.y, 0};
  }
  const std::vector<spline::Vec3> x = spline::gauss_solve(M, rhs);
  std::vector<Vec2> d(m);
  for (int k = 0; k < m; ++k) d[k] = {x[k].x, x[k].y};
  return d;
}

TEST(Plane, FitMinimisesTheMembraneEnergyOfTheDisplacements) {
  // plane.h: the inner points' displacements minimise sum over the grid's
  // edges |d_a - d_b|^2 subject to f2(from[k]) = to[k]. Against the dense
  // Lagrange system above (a different solver: the core uses a band Cholesky
  // of K and the Schur complement W K^-1 W^T): the same displacements to
  // kTwoSolvers of the largest one. 12 features on 9 x 9 and 12 x 10 cubic
  // grids, one feature on a 8 x 8 quadratic one.
  const Features twelve = twelve_features(286), one{{{0.3, 0.62}}, {{0.34, 0.58}}};
  struct Case {
    PlaneDeformation base;
    const Features* f;
  };
  for (const Case& c : {Case{identity_plane(9, 9, 3), &twelve},
                        Case{identity_plane(12, 10, 3), &twelve},
                        Case{identity_plane(8, 8, 2), &one}}) {
    const PlaneDeformation f2 = fit_features(c.base, c.f->from, c.f->to);
    const std::vector<Vec2> d = dense_fit(c.base, *c.f);
    double largest = 0;
    for (const Vec2 v : d) largest = std::max({largest, std::fabs(v.x), std::fabs(v.y)});
    const int ny = c.base.count[1];
    double worst = 0;
    for (int i = 1; i + 1 < c.base.count[0]; ++i)
      for (int j = 1; j + 1 < ny; ++j)
        worst = std::max(worst, dist(f2.point(i, j) - c.base.point(i, j),
                                     d[(i - 1) * (ny - 2) + (j - 1)]) / largest);
    static int n = 0;
    record("relative difference " + std::to_string(++n), worst);
    for (int i = 1; i + 1 < c.base.count[0]; ++i)
      for (int j = 1; j + 1 < ny; ++j)
        EXPECT_LE(dist(f2.point(i, j) - c.base.point(i, j), d[(i - 1) * (ny - 2) + (j - 1)]),
                  kTwoSolvers * largest)
            << i << " " << j;
  }
}

TEST(Plane, FitDisplacementIsHarmonicAwayFromTheFeatures) {
  // plane.h: outside the features' supports d is a discrete harmonic
  // function: at an inner point whose basis function is 0 at every feature,
  // d equals the mean of its 4 neighbours' (the border's are 0). Features
  // with x < 0.45 on a 10 x 10 cubic grid (knots at k/7): N_i is 0 left of
  // U_i, so the points i = 7, 8 (U_7 = 4/7 > 0.45) have no weight at any
  // feature; their displacements are not zero (the membrane spreads) but
  // harmonic.
  Features f = twelve_features(291);
  for (Vec2& p : f.from) p.x *= 0.45 / 0.85;
  for (std::size_t k = 0; k < f.to.size(); ++k) f.to[k] = f.from[k] + Vec2{0.01, -0.02};
  const PlaneDeformation base = identity_plane(10, 10, 3);
  const PlaneDeformation f2 = fit_features(base, f.from, f.to);
  const auto d = [&](int i, int j) { return f2.point(i, j) - base.point(i, j); };
  double largest = 0;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) largest = std::max(largest, norm(d(i, j)));
  for (int i = 7; i < 9; ++i)
    for (int j = 1; j < 9; ++j) {
      const Vec2 mean = 0.25 * (d(i - 1, j) + d(i + 1, j) + d(i, j - 1) + d(i, j + 1));
      EXPECT_LE(dist(d(i, j), mean), kTwoSolvers * largest) << i << " " << j;
      EXPECT_GT(norm(d(i, j)), 0) << i << " " << j;
    }
}

TEST(Plane, FitWithoutFeaturesIsTheBase) {
  const PlaneDeformation base = fitted(301);
  const PlaneDeformation f2 = fit_features(base, {}, {});
  EXPECT_EQ(f2.count, base.count);
  EXPECT_EQ(f2.degree, base.degree);
  ASSERT_EQ(f2.P.size(), base.P.size());
  for (std::size_t k = 0; k < base.P.size(); ++k) EXPECT_EQ(f2.P[k], base.P[k]);
}

TEST(Plane, FitOfARepeatedFeatureWithTheSameTargetMeetsIt) {
  // plane.h names "two at nearly the same place going to different places"
  // as what cannot be met. The same feature given twice (the same place to
  // the same place) can: the fit meets all of them.
  Features f = twelve_features(311);
  f.from.push_back(f.from[4]);
  f.to.push_back(f.to[4]);
  const PlaneDeformation f2 = fit_features(identity_plane(9, 9, 3), f.from, f.to);
  for (std::size_t k = 0; k < f.from.size(); ++k)
    EXPECT_LE(norm(plane_derivs(f2, f.from[k]).f - f.to[k]), kFeatureMet) << "feature " << k;
}

// ---- fit: bad input ---------------------------------------------------------

TEST(Plane, FitWithCountsThatDifferThrowsNamingThem) {
  const Features f = twelve_features(321);
  std::vector<Vec2> to = f.to;
  to.pop_back();
  EXPECT_EQ(error_of([&] { fit_features(identity_plane(9, 9, 3), f.from, to); }),
            "fit_features: 12 feature points but 11 targets");
}

TEST(Plane, FitWithAFeatureOutsideTheOpenSquareThrowsNamingIt) {
  // plane.h: a point outside (0, 1)^2 (the border itself is outside: the
  // border's points cannot move).
  Features f = twelve_features(331);
  const PlaneDeformation base = identity_plane(9, 9, 3);
  f.from[4] = {0, 0.5};
  EXPECT_EQ(error_of([&] { fit_features(base, f.from, f.to); }),
            "fit_features: feature 4 at (0, 0.5) must lie inside (0, 1)^2");
  f.from[4] = f.to[4];
  f.to[9] = {0.5, 1.25};
  EXPECT_EQ(error_of([&] { fit_features(base, f.from, f.to); }),
            "fit_features: feature 9 at (0.5, 1.25) must lie inside (0, 1)^2");
  f.to[9] = {NAN, 0.5};
  EXPECT_EQ(error_of([&] { fit_features(base, f.from, f.to); }),
            "fit_features: feature 9 at (nan, 0.5) must lie inside (0, 1)^2");
}

TEST(Plane, FitOfTwoFeaturesAtOnePlaceGoingApartThrowsNamingTheFeature) {
  // plane.h: "features that the grid cannot meet together (two at nearly the
  // same place going to different places ...)" throw naming the feature.
  // Feature 7 repeats feature 3's place with another target: the message
  // must name feature 7 (the one that cannot be met together with 3), not
  // a feature that is fine.
  Features f = twelve_features(341);
  f.from[7] = f.from[3];
  f.to[7] = f.from[3] + Vec2{-0.03, 0.02};
  const std::string message =
      error_of([&] { fit_features(identity_plane(9, 9, 3), f.from, f.to); });
  EXPECT_NE(message.find("fit_features: feature 7 "), std::string::npos) << message;
}

TEST(Plane, FitOfTwoFeaturesAtNearlyOnePlaceGoingApartThrowsNamingTheFeature) {
  // The same with feature 7 a hair (1e-9, far below any pixel) from feature
  // 3: its weights differ from 3's by about 1e-8, so the two conditions
  // cannot both be met by any reasonable grid; the message names feature 7.
  Features f = twelve_features(342);
  f.from[7] = f.from[3] + Vec2{1e-9, -1e-9};
  f.to[7] = f.from[3] + Vec2{-0.03, 0.02};
  const std::string message =
      error_of([&] { fit_features(identity_plane(9, 9, 3), f.from, f.to); });
  EXPECT_NE(message.find("fit_features: feature 7 "), std::string::npos) << message;
}

TEST(Plane, FitOfMoreFeaturesThanTheGridCanBendToThrowsNamingOne) {
  // 4 x 4 cubic: 2 x 2 interior points, so at most 4 independent features;
  // a fifth cannot be met in general: the message names it (feature 4).
  const PlaneDeformation base = identity_plane(4, 4, 3);
  const std::vector<Vec2> from = {{0.3, 0.3}, {0.7, 0.3}, {0.3, 0.7}, {0.7, 0.7}, {0.5, 0.5}};
  std::vector<Vec2> to = from;
  for (Vec2& p : to) p += Vec2{0.02, 0.01};
  to[4] = {0.45, 0.52};
  const std::string message = error_of([&] { fit_features(base, from, to); });
  EXPECT_NE(message.find("fit_features: feature 4 "), std::string::npos) << message;
}

// ---- folds ------------------------------------------------------------------

TEST(Plane, ControlPointDraggedThroughItsNeighbourFolds) {
  // Quadratic 7 x 7: c_33 at the Greville point (0.5, 0.5), its neighbour
  // c_43 at x = 0.7. Dragged to 0.85, past it: fx . e_x < 0 between them,
  // det J < 0; found near the dragged point (within the spacing 0.2 of
  // (0.5, 0.5)); the text names det J and (x, y) as the header shows.
  PlaneDeformation f = identity_plane(7, 7, 2);
  f.point(3, 3).x = 0.85;
  const PlaneFold fold = find_plane_fold(f);
  EXPECT_TRUE(fold.folds);
  EXPECT_LE(fold.min_det, 0);
  EXPECT_LE(dist(fold.at, {0.5, 0.5}), 0.2) << plane_fold_text(fold);
  EXPECT_EQ(det(plane_derivs(f, fold.at).jacobian()), fold.min_det);
  char expected[128];
  std::snprintf(expected, sizeof expected, "the grid folds: det J = %.3g at (x, y) = (%.2f, %.2f)",
                fold.min_det, fold.at.x, fold.at.y);
  EXPECT_EQ(plane_fold_text(fold), expected);
}

TEST(Plane, UnfoldedDeformationReportsNoFold) {
  const PlaneFold id = find_plane_fold(identity_plane(7, 7, 3));
  EXPECT_FALSE(id.folds);
  EXPECT_EQ(plane_fold_text(id), "no fold: det J >= 1");
  PlaneDeformation f = identity_plane(7, 7, 2);
  f.point(3, 3).x = 0.6;  // towards its neighbour, not past it
  const PlaneFold fold = find_plane_fold(f, 1);
  EXPECT_FALSE(fold.folds);
  EXPECT_GT(fold.min_det, 0);
  char expected[64];
  std::snprintf(expected, sizeof expected, "no fold: det J >= %.3g", fold.min_det);
  EXPECT_EQ(plane_fold_text(fold), expected);
}

TEST(Plane, FoldSamplesOutsideTheirRangeThrowNamingThem) {
  const PlaneDeformation f = identity_plane(4, 4, 2);
  EXPECT_EQ(error_of([&] { find_plane_fold(f, 0); }),
            "find_plane_fold: samples = 0 (must be 1..256)");
  EXPECT_EQ(error_of([&] { find_plane_fold(f, 257); }),
            "find_plane_fold: samples = 257 (must be 1..256)");
}

// ---- bad input --------------------------------------------------------------

TEST(Plane, CountOrDegreeOutsideTheLimitsThrowsNamingIt) {
  EXPECT_EQ(error_of([] { identity_plane(1, 4, 1); }),
            "plane deformation: 1 control points along x (must be 2..64)");
  EXPECT_EQ(error_of([] { identity_plane(4, 65, 1); }),
            "plane deformation: 65 control points along y (must be 2..64)");
  EXPECT_EQ(error_of([] { identity_plane(4, 4, 0); }),
            "plane deformation: degree 0 with 4 x 4 points (must be 1..15 and below both counts)");
  EXPECT_EQ(error_of([] { identity_plane(7, 3, 3); }),
            "plane deformation: degree 3 with 7 x 3 points (must be 1..15 and below both counts)");
  EXPECT_EQ(error_of([] { identity_plane(20, 20, 16); }),
            "plane deformation: degree 16 with 20 x 20 points (must be 1..15 and below both "
            "counts)");
  EXPECT_NO_THROW(identity_plane(2, kMaxLatticePoints, 1));
}

TEST(Plane, WrongOrNonFiniteControlPointsThrowNamingThem) {
  PlaneDeformation f = identity_plane(5, 4, 2);
  f.P.push_back({0.5, 0.5});
  EXPECT_EQ(error_of([&] { validate(f); }), "plane deformation: 21 control points for 5 x 4 = 20");
  EXPECT_EQ(error_of([&] { PlaneEvaluator e(f); }),
            "plane deformation: 21 control points for 5 x 4 = 20");
  f.P.pop_back();
  f.P[13].x = std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of([&] { validate(f); }), "plane deformation: control point P[13] is not finite");
  EXPECT_EQ(error_of([&] { fit_features(f, {}, {}); }),
            "plane deformation: control point P[13] is not finite");
  EXPECT_EQ(error_of([&] { find_plane_fold(f); }),
            "plane deformation: control point P[13] is not finite");
}

TEST(Plane, PointOutsideTheSquareThrowsNamingIt) {
  const PlaneDeformation f = identity_plane(4, 4, 2);
  EXPECT_EQ(error_of([&] { plane_derivs(f, {1.5, 0.5}); }),
            "plane deformation: x = (1.5, 0.5) outside [0, 1]^2");
  EXPECT_EQ(error_of([&] { plane_derivs(f, {0.5, -0.125}); }),
            "plane deformation: x = (0.5, -0.125) outside [0, 1]^2");
  EXPECT_EQ(error_of([&] { plane_derivs(f, {NAN, 0.5}); }),
            "plane deformation: x = (nan, 0.5) outside [0, 1]^2");
  EXPECT_NO_THROW(plane_derivs(f, {1, 0}));
}

}  // namespace
}  // namespace gllab::deform
