// lab 04 · vertex buffer objects                            difficulty: ★★☆☆
// The torus from buffer objects (lecture notes ch. 1, §1.3 Polygon rendering with
// OpenGL, "Vertex buffer objects (VBO)"): colours and indices uploaded once
// (GL_STATIC_DRAW), positions and normals rewritten every frame (glBufferSubData,
// GL_DYNAMIC_DRAW) as a ripple runs round the ring, normal lines (GL_STREAM_DRAW).
// Notice: with a buffer bound, the last argument of glVertexPointer is a byte
//   offset into it. In unbound_pitfall the checker floor, a client-memory
//   array, vanishes: GL_ARRAY_BUFFER was still bound, so its address was
//   read as an offset far past the end of the buffer.
// Try: [a] to 0 makes the plain torus; why do the normal lines ([n]) tilt
//   where the tube swells? Render `--time 0.5`: where are the crests now?
// Keys: [a]/[A] ripple amplitude -/+  [n] normal lines
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
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

// x y z nx ny nz per vertex in one buffer: 24 bytes from one vertex to the next.
constexpr GLsizei kStride = 6 * sizeof(float);

// The torus's colours and indices (its positions and normals ripple, below).
const gllab::IndexedMesh kTorus = gllab::make_torus(kRings, kSides, kRingRadius, kTubeRadius);
// The floor stays in client memory, as in lab 03: 8 x 8 squares, 4 corners each.
const gllab::ColouredQuads kFloor = gllab::checker_floor(8, 1.6f, -0.62f);

// GL buffer names, made in init() (once per context).
struct Buffers { GLuint colours = 0, shape = 0, indices = 0, normal_lines = 0; } g_buffers;

template <typename T>
GLsizeiptr bytes(const std::vector<T>& v) { return static_cast<GLsizeiptr>(v.size() * sizeof(T)); }
const void* offset(std::size_t byte) { return reinterpret_cast<const void*>(byte); }

// Drawing -------------------------------------------------------------------
void draw_torus() {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glBindBuffer(GL_ARRAY_BUFFER, g_buffers.shape);
  // A buffer is bound, so these are byte offsets into it, not addresses:
  // the position at 0, the normal 12 bytes in, 24 bytes per vertex.
  glVertexPointer(3, GL_FLOAT, kStride, offset(0));
  glNormalPointer(GL_FLOAT, kStride, offset(3 * sizeof(float)));
  // Each pointer keeps the buffer bound when it was set: colours from another.
  glBindBuffer(GL_ARRAY_BUFFER, g_buffers.colours);
  glColorPointer(3, GL_FLOAT, 0, offset(0));
  // The indices come from the element array buffer: offset 0 into it.
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g_buffers.indices);
  glDrawElements(GL_TRIANGLES, GLsizei(kTorus.indices.size()), GL_UNSIGNED_INT, offset(0));
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
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, kFloor.positions.data());
  glColorPointer(3, GL_FLOAT, 0, kFloor.colours.data());
  glNormal3f(0.f, 0.f, 1.f);
  glDrawArrays(GL_QUADS, 0, GLsizei(kFloor.positions.size() / 3));
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

// What a view adds to the rippling torus and its floor.
enum Variant { kPlain, kNormals, kLater, kUnbound };

void draw_scene(const gllab::State& s, Variant variant) {
  gllab::ortho_fit(s.width, s.height, 1.9, 1.9);
  gllab::enable_headlight();
  gllab::apply_orbit(s);  // right-drag, wheel, [0]: the camera (common/gl/scene.h)
  const double time = s.time + (variant == kLater ? kPeriod / 4 : 0);
  glTranslatef(0.f, -0.2f, 0.f);
  glRotatef(-58.f, 1.f, 0.f, 0.f);  // look down on the ring at a slant
  // The ripple at this time: x y z nx ny nz per vertex (common/mesh, README).
  const double amplitude = s.get("amplitude"), phase = 2 * M_PI * time / kPeriod;
  const std::vector<float> shape =
      gllab::rippled_torus(kRings, kSides, kRingRadius, kTubeRadius, kWaves, amplitude, phase);
  // The frame's one upload: every position and normal, into the storage made in init().
  glBindBuffer(GL_ARRAY_BUFFER, g_buffers.shape);
  glBufferSubData(GL_ARRAY_BUFFER, 0, bytes(shape), shape.data());
  draw_torus();
  if (s.flag("normals") || variant == kNormals) draw_normal_lines(shape);
  draw_floor(variant != kUnbound);

  char status[80];
  std::snprintf(status, sizeof status, "t = %.3f s   amplitude %.2f, %ld B uploaded", time,
                amplitude, long(bytes(shape)));
  gllab::draw_text_panel(8, 8,
                         {"buffer              usage            filled",
                          "colours             GL_STATIC_DRAW   once, in init()",
                          "indices (element)   GL_STATIC_DRAW   once, in init()",
                          "positions, normals  GL_DYNAMIC_DRAW  glBufferSubData/frame",
                          "normal lines        GL_STREAM_DRAW   glBufferData/frame",
                          status},
                         {0.9f, 0.95f, 1.f});
  if (variant == kUnbound)
    gllab::draw_text_panel(8, s.height - 60,
                           {"floor: GL_ARRAY_BUFFER still bound, so its address",
                            "was read as an offset into the last bound buffer"},
                           {1.f, 0.45f, 0.4f});
}

void draw_default(const gllab::State& s) { draw_scene(s, kPlain); }
void draw_normals(const gllab::State& s) { draw_scene(s, kNormals); }
void draw_later(const gllab::State& s) { draw_scene(s, kLater); }
void draw_unbound(const gllab::State& s) { draw_scene(s, kUnbound); }

// init / shutdown -------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
  GLuint names[4];
  glGenBuffers(GLsizei(std::size(names)), names);
  g_buffers = {names[0], names[1], names[2], names[3]};
  const gllab::IndexedMesh& m = kTorus;
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

// glDeleteBuffers frees the names and their storage. It needs the context
// current: the runners call this (lab.shutdown) before they destroy it.
void release_buffers() {
  const GLuint names[] = {g_buffers.colours, g_buffers.shape, g_buffers.indices,
                          g_buffers.normal_lines};
  glDeleteBuffers(GLsizei(std::size(names)), names);
  g_buffers = {};
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{"04_vertex_buffer_objects", "lab 04 · vertex buffer objects",
                 {{"default", "the ripple: static, dynamic, element buffers", draw_default, kOrbit},
                  {"normals", "its normals from a GL_STREAM_DRAW buffer", draw_normals, kOrbit},
                  {"later", "a quarter period (0.5 s) later: crests moved on", draw_later, kOrbit},
                  {"unbound_pitfall", "floor lost: a buffer still bound", draw_unbound, kOrbit}},
                 {{"amplitude", 0.08, 0, 0.16, "ripple height (0 = plain torus)"},
                  {"normals", 0, 0, 1, "draw the normals as lines (any view)"}},
                 {{'a', "amplitude -0.02", "amplitude", -0.02},
                  {'A', "amplitude +0.02", "amplitude", +0.02},
                  {'n', "normal lines on/off", "normals"}},
                 init};
  lab.animated = true;  // the views read State::time
  lab.shutdown = release_buffers;
  return lab;
}
