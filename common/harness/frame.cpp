// common/harness/frame.cpp
#include "harness/frame.h"

#include <algorithm>
#include <exception>
#include <sstream>
#include <stdexcept>

#include "gl/check.h"
#include "gl/gl.h"
#include "gl/text.h"

namespace gllab {

void draw_frame(const Lab& lab, const State& state) {
  glViewport(0, 0, state.width, state.height);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();

  // The depths to return to, whatever the view's draw left pushed.
  GLint modelview_depth = 0, projection_depth = 0, attrib_depth = 0;
  glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &modelview_depth);
  glGetIntegerv(GL_PROJECTION_STACK_DEPTH, &projection_depth);
  glGetIntegerv(GL_ATTRIB_STACK_DEPTH, &attrib_depth);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  try {
    state.current_view().draw(state);
  } catch (const std::exception& e) {
    // The spline core throws on bad input (two interpolation nodes dragged
    // onto one x): a frame error like a GL error, never a crash.
    report_frame_error(e.what());
  }
  for (GLint d = 0; glGetIntegerv(GL_ATTRIB_STACK_DEPTH, &d), d > attrib_depth;) glPopAttrib();
  glMatrixMode(GL_PROJECTION);
  for (GLint d = 0; glGetIntegerv(GL_PROJECTION_STACK_DEPTH, &d), d > projection_depth;) glPopMatrix();
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  for (GLint d = 0; glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &d), d > modelview_depth;) glPopMatrix();
  glPopMatrix();
  glPopClientAttrib();
  glPopAttrib();
  check_gl_errors("in the draw function of view '" + state.view() + "'");

  if (state.help) {
    draw_text_panel(8, 8, help_lines(lab, state), Rgb{1.f, 1.f, 0.85f});
    check_gl_errors("while drawing the help overlay");
  }
}

std::vector<std::string> help_lines(const Lab& lab, const State& state) {
  std::vector<std::string> lines;
  lines.push_back(lab.title);
  const View& v = state.views()[state.view_index()];
  lines.push_back("view " + std::to_string(state.view_index() + 1) + "/" +
                  std::to_string(state.views().size()) + ": " + v.name);
  lines.push_back("  " + v.what);
  lines.push_back("");
  lines.push_back("[v]/[V] next/previous view  [h] help");
  lines.push_back("[p] print headless command  [Esc] quit");
  if (v.orbit()) lines.push_back("[right-drag] turn  [wheel] zoom  [0] reset the camera");
  if (!lab.points.empty()) {
    std::string names;
    for (const PointList& l : lab.points) names += (names.empty() ? "" : ", ") + l.name;
    lines.push_back("[mouse] drag a point (" + names + ")");
  }
  if (lab.model) lines.push_back("[Ctrl+S] save it as " + lab.id + "__<view>.json");
  for (const Key& k : lab.keys) lines.push_back(std::string("[") + static_cast<char>(k.key) + "] " + k.what);
  if (!state.params().empty()) {
    lines.push_back("");
    std::ostringstream p;
    for (const Param& param : state.params()) {
      const std::string item = param.name + "=" + [&] {
        std::ostringstream n;
        n << param.value;
        return n.str();
      }();
      if (p.tellp() > 0 && static_cast<int>(p.tellp()) + 1 + static_cast<int>(item.size()) > 56) {
        lines.push_back(p.str());
        p.str("");
      }
      p << (p.tellp() > 0 ? " " : "") << item;
    }
    lines.push_back(p.str());
  }
  return lines;
}

namespace {

// Splits text at spaces into lines of at most `columns` characters (a word
// longer than that is cut). Errors are ASCII: one byte, one glyph.
std::vector<std::string> wrap(const std::string& text, std::size_t columns) {
  std::vector<std::string> lines;
  std::string rest = text;
  while (rest.size() > columns) {
    std::size_t cut = rest.rfind(' ', columns);
    if (cut == std::string::npos || cut == 0) cut = columns;
    lines.push_back(rest.substr(0, cut));
    rest = rest.substr(rest[cut] == ' ' ? cut + 1 : cut);
  }
  lines.push_back(rest);
  return lines;
}

}  // namespace

void draw_error_lines(const std::vector<std::string>& errors) {
  GLint vp[4];
  glGetIntegerv(GL_VIEWPORT, vp);
  // Wrap to the window, continuation lines indented, so no error runs off it.
  const std::size_t columns = static_cast<std::size_t>(std::max(16, (vp[2] - 32) / kGlyphWidth));
  std::vector<std::string> lines;
  for (const std::string& e : errors) {
    const std::vector<std::string> wrapped = wrap(e, columns);
    for (std::size_t i = 0; i < wrapped.size(); ++i) lines.push_back(i ? "  " + wrapped[i] : wrapped[i]);
  }
  const int y = vp[3] - 8 - (kGlyphHeight + 12) - kGlyphHeight * static_cast<int>(lines.size() - 1);
  draw_text_panel(8, y, lines, Rgb{1.f, 0.35f, 0.3f});
}

}  // namespace gllab
