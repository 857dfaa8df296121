// lab 03 · vertex arrays                                    difficulty: ★★☆☆
// The torus sent as arrays (lecture notes ch. 1, §1.3 Polygon rendering with
// OpenGL, "Vertex arrays"): glVertexPointer, glNormalPointer and glColorPointer
// over separate arrays or one interleaved array, drawn with glDrawArrays (every
// corner sent) or glDrawElements (shared vertices, indices).
// Notice: glDrawElements stores each vertex once; the overlay counts 6 times
//   fewer vertices for the same triangles and the same picture.
// Try: in wrong_stride press [s] until the stride is 36 bytes. Why does every
//   smaller stride scramble the torus, and why is 0 not "tightly packed" here?
// Keys: [l] separate/interleaved  [d] glDrawElements/glDrawArrays
//   [s]/[S] stride +/-12 bytes  [+]/[-] detail  [n] labels
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: default, separate_vs_interleaved, draw_arrays_vs_elements, wrong_stride
// Reference: reference_images/03_vertex_arrays__*.png

#include <map>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "harness/lab.h"
#include "mesh/indexed_mesh.h"

namespace {

using std::to_string;

// Lab data (edit me) -------------------------------------------------------
// The torus: 2k rings around z, k sides around the tube, 4k^2 triangles.
constexpr int kDefaultDetail = 14;

// One interleaved vertex: x y z, nx ny nz, r g b (gllab::interleaved).
constexpr GLsizei kStride = 9 * sizeof(float);       // 36 bytes
constexpr int kNormalOffset = 3, kColourOffset = 6;  // in floats

enum Layout { kSeparate = 0, kInterleaved = 1 };
enum Call { kElements = 0, kArrays = 1 };

const gllab::Rgb kLabel{1.f, 1.f, 1.f}, kDim{0.6f, 0.62f, 0.68f};

// The same torus in the four layouts the lab draws from, made once per detail.
struct Arrays {
  gllab::IndexedMesh shared, flat;           // indexed; every corner its own vertex
  std::vector<float> shared_packed, flat_packed;  // the same, interleaved
};

const Arrays& arrays(int k) {
  static std::map<int, Arrays> made;
  Arrays& a = made[k];
  if (a.shared.indices.empty()) {
    a.shared = gllab::make_torus(2 * k, k, 1.0, 0.4);
    a.flat = gllab::unshared(a.shared);
    a.shared_packed = gllab::interleaved(a.shared);
    a.flat_packed = gllab::interleaved(a.flat);
  }
  return a;
}

// Drawing -------------------------------------------------------------------
// Separate arrays: stride 0 means "tightly packed", 3 floats after 3 floats.
void point_separate(const gllab::IndexedMesh& m) {
  glVertexPointer(3, GL_FLOAT, 0, m.positions.data());
  glNormalPointer(GL_FLOAT, 0, m.normals.data());
  glColorPointer(3, GL_FLOAT, 0, m.colours.data());
}

// One interleaved array: each pointer starts at its attribute in vertex 0,
// and the stride is the size of a whole vertex, so GL skips the others.
void point_interleaved(const std::vector<float>& v, GLsizei stride) {
  glVertexPointer(3, GL_FLOAT, stride, v.data());
  glNormalPointer(GL_FLOAT, stride, v.data() + kNormalOffset);
  glColorPointer(3, GL_FLOAT, stride, v.data() + kColourOffset);
}

void draw_torus(const Arrays& a, Layout layout, Call call, GLsizei stride = kStride) {
  // Client state: it lives on the client side of GL, so glPushAttrib does not
  // save it (glPushClientAttrib does). Enable what the draw reads, then disable.
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  const gllab::IndexedMesh& m = call == kArrays ? a.flat : a.shared;
  if (layout == kSeparate) point_separate(m);
  else point_interleaved(call == kArrays ? a.flat_packed : a.shared_packed, stride);
  if (call == kArrays) {
    // Vertices 0, 1, 2, ... in order: 3 per triangle, shared corners repeated.
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(m.vertex_count()));
  } else {
    // Each index picks a stored vertex: a corner of 6 triangles is stored once.
    glDrawElements(GL_TRIANGLES, GLsizei(m.indices.size()), GL_UNSIGNED_INT, m.indices.data());
  }
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

// The projection, the light and the camera of every view.
const Arrays& set_up(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 3.3, 3.3);
  gllab::enable_headlight();
  gllab::apply_orbit(s);  // right-drag, wheel, [0]: the camera (common/gl/scene.h)
  return arrays(s.integer("detail"));
}

// Places a torus at (x, y), tilted towards the viewer, and draws it lit.
void lit_torus(const Arrays& a, float x, float y, float scale, Layout layout, Call call,
               GLsizei stride = kStride) {
  glPushMatrix();
  glTranslatef(x, y, 0.f);
  glScalef(scale, scale, scale);
  glRotatef(-55.f, 1.f, 0.f, 0.f);
  draw_torus(a, layout, call, stride);
  glPopMatrix();
}

void label(const gllab::State& s, float x, float y, const std::string& text,
           gllab::Rgb colour = kLabel) {
  if (s.flag("labels")) gllab::draw_label(x, y, 0, text, colour);
}

void draw_default(const gllab::State& s) {
  const Arrays& a = set_up(s);
  lit_torus(a, 0.f, 0.35f, 2.f, s.flag("layout") ? kInterleaved : kSeparate,
            s.flag("call") ? kArrays : kElements);
  // The counts are read from the data; neither layout nor call changes them.
  const std::vector<std::string> lines = {
      "triangles:                 " + to_string(a.shared.triangle_count()),
      "glDrawArrays   vertices:   " + to_string(a.flat.vertex_count()) + " (3 per triangle)",
      "glDrawElements vertices:   " + to_string(a.shared.vertex_count()) + " stored once",
      "               indices:    " + to_string(a.shared.indices.size()),
      "[l] layout, [d] draw call: the picture must not change"};  // bottom left, clear of [h]
  const int top = s.height - 20 - gllab::kGlyphHeight * static_cast<int>(lines.size());
  if (s.flag("labels")) gllab::draw_text_panel(8, top, lines, kLabel);
}

void draw_layouts(const gllab::State& s) {
  const Arrays& a = set_up(s);
  lit_torus(a, -1.65f, 0.f, 1.05f, kSeparate, kElements);
  lit_torus(a, 1.65f, 0.f, 1.05f, kInterleaved, kElements);
  label(s, -1.65f, 1.5f, "separate arrays");
  label(s, -1.65f, -1.5f, "stride 0", kDim);
  label(s, 1.65f, 1.5f, "one interleaved array");
  label(s, 1.65f, -1.5f, "stride " + to_string(kStride) + " bytes", kDim);
}

void draw_calls(const gllab::State& s) {
  const Arrays& a = set_up(s);
  lit_torus(a, -1.65f, 0.5f, 1.05f, kSeparate, kArrays);
  lit_torus(a, 1.65f, 0.5f, 1.05f, kSeparate, kElements);
  label(s, -1.65f, 2.f, "glDrawArrays");
  label(s, 1.65f, 2.f, "glDrawElements");
  label(s, -1.65f, -1.f, to_string(a.flat.vertex_count()) + " vertices sent", kDim);
  label(s, 1.65f, -1.f, to_string(a.shared.vertex_count()) + " vertices stored", kDim);
  label(s, 1.65f, -1.35f, "+ " + to_string(a.shared.indices.size()) + " indices", kDim);
  label(s, 0.f, -2.2f, "same " + to_string(a.shared.triangle_count()) + " triangles, same picture");
}

void draw_wrong_stride(const gllab::State& s) {
  const Arrays& a = set_up(s);
  const GLsizei stride = 4 * (s.integer("stride") / 4);  // floats are 4-byte aligned
  lit_torus(a, -1.65f, 0.f, 1.05f, kInterleaved, kElements);
  // Wrong unless stride is 36: GL reads vertex i at i * stride bytes, so it takes
  // normals and colours for positions (stride 0 means "packed": 12 bytes). Garbage
  // triangles overlap in shared planes: without the depth test the last one wins.
  if (stride != kStride) glDisable(GL_DEPTH_TEST);
  lit_torus(a, 1.65f, 0.f, 1.05f, kInterleaved, kElements, stride);
  glEnable(GL_DEPTH_TEST);
  label(s, -1.65f, 1.5f, "interleaved, stride " + to_string(kStride));
  label(s, 1.65f, 1.5f, "interleaved, stride " + to_string(stride));
  label(s, 0.f, -2.2f, stride == kStride ? "right: one whole vertex per step"
                                          : "wrong: GL reads x y z from normals and colours");
}

// init ----------------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  return {"03_vertex_arrays",
          "lab 03 · vertex arrays",
          {{"default", "the lit torus with vertex counts", draw_default, kOrbit},
           {"separate_vs_interleaved", "stride 0 on 3 arrays, 36 on one", draw_layouts, kOrbit},
           {"draw_arrays_vs_elements", "every corner sent vs shared + indices", draw_calls, kOrbit},
           {"wrong_stride", "the interleaved array, a wrong stride", draw_wrong_stride, kOrbit}},
          {{"layout", 0, 0, 1, "default: separate arrays (0) or one interleaved array (1)"},
           {"call", 0, 0, 1, "default: glDrawElements (0) or glDrawArrays (1)"},
           {"stride", 0, 0, kStride, "wrong_stride: the stride of the right torus, bytes"},
           {"detail", kDefaultDetail, 3, 60, "torus sides k: 2k rings, 4k^2 triangles"},
           {"labels", 1, 0, 1, "labels and counts on/off"}},
          {{'l', "separate / interleaved", "layout"}, {'d', "glDrawElements / Arrays", "call"},
           {'s', "stride +12 bytes", "stride", +12}, {'S', "stride -12 bytes", "stride", -12},
           {'+', "torus detail +2", "detail", +2}, {'-', "torus detail -2", "detail", -2},
           {'n', "labels and counts on/off", "labels"}},
          init};
}
