// common/gl/glut_shapes_window.cpp — in a window the labs' glut shapes are freeglut's
// own calls (use_freeglut_shapes, after glutInit).
#include <GL/freeglut.h>

#include "gl/glut_shapes.h"
#include "gl/glut_shapes_args.h"

namespace gllab {

namespace {

void freeglut_shape(GlutShape shape, bool solid) {
  // Keep the GlutArgs alive: glut_args(shape).args would point into a
  // temporary that is gone before the switch reads it.
  const GlutArgs args = glut_args(shape);
  const double* a = args.args;
  switch (shape) {
    case GlutShape::kSphere:
      solid ? glutSolidSphere(a[0], int(a[1]), int(a[2])) : glutWireSphere(a[0], int(a[1]), int(a[2]));
      break;
    case GlutShape::kCube: solid ? glutSolidCube(a[0]) : glutWireCube(a[0]); break;
    case GlutShape::kCone:
      solid ? glutSolidCone(a[0], a[1], int(a[2]), int(a[3])) : glutWireCone(a[0], a[1], int(a[2]), int(a[3]));
      break;
    case GlutShape::kTorus:
      solid ? glutSolidTorus(a[0], a[1], int(a[2]), int(a[3])) : glutWireTorus(a[0], a[1], int(a[2]), int(a[3]));
      break;
    case GlutShape::kTetrahedron: solid ? glutSolidTetrahedron() : glutWireTetrahedron(); break;
    case GlutShape::kOctahedron: solid ? glutSolidOctahedron() : glutWireOctahedron(); break;
    case GlutShape::kDodecahedron: solid ? glutSolidDodecahedron() : glutWireDodecahedron(); break;
    case GlutShape::kIcosahedron: solid ? glutSolidIcosahedron() : glutWireIcosahedron(); break;
    case GlutShape::kTeapot: solid ? glutSolidTeapot(a[0]) : glutWireTeapot(a[0]); break;
  }
}

void freeglut_sphere(int slices, int stacks, bool solid) {
  solid ? glutSolidSphere(1.0, slices, stacks) : glutWireSphere(1.0, slices, stacks);
}

}  // namespace

void use_freeglut_shapes() { set_freeglut_shapes({freeglut_shape, freeglut_sphere}); }

}  // namespace gllab
