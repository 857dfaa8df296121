// common/spline/weld.cpp — welding patch edges: weld and tessellate_patches
// (tessellate.h). In plain words (no paper): vertices within the weld
// tolerance become one, found through a hash grid of that cell size (a vertex
// can only merge with one in its own or a neighbouring cell), and triangles
// that collapse are dropped. Shared edges fit because every patch samples its
// edges from the edge alone (patch_quadtree.cpp): welding only absorbs
// round-off.
#include "spline/tessellate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "spline/errors.h"

namespace gllab::spline {

Mesh weld(const std::vector<Mesh>& meshes, double weld_tolerance) {
  if (!(weld_tolerance >= 0) || !std::isfinite(weld_tolerance))
    fail(std::isfinite(weld_tolerance) ? ErrorCode::kToleranceNotPositive : ErrorCode::kNotFinite,
         "weld: weld_tolerance=" + num(weld_tolerance) + " must be >= 0", {{"weld_tolerance", weld_tolerance}});
  Mesh out;
  // A hash grid of cell size weld_tolerance: a vertex can only merge with one
  // in its own or a neighbouring cell.
  const double cell = weld_tolerance > 0 ? weld_tolerance : 1.0;
  std::map<std::array<std::int64_t, 3>, std::vector<int>> grid;
  const auto key = [&](Vec3 p) {
    const auto k = [&](double x) {
      const double c = std::floor(x / cell);
      return static_cast<std::int64_t>(std::clamp(c, -9e15, 9e15));
    };
    return std::array<std::int64_t, 3>{k(p.x), k(p.y), k(p.z)};
  };
  for (const Mesh& m : meshes) {
    std::vector<int> remap(m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      const Vec3 p = m.positions[i];
      const auto c = key(p);
      int found = -1;
      for (int dx = -1; dx <= 1 && found < 0; ++dx)
        for (int dy = -1; dy <= 1 && found < 0; ++dy)
          for (int dz = -1; dz <= 1 && found < 0; ++dz) {
            const auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
            if (it == grid.end()) continue;
            for (int j : it->second)
              if (norm(out.positions[j] - p) <= weld_tolerance) {
                found = j;
                break;
              }
          }
      if (found < 0) {
        found = static_cast<int>(out.positions.size());
        out.positions.push_back(p);
        out.normals.push_back(i < m.normals.size() ? m.normals[i] : Vec3{});
        out.uv.push_back(i < m.uv.size() ? m.uv[i] : Vec2{});
        grid[c].push_back(found);
      }
      remap[i] = found;
    }
    for (const auto& t : m.triangles) {
      const std::array<int, 3> r{remap[t[0]], remap[t[1]], remap[t[2]]};
      if (r[0] != r[1] && r[1] != r[2] && r[2] != r[0]) out.triangles.push_back(r);
    }
  }
  return out;
}

Mesh tessellate_patches(const std::vector<Patch>& patches, const TessellationOptions& options, double weld_tolerance) {
  std::vector<Mesh> meshes;
  for (std::size_t k = 0; k < patches.size(); ++k) {
    try {
      meshes.push_back(tessellate_surface(patches[k].surface, patches[k].domain, options, patches[k].trims));
    } catch (const SplineError& e) {  // the patch's error, its code kept, with the patch named
      throw with_context(e, "patch " + std::to_string(k) + ": ", {{"patch", k}});
    } catch (const std::invalid_argument& e) {  // thrown by a caller's evaluator: no code to keep
      throw std::invalid_argument("patch " + std::to_string(k) + ": " + e.what());
    }
  }
  return weld(meshes, weld_tolerance);
}

}  // namespace gllab::spline
