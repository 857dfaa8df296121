// common/space/internal.h — checks the space core's files share (not installed for labs).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "mesh/indexed_mesh.h"

namespace gllab::space::internal {

/// Throws std::invalid_argument with one line, "<what>: index 5 = 999 is out of range (32
/// vertices)" or "<what>: vertex 3 has a coordinate that is not finite".
inline void require_valid_mesh(const IndexedMesh& mesh, const std::string& what) {
  const std::size_t vertices = mesh.vertex_count();
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= vertices)
      throw std::invalid_argument(what + ": index " + std::to_string(i) + " = " +
                                  std::to_string(mesh.indices[i]) + " is out of range (" +
                                  std::to_string(vertices) + " vertices)");
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    if (!std::isfinite(mesh.positions[i]))
      throw std::invalid_argument(what + ": vertex " + std::to_string(i / 3) +
                                  " has a coordinate that is not finite");
}

}  // namespace gllab::space::internal
