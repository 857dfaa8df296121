// common/field/mesh_measures.h — what the tests and labs measure on an
// iso-surface mesh: its topology (closed, oriented, Euler characteristic,
// components) and its area and enclosed volume.
#pragma once

#include <cstddef>

#include "mesh/indexed_mesh.h"

namespace gllab::field {

struct MeshTopology {
  std::size_t vertices = 0, edges = 0, triangles = 0;
  std::size_t boundary_edges = 0;     // used by one triangle
  std::size_t nonmanifold_edges = 0;  // used by three or more
  std::size_t misoriented_edges = 0;  // used twice in the same direction
  std::size_t components = 0;         // connected through shared edges
  long euler() const { return long(vertices) - long(edges) + long(triangles); }
  bool closed_and_oriented() const {
    return boundary_edges == 0 && nonmanifold_edges == 0 && misoriented_edges == 0;
  }
};

/// Counts only the vertices that some triangle uses.
MeshTopology topology(const IndexedMesh& m);

double surface_area(const IndexedMesh& m);
/// The signed volume enclosed (divergence theorem, sum of det(a, b, c) / 6):
/// positive for a closed mesh oriented counter-clockwise from outside.
double enclosed_volume(const IndexedMesh& m);

}  // namespace gllab::field
