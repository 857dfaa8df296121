// common/mesh/polygon_mesh.h — the polygon mesh data structure of the lecture
// notes, ch. 1, §1.2 Polygonal representation (lab 06), and the arrays OpenGL
// draws from it.
//
// Hierarchy (§1.2, "Hierarchy of the representation", Topology): object →
// surfaces → polygons → edges → vertices. The object is a PolygonMesh; each
// Surface is a list of polygons; each Polygon lists its vertices
// (counter-clockwise seen from outside) and its edges; each Edge joins two
// vertices and knows the polygons that use it; each Vertex is stored once and
// referenced by index everywhere else ("Vertices are stored only once"). The
// attributes are those of §1.2, "Comment on data structures":
//   surface: colour, shading, its polygons
//   polygon: normal (Newell's method), area, flatness (non-planarity)
//   edge:    length, type (feature line, virtual edge, boundary), its polygons
//   vertex:  position, normal, optional colour, its polygons
//
// Sharp edges: §1.2, "Comment on edges", keeps a feature line sharp "by storing
// edges multiple times". render_arrays() does exactly that when it builds what
// glDrawElements needs: a vertex on a feature edge is written once per
// smoothing group, each copy with its own normal.
//
// No GL here; lab 06 draws the arrays. Everything throws std::invalid_argument
// with a message naming the bad value.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mesh/indexed_mesh.h"
#include "spline/vec.h"

namespace gllab {

using spline::Vec3;

struct Colour {
  float r = 0.8f, g = 0.8f, b = 0.8f;
};

/// How a surface is meant to be shaded: one normal per polygon, or normals
/// interpolated across its virtual edges.
enum class Shading { kFlat, kSmooth };

/// Lecture notes ch. 1, §1.2, "Comment on edges": feature lines should stay
/// visible, virtual edges (inside a smooth surface) should disappear after
/// shading. A boundary edge belongs to one polygon only (an open surface).
enum class EdgeType { kVirtual, kFeature, kBoundary };

struct Surface {
  Surface(std::string name = "surface", Colour colour = {}, Shading shading = Shading::kSmooth)
      : name(std::move(name)), colour(colour), shading(shading) {}
  std::string name;
  Colour colour;
  Shading shading;
  std::vector<std::size_t> polygons;  // filled by build_polygon_mesh
};

struct Polygon {
  std::vector<std::size_t> vertices;  // counter-clockwise seen from outside
  std::vector<std::size_t> edges;     // edges[k] joins vertices[k] and vertices[k+1]
  std::size_t surface = 0;
  Vec3 normal;            // unit, by Newell's method
  double area = 0;        // of the polygon projected on its plane
  double flatness = 0;    // largest distance of a vertex from the polygon's plane
};

struct Edge {
  std::size_t v0 = 0, v1 = 0;            // v0 < v1
  std::vector<std::size_t> polygons;     // 2 for a closed surface, 1 on a boundary
  EdgeType type = EdgeType::kVirtual;
  double length = 0;
  double dihedral_degrees = 0;           // angle between the two polygon normals
};

struct Vertex {
  Vec3 position;
  Vec3 normal;                           // mean of the adjacent polygons' normals
  std::optional<Colour> colour;          // else the surface colour is used
  std::vector<std::size_t> polygons;     // polygons that use this vertex
};

/// The object: all surfaces, polygons, edges and vertices, cross-referenced by index.
struct PolygonMesh {
  std::vector<Surface> surfaces;
  std::vector<Polygon> polygons;
  std::vector<Edge> edges;
  std::vector<Vertex> vertices;

  /// Index of the edge joining vertices a and b (either order), or none.
  std::optional<std::size_t> find_edge(std::size_t a, std::size_t b) const;
  std::size_t count(EdgeType type) const;
  /// Triangles the fan triangulation draws: sum of (corners - 2).
  std::size_t triangle_count() const;
};

/// One polygon of the input: vertex indices, counter-clockwise from outside,
/// and the surface it belongs to.
struct PolygonInput {
  std::vector<std::size_t> vertices;
  std::size_t surface = 0;
};

/// Builds the object from vertex positions and polygons. Derives the edges
/// (one per vertex pair, shared by the two polygons that use it), the
/// adjacency lists, polygon normals and areas, vertex normals, and edge types
/// with classify_edges(mesh, 180) (no feature edges until you classify again).
/// Throws, naming the polygon and corner, when a vertex index is out of range,
/// a polygon has fewer than 3 vertices or uses a vertex twice, a polygon is
/// degenerate (area 0), a position is not finite, a surface index is out of
/// range, or two polygons run the same edge in the same direction (their
/// windings disagree).
PolygonMesh build_polygon_mesh(const std::vector<Vec3>& positions, const std::vector<PolygonInput>& polygons,
                               std::vector<Surface> surfaces = {Surface{}});

/// Newell's method for the normal of a polygon that need not be planar:
///   n.x = Σ (y_i − y_{i+1})(z_i + z_{i+1}),  n.y = Σ (z_i − z_{i+1})(x_i + x_{i+1}),
///   n.z = Σ (x_i − x_{i+1})(y_i + y_{i+1})
/// (M. E. Newell; F. Tampieri, "Newell's Method for Computing the Plane Equation
/// of a Polygon", Graphics Gems III, 1992, pp. 231–232). Not normalized: its
/// length is twice the area of the polygon projected on the plane it defines.
Vec3 newell_normal(const std::vector<Vec3>& corners);

/// Sets every edge's type: kBoundary when one polygon uses it, kFeature when
/// its dihedral angle (between the two polygon normals) exceeds
/// `feature_angle_degrees` (an equal angle, up to rounding, does not) or more
/// than two polygons use it, else kVirtual.
/// 0 makes every interior edge of a curved object a feature, 180 none.
/// Returns the number of feature edges.
std::size_t classify_edges(PolygonMesh& mesh, double feature_angle_degrees);

/// Which normals render_arrays() writes.
enum class Normals {
  kFace,          // each polygon its own vertices and its own normal (flat)
  kAveraged,      // each vertex once, normal averaged over all its polygons
  kSplitFeatures  // averaged within smoothing groups: feature edges stay sharp
};

/// The triangles OpenGL draws (positions, normals, colours, indices), each
/// polygon fanned from its first corner (right for convex polygons; a
/// non-convex one needs ear clipping). kSplitFeatures writes a vertex once per
/// smoothing group: the polygons around it that can reach each other without
/// crossing a feature or boundary edge. A polygon of a kFlat surface is a group
/// of its own. Colours: the vertex colour if set, else the surface colour.
IndexedMesh render_arrays(const PolygonMesh& mesh, Normals normals);

/// A plane profile point: distance r >= 0 from the z axis, height z.
struct ProfilePoint {
  double r = 0, z = 0;
};

/// Revolves a profile (listed from bottom to top) about the z axis in
/// `slices` steps. A profile end with r == 0 becomes a pole (a fan of
/// triangles), every other profile segment a ring of quads. Profile segment k
/// goes into surface segment_surface[k] (all into surface 0 when empty).
/// Throws when slices < 3, the profile has < 2 points, an r is negative or
/// an inner point has r == 0, or the sizes disagree.
PolygonMesh make_surface_of_revolution(const std::vector<ProfilePoint>& profile, int slices,
                                       std::vector<Surface> surfaces = {Surface{}},
                                       const std::vector<std::size_t>& segment_surface = {});

/// Half an ellipse from the south pole to the north pole, (a cos t, b sin t)
/// for t from -90 to 90 degrees in n equal steps: n + 1 points, the poles with
/// r = 0 exactly. Revolved, a = b gives a sphere, b < a a lentil.
std::vector<ProfilePoint> half_ellipse_profile(double a, double b, int n);

/// Picks segments + 1 points of a densely sampled profile, first and last
/// included. Each dense segment weighs (1 − c)·length/total length +
/// c·turning/total turning, and the picks split the total weight evenly:
/// c = 0 spaces them uniformly along the curve, c = 1 by curvature only
/// (lecture notes ch. 1, §1.2, "Properties/Characteristics": "choose the
/// polygonal resolution based on the curvature").
/// Throws when segments < 1 or > dense.size() − 1, or c is outside [0, 1].
std::vector<ProfilePoint> resample_profile(const std::vector<ProfilePoint>& dense, int segments,
                                           double curvature_share);

/// How far the true curve (its dense samples) strays from the polyline through
/// `picked`: the largest distance of a dense point from the nearest polyline
/// segment. For a circle of radius ρ cut into chords of angle θ this is the
/// sagitta ρ(1 − cos θ/2), where the chord's midpoint misses the arc.
double profile_deviation(const std::vector<ProfilePoint>& dense, const std::vector<ProfilePoint>& picked);

}  // namespace gllab
