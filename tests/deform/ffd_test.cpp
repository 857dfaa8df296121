// tests/deform/ffd_test.cpp — free-form deformation of points and meshes,
// folds and volumes (common/deform/ffd.cpp).
//
// Every expected value names its origin: linear precision (the identity and
// affine lattices), the chain rule and the cofactor identity
// (A a) x (A b) = cof(A) (a x b), central differences whose error is c h^2,
// the divergence theorem V = 1/3 closed-integral X . n dA evaluated with
// Gauss–Legendre (exact for the polynomials at hand), the change of
// variables det A for an affine map, or a count made independently here.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "deform/ffd.h"
#include "deform_checks.h"
#include "spline/quadrature.h"

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

/// The identity lattice maps a point to itself to 1e-15 (the bound),
/// box frames and cubic lattices (measured at most 4 ulps, 8.9e-16).
constexpr double kIdentity = 1e-15;
/// A skewed frame adds the round trip x -> (s, t, u) = M^-1 (x - X0) ->
/// X0 + M (s, t, u): kappa(M) ulps of |x|. With the frame below (kappa_inf
/// = 3.24, |x| < 2) that is up to 6.5 ulps on top of the volume's own error,
/// and 1e-15 is not attainable: over 1e6 random points the B-spline 6 x 6 x 6
/// identity reached 5 ulps = 1.1e-15. The bound: 1e-15 + kappa ulps of |x|.
double skewed_identity_bound(double kappa, double size) { return kIdentity + kappa * size * kUlp; }
/// The Jacobian of an identity or affine lattice: the derivative basis
/// functions (each up to p / spacing in size) cancel to the matrix, so
/// (p + 1) ulps of p / spacing per direction, twice (the partition of unity
/// of the other two directions), times the net's size and |M^-1|.
double jacobian_bound(int p, double spacing, double size) {
  return 2 * (p + 1) * kUlp * p / spacing * size;
}
/// Two exact quadratures of one polynomial integral (the divergence theorem
/// on the faces, deformed_volume's det J): each sums some 10^4..10^5 terms of
/// a few ulps; relative to the volume. The issue's ~1e-12.
constexpr double kExactQuadratures = 1e-12;
/// A quadrature that is not exact (too few points per span) misses by far
/// more than rounding: at least this, relative.
constexpr double kNotExact = 1e-9;
/// Random lattices: the identity plus displacements up to this (in units of
/// the box), small enough that nothing folds.
constexpr double kJiggle = 0.08;

// ---- frames and lattices ----------------------------------------------------

/// A rotated (0.7 rad about z) and sheared parallelepiped, right-handed, det
/// M = 0.761, kappa_inf(M) = 3.24.
Frame skewed_frame() {
  Frame f;
  f.origin = {0.3, -0.2, 0.1};
  const double c = std::cos(0.7), s = std::sin(0.7);
  f.S = {c, s, 0.1};
  f.T = {-0.8 * s + 0.3 * c, 0.8 * c + 0.3 * s, 0.2};
  f.U = {0.1, -0.2, 0.9};
  return f;
}
constexpr double kSkewKappa = 3.25;  // kappa_inf of skewed_frame(), rounded up

/// |A|_inf: the largest row sum.
double norm_inf(const Mat3& a) {
  const Mat3 t = transpose(a);
  return std::max({std::fabs(t.c0.x) + std::fabs(t.c0.y) + std::fabs(t.c0.z),
                   std::fabs(t.c1.x) + std::fabs(t.c1.y) + std::fabs(t.c1.z),
                   std::fabs(t.c2.x) + std::fabs(t.c2.y) + std::fabs(t.c2.z)});
}

double dist(Vec3 a, Vec3 b) { return max_abs(a - b); }
double dist(const Mat3& a, const Mat3& b) {
  return std::max({dist(a.c0, b.c0), dist(a.c1, b.c1), dist(a.c2, b.c2)});
}

/// The identity lattice of `frame` with every control point moved by up to
/// kJiggle times the frame's axes (seeded).
Lattice jiggled(const Frame& frame, const Volume& unit, unsigned seed) {
  Lattice l = identity_lattice(frame, unit);
  Random r(seed);
  for (Vec3& p : l.volume.P) p += frame.matrix() * r.vec3(-kJiggle, kJiggle);
  return l;
}

/// Points of the box: corners, face and edge points, random ones (seeded).
std::vector<Vec3> box_points(const Frame& f, unsigned seed, int random_count) {
  std::vector<Vec3> stu;
  for (int c = 0; c < 8; ++c) stu.push_back({double(c & 1), double((c >> 1) & 1), double(c >> 2)});
  for (double a : {0.0, 1.0}) {
    stu.push_back({a, 0.5, 0.25});
    stu.push_back({0.75, a, 0.5});
    stu.push_back({0.5, 0.125, a});
  }
  Random r(seed);
  for (int n = 0; n < random_count; ++n) stu.push_back(r.vec3(0, 1));
  std::vector<Vec3> x;
  for (const Vec3 w : stu) x.push_back(f.origin + f.matrix() * w);
  return x;
}

int max_degree(const Volume& v) { return std::max({v.degree[0], v.degree[1], v.degree[2]}); }
double min_spacing(const Volume& v) {
  double s = 1;
  for (int a = 0; a < 3; ++a) s = std::min(s, 1.0 / (v.count[a] - v.degree[a]));
  return s;
}
double net_size(const Volume& v) {
  double s = 0;
  for (const Vec3& p : v.P) s = std::max(s, max_abs(p));
  return s;
}

// ---- frames -----------------------------------------------------------------

TEST(Ffd, BoxFrameSpansTheBox) {
  // ffd.h: x = lo + s S + t T + u U with S, T, U the box's edges.
  const Frame f = box_frame({-1, 0.5, 2}, {3, 1.5, 2.25});
  EXPECT_EQ(f.origin, (Vec3{-1, 0.5, 2}));
  EXPECT_EQ(f.S, (Vec3{4, 0, 0}));
  EXPECT_EQ(f.T, (Vec3{0, 1, 0}));
  EXPECT_EQ(f.U, (Vec3{0, 0, 0.25}));
  EXPECT_EQ(det(f.matrix()), 1.0);
}

TEST(Ffd, LocalCoordinatesInvertTheFrame) {
  // Cramer's rule: origin + M local_coordinates(x) = x. On the unit box
  // (M = I) exactly; on the skewed frame to kappa(M) ulps of |x|.
  EXPECT_EQ(local_coordinates(box_frame({0, 0, 0}, {1, 1, 1}), {0.25, 1, 0.5}),
            (Vec3{0.25, 1, 0.5}));
  EXPECT_EQ(local_coordinates(box_frame({1, 1, 1}, {3, 5, 9}), {2, 2, 5}), (Vec3{0.5, 0.25, 0.5}));
  const Frame f = skewed_frame();
  for (const Vec3 x : box_points(f, 81, 200)) {  // seed 81
    const Vec3 stu = local_coordinates(f, x);
    EXPECT_LE(dist(f.origin + f.matrix() * stu, x), kSkewKappa * 2 * kUlp * 2);
  }
  EXPECT_LE(dist(local_coordinates(f, f.origin + f.S + f.U), {1, 0, 1}), kSkewKappa * 2 * kUlp);
}

// ---- the identity -----------------------------------------------------------

void expect_identity(const Frame& f, const Volume& unit, double bound) {
  const Lattice l = identity_lattice(f, unit);
  const int p = max_degree(unit);
  const double j_bound = jacobian_bound(p, min_spacing(unit), 1) * norm_inf(inverse(f.matrix())) *
                         norm_inf(f.matrix());
  double worst = 0;
  for (const Vec3 x : box_points(f, 91, 500)) {  // seed 91
    const FfdPoint q = ffd_point(l, x);
    EXPECT_TRUE(q.inside);
    EXPECT_LE(dist(q.x, x), bound) << x.x << " " << x.y << " " << x.z;
    EXPECT_LE(dist(q.J, Mat3{}), j_bound);
    EXPECT_NEAR(q.det, 1.0, 3 * j_bound);
    worst = std::max(worst, dist(q.x, x));
  }
  static int n = 0;
  record("identity " + std::to_string(++n) + " worst", worst);
}

TEST(Ffd, IdentityLatticeMapsEveryPointToItself) {
  // ffd.h identity_lattice: the unit volume's identity carried into the box;
  // X(x) = x and J = I (linear precision).
  const Frame unit_box = box_frame({0, 0, 0}, {1, 1, 1});
  const Frame shifted = box_frame({-0.5, -0.25, -0.5}, {0.5, 0.75, 0.25});
  for (const Frame& f : {unit_box, shifted}) {
    expect_identity(f, bernstein_volume(4, 4, 4), kIdentity);
    expect_identity(f, bernstein_volume(2, 2, 2), kIdentity);
    expect_identity(f, bspline_volume(6, 6, 6, 3), kIdentity);
    expect_identity(f, bspline_volume(5, 7, 4, 1), kIdentity);
  }
}

TEST(Ffd, IdentityLatticeInASkewedRotatedFrameMapsEveryPointToItself) {
  // The same through a parallelepiped: the bound adds the frame's round trip.
  const Frame f = skewed_frame();
  const double bound = skewed_identity_bound(kSkewKappa, 2);
  expect_identity(f, bernstein_volume(4, 4, 4), bound);
  expect_identity(f, bspline_volume(6, 6, 6, 3), bound);
  expect_identity(f, bspline_volume(3, 4, 5, 2), bound);
}

// ---- affine maps ------------------------------------------------------------

TEST(Ffd, AffineLatticeMovesPointsByTheAffineMap) {
  // Linear precision: control points A P + b give X(x) = A x + b, J = A and
  // det J = det A everywhere. Bounds: (p + 3) ulps of the net's size for the
  // point (the identity's p + 1 and the rounding of A P + b); jacobian_bound
  // times |M^-1| for J; det sums 6 products of three entries, each entry off
  // by the J bound: 3 |A|^2 times it.
  const Mat3 A{{1.1, 0.2, -0.3}, {-0.4, 0.9, 0.25}, {0.15, -0.35, 1.2}};  // det 1.386
  const Vec3 b{0.3, -0.7, 0.45};
  for (const Frame& f : {box_frame({0, 0, 0}, {1, 1, 1}), skewed_frame()}) {
    for (const Volume& unit : {bernstein_volume(4, 4, 4), bspline_volume(6, 6, 6, 3)}) {
      Lattice l = identity_lattice(f, unit);
      for (Vec3& p : l.volume.P) p = A * p + b;
      const int p = max_degree(unit);
      const double size = net_size(l.volume);
      const double j_bound =
          jacobian_bound(p, min_spacing(unit), size) * norm_inf(inverse(f.matrix()));
      for (const Vec3 x : box_points(f, 101, 300)) {  // seed 101
        const FfdPoint q = ffd_point(l, x);
        EXPECT_LE(dist(q.x, A * x + b), (p + 3) * kUlp * size);
        EXPECT_LE(dist(q.J, A), j_bound);
        EXPECT_NEAR(q.det, det(A), 3 * norm_inf(A) * norm_inf(A) * j_bound);
      }
    }
  }
}

// ---- outside, on and near the box -------------------------------------------

TEST(Ffd, PointOutsideTheBoxDoesNotMove) {
  // ffd.h: outside the box X = x, J = I, det 1, inside false.
  const Lattice l = jiggled(box_frame({0, 0, 0}, {1, 1, 1}), bernstein_volume(4, 4, 4), 111);
  for (const Vec3 x : {Vec3{1.5, 0.5, 0.5}, Vec3{-0.1, 0.2, 0.3}, Vec3{0.5, 0.5, 1 + 1e-9}}) {
    const FfdPoint q = ffd_point(l, x);
    EXPECT_FALSE(q.inside);
    EXPECT_EQ(q.x, x);
    EXPECT_EQ(dist(q.J, Mat3{}), 0.0);
    EXPECT_EQ(q.det, 1.0);
  }
}

TEST(Ffd, PointWithinTheSlackOfAFaceFollowsTheFace) {
  // ffd.h kBoxSlack: within 1e-12 (in s, t, u) of the box the point counts as
  // inside and is clamped onto the face: it goes where the face point goes
  // (X(1, t, u) of the volume); 2e-12 out it is outside.
  const Lattice l = jiggled(box_frame({0, 0, 0}, {1, 1, 1}), bernstein_volume(4, 4, 4), 112);
  const FfdPoint near = ffd_point(l, {1 + 0.5 * kBoxSlack, 0.25, 0.75});
  EXPECT_TRUE(near.inside);
  EXPECT_EQ(near.x, volume_point(l.volume, 1, 0.25, 0.75));
  const FfdPoint below = ffd_point(l, {0.25, -0.5 * kBoxSlack, 0.5});
  EXPECT_TRUE(below.inside);
  EXPECT_EQ(below.x, volume_point(l.volume, 0.25, 0, 0.5));
  EXPECT_FALSE(ffd_point(l, {1 + 2 * kBoxSlack, 0.25, 0.75}).inside);
  EXPECT_FALSE(ffd_point(l, {0.5, 0.5, -2 * kBoxSlack}).inside);
  // On the faces and corners themselves: inside.
  EXPECT_TRUE(ffd_point(l, {1, 1, 1}).inside);
  EXPECT_TRUE(ffd_point(l, {0, 0.5, 0}).inside);
}

// ---- derivatives ------------------------------------------------------------

/// max over the columns of |CD_h - J| with central differences along the
/// world axes at x.
double jacobian_cd_error(const Lattice& l, Vec3 x, double h) {
  const Mat3 J = ffd_point(l, x).J;
  const Vec3 e[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Vec3 col[3] = {J.c0, J.c1, J.c2};
  double worst = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec3 cd = (ffd_point(l, x + h * e[k]).x - ffd_point(l, x - h * e[k]).x) / (2 * h);
    worst = std::max(worst, dist(cd, col[k]));
  }
  return worst;
}

TEST(Ffd, JacobianAgreesWithCentralDifferencesAtSecondOrder) {
  // ffd.h step 3: J = [Xs Xt Xu] M^-1 in world coordinates. Central
  // differences along the world axes: error h^2/6 X''' + O(h^4), ratio 4 per
  // halving (observed order 2), far above rounding (ulps / h = 1e-14) at
  // h = 0.01..0.0025. Skewed frame (the M^-1 matters); a Bernstein lattice
  // and a cubic B-spline at points 0.05 or more (in s, t, u) from its knots.
  const Frame f = skewed_frame();
  const Lattice bern = jiggled(f, bernstein_volume(4, 4, 4), 121);
  const Lattice spl = jiggled(f, bspline_volume(6, 6, 6, 3), 122);
  const double h = 0.01;
  for (const Vec3 stu : {Vec3{0.4, 0.55, 0.5}, Vec3{0.15, 0.8, 0.2}, Vec3{0.5, 0.2, 0.85}}) {
    for (const Lattice* l : {&bern, &spl}) {
      const Vec3 x = f.origin + f.matrix() * stu;
      const double e1 = jacobian_cd_error(*l, x, h), e2 = jacobian_cd_error(*l, x, h / 2),
                   e3 = jacobian_cd_error(*l, x, h / 4);
      static int n = 0;
      record("order " + std::to_string(++n), observed_order(e1, e2));
      record("order h/2 " + std::to_string(n), observed_order(e2, e3));
      record("error h " + std::to_string(n), e1);
      EXPECT_NEAR(observed_order(e1, e2), 2.0, kOrderSlack) << e1 << " " << e2;
      EXPECT_NEAR(observed_order(e2, e3), 2.0, kOrderSlack) << e2 << " " << e3;
    }
  }
}

// ---- normals ----------------------------------------------------------------

TEST(Ffd, CofactorCarriesTheCrossProductOfAnyTwoTangents) {
  // deform/mat.h: (A a) x (A b) = cof(A) (a x b) for every A, including
  // mirrored (det < 0) ones, so deform_normal(A, a x b) is the unit normal of
  // the image with its orientation. Random A, a, b (seed 131); each side sums
  // products of four factors of size <= 1 (24 terms): 32 ulps; after
  // normalising, that over the length of the cross product.
  constexpr double kFourFactors = 32 * kUlp;
  Random r(131);
  for (int n = 0; n < 1000; ++n) {
    const Mat3 A{r.vec3(-1, 1), r.vec3(-1, 1), r.vec3(-1, 1)};
    const Vec3 a = r.vec3(-1, 1), b = r.vec3(-1, 1);
    const Vec3 image = cross(A * a, A * b);
    EXPECT_LE(dist(image, cofactor(A) * cross(a, b)), kFourFactors);
    if (norm(image) > 0) {
      EXPECT_LE(dist(deform_normal(A, cross(a, b)), normalized(image)),
                2 * kFourFactors / norm(image));
    }
  }
}

TEST(Ffd, NormalOfASingularDirectionIsZero) {
  // ffd.h: the zero vector when cof(J) n is zero. J squashes z to 0: cof(J)
  // = diag(0, 0, 1) kills a normal along x; a mirror in x turns (1, 0, 0)
  // into itself and (0, 0, 1) over (cof = det J J^-T = diag(1, -1, -1)).
  const Mat3 flat{{1, 0, 0}, {0, 1, 0}, {0, 0, 0}};
  EXPECT_EQ(deform_normal(flat, {1, 0, 0}), (Vec3{0, 0, 0}));
  EXPECT_EQ(deform_normal(flat, {0, 0, 2}), (Vec3{0, 0, 1}));
  const Mat3 mirror{{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  EXPECT_EQ(deform_normal(mirror, {3, 0, 0}), (Vec3{1, 0, 0}));
  EXPECT_EQ(deform_normal(mirror, {0, 0, 1}), (Vec3{0, 0, -1}));
}

/// A sphere patch of centre c and radius r: x(a, b) = c + r (cos a cos b,
/// sin a cos b, sin b); x_a x x_b = r^2 cos b (the outward unit normal).
struct SpherePatch {
  Vec3 c;
  double r;
  Vec3 at(double a, double b) const {
    return c + r * Vec3{std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b)};
  }
  Vec3 normal(double a, double b) const { return normalized(at(a, b) - c); }
};

/// The angle between deform_normal(J, n) and the normal of the deformed
/// patch from central-difference tangents d/da X(x(a, b)), d/db X(x(a, b)).
double normal_cd_error(const Lattice& l, const SpherePatch& s, double a, double b, double h) {
  const auto X = [&](double a2, double b2) { return ffd_point(l, s.at(a2, b2)).x; };
  const Vec3 ta = (X(a + h, b) - X(a - h, b)) / (2 * h);
  const Vec3 tb = (X(a, b + h) - X(a, b - h)) / (2 * h);
  const Vec3 n_cd = normalized(cross(ta, tb));
  const Vec3 n = deform_normal(ffd_point(l, s.at(a, b)).J, s.normal(a, b));
  return std::atan2(norm(cross(n, n_cd)), dot(n, n_cd));
}

TEST(Ffd, TransformedNormalsAgreeWithTheDeformedSurfaceAtSecondOrder) {
  // ffd.h step 4: the normal cof(J) n is the exact normal of the deformed
  // surface. Its tangents by central differences of X(x(a, b)) carry an
  // error c h^2, and so does the normal they span: the angle between the two
  // falls by 4 per halving of h. A sphere patch of radius 0.3 inside each
  // lattice; a Bernstein and a cubic B-spline lattice, skewed frame.
  const Frame f = skewed_frame();
  const Vec3 centre = f.origin + f.matrix() * Vec3{0.5, 0.5, 0.5};
  const SpherePatch s{centre, 0.3};
  const Lattice bern = jiggled(f, bernstein_volume(4, 4, 4), 141);
  const Lattice spl = jiggled(f, bspline_volume(5, 5, 5, 3), 142);
  const double h = 0.02;
  for (const Lattice* l : {&bern, &spl})
    for (const auto& [a, b] : {std::array<double, 2>{0.3, 0.2}, {1.9, -0.6}, {4.0, 0.9}}) {
      const double e1 = normal_cd_error(*l, s, a, b, h), e2 = normal_cd_error(*l, s, a, b, h / 2),
                   e3 = normal_cd_error(*l, s, a, b, h / 4);
      static int n = 0;
      record("order " + std::to_string(++n), observed_order(e1, e2));
      record("order h/2 " + std::to_string(n), observed_order(e2, e3));
      record("angle h " + std::to_string(n), e1);
      EXPECT_NEAR(observed_order(e1, e2), 2.0, kOrderSlack) << e1 << " " << e2;
      EXPECT_NEAR(observed_order(e2, e3), 2.0, kOrderSlack) << e2 << " " << e3;
    }
}

// ---- meshes -----------------------------------------------------------------

/// A small mesh: a grid of vertices over [-0.2, 1.2] x [-0.2, 1.2] at z = 0.5
/// (some outside the unit box), normals (0, 0, 1), colours, two triangles per cell.
IndexedMesh grid_mesh(int n) {
  IndexedMesh m;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const float x = float(-0.2 + 1.4 * i / n), y = float(-0.2 + 1.4 * j / n);
      m.positions.insert(m.positions.end(), {x, y, 0.5f});
      m.normals.insert(m.normals.end(), {0.f, 0.f, 1.f});
      m.colours.insert(m.colours.end(), {float(i) / n, float(j) / n, 0.5f});
    }
  const auto at = [&](int i, int j) { return std::uint32_t(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j),
                                         at(i + 1, j + 1), at(i, j + 1)});
  return m;
}

TEST(Ffd, DeformMeshMovesEveryVertexAsFfdPoint) {
  // ffd.h deform_mesh: each vertex through ffd_point (positions and det as
  // floats), normals by deform_normal, colours and indices as given; outside
  // vertices counted and left; min and max det over the inside ones.
  const Lattice l = jiggled(box_frame({0, 0, 0}, {1, 1, 1}), bspline_volume(5, 5, 5, 2), 151);
  const IndexedMesh m = grid_mesh(14);
  const DeformedMesh d = deform_mesh(l, m);
  EXPECT_EQ(d.mesh.indices, m.indices);
  EXPECT_EQ(d.mesh.colours, m.colours);
  ASSERT_EQ(d.mesh.positions.size(), m.positions.size());
  ASSERT_EQ(d.mesh.normals.size(), m.normals.size());
  ASSERT_EQ(d.det.size(), m.vertex_count());
  std::size_t outside = 0;
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const float* p = &m.positions[3 * v];
    const FfdPoint q = ffd_point(l, {p[0], p[1], p[2]});
    const Vec3 n = deform_normal(q.J, {0, 0, 1});
    EXPECT_EQ(d.mesh.positions[3 * v], float(q.x.x));
    EXPECT_EQ(d.mesh.positions[3 * v + 1], float(q.x.y));
    EXPECT_EQ(d.mesh.positions[3 * v + 2], float(q.x.z));
    EXPECT_EQ(d.mesh.normals[3 * v], float(n.x));
    EXPECT_EQ(d.mesh.normals[3 * v + 1], float(n.y));
    EXPECT_EQ(d.mesh.normals[3 * v + 2], float(n.z));
    EXPECT_EQ(d.det[v], float(q.det));
    if (!q.inside) {
      ++outside;
    } else {
      lo = std::min(lo, q.det), hi = std::max(hi, q.det);
    }
  }
  // The grid's x and y step 0.1 from -0.2 to 1.2: 4 of 15 columns and rows
  // (-0.2, -0.1, 1.1, 1.2) lie outside the box; 11 x 11 vertices are inside.
  EXPECT_EQ(outside, 15u * 15u - 11u * 11u);
  EXPECT_EQ(d.outside, outside);
  EXPECT_EQ(d.folded, 0u);
  EXPECT_EQ(d.min_det, lo);
  EXPECT_EQ(d.max_det, hi);
  EXPECT_LT(d.min_det, d.max_det);
}

TEST(Ffd, DeformMeshWithoutNormalsOrVerticesGivesNone) {
  const Lattice l = identity_lattice(box_frame({0, 0, 0}, {1, 1, 1}), bernstein_volume(3, 3, 3));
  IndexedMesh m = grid_mesh(3);
  m.normals.clear();
  const DeformedMesh d = deform_mesh(l, m);
  EXPECT_TRUE(d.mesh.normals.empty());
  EXPECT_EQ(d.mesh.positions.size(), m.positions.size());
  const DeformedMesh e = deform_mesh(l, IndexedMesh{});
  EXPECT_TRUE(e.mesh.positions.empty());
  EXPECT_TRUE(e.det.empty());
  EXPECT_EQ(e.outside, 0u);
  EXPECT_EQ(e.folded, 0u);
  // ffd.h: min_det and max_det are over the inside vertices; with none they
  // keep their defaults 1.
  EXPECT_EQ(e.min_det, 1.0);
  EXPECT_EQ(e.max_det, 1.0);
}

TEST(Ffd, DeformMeshVertexNotFiniteThrowsNamingIt) {
  const Lattice l = identity_lattice(box_frame({0, 0, 0}, {1, 1, 1}), bernstein_volume(3, 3, 3));
  IndexedMesh m = grid_mesh(3);
  m.positions[3 * 5 + 1] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW_NAMING(deform_mesh(l, m), "deform_mesh: vertex 5 (");
  EXPECT_THROW_NAMING(deform_mesh(l, m), "nan");
  m.positions[3 * 5 + 1] = 0;
  m.positions[3 * 7 + 2] = std::numeric_limits<float>::infinity();
  EXPECT_THROW_NAMING(deform_mesh(l, m), "deform_mesh: vertex 7 (");
  // ffd.h: "Throws as ffd_point": an invalid lattice too.
  m.positions[3 * 7 + 2] = 0;
  Lattice bad = l;
  bad.volume.P.pop_back();
  EXPECT_EQ(error_of([&] { deform_mesh(bad, m); }), "volume: 26 control points for 3 x 3 x 3 = 27");
}

TEST(Ffd, FaceAveragedNormalsOfAFlatGridAreItsNormal) {
  // The cross products of counter-clockwise triangles in z = 0.5 all point
  // along +z; their sum normalised is (0, 0, 1) exactly.
  const std::vector<float> n = face_averaged_normals(grid_mesh(4));
  ASSERT_EQ(n.size(), 3u * 25u);
  for (std::size_t v = 0; v < 25; ++v) {
    EXPECT_EQ(n[3 * v], 0.f);
    EXPECT_EQ(n[3 * v + 1], 0.f);
    EXPECT_EQ(n[3 * v + 2], 1.f);
  }
}

TEST(Ffd, NormalAnglesMeasureDegrees) {
  // (1, 0, 0) against itself: 0; against (0, 1, 0): 90; against
  // (cos 30, sin 30, 0): 30, so the mean is 40. The float unit vector is off
  // by 2^-24 = 6e-8 rad = 3.4e-6 degrees.
  constexpr double kFloatAngle = 1e-5;
  const float c = float(std::cos(std::acos(-1.0) / 6)), s = 0.5f;
  const AngleStats a = normal_angles({1, 0, 0, 1, 0, 0, 1, 0, 0}, {1, 0, 0, 0, 1, 0, c, s, 0});
  EXPECT_NEAR(a.max_deg, 90.0, kFloatAngle);
  EXPECT_NEAR(a.mean_deg, 40.0, kFloatAngle);
  EXPECT_EQ(normal_angles({}, {}).max_deg, 0.0);
}

TEST(Ffd, NormalAnglesOfDifferentSizesThrowNamingThem) {
  EXPECT_EQ(error_of([] { normal_angles({1, 0, 0, 1, 0, 0}, {1, 0, 0}); }),
            "normal_angles: 6 and 3 floats (3 per normal, as many each)");
  EXPECT_EQ(error_of([] { normal_angles({1, 0, 0, 1}, {1, 0, 0, 1}); }),
            "normal_angles: 4 and 4 floats (3 per normal, as many each)");
}

// ---- volume -----------------------------------------------------------------

/// The cuts of [0, 1] at the distinct knots of a direction: Gauss–Legendre is
/// exact on each polynomial piece only.
std::vector<double> pieces(const Volume& v, int axis) {
  std::vector<double> cuts;
  for (double k : volume_knots(v, axis))
    if (cuts.empty() || k > cuts.back()) cuts.push_back(k);
  return cuts;
}

/// Gauss–Legendre nodes and weights with `n` points on every piece.
void nodes(const std::vector<double>& cuts, int n, std::vector<double>& x, std::vector<double>& w) {
  const spline::GaussRule r = spline::gauss_legendre(n);
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    const double half = (cuts[c + 1] - cuts[c]) / 2, mid = (cuts[c + 1] + cuts[c]) / 2;
    for (int i = 0; i < n; ++i) x.push_back(mid + half * r.x[i]), w.push_back(half * r.w[i]);
  }
}

/// The divergence theorem: V = 1/3 closed-integral X . n dA over the image of
/// the box's 6 faces, each a parametric surface of the volume: on s = c,
/// (t, u) -> X(c, t, u) with area normal X_t x X_u, outward at s = 1 and
/// inward at s = 0 (for det J > 0); likewise (u, s) on t = c and (s, t) on
/// u = c. X . (X_t x X_u) has degree 3p - 1 in each of its two variables, so
/// n points per piece are exact once 2n - 1 >= 3p - 1.
double divergence_volume(const Volume& v, int n) {
  double sum = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;  // the face's parameters, cyclic
    std::vector<double> xa, wa, xb, wb;
    nodes(pieces(v, a), n, xa, wa);
    nodes(pieces(v, b), n, xb, wb);
    for (const double side : {0.0, 1.0})
      for (std::size_t i = 0; i < xa.size(); ++i)
        for (std::size_t j = 0; j < xb.size(); ++j) {
          double w[3];
          w[axis] = side, w[a] = xa[i], w[b] = xb[j];
          const VolumeDerivs d = volume_derivs(v, w[0], w[1], w[2]);
          const Vec3 partial[3] = {d.Xs, d.Xt, d.Xu};
          const double flux = dot(d.X, cross(partial[a], partial[b]));
          sum += (side == 1 ? 1 : -1) * wa[i] * wb[j] * flux;
        }
  }
  return sum / 3;
}

TEST(Ffd, DeformedVolumeEqualsTheDivergenceTheoremOnTheDeformedFaces) {
  // Both exact: deformed_volume integrates det J (degree 3p - 1 per
  // direction: 8 for cubic) with 5 points per knot span (exact to degree 9),
  // the face integral X . (X_a x X_b) (degree 8 per direction) with 5 too.
  // The B-spline 6 x 6 x 6 has interior knots at 1/3, 2/3: both split there.
  for (const Lattice& l :
       {jiggled(box_frame({0, 0, 0}, {1, 1, 1}), bernstein_volume(4, 4, 4), 161),
        jiggled(skewed_frame(), bernstein_volume(4, 4, 4), 162),
        jiggled(box_frame({-1, 0, 0.5}, {0.5, 2, 1.5}), bspline_volume(6, 6, 6, 3), 163),
        jiggled(skewed_frame(), bspline_volume(6, 6, 6, 3), 164)}) {
    const double v = deformed_volume(l, {0, 0, 0}, {1, 1, 1}, 5);
    const double reference = divergence_volume(l.volume, 5);
    EXPECT_NEAR(v, reference, kExactQuadratures * std::fabs(reference));
    static int n = 0;
    record("relative difference " + std::to_string(++n), std::fabs(v - reference) / reference);
    record("volume " + std::to_string(n), v);
    // Not the original volume: the jiggle (8 % of the box) changes it by far
    // more than this, so the case is not the trivial one.
    constexpr double kJiggleChangesVolume = 1e-4;
    EXPECT_GT(std::fabs(v - det(l.frame.matrix())), kJiggleChangesVolume);
  }
}

TEST(Ffd, DeformedVolumeIsExactFromCeilThreePHalfPointsOnAndNotBelow) {
  // ffd.h: exact once 2 points - 1 >= 3p - 1. Cubic (3p - 1 = 8): 5 points
  // and 16 give the same volume; 4 points (exact to degree 7) miss it by far
  // more than rounding. Quadratic (5): 3 points suffice, 2 do not. A
  // B-spline with interior knots: a rule over [0, 1] without the cuts would
  // not be exact at any number of points.
  struct Case {
    Lattice l;
    int enough;
  };
  for (const Case& c :
       {Case{jiggled(skewed_frame(), bspline_volume(6, 6, 6, 3), 171), 5},
        Case{jiggled(skewed_frame(), bernstein_volume(4, 4, 4), 172), 5},
        Case{jiggled(box_frame({0, 0, 0}, {1, 1, 1}), bspline_volume(7, 5, 6, 2), 173), 3}}) {
    const double exact = deformed_volume(c.l, {0, 0, 0}, {1, 1, 1}, 16);
    static int n = 0;
    record("enough " + std::to_string(++n),
           std::fabs(deformed_volume(c.l, {0, 0, 0}, {1, 1, 1}, c.enough) - exact) / exact);
    record("one fewer " + std::to_string(n),
           std::fabs(deformed_volume(c.l, {0, 0, 0}, {1, 1, 1}, c.enough - 1) - exact) / exact);
    EXPECT_NEAR(deformed_volume(c.l, {0, 0, 0}, {1, 1, 1}, c.enough), exact,
                kExactQuadratures * exact);
    EXPECT_GT(std::fabs(deformed_volume(c.l, {0, 0, 0}, {1, 1, 1}, c.enough - 1) - exact),
              kNotExact * exact);
  }
}

TEST(Ffd, DeformedVolumeOfAnAffineLatticeIsDetATimesTheBox) {
  // Change of variables: X = A x + b multiplies every volume by det A. The
  // box's own volume is det M; a sub-box (lo, hi) of (s, t, u) has det M
  // times its size. The identity (A = I) gives the box back.
  const Mat3 A{{1.1, 0.2, -0.3}, {-0.4, 0.9, 0.25}, {0.15, -0.35, 1.2}};
  const Vec3 b{0.3, -0.7, 0.45};
  for (const Frame& f : {box_frame({-1, 0, 0.5}, {0.5, 2, 1.5}), skewed_frame()}) {
    for (const Volume& unit : {bernstein_volume(4, 4, 4), bspline_volume(6, 6, 6, 3)}) {
      Lattice l = identity_lattice(f, unit);
      const double box = det(f.matrix());
      EXPECT_NEAR(deformed_volume(l, {0, 0, 0}, {1, 1, 1}, 5), box, kExactQuadratures * box);
      for (Vec3& p : l.volume.P) p = A * p + b;
      EXPECT_NEAR(deformed_volume(l, {0, 0, 0}, {1, 1, 1}, 5), det(A) * box,
                  kExactQuadratures * box);
      const Vec3 lo{0.1, 0.25, 0.5}, hi{0.6, 0.5, 0.75};
      const double part = box * 0.5 * 0.25 * 0.25;
      EXPECT_NEAR(deformed_volume(l, lo, hi, 5), det(A) * part, kExactQuadratures * part);
    }
  }
}

TEST(Ffd, DeformedVolumesOfTwoHalvesAddUp) {
  // Additivity: the box split at s = 0.4 (not a knot of the 6 x 6 x 6 cubic,
  // so each half cuts a span): the two integrals sum to the whole.
  const Lattice l = jiggled(skewed_frame(), bspline_volume(6, 6, 6, 3), 181);
  const double whole = deformed_volume(l, {0, 0, 0}, {1, 1, 1}, 5);
  const double left = deformed_volume(l, {0, 0, 0}, {0.4, 1, 1}, 5);
  const double right = deformed_volume(l, {0.4, 0, 0}, {1, 1, 1}, 5);
  EXPECT_NEAR(left + right, whole, kExactQuadratures * whole);
}

/// The box's surface in world coordinates, n x n quads per face (2 n^2
/// triangles), counter-clockwise seen from outside.
IndexedMesh box_surface(const Frame& f, int n) {
  IndexedMesh m;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (const int side : {0, 1}) {
      const std::uint32_t first = std::uint32_t(m.vertex_count());
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
          double w[3];
          w[axis] = side, w[a] = double(i) / n, w[b] = double(j) / n;
          const Vec3 x = f.origin + f.matrix() * Vec3{w[0], w[1], w[2]};
          m.positions.insert(m.positions.end(), {float(x.x), float(x.y), float(x.z)});
        }
      const auto at = [&](int i, int j) { return first + std::uint32_t(i * (n + 1) + j); };
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          // (a, b, axis) is right-handed: (i, j) counter-clockwise seen from
          // +axis, the outside of the side-1 face; reversed on side 0.
          std::array<std::uint32_t, 6> t = {at(i, j), at(i + 1, j), at(i + 1, j + 1),
                                            at(i, j), at(i + 1, j + 1), at(i, j + 1)};
          if (side == 0) std::swap(t[1], t[2]), std::swap(t[4], t[5]);
          m.indices.insert(m.indices.end(), t.begin(), t.end());
        }
    }
  }
  return m;
}

/// The divergence theorem on a closed triangle mesh: sum det(a, b, c) / 6.
double mesh_volume(const IndexedMesh& m) {
  double v = 0;
  const auto at = [&](std::uint32_t i) {
    return Vec3{m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2]};
  };
  for (std::size_t t = 0; t < m.indices.size(); t += 3)
    v += dot(at(m.indices[t]), cross(at(m.indices[t + 1]), at(m.indices[t + 2]))) / 6;
  return v;
}

TEST(Ffd, TriangulatedDeformedBoxConvergesToTheVolumeAtSecondOrder) {
  // The deformed box's faces triangulated (vertices through deform_mesh):
  // each flat triangle is off the curved face by O(h^2), so the enclosed
  // volume converges to the exact one (deformed_volume) at order 2: the error
  // falls by 4 per halving of the triangles' size, N = 8, 16, 32 per face.
  // Box frames with dyadic corners: the vertices on the faces are exact in
  // float, so every one is inside (skewed faces: the next test).
  for (const Lattice& l :
       {jiggled(box_frame({0, 0, 0}, {1, 1, 1}), bernstein_volume(4, 4, 4), 191),
        jiggled(box_frame({-1, 0, 0.5}, {0.5, 2, 1.5}), bspline_volume(6, 6, 6, 3), 192)}) {
    const double exact = deformed_volume(l, {0, 0, 0}, {1, 1, 1}, 5);
    double e[3];
    for (int k = 0; k < 3; ++k) {
      const DeformedMesh d = deform_mesh(l, box_surface(l.frame, 8 << k));
      ASSERT_EQ(d.outside, 0u);  // every vertex on the faces counts as inside
      e[k] = std::fabs(mesh_volume(d.mesh) - exact);
    }
    EXPECT_NEAR(observed_order(e[0], e[1]), 2.0, kOrderSlack) << e[0] << " " << e[1];
    EXPECT_NEAR(observed_order(e[1], e[2]), 2.0, kOrderSlack) << e[1] << " " << e[2];
    static int n = 0;
    record("order 8-16 " + std::to_string(++n), observed_order(e[0], e[1]));
    record("order 16-32 " + std::to_string(n), observed_order(e[1], e[2]));
    for (int k = 0; k < 3; ++k)
      record("relative error N=" + std::to_string(8 << k) + " " + std::to_string(n), e[k] / exact);
  }
}

TEST(Ffd, FloatVerticesOnTheFacesOfASkewedBoxFollowTheLattice) {
  // ffd.h kBoxSlack: "a vertex on the box's face that rounding puts a hair
  // outside still follows the lattice". A mesh's vertices are floats: on a
  // skewed box's faces they are rounded by up to 2^-24 of |x| (about 1e-7 in
  // s, t, u), and each must still count as inside, or the deformed surface
  // tears along the box's faces.
  const Lattice l = jiggled(skewed_frame(), bspline_volume(6, 6, 6, 3), 193);
  const IndexedMesh m = box_surface(l.frame, 8);
  const DeformedMesh d = deform_mesh(l, m);
  EXPECT_EQ(d.outside, 0u) << "of " << m.vertex_count() << " vertices on the faces";
}

TEST(Ffd, DeformedVolumeBoxOutsideTheUnitCubeThrowsNamingIt) {
  // ffd.h: lo, hi in [0, 1]^3 with lo < hi.
  const Lattice l = identity_lattice(box_frame({0, 0, 0}, {1, 1, 1}), bernstein_volume(3, 3, 3));
  const std::string tail = " (must have 0 <= lo < hi <= 1 in s, t, u)";
  EXPECT_EQ(error_of([&] { deformed_volume(l, {0, 0, 0}, {1, 1.5, 1}, 4); }),
            "deformed_volume: box (0, 0, 0) .. (1, 1.5, 1)" + tail);
  EXPECT_EQ(error_of([&] { deformed_volume(l, {0.5, 0, -0.25}, {1, 1, 1}, 4); }),
            "deformed_volume: box (0.5, 0, -0.25) .. (1, 1, 1)" + tail);
  EXPECT_EQ(error_of([&] { deformed_volume(l, {0, 0.5, 0}, {1, 0.5, 1}, 4); }),
            "deformed_volume: box (0, 0.5, 0) .. (1, 0.5, 1)" + tail);
  EXPECT_EQ(error_of([&] { deformed_volume(l, {0, 0, NAN}, {1, 1, 1}, 4); }),
            "deformed_volume: box (0, 0, nan) .. (1, 1, 1)" + tail);
}

TEST(Ffd, DeformedVolumePointsOutsideOneToSixteenThrowNamingThem) {
  // ffd.h: "Gauss–Legendre with `points` (1..16) nodes ... Throws
  // std::invalid_argument naming what is outside its range."
  const Lattice l = identity_lattice(box_frame({0, 0, 0}, {1, 1, 1}), bernstein_volume(3, 3, 3));
  EXPECT_THROW_NAMING(deformed_volume(l, {0, 0, 0}, {1, 1, 1}, 0), "points = 0");
  EXPECT_THROW_NAMING(deformed_volume(l, {0, 0, 0}, {1, 1, 1}, 17), "points = 17");
  EXPECT_THROW_NAMING(deformed_volume(l, {0, 0, 0}, {1, 1, 1}, -2), "points = -2");
  EXPECT_NEAR(deformed_volume(l, {0, 0, 0}, {1, 1, 1}, 1), 1.0, 8 * kUlp);
  EXPECT_NEAR(deformed_volume(l, {0, 0, 0}, {1, 1, 1}, 16), 1.0, 64 * kUlp);
}

// ---- folds ------------------------------------------------------------------

/// The identity lattice of the unit box with control point (i, j, k) dragged
/// along s to `to` (the box's x).
Lattice dragged(const Volume& unit, int i, int j, int k, double to) {
  Lattice l = identity_lattice(box_frame({0, 0, 0}, {1, 1, 1}), unit);
  l.volume.point(i, j, k).x = to;
  return l;
}

TEST(Ffd, ControlPointDraggedThroughItsNeighbourFolds) {
  // A quadratic B-spline 6 x 6 x 6: P(2, 2, 2) sits at the Greville point
  // 0.375, its neighbour P(3, 2, 2) at 0.625. Dragged to 0.9, past the
  // neighbour, the lattice's s-direction reverses between them: Xs . e_s < 0
  // and det J < 0 there (measured min -0.15 at (0.5, 0.35, 0.35)). A
  // trilinear lattice (degree 1) folds as soon as the point passes its
  // neighbour (0.7 > 2/3): det J = (0.667 - 0.7) * 3 = -0.1 on the cell.
  struct Case {
    Lattice l;
    Vec3 greville;
  };
  const double third = 1.0 / 3;
  for (const Case& c :
       {Case{dragged(bspline_volume(6, 6, 6, 2), 2, 2, 2, 0.9), {0.375, 0.375, 0.375}},
        Case{dragged(bspline_volume(4, 4, 4, 1), 1, 1, 1, 0.7), {third, third, third}}}) {
    const Fold f = find_fold(c.l);
    EXPECT_TRUE(f.folds);
    EXPECT_LE(f.min_det, 0);
    // Near the dragged point: within one control-point spacing (0.25 and
    // 1/3) of where it sat, in every parameter.
    EXPECT_LE(max_abs(f.stu - c.greville), 1.0 / 3) << fold_text(f);
    // f.x is the box's point at f.stu (the unit box: the same numbers).
    EXPECT_EQ(f.x, f.stu);
    // The sample it reports has that det J.
    EXPECT_EQ(ffd_point(c.l, f.x).det, f.min_det);
    // fold_text names det J and (s, t, u) as the header shows them.
    char expected[128];
    std::snprintf(expected, sizeof expected,
                  "folds: det J %.3g at (s, t, u) = (%.2f, %.2f, %.2f)", f.min_det,
                  f.stu.x, f.stu.y, f.stu.z);
    EXPECT_EQ(fold_text(f), expected);
    EXPECT_EQ(error_of([&] { require_no_fold(c.l); }), fold_text(f));
  }
  // The trilinear case in numbers: det J = 3 (2/3 - 0.7) on the cell
  // [1/3, 2/3] x [0, 1/3] x [0, 1/3]'s corner at the dragged point.
  EXPECT_EQ(fold_text(find_fold(dragged(bspline_volume(4, 4, 4, 1), 1, 1, 1, 0.7))),
            "folds: det J -0.1 at (s, t, u) = (0.33, 0.33, 0.33)");
}

TEST(Ffd, UnfoldedLatticeReportsNoFold) {
  // The identity: det J = 1 everywhere; a jiggled lattice: det J > 0 (the
  // smallest det of the samples is what fold_text reports). The same point
  // dragged only half-way to its neighbour (0.5 < 0.625) does not fold.
  const Fold id = find_fold(identity_lattice(box_frame({0, 0, 0}, {1, 1, 1}),
                                             bspline_volume(6, 6, 6, 2)));
  EXPECT_FALSE(id.folds);
  EXPECT_NEAR(id.min_det, 1.0, 3 * jacobian_bound(2, 0.25, 1));
  EXPECT_EQ(fold_text(id), "no fold: det J >= 1");
  const Lattice half = dragged(bspline_volume(6, 6, 6, 2), 2, 2, 2, 0.5);
  const Fold f = find_fold(half);
  EXPECT_FALSE(f.folds);
  EXPECT_GT(f.min_det, 0);
  char expected[64];
  std::snprintf(expected, sizeof expected, "no fold: det J >= %.3g", f.min_det);
  EXPECT_EQ(fold_text(f), expected);
  EXPECT_NO_THROW(require_no_fold(half));
  EXPECT_NO_THROW(require_no_fold(jiggled(skewed_frame(), bernstein_volume(4, 4, 4), 201)));
}

TEST(Ffd, FoldSamplesOutsideOneToSixtyFourThrowNamingThem) {
  const Lattice l = identity_lattice(box_frame({0, 0, 0}, {1, 1, 1}), bernstein_volume(3, 3, 3));
  EXPECT_EQ(error_of([&] { find_fold(l, 0); }), "find_fold: samples = 0 (must be 1..64)");
  EXPECT_EQ(error_of([&] { find_fold(l, 65); }), "find_fold: samples = 65 (must be 1..64)");
  EXPECT_EQ(error_of([&] { require_no_fold(l, -1); }), "find_fold: samples = -1 (must be 1..64)");
  EXPECT_FALSE(find_fold(l, 1).folds);
}

TEST(Ffd, DeformMeshCountsFoldedVertices) {
  // ffd.h: folded = the vertices with det J <= 0, counted here independently
  // with ffd_point on a grid through the fold of the dragged quadratic lattice.
  const Lattice l = dragged(bspline_volume(6, 6, 6, 2), 2, 2, 2, 0.9);
  IndexedMesh m;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j)
      m.positions.insert(m.positions.end(), {float(i) / 20, float(j) / 20, 0.35f});
  std::size_t folded = 0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v)
    folded += ffd_point(l, {m.positions[3 * v], m.positions[3 * v + 1], 0.35f}).det <= 0;
  ASSERT_GT(folded, 0u);
  ASSERT_LT(folded, m.vertex_count());
  const DeformedMesh d = deform_mesh(l, m);
  EXPECT_EQ(d.folded, folded);
  EXPECT_LE(d.min_det, 0);
  EXPECT_GT(d.max_det, 0);
}

// ---- bad input --------------------------------------------------------------

TEST(Ffd, BoxFrameWithLoNotBelowHiThrowsNamingBoth) {
  const std::string tail = " in every coordinate";
  EXPECT_EQ(error_of([] { box_frame({0, 0, 0}, {1, 0, 1}); }),
            "box_frame: lo (0, 0, 0) must lie below hi (1, 0, 1)" + tail);
  EXPECT_EQ(error_of([] { box_frame({2, 0, 0}, {1, 1, 1}); }),
            "box_frame: lo (2, 0, 0) must lie below hi (1, 1, 1)" + tail);
  EXPECT_EQ(error_of([] { box_frame({0, 0, NAN}, {1, 1, 1}); }),
            "box_frame: lo (0, 0, nan) must lie below hi (1, 1, 1)" + tail);
  EXPECT_EQ(error_of([] { box_frame({0, 0, 0}, {1, INFINITY, 1}); }),
            "box_frame: lo (0, 0, 0) must lie below hi (1, inf, 1)" + tail);
}

TEST(Ffd, DegenerateOrLeftHandedFrameThrowsNamingDetM) {
  // ffd.h identity_lattice: det M <= 0 throws naming det M; so does every
  // use of such a lattice (ffd_point, local_coordinates).
  Frame flat;
  flat.U = {1, 1, 0};  // in the plane of S and T: det 0
  Frame left;
  left.U = {0, 0, -2};  // det -2
  const std::string tail = " (the box must have volume and S, T, U be right-handed)";
  EXPECT_EQ(error_of([&] { identity_lattice(flat, bernstein_volume(3, 3, 3)); }),
            "lattice frame: det [S T U] = 0" + tail);
  EXPECT_EQ(error_of([&] { identity_lattice(left, bernstein_volume(3, 3, 3)); }),
            "lattice frame: det [S T U] = -2" + tail);
  EXPECT_EQ(error_of([&] { local_coordinates(left, {0, 0, 0}); }),
            "lattice frame: det [S T U] = -2" + tail);
  Lattice l = identity_lattice(Frame{}, bernstein_volume(3, 3, 3));
  l.frame = left;
  EXPECT_EQ(error_of([&] { ffd_point(l, {0.5, 0.5, 0.5}); }),
            "lattice frame: det [S T U] = -2" + tail);
  Frame nan_frame;
  nan_frame.S.y = NAN;
  EXPECT_EQ(error_of([&] { identity_lattice(nan_frame, bernstein_volume(3, 3, 3)); }),
            "lattice frame: det [S T U] = nan" + tail);
  Frame inf_frame;
  inf_frame.S.x = INFINITY;  // det +inf: not a box either
  EXPECT_THROW_NAMING(identity_lattice(inf_frame, bernstein_volume(3, 3, 3)), "det [S T U] = inf");
}

TEST(Ffd, InvalidVolumeInALatticeThrowsNamingIt) {
  // ffd.h ffd_point: throws for an invalid lattice (validate's message).
  Lattice l = identity_lattice(Frame{}, bernstein_volume(3, 3, 3));
  l.volume.P[4].x = NAN;
  EXPECT_EQ(error_of([&] { ffd_point(l, {0.5, 0.5, 0.5}); }),
            "volume: control point P[4] is not finite");
  EXPECT_EQ(error_of([&] { identity_lattice(Frame{}, l.volume); }),
            "volume: control point P[4] is not finite");
  l.volume.P.resize(26);
  EXPECT_EQ(error_of([&] { find_fold(l); }), "volume: 26 control points for 3 x 3 x 3 = 27");
}

TEST(Ffd, PointNotFiniteThrowsNamingIt) {
  const Lattice l = identity_lattice(Frame{}, bernstein_volume(3, 3, 3));
  EXPECT_EQ(error_of([&] { ffd_point(l, {NAN, 0.5, 0.5}); }),
            "ffd_point: x = (nan, 0.5, 0.5) is not finite");
  EXPECT_EQ(error_of([&] { ffd_point(l, {0.5, -INFINITY, 0.5}); }),
            "ffd_point: x = (0.5, -inf, 0.5) is not finite");
}

}  // namespace
}  // namespace gllab::deform
