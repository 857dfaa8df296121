// common/mesh/polygon_mesh.cpp
#include "mesh/polygon_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace gllab {

namespace {

[[noreturn]] void fail(const std::string& message) { throw std::invalid_argument("polygon mesh: " + message); }

std::string str(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

bool finite(Vec3 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

std::vector<Vec3> corners_of(const PolygonMesh& mesh, const Polygon& p) {
  std::vector<Vec3> corners;
  for (std::size_t v : p.vertices) corners.push_back(mesh.vertices[v].position);
  return corners;
}

// Union-find over a few polygons around one vertex.
std::size_t root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

void push(std::vector<float>& out, Vec3 v) {
  out.insert(out.end(), {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)});
}

void push(std::vector<float>& out, Colour c) { out.insert(out.end(), {c.r, c.g, c.b}); }

}  // namespace

std::optional<std::size_t> PolygonMesh::find_edge(std::size_t a, std::size_t b) const {
  const std::size_t lo = std::min(a, b), hi = std::max(a, b);
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (edges[e].v0 == lo && edges[e].v1 == hi) return e;
  return std::nullopt;
}

std::size_t PolygonMesh::count(EdgeType type) const {
  return static_cast<std::size_t>(
      std::count_if(edges.begin(), edges.end(), [type](const Edge& e) { return e.type == type; }));
}

std::size_t PolygonMesh::triangle_count() const {
  std::size_t n = 0;
  for (const Polygon& p : polygons) n += p.vertices.size() - 2;
  return n;
}

Vec3 newell_normal(const std::vector<Vec3>& corners) {
  Vec3 n;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3 a = corners[i], b = corners[(i + 1) % corners.size()];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

PolygonMesh build_polygon_mesh(const std::vector<Vec3>& positions, const std::vector<PolygonInput>& polygons,
                               std::vector<Surface> surfaces) {
  if (surfaces.empty()) fail("no surfaces (need at least one)");
  if (polygons.empty()) fail("no polygons");
  PolygonMesh mesh;
  mesh.surfaces = std::move(surfaces);
  for (Surface& s : mesh.surfaces) s.polygons.clear();
  for (std::size_t v = 0; v < positions.size(); ++v) {
    if (!finite(positions[v])) fail("vertex " + std::to_string(v) + " has a position that is not finite");
    mesh.vertices.push_back({positions[v], {}, std::nullopt, {}});
  }
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> edge_of;       // (lo, hi) -> edge
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> directed_use;  // (from, to) -> polygon
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    const PolygonInput& in = polygons[p];
    const std::string name = "polygon " + std::to_string(p);
    const std::size_t n = in.vertices.size();
    if (n < 3) fail(name + " has " + std::to_string(n) + " vertices (need >= 3)");
    if (in.surface >= mesh.surfaces.size())
      fail(name + ": surface " + std::to_string(in.surface) + " out of range (" +
           std::to_string(mesh.surfaces.size()) + " surfaces)");
    for (std::size_t k = 0; k < n; ++k) {
      if (in.vertices[k] >= positions.size())
        fail(name + ", corner " + std::to_string(k) + ": vertex index " + std::to_string(in.vertices[k]) +
             " out of range (" + std::to_string(positions.size()) + " vertices)");
      for (std::size_t j = 0; j < k; ++j)
        if (in.vertices[j] == in.vertices[k])
          fail(name + " uses vertex " + std::to_string(in.vertices[k]) + " twice (corners " + std::to_string(j) +
               " and " + std::to_string(k) + ")");
    }
    Polygon poly;
    poly.vertices = in.vertices;
    poly.surface = in.surface;
    const std::vector<Vec3> corners = corners_of(mesh, poly);
    const Vec3 newell = newell_normal(corners);
    double perimeter = 0;
    for (std::size_t k = 0; k < n; ++k) perimeter += spline::norm(corners[(k + 1) % n] - corners[k]);
    // Degenerate: no area compared with the polygon's own size (collinear or coincident corners).
    if (!(spline::norm(newell) > 1e-12 * perimeter * perimeter))
      fail(name + " is degenerate: area 0 (its vertices are collinear or coincide)");
    poly.normal = spline::normalized(newell);
    poly.area = spline::norm(newell) / 2;
    const Vec3 centre = std::accumulate(corners.begin(), corners.end(), Vec3{}) / static_cast<double>(n);
    for (const Vec3& c : corners) poly.flatness = std::max(poly.flatness, std::abs(dot(c - centre, poly.normal)));
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t a = in.vertices[k], b = in.vertices[(k + 1) % n];
      const auto [used, fresh] = directed_use.insert({{a, b}, p});
      if (!fresh)
        fail("polygons " + std::to_string(used->second) + " and " + std::to_string(p) + " both run from vertex " +
             std::to_string(a) + " to vertex " + std::to_string(b) + " (their windings disagree)");
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = edge_of.find(key);
      if (it == edge_of.end()) {
        it = edge_of.insert({key, mesh.edges.size()}).first;
        Edge e;
        e.v0 = key.first;
        e.v1 = key.second;
        e.length = spline::norm(positions[b] - positions[a]);
        mesh.edges.push_back(e);
      }
      mesh.edges[it->second].polygons.push_back(p);
      poly.edges.push_back(it->second);
      mesh.vertices[a].polygons.push_back(p);
    }
    mesh.surfaces[in.surface].polygons.push_back(p);
    mesh.polygons.push_back(std::move(poly));
  }
  // Vertex normal: the mean of the unit normals of the polygons around it.
  for (Vertex& v : mesh.vertices) {
    Vec3 sum;
    for (std::size_t p : v.polygons) sum += mesh.polygons[p].normal;
    v.normal = spline::normalized(sum);
  }
  classify_edges(mesh, 180);
  return mesh;
}

std::size_t classify_edges(PolygonMesh& mesh, double feature_angle_degrees) {
  if (!(feature_angle_degrees >= 0 && feature_angle_degrees <= 180))
    fail("feature angle " + str(feature_angle_degrees) + " degrees (need 0..180)");
  std::size_t features = 0;
  for (Edge& e : mesh.edges) {
    e.dihedral_degrees = 0;
    if (e.polygons.size() == 1) {
      e.type = EdgeType::kBoundary;
      continue;
    }
    if (e.polygons.size() == 2) {
      const double c = dot(mesh.polygons[e.polygons[0]].normal, mesh.polygons[e.polygons[1]].normal);
      e.dihedral_degrees = std::acos(std::clamp(c, -1.0, 1.0)) * 180 / M_PI;
    }
    // An angle equal to the threshold is not above it, even after rounding:
    // a 12-sided cylinder's 30 degrees must not flip with the last bit.
    constexpr double kTieDegrees = 1e-9;
    const bool feature = e.polygons.size() > 2 || e.dihedral_degrees > feature_angle_degrees + kTieDegrees;
    e.type = feature ? EdgeType::kFeature : EdgeType::kVirtual;
    features += feature;
  }
  return features;
}

IndexedMesh render_arrays(const PolygonMesh& mesh, Normals normals) {
  IndexedMesh out;
  // corner[p][k]: the render vertex of corner k of polygon p.
  std::vector<std::vector<std::uint32_t>> corner(mesh.polygons.size());
  auto add = [&out](Vec3 position, Vec3 normal, Colour colour) {
    push(out.positions, position);
    push(out.normals, normal);
    push(out.colours, colour);
    return static_cast<std::uint32_t>(out.vertex_count() - 1);
  };
  auto colour_of = [&mesh](std::size_t v, std::size_t p) {
    return mesh.vertices[v].colour.value_or(mesh.surfaces[mesh.polygons[p].surface].colour);
  };
  auto corner_of = [&mesh](std::size_t p, std::size_t v) {
    const auto& vs = mesh.polygons[p].vertices;
    return static_cast<std::size_t>(std::find(vs.begin(), vs.end(), v) - vs.begin());
  };
  for (std::size_t p = 0; p < mesh.polygons.size(); ++p) corner[p].resize(mesh.polygons[p].vertices.size());

  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const std::vector<std::size_t>& around = mesh.vertices[v].polygons;
    std::vector<std::size_t> parent(around.size());
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    if (normals == Normals::kAveraged) std::fill(parent.begin(), parent.end(), std::size_t{0});
    if (normals == Normals::kSplitFeatures) {
      // Join two polygons around v when a virtual edge at v separates them,
      // unless one of them belongs to a flat surface.
      for (std::size_t i = 0; i < around.size(); ++i) {
        const Polygon& p = mesh.polygons[around[i]];
        if (mesh.surfaces[p.surface].shading == Shading::kFlat) continue;
        const std::size_t n = p.vertices.size(), k = corner_of(around[i], v);
        for (std::size_t e : {p.edges[(k + n - 1) % n], p.edges[k]}) {
          const Edge& edge = mesh.edges[e];
          if (edge.type != EdgeType::kVirtual || edge.polygons.size() != 2) continue;
          const std::size_t q = edge.polygons[0] == around[i] ? edge.polygons[1] : edge.polygons[0];
          if (mesh.surfaces[mesh.polygons[q].surface].shading == Shading::kFlat) continue;
          const std::size_t j = static_cast<std::size_t>(std::find(around.begin(), around.end(), q) - around.begin());
          parent[root(parent, i)] = root(parent, j);
        }
      }
    }
    // One render vertex per (smoothing group, surface): the surface gives the colour.
    std::map<std::size_t, Vec3> group_normal;
    for (std::size_t i = 0; i < around.size(); ++i) group_normal[root(parent, i)] += mesh.polygons[around[i]].normal;
    std::map<std::pair<std::size_t, std::size_t>, std::uint32_t> made;
    for (std::size_t i = 0; i < around.size(); ++i) {
      const std::size_t p = around[i];
      const std::size_t g = root(parent, i);
      const auto key = std::make_pair(g, normals == Normals::kFace ? p : mesh.polygons[p].surface);
      auto it = made.find(key);
      if (it == made.end()) {
        const Vec3 n = normals == Normals::kAveraged ? mesh.vertices[v].normal : spline::normalized(group_normal[g]);
        it = made.insert({key, add(mesh.vertices[v].position, n, colour_of(v, p))}).first;
      }
      corner[p][corner_of(p, v)] = it->second;
    }
  }
  // Fan each polygon from its first corner: n - 2 triangles.
  for (std::size_t p = 0; p < mesh.polygons.size(); ++p)
    for (std::size_t k = 1; k + 1 < corner[p].size(); ++k)
      out.indices.insert(out.indices.end(), {corner[p][0], corner[p][k], corner[p][k + 1]});
  return out;
}

PolygonMesh make_surface_of_revolution(const std::vector<ProfilePoint>& profile, int slices,
                                       std::vector<Surface> surfaces,
                                       const std::vector<std::size_t>& segment_surface) {
  const std::string what = "surface of revolution: ";
  if (slices < 3) throw std::invalid_argument(what + "slices=" + std::to_string(slices) + " (need >= 3)");
  const std::size_t m = profile.size();
  if (m < 2) throw std::invalid_argument(what + "profile has " + std::to_string(m) + " points (need >= 2)");
  if (!segment_surface.empty() && segment_surface.size() != m - 1)
    throw std::invalid_argument(what + std::to_string(segment_surface.size()) + " segment surfaces for " +
                                std::to_string(m - 1) + " profile segments");
  for (std::size_t i = 0; i < m; ++i) {
    const ProfilePoint q = profile[i];
    if (!(q.r >= 0) || !std::isfinite(q.r) || !std::isfinite(q.z))
      throw std::invalid_argument(what + "profile point " + std::to_string(i) + " has r=" + str(q.r) +
                                  ", z=" + str(q.z) + " (need finite, r >= 0)");
    if (q.r == 0 && i > 0 && i + 1 < m)
      throw std::invalid_argument(what + "inner profile point " + std::to_string(i) + " has r=0 (only the ends may)");
  }
  if (m == 2 && profile[0].r == 0 && profile[1].r == 0)
    throw std::invalid_argument(what + "profile segment 0 has r=0 at both ends");
  std::vector<Vec3> positions;
  std::vector<std::size_t> first(m);  // first vertex of profile point i
  for (std::size_t i = 0; i < m; ++i) {
    first[i] = positions.size();
    const int ring = profile[i].r == 0 ? 1 : slices;  // a pole is one vertex
    for (int j = 0; j < ring; ++j) {
      const double phi = 2 * M_PI * j / slices;
      positions.push_back({profile[i].r * std::cos(phi), profile[i].r * std::sin(phi), profile[i].z});
    }
  }
  auto at = [&](std::size_t i, int j) { return profile[i].r == 0 ? first[i] : first[i] + j % slices; };
  std::vector<PolygonInput> polygons;
  for (std::size_t i = 0; i + 1 < m; ++i) {
    const std::size_t s = segment_surface.empty() ? 0 : segment_surface[i];
    for (int j = 0; j < slices; ++j) {
      // Around (phi grows) then up the profile: counter-clockwise seen from outside.
      std::vector<std::size_t> quad = {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)};
      quad.erase(std::unique(quad.begin(), quad.end()), quad.end());  // a pole makes it a triangle
      if (quad.size() > 3 && quad.back() == quad.front()) quad.pop_back();
      polygons.push_back({quad, s});
    }
  }
  return build_polygon_mesh(positions, polygons, std::move(surfaces));
}

std::vector<ProfilePoint> half_ellipse_profile(double a, double b, int n) {
  std::vector<ProfilePoint> profile;
  for (int i = 0; i <= n; ++i) {
    const double t = M_PI * i / n - M_PI / 2;
    profile.push_back({i == 0 || i == n ? 0 : a * std::cos(t), b * std::sin(t)});
  }
  return profile;
}

std::vector<ProfilePoint> resample_profile(const std::vector<ProfilePoint>& dense, int segments,
                                           double curvature_share) {
  const std::size_t n = dense.size();
  if (segments < 1 || static_cast<std::size_t>(segments) + 1 > n)
    throw std::invalid_argument("resample profile: segments=" + std::to_string(segments) + " (need 1.." +
                                std::to_string(n > 0 ? n - 1 : 0) + " for " + std::to_string(n) + " points)");
  if (!(curvature_share >= 0 && curvature_share <= 1))
    throw std::invalid_argument("resample profile: curvature share " + str(curvature_share) + " (need 0..1)");
  std::vector<double> length(n - 1), turn(n, 0.0);
  auto dir = [&](std::size_t k) { return spline::Vec2{dense[k + 1].r - dense[k].r, dense[k + 1].z - dense[k].z}; };
  for (std::size_t k = 0; k + 1 < n; ++k) length[k] = spline::norm(dir(k));
  for (std::size_t k = 1; k + 1 < n; ++k) turn[k] = std::abs(std::atan2(cross(dir(k - 1), dir(k)), dot(dir(k - 1), dir(k))));
  const double total_length = std::accumulate(length.begin(), length.end(), 0.0);
  const double total_turn = std::accumulate(turn.begin(), turn.end(), 0.0);
  // A straight profile has no curvature to follow: space it by length.
  const double c = total_turn > 0 ? curvature_share : 0.0;
  std::vector<double> weight(n, 0.0);  // cumulative, weight[n-1] = 1
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double t = total_turn > 0 ? (turn[k] + turn[k + 1]) / 2 / total_turn : 0;
    weight[k + 1] = weight[k] + (1 - c) * length[k] / total_length + c * t;
  }
  std::vector<ProfilePoint> out = {dense.front()};
  std::size_t previous = 0;
  for (int i = 1; i < segments; ++i) {
    const double target = weight.back() * i / segments;
    std::size_t j = static_cast<std::size_t>(std::lower_bound(weight.begin(), weight.end(), target) - weight.begin());
    if (j > 0 && target - weight[j - 1] < weight[j] - target) --j;
    // Keep the picks distinct and leave room for the ones still to come.
    j = std::clamp(j, previous + 1, n - 1 - static_cast<std::size_t>(segments - i));
    out.push_back(dense[j]);
    previous = j;
  }
  out.push_back(dense.back());
  return out;
}

double profile_deviation(const std::vector<ProfilePoint>& dense, const std::vector<ProfilePoint>& picked) {
  if (picked.size() < 2)
    throw std::invalid_argument("profile deviation: " + std::to_string(picked.size()) + " picked points (need >= 2)");
  double worst = 0;
  for (const ProfilePoint& q : dense) {
    double nearest = INFINITY;
    for (std::size_t k = 0; k + 1 < picked.size(); ++k) {
      const spline::Vec2 a{picked[k].r, picked[k].z}, d = spline::Vec2{picked[k + 1].r, picked[k + 1].z} - a;
      const spline::Vec2 w = spline::Vec2{q.r, q.z} - a;
      const double t = dot(d, d) > 0 ? std::clamp(dot(w, d) / dot(d, d), 0.0, 1.0) : 0.0;
      nearest = std::min(nearest, spline::norm(w - t * d));
    }
    worst = std::max(worst, nearest);
  }
  return worst;
}

}  // namespace gllab
