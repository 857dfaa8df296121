// common/gl/submission.h — the four ways to send a mesh to OpenGL (seed §1.3),
// as lab 05 shows them and bench/submission_bench times them: one definition,
// so the benchmark measures exactly what the lab draws.
//
//   immediate      glBegin/glColor3fv/glNormal3fv/glVertex3fv/glEnd, every frame
//   display list   the same calls compiled once (GL_COMPILE), glCallList per frame
//   vertex arrays  pointers into our memory, glDrawElements with an index array
//   VBO            one interleaved buffer + an element buffer, GL_STATIC_DRAW,
//                  filled once; the pointers are byte offsets into them
// All four send the same colour, normal and position per vertex in the same
// order, so they give the same pixels.
#pragma once

#include <utility>

#include "gl/gl.h"
#include "mesh/indexed_mesh.h"

namespace gllab {

enum class Submit { kImmediate, kDisplayList, kVertexArrays, kVbo };
inline constexpr int kSubmitPaths = 4;
inline constexpr const char* kSubmitNames[kSubmitPaths] = {"immediate", "display_list", "vertex_arrays", "vbo"};

/// A mesh and the GL objects its display-list and VBO paths keep. The GL
/// objects are made on first use, with a context current, and must be freed
/// with release() while it still is.
class SubmittedMesh {
 public:
  SubmittedMesh() = default;
  explicit SubmittedMesh(IndexedMesh mesh) : mesh_(std::move(mesh)) {}
  SubmittedMesh(const SubmittedMesh&) = delete;
  SubmittedMesh& operator=(const SubmittedMesh&) = delete;
  SubmittedMesh(SubmittedMesh&& other) noexcept;
  SubmittedMesh& operator=(SubmittedMesh&& other) noexcept;
  ~SubmittedMesh() = default;  // GL objects are freed by release(), not here: no context may be current

  const IndexedMesh& mesh() const { return mesh_; }
  /// Compiles the list or fills the buffers when `path` needs them and they
  /// are not made yet. draw() calls it; call it first to keep it out of a timing.
  void prepare(Submit path);
  /// Draws the whole mesh as GL_TRIANGLES through `path`; leaves the client
  /// arrays disabled and no buffer bound.
  void draw(Submit path);
  /// glDeleteLists / glDeleteBuffers for what prepare() made.
  void release();

 private:
  IndexedMesh mesh_;
  GLuint list_ = 0;
  GLuint buffers_[2] = {0, 0};  // interleaved x y z nx ny nz r g b; indices
};

}  // namespace gllab
