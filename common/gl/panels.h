// common/gl/panels.h — a window split into equal panels side by side.
//
// Each panel gets its own viewport and scissor box, so what it draws stays in
// it, and GLU's screen-space sampling (GLU_PATH_LENGTH, GLU_PARAMETRIC_ERROR)
// measures the panel's own pixels. Two panels of the same size with the same
// projection rasterize the same scene to the same pixels, shifted by exactly
// the panel width (a test can compare them). Captions go in window pixels
// above or below a panel, after or between the panels' drawing.
//
//   const gllab::Panel left = gllab::enter_panel(0, 0, 2, 1, s.width, s.height);
//   gllab::ortho_fit(left.width, left.height, 3, 3);  ... draw ...
//   gllab::leave_panels(s.width, s.height);
//   gllab::draw_panel_caption(left, 0, "direct call", white);
#pragma once

#include <string>

#include "gl/text.h"

namespace gllab {

struct Panel {
  int x = 0, y = 0, width = 0, height = 0;  // glViewport of the panel (y from the window's bottom)
  int window_width = 0, window_height = 0;
};

/// Panel (col, row) of a cols x rows grid over a width x height window, row 0
/// at the top: sets its viewport and scissor box and enables GL_SCISSOR_TEST.
/// Columns and rows split the window in whole pixels (col * width / cols).
Panel enter_panel(int col, int row, int cols, int rows, int width, int height);

/// The whole window again: its viewport, scissor test off.
void leave_panels(int width, int height);

/// Text centred over the panel on text line `line`: line 0 is the first line
/// inside its top edge, line -1 the last line inside its bottom edge (-2 the
/// one above it, ...), white unless a colour is given. Drawn in window pixels whatever the current viewport
/// and scissor box; both are left as they were.
void draw_panel_caption(const Panel& panel, int line, const std::string& text, Rgb colour = {1.f, 1.f, 1.f});

}  // namespace gllab
