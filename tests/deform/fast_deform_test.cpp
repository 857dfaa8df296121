// tests/deform/fast_deform_test.cpp — the fast layer of free-form deformation
// (common/deform/fast_deform.cpp) against the textbook layer (ffd.cpp:
// deform_mesh, ffd_point, deform_normal), which is the reference.
//
// The fast layer computes the same quantities in another order (the cell's
// polynomial in Taylor form, Horner, cof(J) without J), so it agrees with the
// textbook to rounding, not bit for bit. Where it must agree exactly, it is
// tested exactly: the inside / outside decision and the clamping (the same
// arithmetic), the outside vertices' values, the counts, the exceptions, and
// the lattices above kMaxFastDegree (the textbook evaluator itself).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "deform/fast_deform.h"
#include "deform/ffd.h"
#include "deform/teapot.h"
#include "deform/volume.h"
#include "deform_checks.h"
#include "spline/knots.h"

namespace gllab::deform {
namespace {

using testing::error_of;
using testing::max_abs;
using testing::Random;
using testing::record;

// ---- tolerances (named, never loosened to pass) -----------------------------

/// The bound, relative to each quantity's scale (below): 1e-12. Its
/// origin: the first test below records the largest errors it sees (random
/// lattices of degrees 1..5, counts up to 12, skewed frames, ~19,000 points):
/// 8.1e-16 for positions, 2.7e-14 for det J, 1.4e-14 for the normals, each
/// over its scale (and a separate run over degrees 1..8: at most 2.0e-15,
/// 2.9e-14 of max |det J|, 1.9e-14). The bound keeps a factor of 35 above the
/// worst of them and lies five orders below float's rounding (6e-8), so that in
/// float the two agree to one rounding (float_ulp).
/// The scales, from the textbook's values at the point:
///   - a position: the lattice's size, the largest |coordinate| of the control
///     points and of the point itself (X is a weighted mean of the control
///     points; its rounding errors are ulps of their size);
///   - det J = det [Xs Xt Xu] / det M: |Xs| |Xt| |Xu| / det M, Hadamard's
///     bound of |det J| (the sizes of the three products that cancel);
///   - the unit normal cof(J) n / |cof(J) n|: |cof(J)|_F |n| / |cof(J) n|, the
///     condition of normalising cof(J) n (an error of relative size e in
///     cof(J) moves the unit normal by up to e times this). Near a fold, where
///     cof(J) n is small, the normal is ill-conditioned for either layer.
constexpr double kAgree = 1e-12;

/// Two doubles within kAgree of each other become floats at most one float
/// rounding apart (they may straddle a rounding boundary); a value much
/// smaller than its scale can differ by the double tolerance itself. So a
/// float of the fast layer is within one ulp (of float, at the value) plus the
/// double tolerance of the textbook's.
double float_ulp(double v) {
  const float a = float(std::fabs(v));
  return double(std::nextafter(a, std::numeric_limits<float>::infinity()) - a);
}

// ---- lattices ----------------------------------------------------------------

/// A right-handed parallelepiped: scales 0.5..3, shears up to 0.3 of them
/// (diagonally dominant, so det M > 0), turned about z; seeded.
Frame random_frame(Random& r) {
  Frame f;
  f.origin = r.vec3(-2, 2);
  const double a = r.real(0, 6.28), c = std::cos(a), s = std::sin(a);
  const double sx = r.real(0.5, 3), sy = r.real(0.5, 3), sz = r.real(0.5, 3);
  const auto turn = [&](Vec3 v) { return Vec3{c * v.x - s * v.y, s * v.x + c * v.y, v.z}; };
  f.S = turn({sx, r.real(-0.3, 0.3) * sx, r.real(-0.3, 0.3) * sx});
  f.T = turn({r.real(-0.3, 0.3) * sy, sy, r.real(-0.3, 0.3) * sy});
  f.U = turn({r.real(-0.3, 0.3) * sz, r.real(-0.3, 0.3) * sz, sz});
  return f;
}

/// The identity of [0, 1]^3 with the given counts and degrees: control points
/// at the Greville abscissae (what bernstein_volume and bspline_volume do, for
/// degrees that differ between directions).
Volume unit_volume(std::array<int, 3> count, std::array<int, 3> degree) {
  Volume v;
  v.count = count;
  v.degree = degree;
  std::array<std::vector<double>, 3> g;
  for (int a = 0; a < 3; ++a) g[a] = spline::greville_abscissae(degree[a], volume_knots(v, a));
  v.P.resize(std::size_t(count[0]) * count[1] * count[2]);
  for (int i = 0; i < count[0]; ++i)
    for (int j = 0; j < count[1]; ++j)
      for (int k = 0; k < count[2]; ++k) v.point(i, j, k) = {g[0][i], g[1][j], g[2][k]};
  return v;
}

/// The identity lattice of `frame` with every control point moved by up to
/// `jiggle` times the frame's axes (seeded).
Lattice jiggled(const Frame& frame, const Volume& unit, double jiggle, Random& r) {
  Lattice l = identity_lattice(frame, unit);
  for (Vec3& p : l.volume.P) p += frame.matrix() * r.vec3(-jiggle, jiggle);
  return l;
}

/// Bernstein of degree p (p + 1 points), or a B-spline of degree p with a
/// random count p + 1..12 in each direction.
Volume random_unit(Random& r, bool bernstein, int p) {
  if (bernstein) return bernstein_volume(p + 1, p + 1, p + 1);
  return bspline_volume(r.integer(p + 1, 12), r.integer(p + 1, 12), r.integer(p + 1, 12), p);
}

// ---- points ------------------------------------------------------------------

/// Points given by their box coordinates (s, t, u), and unit normals.
struct Points {
  std::vector<Vec3> x, n;
};

/// In the box: random (s, t, u); on the knot planes j / segments of each
/// direction and on the box's faces (0 and 1, the corners too); outside, by
/// up to 0.3 and by as little as 1e-9 (beyond kBoxSlack) in one coordinate;
/// kBoxSlack / 2 outside a face (inside, clamped; in float that offset is
/// lost). Normals random, unit; seeded.
Points box_points(const Lattice& l, Random& r, int random_count) {
  std::vector<Vec3> stu;
  for (int k = 0; k < random_count; ++k) stu.push_back(r.vec3(0, 1));
  for (int a = 0; a < 3; ++a) {
    const int segments = l.volume.count[a] - l.volume.degree[a];
    for (int j = 0; j <= segments; ++j)
      for (int k = 0; k < 4; ++k) {
        Vec3 w = r.vec3(0, 1);
        (a == 0 ? w.x : a == 1 ? w.y : w.z) = double(j) / segments;
        stu.push_back(w);
      }
  }
  for (int c = 0; c < 8; ++c) stu.push_back({double(c & 1), double((c >> 1) & 1), double(c >> 2)});
  for (double by : {0.3, 1e-3, 1e-9, kBoxSlack / 2})
    for (int a = 0; a < 3; ++a)
      for (double side : {0.0, 1.0}) {
        Vec3 w = r.vec3(0, 1);
        (a == 0 ? w.x : a == 1 ? w.y : w.z) = side == 0 ? -by : 1 + by;
        stu.push_back(w);
      }
  Points p;
  for (const Vec3 w : stu) {
    p.x.push_back(l.frame.origin + l.frame.matrix() * w);
    p.n.push_back(normalized(r.vec3(-1, 1)));
  }
  return p;
}

/// The points as a float mesh (positions and normals; no triangles needed).
IndexedMesh as_mesh(const Points& p) {
  IndexedMesh m;
  for (std::size_t k = 0; k < p.x.size(); ++k) {
    m.positions.insert(m.positions.end(), {float(p.x[k].x), float(p.x[k].y), float(p.x[k].z)});
    m.normals.insert(m.normals.end(), {float(p.n[k].x), float(p.n[k].y), float(p.n[k].z)});
  }
  return m;
}

/// deform_mesh's slack for float vertices (ffd.h): |M^-1|_inf 2^-23 times the
/// box's size |X0|_max + |M|_inf, at least kBoxSlack.
double norm_inf(const Mat3& a) {
  const Mat3 t = transpose(a);
  const auto row = [](Vec3 r) { return std::fabs(r.x) + std::fabs(r.y) + std::fabs(r.z); };
  return std::max({row(t.c0), row(t.c1), row(t.c2)});
}
double mesh_slack(const Frame& f) {
  const double size = max_abs(f.origin) + norm_inf(f.matrix());
  return std::max(kBoxSlack, norm_inf(inverse(f.matrix())) * size * 0x1p-23);
}

double lattice_size(const Lattice& l) {
  double s = max_abs(l.frame.origin);
  for (const Vec3& q : l.volume.P) s = std::max(s, max_abs(q));
  return s;
}

/// ffd_point's arithmetic (ffd.cpp's Mapper: M^-1 (x - X0), the box test,
/// VolumeEvaluator, J = [Xs Xt Xu] M^-1, det [Xs Xt Xu] / det M) with the
/// evaluator built once: ffd_point copies the lattice at every call, which
/// for the 40^3 lattice below costs more than the whole test should.
/// TextbookReferenceIsFfdPoint checks that it gives ffd_point's bits.
struct Reference {
  explicit Reference(const Lattice& l)
      : eval(l.volume), frame(l.frame), m_inv(inverse(l.frame.matrix())),
        det_m(det(l.frame.matrix())) {}
  FfdPoint operator()(Vec3 x, double slack = kBoxSlack) const {
    FfdPoint r;
    r.x = x;
    Vec3 stu = m_inv * (x - frame.origin);
    for (double* c : {&stu.x, &stu.y, &stu.z}) {
      if (!(*c >= -slack && *c <= 1 + slack)) return r;
      *c = std::clamp(*c, 0.0, 1.0);
    }
    const VolumeDerivs d = eval(stu.x, stu.y, stu.z);
    r.inside = true;
    r.x = d.X;
    r.J = d.jacobian() * m_inv;
    r.det = det(d.jacobian()) / det_m;
    return r;
  }
  VolumeEvaluator eval;
  Frame frame;
  Mat3 m_inv;
  double det_m;
};

/// The scales of kAgree at one point, from the textbook's values there
/// (size: lattice_size).
struct Scales {
  double x, det, normal;
};
Scales scales(const Lattice& l, double size, Vec3 x, Vec3 n, const FfdPoint& f) {
  const Mat3 jac = f.J * l.frame.matrix();  // [Xs Xt Xu] = J M
  const Mat3 c = cofactor(f.J);
  const double cof = std::sqrt(dot(c.c0, c.c0) + dot(c.c1, c.c1) + dot(c.c2, c.c2));
  return {std::max(size, max_abs(x)),
          norm(jac.c0) * norm(jac.c1) * norm(jac.c2) / det(l.frame.matrix()),
          cof * norm(n) / norm(c * n)};
}

// ---- the comparisons -----------------------------------------------------------

/// deform_points_fast against ffd_point and deform_normal, point by point;
/// the counts against deform_mesh's definitions. Returns the largest errors
/// seen (each over its scale), for the report.
struct Errors {
  double x = 0, det = 0, normal = 0;
};
Errors expect_points_agree(const Lattice& l, const Points& p, const std::string& what) {
  const DeformedPoints d = deform_points_fast(l, p.x, p.n);
  const Reference ffd(l);
  const double size = lattice_size(l);
  EXPECT_EQ(d.x.size(), p.x.size()) << what;
  EXPECT_EQ(d.normals.size(), p.x.size()) << what;
  EXPECT_EQ(d.det.size(), p.x.size()) << what;
  Errors e;
  std::size_t outside = 0, folded = 0, near_fold = 0;
  double lo = INFINITY, hi = -INFINITY, lo_tol = 0, hi_tol = 0;
  for (std::size_t k = 0; k < p.x.size(); ++k) {
    const FfdPoint f = ffd(p.x[k]);
    const Vec3 n = deform_normal(f.J, p.n[k]);
    if (!f.inside) {
      // The same arithmetic decides; outside, deform_mesh's values exactly.
      ++outside;
      EXPECT_EQ(d.x[k], p.x[k]) << what << ", outside point " << k;
      EXPECT_EQ(d.det[k], 1.0) << what << ", outside point " << k;
      EXPECT_EQ(d.normals[k], n) << what << ", outside point " << k;
      continue;
    }
    const Scales s = scales(l, size, p.x[k], p.n[k], f);
    const double ex = max_abs(d.x[k] - f.x) / s.x, ed = std::fabs(d.det[k] - f.det) / s.det;
    const double en = max_abs(d.normals[k] - n) / s.normal;
    EXPECT_LE(ex, kAgree) << what << ", point " << k;
    EXPECT_LE(ed, kAgree) << what << ", point " << k << ": det " << d.det[k] << " vs " << f.det;
    EXPECT_LE(en, kAgree) << what << ", point " << k;
    e.x = std::max(e.x, ex), e.det = std::max(e.det, ed), e.normal = std::max(e.normal, en);
    folded += f.det <= 0;
    near_fold += std::fabs(f.det) <= kAgree * s.det;
    if (f.det < lo) lo = f.det, lo_tol = kAgree * s.det;
    if (f.det > hi) hi = f.det, hi_tol = kAgree * s.det;
  }
  EXPECT_EQ(d.outside, outside) << what;
  // No point lies within rounding of a fold (else either count would do).
  EXPECT_EQ(near_fold, 0u) << what;
  EXPECT_EQ(d.folded, folded) << what;
  if (outside < p.x.size()) {
    EXPECT_NEAR(d.min_det, lo, lo_tol) << what;
    EXPECT_NEAR(d.max_det, hi, hi_tol) << what;
  } else {
    EXPECT_EQ(d.min_det, 1.0) << what;
    EXPECT_EQ(d.max_det, 1.0) << what;
  }
  return e;
}

/// deform_mesh_fast against deform_mesh, float by float (float_ulp's bound,
/// with the scales of the textbook at the float vertex); counts and min / max
/// det as above. Counts the floats that differ at all, and those that differ
/// by more than the double tolerance: where the two doubles straddled a
/// float rounding boundary. (A value far below its scale, such as a
/// coordinate that is 0 in the input, differs without that: 2.8e-17 against
/// 0 on the teapot's plane y = 0.)
struct FloatDiff {
  std::size_t any = 0, rounding = 0, compared = 0;
};
FloatDiff expect_meshes_agree(const Lattice& l, const IndexedMesh& m, const std::string& what) {
  const DeformedMesh a = deform_mesh(l, m), b = deform_mesh_fast(l, m);
  EXPECT_EQ(b.mesh.indices, a.mesh.indices) << what;
  EXPECT_EQ(b.mesh.colours, a.mesh.colours) << what;
  EXPECT_EQ(b.mesh.positions.size(), a.mesh.positions.size()) << what;
  EXPECT_EQ(b.mesh.normals.size(), a.mesh.normals.size()) << what;
  EXPECT_EQ(b.det.size(), a.det.size()) << what;
  EXPECT_EQ(b.outside, a.outside) << what;
  EXPECT_EQ(b.folded, a.folded) << what;
  if (b.mesh.positions.size() != a.mesh.positions.size() || b.det.size() != a.det.size() ||
      b.mesh.normals.size() != a.mesh.normals.size())
    return {};
  const bool normals = !a.mesh.normals.empty();
  const Reference ffd(l);
  const double slack = mesh_slack(l.frame), size = lattice_size(l);
  FloatDiff differ;
  const auto count = [&](float p, float q, double tolerance) {
    ++differ.compared;
    differ.any += p != q;
    differ.rounding += std::fabs(double(p) - q) > tolerance;
  };
  double lo_tol = 0, hi_tol = 0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const float* q = &m.positions[3 * v];
    const Vec3 x{q[0], q[1], q[2]};
    const Vec3 n = normals ? Vec3{m.normals[3 * v], m.normals[3 * v + 1], m.normals[3 * v + 2]}
                           : Vec3{0, 0, 1};
    // deform_mesh's inside test (its slack for float vertices, ffd.h).
    const FfdPoint f = ffd(x, slack);
    const bool inside = f.inside;
    const Scales s = inside ? scales(l, size, x, n, f) : Scales{0, 0, 0};
    if (inside && a.det[v] == float(a.min_det)) lo_tol = std::max(lo_tol, kAgree * s.det);
    if (inside && a.det[v] == float(a.max_det)) hi_tol = std::max(hi_tol, kAgree * s.det);
    for (int c = 0; c < 3; ++c) {
      const std::size_t i = 3 * v + c;
      const float pa = a.mesh.positions[i], pb = b.mesh.positions[i];
      count(pa, pb, kAgree * s.x);
      EXPECT_LE(std::fabs(double(pa) - pb), float_ulp(pa) + kAgree * s.x)
          << what << ", vertex " << v << " position " << c;
      if (!normals) continue;
      const float na = a.mesh.normals[i], nb = b.mesh.normals[i];
      count(na, nb, kAgree * s.normal);
      EXPECT_LE(std::fabs(double(na) - nb), float_ulp(na) + kAgree * s.normal)
          << what << ", vertex " << v << " normal " << c;
    }
    count(a.det[v], b.det[v], kAgree * s.det);
    EXPECT_LE(std::fabs(double(a.det[v]) - b.det[v]), float_ulp(a.det[v]) + kAgree * s.det)
        << what << ", vertex " << v << " det";
    if (!inside) {
      // Outside: deform_mesh's values exactly.
      EXPECT_EQ(b.det[v], 1.0f) << what << ", vertex " << v;
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(b.mesh.positions[3 * v + c], m.positions[3 * v + c]) << what << ", vertex " << v;
        if (normals) {
          EXPECT_EQ(b.mesh.normals[3 * v + c], a.mesh.normals[3 * v + c]) << what;
        }
      }
    }
  }
  EXPECT_NEAR(b.min_det, a.min_det, lo_tol) << what;
  EXPECT_NEAR(b.max_det, a.max_det, hi_tol) << what;
  return differ;
}

// ---- agreement -----------------------------------------------------------------------------

TEST(FastDeform, AgreesWithTheTextbookOnRandomLatticesOfDegreesOneToFive) {
  // Both kinds, degrees 1..5 (the fixed-degree kernels), B-spline counts up to
  // 12 per direction, 4 random lattices each in random skewed frames;
  // random points, points on every knot plane and on the faces, outside and
  // within the slack. In double and in float.
  Random r(2026);
  Errors worst;
  FloatDiff all;
  for (const bool bernstein : {true, false})
    for (int p = 1; p <= 5; ++p)
      for (int trial = 0; trial < 4; ++trial) {
        const Lattice l = jiggled(random_frame(r), random_unit(r, bernstein, p), 0.15, r);
        const std::string what = std::string(bernstein ? "Bernstein" : "B-spline") +
                                 " degree " + std::to_string(p) + ", counts " +
                                 std::to_string(l.volume.count[0]) + " x " +
                                 std::to_string(l.volume.count[1]) + " x " +
                                 std::to_string(l.volume.count[2]);
        const Points pts = box_points(l, r, 400);
        const Errors e = expect_points_agree(l, pts, what);
        worst.x = std::max(worst.x, e.x), worst.det = std::max(worst.det, e.det);
        worst.normal = std::max(worst.normal, e.normal);
        const FloatDiff f = expect_meshes_agree(l, as_mesh(pts), what);
        all.any += f.any, all.rounding += f.rounding, all.compared += f.compared;
      }
  record("max_position_error_over_scale", worst.x);
  record("max_det_error_over_scale", worst.det);
  record("max_normal_error_over_scale", worst.normal);
  record("floats_compared", double(all.compared));
  record("floats_differing", double(all.any));
  record("floats_rounded_differently", double(all.rounding));
  // In float the two layers are mostly identical (a difference needs the two
  // doubles to straddle a float rounding boundary, within 1e-12 of it).
  EXPECT_LT(double(all.rounding), 1e-3 * double(all.compared));
}

TEST(FastDeform, VerticesOnTheFacesAndKnotPlanesOfAnAxisAlignedBoxFollowTheRightSpan) {
  // A box whose sides are powers of two: the float vertices at (s, t, u) =
  // k / 8 are exact, so they lie exactly on the faces and on the knot planes
  // of 2, 4 and 8 spans. A2.1 puts a knot into the span on its right (the last
  // span for 1); at degree 1 Xs jumps there, so the wrong span would give
  // another det J and normal. Degrees 1..5, counts degree + 2, + 4, + 8.
  const Frame box = box_frame({-1, -0.5, 0.25}, {3, 1.5, 2.25});
  Random r(88);
  for (int p = 1; p <= 5; ++p)
    for (int segments : {2, 4, 8}) {
      const int n = p + segments;
      const Lattice l = jiggled(box, bspline_volume(n, n, n, p), 0.1, r);
      Points pts;
      for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j)
          for (int k = 0; k <= 8; ++k) {
            const Vec3 w{i / 8.0, j / 8.0, k / 8.0};
            pts.x.push_back(box.origin + box.matrix() * w);
            pts.n.push_back(normalized(r.vec3(-1, 1)));
          }
      const std::string what = "degree " + std::to_string(p) + ", " + std::to_string(segments) +
                               " spans";
      expect_points_agree(l, pts, what);
      const IndexedMesh m = as_mesh(pts);
      expect_meshes_agree(l, m, what);
      EXPECT_EQ(deform_mesh_fast(l, m).outside, 0u) << what;  // the faces are inside
    }
}

TEST(FastDeform, MixedAndHighDegreesAgreeAndAboveTheCapAreTheTextbooksBits) {
  // Degrees that differ between directions use the kernel of the largest
  // with zero-padded coefficients; 6..8 the kernel with the degree at run
  // time; above kMaxFastDegree (8) the textbook evaluator itself: then every
  // float is deform_mesh's.
  Random r(7);
  struct Shape {
    std::array<int, 3> count, degree;
  };
  for (const Shape sh : {Shape{{5, 7, 4}, {2, 3, 1}}, Shape{{6, 2, 9}, {5, 1, 4}},
                         Shape{{3, 4, 6}, {2, 3, 5}}, Shape{{7, 7, 7}, {6, 6, 6}},
                         Shape{{9, 9, 9}, {8, 8, 8}}, Shape{{12, 8, 10}, {7, 2, 4}}}) {
    const Lattice l = jiggled(random_frame(r), unit_volume(sh.count, sh.degree), 0.1, r);
    const std::string what = "degrees " + std::to_string(sh.degree[0]) + ", " +
                             std::to_string(sh.degree[1]) + ", " + std::to_string(sh.degree[2]);
    const Points pts = box_points(l, r, 300);
    expect_points_agree(l, pts, what);
    expect_meshes_agree(l, as_mesh(pts), what);
  }
  for (const Shape sh : {Shape{{10, 10, 10}, {9, 9, 9}}, Shape{{16, 4, 5}, {15, 2, 3}}}) {
    const Lattice l = jiggled(random_frame(r), unit_volume(sh.count, sh.degree), 0.1, r);
    const IndexedMesh m = as_mesh(box_points(l, r, 200));
    const DeformedMesh a = deform_mesh(l, m), b = deform_mesh_fast(l, m);
    EXPECT_EQ(b.mesh.positions, a.mesh.positions);
    EXPECT_EQ(b.mesh.normals, a.mesh.normals);
    EXPECT_EQ(b.det, a.det);
    EXPECT_EQ(b.outside, a.outside);
    EXPECT_EQ(b.folded, a.folded);
    EXPECT_EQ(b.min_det, a.min_det);
    EXPECT_EQ(b.max_det, a.max_det);
  }
}

TEST(FastDeform, FoldedLatticesGiveTheSameFoldedCount) {
  // ffd_test's fold: a control point dragged past its neighbour (quadratic
  // 6 x 6 x 6 and trilinear 4 x 4 x 4), and a Bernstein 4 x 4 x 4 whose top
  // centre points are pushed down through the bottom. Folded vertices have
  // det J <= 0 and reversed normals, in both layers alike.
  struct Case {
    Lattice l;
    const char* what;
  };
  const Frame unit = box_frame({0, 0, 0}, {1, 1, 1});
  std::vector<Case> cases;
  Lattice q = identity_lattice(unit, bspline_volume(6, 6, 6, 2));
  q.volume.point(2, 2, 2).x = 0.9;
  cases.push_back({q, "quadratic, P(2, 2, 2) dragged to s = 0.9"});
  Lattice t = identity_lattice(unit, bspline_volume(4, 4, 4, 1));
  t.volume.point(1, 1, 1).x = 0.7;
  cases.push_back({t, "trilinear, P(1, 1, 1) dragged to s = 0.7"});
  Lattice b = identity_lattice(unit, bernstein_volume(4, 4, 4));
  for (int i = 1; i <= 2; ++i)
    for (int j = 1; j <= 2; ++j) b.volume.point(i, j, 3).z = -0.6;
  cases.push_back({b, "Bernstein, the top centre pushed through the bottom"});
  Random r(31);
  for (const Case& c : cases) {
    ASSERT_TRUE(find_fold(c.l).folds) << c.what;
    const Points pts = box_points(c.l, r, 3000);
    expect_points_agree(c.l, pts, c.what);
    expect_meshes_agree(c.l, as_mesh(pts), c.what);
    const DeformedMesh d = deform_mesh_fast(c.l, as_mesh(pts));
    EXPECT_GT(d.folded, 0u) << c.what;
    EXPECT_LE(d.min_det, 0) << c.what;
  }
}

TEST(FastDeform, TeapotThroughTheLabsLatticesAgreesWithDeformMesh) {
  // Lab 29's setting: the teapot in the box round it, 5 x 5 x 5 points, a
  // Bernstein lattice (degree 4) and a cubic B-spline one, a point pulled.
  const Frame box = box_frame({-3.3, -2.3, -.2}, {3.7, 2.3, 3.4});
  const IndexedMesh m = teapot_mesh(12);
  for (const bool bernstein : {true, false}) {
    Lattice l = identity_lattice(box, bernstein ? bernstein_volume(5, 5, 5)
                                                : bspline_volume(5, 5, 5, 3));
    l.volume.P[(4 * 5 + 2) * 5 + 4] += Vec3{1.6, 0, 0.5};
    const std::string what = bernstein ? "Bernstein 5^3" : "cubic B-spline 5^3";
    const FloatDiff f = expect_meshes_agree(l, m, what);
    const std::string kind = bernstein ? "bernstein" : "bspline";
    record("teapot_floats_compared_" + kind, double(f.compared));
    record("teapot_floats_differing_" + kind, double(f.any));
    record("teapot_floats_rounded_differently_" + kind, double(f.rounding));
    EXPECT_LT(double(f.rounding), 1e-3 * double(f.compared)) << what;
  }
}

TEST(FastDeform, TextbookReferenceIsFfdPoint) {
  // The tests' Reference is ffd_point, bit for bit (and with deform_mesh's
  // slack, deform_mesh: its outside count).
  Random r(17);
  for (const bool bernstein : {true, false}) {
    const Lattice l = jiggled(random_frame(r), random_unit(r, bernstein, 3), 0.15, r);
    const Points pts = box_points(l, r, 200);
    const Reference ffd(l);
    std::size_t outside = 0;
    for (const Vec3 x : pts.x) {
      const FfdPoint a = ffd_point(l, x), b = ffd(x);
      EXPECT_EQ(a.inside, b.inside);
      EXPECT_EQ(a.x, b.x);
      EXPECT_EQ(a.det, b.det);
      EXPECT_EQ(a.J.c0, b.J.c0);
      EXPECT_EQ(a.J.c1, b.J.c1);
      EXPECT_EQ(a.J.c2, b.J.c2);
    }
    const IndexedMesh m = as_mesh(pts);
    for (std::size_t v = 0; v < m.vertex_count(); ++v)
      outside += !ffd({m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]},
                      mesh_slack(l.frame))
                      .inside;
    EXPECT_EQ(deform_mesh(l, m).outside, outside);
  }
}

// ---- sizes, reuse, the sort's two ways, errors ------------------------------------------

TEST(FastDeform, ChunksAndLatticesOfManyCells) {
  // More vertices than a chunk (4096) and more cells than the counting sort
  // takes (a trilinear 40 x 40 x 40: 59,319 cells, sorted by comparison), and
  // more cells touched than the coefficient cache holds (21,845 trilinear
  // cells): the cache starts over, the results do not change.
  Random r(4242);
  const Lattice many = jiggled(random_frame(r), bspline_volume(40, 40, 40, 1), 0.2, r);
  const Points a = box_points(many, r, 40000);
  expect_points_agree(many, a, "trilinear 40^3");
  const Lattice cubic = jiggled(random_frame(r), bspline_volume(9, 9, 9, 3), 0.15, r);
  const Points b = box_points(cubic, r, 20000);
  expect_points_agree(cubic, b, "cubic 9^3");
  expect_meshes_agree(cubic, as_mesh(b), "cubic 9^3");
}

TEST(FastDeform, EmptyMeshNoNormalsAndWhatIsCopied) {
  Random r(5);
  const Lattice l = jiggled(box_frame({0, 0, 0}, {1, 1, 1}), bspline_volume(5, 5, 5, 2), 0.1, r);
  // Empty: nothing, counts 0, min and max det their defaults 1 (ffd.h).
  const DeformedMesh e = deform_mesh_fast(l, IndexedMesh{});
  EXPECT_TRUE(e.mesh.positions.empty());
  EXPECT_TRUE(e.mesh.normals.empty());
  EXPECT_TRUE(e.det.empty());
  EXPECT_EQ(e.outside, 0u);
  EXPECT_EQ(e.folded, 0u);
  EXPECT_EQ(e.min_det, 1.0);
  EXPECT_EQ(e.max_det, 1.0);
  const DeformedPoints ep = deform_points_fast(l, {});
  EXPECT_TRUE(ep.x.empty());
  EXPECT_EQ(ep.min_det, 1.0);
  // Without normals (none, or not one per vertex): none out, the rest as
  // deform_mesh; colours and indices copied.
  IndexedMesh m = as_mesh(box_points(l, r, 100));
  m.colours.assign(m.positions.size(), 0.25f);
  for (std::uint32_t k = 0; k + 2 < m.vertex_count(); ++k)
    m.indices.insert(m.indices.end(), {k, k + 1, k + 2});
  expect_meshes_agree(l, m, "with normals");
  IndexedMesh no = m;
  no.normals.clear();
  EXPECT_TRUE(deform_mesh_fast(l, no).mesh.normals.empty());
  expect_meshes_agree(l, no, "without normals");
  IndexedMesh fewer = m;
  fewer.normals.resize(fewer.normals.size() - 3);
  EXPECT_TRUE(deform_mesh_fast(l, fewer).mesh.normals.empty());
  expect_meshes_agree(l, fewer, "normals not one per vertex");
  // Positions not a multiple of 3: the last float is no vertex, and stays 0.
  IndexedMesh odd = m;
  odd.positions.push_back(0.5f);
  odd.normals.push_back(0.5f);
  const DeformedMesh d = deform_mesh_fast(l, odd), t = deform_mesh(l, odd);
  ASSERT_EQ(d.mesh.positions.size(), t.mesh.positions.size());
  EXPECT_EQ(d.mesh.positions.back(), t.mesh.positions.back());
  EXPECT_EQ(d.mesh.normals.back(), t.mesh.normals.back());
}

TEST(FastDeform, ReusedOutputEqualsAFreshOne) {
  // deform_mesh_fast(l, m, out) reuses out's buffers: a larger mesh with
  // normals, then a smaller one without, then the first again.
  Random r(9);
  const Lattice l = jiggled(random_frame(r), bernstein_volume(4, 4, 4), 0.15, r);
  const IndexedMesh big = as_mesh(box_points(l, r, 5000));
  IndexedMesh small = as_mesh(box_points(l, r, 50));
  small.normals.clear();
  DeformedMesh out;
  for (const IndexedMesh* m : std::vector<const IndexedMesh*>{&big, &small, &big}) {
    deform_mesh_fast(l, *m, out);
    const DeformedMesh fresh = deform_mesh_fast(l, *m);
    EXPECT_EQ(out.mesh.positions, fresh.mesh.positions);
    EXPECT_EQ(out.mesh.normals, fresh.mesh.normals);
    EXPECT_EQ(out.mesh.indices, fresh.mesh.indices);
    EXPECT_EQ(out.det, fresh.det);
    EXPECT_EQ(out.outside, fresh.outside);
    EXPECT_EQ(out.folded, fresh.folded);
    EXPECT_EQ(out.min_det, fresh.min_det);
    EXPECT_EQ(out.max_det, fresh.max_det);
  }
}

TEST(FastDeform, ErrorsAreDeformMeshs) {
  const Lattice good =
      identity_lattice(box_frame({0, 0, 0}, {1, 1, 1}), bernstein_volume(3, 3, 3));
  Random r(3);
  const IndexedMesh m = as_mesh(box_points(good, r, 20));
  // An invalid lattice: deform_mesh's message, word for word.
  Lattice bad_volume = good;
  bad_volume.volume.P.pop_back();
  Lattice bad_frame = good;
  bad_frame.frame.U = {0, 0, -1};
  Lattice bad_point = good;
  bad_point.volume.P[4].y = std::numeric_limits<double>::quiet_NaN();
  for (const Lattice* l : {&bad_volume, &bad_frame, &bad_point}) {
    const std::string expected = error_of([&] { deform_mesh(*l, m); });
    EXPECT_EQ(error_of([&] { deform_mesh_fast(*l, m); }), expected);
    EXPECT_EQ(error_of([&] { deform_points_fast(*l, {Vec3{0.5, 0.5, 0.5}}); }), expected);
  }
  // A vertex that is not finite: the first one is named (here in the second
  // chunk, after a finite first chunk).
  IndexedMesh big = as_mesh(box_points(good, r, 6000));
  big.positions[3 * 5000 + 1] = std::numeric_limits<float>::quiet_NaN();
  big.positions[3 * 5500 + 2] = std::numeric_limits<float>::infinity();
  EXPECT_THROW_NAMING(deform_mesh_fast(good, big), "deform_mesh_fast: vertex 5000 (");
  EXPECT_THROW_NAMING(deform_mesh_fast(good, big), "nan");
  std::vector<Vec3> x{{0.5, 0.5, 0.5}, {0.1, -std::numeric_limits<double>::infinity(), 0}};
  EXPECT_THROW_NAMING(deform_points_fast(good, x), "deform_points_fast: point 1 (");
  // Normals: none or one per point.
  const std::vector<Vec3> one{{0.5, 0.5, 0.5}}, two{{0, 0, 1}, {0, 1, 0}};
  EXPECT_THROW_NAMING(deform_points_fast(good, one, two),
                      "deform_points_fast: 2 normals for 1 points");
}

}  // namespace
}  // namespace gllab::deform
