// common/gl/glut_shapes.h — freeglut's glutSolid*/glutWire* shapes, in a window
// and headless.
//
// One lab program opens a window (freeglut) or renders headless (no freeglut:
// glutInit needs an X display, and without it every glutSolid* call exits with
// "called without first calling 'glutInit'"; EGL changes nothing there). So labs
// draw glut shapes through this header:
//   window:   the real freeglut call (glut_shapes_window.cpp), switched on by
//             the window runner after glutInit (use_freeglut_shapes)
//   headless: the same GL calls with the same arrays, replayed from what
//             freeglut itself sent, recorded by tools/glut_record
//             (glut_shapes_replay.cpp)
// Only recorded argument sets can be replayed; any other reports a frame error
// that names the call and the recorded sets.
#pragma once

#include <string>

namespace gllab {

enum class GlutShape {
  kSphere,
  kCube,
  kCone,
  kTorus,
  kTetrahedron,
  kOctahedron,
  kDodecahedron,
  kIcosahedron,
  kTeapot,
};

inline constexpr GlutShape kGlutShapes[] = {
    GlutShape::kSphere,      GlutShape::kCube,         GlutShape::kCone,
    GlutShape::kTorus,       GlutShape::kTetrahedron,  GlutShape::kOctahedron,
    GlutShape::kDodecahedron, GlutShape::kIcosahedron, GlutShape::kTeapot};

/// "glutSolidTeapot(0.6)" or "glutWireTorus(0.2, 0.6, 12, 24)": the call
/// draw_glut_shape makes.
std::string glut_call_text(GlutShape shape, bool solid);

/// Draws the shape with its canonical arguments, each fitting in a unit
/// sphere about the origin:
///   sphere (0.9, 24, 12), cube (1.2), cone (0.7, 1.4, 24, 6) base at z = 0,
///   torus (0.25, 0.65, 12, 24), tetrahedron/octahedron/icosahedron (unit),
///   dodecahedron (radius sqrt 3, so labs scale it), teapot (0.6).
void draw_glut_shape(GlutShape shape, bool solid);

/// glutSolidSphere/glutWireSphere(radius 1, slices, stacks) for comparing with
/// gluSphere. Recorded for stacks = 2..24 with slices = 2 * stacks.
void draw_glut_sphere(int slices, int stacks, bool solid);

/// The window runner calls this right after glutInit: from then on the
/// shapes are freeglut's own calls. Until then (always, headless) they are
/// replayed.
void use_freeglut_shapes();

/// Where use_freeglut_shapes leaves freeglut's drawing functions (both null
/// until it is called; glut_shapes.cpp keeps them, so the replay needs no freeglut).
struct FreeglutShapes {
  void (*shape)(GlutShape shape, bool solid) = nullptr;
  void (*sphere)(int slices, int stacks, bool solid) = nullptr;
};
void set_freeglut_shapes(const FreeglutShapes& drawers);
const FreeglutShapes& freeglut_shapes();

}  // namespace gllab
