// tests/gl/glu_nurbs_fixes_test.cpp — two things gllab::GluNurbs does about
// GLU 9.0.2 (common/gl/glu_nurbs.cpp):
//  - GLU finds a misoriented or crossing trim loop (NURBS error 28) but loses
//    the error on the way to its callback; the wrapper catches GLU's longjmp
//    and reports it ("errors GLU finds and then loses");
//  - the (u, v) of captured vertices come through a float texture map and
//    are clamped back into the domain, where the core can evaluate them.
//
// Capture mode with GLU_DOMAIN_DISTANCE needs no GL context (glu_nurbs.h).
// The surface is the bilinear-spaced bicubic plane x = 3u, y = 3v, z = 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <csetjmp>
#include <string>
#include <vector>

#include "gl/glu_nurbs.h"
#include "harness/lab.h"

namespace {

using gllab::spline::BsplineSurface;
using gllab::spline::TrimLoop;
using gllab::spline::Vec2;

// glu.h: GLU_NURBS_ERROR28 and gluErrorString's text for it.
constexpr int kMisoriented = 28;
const std::string kMisorientedText = "GLU NURBS error 28 (intersecting or misoriented trim curves)";

BsplineSurface plane_with(std::vector<TrimLoop> trims) {
  BsplineSurface s;
  s.p = s.q = 3;
  s.U = s.V = {0, 0, 0, 0, 1, 1, 1, 1};
  s.nu = s.nv = 4;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) s.P.push_back({double(i), double(j), 0});
  s.trims = std::move(trims);
  return s;
}

// A closed polyline loop through the points (the first repeated at the end).
TrimLoop loop(std::vector<Vec2> p) {
  p.push_back(p.front());
  return TrimLoop{{{p, std::nullopt}}};
}

gllab::SurfaceCapture capture(const BsplineSurface& s) {
  gllab::GluNurbsProperties p;
  p.sampling_method = GLU_DOMAIN_DISTANCE;
  p.u_step = p.v_step = 10;
  gllab::GluNurbs glu(p);
  gllab::SurfaceCapture c = glu.capture_surface(s, "plane");
  gllab::take_frame_errors();  // reported too; the capture's list is checked
  return c;
}

TEST(GluLostErrors, ClockwiseOuterLoopIsError28AndNothingIsDrawn) {
  const gllab::SurfaceCapture c = capture(plane_with({loop({{0.1, 0.1}, {0.1, 0.9}, {0.9, 0.9}, {0.9, 0.1}})}));
  ASSERT_EQ(c.errors.size(), 1u);
  EXPECT_EQ(c.errors[0].nurbs_error, kMisoriented);
  EXPECT_EQ(c.errors[0].message, "gluNurbsSurface (plane): " + kMisorientedText);
  EXPECT_EQ(c.mesh.positions.size(), 0u);
}

TEST(GluLostErrors, CrossingHolesAreError28) {
  const TrimLoop outer = loop({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const TrimLoop hole_a = loop({{0.2, 0.2}, {0.2, 0.6}, {0.6, 0.6}, {0.6, 0.2}});  // clockwise
  const TrimLoop hole_b = loop({{0.4, 0.4}, {0.4, 0.8}, {0.8, 0.8}, {0.8, 0.4}});  // clockwise, overlapping hole_a
  const gllab::SurfaceCapture c = capture(plane_with({outer, hole_a, hole_b}));
  ASSERT_EQ(c.errors.size(), 1u);
  EXPECT_EQ(c.errors[0].nurbs_error, kMisoriented);
}

// The negative check: the same loop counter-clockwise is a valid outer loop,
// GLU tessellates it and no error is invented (measured: 250 vertices).
TEST(GluLostErrors, CounterClockwiseOuterLoopRaisesNothing) {
  const gllab::SurfaceCapture c = capture(plane_with({loop({{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {0.1, 0.9}})}));
  EXPECT_TRUE(c.ok()) << c.errors.front().message;
  EXPECT_GT(c.mesh.triangles.size(), 0u);
}

// A jump through __longjmp_chk outside any GluNurbs call (here the test's
// own, the call a fortified longjmp makes) lands where glibc's would and
// records nothing. (The wrapper's definition, as glu_nurbs.cpp declares it.)
extern "C" [[noreturn]] void __longjmp_chk(void* env, int value);

TEST(GluLostErrors, OtherJumpsPassThroughUntouched) {
  std::jmp_buf where;
  volatile int landed = 0;
  if (const int value = setjmp(where); value == 0) __longjmp_chk(where, kMisoriented);
  else landed = value;
  EXPECT_EQ(landed, kMisoriented);
  EXPECT_TRUE(gllab::take_frame_errors().empty());
}

// At u = 1 the float map gave 1.0000000596 (measured), which the core's
// surface_evaluator refuses; clamped, every captured (u, v) lies in [0, 1]^2
// and can be evaluated.
TEST(GluCaptureUv, StaysInTheDomainAtItsEdges) {
  BsplineSurface s = plane_with({});
  for (int k = 0; k < 16; ++k) s.P[k].z = 0.1 * (k % 5);  // not flat, so nothing is exact by accident
  gllab::GluNurbsProperties p;
  p.sampling_method = GLU_DOMAIN_DISTANCE;
  p.u_step = p.v_step = 7;
  const gllab::SurfaceCapture c = gllab::GluNurbs(p).capture_surface(s, "plane");
  ASSERT_TRUE(c.ok());
  double u_max = 0, v_max = 0;
  for (const gllab::spline::Vec2& q : c.mesh.uv) {
    EXPECT_TRUE(q.x >= 0 && q.x <= 1 && q.y >= 0 && q.y <= 1) << q.x << ", " << q.y;
    u_max = std::max(u_max, q.x), v_max = std::max(v_max, q.y);
  }
  EXPECT_EQ(u_max, 1.0);  // the edge itself is reached
  EXPECT_EQ(v_max, 1.0);
}

}  // namespace
