// lab 04 · vertex buffer objects                            difficulty: ★★☆☆
// The torus from buffer objects (seed §1.3): colours and indices uploaded once
// (GL_STATIC_DRAW), positions and normals rewritten every frame with
// glBufferSubData (GL_DYNAMIC_DRAW) while a ripple runs round the ring, and its
// normals as lines from a buffer refilled every frame (GL_STREAM_DRAW).
// Notice: with a buffer bound, the last argument of glVertexPointer is a byte
//   offset into it. In unbound_pitfall the checker floor, a client-memory
//   array, vanishes: GL_ARRAY_BUFFER was still bound, so its address was
//   read as an offset far past the end of the buffer.
// Try: [a] to 0 makes the plain torus; why do the normal lines ([n]) tilt
//   where the tube swells? Render `--time 0.5`: where are the crests now?
// Keys: [a]/[A] ripple amplitude -/+  [n] normal lines  [h] help  [Esc] quit
// Views: default, normals, later, unbound_pitfall
// Reference: reference_images/04_vertex_buffer_objects__*.png

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "harness/lab.h"
#include "mesh/indexed_mesh.h"

namespace {

// Lab data (edit me) -------------------------------------------------------
constexpr int kRings = 96, kSides = 32;  // rings x sides vertices, twice as many triangles
constexpr double kRingRadius = 1.0, kTubeRadius = 0.4;
constexpr int kWaves = 8;                // crests around the ring
constexpr double kPeriod = 2.0;          // seconds until a crest reaches the next one's place
constexpr float kNormalLength = 0.16f;
constexpr int kNormalEvery = 2;          // a line at every 2nd ring and side
constexpr int kFloorCells = 8;           // checker squares along each side
constexpr float kFloorHalf = 1.6f, kFloorZ = -0.62f;

// x y z nx ny nz per vertex in one buffer: 24 bytes from one vertex to the next.
constexpr GLsizei kStride = 6 * sizeof(float);

const gllab::IndexedMesh& torus() {
  static const gllab::IndexedMesh mesh = gllab::make_torus(kRings, kSides, kRingRadius, kTubeRadius);
  return mesh;
}

// The floor stays in client memory, as in lab 03: 4 corners per square.
struct Floor {
  std::vector<float> positions, colours;
};
const Floor& checker_floor() {
  static const Floor floor = [] {
    Floor f;
    const float step = 2 * kFloorHalf / kFloorCells;
    for (int i = 0; i < kFloorCells; ++i)
      for (int j = 0; j < kFloorCells; ++j) {
        const float x = -kFloorHalf + i * step, y = -kFloorHalf + j * step, c = (i + j) % 2 ? 0.75f : 0.35f;
        for (const auto& corner : {0, 1, 3, 2}) {  // (0,0) (1,0) (1,1) (0,1): counter-clockwise
          f.positions.insert(f.positions.end(), {x + (corner & 1) * step, y + (corner >> 1) * step, kFloorZ});
          f.colours.insert(f.colours.end(), {c, c, c});
        }
      }
    return f;
  }();
  return floor;
}

// GL buffer names, made in init() (once per context).
struct Buffers {
  GLuint colours = 0, shape = 0, indices = 0, normal_lines = 0;
} g_buffers;

template <typename T>
GLsizeiptr bytes(const std::vector<T>& v) { return static_cast<GLsizeiptr>(v.size() * sizeof(T)); }
const void* offset(std::size_t byte) { return reinterpret_cast<const void*>(byte); }

// Drawing -------------------------------------------------------------------
// The tube radius rho(u) = r + A sin(m u - 2 pi t / T) swells and shrinks in a
// wave that runs round the ring. The surface is P(u, v) = c(u) + rho(u) n(u, v)
// with c the ring and n the plain torus normal; P_u x P_v points along
// (R + rho cos v) n - rho'(u) e_u (README), e_u = (-sin u, cos u, 0).
// Vertex i * kSides + j is at u = 2 pi i / kRings, v = 2 pi j / kSides, the
// order make_torus uses, so the colours and indices still fit.
std::vector<float> rippled(double amplitude, double time) {
  std::vector<float> out;
  out.reserve(6 * kRings * kSides);
  const double phase = 2 * M_PI * time / kPeriod;
  for (int i = 0; i < kRings; ++i) {
    const double u = 2 * M_PI * i / kRings, cu = std::cos(u), su = std::sin(u);
    const double rho = kTubeRadius + amplitude * std::sin(kWaves * u - phase);
    const double drho = amplitude * kWaves * std::cos(kWaves * u - phase);
    for (int j = 0; j < kSides; ++j) {
      const double v = 2 * M_PI * j / kSides, cv = std::cos(v), sv = std::sin(v);
      const double n[3] = {cv * cu, cv * su, sv}, w = kRingRadius + rho * cv;
      const double m[3] = {w * n[0] + drho * su, w * n[1] - drho * cu, w * n[2]};
      const double len = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
      out.insert(out.end(), {float(kRingRadius * cu + rho * n[0]), float(kRingRadius * su + rho * n[1]),
                             float(rho * n[2]), float(m[0] / len), float(m[1] / len), float(m[2] / len)});
    }
  }
  return out;
}

void draw_torus() {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glBindBuffer(GL_ARRAY_BUFFER, g_buffers.shape);
  // A buffer is bound, so these are byte offsets into it, not addresses:
  // the position at 0, the normal 12 bytes in, 24 bytes per vertex.
  glVertexPointer(3, GL_FLOAT, kStride, offset(0));
  glNormalPointer(GL_FLOAT, kStride, offset(3 * sizeof(float)));
  // Each pointer remembers the buffer bound when it was set: colours come
  // from another buffer.
  glBindBuffer(GL_ARRAY_BUFFER, g_buffers.colours);
  glColorPointer(3, GL_FLOAT, 0, offset(0));
  // The indices come from the element array buffer: offset 0 into it.
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g_buffers.indices);
  glDrawElements(GL_TRIANGLES, GLsizei(torus().indices.size()), GL_UNSIGNED_INT, offset(0));
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glDisableClientState(GL_NORMAL_ARRAY);
}

// New data every frame, drawn once: GL_STREAM_DRAW. glBufferData (not
// SubData) gives GL fresh storage, so it need not wait for the last frame's draw.
void draw_normal_lines(const std::vector<float>& shape) {
  std::vector<float> lines;
  for (int i = 0; i < kRings; i += kNormalEvery)
    for (int j = 0; j < kSides; j += kNormalEvery) {
      const float* p = &shape[6 * std::size_t(i * kSides + j)];  // x y z nx ny nz
      for (float s : {0.f, kNormalLength})
        for (int c = 0; c < 3; ++c) lines.push_back(p[c] + s * p[3 + c]);
    }
  glBindBuffer(GL_ARRAY_BUFFER, g_buffers.normal_lines);
  glBufferData(GL_ARRAY_BUFFER, bytes(lines), lines.data(), GL_STREAM_DRAW);
  glVertexPointer(3, GL_FLOAT, 0, offset(0));
  glDisableClientState(GL_COLOR_ARRAY);
  glDisable(GL_LIGHTING);
  glColor3f(1.f, 1.f, 0.6f);
  glDrawArrays(GL_LINES, 0, GLsizei(lines.size() / 3));
  glEnable(GL_LIGHTING);
}

void draw_floor(bool unbind) {
  // Client-memory arrays need GL_ARRAY_BUFFER unbound (0). Without this line
  // the addresses below are taken as offsets into the last bound buffer.
  if (unbind) glBindBuffer(GL_ARRAY_BUFFER, 0);
  const Floor& f = checker_floor();
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, f.positions.data());
  glColorPointer(3, GL_FLOAT, 0, f.colours.data());
  glNormal3f(0.f, 0.f, 1.f);
  glDrawArrays(GL_QUADS, 0, GLsizei(f.positions.size() / 3));
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

// glDeleteBuffers frees the names and their storage. It needs the context
// current: the runners call this (lab.shutdown) before they destroy it.
void release_buffers() {
  const GLuint names[] = {g_buffers.colours, g_buffers.shape, g_buffers.indices, g_buffers.normal_lines};
  glDeleteBuffers(GLsizei(std::size(names)), names);
  g_buffers = {};
}

// init / display ----------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
  GLuint names[4];
  glGenBuffers(GLsizei(std::size(names)), names);
  g_buffers = {names[0], names[1], names[2], names[3]};
  const gllab::IndexedMesh& m = torus();
  // Written once, drawn every frame: GL_STATIC_DRAW (a driver may keep it in video memory).
  glBindBuffer(GL_ARRAY_BUFFER, g_buffers.colours);
  glBufferData(GL_ARRAY_BUFFER, bytes(m.colours), m.colours.data(), GL_STATIC_DRAW);
  // Rewritten every frame: GL_DYNAMIC_DRAW. Only the size now (data = nullptr).
  glBindBuffer(GL_ARRAY_BUFFER, g_buffers.shape);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m.vertex_count() * kStride), nullptr, GL_DYNAMIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g_buffers.indices);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, bytes(m.indices), m.indices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

void display(const gllab::State& s) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gllab::ortho_fit(s.width, s.height, 1.9, 1.9);
  gllab::enable_headlight();
  const std::string& view = s.view();
  const double time = s.time + (view == "later" ? kPeriod / 4 : 0);
  glTranslatef(0.f, -0.2f, 0.f);
  glRotatef(-58.f, 1.f, 0.f, 0.f);  // look down on the ring at a slant
  const std::vector<float> shape = rippled(s.get("amplitude"), time);
  // The frame's one upload: every position and normal, into the storage made in init().
  glBindBuffer(GL_ARRAY_BUFFER, g_buffers.shape);
  glBufferSubData(GL_ARRAY_BUFFER, 0, bytes(shape), shape.data());
  draw_torus();
  if (s.flag("normals") || view == "normals") draw_normal_lines(shape);
  draw_floor(view != "unbound_pitfall");

  char status[80];
  std::snprintf(status, sizeof status, "t = %.3f s   amplitude %.2f", time, s.get("amplitude"));
  std::vector<std::string> lines = {
      "buffer              usage            filled",
      "colours             GL_STATIC_DRAW   once, in init()",
      "indices (element)   GL_STATIC_DRAW   once, in init()",
      "positions, normals  GL_DYNAMIC_DRAW  glBufferSubData/frame",
      "normal lines        GL_STREAM_DRAW   glBufferData/frame",
      std::string(status) + ", " + std::to_string(bytes(shape)) + " B uploaded"};
  gllab::draw_text_panel(8, 8, lines, {0.9f, 0.95f, 1.f});
  if (view == "unbound_pitfall")
    gllab::draw_text_panel(8, s.height - 60,
                           {"floor: GL_ARRAY_BUFFER still bound, so its address",
                            "was read as an offset into the last bound buffer"},
                           {1.f, 0.45f, 0.4f});
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{"04_vertex_buffer_objects",
                 "lab 04 · vertex buffer objects",
                 {{"default", "rippling torus: static, dynamic and element buffers"},
                  {"normals", "with its normals from a GL_STREAM_DRAW buffer"},
                  {"later", "a quarter period (0.5 s) later: the crests moved on"},
                  {"unbound_pitfall", "floor lost: client array with a buffer still bound"}},
                 {{"amplitude", 0.08, 0, 0.16, "ripple height (0 = plain torus)"},
                  {"normals", 0, 0, 1, "draw the normals as lines (any view)"}},
                 {{'a', "ripple amplitude -0.02", "amplitude", -0.02},
                  {'A', "ripple amplitude +0.02", "amplitude", +0.02},
                  {'n', "normal lines on/off", "normals"}},
                 init,
                 display};
  lab.animated = true;  // display() reads State::time
  lab.shutdown = release_buffers;
  return lab;
}
