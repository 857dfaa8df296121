// tests/gl/glu_arrays_test.cpp — the spline core reads the arrays a lab hands
// GLU (common/gl/glu_arrays.h), and GluNurbsProperties::of reads back what a lab
// set with gluNurbsProperty. No GL context: these only convert and query.
// Expected values come from the arguments' meaning in the GLU 1.3 specification
// (gluNurbsCurve: count knots, stride floats between points, order, type;
// gluNurbsSurface: point (i, j) at ctl[i * s_stride + j * t_stride]; rational
// types hold (w x, w y, w z, w)) and from the GLU man pages' defaults.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/glu_arrays.h"
#include "gl/glu_nurbs.h"

namespace {

using gllab::spline::Vec2;
using gllab::spline::Vec3;

std::string message_of(void (*f)()) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

// A quarter circle as a rational quadratic, (w x, w y, w z, w) with the middle
// weight 1/2: the core gets the points divided back and the weights as they are.
TEST(GluArrays, RationalCurveIsDividedByItsWeights) {
  GLfloat knots[6] = {0, 0, 0, 1, 1, 1};
  GLfloat ctl[3][4] = {{1, 0, 0, 1}, {0.5f, 0.5f, 0, 0.5f}, {0, 1, 0, 1}};
  const gllab::spline::BsplineCurve c = gllab::core_curve(6, knots, 4, &ctl[0][0], 3, GL_MAP1_VERTEX_4);
  EXPECT_EQ(c.p, 2);
  ASSERT_EQ(c.P.size(), 3u);  // knot count - order
  EXPECT_EQ(c.P[1], (Vec3{1, 1, 0}));
  EXPECT_EQ(c.w, (std::vector<double>{1, 0.5, 1}));
  EXPECT_EQ(c.U, (std::vector<double>{0, 0, 0, 1, 1, 1}));
}

// A stride longer than a point skips the floats in between, as GLU does.
TEST(GluArrays, StrideSkipsFloatsBetweenPoints) {
  GLfloat knots[4] = {0, 0, 1, 1};
  GLfloat ctl[2][5] = {{1, 2, 3, -9, -9}, {4, 5, 6, -9, -9}};
  const gllab::spline::BsplineCurve c = gllab::core_curve(4, knots, 5, &ctl[0][0], 2, GL_MAP1_VERTEX_3);
  ASSERT_EQ(c.P.size(), 2u);
  EXPECT_EQ(c.P[1], (Vec3{4, 5, 6}));
  EXPECT_FALSE(c.rational());
}

// Point (i, j) at ctl[i * s_stride + j * t_stride]: swapping the strides reads
// the same array transposed.
TEST(GluArrays, SurfaceStridesPlaceEveryPoint) {
  GLfloat knots[4] = {0, 0, 1, 1};
  GLfloat ctl[2][2][3] = {{{0, 0, 1}, {0, 1, 2}}, {{1, 0, 3}, {1, 1, 4}}};
  const auto S = gllab::core_surface(4, knots, 4, knots, 2 * 3, 3, &ctl[0][0][0], 2, 2, GL_MAP2_VERTEX_3);
  ASSERT_EQ(S.P.size(), 4u);
  EXPECT_EQ(S.P[0 * 2 + 1], (Vec3{0, 1, 2}));  // P(0, 1): i along u (s), j along v (t)
  EXPECT_EQ(S.P[1 * 2 + 0], (Vec3{1, 0, 3}));
  const auto T = gllab::core_surface(4, knots, 4, knots, 3, 2 * 3, &ctl[0][0][0], 2, 2, GL_MAP2_VERTEX_3);
  EXPECT_EQ(T.P[0 * 2 + 1], (Vec3{1, 0, 3}));
}

TEST(GluArrays, TrimPiecesAndLoops) {
  GLfloat pwl[3][3] = {{0.5f, 0.5f, 1}, {1, 0.5f, 2}, {0.5f, 0.5f, 1}};  // (w u, w v, w)
  const gllab::spline::TrimPiece p = gllab::core_pwl(3, &pwl[0][0], 3, GLU_MAP1_TRIM_3);
  EXPECT_EQ(p.polyline, (std::vector<Vec2>{{0.5, 0.5}, {0.5, 0.25}, {0.5, 0.5}}));
  EXPECT_FALSE(p.curve);
  GLfloat knots[4] = {0, 0, 1, 1};
  std::vector<gllab::GluTrimLoop> loops = {{{GLU_MAP1_TRIM_2, {0, 0, 1, 0}, 2, 2, knots},
                                            {GLU_MAP1_TRIM_2, {1, 0, 1, 1, 0, 0}, 2}}};
  const std::vector<gllab::spline::TrimLoop> core = gllab::core_trims(loops);
  ASSERT_EQ(core.size(), 1u);
  ASSERT_EQ(core[0].pieces.size(), 2u);
  ASSERT_TRUE(core[0].pieces[0].curve);
  EXPECT_EQ(core[0].pieces[0].curve->P[1], (Vec3{1, 0, 0}));
  EXPECT_EQ(core[0].pieces[1].polyline.size(), 3u);
}

TEST(GluArrays, DensifiedPolylineHasPerEdgePointsOnEveryEdge) {
  const std::vector<GLfloat> d = gllab::densified_pwl({{0, 0}, {1, 0}, {1, 1}}, 4);
  // 2 edges x 4 points + the last one, evenly spaced: 0, 1/4, 1/2, 3/4 along each.
  EXPECT_EQ(d, (std::vector<GLfloat>{0, 0, .25f, 0, .5f, 0, .75f, 0, 1, 0, 1, .25f, 1, .5f, 1, .75f, 1, 1}));
  EXPECT_EQ(gllab::densified_pwl({{0, 0}, {1, 0}}, 1), (std::vector<GLfloat>{0, 0, 1, 0}));
}

TEST(GluArrays, CountsThatDoNotFitAreRefusedNamingThem) {
  EXPECT_EQ(message_of([] {
              GLfloat k[3] = {0, 0, 1}, c[3] = {0, 0, 0};
              gllab::core_curve(3, k, 3, c, 2, GL_MAP1_VERTEX_3);
            }),
            "gluNurbsCurve: knot_count 3 < 2 x order 2 (at least order control points)");
  EXPECT_EQ(message_of([] {
              GLfloat k[4] = {0, 0, 1, 1}, c[6] = {};
              gllab::core_curve(4, k, 2, c, 2, GL_MAP1_VERTEX_3);
            }),
            "gluNurbsCurve: stride 2 is shorter than one point (3 floats)");
  EXPECT_EQ(message_of([] {
              GLfloat p[2] = {0, 0};
              gllab::core_pwl(1, p, 2, GLU_MAP1_TRIM_2);
            }),
            "gluPwlCurve: count 1 < 2 (a polyline needs 2 points)");
}

// GluNurbsProperties::of reads a renderer's properties back: GLU's defaults
// for a new one (gluNurbsProperty(3G): GLU_PATH_LENGTH, 50 pixels, 0.5, 100
// steps, GLU_FILL, culling off, auto-load on), and what a lab set. Choosing an
// object-space method turns auto-load off (measured, docs/glu.md).
TEST(GluNurbsProperties, OfReadsBackWhatTheLabSet) {
  GLUnurbs* nurb = gluNewNurbsRenderer();
  ASSERT_NE(nurb, nullptr);
  gllab::GluNurbsProperties p = gllab::GluNurbsProperties::of(nurb);
  EXPECT_EQ(p.sampling_method, GLenum(GLU_PATH_LENGTH));
  EXPECT_EQ(p.sampling_tolerance, 50.f);
  EXPECT_EQ(p.parametric_tolerance, 0.5f);
  EXPECT_EQ(p.u_step, 100.f);
  EXPECT_EQ(p.display_mode, GLenum(GLU_FILL));
  EXPECT_FALSE(p.culling);
  EXPECT_TRUE(p.auto_load_matrix);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_OBJECT_PARAMETRIC_ERROR);
  gluNurbsProperty(nurb, GLU_PARAMETRIC_TOLERANCE, 0.03f);
  gluNurbsProperty(nurb, GLU_V_STEP, 8.f);
  p = gllab::GluNurbsProperties::of(nurb);
  EXPECT_EQ(p.sampling_method, GLenum(GLU_OBJECT_PARAMETRIC_ERROR));
  EXPECT_EQ(p.parametric_tolerance, 0.03f);
  EXPECT_EQ(p.v_step, 8.f);
  EXPECT_FALSE(p.auto_load_matrix);
  gluDeleteNurbsRenderer(nurb);
}

}  // namespace
