// common/gl/panels.cpp — see panels.h.
#include "gl/panels.h"

#include "gl/gl.h"

namespace gllab {

Panel enter_panel(int col, int row, int cols, int rows, int width, int height) {
  Panel p;
  p.x = col * width / cols;
  p.width = (col + 1) * width / cols - p.x;
  const int top = row * height / rows;  // from the window's top edge
  p.height = (row + 1) * height / rows - top;
  p.y = height - top - p.height;
  p.window_width = width;
  p.window_height = height;
  glViewport(p.x, p.y, p.width, p.height);
  glScissor(p.x, p.y, p.width, p.height);
  glEnable(GL_SCISSOR_TEST);
  return p;
}

void leave_panels(int width, int height) {
  glViewport(0, 0, width, height);
  glDisable(GL_SCISSOR_TEST);
}

void draw_panel_caption(const Panel& panel, int line, const std::string& text, Rgb colour) {
  constexpr int kMargin = 4;  // pixels between the panel's edge and the text
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  glPushAttrib(GL_SCISSOR_BIT);
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, panel.window_width, panel.window_height);  // draw_text counts from the window's top
  const int panel_top = panel.window_height - panel.y - panel.height;
  const int top = line >= 0 ? panel_top + kMargin + line * kGlyphHeight
                            : panel_top + panel.height - kMargin + line * kGlyphHeight;
  draw_text(panel.x + (panel.width - text_width(text)) / 2, top, text, colour);
  glPopAttrib();
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
}

}  // namespace gllab
