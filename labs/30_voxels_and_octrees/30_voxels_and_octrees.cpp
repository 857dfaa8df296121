// lab 30 · voxels and octrees                                     difficulty: ★★★
// A torus as voxels and as an octree (lecture notes ch. 1, §1.8 Space partitioning: "for a
// resolution of n voxels in each dimension we need n^3 voxels ... therefore, it requires a lot
// of memory -> save space using octrees"). The mesh is voxelized by ray parity; the octree
// splits only the partly covered cubes, into eight children numbered 0..7; a scene octree
// holds triangles and speeds up the ray of a mouse pick.
// Notice: the voxels' memory grows as n^3, the octree's nodes about as n^2 (only cubes on the
//   surface split). A pick ray tests about ten triangles instead of all 20,480.
// Try: in octree, press [d] and [D]: how many nodes does each level add? In picking, drag
//   the cross-hair across the hole of the torus: what does the ray test there?
// Keys: [n]/[N] voxels per side  [d]/[D] octree depth  [c] cells on/off
//   left-drag the cross-hair  right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: voxels, octree, memory, picking
// Reference: reference_images/30_voxels_and_octrees__*.png

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "gl/field_view.h"
#include "gl/gl.h"
#include "gl/panels.h"
#include "gl/scene.h"
#include "gl/space_view.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "mesh/indexed_mesh.h"
#include "space/octree.h"
#include "space/scene_octree.h"
#include "space/voxels.h"

namespace {

namespace sp = gllab::space;
using gllab::Rgb, gllab::State, gllab::kOrbit, gllab::format_text, gllab::count_text;
using gllab::spline::Vec3;

// Lab data (edit me) -------------------------------------------------------
constexpr double kR = 1, kTube = 0.45;                      // the torus: ring and tube radius
const sp::Box3 kCube{{-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}};  // the object space: the root cube
constexpr int kRings = 96, kSides = 48;                     // the voxelized mesh: 9,216 triangles
constexpr int kPickRings = 160, kPickSides = 64;            // the picked mesh: 20,480 triangles
const Rgb kSolid{.9f, .62f, .3f}, kClay{.75f, .75f, .8f}, kText{1, 1, 1};
const Rgb kRay{1, .3f, .3f}, kCell{.4f, .8f, 1};

const gllab::IndexedMesh& torus(int rings, int sides) {
  static std::map<int, gllab::IndexedMesh> cache;
  auto it = cache.find(rings);
  if (it == cache.end())
    it = cache.emplace(rings, gllab::make_torus(rings, sides, kR, kTube)).first;
  return it->second;
}
// The voxels of the torus mesh at n^3 (ray parity, space/voxels.h), kept per n.
const sp::VoxelGrid& voxels(int n) {
  static std::map<int, sp::VoxelGrid> cache;
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, sp::voxelize(torus(kRings, kSides), kCube, n)).first;
  return it->second;
}

// voxels: the solid voxels drawn as cubes (only the faces that can be seen), their memory.
void draw_voxels(const State& s) {
  const int n = s.integer("n");
  const sp::VoxelGrid& g = voxels(n);
  gllab::space_camera(s, s.width, s.height, 1.9);
  glEnable(GL_DEPTH_TEST);
  const std::size_t faces = gllab::draw_voxel_faces(g, kSolid);
  if (s.flag("cells")) gllab::draw_box_edges(kCube, {.5f, .5f, .55f});
  const double exact = 2 * M_PI * M_PI * kR * kTube * kTube;  // Pappus: 2 pi R * pi r^2
  const double volume = g.solid_count() * std::pow(g.voxel_size(), 3);
  gllab::draw_text_panel(
      8, 8,
      {format_text("n = %d: %s voxels, %s solid", n, count_text(std::size_t(n) * n * n).c_str(),
                   count_text(g.solid_count()).c_str()),
       "memory at 1 bit a voxel: " + gllab::bytes_text(g.bytes()),
       format_text("volume %.4f (torus %.4f, %+.1f %%)", volume, exact, 100 * (volume / exact - 1)),
       format_text("%zu faces drawn", faces)},
      kText);
}

// octree: the region octree of the same voxels (depth d: n = 2^d). Covered leaves are solid
// cubes, partly covered nodes the edges around them; the tree's first three levels below.
void draw_octree(const State& s) {
  const int depth = s.integer("depth");
  const sp::RegionOctree tree = sp::RegionOctree::from_voxels(voxels(1 << depth));
  const gllab::Panel top = gllab::enter_panel(0, 0, 1, 2, s.width, s.height);
  gllab::space_camera(s, top.width, top.height, 1.7);
  glEnable(GL_DEPTH_TEST);
  const std::vector<sp::OctreeNode>& nodes = tree.nodes();
  const std::vector<sp::Box3> boxes = tree.boxes();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].state == sp::Coverage::kCovered)
      gllab::draw_box_faces(boxes[i], gllab::coverage_colour(sp::Coverage::kCovered));
    else if (nodes[i].state == sp::Coverage::kPartial && s.flag("cells") && nodes[i].depth < 3)
      gllab::draw_box_edges(boxes[i], gllab::coverage_colour(sp::Coverage::kPartial));
  }
  gllab::leave_panels(s.width, s.height);
  gllab::draw_octree_diagram(tree, std::min(depth + 1, 3), 8, s.height / 2 + 8, s.width - 16,
                             s.height / 2 - 90);
  std::vector<std::string> lines{format_text("depth %d (n = %d): %s nodes, %s", depth, 1 << depth,
                                             count_text(nodes.size()).c_str(),
                                             gllab::bytes_text(tree.bytes()).c_str())};
  lines.push_back(format_text("leaves: %zu covered, %zu uncovered; %zu partly covered nodes",
                              tree.count(sp::Coverage::kCovered),
                              tree.count(sp::Coverage::kUncovered),
                              tree.count(sp::Coverage::kPartial)));
  lines.push_back(format_text("covered leaves hold %s voxels; the grid has %s",
                              count_text(tree.covered_voxels()).c_str(),
                              count_text(voxels(1 << depth).solid_count()).c_str()));
  gllab::draw_text_panel(8, s.height - 56, lines, kText);
  gllab::draw_coverage_legend(8, 8);
}

// memory: bytes of the voxels at one byte each (a CT scan's values), at one bit each, and of
// the exact torus's octree (8 bytes a node), n = 4 .. 256, on log scales. The octree comes
// from the signed distance (from_distance): the tree of the voxels, without the n^3 grid.
void draw_memory(const State& s) {
  static std::vector<std::array<double, 4>> rows;  // n, bytes: voxels (bytes, bits), octree
  for (int d = 2; d <= 8 && rows.size() < 7; ++d) {
    const double n = 1 << d, bits = double(sp::VoxelGrid(kCube, 1 << d).bytes());
    const sp::RegionOctree tree =
        sp::RegionOctree::from_distance(sp::torus_distance({}, kR, kTube), kCube, d);
    rows.push_back({n, n * n * n, bits, double(tree.bytes())});
  }
  gllab::draw_memory_plot(s, rows);  // log scales, a table below
}

// picking: a ray from the eye through the cross-hair A (orthographic: along the view), against
// the torus's 20,480 triangles, by brute force and through the scene octree. Left: as seen;
// right: from the side, with the ray, the cells it visited and the triangle hit.
void draw_picking(const State& s) {
  static const sp::SceneOctree octree(torus(kPickRings, kPickSides));
  const gllab::IndexedMesh& mesh = torus(kPickRings, kPickSides);
  const Vec3 aim = s.points("A")[0];
  sp::Ray ray{};
  sp::RayStats with{}, without{};
  sp::Hit hit{}, brute{};
  for (int panel = 0; panel < 2; ++panel) {
    const gllab::Panel p = gllab::enter_panel(panel, 0, 2, 1, s.width, s.height);
    gllab::space_camera(s, p.width, p.height, 1.7, panel ? 60 : -30);
    if (panel == 0) {  // the ray under the cross-hair, and both searches
      ray = gllab::view_ray(aim, 4);
      hit = octree.first_hit(ray, &with);
      brute = sp::first_hit_brute_force(mesh, ray, &without);
    }
    glEnable(GL_DEPTH_TEST);
    glColor3f(kClay.r, kClay.g, kClay.b);
    gllab::draw_iso_mesh(mesh);
    glDisable(GL_DEPTH_TEST);  // the ray, the cells and the hit show through the torus
    if (panel == 1) {
      gllab::draw_polyline({ray.origin, ray.origin + (hit.hit ? hit.t : 8) * ray.direction}, kRay);
      if (s.flag("cells"))
        for (const sp::Box3& b : octree.visited_boxes(ray)) gllab::draw_box_edges(b, kCell);
    } else {
      gllab::draw_control_points(s, "A", kRay, 9.f);
    }
    if (hit.hit) gllab::draw_dots({ray.origin + hit.t * ray.direction}, {1, 1, .3f}, 8.f);
    gllab::leave_panels(s.width, s.height);
  }
  gllab::draw_text_panel(
      8, 8,
      {format_text("octree: %zu triangles tested in %zu cells", with.triangles_tested,
                   with.cells_visited),
       format_text("brute force: %s triangles tested",
                   count_text(without.triangles_tested).c_str()),
       hit.hit ? format_text("hit %u at t = %.6f; brute force: %u at %.6f", hit.triangle, hit.t,
                             brute.triangle, brute.t)
               : std::string(brute.hit ? "octree missed, brute force hit!" : "no hit (both)")},
      kText);
}

void init() { glClearColor(0.1f, 0.11f, 0.14f, 1.f); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "30_voxels_and_octrees",
      "lab 30 · voxels and octrees",
      {{"voxels", "the torus voxelized at n^3 by ray parity, and its memory", draw_voxels, kOrbit},
       {"octree", "its region octree: cubes by state, the tree numbered", draw_octree, kOrbit},
       {"memory", "bytes of voxels against the octree as n grows", draw_memory},
       {"picking", "a pick ray: triangles tested with and without the octree", draw_picking,
        kOrbit}},
      {{"n", 24, 4, 128, "voxels per side"}, {"depth", 4, 1, 7, "octree depth (n = 2^depth)"},
       {"cells", 1, 0, 1, "the cube, partly covered nodes, cells the ray visits"}},
      {{'n', "fewer voxels (-4)", "n", -4}, {'N', "more voxels (+4)", "n", +4},
       {'d', "shallower octree", "depth", -1}, {'D', "deeper octree", "depth", +1},
       {'c', "cells on/off", "cells"}},
      init};
  lab.points = {{"A", {{0.95, -0.2, 0.3}}, "the pick ray's cross-hair", 3}};
  return lab;
}
