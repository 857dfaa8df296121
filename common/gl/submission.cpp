// common/gl/submission.cpp — the four paths (see submission.h).
#include "gl/submission.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace gllab {
namespace {

const void* offset(std::size_t byte) { return reinterpret_cast<const void*>(byte); }

// 1. Immediate mode: three calls per vertex, every frame, every vertex.
void draw_immediate(const IndexedMesh& m) {
  glBegin(GL_TRIANGLES);
  for (std::uint32_t i : m.indices) {
    glColor3fv(&m.colours[3 * i]);
    glNormal3fv(&m.normals[3 * i]);
    glVertex3fv(&m.positions[3 * i]);
  }
  glEnd();
}

// 3. Vertex arrays: GL reads the arrays from our memory at each draw.
void draw_vertex_arrays(const IndexedMesh& m) {
  glVertexPointer(3, GL_FLOAT, 0, m.positions.data());
  glNormalPointer(GL_FLOAT, 0, m.normals.data());
  glColorPointer(3, GL_FLOAT, 0, m.colours.data());
  glDrawElements(GL_TRIANGLES, GLsizei(m.indices.size()), GL_UNSIGNED_INT, m.indices.data());
}

// 4. VBO: the data went to buffer objects once; pointers are offsets into them.
void draw_vbo(const IndexedMesh& m, const GLuint buffers[2]) {
  constexpr GLsizei kStride = 9 * sizeof(float);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glVertexPointer(3, GL_FLOAT, kStride, offset(0));
  glNormalPointer(GL_FLOAT, kStride, offset(3 * sizeof(float)));
  glColorPointer(3, GL_FLOAT, kStride, offset(6 * sizeof(float)));
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  glDrawElements(GL_TRIANGLES, GLsizei(m.indices.size()), GL_UNSIGNED_INT, offset(0));
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

}  // namespace

SubmittedMesh::SubmittedMesh(SubmittedMesh&& other) noexcept { *this = std::move(other); }

SubmittedMesh& SubmittedMesh::operator=(SubmittedMesh&& other) noexcept {
  mesh_ = std::move(other.mesh_);
  list_ = std::exchange(other.list_, 0);
  buffers_[0] = std::exchange(other.buffers_[0], 0);
  buffers_[1] = std::exchange(other.buffers_[1], 0);
  return *this;
}

void SubmittedMesh::prepare(Submit path) {
  if (path == Submit::kDisplayList && !list_) {
    // 2. Display list: the immediate-mode calls, recorded once (GL_COMPILE
    // stores without drawing), replayed by one glCallList a frame.
    list_ = glGenLists(1);
    glNewList(list_, GL_COMPILE);
    draw_immediate(mesh_);
    glEndList();
  }
  if (path == Submit::kVbo && !buffers_[0]) {
    const std::vector<float> vertices = interleaved(mesh_);
    glGenBuffers(2, buffers_);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh_.indices.size() * sizeof(std::uint32_t)),
                 mesh_.indices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  }
}

void SubmittedMesh::draw(Submit path) {
  prepare(path);
  const bool arrays = path == Submit::kVertexArrays || path == Submit::kVbo;
  if (arrays) {
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
  }
  switch (path) {
    case Submit::kImmediate: draw_immediate(mesh_); break;
    case Submit::kDisplayList: glCallList(list_); break;
    case Submit::kVertexArrays: draw_vertex_arrays(mesh_); break;
    case Submit::kVbo: draw_vbo(mesh_, buffers_); break;
  }
  if (arrays) {
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
  }
}

void SubmittedMesh::release() {
  if (list_) glDeleteLists(list_, 1);
  if (buffers_[0]) glDeleteBuffers(2, buffers_);
  list_ = 0;
  buffers_[0] = buffers_[1] = 0;
}

}  // namespace gllab
