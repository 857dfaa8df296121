// common/gl/glut_shapes.cpp — what both glut shape back ends share: the
// canonical arguments and their text.
#include "gl/glut_shapes.h"
#include "gl/glut_shapes_args.h"

#include <cstdio>

namespace gllab {

GlutArgs glut_args(GlutShape shape) {
  switch (shape) {
    case GlutShape::kSphere: return {"Sphere", {0.9, 24, 12}, 3};
    case GlutShape::kCube: return {"Cube", {1.2}, 1};
    case GlutShape::kCone: return {"Cone", {0.7, 1.4, 24, 6}, 4};
    case GlutShape::kTorus: return {"Torus", {0.25, 0.65, 12, 24}, 4};
    case GlutShape::kTetrahedron: return {"Tetrahedron", {}, 0};
    case GlutShape::kOctahedron: return {"Octahedron", {}, 0};
    case GlutShape::kDodecahedron: return {"Dodecahedron", {}, 0};
    case GlutShape::kIcosahedron: return {"Icosahedron", {}, 0};
    case GlutShape::kTeapot: return {"Teapot", {0.6}, 1};
  }
  return {"?", {}, 0};
}

std::string glut_call_text(const std::string& name, bool solid, const double* args, int count) {
  std::string text = std::string(solid ? "glutSolid" : "glutWire") + name + "(";
  for (int i = 0; i < count; ++i) {
    char number[32];
    std::snprintf(number, sizeof number, "%s%g", i ? ", " : "", args[i]);
    text += number;
  }
  return text + ")";
}

std::string glut_call_text(GlutShape shape, bool solid) {
  const GlutArgs a = glut_args(shape);
  return glut_call_text(a.name, solid, a.args, a.count);
}

namespace {
FreeglutShapes g_freeglut;  // set once by the window runner, after glutInit
}  // namespace

void set_freeglut_shapes(const FreeglutShapes& drawers) { g_freeglut = drawers; }
const FreeglutShapes& freeglut_shapes() { return g_freeglut; }

}  // namespace gllab
