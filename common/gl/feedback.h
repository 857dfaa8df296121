// common/gl/feedback.h — what a drawing sends to GL, read back.
//
// In feedback mode (glRenderMode(GL_FEEDBACK)) GL transforms, clips and
// shades vertices as usual but writes them into a buffer instead of drawing:
// the window coordinates a line strip really has, after float conversion and
// the matrices. Labs use it to compare what their own code sends with what a
// GL or GLU routine generates (an evaluator, a tessellator), vertex by vertex.
#pragma once

#include <functional>
#include <vector>

#include "spline/vec.h"

namespace gllab {

/// Runs draw(), which must send lines (GL_LINES, GL_LINE_STRIP, glEvalMesh1
/// with GL_LINE, ...), in feedback mode with room for max_segments segments,
/// and returns their vertices in window coordinates (x, y in pixels, z in
/// [0, 1]): the first vertex of the first segment, then the second vertex of
/// each segment (a strip's vertices in order). Nothing is drawn. Stops at
/// the first token that is not a line; a buffer too small reports a frame error.
std::vector<spline::Vec3> feedback_line_vertices(const std::function<void()>& draw, int max_segments);

}  // namespace gllab
