// tests/labs/29_free_form_deformation_test.cpp — what lab 29 promises
// (Sederberg and Parry 1986; lecture notes ch. 1, §1.7 Surface
// representations, "Morphing"):
//  - global_vs_local: the pulled Bernstein point moves most vertices, the
//    pulled B-spline point only vertices inside its support, s > 1/2 and
//    u > 1/2 (the last cubic basis function over the knots 0 0 0 0 1/2 1 1 1 1
//    is zero below 1/2); each moves every vertex its basis functions say it
//    moves by more than 1e-5;
//  - normals: the face-averaged normals converge to the Jacobian's as the
//    teapot is refined (the Jacobian's are exact, the faces' an approximation);
//  - volume_change: the bend squeezes and stretches (det J both sides of 1);
//  - fold: the core reports det J < 0, and so do the vertices of the lid.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "deform/ffd.h"
#include "deform/teapot.h"
#include "spline/basis.h"
#include "spline/bezier.h"
#include "spline/knots.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::numbers_after;
using gllab::testing::ScratchDir;
using gllab::testing::view_text;

const std::string kLab = "29_free_form_deformation";

// "1803 of 2082 vertices moved" -> {1803, 2082}, per panel.
std::vector<std::array<double, 2>> moved_counts(const std::vector<std::string>& lines) {
  std::vector<std::array<double, 2>> out;
  for (const std::string& line : lines) {
    double moved = 0, total = 0;
    if (std::sscanf(line.c_str(), "%lf of %lf vertices moved", &moved, &total) == 2)
      out.push_back({moved, total});
  }
  return out;
}

// How far the pulled point moves vertex x: N_4(s) N_2(t) N_4(u) |pull| (the lab's
// (i, j, k) = (4, 2, 4)) for the basis `basis` of 5 points, (s, t, u) in the lab's box
// [-3.3, 3.7] x [-2.3, 2.3] x [-0.2, 3.4]; the lab's pull is (1.6, 0, 0.5), its largest
// coordinate 1.6.
template <typename Basis>
double displacement(const float* x, Basis basis) {
  const double s = (x[0] + 3.3) / 7, t = (x[1] + 2.3) / 4.6, u = (x[2] + 0.2) / 3.6;
  return basis(4, s) * basis(2, t) * basis(4, u) * 1.6;
}

TEST(FreeFormDeformationLab, BernsteinMovesAlmostAllBsplineOnlyItsSupport) {
  ScratchDir dir("lab29");
  const auto counts = moved_counts(view_text(kLab, dir, "global_vs_local"));
  ASSERT_EQ(counts.size(), 2u);  // Bernstein, then B-spline
  const gllab::IndexedMesh teapot = gllab::deform::teapot_mesh(8);  // the lab's default
  ASSERT_EQ(counts[0][1], double(teapot.vertex_count()));
  namespace sp = gllab::spline;
  const std::vector<double> U = sp::clamped_uniform_knots(4, 3);  // 0 0 0 0 1/2 1 1 1 1
  const auto bernstein = [](int i, double w) { return sp::bernstein(i, 4, w); };
  const auto bspline = [&](int i, double w) { return sp::one_basis_fun(i, w, 3, U); };
  // The lab counts a vertex as moved when a coordinate changed by more than 1e-6. Every
  // vertex that the basis functions (A2.4 OneBasisFun, A1.2 Bernstein: not the volume's
  // evaluator) move by more than 1e-5 must be counted; none outside the B-spline point's
  // support s > 1/2, u > 1/2, where its basis functions are 0.
  double bernstein_sure = 0, bspline_sure = 0, support = 0;
  for (std::size_t v = 0; v < teapot.vertex_count(); ++v) {
    const float* x = &teapot.positions[3 * v];
    bernstein_sure += displacement(x, bernstein) > 1e-5;
    bspline_sure += displacement(x, bspline) > 1e-5;
    support += x[0] > 0.2f && x[2] > 1.6f;
  }
  EXPECT_GE(counts[0][0], bernstein_sure);
  EXPECT_GE(counts[1][0], bspline_sure);
  EXPECT_LE(counts[1][0], support);
  // Global against local: the Bernstein point moves most of the teapot, the B-spline point
  // a quarter of the box at most.
  EXPECT_GT(counts[0][0], 2 * counts[1][0]);
}

TEST(FreeFormDeformationLab, FaceNormalsConvergeToTheJacobiansNormals) {
  ScratchDir dir("lab29");
  std::vector<double> mean;
  for (const char* resolution : {"resolution=8", "resolution=16", "resolution=32"}) {
    const std::vector<std::string> text = view_text(kLab, dir, "normals", {resolution});
    // "N triangles: normals differ by D deg mean, M max": D is the number before " deg".
    double d = 0;
    for (const std::string& line : text)
      if (std::sscanf(line.c_str(), "%*d triangles: normals differ by %lf deg", &d) == 1) break;
    ASSERT_GT(d, 0) << resolution;
    mean.push_back(d);
  }
  // Halving the triangles' size at least halves the mean angle (first order, the least an
  // area-weighted average of face normals achieves on a smooth surface).
  EXPECT_LT(mean[1], mean[0] / 1.9);
  EXPECT_LT(mean[2], mean[1] / 1.9);
}

TEST(FreeFormDeformationLab, BendSqueezesTheTopAndStretchesTheBottom) {
  ScratchDir dir("lab29");
  double lo = 0, hi = 0;
  for (const std::string& line : view_text(kLab, dir, "volume_change"))
    if (std::sscanf(line.c_str(), "det J %lf .. %lf", &lo, &hi) == 2) break;
  // The arc keeps the box's middle at its length: above it shorter (det J < 1), below longer.
  EXPECT_LT(lo, 0.9);
  EXPECT_GT(hi, 1.1);
}

TEST(FreeFormDeformationLab, FoldViewReportsTheFoldAndFoldedVertices) {
  ScratchDir dir("lab29");
  const std::vector<std::string> text = view_text(kLab, dir, "fold");
  const std::vector<double> fold = numbers_after(text, "folds: det J ");
  ASSERT_EQ(fold.size(), 1u);
  EXPECT_LT(fold[0], 0);
  double lo = 1, hi = 0;
  for (const std::string& line : text)
    if (std::sscanf(line.c_str(), "det J %lf .. %lf", &lo, &hi) == 2) break;
  EXPECT_LT(lo, 0);  // the knob's vertices turn over
  // The other views' lattices do not fold: no warning there.
  for (const char* view : {"global_vs_local", "bend", "twist", "normals", "volume_change"})
    EXPECT_TRUE(numbers_after(view_text(kLab, dir, view), "folds: det J ").empty()) << view;
}

}  // namespace
