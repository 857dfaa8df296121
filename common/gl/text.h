// common/gl/text.h — text on screen, identical in a window and headless.
//
// GLUT's bitmap fonts live in libglut, which the headless programs must not
// link (it pulls in libGL; see DESIGN.md). So text is drawn with glBitmap from
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

}  // namespace gllab
