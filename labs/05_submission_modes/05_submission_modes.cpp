// lab 05 · four ways to submit a mesh                       difficulty: ★★☆☆
// One lit torus sent to OpenGL four ways, each written out below (lecture notes
// ch. 1, §1.3 Polygon rendering with OpenGL: "Direct rendering", "Display lists",
// "Vertex arrays", "Vertex buffer objects (VBO)"); bench/submission_bench times them.
// Notice: the four views are byte-identical (declared so): the same triangles give
//   the same pixels. Only the cost differs; the window's panel measures it live.
// Try: in the window press [+] up to 1M triangles. Which path keeps its
//   triangles/s? Then read the README: why is the gap ten times wider on a GPU?
// Keys: [+]/[-] mesh size x2 / /2
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: immediate, display_list, vertex_arrays, vbo
// Reference: reference_images/05_submission_modes__*.png

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/throughput.h"
#include "harness/lab.h"
#include "mesh/indexed_mesh.h"

using gllab::IndexedMesh;

// The four paths -------------------------------------------------------------
// In namespace lab05, not the anonymous one: bench/submission_bench.cpp links this
// file's object code (target 05_submission_modes_code) and times these functions.
// Every path draws the whole mesh as GL_TRIANGLES: the same colour, normal and
// position per vertex, in the same order.
namespace lab05 {
const void* offset(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

// 1. Immediate mode: three calls per vertex, for every vertex, every frame.
void draw_immediate(const IndexedMesh& m) {
  glBegin(GL_TRIANGLES);
  for (std::uint32_t i : m.indices) {
    glColor3fv(&m.colours[3 * i]);
    glNormal3fv(&m.normals[3 * i]);
    glVertex3fv(&m.positions[3 * i]);
  }
  glEnd();
}

// 2. Display list: the same calls recorded once (GL_COMPILE stores them
// without drawing); one glCallList a frame replays them.
GLuint compile_list(const IndexedMesh& m) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  draw_immediate(m);
  glEndList();
  return list;
}

// 3. Vertex arrays: pointers into our memory, read by GL at every draw;
// glDrawElements takes vertex indices[k] for k = 0, 1, ...
void draw_vertex_arrays(const IndexedMesh& m) {
  glEnableClientState(GL_VERTEX_ARRAY);  // client state: the arrays glDrawElements reads
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, m.positions.data());  // stride 0: tightly packed
  glNormalPointer(GL_FLOAT, 0, m.normals.data());
  glColorPointer(3, GL_FLOAT, 0, m.colours.data());
  glDrawElements(GL_TRIANGLES, GLsizei(m.indices.size()), GL_UNSIGNED_INT, m.indices.data());
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

// 4. VBO: the data goes into two buffer objects once, GL_STATIC_DRAW: the
// vertices interleaved (x y z nx ny nz r g b, 36 bytes each) and the indices.
void fill_buffers(const IndexedMesh& m, GLuint buffers[2]) {
  const std::vector<float> v = gllab::interleaved(m);
  glGenBuffers(2, buffers);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(float)), v.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.indices.size() * sizeof(std::uint32_t)),
               m.indices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

// With the buffers bound, the pointers are byte offsets into them, and so are the indices.
void draw_buffers(GLsizei index_count, const GLuint buffers[2]) {
  constexpr GLsizei kStride = 9 * sizeof(float);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glVertexPointer(3, GL_FLOAT, kStride, offset(0));
  glNormalPointer(GL_FLOAT, kStride, offset(3 * sizeof(float)));
  glColorPointer(3, GL_FLOAT, kStride, offset(6 * sizeof(float)));
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, offset(0));
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

// Path 0 to 3, the order of the views.
void draw(int path, const IndexedMesh& m, GLuint list, const GLuint buffers[2]) {
  if (path == 0) draw_immediate(m);
  if (path == 1) glCallList(list);
  if (path == 2) draw_vertex_arrays(m);
  if (path == 3) draw_buffers(GLsizei(m.indices.size()), buffers);
}

// What compile_list and fill_buffers made (GL ignores the names 0).
void release(GLuint list, const GLuint buffers[2]) {
  glDeleteLists(list, 1);
  glDeleteBuffers(2, buffers);
}

// The scene every view draws the torus in (and the bench times it in).
void set_up_scene(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 1.7, 1.7);
  gllab::enable_headlight();
  gllab::apply_orbit(s);  // right-drag, wheel, [0]: the camera (common/gl/scene.h)
  glTranslatef(0.f, -0.15f, 0.f);
  glRotatef(-55.f, 1.f, 0.f, 0.f);
  glRotated(12 * s.time, 0, 0, 1);  // 12 degrees a second: the window's frames keep coming
}
}  // namespace lab05

namespace {
// The torus at the current size and what the list and VBO paths made of it,
// a cache keyed by the size: a new size releases the old list and buffers.
struct Torus {
  std::size_t asked = 0;  // 2^size_log2 triangles, asked of torus_with_triangles
  IndexedMesh mesh;
  GLuint list = 0, buffers[2] = {0, 0};
} g_torus;

gllab::Throughput g_rate({"immediate", "display list", "vertex arrays", "VBO"});  // window only

const Torus& torus(const gllab::State& s) {
  const std::size_t asked = std::size_t{1} << s.integer("size_log2");
  if (g_torus.asked == asked) return g_torus;
  lab05::release(g_torus.list, g_torus.buffers);
  g_torus.asked = asked;
  g_torus.mesh = gllab::torus_with_triangles(asked);
  g_torus.list = lab05::compile_list(g_torus.mesh);
  lab05::fill_buffers(g_torus.mesh, g_torus.buffers);
  g_rate.reset();
  return g_torus;
}

void shutdown() { lab05::release(g_torus.list, g_torus.buffers); g_torus = {}; }

// Drawing -------------------------------------------------------------------
// The same scene and panel for every path: the four images compare byte for byte.
void draw_path_view(const gllab::State& s, int path) {
  const Torus& t = torus(s);
  const IndexedMesh& m = t.mesh;
  lab05::set_up_scene(s);
  // Window only: time one path a frame (round-robin) before this frame draws.
  const auto timed = [&t](int p) { lab05::draw(p, t.mesh, t.list, t.buffers); };
  if (s.interactive) g_rate.measure_next(timed, m.triangle_count());
  lab05::draw(path, m, t.list, t.buffers);
  using gllab::with_commas;
  const std::string vertices = with_commas(m.vertex_count()) + " vertices";
  gllab::draw_text_panel(8, 8, {with_commas(m.triangle_count()) + " triangles, " + vertices,
                                with_commas(m.indices.size()) + " indices, 3 per triangle"},
                         {0.9f, 0.95f, 1.f});
  if (s.interactive && g_rate.complete()) g_rate.draw_table(path, s.height);
}

void immediate_view(const gllab::State& s) { draw_path_view(s, 0); }
void display_list_view(const gllab::State& s) { draw_path_view(s, 1); }
void vertex_arrays_view(const gllab::State& s) { draw_path_view(s, 2); }
void vbo_view(const gllab::State& s) { draw_path_view(s, 3); }

// init ----------------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "05_submission_modes", "lab 05 · four ways to submit a mesh",
      {{"immediate", "glBegin/glColor/glNormal/glVertex/glEnd each frame", immediate_view, kOrbit},
       {"display_list", "the same calls compiled once", display_list_view, kOrbit, "immediate"},
       {"vertex_arrays", "client arrays, glDrawElements", vertex_arrays_view, kOrbit, "immediate"},
       {"vbo", "interleaved + element buffer, filled once", vbo_view, kOrbit, "immediate"}},
      {{"size_log2", 14, 10, 20, "about 2^size_log2 triangles (10: 1k .. 20: 1M)"}},
      {{'+', "mesh size x2 (up to 1M)", "size_log2", +1}, {'-', "mesh size /2", "size_log2", -1}},
      init};
  lab.animated = true;  // the views read State::time: the window's timings stay live
  lab.shutdown = shutdown;  // the list and buffers, while the context is current
  return lab;
}
