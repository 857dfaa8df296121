// common/gl/space_view.h — what labs 30 (voxels and octrees) and 31
// (quadtrees and BSP trees) draw that is not their lesson: the camera, boxes
// as edges and as lit faces, the voxels' visible faces, tree diagrams, memory
// in words, the pick ray of an orthographic view, and the painter-against-z-
// buffer pixel count. The structures themselves (common/space) and the calls
// that walk them are the lesson: they are in the labs.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "gl/panels.h"
#include "gl/text.h"
#include "space/bsp.h"
#include "space/octree.h"
#include "space/quadtree.h"
#include "space/voxels.h"

namespace gllab {

class State;

/// The 3-D views' camera: ortho_fit showing [-half, half]^2, the headlight,
/// the orbit camera, then a z-up scene seen from `elevation` degrees above,
/// turned by `azimuth` degrees about z.
void space_camera(const State& s, int width, int height, double half, double azimuth = -30,
                  double elevation = 30);

/// The twelve edges of a box.
void draw_box_edges(const space::Box3& box, Rgb colour, float width = 1.f);
/// The six faces of a box, with outward normals (lit when lighting is on).
void draw_box_faces(const space::Box3& box, Rgb colour);
/// The faces of solid voxels that face an empty voxel or the grid's border:
/// all that can be seen of the voxels (lit quads, outward normals). Returns
/// how many faces it drew.
std::size_t draw_voxel_faces(const space::VoxelGrid& grid, Rgb colour);

/// Colours of the three node states: covered, uncovered, partly covered.
Rgb coverage_colour(space::Coverage state);

/// The first `levels` levels of the octree as a diagram in window pixels
/// (x from the left, y down from the top): the root, its eight children
/// numbered 0..7 by Box3::child's scheme, their children, ... as squares
/// coloured by state, each under its parent; absent children (of a leaf)
/// are left out. Fits the rectangle (x, y, w, h).
void draw_octree_diagram(const space::RegionOctree& tree, int levels, int x, int y, int w, int h);

/// 1536 -> "1.5 KB", 3 << 20 -> "3.0 MB", 512 -> "512 B".
std::string bytes_text(std::size_t bytes);
/// 1234567 -> "1,234,567".
std::string count_text(std::size_t n);

/// The ray of an orthographic view through the lab point `through`, into the
/// screen, from the current model-view matrix: it starts `back` units in
/// front of the point (towards the eye).
space::Ray view_ray(spline::Vec3 through, double back);

/// Panel a and panel b of the same size, read back (glReadPixels) after both
/// are drawn: how many pixels differ, and how many of those lie away from
/// every colour edge (no pixel of its 3 x 3 neighbourhood has another colour,
/// in a or in b). A painter's picture that is right differs from the
/// z-buffer's only along edges: polygon borders, intersection lines, and the
/// one-pixel cracks where split pieces meet at a T-junction. A wrong order
/// paints whole patches, whose inner pixels lie away from every edge.
struct PanelDifference {
  std::size_t pixels = 0, differing = 0, away_from_edges = 0;
};
PanelDifference compare_panels(const Panel& a, const Panel& b);

}  // namespace gllab

namespace gllab {

/// A node of a tree diagram: its parent's index (-1 for the root; parents
/// come before their children, children in order), a label and a colour.
struct DiagramNode {
  int parent;
  std::string label;
  Rgb colour;
};
/// The tree as a diagram in window pixels (x from the left, y down from the
/// top) filling (x, y, w, h): leaves evenly spaced in depth-first order,
/// each parent centred over its children, a square per node with its label
/// under it when there is room.
void draw_tree_diagram(const std::vector<DiagramNode>& nodes, int x, int y, int w, int h);

}  // namespace gllab

namespace gllab {

/// Diagrams (draw_tree_diagram) of a quadtree and a BSP tree, depth first:
/// inner nodes grey, empty leaves dark, a leaf with objects in the first
/// object's colour and name. Quadtree children 0..3; BSP back, then front.
std::vector<DiagramNode> quadtree_diagram(const space::Quadtree& tree,
                                          const std::function<Rgb(int)>& colour,
                                          const std::function<std::string(int)>& name);
std::vector<DiagramNode> bsp_diagram(const space::BspTree& tree,
                                     const std::function<Rgb(int)>& colour,
                                     const std::function<std::string(int)>& name);
/// The cut of every inner BSP node, clipped to its region: the root region
/// (a convex polygon) split down the tree by the nodes' planes.
void draw_bsp_cuts(const space::BspTree& tree, const std::vector<spline::Vec3>& root, Rgb colour);

}  // namespace gllab

namespace gllab {

/// The numbers 1, 2, ... of the first `count` pieces at their centres (the
/// painter's order), under the current matrices.
void draw_piece_numbers(const std::vector<const space::Polygon3*>& pieces, std::size_t count,
                        Rgb colour);

}  // namespace gllab

namespace gllab {

/// Lab 30's memory plot over the whole window: rows of (n, bytes of voxels at
/// a byte each, at a bit each, of the octree), log2 bytes against log2 n for
/// n = 4 .. 256, a legend and a table "n = 256: voxels 16.0 MB, 2.0 MB; octree
/// 2.1 MB (7.7x)" (the last figure: byte voxels over octree).
void draw_memory_plot(const State& s, const std::vector<std::array<double, 4>>& rows);
/// The three node states' colours, as a legend at window pixel (x, y).
void draw_coverage_legend(int x, int y);

}  // namespace gllab

namespace gllab {

/// Convex objects of the plane as polygons in z = 0, object i with id and
/// object i (for a BSP tree of a 2-D scene).
std::vector<space::Polygon3> in_plane(const std::vector<space::ConvexPolygon2>& objects);
/// Each object filled (GL_POLYGON) in colour(i).
void draw_convex_objects(const std::vector<space::ConvexPolygon2>& objects,
                         const std::function<Rgb(int)>& colour);
/// `count` points along 30 degrees through (0.1, -0.05), 1.8 long, spread across by a
/// fixed wobble (0.25 sin 2.4 i), snapped to the lab grid: lab 31's PCA cloud.
std::vector<spline::Vec3> elongated_cloud(int count);

}  // namespace gllab
