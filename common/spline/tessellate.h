// common/spline/tessellate.h — from curves and surfaces to line strips and
// triangle meshes, to a tolerance.
//
// Notes "Higher Order Surfaces" ("Rendering Bezier Patches"): split a patch until it is
// "sufficiently planar — make a plane out of 3 vertices and measure how far the
// others are from the plane", or "sufficiently small"; and beware of "patch
// cracking: when one patch is subdivided independently of another, cracking
// may occur". This file does exactly that, with a named tolerance:
//
//   curves    flatten_curve: recursive bisection until the chord is within the
//             tolerance of the curve at three interior samples (1/4, 1/2, 3/4).
//   surfaces  tessellate_surface: a restricted quadtree over the (u, v) domain
//             (Von Herzen & Barr, "Accurate triangulations of deformed,
//             intersecting surfaces", SIGGRAPH 1987), split until each cell's two
//             triangles are within the tolerance of the surface; or a fixed
//             u_steps x v_steps grid (GLU_DOMAIN_DISTANCE). Trim loops (trim.h)
//             cut the cells; the pieces are triangulated by ear clipping.
//   cracks    every patch edge is sampled from the edge alone (deterministic),
//             so two patches that share an edge share its vertices;
//             tessellate_patches welds them into one mesh.
//
// Tolerance means parametric error (GLU_OBJECT_PARAMETRIC_ERROR): for every
// triangle and every point (u, v) in it, the distance between the surface
// point S(u, v) and the triangle's point at the same barycentric coordinates.
// The tests measure it at each triangle's barycentre and edge midpoints.
//
// The spline core stays independent of how a surface is evaluated: the caller
// passes a SurfaceEvaluator (point + unit normal at (u, v)), e.g. built from
// surface.h, an analytic sphere, or a student's own Bézier patch.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "spline/trim.h"
#include "spline/types.h"
#include "spline/vec.h"

namespace gllab::spline {

// ---- curves ------------------------------------------------------------------

/// How far a chord may be from its curve piece C(t), t in [a, b]:
///  - Chordal: the distance from C(t) to the chord segment (the geometric
///    error a viewer sees);
///  - Parametric: the distance from C(t) to the chord point at the same
///    fraction (t - a) / (b - a) (what GLU_OBJECT_PARAMETRIC_ERROR bounds).
///    Never smaller than Chordal; it also bounds how far a texture slides.
enum class ChordError { Chordal, Parametric };

inline constexpr int kMinFlattenDepth = 2;    // always at least 2^2 = 4 segments
inline constexpr int kMaxFlattenDepth = 20;   // at most 2^20 segments (a guard, not a goal)
inline constexpr double kFlattenSafety = 0.9; // accept when sampled error <= 0.9 tolerance (see flatten_curve)

struct FlattenOptions {
  double tolerance = 1e-3;
  ChordError error = ChordError::Chordal;
  int min_depth = kMinFlattenDepth;  // bisect at least this often (catches curves whose samples all sit on the chord)
  int max_depth = kMaxFlattenDepth;  // never bisect more often (cusps, discontinuities, NaN)
};

struct CurveSample {
  double t = 0;
  Vec3 point;
};

/// Adaptive flattening by recursive bisection. Returns samples at increasing
/// t from a to b (both included, first.t == a, last.t == b exactly) such that
/// each chord is within options.tolerance of the curve:
///   1. bisect [a, b] at its midpoint until the depth reaches min_depth;
///   2. then accept an interval when the error (ChordError) at its three
///      interior samples t = 1/4, 1/2, 3/4 is <= kFlattenSafety * tolerance,
///      otherwise bisect; stop at max_depth regardless.
/// Why three samples and not just the midpoint: at an inflection the curve
/// crosses its chord, and a symmetric S-shape has its midpoint ON the chord.
/// Why the 0.9: a short piece of a smooth curve deviates from its chord like a
/// cubic f(1 - f)(alpha + beta f); its maximum can exceed the largest of the
/// three samples by up to 9.4 %, so accepting at 0.9 keeps the true error
/// within the tolerance (0.9 x 1.094 < 1).
/// Parameters are a + (b - a) * (k / 2^max_depth), computed the same way every
/// time: two callers flattening the same curve on the same [a, b] get
/// bit-identical samples (the basis of crack-free patch edges).
/// Throws std::invalid_argument for tolerance <= 0 or not finite, a or b not
/// finite, a > b, 0 <= min_depth <= max_depth <= 30 violated, or a curve point
/// that is not finite (naming t).
std::vector<CurveSample> flatten_curve(const std::function<Vec3(double)>& curve, double a, double b,
                                       const FlattenOptions& options = {});

// ---- surfaces --------------------------------------------------------------------

/// What a SurfaceEvaluator returns at (u, v). normal: the surface normal
/// (normalised by the tessellator; if zero, it is taken from du x dv, then
/// from central differences of the point, then from a point a hair inwards,
/// as at a pole). du, dv (the partials S_u, S_v) are optional; when present
/// they let the edge sampling see twist (see tessellate_surface).
struct SurfaceSample {
  Vec3 point;
  Vec3 normal;
  Vec3 du, dv;
};
using SurfaceEvaluator = std::function<SurfaceSample(double u, double v)>;

/// A triangle mesh with one unit normal and one (u, v) per vertex. Triangles
/// are counter-clockwise in (u, v), so their winding agrees with S_u x S_v.
struct Mesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
  std::vector<Vec2> uv;
  std::vector<std::array<int, 3>> triangles;
};

/// GLU_SAMPLING_METHOD, in spirit: Adaptive = GLU_OBJECT_PARAMETRIC_ERROR with
/// GLU_PARAMETRIC_TOLERANCE, FixedSteps = GLU_DOMAIN_DISTANCE (u_steps x v_steps cells).
enum class Sampling { Adaptive, FixedSteps };

/// Triangles with a smaller angle (radians, in 3D) start the sliver flips
/// of an adaptive tessellation (see tessellate_surface).
inline constexpr double kSliverAngle = 15 * 3.14159265358979323846 / 180;

/// An adaptive quadtree leaf holding more trim points is split (so cut cells
/// follow the trim at its own spacing instead of fanning long needles).
inline constexpr int kMaxTrimPointsPerLeaf = 2;
/// The most trim points one patch's trims may need once flattened and refined
/// to the tolerance: 2^20. The labs' trims need a few thousand; a tolerance far
/// below the surface's size (1e-300) would need billions, and is refused with
/// a SplineError (kOutOfRange) naming the tolerance instead.
inline constexpr std::size_t kMaxTrimPoints = std::size_t{1} << 20;

inline constexpr int kMinQuadtreeDepth = 2;   // at least 4 x 4 cells
// The cost of tessellate_surface is a function of its output: about 6 us and
// 400 bytes per triangle on this machine (measured with splinetool tessellate
// on examples/bicubic_surface.json: 12,000 triangles at tolerance 1e-3 in
// 0.13 s and 14 MB; 2,097,152 at 1e-300, where every cell goes to the maximum
// depth, in 13 s and 850 MB). The maximum depth bounds it: at most
// 2 x 4^kMaxQuadtreeDepth triangles per untrimmed patch (plus the trim cuts,
// bounded by kMaxTrimPoints).
inline constexpr int kMaxQuadtreeDepth = 10;  // at most 1024 x 1024 cells
inline constexpr int kMaxQuadtreeDepthLimit = 20;

struct TessellationOptions {
  Sampling sampling = Sampling::Adaptive;
  double tolerance = 1e-3;  // Adaptive: parametric error in object units
  int u_steps = 8;          // FixedSteps: cells along u
  int v_steps = 8;          // FixedSteps: cells along v
  int min_depth = kMinQuadtreeDepth;
  int max_depth = kMaxQuadtreeDepth;

  static TessellationOptions adaptive(double tolerance);
  static TessellationOptions fixed_steps(int u_steps, int v_steps);
};

/// Tessellates one patch over `domain`, optionally trimmed.
///
/// Adaptive (the steps, in the order tessellate.cpp runs them):
///  1. Trims: checked with trim.h's rules and messages; curve pieces
///     flattened on the surface (the 3D curve S(C(t)), chordal error); every
///     trim edge refined until its image is within the tolerance (GLU does not
///     refine gluPwlCurve edges and so fans slivers across the region:
///     docs/glu.md). Stretches of a loop that run along the domain edge only
///     repeat it (the Red Book's outer square) and are moved outside.
///  2. Quadtree over the domain: a cell is split while the surface deviates
///     from the cell's two triangles by more than kFlattenSafety x tolerance at
///     11 samples (centre, edge midpoints, the two barycentres, quarter points)
///     — the "sufficiently planar" test of the notes "Higher Order Surfaces", measured the way the
///     tolerance is defined — or while it holds more than
///     kMaxTrimPointsPerLeaf trim points. Then restricted (neighbouring leaves
///     differ by at most one level; Von Herzen & Barr 1987); a leaf with a
///     smaller neighbour's corner on a side is fanned from its centre
///     (transition triangles), so there are no T-junctions.
///  3. Patch edges are sampled from the edge alone: each side is bisected
///     until the edge curve S(u, v0) (etc.) is within the tolerance of its
///     chords (parametric error, as flatten_curve) and — when the evaluator
///     returns partials — the cross-edge tangent turns little along each
///     segment (|S_v(b) - S_v(a)| h / 4 <= tolerance, h the matching cell
///     size: a bilinear cell's twist error). Leaves along a side are split
///     down to those samples. Where they are finer than their edge segment
///     A-B, their corners on the edge are lifted half a leaf inwards and a
///     band of thin triangles joins A-B to the lifted row: A-B stays one mesh
///     edge. Two patches whose evaluators agree on a shared edge therefore
///     produce the same vertices there.
///  4. Trimmed leaves: the trim polygon is cut along the cell lines; each
///     leaf keeps its part of the trimmed region — the trim segments inside it
///     plus the stretches of its boundary that are inside (winding rule,
///     trim.h) — chained into loops and ear-clipped (triangulate_polygon).
///     Those triangles are then checked at their barycentres and edge
///     midpoints; where one misses the tolerance, its leaves are split and the
///     cutting redone (up to max_depth).
///  5. Edges between a sliver (an angle below kSliverAngle) and its neighbour
///     are flipped when that raises the smaller angle and both new triangles
///     still meet the tolerance (Lawson's edge swapping). Trim and patch
///     edges are mesh boundary edges: never flipped.
///
/// FixedSteps: u_steps x v_steps cells, two triangles each (exactly
/// 2 u_steps v_steps triangles when untrimmed), cut by the trims the same way;
/// trim edges are not refined and nothing is verified (as GLU_DOMAIN_DISTANCE).
///
/// Throws std::invalid_argument for an empty or non-finite domain, bad
/// options, invalid trims (trim.h messages), or a surface point or normal that
/// is not finite (naming u, v).
Mesh tessellate_surface(const SurfaceEvaluator& surface, UvDomain domain, const TessellationOptions& options,
                        const std::vector<TrimLoop>& trims = {});

/// One patch of a multi-patch surface.
struct Patch {
  SurfaceEvaluator surface;
  UvDomain domain;
  std::vector<TrimLoop> trims;
};

/// Vertices closer than this (object units) are merged by tessellate_patches.
inline constexpr double kWeldTolerance = 1e-9;

/// Tessellates each patch with the same options and welds them into one mesh:
/// vertices within weld_tolerance of each other become one (the first patch's
/// normal and (u, v) are kept), and triangles that collapse are dropped.
/// Patches sharing an edge share its samples (see tessellate_surface), so the
/// welded mesh has no cracks and no T-junctions along that edge. The samples
/// are bit-identical when both patches evaluate the edge identically (one
/// surface split along a knot or a parameter value); separately written
/// patches (e.g. the two halves of a subdivided Bézier net) agree up to
/// round-off, which welding absorbs, unless a flatness test lands exactly on
/// its threshold. The twist term assumes the same parameter width across
/// the edge on both sides (as in a split domain).
Mesh tessellate_patches(const std::vector<Patch>& patches, const TessellationOptions& options,
                        double weld_tolerance = kWeldTolerance);

/// Merges meshes and welds their vertices as tessellate_patches does.
Mesh weld(const std::vector<Mesh>& meshes, double weld_tolerance = kWeldTolerance);

// ---- polygons and mesh measures ------------------------------------------------------

/// Ear clipping (Meisters' two-ears theorem, 1975; Eberly, "Triangulation by
/// Ear Clipping", 2002) of a polygon with holes: loops[0] is the outer boundary
/// (counter-clockwise), loops[1..] are holes inside it (clockwise). Holes are
/// joined to the outer boundary by bridge edges (Eberly §3). Among the current
/// ears the one with the largest smallest angle is cut first, which avoids
/// most slivers. Points exactly on an edge (collinear) stay vertices, so a
/// neighbour's vertex on a shared edge never becomes a T-junction.
/// Returns triangles as indices into the concatenation of the loops (loop 0's
/// points first), counter-clockwise. n - 2 + 2h triangles for n points in
/// total and h holes, fewer only if a degenerate (zero-area) polygon remains.
std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<std::vector<Vec2>>& loops);

/// Sum of the triangle areas.
double mesh_area(const Mesh& mesh);

/// Edges used by exactly one triangle (the mesh boundary), as (a, b) in the
/// direction the triangle runs. A crack-free mesh of an open surface has only
/// its outline here.
std::vector<std::array<int, 2>> boundary_edges(const Mesh& mesh);

/// Iso-curves (ch. 1 §1.7, "Iso-curves": the height curves f = const of a
/// scalar field) on a triangle mesh: where the height h(p) = dot(p, direction),
/// linear on each triangle, equals level. Each triangle the level crosses
/// gives one segment between the two edge points where h = level (linear
/// interpolation along the edge; "marching triangles"). A vertex exactly at
/// the level counts as above it (a level through a row of vertices is drawn
/// once, and a vertex that only touches the level gives no point-sized
/// segment; only a mesh edge at the level with both neighbours below, a ridge
/// touching it, is drawn by both triangles). Every edge point is computed
/// from the edge's two vertices in index order, so the segments of
/// neighbouring triangles meet exactly. On a mesh within tolerance e of a surface, the points lie within
/// e of the surface's iso-curve in height. Throws for a zero or non-finite
/// direction or a non-finite level.
std::vector<std::array<Vec3, 2>> contour_segments(const Mesh& mesh, Vec3 direction, double level);

/// The area of the surface over the (u, v) triangles of a mesh: for each
/// triangle, the integral of |S_u x S_v| over its (u, v) corners, by Radon's
/// 7-point rule, exact for polynomials of degree 5 (Stroud, "Approximate
/// Calculation of Multiple Integrals", 1971, formula T2:5-1). When the (u, v)
/// triangles tile a trimmed region, as tessellate_surface's do, this is the
/// area of the trimmed surface itself, however well or badly the triangles
/// follow it in 3D: the reference against which mesh_area is judged.
/// The evaluator must return the partials du, dv (surface_evaluator does).
double surface_area(const SurfaceEvaluator& surface, const Mesh& mesh);

/// How closely a mesh with a (u, v) per vertex follows its surface S
/// (mesh_fidelity). T(u, v) is a triangle's point at the barycentric
/// coordinates (u, v) has among its (u, v) corners.
struct MeshFidelity {
  /// max |S(u, v) - T(u, v)| at every triangle's barycentre and edge
  /// midpoints: the parametric error tessellate_surface's tolerance bounds.
  double max_deviation = 0;
  /// The same at the quarter points of every boundary edge (the edges used
  /// by one triangle once coincident vertices are welded): how closely the
  /// mesh's rim follows the surface along its trim (and patch) edges. GLU
  /// draws a gluPwlCurve edge as one chord, so here it can be far off.
  double max_trim_deviation = 0;
  /// Triangles whose normal (P1 - P0) x (P2 - P0) is more than tilt_degrees
  /// from the surface normal at their (u, v) barycentre (a reversed triangle
  /// is tilted by about 180): how many, which (indices into mesh.triangles,
  /// ascending), and the largest tilt. Triangles of zero area have no normal
  /// and are not counted.
  std::size_t tilted_faces = 0;
  std::vector<std::size_t> tilted;
  double max_tilt_degrees = 0;
};

/// Measures a mesh against the surface it came from: the own tessellation,
/// or GLU's (gllab::GluNurbs capture mode gives every vertex its (u, v)).
/// Vertices closer than weld_tolerance count as one for the boundary (GLU
/// sends each strip's vertices again). Throws std::invalid_argument for
/// tilt_degrees outside [0, 180], a bad weld_tolerance, or a mesh whose uv
/// or triangle indices do not fit its positions.
MeshFidelity mesh_fidelity(const Mesh& mesh, const SurfaceEvaluator& surface, double tilt_degrees,
                           double weld_tolerance = kWeldTolerance);

}  // namespace gllab::spline
