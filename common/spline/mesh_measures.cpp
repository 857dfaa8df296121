// common/spline/mesh_measures.cpp — measures of a mesh (tessellate.h), for the
// own tessellation and GLU's alike: mesh_area; boundary_edges; contour_segments
// (iso-curves of the height, ch. 1 §1.7 "Iso-curves", by marching triangles);
// surface_area (Radon's 7-point rule, Stroud T2:5-1); and mesh_fidelity (the
// parametric error measured as tessellate.h defines the tolerance, along the
// rim too, and the tilted faces).
#include "spline/tessellate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "spline/errors.h"

namespace gllab::spline {

double mesh_area(const Mesh& mesh) {
  double area = 0;
  for (const auto& t : mesh.triangles)
    area += norm(cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]])) / 2;
  return area;
}

std::vector<std::array<int, 2>> boundary_edges(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  std::vector<std::array<int, 2>> out;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (uses[std::minmax(t[k], t[(k + 1) % 3])] == 1) out.push_back({t[k], t[(k + 1) % 3]});
  return out;
}

std::vector<std::array<Vec3, 2>> contour_segments(const Mesh& mesh, Vec3 direction, double level) {
  const std::string what = "contour_segments";
  require_finite(direction, what, "direction");
  require_finite(level, what, "level");
  if (norm(direction) == 0)
    fail(ErrorCode::kDegenerate, what + ": direction is the zero vector", {{"direction", direction}});
  std::vector<double> h;  // height above the level, per vertex
  for (const Vec3& p : mesh.positions) h.push_back(dot(p, direction) - level);
  const auto below = [&h](int k) { return h[static_cast<std::size_t>(k)] < 0; };
  // The point where h = 0 on edge (i, j), one end below and one at or above:
  // always interpolated from the lower index, so both triangles get the same point.
  const auto crossing = [&](int i, int j) {
    if (i > j) std::swap(i, j);
    const double hi = h[static_cast<std::size_t>(i)], hj = h[static_cast<std::size_t>(j)];
    return lerp(mesh.positions[static_cast<std::size_t>(i)], mesh.positions[static_cast<std::size_t>(j)],
                hi / (hi - hj));
  };
  std::vector<std::array<Vec3, 2>> out;
  for (const auto& t : mesh.triangles) {
    Vec3 ends[2];
    int found = 0;
    for (int k = 0; k < 3; ++k)
      if (below(t[k]) != below(t[(k + 1) % 3])) ends[found++] = crossing(t[k], t[(k + 1) % 3]);
    // A vertex at the level with both neighbours below crosses "twice" at itself: no segment.
    if (found == 2 && ends[0] != ends[1]) out.push_back({ends[0], ends[1]});
  }
  return out;
}

namespace {

void check_mesh(const Mesh& mesh, const char* what) {
  if (mesh.uv.size() != mesh.positions.size())
    fail(ErrorCode::kSizeMismatch,
         std::string(what) + ": the mesh has " + std::to_string(mesh.uv.size()) + " (u, v) for " +
             std::to_string(mesh.positions.size()) + " vertices",
         {{"uv", mesh.uv.size()}, {"positions", mesh.positions.size()}});
  const auto n = static_cast<int>(mesh.positions.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k : mesh.triangles[t])
      if (k < 0 || k >= n)
        fail(ErrorCode::kIndexOutOfRange,
             std::string(what) + ": triangle " + std::to_string(t) + " uses vertex " + std::to_string(k) + " of " +
                 std::to_string(n),
             {{"triangle", t}, {"vertex", k}, {"vertices", n}});
}

}  // namespace

double surface_area(const SurfaceEvaluator& surface, const Mesh& mesh) {
  check_mesh(mesh, "surface_area");
  // Radon's rule (Stroud T2:5-1): the centroid, weight 9/40, and the points
  // with barycentric coordinates (a, a, 1 - 2a) and their permutations,
  // a = (6 -+ sqrt 15) / 21 with weight (155 -+ sqrt 15) / 1200.
  const double r15 = std::sqrt(15.0);
  const double a1 = (6 - r15) / 21, a2 = (6 + r15) / 21;
  const double w1 = (155 - r15) / 1200, w2 = (155 + r15) / 1200;
  const double rule[7][4] = {{1.0 / 3, 1.0 / 3, 1.0 / 3, 9.0 / 40},
                             {a1, a1, 1 - 2 * a1, w1}, {a1, 1 - 2 * a1, a1, w1}, {1 - 2 * a1, a1, a1, w1},
                             {a2, a2, 1 - 2 * a2, w2}, {a2, 1 - 2 * a2, a2, w2}, {1 - 2 * a2, a2, a2, w2}};
  double area = 0;
  for (const auto& t : mesh.triangles) {
    const Vec2 a = mesh.uv[t[0]], b = mesh.uv[t[1]], c = mesh.uv[t[2]];
    double sum = 0;
    for (const auto& r : rule) {
      const Vec2 q = r[0] * a + r[1] * b + r[2] * c;
      const SurfaceSample s = surface(q.x, q.y);
      sum += r[3] * norm(cross(s.du, s.dv));
    }
    area += std::abs(cross(b - a, c - a)) / 2 * sum;
  }
  return area;
}

MeshFidelity mesh_fidelity(const Mesh& mesh, const SurfaceEvaluator& surface, double tilt_degrees,
                           double weld_tolerance) {
  check_mesh(mesh, "mesh_fidelity");
  if (!(tilt_degrees >= 0 && tilt_degrees <= 180))
    fail(ErrorCode::kOutOfRange, "mesh_fidelity: tilt_degrees=" + num(tilt_degrees) + " must be in [0, 180]",
         {{"tilt_degrees", tilt_degrees}});
  const double kDegrees = 180 / std::acos(-1.0);
  MeshFidelity f;
  // Barycentre and edge midpoints, as tessellate.h measures its tolerance.
  const double samples[4][3] = {{1.0 / 3, 1.0 / 3, 1.0 / 3}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}};
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    const Vec3 P[3] = {mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
    const Vec2 Q[3] = {mesh.uv[t[0]], mesh.uv[t[1]], mesh.uv[t[2]]};
    for (const auto& b : samples) {
      const Vec2 q = b[0] * Q[0] + b[1] * Q[1] + b[2] * Q[2];
      const Vec3 p = b[0] * P[0] + b[1] * P[1] + b[2] * P[2];
      f.max_deviation = std::max(f.max_deviation, norm(surface(q.x, q.y).point - p));
    }
    const Vec3 face = cross(P[1] - P[0], P[2] - P[0]);
    if (norm(face) == 0) continue;
    const Vec2 centre = (Q[0] + Q[1] + Q[2]) / 3;
    const Vec3 n = surface(centre.x, centre.y).normal;
    const double tilt = std::atan2(norm(cross(face, n)), dot(face, n)) * kDegrees;
    f.max_tilt_degrees = std::max(f.max_tilt_degrees, tilt);
    if (tilt > tilt_degrees) f.tilted.push_back(i);
  }
  f.tilted_faces = f.tilted.size();
  const Mesh welded = weld({mesh}, weld_tolerance);
  for (const auto& e : boundary_edges(welded))
    for (double s : {0.25, 0.5, 0.75}) {
      const Vec2 q = (1 - s) * welded.uv[e[0]] + s * welded.uv[e[1]];
      const Vec3 p = lerp(welded.positions[e[0]], welded.positions[e[1]], s);
      f.max_trim_deviation = std::max(f.max_trim_deviation, norm(surface(q.x, q.y).point - p));
    }
  return f;
}

}  // namespace gllab::spline
