// lab 05 · four ways to submit a mesh                       difficulty: ★★☆☆
// One lit torus sent to OpenGL four ways (seed §1.3): immediate mode, a
// display list, vertex arrays and a vertex buffer object. The four paths are
// in common/gl/submission.cpp (one definition, so bench/submission_bench times
// exactly what this lab draws); labs 01-04 teach each one.
// Notice: the four views are byte-identical (tests/labs checks it): the same
//   triangles give the same pixels. Only the cost differs, and the window's
//   panel measures it live for every path at the current mesh size.
// Try: in the window press [+] up to 1M triangles. Which path keeps its
//   triangles/s, which falls behind? Then read the README: why is the gap
//   ten times wider on a GPU?
// Keys: [+]/[-] mesh size x2 / /2  [h] help  [Esc] quit
// Views: immediate, display_list, vertex_arrays, vbo
// Reference: reference_images/05_submission_modes__*.png

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/submission.h"
#include "harness/lab.h"
#include "mesh/indexed_mesh.h"

namespace {

using gllab::Submit;

// Lab data (edit me) -------------------------------------------------------
constexpr double kSpinPerSecond = 12;   // degrees about the ring's axis, window only
constexpr double kMeasureSeconds = 0.02; // time one path per frame for at least this

// The mesh for the current size and the GL objects its list and VBO paths
// keep (common/gl/submission.cpp holds the four paths: read it beside this
// file). A new size releases the old objects.
struct Current {
  std::size_t asked = 0;  // 2^size_log2, the key of this cache
  gllab::SubmittedMesh mesh;
} g_current;

// Live measurements (window only): Mtri/s per path, for g_current.asked.
struct Throughput {
  double mtri_s[gllab::kSubmitPaths] = {0, 0, 0, 0};
  int next = 0, measured = 0;
} g_rate;

gllab::SubmittedMesh& mesh_for(std::size_t asked) {
  if (g_current.asked != asked) {
    g_current.mesh.release();
    g_current = Current{asked, gllab::SubmittedMesh(gllab::torus_with_triangles(asked))};
    g_rate = Throughput{};
  }
  return g_current.mesh;
}

void release() { g_current.mesh.release(); }

// Window only: time one path (round-robin, one per frame) with glFinish on
// both sides, so the time covers GL's work and not just the calls.
void measure_next_path(std::size_t asked) {
  const Submit path = Submit(g_rate.next);
  gllab::SubmittedMesh& mesh = mesh_for(asked);
  mesh.prepare(path);  // compiling the list or filling the buffers is not timed
  glFinish();
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  int draws = 0;
  double seconds = 0;
  do {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    mesh.draw(path);
    glFinish();
    ++draws;
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
  } while (seconds < kMeasureSeconds);
  g_rate.mtri_s[g_rate.next] = draws * double(mesh.mesh().triangle_count()) / seconds / 1e6;
  g_rate.next = (g_rate.next + 1) % gllab::kSubmitPaths;
  if (g_rate.measured < gllab::kSubmitPaths) ++g_rate.measured;
}

std::string with_commas(std::size_t n) {
  std::string digits = std::to_string(n);
  for (int k = int(digits.size()) - 3; k > 0; k -= 3) digits.insert(std::size_t(k), ",");
  return digits;
}

// init / display ----------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

void display(const gllab::State& s) {
  const std::size_t asked = std::size_t{1} << s.integer("size_log2");
  const Submit path = Submit(s.view_index());  // the views are the paths, in order
  gllab::ortho_fit(s.width, s.height, 1.7, 1.7);
  gllab::enable_headlight();
  glTranslatef(0.f, -0.15f, 0.f);
  glRotatef(-55.f, 1.f, 0.f, 0.f);
  glRotated(kSpinPerSecond * s.time, 0, 0, 1);  // the window's clock keeps the frames coming
  // Timings before the frame's own clear: they never reach its pixels, and a
  // frame shows them only once all four paths are measured.
  if (s.interactive) measure_next_path(asked);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  mesh_for(asked).draw(path);

  // The same panel for every path, so the four images can be compared byte for byte.
  const gllab::IndexedMesh& m = g_current.mesh.mesh();
  std::vector<std::string> lines = {
      with_commas(m.triangle_count()) + " triangles, " + with_commas(m.vertex_count()) + " vertices",
      with_commas(m.indices.size()) + " indices, 3 per triangle"};
  gllab::draw_text_panel(8, 8, lines, {0.9f, 0.95f, 1.f});
  if (s.interactive && g_rate.measured == gllab::kSubmitPaths) {
    lines = {"path            Mtri/s   / immediate"};
    for (int p = 0; p < gllab::kSubmitPaths; ++p) {
      char row[64];
      std::snprintf(row, sizeof row, "%-14s %7.2f   %6.2fx%s", gllab::kSubmitNames[p], g_rate.mtri_s[p],
                    g_rate.mtri_s[p] / g_rate.mtri_s[0], p == int(path) ? "  <" : "");
      lines.push_back(row);
    }
    gllab::draw_text_panel(8, s.height - 8 - (gllab::kSubmitPaths + 2) * gllab::kGlyphHeight, lines, {1.f, 0.9f, 0.6f});
  }
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{"05_submission_modes",
                 "lab 05 · four ways to submit a mesh",
                 {{"immediate", "glBegin/glColor/glNormal/glVertex/glEnd, every frame"},
                  {"display_list", "the same calls compiled once, glCallList per frame"},
                  {"vertex_arrays", "client arrays + glDrawElements with an index array"},
                  {"vbo", "interleaved buffer + element buffer, uploaded once"}},
                 {{"size_log2", 14, 10, 20, "about 2^size_log2 triangles (10: 1k .. 20: 1M)"}},
                 {{'+', "mesh size x2 (up to 1M triangles)", "size_log2", +1},
                  {'-', "mesh size /2 (down to 1k)", "size_log2", -1}},
                 init,
                 display};
  // display() reads State::time (a slow spin), so the window redraws
  // continuously and the timings stay live; headless renders use --time.
  lab.animated = true;
  lab.shutdown = release;  // the list and buffers, while the context is current
  return lab;
}
