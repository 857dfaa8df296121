// STUB until the recording replay lands (helper E replaces this file).
#include "gl/glut_shapes.h"
#include "gl/glut_shapes_args.h"
#include "harness/lab.h"

namespace gllab {

void draw_glut_shape(GlutShape shape, bool solid) {
  report_frame_error(glut_call_text(shape, solid) + ": glut shapes are not available headless yet");
}

void draw_glut_sphere(int slices, int stacks, bool solid) {
  const double args[] = {1.0, double(slices), double(stacks)};
  report_frame_error(glut_call_text("Sphere", solid, args, 3) + ": not available headless yet");
}

}  // namespace gllab
