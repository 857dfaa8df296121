// common/gl/glut_shapes_replay.cpp — glut shapes headless: freeglut's own GL
// calls, replayed.
//
// A headless render has no freeglut (glutInit needs an X display, and every
// glutSolid* call exits without it; in a window use_freeglut_shapes hands the
// shapes to freeglut itself). tools/glut_record ran freeglut
// under Xvfb and wrote down each GL call it made for every argument set the
// labs use, with the arrays it passed, into common/gl/glut_shapes.dat. That
// file is assembled into this object (.incbin below), and draw_glut_shape
// makes the same glEnableClientState / gl*Pointer / glDrawArrays /
// glDrawElements calls in the same order with the same floats and indices, so
// the pixels are those of freeglut (tests/gl/glut_shapes_test.cpp checks it
// for every recorded call). Design and how to re-record: common/gl/README.md.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/glut_shapes.h"
#include "gl/glut_shapes_args.h"
#include "harness/lab.h"

// The recording, bytes [begin, end). GLLAB_GLUT_SHAPES_DAT is its path
// (common/CMakeLists.txt, which also rebuilds this file when it changes).
__asm__(".pushsection .rodata\n"
        ".balign 16\n"
        "gllab_glut_shapes_dat_begin:\n"
        ".incbin \"" GLLAB_GLUT_SHAPES_DAT "\"\n"
        "gllab_glut_shapes_dat_end:\n"
        ".byte 0\n"  // so strtoul stops at the end
        ".popsection\n");
extern "C" const char gllab_glut_shapes_dat_begin[];
extern "C" const char gllab_glut_shapes_dat_end[];

namespace gllab {
namespace {

// One recorded GL call.
struct Event {
  enum Kind { kEnable, kDisable, kVertex, kNormal, kTexCoord, kDrawArrays, kDrawElements } kind;
  GLenum what = 0;   // the client array, or the primitive mode of a draw
  GLint size = 0;    // components per element (pointers)
  int array = -1;    // array id (pointers, glDrawElements)
  GLint first = 0;   // glDrawArrays
  GLsizei count = 0; // glDrawArrays
};

struct Recording {
  std::string source;  // the "# freeglut ..." header line
  std::map<std::string, std::vector<Event>> calls;
  std::vector<std::vector<GLfloat>> floats;     // by array id (empty if indices)
  std::vector<std::vector<GLushort>> indices;   // by array id (empty if floats)
  std::string error;   // non-empty when the embedded file could not be read
};

const std::pair<const char*, GLenum> kEnums[] = {
    {"GL_VERTEX_ARRAY", GL_VERTEX_ARRAY},
    {"GL_NORMAL_ARRAY", GL_NORMAL_ARRAY},
    {"GL_TEXTURE_COORD_ARRAY", GL_TEXTURE_COORD_ARRAY},
    {"GL_POINTS", GL_POINTS},
    {"GL_LINES", GL_LINES},
    {"GL_LINE_LOOP", GL_LINE_LOOP},
    {"GL_LINE_STRIP", GL_LINE_STRIP},
    {"GL_TRIANGLES", GL_TRIANGLES},
    {"GL_TRIANGLE_STRIP", GL_TRIANGLE_STRIP},
    {"GL_TRIANGLE_FAN", GL_TRIANGLE_FAN},
    {"GL_QUADS", GL_QUADS},
    {"GL_QUAD_STRIP", GL_QUAD_STRIP},
    {"GL_POLYGON", GL_POLYGON},
    {"GL_UNSIGNED_SHORT", GL_UNSIGNED_SHORT},
};

// Reads the text format tools/glut_record writes (common/gl/README.md).
class Parser {
 public:
  Parser(const char* begin, const char* end) : p_(begin), end_(end) {}

  Recording parse() {
    Recording r;
    if (line() != "gllab glut shapes 1") fail("the first line is not 'gllab glut shapes 1'");
    r.source = line();
    for (std::string word = token(); word != "eof"; word = token()) {
      if (word == "call") {
        const std::string call = line_rest();
        std::vector<Event>& events = r.calls[call];
        for (std::string w = token(); w != "end"; w = token()) events.push_back(event(w));
      } else if (word == "array") {
        const std::size_t id = array_id(token());
        if (id != r.floats.size()) fail("array a" + std::to_string(id) + " out of order");
        const std::string kind = token();
        const unsigned long n = number(token(), 10);
        r.floats.emplace_back();
        r.indices.emplace_back();
        for (unsigned long i = 0; i < n; ++i) {
          if (kind == "float") {
            const std::uint32_t bits = std::uint32_t(next_number(16));
            GLfloat f;
            std::memcpy(&f, &bits, sizeof f);
            r.floats.back().push_back(f);
          } else if (kind == "ushort") {
            r.indices.back().push_back(GLushort(next_number(10)));
          } else {
            fail("array kind '" + kind + "'");
          }
        }
      } else {
        fail("unexpected '" + word + "'");
      }
    }
    return r;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("common/gl/glut_shapes.dat: " + what);
  }
  void skip_space_and_comments() {
    while (p_ < end_) {
      if (*p_ == '#') {
        while (p_ < end_ && *p_ != '\n') ++p_;
      } else if (*p_ == ' ' || *p_ == '\n') {
        ++p_;
      } else {
        break;
      }
    }
  }
  std::string token() {
    skip_space_and_comments();
    const char* start = p_;
    while (p_ < end_ && *p_ != ' ' && *p_ != '\n') ++p_;
    if (start == p_) fail("ends early");
    return std::string(start, p_);
  }
  std::string line() {  // a whole line, comment or not
    const char* start = p_;
    while (p_ < end_ && *p_ != '\n') ++p_;
    std::string text(start, p_);
    if (p_ < end_) ++p_;
    return text;
  }
  std::string line_rest() {
    while (p_ < end_ && *p_ == ' ') ++p_;
    return line();
  }
  // The next token as a number, read in place (the arrays are most of the file).
  unsigned long next_number(int base) {
    skip_space_and_comments();
    char* stop = nullptr;
    const unsigned long n = std::strtoul(p_, &stop, base);
    if (p_ >= end_ || stop == p_ || stop > end_ || (stop < end_ && *stop != ' ' && *stop != '\n'))
      fail("bad number in an array");
    p_ = stop;
    return n;
  }
  unsigned long number(const std::string& text, int base) const {
    char* stop = nullptr;
    const unsigned long n = std::strtoul(text.c_str(), &stop, base);
    if (text.empty() || *stop != '\0') fail("'" + text + "' is not a number");
    return n;
  }
  std::size_t array_id(const std::string& text) const {
    if (text.size() < 2 || text[0] != 'a') fail("'" + text + "' is not an array id");
    return number(text.substr(1), 10);
  }
  GLenum enum_value(const std::string& name) const {
    for (const auto& [n, value] : kEnums)
      if (name == n) return value;
    fail("unknown GL enum " + name);
  }
  Event event(const std::string& word) {
    Event e{};
    if (word == "enable" || word == "disable") {
      e.kind = word == "enable" ? Event::kEnable : Event::kDisable;
      e.what = enum_value(token());
    } else if (word == "vertex" || word == "normal" || word == "texcoord") {
      e.kind = word == "vertex" ? Event::kVertex : word == "normal" ? Event::kNormal : Event::kTexCoord;
      e.size = GLint(number(token(), 10));
      e.array = int(array_id(token()));
    } else if (word == "arrays") {
      e.kind = Event::kDrawArrays;
      e.what = enum_value(token());
      e.first = GLint(number(token(), 10));
      e.count = GLsizei(number(token(), 10));
    } else if (word == "elements") {
      e.kind = Event::kDrawElements;
      e.what = enum_value(token());
      if (enum_value(token()) != GL_UNSIGNED_SHORT) fail("index type is not GL_UNSIGNED_SHORT");
      e.array = int(array_id(token()));
    } else {
      fail("unknown event '" + word + "'");
    }
    return e;
  }

  const char* p_;
  const char* end_;
};

// Every array a call names exists and has the right kind, and every draw stays
// inside the arrays it reads, so a damaged file cannot make GL read past them.
void check(const Recording& r, const std::string& call, const std::vector<Event>& events) {
  auto fail = [&](const std::string& what) {
    throw std::runtime_error("common/gl/glut_shapes.dat: " + call + ": " + what);
  };
  auto exists = [&](int id, bool floats) {
    if (id < 0 || std::size_t(id) >= r.floats.size()) fail("no array a" + std::to_string(id));
    if (floats ? r.indices[id].size() : r.floats[id].size()) fail("array a" + std::to_string(id) + " has the wrong kind");
  };
  std::map<GLenum, bool> enabled;
  std::map<GLenum, std::size_t> elements;  // per client array: elements in its pointer
  auto fits = [&](long last) {
    for (const auto& [array, on] : enabled) {
      if (!on) continue;
      if (!elements.count(array)) fail("a draw reads an array with no pointer");
      if (last >= 0 && std::size_t(last) >= elements[array]) fail("a draw reads past an array");
    }
  };
  for (const Event& e : events) {
    switch (e.kind) {
      case Event::kEnable: enabled[e.what] = true; break;
      case Event::kDisable: enabled[e.what] = false; break;
      case Event::kVertex:
      case Event::kNormal:
      case Event::kTexCoord: {
        exists(e.array, true);
        if (e.size < 1 || e.size > 4 || (e.kind == Event::kNormal && e.size != 3)) fail("bad size");
        const GLenum array = e.kind == Event::kVertex   ? GL_VERTEX_ARRAY
                             : e.kind == Event::kNormal ? GL_NORMAL_ARRAY
                                                        : GL_TEXTURE_COORD_ARRAY;
        elements[array] = r.floats[e.array].size() / std::size_t(e.size);
        break;
      }
      case Event::kDrawArrays: fits(long(e.first) + e.count - 1); break;
      case Event::kDrawElements: {
        exists(e.array, false);
        long last = -1;
        for (GLushort i : r.indices[e.array]) last = std::max(last, long(i));
        fits(last);
        break;
      }
    }
  }
}

const Recording& recording() {
  static const Recording r = [] {
    Recording parsed;
    try {
      parsed = Parser(gllab_glut_shapes_dat_begin, gllab_glut_shapes_dat_end).parse();
      for (const auto& [call, events] : parsed.calls) check(parsed, call, events);
    } catch (const std::exception& e) {
      parsed.calls.clear();
      parsed.error = e.what();
    }
    return parsed;
  }();
  return r;
}

// What is recorded besides the canonical calls, for the error message.
std::string recorded_spheres() {
  int lo = 0, hi = 0;
  for (int stacks = 1; stacks <= 256; ++stacks) {
    const double args[] = {1.0, double(2 * stacks), double(stacks)};
    if (recording().calls.count(glut_call_text("Sphere", true, args, 3))) {
      if (!lo) lo = stacks;
      hi = stacks;
    }
  }
  return lo ? "glut*Sphere(1, 2*stacks, stacks) for stacks " + std::to_string(lo) + ".." + std::to_string(hi)
            : "no radius-1 spheres";
}

void replay(const std::string& call) {
  const Recording& r = recording();
  if (!r.error.empty()) {
    report_frame_error(call + ": cannot replay glut shapes headless: " + r.error);
    return;
  }
  const auto found = r.calls.find(call);
  if (found == r.calls.end()) {
    report_frame_error(call + " is not recorded for headless replay; recorded: draw_glut_shape's " +
                       std::to_string(std::size(kGlutShapes)) + " shapes (solid and wire) and " +
                       recorded_spheres() + " (common/gl/README.md)");
    return;
  }
  for (const Event& e : found->second) {
    switch (e.kind) {
      case Event::kEnable: glEnableClientState(e.what); break;
      case Event::kDisable: glDisableClientState(e.what); break;
      case Event::kVertex: glVertexPointer(e.size, GL_FLOAT, 0, r.floats[e.array].data()); break;
      case Event::kNormal: glNormalPointer(GL_FLOAT, 0, r.floats[e.array].data()); break;
      case Event::kTexCoord: glTexCoordPointer(e.size, GL_FLOAT, 0, r.floats[e.array].data()); break;
      case Event::kDrawArrays: glDrawArrays(e.what, e.first, e.count); break;
      case Event::kDrawElements:
        glDrawElements(e.what, GLsizei(r.indices[e.array].size()), GL_UNSIGNED_SHORT, r.indices[e.array].data());
        break;
    }
  }
}

}  // namespace

void draw_glut_shape(GlutShape shape, bool solid) {
  if (freeglut_shapes().shape) return freeglut_shapes().shape(shape, solid);  // in a window
  replay(glut_call_text(shape, solid));
}

void draw_glut_sphere(int slices, int stacks, bool solid) {
  if (freeglut_shapes().sphere) return freeglut_shapes().sphere(slices, stacks, solid);
  const double args[] = {1.0, double(slices), double(stacks)};
  replay(glut_call_text("Sphere", solid, args, 3));
}

}  // namespace gllab
