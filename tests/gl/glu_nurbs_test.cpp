// tests/gl/glu_nurbs_test.cpp — the GLU NURBS wrapper (common/gl/glu_nurbs.h).
//
// Expected values come from GLU itself (read back with gluGetNurbsProperty,
// or measured and named as such), from the definition of a GLU property in
// the GLU 1.3 specification, or from a property of the data (a circle's
// points lie on the circle). Tests that must run without a GL context check
// that none is current first; the others make an OSMesa context for their
// own duration (harness/offscreen.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gl/glu_nurbs.h"
#include "harness/lab.h"
#include "harness/offscreen.h"
#include "nurbs_suite.h"
#include "spline/bspline.h"
#include "spline/nurbs.h"
#include "spline/surface.h"

namespace gllab {
namespace {

using spline::BsplineCurve;
using spline::BsplineSurface;
using spline::Vec2;
using spline::Vec3;

/// GLU returns floats: a float has a 24-bit mantissa (6e-8 relative); its
/// evaluation adds a few roundings. Relative to the size of the data.
constexpr double kFloatRounding = 1e-6;

GluNurbsProperties domain_distance(float steps) {
  GluNurbsProperties p;
  p.sampling_method = GLU_DOMAIN_DISTANCE;
  p.u_step = p.v_step = steps;
  return p;
}

const testing::SurfaceCase& suite_surface(const std::string& name) {
  static const std::vector<testing::SurfaceCase> suite = testing::surface_suite();
  return testing::surface_case(suite, name);
}
const testing::CurveCase& suite_curve(const std::string& name) {
  static const std::vector<testing::CurveCase> suite = testing::curve_suite();
  return testing::curve_case(suite, name);
}

float glu_property(const GluNurbs& glu, GLenum property) {
  GLfloat value = -1;
  gluGetNurbsProperty(glu.get(), property, &value);
  return value;
}

void expect_same_capture(const SurfaceCapture& a, const SurfaceCapture& b) {
  ASSERT_EQ(a.mesh.positions.size(), b.mesh.positions.size());
  ASSERT_EQ(a.mesh.triangles.size(), b.mesh.triangles.size());
  for (std::size_t k = 0; k < a.mesh.positions.size(); ++k) {
    ASSERT_EQ(a.mesh.positions[k], b.mesh.positions[k]) << "vertex " << k;
    ASSERT_EQ(a.mesh.normals[k], b.mesh.normals[k]) << "normal " << k;
    ASSERT_EQ(a.mesh.uv[k], b.mesh.uv[k]) << "uv " << k;
  }
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
}

// ---- properties ------------------------------------------------------------------

TEST(GluNurbsProperties, DefaultsAreGlusOwn) {
  // Expected: what a fresh GLU object reports (GLU 9.0.2).
  GLUnurbs* raw = gluNewNurbsRenderer();
  ASSERT_NE(raw, nullptr);
  const GluNurbsProperties p;
  const auto get = [&](GLenum property) {
    GLfloat v = -1;
    gluGetNurbsProperty(raw, property, &v);
    return v;
  };
  EXPECT_EQ(get(GLU_SAMPLING_METHOD), GLfloat(p.sampling_method));
  EXPECT_EQ(get(GLU_SAMPLING_TOLERANCE), p.sampling_tolerance);
  EXPECT_EQ(get(GLU_PARAMETRIC_TOLERANCE), p.parametric_tolerance);
  EXPECT_EQ(get(GLU_U_STEP), p.u_step);
  EXPECT_EQ(get(GLU_V_STEP), p.v_step);
  EXPECT_EQ(get(GLU_DISPLAY_MODE), GLfloat(p.display_mode));
  EXPECT_EQ(get(GLU_CULLING), p.culling ? 1.f : 0.f);
  EXPECT_EQ(get(GLU_AUTO_LOAD_MATRIX), p.auto_load_matrix ? 1.f : 0.f);
  gluDeleteNurbsRenderer(raw);
}

TEST(GluNurbsProperties, EveryFieldReachesGlu) {
  GluNurbsProperties p;
  p.sampling_method = GLU_PARAMETRIC_ERROR;
  p.sampling_tolerance = 7;
  p.parametric_tolerance = 0.25f;
  p.u_step = 12;
  p.v_step = 34;
  p.display_mode = GLU_OUTLINE_PATCH;
  p.culling = true;
  p.auto_load_matrix = false;
  p.sampling_matrices = SamplingMatrices{};
  const GluNurbs glu(p);
  EXPECT_TRUE(take_frame_errors().empty());
  EXPECT_EQ(glu_property(glu, GLU_SAMPLING_METHOD), GLfloat(GLU_PARAMETRIC_ERROR));
  EXPECT_EQ(glu_property(glu, GLU_SAMPLING_TOLERANCE), 7.f);
  EXPECT_EQ(glu_property(glu, GLU_PARAMETRIC_TOLERANCE), 0.25f);
  EXPECT_EQ(glu_property(glu, GLU_U_STEP), 12.f);
  EXPECT_EQ(glu_property(glu, GLU_V_STEP), 34.f);
  EXPECT_EQ(glu_property(glu, GLU_DISPLAY_MODE), GLfloat(GLU_OUTLINE_PATCH));
  EXPECT_EQ(glu_property(glu, GLU_CULLING), 1.f);
  EXPECT_EQ(glu_property(glu, GLU_AUTO_LOAD_MATRIX), 0.f);
}

TEST(GluNurbsProperties, ObjectSpaceMethodsRunWithAutoLoadOff) {
  // Measured: choosing GLU_OBJECT_* turns GLU_AUTO_LOAD_MATRIX off, and the
  // wrapper keeps it off even though the struct's default says on.
  for (GLenum method : {GLenum(GLU_OBJECT_PATH_LENGTH), GLenum(GLU_OBJECT_PARAMETRIC_ERROR)}) {
    GluNurbsProperties p;
    p.sampling_method = method;
    const GluNurbs glu(p);
    EXPECT_FALSE(glu.properties().auto_load_matrix) << glu_enum_name(method);
    EXPECT_EQ(glu_property(glu, GLU_AUTO_LOAD_MATRIX), 0.f) << glu_enum_name(method);
  }
  // And a screen-space method chosen after one gets auto-load back on.
  GluNurbsProperties object;
  object.sampling_method = GLU_OBJECT_PATH_LENGTH;
  GluNurbs glu(object);
  ASSERT_TRUE(glu.set(GluNurbsProperties{}));
  EXPECT_EQ(glu_property(glu, GLU_AUTO_LOAD_MATRIX), 1.f);
}

TEST(GluNurbsProperties, BadValuesAreRefusedWithOneLineAndChangeNothing) {
  struct Bad {
    void (*change)(GluNurbsProperties&);
    std::string message;
  };
  const Bad bad[] = {
      {[](GluNurbsProperties& p) { p.sampling_method = 12345; },
       "gluNurbsProperty: sampling_method=0x3039 is not GLU_PATH_LENGTH, GLU_PARAMETRIC_ERROR, GLU_DOMAIN_DISTANCE, "
       "GLU_OBJECT_PATH_LENGTH or GLU_OBJECT_PARAMETRIC_ERROR"},
      {[](GluNurbsProperties& p) { p.display_mode = GLU_FILL + 7; },
       "gluNurbsProperty: display_mode=0x186B3 is not GLU_FILL, GLU_OUTLINE_POLYGON or GLU_OUTLINE_PATCH"},
      {[](GluNurbsProperties& p) { p.sampling_tolerance = 0; },
       "gluNurbsProperty: sampling_tolerance=0 must be > 0 and finite"},
      {[](GluNurbsProperties& p) { p.parametric_tolerance = -0.5f; },
       "gluNurbsProperty: parametric_tolerance=-0.5 must be > 0 and finite"},
      {[](GluNurbsProperties& p) { p.u_step = NAN; }, "gluNurbsProperty: u_step=nan must be > 0 and finite"},
      {[](GluNurbsProperties& p) { p.v_step = INFINITY; }, "gluNurbsProperty: v_step=inf must be > 0 and finite"},
      {[](GluNurbsProperties& p) { p.auto_load_matrix = false; },
       "gluNurbsProperty: auto_load_matrix is off but no sampling_matrices are given (GLU_PATH_LENGTH needs them)"},
      {[](GluNurbsProperties& p) { p.sampling_matrices = SamplingMatrices{}; },
       "gluNurbsProperty: sampling_matrices given while auto_load_matrix is on (GLU would ignore them)"},
      {[](GluNurbsProperties& p) {
         p.sampling_method = GLU_OBJECT_PARAMETRIC_ERROR;
         p.culling = true;
       },
       "gluNurbsProperty: culling with GLU_OBJECT_PARAMETRIC_ERROR: object-space methods run without matrices, so "
       "GLU has no view volume to cull against"},
  };
  for (const Bad& b : bad) {
    GluNurbs glu(domain_distance(5));
    take_frame_errors();
    GluNurbsProperties p = domain_distance(5);
    p.sampling_method = GLU_PATH_LENGTH;
    b.change(p);
    EXPECT_FALSE(glu.set(p)) << b.message;
    EXPECT_EQ(take_frame_errors(), std::vector<std::string>{b.message});
    // Unchanged: still the DOMAIN_DISTANCE object of 5 steps.
    EXPECT_EQ(glu.properties().sampling_method, GLenum(GLU_DOMAIN_DISTANCE)) << b.message;
    EXPECT_EQ(glu_property(glu, GLU_U_STEP), 5.f) << b.message;
  }
}

// ---- errors ------------------------------------------------------------------------------

TEST(GluNurbsErrors, GluErrorsAreReportedWithNumberTextAndName) {
  BsplineCurve curve = suite_curve("cubic_clamped_3d").curve;
  curve.U = {0, 0, 0, 0, 0.5, 0.25, 0.75, 1, 1, 1, 1};  // decreasing at U[5]
  GluNurbs glu(domain_distance(10));
  take_frame_errors();
  const CurveCapture c = glu.capture_curve(curve, "bad knots");
  // GLU's own answer (measured, GLU 9.0.2): error 4, then 9 from gluEndCurve.
  ASSERT_EQ(c.errors.size(), 2u);
  EXPECT_EQ(c.errors[0].code, GLenum(GLU_NURBS_ERROR4));
  EXPECT_EQ(c.errors[0].nurbs_error, 4);
  EXPECT_EQ(c.errors[0].message, "gluNurbsCurve (bad knots): GLU NURBS error 4 (decreasing knot sequence knot)");
  EXPECT_EQ(c.errors[1].message,
            "gluNurbsCurve (bad knots): GLU NURBS error 9 (can't draw piecewise linear trimming curves)");
  EXPECT_EQ(c.vertex_count(), 0u);
  const std::vector<std::string> reported = take_frame_errors();
  ASSERT_EQ(reported.size(), 2u);
  EXPECT_EQ(reported[0], c.errors[0].message);
}

TEST(GluNurbsErrors, RepeatedErrorsAreReportedOnceWithACount) {
  // Two trim loops without pieces: GLU raises error 18 for each (measured).
  BsplineSurface s = suite_surface("bicubic_hill").surface;
  s.trims = {spline::TrimLoop{}, spline::TrimLoop{}};
  GluNurbs glu(domain_distance(10));
  take_frame_errors();
  const SurfaceCapture c = glu.capture_surface(s, "two empty loops");
  ASSERT_EQ(c.errors.size(), 1u);
  EXPECT_EQ(c.errors[0].message,
            "gluNurbsSurface (two empty loops): GLU NURBS error 18 (invalid or missing trim curve) (2 times)");
  EXPECT_EQ(take_frame_errors().size(), 1u);
}

// GLU's error callback takes only the error code: there is no
// GLU_NURBS_ERROR_DATA in GLU 9.0.2's glu.h, and a data callback registered
// under the enum after GLU_NURBS_END_DATA is never called. This is why the
// wrapper keeps its call in a thread-local (glu_nurbs.h).
int g_data_error_calls = 0;
void GLAPIENTRY count_data_error(GLenum, void*) { ++g_data_error_calls; }

TEST(GluNurbsErrors, GluHasNoErrorCallbackWithUserData) {
#ifdef GLU_NURBS_ERROR_DATA
  FAIL() << "glu.h defines GLU_NURBS_ERROR_DATA now: the wrapper could pass its call as user data";
#endif
  GLUnurbs* raw = gluNewNurbsRenderer();
  ASSERT_NE(raw, nullptr);
  gluNurbsProperty(raw, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
  gluNurbsCallback(raw, GLU_NURBS_END_DATA + 1, reinterpret_cast<_GLUfuncptr>(count_data_error));
  gluNurbsCallbackData(raw, &g_data_error_calls);
  GLfloat knots[] = {0, 0, 1};  // too few knots for order 2: error 2
  GLfloat ctrl[] = {0, 0, 0, 1, 0, 0};
  gluBeginCurve(raw);
  gluNurbsCurve(raw, 3, knots, 3, ctrl, 2, GL_MAP1_VERTEX_3);
  gluEndCurve(raw);
  gluDeleteNurbsRenderer(raw);
  EXPECT_EQ(g_data_error_calls, 0);
}

// ---- what the wrapper refuses (GLU would read past the arrays or crash) ---------------

TEST(GluNurbsRefusals, ShapesGluWouldReadPastNonFiniteValuesAndOpenTrimLoops) {
  GluNurbs glu(domain_distance(10));
  take_frame_errors();
  const BsplineCurve good = suite_curve("cubic_clamped_3d").curve;  // 7 points, 11 knots
  {
    BsplineCurve c = good;
    c.U.push_back(1);
    EXPECT_EQ(glu.capture_curve(c, "long knots").errors.at(0).message,
              "gluNurbsCurve (long knots): U has 12 knots: with order 4 GLU would read 8 control points, P has 7 "
              "(knots must be <= points + order = 11)");
  }
  {
    BsplineCurve c = good;
    c.w = {1, 2, 3};
    EXPECT_EQ(glu.capture_curve(c, "weights").errors.at(0).message,
              "gluNurbsCurve (weights): w has 3 weights for 7 control points");
  }
  {
    BsplineCurve c = good;
    c.P[2].y = NAN;
    EXPECT_EQ(glu.capture_curve(c, "nan").errors.at(0).message, "gluNurbsCurve (nan): P[2]=(3, nan, 0.5) is not finite");
  }
  {
    BsplineCurve c = good;
    c.P[1].x = 1e300;
    EXPECT_EQ(glu.capture_curve(c, "huge").errors.at(0).message,
              "gluNurbsCurve (huge): P[1]=(1e+300, 2, 0) is beyond float range (GLU takes floats)");
  }
  {
    BsplineSurface s = suite_surface("bicubic_hill").surface;
    s.P.pop_back();
    EXPECT_EQ(glu.capture_surface(s, "net").errors.at(0).message,
              "gluNurbsSurface (net): P has 24 points, nu x nv = 5 x 5 = 25");
  }
  {
    BsplineSurface s = suite_surface("bicubic_hill").surface;
    s.trims = {spline::TrimLoop{{spline::TrimPiece{{{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}}, std::nullopt}}}};
    EXPECT_EQ(glu.capture_surface(s, "open").errors.at(0).message,
              "gluNurbsSurface (open): trim loop 0: not closed: piece 0 ends at (0.9, 0.9), piece 0 starts at "
              "(0.1, 0.1) (not passed to GLU: it crashes on open loops and broken trim curves)");
  }
  EXPECT_EQ(take_frame_errors().size(), 6u);
}

TEST(GluNurbsRefusals, DrawingNeedsAContext) {
  ASSERT_FALSE(gl_context_current());
  GluNurbs glu(domain_distance(10));
  take_frame_errors();
  const std::vector<GluError> e = glu.draw_curve(suite_curve("nurbs_circle_2d").curve, "circle");
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].message,
            "gluNurbsCurve (circle): no GL context is current (drawing needs one; capture works without for "
            "GLU_DOMAIN_DISTANCE and the object-space methods)");
  EXPECT_EQ(take_frame_errors(), std::vector<std::string>{e[0].message});
}

TEST(GluNurbsRefusals, MovedFromObjectRefusesAndTheNewOneWorks) {
  GluNurbs a(domain_distance(10));
  GluNurbs b(std::move(a));
  take_frame_errors();
  const BsplineCurve& circle = suite_curve("nurbs_circle_2d").curve;
  EXPECT_EQ(a.capture_curve(circle, "old").errors.at(0).message,  // NOLINT(bugprone-use-after-move): on purpose
            "gluNurbsCurve (old): no GLU NURBS object (moved from, or gluNewNurbsRenderer failed)");
  EXPECT_TRUE(b.capture_curve(circle, "new").ok());
  GluNurbs c(domain_distance(3));
  c = std::move(b);
  EXPECT_EQ(c.properties().u_step, 10.f);
  EXPECT_TRUE(c.capture_curve(circle, "assigned").ok());
  take_frame_errors();
}

// ---- capture ---------------------------------------------------------------------------------

TEST(GluNurbsCapture, UntrimmedGridHasTwoTrianglesPerStepCell) {
  // GLU 1.3 spec, GLU_DOMAIN_DISTANCE: u_step, v_step sample points per unit
  // of parameter. The hill's domain is [0, 1]^2, so 4 steps each way give
  // 4 x 4 cells, 2 triangles each: 32. (GLU sends them as quad strips, one
  // strip per Bezier patch row: measured.)
  ASSERT_FALSE(gl_context_current());
  GluNurbs glu(domain_distance(4));
  const SurfaceCapture c = glu.capture_surface(suite_surface("bicubic_hill").surface, "hill");
  ASSERT_TRUE(c.ok());
  EXPECT_EQ(c.mesh.triangles.size(), 32u);
  EXPECT_EQ(c.count(GL_QUAD_STRIP), c.primitives.size());
  for (std::size_t k = 0; k < c.mesh.positions.size(); ++k) {
    EXPECT_NEAR(spline::norm(c.mesh.normals[k]), 1.0, kFloatRounding) << "normal " << k;
    EXPECT_GE(c.mesh.uv[k].x, 0.0);
    EXPECT_LE(c.mesh.uv[k].x, 1.0);
  }
}

TEST(GluNurbsCapture, SameVerticesWithAndWithoutAContext) {
  // The data-independent methods must not depend on GL state (docs/glu.md).
  const BsplineSurface& s = suite_surface("trimmed_nurbs_outer_disk").surface;
  GluNurbsProperties object;
  object.sampling_method = GLU_OBJECT_PARAMETRIC_ERROR;
  object.parametric_tolerance = 0.01f;
  ASSERT_FALSE(gl_context_current());
  GluNurbs glu(domain_distance(20));
  const SurfaceCapture without = glu.capture_surface(s, "disk");
  GluNurbs glu_object(object);
  const SurfaceCapture without_object = glu_object.capture_surface(s, "disk");
  const CurveCapture curve_without = glu.capture_curve(suite_curve("rational_quartic_3d").curve, "quartic");
  ASSERT_TRUE(without.ok() && without_object.ok() && curve_without.ok());
  ASSERT_GT(without.mesh.triangles.size(), 0u);
  ASSERT_GT(without_object.mesh.triangles.size(), 0u);

  OffscreenContext context(64, 64);
  ASSERT_TRUE(gl_context_current());
  glMatrixMode(GL_PROJECTION);
  glOrtho(-5, 5, -5, 5, -5, 5);  // some matrices, which must not matter
  glMatrixMode(GL_MODELVIEW);
  glRotated(30, 1, 0, 0);
  expect_same_capture(without, glu.capture_surface(s, "disk"));
  expect_same_capture(without_object, glu_object.capture_surface(s, "disk"));
  const CurveCapture curve_with = glu.capture_curve(suite_curve("rational_quartic_3d").curve, "quartic");
  ASSERT_EQ(curve_with.polylines.size(), curve_without.polylines.size());
  for (std::size_t k = 0; k < curve_with.polylines.size(); ++k)
    EXPECT_EQ(curve_with.polylines[k].points, curve_without.polylines[k].points);
}

TEST(GluNurbsCapture, ScreenSpaceSamplingWithoutContextIsRefused) {
  // Measured without the wrapper: GLU returned 14 vertices for the hill,
  // which needs hundreds, and no error.
  ASSERT_FALSE(gl_context_current());
  GluNurbs glu;  // GLU's default: GLU_PATH_LENGTH, auto-load on
  take_frame_errors();
  const SurfaceCapture c = glu.capture_surface(suite_surface("bicubic_hill").surface, "hill");
  ASSERT_EQ(c.errors.size(), 1u);
  EXPECT_EQ(c.errors[0].message,
            "gluNurbsSurface (hill): GLU_PATH_LENGTH samples in screen space and no GL context is current: GLU would "
            "read matrices that are not there and return wrong vertices without an error (use GLU_DOMAIN_DISTANCE or "
            "an object-space method, or auto_load_matrix = false with sampling_matrices)");
  EXPECT_TRUE(c.mesh.positions.empty());
  take_frame_errors();
}

TEST(GluNurbsCapture, ScreenSpaceSamplingWithGivenMatricesNeedsNoContext) {
  // The same GL_PATH_LENGTH tessellation twice: without a context from
  // matrices given by hand, and in a context from GL's own matrices (the
  // ones glOrtho(-1, 5, -1, 5, -5, 5) makes, written out: Red Book app. F).
  ASSERT_FALSE(gl_context_current());
  const BsplineSurface& hill = suite_surface("bicubic_hill").surface;
  SamplingMatrices m;
  m.modelview = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  m.projection = {1.f / 3, 0, 0, 0, 0, 1.f / 3, 0, 0, 0, 0, -0.2f, 0, -2.f / 3, -2.f / 3, 0, 1};
  m.viewport = {0, 0, 256, 256};
  GluNurbsProperties given;
  given.sampling_tolerance = 10;
  given.auto_load_matrix = false;
  given.sampling_matrices = m;
  GluNurbs glu_given(given);
  const SurfaceCapture without = glu_given.capture_surface(hill, "hill");
  ASSERT_TRUE(without.ok());

  OffscreenContext context(256, 256);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 5, -1, 5, -5, 5);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const SamplingMatrices from_gl = SamplingMatrices::from_gl();
  for (int k = 0; k < 16; ++k) EXPECT_NEAR(from_gl.projection[k], m.projection[k], 1e-7) << k;
  GluNurbsProperties automatic;
  automatic.sampling_tolerance = 10;
  GluNurbs glu_auto(automatic);
  const SurfaceCapture with = glu_auto.capture_surface(hill, "hill");
  ASSERT_TRUE(with.ok());
  EXPECT_GT(with.mesh.triangles.size(), 32u);
  expect_same_capture(without, with);
}

TEST(GluNurbsCapture, RationalCurveVerticesAreProjected) {
  // Curve vertices of a GL_MAP1_VERTEX_4 map arrive homogeneous; projected,
  // the circle's lie on it (The NURBS Book Ex. 7.2: an exact circle).
  GluNurbs glu(domain_distance(30));
  const CurveCapture c = glu.capture_curve(suite_curve("nurbs_circle_2d").curve, "circle");  // centre (1, 2), r 1.5
  ASSERT_TRUE(c.ok());
  ASSERT_GT(c.vertex_count(), 20u);
  for (const CapturedPolyline& line : c.polylines)
    for (std::size_t k = 0; k < line.points.size(); ++k) {
      const Vec3 p = line.points[k];
      EXPECT_NEAR(std::hypot(p.x - 1, p.y - 2), 1.5, 1.5 * kFloatRounding);
      EXPECT_EQ(p.z, 0.0) << "a 2D curve stays in z = 0";
      if (k > 0) {
        EXPECT_GT(line.u[k], line.u[k - 1]) << "u increases along a polyline";
      }
    }
}

TEST(GluNurbsCapture, NotPremultipliedIsTheCurveWithPointsOverWeights) {
  // The mistake: (x, y, z, w) read as (w x', w y', w z', w) gives x' = x / w,
  // the same weights: the curve with control points P_i / w_i.
  const BsplineCurve& circle = suite_curve("nurbs_circle_2d").curve;
  BsplineCurve what_glu_sees = circle;
  for (std::size_t i = 0; i < circle.P.size(); ++i) what_glu_sees.P[i] = circle.P[i] / circle.w[i];
  GluNurbs glu(domain_distance(30));
  const CurveCapture c = glu.capture_curve(circle, "circle", RationalFeed::kMistakeNotPremultiplied);
  ASSERT_TRUE(c.ok());
  double off_circle = 0;
  for (const CapturedPolyline& line : c.polylines)
    for (std::size_t k = 0; k < line.points.size(); ++k) {
      const Vec3 p = line.points[k];
      EXPECT_LE(spline::norm(p - spline::curve_point(what_glu_sees, line.u[k])), 4 * kFloatRounding);
      off_circle = std::max(off_circle, std::abs(std::hypot(p.x - 1, p.y - 2) - 1.5));
    }
  EXPECT_GT(off_circle, 0.1 * 1.5) << "the mistake must show";
}

TEST(GluNurbsCapture, TrianglesKeepTheSurfacesWinding) {
  // A flat patch in z = 0 with Su x Sv = +z: every triangle GLU emitted, made
  // from strips, fans and quad strips by GL's rules, winds counter-clockwise
  // seen from +z, and GLU's normals point to +z.
  GluNurbs glu(domain_distance(8));
  for (const std::string name : {"bilinear_flat_2d"}) {
    BsplineSurface flat = suite_surface(name).surface;
    flat.trims = suite_surface("trimmed_island_in_hole").surface.trims;  // fans and strips around trims
    const SurfaceCapture c = glu.capture_surface(flat, name);
    ASSERT_TRUE(c.ok());
    ASSERT_GT(c.count(GL_TRIANGLE_FAN) + c.count(GL_TRIANGLE_STRIP), 0u);
    for (const auto& t : c.mesh.triangles) {
      const Vec3 a = c.mesh.positions[t[0]], b = c.mesh.positions[t[1]], d = c.mesh.positions[t[2]];
      EXPECT_GE(spline::cross(b - a, d - a).z, 0.0);
    }
    for (const Vec3& n : c.mesh.normals) EXPECT_NEAR(n.z, 1.0, kFloatRounding);
  }
}

TEST(GluNurbsCapture, TriangleCountIsWhatGluEmitted) {
  // Counted from the primitives themselves: n - 2 per strip and fan,
  // 2 per quad of a quad strip, n / 3 for GL_TRIANGLES.
  GluNurbs glu(domain_distance(16));
  const SurfaceCapture c = glu.capture_surface(suite_surface("trimmed_hole_of_pieces").surface, "pieces");
  ASSERT_TRUE(c.ok());
  std::size_t expected = 0;
  for (const GluPrimitive& p : c.primitives) {
    if (p.mode == GL_TRIANGLE_STRIP || p.mode == GL_TRIANGLE_FAN || p.mode == GL_POLYGON) expected += p.count - 2;
    else if (p.mode == GL_QUAD_STRIP) expected += 2 * (p.count / 2 - 1);
    else if (p.mode == GL_TRIANGLES) expected += p.count / 3;
    else if (p.mode == GL_QUADS) expected += 2 * (p.count / 4);
  }
  EXPECT_EQ(c.mesh.triangles.size(), expected);
  EXPECT_GT(expected, 0u);
}

TEST(GluNurbsCapture, OutlinePatchGivesLinesOnTheSurface) {
  GluNurbsProperties p = domain_distance(8);
  p.display_mode = GLU_OUTLINE_PATCH;
  GluNurbs glu(p);
  const BsplineSurface& s = suite_surface("trimmed_nurbs_outer_disk").surface;
  const SurfaceCapture c = glu.capture_surface(s, "disk");
  ASSERT_TRUE(c.ok());
  EXPECT_TRUE(c.mesh.triangles.empty());
  ASSERT_FALSE(c.lines.empty());
  EXPECT_EQ(c.count(GL_LINE_STRIP), c.lines.size());  // measured: GLU sends line strips
}

TEST(GluNurbsCapture, OutlinePolygonCapturesTheSameTrianglesAsFill) {
  // Measured: in tessellator mode GLU sends the fill primitives for
  // GLU_OUTLINE_POLYGON too (drawing them as lines is the receiver's job).
  GluNurbsProperties p = domain_distance(8);
  GluNurbs fill(p);
  p.display_mode = GLU_OUTLINE_POLYGON;
  GluNurbs outline(p);
  const BsplineSurface& s = suite_surface("trimmed_polyline_hole").surface;
  expect_same_capture(fill.capture_surface(s, "fill"), outline.capture_surface(s, "outline"));
}

// ---- with a context ------------------------------------------------------------------------

TEST(GluNurbsDraw, DrawsAndCaptureLeavesTheEvaluatorsAsTheyWere) {
  OffscreenContext context(64, 64);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glOrtho(-1, 5, -1, 5, -5, 5);
  glMatrixMode(GL_MODELVIEW);
  GluNurbs glu(domain_distance(8));
  take_frame_errors();
  EXPECT_TRUE(glu.draw_surface(suite_surface("bicubic_hill").surface, "hill").empty());
  const Image img = context.read_pixels();
  long long lit = 0;
  for (std::size_t k = 0; k < img.rgba.size(); k += 4) lit += img.rgba[k] > 0;
  EXPECT_GT(lit, 64 * 64 / 10) << "the hill covers part of the frame";
  // Regression: GLU 9.0.2 enables the curve's maps in capture mode and leaves
  // them on; the wrapper restores them (a map left on wins over the next one).
  glu.capture_curve(suite_curve("rational_quartic_3d").curve, "quartic");
  EXPECT_FALSE(glIsEnabled(GL_MAP1_VERTEX_4));
  EXPECT_FALSE(glIsEnabled(GL_MAP1_VERTEX_3));
  EXPECT_FALSE(glIsEnabled(GL_MAP1_TEXTURE_COORD_1));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(GluNurbsDraw, CullingDropsWhatIsOutsideTheView) {
  OffscreenContext context(64, 64);
  glMatrixMode(GL_PROJECTION);
  glOrtho(-1, 5, -1, 5, -5, 5);
  glMatrixMode(GL_MODELVIEW);
  GluNurbsProperties p = domain_distance(8);
  p.culling = true;
  GluNurbs glu(p);
  const BsplineSurface& hill = suite_surface("bicubic_hill").surface;  // x, y in [0, 4]
  EXPECT_GT(glu.capture_surface(hill, "in view").mesh.triangles.size(), 0u);
  glTranslated(100, 0, 0);
  EXPECT_EQ(glu.capture_surface(hill, "out of view").mesh.triangles.size(), 0u);
}

}  // namespace
}  // namespace gllab
