// common/mesh/indexed_mesh.cpp
#include "mesh/indexed_mesh.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gllab {

IndexedMesh make_torus(int rings, int sides, double R, double r) {
  if (rings < 3) throw std::invalid_argument("torus: rings=" + std::to_string(rings) + " (need >= 3)");
  if (sides < 3) throw std::invalid_argument("torus: sides=" + std::to_string(sides) + " (need >= 3)");
  if (!(r > 0) || !(R > r))
    throw std::invalid_argument("torus: R=" + std::to_string(R) + ", r=" + std::to_string(r) +
                                " (need R > r > 0)");
  IndexedMesh m;
  const double two_pi = 2 * M_PI;
  for (int i = 0; i < rings; ++i) {
    const double u = two_pi * i / rings;  // around z
    const double cu = std::cos(u), su = std::sin(u);
    for (int j = 0; j < sides; ++j) {
      const double v = two_pi * j / sides;  // around the tube
      const double cv = std::cos(v), sv = std::sin(v);
      // Point = tube centre (R cos u, R sin u, 0) + r * normal.
      const double n[3] = {cv * cu, cv * su, sv};
      m.positions.insert(m.positions.end(), {static_cast<float>((R + r * cv) * cu),
                                             static_cast<float>((R + r * cv) * su),
                                             static_cast<float>(r * sv)});
      m.normals.insert(m.normals.end(),
                       {static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2])});
      // Hue runs once around the ring: warm on one side, cool on the other.
      m.colours.insert(m.colours.end(), {static_cast<float>(0.55 + 0.4 * cu),
                                         static_cast<float>(0.55 + 0.35 * su),
                                         static_cast<float>(0.6 - 0.3 * cu)});
    }
  }
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>((i % rings) * sides + (j % sides)); };
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      // The quad (i, j)-(i+1, j)-(i+1, j+1)-(i, j+1) as two triangles,
      // counter-clockwise seen from outside.
      m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return m;
}

IndexedMesh torus_with_triangles(std::size_t triangles) {
  // 2 * rings * sides = 4 k^2 with rings = 2k, sides = k.
  const int k = std::max(3, static_cast<int>(std::lround(std::sqrt(triangles / 4.0))));
  return make_torus(2 * k, k, 1.0, 0.4);
}

IndexedMesh unshared(const IndexedMesh& mesh) {
  IndexedMesh out;
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
    const std::size_t v = 3 * std::size_t{mesh.indices[i]};
    out.positions.insert(out.positions.end(), &mesh.positions[v], &mesh.positions[v] + 3);
    // Only the arrays the mesh has: an iso-surface has no colours, maybe no normals.
    if (!mesh.normals.empty())
      out.normals.insert(out.normals.end(), &mesh.normals[v], &mesh.normals[v] + 3);
    if (!mesh.colours.empty())
      out.colours.insert(out.colours.end(), &mesh.colours[v], &mesh.colours[v] + 3);
    out.indices.push_back(static_cast<std::uint32_t>(i));
  }
  return out;
}

std::vector<float> interleaved(const IndexedMesh& mesh) {
  std::vector<float> out;
  out.reserve(9 * mesh.vertex_count());
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    out.insert(out.end(), &mesh.positions[3 * v], &mesh.positions[3 * v] + 3);
    out.insert(out.end(), &mesh.normals[3 * v], &mesh.normals[3 * v] + 3);
    out.insert(out.end(), &mesh.colours[3 * v], &mesh.colours[3 * v] + 3);
  }
  return out;
}

std::vector<float> rippled_torus(int rings, int sides, double R, double r, int waves,
                                 double amplitude, double phase) {
  std::vector<float> out;
  out.reserve(6 * std::size_t(rings) * std::size_t(sides));
  for (int i = 0; i < rings; ++i) {
    const double u = 2 * M_PI * i / rings, cu = std::cos(u), su = std::sin(u);
    const double rho = r + amplitude * std::sin(waves * u - phase);
    const double drho = amplitude * waves * std::cos(waves * u - phase);
    for (int j = 0; j < sides; ++j) {
      const double v = 2 * M_PI * j / sides, cv = std::cos(v), sv = std::sin(v);
      const double n[3] = {cv * cu, cv * su, sv}, w = R + rho * cv;
      const double m[3] = {w * n[0] + drho * su, w * n[1] - drho * cu, w * n[2]};
      const double len = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
      out.insert(out.end(), {float(R * cu + rho * n[0]), float(R * su + rho * n[1]),
                             float(rho * n[2]), float(m[0] / len), float(m[1] / len),
                             float(m[2] / len)});
    }
  }
  return out;
}

ColouredQuads checker_floor(int cells, float half, float z) {
  ColouredQuads f;
  const float step = 2 * half / cells;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j) {
      const float x = -half + i * step, y = -half + j * step, c = (i + j) % 2 ? 0.75f : 0.35f;
      for (const auto& corner : {0, 1, 3, 2}) {  // (0,0) (1,0) (1,1) (0,1): counter-clockwise
        f.positions.insert(f.positions.end(), {x + (corner & 1) * step, y + (corner >> 1) * step, z});
        f.colours.insert(f.colours.end(), {c, c, c});
      }
    }
  return f;
}

}  // namespace gllab
