// tools/glut_record.cpp — records the GL calls freeglut makes for every glut
// shape call the labs use, into common/gl/glut_shapes.dat (common/gl/README.md).
//
//   xvfb-run -a -s "-screen 0 1024x768x24" build/bin/glut_record common/gl/glut_shapes.dat
//
// How: this executable defines the GL client-array entry points that libglut
// imports (glEnableClientState, glVertexPointer, glDrawElements, ...) and
// exports them (ENABLE_EXPORTS), so the dynamic linker resolves libglut's
// calls to them. Each one records the call, copies the arrays it reads, and
// forwards to the real GL function (dlsym RTLD_NEXT). Every other GL function
// libglut imports is wrapped too: if a shape call uses one, the recording
// fails, because the headless replay could not reproduce it.
//
// The shapes are drawn through gllab::draw_glut_shape / draw_glut_sphere
// (gl/glut_shapes_window.cpp, after use_freeglut_shapes): the very calls a lab makes in
// its window.
#include <GL/freeglut.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <dlfcn.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl/glut_shapes.h"
#include "gl/glut_shapes_args.h"

namespace {

// The GL enums a recording may contain, by name (the file is text).
const std::pair<GLenum, const char*> kEnumNames[] = {
    {GL_VERTEX_ARRAY, "GL_VERTEX_ARRAY"},
    {GL_NORMAL_ARRAY, "GL_NORMAL_ARRAY"},
    {GL_TEXTURE_COORD_ARRAY, "GL_TEXTURE_COORD_ARRAY"},
    {GL_POINTS, "GL_POINTS"},
    {GL_LINES, "GL_LINES"},
    {GL_LINE_LOOP, "GL_LINE_LOOP"},
    {GL_LINE_STRIP, "GL_LINE_STRIP"},
    {GL_TRIANGLES, "GL_TRIANGLES"},
    {GL_TRIANGLE_STRIP, "GL_TRIANGLE_STRIP"},
    {GL_TRIANGLE_FAN, "GL_TRIANGLE_FAN"},
    {GL_QUADS, "GL_QUADS"},
    {GL_QUAD_STRIP, "GL_QUAD_STRIP"},
    {GL_POLYGON, "GL_POLYGON"},
    {GL_UNSIGNED_SHORT, "GL_UNSIGNED_SHORT"},
};

std::string enum_name(GLenum e) {
  for (const auto& [value, name] : kEnumNames)
    if (value == e) return name;
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04x", e);
  throw std::runtime_error(std::string("GL enum ") + hex + " is not one the replay knows");
}

// A client array as set by gl*Pointer: where it is, and what was read from it.
struct Binding {
  GLenum array;         // GL_VERTEX_ARRAY, ...
  int size;             // components per element
  const float* data;    // freeglut's pointer, valid while the shape call runs
  std::vector<std::uint32_t> bits;  // float bits of elements 0..n-1 read so far
  int id = -1;          // array id once finished
};

// Everything recorded for one glut call, and the arrays of all calls.
struct Recorder {
  bool active = false;
  std::string error;                         // first problem in the current call
  std::vector<std::string> lines;            // the current call's events
  std::vector<std::unique_ptr<Binding>> bindings;  // of the current call
  std::map<GLenum, Binding*> current;        // array -> its latest binding
  std::map<GLenum, bool> enabled;            // client state as set in this call
  std::vector<std::string> arrays;           // array text by id (deduplicated)
  std::map<std::string, int> array_ids;
  std::size_t array_floats = 0, array_indices = 0;

  void fail(const std::string& what) {
    if (error.empty()) error = what;
  }

  int add_array(const std::string& kind, std::size_t count, const std::string& body) {
    const std::string key = kind + " " + std::to_string(count) + "\n" + body;
    auto [it, added] = array_ids.emplace(key, int(arrays.size()));
    if (added) {
      arrays.push_back(key);
      (kind == "float" ? array_floats : array_indices) += count;
    }
    return it->second;
  }

  // Copies elements [0, last] of every enabled array, checking that what was
  // copied by an earlier draw of this call has not changed since.
  void read_arrays(long last) {
    for (auto& [array, on] : enabled) {
      if (!on) continue;
      Binding* b = current.count(array) ? current[array] : nullptr;
      if (!b) {
        fail(enum_name(array) + " enabled without a pointer set in this call");
        continue;
      }
      const std::size_t want = std::size_t(last + 1) * std::size_t(b->size);
      for (std::size_t i = 0; i < want; ++i) {
        std::uint32_t w;
        std::memcpy(&w, b->data + i, sizeof w);
        if (i < b->bits.size()) {
          if (b->bits[i] != w) fail(enum_name(array) + " data changed between draws");
        } else {
          b->bits.push_back(w);
        }
      }
    }
  }

  void finish_bindings() {
    for (auto& b : bindings) {
      std::ostringstream body;
      char word[16];
      for (std::size_t i = 0; i < b->bits.size(); ++i) {
        std::snprintf(word, sizeof word, "%08x", b->bits[i]);
        body << word << ((i + 1) % 8 == 0 || i + 1 == b->bits.size() ? "\n" : " ");
      }
      b->id = add_array("float", b->bits.size(), body.str());
    }
  }
};

Recorder g_rec;

template <typename F>
F real(const char* name) {
  void* f = dlsym(RTLD_NEXT, name);
  if (!f) {
    std::fprintf(stderr, "glut_record: dlsym(RTLD_NEXT, %s) failed\n", name);
    std::exit(1);
  }
  return reinterpret_cast<F>(f);
}

// A pointer event whose array id is known only when the call ends.
std::string pointer_line(const char* what, const Binding* b) {
  return std::string(what) + " " + std::to_string(b->size) + " @" + std::to_string(reinterpret_cast<std::uintptr_t>(b));
}

void set_pointer(GLenum array, const char* what, int size, GLenum type, GLsizei stride, const void* p) {
  if (!g_rec.active) return;
  if (type != GL_FLOAT) g_rec.fail(std::string(what) + ": type is not GL_FLOAT");
  if (stride != 0) g_rec.fail(std::string(what) + ": stride " + std::to_string(stride) + " is not 0");
  GLint buffer = 0;
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &buffer);
  if (buffer != 0) g_rec.fail(std::string(what) + " with a GL_ARRAY_BUFFER bound");
  auto b = std::make_unique<Binding>();
  *b = Binding{array, size, static_cast<const float*>(p), {}, -1};
  g_rec.current[array] = b.get();
  g_rec.lines.push_back(pointer_line(what, b.get()));
  g_rec.bindings.push_back(std::move(b));
}

// Records one glut call: runs draw() with recording on and returns its text.
template <typename Draw>
std::string record_call(const std::string& call, Draw draw) {
  g_rec.active = true;
  g_rec.error.clear();
  g_rec.lines.clear();
  g_rec.bindings.clear();
  g_rec.current.clear();
  g_rec.enabled.clear();
  draw();
  g_rec.active = false;
  if (!g_rec.error.empty()) throw std::runtime_error(call + ": " + g_rec.error);
  for (auto& [array, on] : g_rec.enabled)
    if (on) throw std::runtime_error(call + ": leaves " + enum_name(array) + " enabled");
  g_rec.finish_bindings();
  std::string text = "call " + call + "\n";
  for (std::string line : g_rec.lines) {
    // Replace "@<binding address>" by "a<array id>".
    const std::size_t at = line.find('@');
    if (at != std::string::npos) {
      const auto* b = reinterpret_cast<const Binding*>(std::stoull(line.substr(at + 1)));
      line = line.substr(0, at) + "a" + std::to_string(b->id);
    }
    text += "  " + line + "\n";
  }
  return text + "end\n";
}

std::string package_version() {
  std::string version;
  if (FILE* p = popen("dpkg-query -W -f '${Version}' libglut3.12 2>/dev/null", "r")) {
    char buf[128];
    while (std::fgets(buf, sizeof buf, p)) version += buf;
    pclose(p);
  }
  return version.empty() ? "unknown" : version;
}

}  // namespace

// ---- the interposed GL entry points (exported from this executable) -------
extern "C" {

void glEnableClientState(GLenum array) {
  static auto f = real<void (*)(GLenum)>("glEnableClientState");
  if (g_rec.active) {
    g_rec.enabled[array] = true;
    try {
      g_rec.lines.push_back("enable " + enum_name(array));
    } catch (const std::exception& e) {
      g_rec.fail(e.what());
    }
  }
  f(array);
}

void glDisableClientState(GLenum array) {
  static auto f = real<void (*)(GLenum)>("glDisableClientState");
  if (g_rec.active) {
    g_rec.enabled[array] = false;
    try {
      g_rec.lines.push_back("disable " + enum_name(array));
    } catch (const std::exception& e) {
      g_rec.fail(e.what());
    }
  }
  f(array);
}

void glVertexPointer(GLint size, GLenum type, GLsizei stride, const void* p) {
  static auto f = real<void (*)(GLint, GLenum, GLsizei, const void*)>("glVertexPointer");
  set_pointer(GL_VERTEX_ARRAY, "vertex", size, type, stride, p);
  f(size, type, stride, p);
}

void glNormalPointer(GLenum type, GLsizei stride, const void* p) {
  static auto f = real<void (*)(GLenum, GLsizei, const void*)>("glNormalPointer");
  set_pointer(GL_NORMAL_ARRAY, "normal", 3, type, stride, p);
  f(type, stride, p);
}

void glTexCoordPointer(GLint size, GLenum type, GLsizei stride, const void* p) {
  static auto f = real<void (*)(GLint, GLenum, GLsizei, const void*)>("glTexCoordPointer");
  set_pointer(GL_TEXTURE_COORD_ARRAY, "texcoord", size, type, stride, p);
  f(size, type, stride, p);
}

void glDrawArrays(GLenum mode, GLint first, GLsizei count) {
  static auto f = real<void (*)(GLenum, GLint, GLsizei)>("glDrawArrays");
  if (g_rec.active) {
    try {
      g_rec.lines.push_back("arrays " + enum_name(mode) + " " + std::to_string(first) + " " +
                            std::to_string(count));
    } catch (const std::exception& e) {
      g_rec.fail(e.what());
    }
    if (count > 0) g_rec.read_arrays(long(first) + count - 1);
  }
  f(mode, first, count);
}

void glDrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
  static auto f = real<void (*)(GLenum, GLsizei, GLenum, const void*)>("glDrawElements");
  if (g_rec.active) {
    GLint buffer = 0;
    glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &buffer);
    if (buffer != 0) g_rec.fail("glDrawElements with a GL_ELEMENT_ARRAY_BUFFER bound");
    if (type != GL_UNSIGNED_SHORT) {
      g_rec.fail("glDrawElements: index type is not GL_UNSIGNED_SHORT");
    } else {
      const auto* idx = static_cast<const GLushort*>(indices);
      std::ostringstream body;
      long last = -1;
      for (GLsizei i = 0; i < count; ++i) {
        body << idx[i] << ((i + 1) % 16 == 0 || i + 1 == count ? "\n" : " ");
        last = std::max(last, long(idx[i]));
      }
      const int id = g_rec.add_array("ushort", std::size_t(count), body.str());
      try {
        g_rec.lines.push_back("elements " + enum_name(mode) + " " + enum_name(type) + " a" + std::to_string(id));
      } catch (const std::exception& e) {
        g_rec.fail(e.what());
      }
      if (last >= 0) g_rec.read_arrays(last);
    }
  }
  f(mode, count, type, indices);
}

// Every other GL function libglut imports that changes what is drawn
// (nm -D --undefined-only libglut.so.3.12). None may run inside a shape call.
#define GLLAB_GUARD(name, params, args)                                   \
  void name params {                                                      \
    static auto f = real<void(*) params>(#name);                          \
    if (g_rec.active) g_rec.fail(#name " is called (the replay does not reproduce it)"); \
    f args;                                                               \
  }
GLLAB_GUARD(glBegin, (GLenum a), (a))
GLLAB_GUARD(glEnd, (void), ())
GLLAB_GUARD(glVertex2f, (GLfloat a, GLfloat b), (a, b))
GLLAB_GUARD(glVertex2i, (GLint a, GLint b), (a, b))
GLLAB_GUARD(glColor4f, (GLfloat a, GLfloat b, GLfloat c, GLfloat d), (a, b, c, d))
GLLAB_GUARD(glColor4fv, (const GLfloat* a), (a))
GLLAB_GUARD(glDisable, (GLenum a), (a))
GLLAB_GUARD(glPushAttrib, (GLbitfield a), (a))
GLLAB_GUARD(glPopAttrib, (void), ())
GLLAB_GUARD(glPushClientAttrib, (GLbitfield a), (a))
GLLAB_GUARD(glPopClientAttrib, (void), ())
GLLAB_GUARD(glPushMatrix, (void), ())
GLLAB_GUARD(glPopMatrix, (void), ())
GLLAB_GUARD(glMatrixMode, (GLenum a), (a))
GLLAB_GUARD(glLoadIdentity, (void), ())
GLLAB_GUARD(glTranslatef, (GLfloat a, GLfloat b, GLfloat c), (a, b, c))
GLLAB_GUARD(glOrtho, (GLdouble a, GLdouble b, GLdouble c, GLdouble d, GLdouble e, GLdouble g), (a, b, c, d, e, g))
GLLAB_GUARD(glViewport, (GLint a, GLint b, GLsizei c, GLsizei d), (a, b, c, d))
GLLAB_GUARD(glBitmap, (GLsizei a, GLsizei b, GLfloat c, GLfloat d, GLfloat e, GLfloat g, const GLubyte* h),
            (a, b, c, d, e, g, h))
GLLAB_GUARD(glRasterPos2i, (GLint a, GLint b), (a, b))
GLLAB_GUARD(glPixelStorei, (GLenum a, GLint b), (a, b))
GLLAB_GUARD(glDrawBuffer, (GLenum a), (a))
GLLAB_GUARD(glReadBuffer, (GLenum a), (a))
GLLAB_GUARD(glFlush, (void), ())
#undef GLLAB_GUARD

// freeglut's OpenGL 2.0 path fetches its functions through here; it must not
// be taken (it is only taken after glutSetVertexAttribCoord3 and friends).
__GLXextFuncPtr glXGetProcAddressARB(const GLubyte* name) {
  static auto f = real<__GLXextFuncPtr (*)(const GLubyte*)>("glXGetProcAddressARB");
  if (g_rec.active) g_rec.fail(std::string("glXGetProcAddressARB(") + reinterpret_cast<const char*>(name) + ")");
  return f(name);
}

}  // extern "C"

int main(int argc, char** argv) {
  if (argc != 2 || argv[1][0] == '-') {
    std::fprintf(stderr,
                 "usage: xvfb-run -a -s \"-screen 0 1024x768x24\" glut_record OUT.dat\n"
                 "records freeglut's GL calls for the glut shapes (common/gl/README.md)\n");
    return 2;
  }
  Display* x = XOpenDisplay(nullptr);
  if (!x) {
    std::fprintf(stderr, "glut_record: no X display; run it under xvfb-run -a -s \"-screen 0 1024x768x24\"\n");
    return 2;
  }
  int glut_argc = 1;
  glutInit(&glut_argc, argv);
  gllab::use_freeglut_shapes();  // the shapes are freeglut's own calls, not the replay
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA | GLUT_DEPTH);
  glutInitWindowSize(64, 64);
  glutCreateWindow("glut_record");
  XCloseDisplay(x);

  try {
    std::vector<std::string> calls;
    for (bool solid : {true, false}) {
      for (gllab::GlutShape shape : gllab::kGlutShapes)
        calls.push_back(record_call(gllab::glut_call_text(shape, solid),
                                    [&] { gllab::draw_glut_shape(shape, solid); }));
      // draw_glut_sphere's set (glut_shapes.h).
      for (int stacks = 2; stacks <= 24; ++stacks) {
        const double args[] = {1.0, double(2 * stacks), double(stacks)};
        calls.push_back(record_call(gllab::glut_call_text("Sphere", solid, args, 3),
                                    [&] { gllab::draw_glut_sphere(2 * stacks, stacks, solid); }));
      }
    }
    std::ostringstream out;
    out << "gllab glut shapes 1\n"
        << "# freeglut " << glutGet(GLUT_VERSION) << " (package libglut3.12 " << package_version()
        << "), recorded by tools/glut_record; see common/gl/README.md\n"
        << "# " << calls.size() << " calls, " << g_rec.arrays.size() << " arrays ("
        << g_rec.array_floats << " floats, " << g_rec.array_indices << " indices)\n";
    for (const std::string& c : calls) out << c;
    for (std::size_t i = 0; i < g_rec.arrays.size(); ++i) out << "array a" << i << " " << g_rec.arrays[i];
    out << "eof\n";
    std::ofstream file(argv[1], std::ios::binary);
    file << out.str();
    file.close();
    if (!file) throw std::runtime_error(std::string("cannot write ") + argv[1]);
    std::printf("glut_record: %zu calls, %zu arrays (%zu floats, %zu indices) -> %s\n", calls.size(),
                g_rec.arrays.size(), g_rec.array_floats, g_rec.array_indices, argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "glut_record: %s\n", e.what());
    glutExit();
    return 1;
  }
  glutExit();
  return 0;
}
