// common/gl/glut_shapes_args.h — internal to the glut shape back ends.
#pragma once

#include <string>

#include "gl/glut_shapes.h"

namespace gllab {

struct GlutArgs {
  const char* name;  // "Teapot": glutSolid<name> / glutWire<name>
  double args[4];
  int count;
};

GlutArgs glut_args(GlutShape shape);
std::string glut_call_text(const std::string& name, bool solid, const double* args, int count);

}  // namespace gllab
