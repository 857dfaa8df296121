// tests/spline/patch_subdivision_test.cpp — common/spline/patch_subdivision.h:
// one-direction splits, the notes' flatness test and adaptive splitting, cracks and
// their closing, the diagonal curve of degree n + m, the matrix form, G1 joins.
#include "spline/patch_subdivision.h"

#include <gtest/gtest.h>

#include <random>

#include "spline/bezier.h"
#include "spline/surface.h"
#include "spline_test_support.h"

namespace gllab::spline {
namespace {

using testing::error_of;
using testing::kSameCurve;

/// The bicubic-family nets below span about [-1, 1]^3, so kSameCurve is absolute here.
BezierSurface random_patch(std::mt19937& rng, int n, int m) {
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  BezierSurface s;
  s.n = n;
  s.m = m;
  for (int k = 0; k < (n + 1) * (m + 1); ++k) s.P.push_back({d(rng), d(rng), d(rng)});
  return s;
}

double dist(Vec3 a, Vec3 b) { return norm(a - b); }

// "we can split in each direction separately": the halves of split_u / split_v
// evaluate the same surface over their part of the domain (property: de Casteljau
// subdivision does not change the curve, here applied to every column / row).
TEST(PatchSubdivision, OneDirectionSplitKeepsTheSurface) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const BezierSurface s = random_patch(rng, 3, 2);
    const BezierSurfaceSplit hu = split_u(s, 0.3);
    const BezierSurfaceSplit hv = split_v(s, 0.6);
    EXPECT_EQ(hu.first.c, 0.0);  // v untouched by a u split
    EXPECT_EQ(hu.first.d, 1.0);
    for (double u : {0.0, 0.1, 0.3, 0.55, 1.0})
      for (double v : {0.0, 0.25, 0.6, 0.9, 1.0}) {
        const Vec3 x = surface_point(s, u, v);
        EXPECT_LT(dist(surface_point(u <= 0.3 ? hu.first : hu.second, u, v), x), kSameCurve);
        EXPECT_LT(dist(surface_point(v <= 0.6 ? hv.first : hv.second, u, v), x), kSameCurve);
      }
  }
  BezierSurface s;
  s.P.assign(16, Vec3{});
  EXPECT_NE(error_of([&] { split_u(s, 1.0); }).find("split_u"), std::string::npos);
}

// The notes' test: a plane through three corner vertices, the distance of the others.
TEST(PatchSubdivision, FlatnessOfAPlaneIsZeroAndOfABumpIsItsHeight) {
  BezierSurface s;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) s.P.push_back({i / 3.0, j / 3.0, 0.0});
  EXPECT_EQ(patch_flatness(s), 0.0);  // every control vertex lies in z = 0
  s.P[1 * 4 + 2].z = 0.5;             // one inner vertex lifted by 0.5 above that plane
  EXPECT_NEAR(patch_flatness(s), 0.5, testing::kRounding);
}

// Termination: depth never exceeds max_depth, hence at most 4^max_depth leaves; the
// leaves tile the domain (areas add to 1) and every leaf that stopped early is flat.
TEST(PatchSubdivision, AdaptiveSplitTerminatesAndTilesTheDomain) {
  std::mt19937 rng(11);
  const BezierSurface s = random_patch(rng, 3, 3);
  for (int max_depth : {0, 1, 3, 5}) {
    const std::vector<PatchLeaf> leaves = split_adaptive(s, 1e-3, max_depth);
    EXPECT_LE(leaves.size(), static_cast<std::size_t>(1) << (2 * max_depth));
    double area = 0;
    for (const PatchLeaf& l : leaves) {
      EXPECT_LE(l.depth, max_depth);
      if (l.depth < max_depth) {
        EXPECT_LE(patch_flatness(l.patch), 1e-3);
      }
      area += (l.patch.b - l.patch.a) * (l.patch.d - l.patch.c);
      const double u = 0.5 * (l.patch.a + l.patch.b), v = 0.5 * (l.patch.c + l.patch.d);
      EXPECT_LT(dist(surface_point(l.patch, u, v), surface_point(s, u, v)), kSameCurve);
    }
    EXPECT_NEAR(area, 1.0, testing::kRounding);
  }
  // Subdivision nets converge to the surface: the flatness (a bound on how far the
  // net is from a plane) of the deepest leaves shrinks about 4x per level (O(h^2)) once
  // the leaves are small; the first levels of a random twisted net are not yet asymptotic.
  double prev = 0;
  for (const PatchLeaf& l : split_adaptive(s, 1e-300, 3))
    prev = std::max(prev, patch_flatness(l.patch));
  for (int depth = 4; depth <= 6; ++depth) {
    double worst = 0;
    for (const PatchLeaf& l : split_adaptive(s, 1e-300, depth))
      worst = std::max(worst, patch_flatness(l.patch));
    EXPECT_LT(worst, prev / 2.0);  // at least halved; the O(h^2) rate gives about 4x
    prev = worst;
  }
  EXPECT_NE(error_of([&] { split_adaptive(s, 0.0, 3); }).find("tolerance"), std::string::npos);
  EXPECT_NE(error_of([&] { split_adaptive(s, 1e-3, 13); }).find("max_depth"), std::string::npos);
}

/// The largest distance of a T-junction vertex (a leaf corner inside another leaf's
/// edge) from that edge's straight segment in 3D, over all such pairs; count of pairs.
std::pair<double, int> crack_width(const std::vector<LeafQuad>& quads) {
  double worst = 0;
  int pairs = 0;
  for (const LeafQuad& a : quads)
    for (int k = 0; k < 4; ++k)
      for (const LeafQuad& b : quads)
        for (int e = 0; e < 4; ++e) {
          const Vec2 p0 = b.uv[e], p1 = b.uv[(e + 1) % 4], x = a.uv[k];
          const bool h = p0.y == p1.y;
          if ((h ? x.y != p0.y : x.x != p0.x)) continue;
          const double w = h ? (x.x - p0.x) / (p1.x - p0.x) : (x.y - p0.y) / (p1.y - p0.y);
          if (!(w > 0 && w < 1)) continue;
          ++pairs;
          const Vec3 on = (1 - w) * b.p[e] + w * b.p[(e + 1) % 4];
          worst = std::max(worst, norm(a.p[k] - on));
        }
  return {worst, pairs};
}

// "Patch Cracking": leaves split to different depths leave T-junction cracks when
// drawn as flat quads; leaf_quads(..., true) snaps the finer side's vertices onto the
// coarser edge, after which every T-junction vertex lies on the edge it meets.
TEST(PatchSubdivision, CracksOpenBetweenDepthsAndCloseWhenSnapped) {
  BezierSurface s;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) s.P.push_back({i / 3.0, j / 3.0, 0.0});
  s.P[3 * 4 + 3].z = 0.6;  // one raised corner: that quarter needs deeper splits
  s.P[2 * 4 + 2].z = 0.4;
  const std::vector<PatchLeaf> leaves = split_adaptive(s, 2e-3, 5);
  int lo = 99, hi = 0;
  for (const PatchLeaf& l : leaves) {
    lo = std::min(lo, l.depth);
    hi = std::max(hi, l.depth);
  }
  ASSERT_LT(lo, hi);  // mixed depths, or there are no T-junctions to test
  const auto [open, open_pairs] = crack_width(leaf_quads(s, leaves, false));
  const auto [closed, closed_pairs] = crack_width(leaf_quads(s, leaves, true));
  EXPECT_GT(open_pairs, 0);
  EXPECT_EQ(open_pairs, closed_pairs);
  EXPECT_GT(open, 1e-4);  // a crack: the surface bulges off the coarse quad's straight edge
  EXPECT_LT(closed, kSameCurve);  // closed: on the edge up to round-off
  RecordProperty("open_crack", std::to_string(open));
}

// The diagonal curve has degree n + m and gives X(t, t) (property of the Bernstein
// product B_i^n B_j^m = C(n,i) C(m,j) / C(n+m,i+j) B_{i+j}^{n+m}).
TEST(PatchSubdivision, DiagonalCurveIsThePatchAlongUEqualsV) {
  std::mt19937 rng(3);
  for (auto [n, m] : {std::pair{3, 3}, std::pair{2, 4}, std::pair{1, 1}, std::pair{0, 2}}) {
    const BezierSurface s = random_patch(rng, n, m);
    const BezierCurve c = diagonal_curve(s);
    ASSERT_EQ(c.P.size(), static_cast<std::size_t>(n + m + 1));
    for (double t = 0; t <= 1.0; t += 0.125)
      EXPECT_LT(dist(bezier_point(c, t), surface_point(s, t, t)), kSameCurve) << n << "," << m;
  }
}

// U M P M^T V^T against de Casteljau: 50 random bicubic patches, 7 x 7 parameters.
TEST(PatchSubdivision, MatrixFormAgreesWithDeCasteljau) {
  std::mt19937 rng(19);
  for (int trial = 0; trial < 50; ++trial) {
    const BezierSurface s = random_patch(rng, 3, 3);
    for (int a = 0; a <= 6; ++a)
      for (int b = 0; b <= 6; ++b)
        EXPECT_LT(dist(matrix_form_point(s, a / 6.0, b / 6.0), surface_point(s, a / 6.0, b / 6.0)),
                  kSameCurve);
  }
}

/// The largest angle (radians) between the normals of p at u = 1 and r at u = 0 along v.
double normal_gap(const BezierSurface& p, const BezierSurface& r) {
  double worst = 0;
  for (int k = 1; k < 10; ++k) {
    const double v = k / 10.0;
    worst = std::max(worst, norm(cross(surface_normal(p, 1.0, v), surface_normal(r, 0.0, v))));
  }
  return worst;
}

// "Higher Order Surfaces", "Joining of Bezier patches": G1 when
// p_ni - p_(n-1)i = k (r_1i - r_0i). Built with k = 2: the normals agree along the
// shared edge. A C0-only join (same edge, r_1i moved off that rule) does not.
TEST(PatchSubdivision, G1JoinHasEqualNormalsAndC0JoinDoesNot) {
  std::mt19937 rng(5);
  const BezierSurface p = random_patch(rng, 3, 3);
  BezierSurface r = random_patch(rng, 3, 3);
  const double k = 2.0;
  for (int j = 0; j <= 3; ++j) {
    r.P[0 * 4 + j] = p.P[3 * 4 + j];                                    // C0: r_0i = p_ni
    r.P[1 * 4 + j] = r.P[0 * 4 + j] + (p.P[3 * 4 + j] - p.P[2 * 4 + j]) / k;  // the G1 rule
  }
  const double kSameNormal = 1e-9;  // sin of the angle; round-off in the unit normals
  EXPECT_LT(normal_gap(p, r), kSameNormal);
  BezierSurface c0 = r;
  c0.P[1 * 4 + 1] += Vec3{0.0, 0.0, 0.5};  // break the rule at one vertex, edge kept
  for (int j = 0; j <= 3; ++j) EXPECT_EQ(c0.P[j], p.P[12 + j]);
  EXPECT_GT(normal_gap(p, c0), 1e-2);  // a visible crease: over half a degree
}

}  // namespace
}  // namespace gllab::spline
