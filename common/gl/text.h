// common/gl/text.h — text on screen, identical in a window and headless.
//
// GLUT's bitmap fonts live in libglut, which the headless programs must not
// link (it pulls in libGL; see docs/platform.md). So text is drawn with glBitmap from
// a Linux console font (PSF1, 8x16 Terminus, Debian package console-setup-linux),
// which gives the same pixels under OSMesa and GLX.
#pragma once

#include <string>
#include <vector>

namespace gllab {

inline constexpr int kGlyphWidth = 8;
inline constexpr int kGlyphHeight = 16;
inline constexpr char kFontPath[] = "/usr/share/consolefonts/Lat15-Terminus16.psf.gz";

struct Rgb {
  float r, g, b;
};

/// Drawing in window pixels while it lives: the projection is the viewport in
/// pixels (x right, y up from its bottom-left corner), the model-view the
/// identity; lighting, depth test, culling and texturing off. Everything is
/// restored when it ends (matrices pushed and popped, attributes too).
class PixelSpace {
 public:
  PixelSpace();
  ~PixelSpace();
  PixelSpace(const PixelSpace&) = delete;
  PixelSpace& operator=(const PixelSpace&) = delete;
  int height = 0;  // of the viewport
};

/// Draws UTF-8 text with its top-left corner at window pixel (x, y), y counted
/// down from the top edge. Uses the current viewport size; changes no GL state
/// the caller can see. Code points the font lacks are drawn as '?'.
void draw_text(int x, int y, const std::string& utf8, Rgb colour);

/// A dark, translucent box with lines of text, top-left at (x, y) from the top.
void draw_text_panel(int x, int y, const std::vector<std::string>& lines, Rgb colour);
/// The same with a colour per line (a legend); lines beyond the colours get the last one.
void draw_text_panel(int x, int y, const std::vector<std::string>& lines, const std::vector<Rgb>& colours);

/// printf into a std::string, for labels and panels: format_text("k = %.2f", k).
std::string format_text(const char* format, ...) __attribute__((format(printf, 1, 2)));

/// Width in pixels of the text drawn by draw_text (one glyph per code point).
int text_width(const std::string& utf8);

/// One number in printf's notation, for labels: fmt("%.2e", 0.00127) is
/// "1.27e-03", fmt("%g steps", 32) is "32 steps" (at most 63 characters).
std::string fmt(const char* printf_format, double value);

/// While on, every string draw_text and draw_text_panel draw is also kept, in
/// order; take_recorded_text() hands them over and starts again. The headless
/// runner's --print-text prints them, so a test can read the numbers a view
/// shows on screen. Off by default (the window never records).
void record_text(bool on);
std::vector<std::string> take_recorded_text();

}  // namespace gllab
