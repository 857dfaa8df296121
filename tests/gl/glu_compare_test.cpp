// tests/gl/glu_compare_test.cpp — common/gl/glu_compare.h: GLU's curve
// against the own core at GLU's own parameters, without a GL context
// (GLU_DOMAIN_DISTANCE in capture mode needs none: glu_nurbs.h).
#include "gl/glu_compare.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>

#include "spline/bspline.h"
#include "spline/nurbs.h"

namespace {

using gllab::compare_with_glu;
using gllab::GluCurveDifference;
using gllab::GluNurbs;
using gllab::RationalFeed;
using gllab::spline::BsplineCurve;
using gllab::spline::Vec3;

GluNurbs glu_with_steps(float u_step) {
  gllab::GluNurbsProperties p;
  p.sampling_method = GLU_DOMAIN_DISTANCE;
  p.u_step = u_step;
  return GluNurbs(p);
}

/// the cases A–D of the notes "B-Spline Polynomials": a cubic on 8 points, knot 4 of multiplicity mult
/// (as tests/spline/bspline_test.cpp builds them).
BsplineCurve lecture_case(int mult) {
  BsplineCurve c;
  c.p = 3;
  c.dimension = 2;
  c.P = {{0, 0, 0}, {1, 2, 0}, {2, 3, 0}, {3, 1, 0}, {5, 2, 0}, {6, 0, 0}, {7, 3, 0}, {8, 1, 0}};
  for (int i = 0; i < 4; ++i) c.U.push_back(i);
  for (int i = 0; i < mult; ++i) c.U.push_back(4);
  for (double v = 5; c.U.size() < 12; ++v) c.U.push_back(v);
  return c;
}

TEST(CompareWithGlu, LectureCasesAgreeToFloatPrecision) {
  for (int mult = 1; mult <= 4; ++mult) {
    GluNurbs glu = glu_with_steps(8);
    const GluCurveDifference d = compare_with_glu(glu, lecture_case(mult), "lecture case");
    ASSERT_TRUE(d.ok()) << "mult " << mult;
    // GLU_DOMAIN_DISTANCE: one strip per non-empty span (measured), and
    // the domain [3, 8 - (mult - 1)] has 5 - (mult - 1) of them.
    EXPECT_EQ(d.polylines, std::size_t(5 - (mult - 1))) << "mult " << mult;
    EXPECT_EQ(d.a, 3.0);
    EXPECT_EQ(d.b, 8.0 - (mult - 1));
    EXPECT_EQ(d.size, 8.0);  // the largest coordinate, x of P7
    EXPECT_LE(d.spacings(), gllab::kGluAgreement) << "mult " << mult << ": max " << d.max_distance;
    EXPECT_TRUE(d.agrees());
  }
}

// Case D: GLU ends the first piece at P3 and starts the second at P4, both
// at u = 4. Evaluated only from the right, the end of the first piece would
// be |P4 - P3| = |(2, 1)| = 2.24 away; compared with both sides it agrees.
TEST(CompareWithGlu, AtAGapBothOneSidedLimitsAreTried) {
  GluNurbs glu = glu_with_steps(8);
  const BsplineCurve c = lecture_case(4);
  const GluCurveDifference d = compare_with_glu(glu, c, "case D");
  ASSERT_TRUE(d.ok());
  int at_knot = 0;
  for (double u : d.u) at_knot += std::abs(u - 4) <= gllab::kGluKnotSnap * (d.b - d.a);
  EXPECT_EQ(at_knot, 2);  // the end of one strip and the start of the next
  EXPECT_TRUE(d.agrees()) << d.max_distance;
}

// Property: 200 random clamped curves, degree 1..5, every other one rational
// (weights 0.25..4), u_step 8..64: the measurement behind kGluAgreement.
TEST(CompareWithGlu, RandomCurvesAgreeWithinTheStatedSpacings) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-5, 5), weight(.25, 4);
  for (int t = 0; t < 200; ++t) {
    const int p = 1 + t % 5, n = p + 1 + t % 7;
    std::vector<Vec3> P;
    for (int i = 0; i <= n; ++i) P.push_back({coordinate(rng), coordinate(rng), 0});
    BsplineCurve c = gllab::spline::clamped_curve(P, p, 2);
    if (t % 2) {
      c.w.resize(P.size());
      for (double& w : c.w) w = weight(rng);
    }
    GluNurbs glu = glu_with_steps(float(8 << (t % 4)));
    const GluCurveDifference d = compare_with_glu(glu, c, "random curve");
    EXPECT_TRUE(d.agrees()) << "curve " << t << ": " << d.spacings() << " float spacings";
  }
}

// Negative checks: the measurement sees a wrong curve.
TEST(CompareWithGlu, AMovedControlPointIsSeen) {
  GluNurbs glu = glu_with_steps(8);
  const BsplineCurve c = lecture_case(1);
  BsplineCurve moved = c;
  moved.P[4].y += 0.08;  // 1 % of the size 8
  const GluCurveDifference d = compare_with_glu(glu, c, moved, "moved point");
  ASSERT_TRUE(d.ok());
  // At most 0.08 (the basis functions sum to 1), at least 0.08 N_4(5.5) =
  // 0.08 x 23/48 (the uniform cubic's B1(1/2)) wherever GLU samples near u = 5.5.
  EXPECT_LE(d.max_distance, 0.08 + 1e-6);
  EXPECT_GE(d.max_distance, 0.03);
  EXPECT_FALSE(d.agrees());
}

// The classic mistake on the exact circle (The NURBS Book §7.5): fed (x, y, w)
// GLU draws sum N_i P_i / sum N_i w_i. At u = 1/8 the arc's Bernstein weights
// are 1/4, 1/2, 1/4, so the point is (3/4, 3/4) R / (1/2 + sqrt(2)/4): radius
// 3 (sqrt 2 - 1) R = 1.2426 R, 0.2426 R off, radially. GLU's vertices near
// u = 1/8 come close to that.
TEST(CompareWithGlu, NotPremultipliedWeightsAreSeen) {
  GluNurbs glu = glu_with_steps(64);
  const BsplineCurve circle = gllab::spline::circle({}, 1.0);
  const GluCurveDifference right = compare_with_glu(glu, circle, "circle");
  const GluCurveDifference wrong = compare_with_glu(glu, circle, "circle", RationalFeed::kMistakeNotPremultiplied);
  EXPECT_TRUE(right.agrees()) << right.spacings();
  EXPECT_NEAR(wrong.max_distance, 3 * (std::sqrt(2.0) - 1) - 1, 0.01);
  EXPECT_FALSE(wrong.agrees());
}

TEST(CompareWithGlu, GluErrorsComeBackAndNothingIsMeasured) {
  GluNurbs glu = glu_with_steps(8);
  BsplineCurve c = lecture_case(1);
  c.U.push_back(13);  // one knot too many: the wrapper refuses (GLU would read past P)
  const GluCurveDifference d = compare_with_glu(glu, c, lecture_case(1), "too many knots");
  (void)gllab::take_frame_errors();
  EXPECT_FALSE(d.ok());
  EXPECT_TRUE(d.u.empty());
  EXPECT_FALSE(d.agrees());
}

}  // namespace
