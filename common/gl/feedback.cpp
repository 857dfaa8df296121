// common/gl/feedback.cpp — feedback.h.
#include "gl/feedback.h"

#include <string>

#include "gl/gl.h"
#include "harness/lab.h"

namespace gllab {

std::vector<spline::Vec3> feedback_line_vertices(const std::function<void()>& draw, int max_segments) {
  // GL_3D: each line is a token (GL_LINE_RESET_TOKEN after glBegin or a
  // stipple reset, else GL_LINE_TOKEN) and two vertices x, y, z: 7 floats.
  std::vector<GLfloat> buffer(7 * static_cast<std::size_t>(max_segments > 0 ? max_segments : 0) + 8);
  glFeedbackBuffer(static_cast<GLsizei>(buffer.size()), GL_3D, buffer.data());
  glRenderMode(GL_FEEDBACK);
  draw();
  const GLint used = glRenderMode(GL_RENDER);  // < 0: the buffer overflowed
  if (used < 0) report_frame_error("feedback: more than " + std::to_string(max_segments) + " line segments");
  std::vector<spline::Vec3> v;
  for (GLint i = 0; i + 7 <= used && (buffer[i] == GL_LINE_TOKEN || buffer[i] == GL_LINE_RESET_TOKEN); i += 7) {
    if (v.empty()) v.push_back({buffer[i + 1], buffer[i + 2], buffer[i + 3]});
    v.push_back({buffer[i + 4], buffer[i + 5], buffer[i + 6]});
  }
  return v;
}

}  // namespace gllab
