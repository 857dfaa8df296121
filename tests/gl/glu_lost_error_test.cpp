// tests/gl/glu_lost_error_test.cpp — a lab's own GLU calls get GLU 9.0.2's lost
// trim errors too (common/gl/glu_errors.cpp): a clockwise outer loop makes GLU
// raise NURBS error 28 and jump out of gluEndSurface without calling the error
// callback (docs/glu.md); the longjmp is caught and the error reported as a
// frame error. A process of its own: GLU leaks on that path, so LeakSanitizer
// is turned off for this process at exit (glu_errors.cpp), and for no other test.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/glu_errors.h"
#include "harness/lab.h"

namespace {

int g_callback_calls = 0;
void GLAPIENTRY on_error(GLenum code) {
  ++g_callback_calls;
  gllab::report_glu_error(code, "test");
}

// The trimmed patch as a lab would write it, in tessellator mode (no context
// needed with GLU_DOMAIN_DISTANCE), the outer loop `clockwise` or not.
void draw(bool clockwise) {
  GLUnurbs* nurb = gluNewNurbsRenderer();
  gluNurbsCallback(nurb, GLU_NURBS_ERROR, reinterpret_cast<_GLUfuncptr>(on_error));
  gluNurbsProperty(nurb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  GLfloat knots[4] = {0, 0, 1, 1};
  GLfloat ctl[2][2][3] = {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}}};
  GLfloat ccw[5][2] = {{.2f, .2f}, {.8f, .2f}, {.8f, .8f}, {.2f, .8f}, {.2f, .2f}};
  GLfloat cw[5][2] = {{.2f, .2f}, {.2f, .8f}, {.8f, .8f}, {.8f, .2f}, {.2f, .2f}};
  gluBeginSurface(nurb);
  gluNurbsSurface(nurb, 4, knots, 4, knots, 2 * 3, 3, &ctl[0][0][0], 2, 2, GL_MAP2_VERTEX_3);
  gluBeginTrim(nurb);
  gluPwlCurve(nurb, 5, clockwise ? &cw[0][0] : &ccw[0][0], 2, GLU_MAP1_TRIM_2);
  gluEndTrim(nurb);
  gluEndSurface(nurb);
  gluDeleteNurbsRenderer(nurb);
}

TEST(GluLostError, AClockwiseOuterLoopInALabsOwnCallsIsReported) {
  draw(false);
  EXPECT_TRUE(gllab::take_frame_errors().empty()) << "a counter-clockwise loop is fine";
  draw(true);
  const std::vector<std::string> errors = gllab::take_frame_errors();
  ASSERT_FALSE(errors.empty());
  EXPECT_EQ(errors[0], "GLU NURBS error 28 (intersecting or misoriented trim curves), lost by GLU 9.0.2 "
                       "before its error callback");
  EXPECT_EQ(g_callback_calls, 0) << "GLU did call its callback: then the catch is not needed";
}

// report_glu_error's line: the number and gluErrorString's text.
TEST(GluLostError, ReportedErrorsNameTheCodeAndGlusText) {
  gllab::report_glu_error(GLU_NURBS_ERROR4, "hill");
  gllab::report_glu_error(GLU_INVALID_VALUE);
  const std::vector<std::string> errors = gllab::take_frame_errors();
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0], "hill: GLU NURBS error 4 (decreasing knot sequence knot)");
  EXPECT_EQ(errors[1], "GLU error GLU_INVALID_VALUE (invalid value)");
}

}  // namespace
