// common/gl/text.cpp — a PSF1 console font drawn with glBitmap.
#include "gl/text.h"

#include <cstdio>

#include <zlib.h>

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <array>
#include <cstdarg>
#include <cstdio>
#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>

#include "gl/gl.h"
#include "harness/lab.h"

namespace gllab {

namespace {

// PSF1 layout (Linux kbd documentation, psffontdata): 2 magic bytes 0x36 0x04,
// a mode byte (bit 0: 512 glyphs, bits 1-2: a Unicode table follows), the
// glyph height in bytes; then the glyphs, one byte per row, top row first,
// most significant bit leftmost; then per glyph a list of little-endian UCS-2
// code points ended by 0xFFFF (0xFFFE starts multi-character sequences).
struct Font {
  int glyph_count = 0;
  int height = 0;
  std::vector<std::uint8_t> rows_bottom_up;  // per glyph, flipped for glBitmap
  std::map<std::uint32_t, int> glyph_of;     // code point -> glyph index
};

std::vector<std::uint8_t> read_gzip(const char* path) {
  gzFile f = gzopen(path, "rb");
  if (!f) throw std::runtime_error(std::string("font: cannot open '") + path +
                                   "' (install the Debian package console-setup-linux)");
  std::vector<std::uint8_t> data;
  std::array<std::uint8_t, 16384> chunk{};
  int n = 0;
  while ((n = gzread(f, chunk.data(), static_cast<unsigned>(chunk.size()))) > 0)
    data.insert(data.end(), chunk.begin(), chunk.begin() + n);
  const bool failed = n < 0;
  gzclose(f);
  if (failed) throw std::runtime_error(std::string("font: '") + path + "' is not valid gzip");
  return data;
}

Font load_psf1(const char* path) {
  const std::vector<std::uint8_t> d = read_gzip(path);
  if (d.size() < 4 || d[0] != 0x36 || d[1] != 0x04)
    throw std::runtime_error(std::string("font: '") + path + "' is not a PSF1 font");
  Font font;
  font.glyph_count = (d[2] & 0x01) ? 512 : 256;
  font.height = d[3];
  const std::size_t glyph_bytes = static_cast<std::size_t>(font.glyph_count) * font.height;
  if (font.height != kGlyphHeight || d.size() < 4 + glyph_bytes)
    throw std::runtime_error(std::string("font: '") + path + "' is truncated or not 8x16");
  font.rows_bottom_up.resize(glyph_bytes);
  for (int g = 0; g < font.glyph_count; ++g)
    for (int row = 0; row < font.height; ++row)
      font.rows_bottom_up[g * font.height + (font.height - 1 - row)] = d[4 + g * font.height + row];

  std::size_t at = 4 + glyph_bytes;
  const bool has_table = (d[2] & 0x06) != 0;
  for (int g = 0; has_table && g < font.glyph_count && at + 1 < d.size(); ++g) {
    bool in_sequence = false;
    for (; at + 1 < d.size(); at += 2) {
      const std::uint32_t u = d[at] | (d[at + 1] << 8);
      if (u == 0xFFFF) { at += 2; break; }
      if (u == 0xFFFE) in_sequence = true;
      else if (!in_sequence) font.glyph_of.emplace(u, g);
    }
  }
  if (font.glyph_of.empty())  // no table: the first 128 glyphs are ASCII
    for (std::uint32_t c = 0; c < 128; ++c) font.glyph_of[c] = static_cast<int>(c);
  return font;
}

// Loaded once; a missing font is reported as a frame error, not a crash.
const Font* font() {
  static std::unique_ptr<Font> loaded;
  static std::string error;
  if (!loaded && error.empty()) {
    try {
      loaded = std::make_unique<Font>(load_psf1(kFontPath));
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  if (!loaded) report_frame_error(error);
  return loaded.get();
}

// Decodes UTF-8; malformed bytes become U+FFFD.
std::vector<std::uint32_t> code_points(const std::string& s) {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    int extra = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xE ? 2 : (c >> 3) == 0x1E ? 3 : -1;
    const bool truncated = extra > 0 && i + static_cast<std::size_t>(extra) >= s.size();
    if (extra < 0 || truncated) {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    std::uint32_t u = extra == 0 ? c : c & (0x3F >> extra);
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const auto cc = static_cast<unsigned char>(s[i + k]);
      ok = ok && (cc >> 6) == 0x2;
      u = (u << 6) | (cc & 0x3F);
    }
    out.push_back(ok ? u : 0xFFFD);
    i += ok ? extra + 1 : 1;
  }
  return out;
}

// --print-text (text.h): the strings drawn while recording is on.
bool g_recording = false;
std::vector<std::string>& recorded() {
  static std::vector<std::string> lines;
  return lines;
}

void bitmap_text(int x, int y_top, int viewport_height, const std::string& utf8, Rgb c) {
  if (g_recording) recorded().push_back(utf8);
  const Font* f = font();
  if (!f) return;
  glColor3f(c.r, c.g, c.b);
  // glWindowPos takes the raster colour from the current colour; the bitmap's
  // origin is its bottom-left, so go down one glyph height from the top.
  glWindowPos2i(x, viewport_height - y_top - f->height);
  for (std::uint32_t u : code_points(utf8)) {
    auto it = f->glyph_of.find(u);
    if (it == f->glyph_of.end() && u == 0x222A) it = f->glyph_of.find('U');  // ∪: the font has ∩ only
    if (it == f->glyph_of.end()) it = f->glyph_of.find('?');
    const int g = it == f->glyph_of.end() ? 0 : it->second;
    glBitmap(kGlyphWidth, f->height, 0, 0, kGlyphWidth, 0, &f->rows_bottom_up[g * f->height]);
  }
}

}  // namespace

void record_text(bool on) { g_recording = on; }

std::vector<std::string> take_recorded_text() {
  std::vector<std::string> lines;
  lines.swap(recorded());
  return lines;
}

std::string fmt(const char* printf_format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, printf_format, value);
  return text;
}

int text_width(const std::string& utf8) {
  return kGlyphWidth * static_cast<int>(code_points(utf8).size());
}

void draw_text(int x, int y, const std::string& utf8, Rgb colour) {
  PixelSpace px;
  bitmap_text(x, y, px.height, utf8, colour);
}

std::string format_text(const char* format, ...) {
  va_list args, again;
  va_start(args, format);
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  std::string out(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(out.data(), out.size() + 1, format, again);
  va_end(again);
  return out;
}

PixelSpace::PixelSpace() {
  GLint vp[4];
  glGetIntegerv(GL_VIEWPORT, vp);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glOrtho(0, vp[2], 0, vp[3], -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_FOG);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  height = vp[3];
}

PixelSpace::~PixelSpace() {
  glMatrixMode(GL_MODELVIEW);
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glPopClientAttrib();
  glPopAttrib();
}

void draw_text_panel(int x, int y, const std::vector<std::string>& lines, Rgb colour) {
  draw_text_panel(x, y, lines, std::vector<Rgb>{colour});
}

void draw_text_panel(int x, int y, const std::vector<std::string>& lines, const std::vector<Rgb>& colours) {
  PixelSpace px;
  constexpr int kPad = 6;
  int w = 0;
  for (const std::string& l : lines) w = std::max(w, text_width(l));
  const int h = kGlyphHeight * static_cast<int>(lines.size());
  glEnable(GL_BLEND);
  // Blend colour only; keep the destination alpha. A window has no alpha
  // channel (reads back 255) while the headless buffer has one, so blending
  // alpha too would make the two runners' images differ under every panel.
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  glColor4f(0.f, 0.f, 0.f, 0.75f);
  const int top = px.height - y;
  glRecti(x, top - h - 2 * kPad, x + w + 2 * kPad, top);
  glDisable(GL_BLEND);
  for (std::size_t i = 0; i < lines.size(); ++i)
    bitmap_text(x + kPad, y + kPad + kGlyphHeight * static_cast<int>(i), px.height, lines[i],
                colours.empty() ? Rgb{1.f, 1.f, 1.f} : colours[std::min(i, colours.size() - 1)]);
}

}  // namespace gllab
