// common/mesh/indexed_mesh.h — the triangle mesh the submission labs send to
// OpenGL (03 vertex arrays, 04 VBOs, 05 the four paths).
//
// Plain arrays in the layout glVertexPointer/glNormalPointer/glColorPointer
// expect: 3 floats per position, normal and colour, each vertex stored once,
// triangles as index triples (lecture notes ch. 1, §1.2 Polygonal
// representation, "Hierarchy of the representation": a vertex shared by several
// polygons is stored once and referenced). No GL here; the labs draw it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gllab {

struct IndexedMesh {
  std::vector<float> positions;       // x y z per vertex
  std::vector<float> normals;         // unit normal per vertex
  std::vector<float> colours;         // r g b per vertex, 0..1
  std::vector<std::uint32_t> indices; // 3 per triangle, counter-clockwise from outside

  std::size_t vertex_count() const { return positions.size() / 3; }
  std::size_t triangle_count() const { return indices.size() / 3; }
};

/// A torus around the z axis: ring radius R (centre to tube centre), tube
/// radius r, `rings` steps around z and `sides` steps around the tube.
/// rings * sides vertices, 2 * rings * sides triangles; the seam shares its
/// vertices, so the mesh is closed. Normals are exact (from the tube centre),
/// colours run around the ring. Throws std::invalid_argument naming the value
/// when rings or sides < 3, or r <= 0, or R <= r.
IndexedMesh make_torus(int rings, int sides, double R, double r);

/// The torus with about `triangles` triangles (at least 18), its rings twice
/// its sides: make_torus(2k, k, 1, 0.4) with 4k^2 close to `triangles`.
IndexedMesh torus_with_triangles(std::size_t triangles);

/// The same triangles with nothing shared: vertex i of the result is vertex
/// indices[i] of the mesh, and the result's indices are 0, 1, 2, ...
/// What glDrawArrays(GL_TRIANGLES) needs. Normals and colours are copied
/// when the mesh has them (an empty array stays empty).
IndexedMesh unshared(const IndexedMesh& mesh);

/// One interleaved array of (x y z, nx ny nz, r g b) per vertex: 9 floats, a
/// stride of 36 bytes.
std::vector<float> interleaved(const IndexedMesh& mesh);

/// The torus of make_torus(rings, sides, R, r) with a ripple running round the
/// ring (lab 04): the tube radius is rho(u) = r + amplitude sin(waves u - phase).
/// The surface is P(u, v) = c(u) + rho(u) n(u, v), c the ring and n the plain
/// torus normal; its unit normal is along P_u x P_v = rho [(R + rho cos v) n -
/// rho'(u) e_u], e_u = (-sin u, cos u, 0). Per vertex, in make_torus's order
/// (so its colours and indices fit): x y z nx ny nz, 6 floats, 24 bytes.
std::vector<float> rippled_torus(int rings, int sides, double R, double r, int waves,
                                 double amplitude, double phase);

/// Quads with a colour per corner, as glVertexPointer/glColorPointer take them.
struct ColouredQuads {
  std::vector<float> positions, colours;  // 3 floats per corner, 4 corners per quad
};

/// A checkerboard of cells x cells squares covering [-half, half]^2 in the plane
/// z, two greys alternating (0.35, 0.75), each square's corners counter-
/// clockwise seen from +z: what glDrawArrays(GL_QUADS) takes (lab 04's floor).
ColouredQuads checker_floor(int cells, float half, float z);

}  // namespace gllab
