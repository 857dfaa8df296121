// tests/gl/glut_shapes_lab.cpp — a test-only lab that draws one glut shape
// call. It is built three times: a window program with real freeglut, a
// headless program with the replay of common/gl/glut_shapes.dat, and a window
// program with the replay. glut_shapes_test.cpp renders every recorded call
// with them and requires identical pixels.
//
// The shape is lit (normals matter), seen at an angle (depth test and back
// faces matter), and solid shapes are textured with a checkerboard, so the
// teapot's texture coordinates matter too.
#include <cmath>
#include <iterator>

#include "gl/gl.h"
#include "gl/glut_shapes.h"
#include "gl/scene.h"
#include "harness/lab.h"

namespace {

constexpr int kChecker = 8;  // texels per side of the checkerboard texture

void init() {
  GLubyte texels[kChecker][kChecker][3];
  for (int i = 0; i < kChecker; ++i)
    for (int j = 0; j < kChecker; ++j)
      for (int c = 0; c < 3; ++c) texels[i][j][c] = ((i + j) % 2) ? 255 : 120;
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, kChecker, kChecker, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

void draw(const gllab::State& s) {
  glClearColor(0.1f, 0.1f, 0.15f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gllab::ortho_fit(s.width, s.height, 1.2, 1.2);
  gllab::enable_headlight();
  glEnable(GL_DEPTH_TEST);
  const bool solid = s.flag("solid");
  if (solid) glEnable(GL_TEXTURE_2D);
  // Lit wire shapes z-fight: adjacent faces both draw their shared edge, each
  // with its own normal, and GLX and OSMesa settle such ties differently
  // (same data, same calls). depth=0 lets the draw order decide instead.
  if (!s.flag("depth")) glDisable(GL_DEPTH_TEST);
  glColor3f(0.95f, 0.7f, 0.3f);
  glRotated(-60, 1, 0, 0);
  glRotated(25, 0, 0, 1);
  const int stacks = s.integer("stacks");
  if (stacks > 0) {
    const int slices = s.integer("slices") > 0 ? s.integer("slices") : 2 * stacks;
    gllab::draw_glut_sphere(slices, stacks, solid);
    return;
  }
  const gllab::GlutShape shape = gllab::kGlutShapes[s.integer("shape")];
  // The dodecahedron has radius sqrt(3); the cone's base is at z = 0.
  if (shape == gllab::GlutShape::kDodecahedron) glScaled(1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0));
  if (shape == gllab::GlutShape::kCone) glTranslated(0, 0, -0.7);
  gllab::draw_glut_shape(shape, solid);
}

}  // namespace

gllab::Lab gllab::define_lab() {
  return {"glut_shapes_lab",
          "test fixture · glut shapes, window vs headless",
          {{"default", "one glut shape call, lit, solid ones textured", draw}},
          {{"shape", 0, 0, double(std::size(gllab::kGlutShapes) - 1), "index in kGlutShapes (canonical arguments)"},
           {"solid", 1, 0, 1, "glutSolid* (1) or glutWire* (0)"},
           {"stacks", 0, 0, 64, "0: the shape; else draw_glut_sphere(slices, stacks)"},
           {"slices", 0, 0, 128, "0: 2 * stacks"},
           {"depth", 1, 0, 1, "depth test on (1) or off (0)"}},
          {},
          init};
}
