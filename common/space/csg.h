// common/space/csg.h — constructive solid geometry (lecture notes ch. 1, "3-D Graphics",
// "Solid Representation", "Constructive Solid Geometry": primitives combined by union,
// intersection and difference and by linear transforms, stored as a tree with the
// primitives in the leaves and the operators or transforms in the nodes).
//
// What it answers, with no GL:
//  - classify: is a point inside, outside or on the solid (point-membership classification);
//  - ray_spans / first_hit: where a ray is inside the solid, exactly, by combining each
//    primitive's ray interval with the tree's operators (Roth 1982, "Ray casting for
//    modeling solids");
//  - cast_image: the first hit through every pixel centre of a camera (the ground truth
//    the stencil rendering of lab 33 is compared with);
//  - volume_monte_carlo / volume_by_rays: the volume, with its error estimate;
//  - sum_of_products: the tree as a union of products of primitives and complements
//    (Goldfeather, Molnar, Turk and Fuchs 1989), the form the image-based CSG algorithms
//    draw.
// Every primitive is convex: a sphere, a capped cylinder, a box or a capped cone, centred on
// the origin of its own coordinates (cylinder and cone along z, z in [-h/2, h/2], the cone's
// apex at +h/2), and placed by the affine transforms above it.
//
// Bad input throws std::invalid_argument with one line naming the value, e.g.
// "csg: sphere radius -1 (must be > 0)", "csg: the transform is singular (det = 0)".
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "space/box.h"

namespace gllab::space {

/// x' = L x + t, L row-major (a 3 x 4 matrix).
struct Affine {
  std::array<double, 12> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  Vec3 apply(Vec3 p) const;         // L p + t
  Vec3 apply_linear(Vec3 v) const;  // L v
  Vec3 apply_transpose(Vec3 v) const;  // L^T v (normals go through the inverse's transpose)
  double determinant() const;          // det L
  Affine inverse() const;              // throws std::invalid_argument when det L = 0
  double norm() const;                 // the operator 2-norm of L (its largest singular value)
  /// The 4 x 4 matrix in OpenGL's column-major order (for glMultMatrixd).
  std::array<double, 16> gl_matrix() const;

  static Affine translate(Vec3 t);
  static Affine scale(Vec3 s);
  static Affine rotate(Vec3 axis, double degrees);  // right-handed about a non-zero axis
};
Affine operator*(const Affine& a, const Affine& b);  // a after b

enum class Shape { kSphere, kCylinder, kBox, kCone };
enum class Op { kPrimitive, kUnion, kIntersection, kDifference, kTransform };

const char* shape_name(Shape s);  // "sphere", "cylinder", "box", "cone"
const char* op_name(Op o);        // "primitive", "union", "intersection", "difference", "transform"
const char* op_symbol(Op o);      // "∪", "∩", "−", "T", ""

struct CsgNode {
  Op op = Op::kPrimitive;
  // kPrimitive: the shape and its sizes (radius for sphere, cylinder, cone; height for
  // cylinder and cone; size = the box's edge lengths).
  Shape shape = Shape::kSphere;
  double radius = 1, height = 1;
  Vec3 size{1, 1, 1};
  // kTransform: maps the child's coordinates to this node's.
  Affine transform;
  int left = -1, right = -1;  // children (kTransform: left only)
  std::string name;           // a label for diagrams ("box", "cyl x", ...); may be empty
};

/// A primitive with the product of the transforms above it.
struct CsgLeaf {
  int node = -1;     // its index in CsgTree::nodes()
  Shape shape = Shape::kSphere;
  double radius = 1, height = 1;
  Vec3 size{1, 1, 1};
  Affine to_world;   // local -> world
  Affine to_local;   // world -> local
  std::string name;
};

class CsgTree {
 public:
  // Building: each call adds a node and returns its index; the last node added is the
  // root unless set_root says otherwise. Sizes must be > 0 and finite, transforms invertible.
  int sphere(double radius, std::string name = {});
  int cylinder(double radius, double height, std::string name = {});
  int box(Vec3 size, std::string name = {});
  int cone(double radius, double height, std::string name = {});
  int unite(int a, int b);
  int intersect(int a, int b);
  int subtract(int a, int b);  // a − b
  int transform(const Affine& t, int child);
  void set_root(int node);

  int root() const { return root_; }
  const std::vector<CsgNode>& nodes() const { return nodes_; }
  /// The primitives in depth-first, left-to-right order; a primitive's index here is its
  /// "primitive id" everywhere else (hits, products, colours).
  const std::vector<CsgLeaf>& leaves() const { return leaves_; }
  /// A box around the solid: unions join their children's boxes, intersections intersect
  /// them, a difference keeps its left box.
  Box3 bounds() const;

 private:
  int add(CsgNode n);
  void rebuild_leaves();
  std::vector<CsgNode> nodes_;
  std::vector<CsgLeaf> leaves_;
  int root_ = -1;
};

// --- Point-membership classification ---------------------------------------------------

enum class Where { kInside, kOutside, kOn };
const char* where_name(Where w);  // "inside", "outside", "on"

/// The primitive's signed distance in its own coordinates (negative inside; exact for the
/// sphere, box, cylinder and cone) divided by to_local.norm(): a lower bound of the world
/// distance to its surface (equal to it for rigid motions and uniform scales).
double leaf_distance(const CsgLeaf& leaf, Vec3 world_point);

/// Each primitive: on when |leaf_distance| <= tolerance, else inside or outside; combined
/// by the tree with the regularized rules (on ∪ inside = inside, on ∩ outside = outside,
/// inside − on = on, ...). tolerance >= 0.
Where classify(const CsgTree& tree, Vec3 p, double tolerance = 1e-9);

// --- Rays (Roth 1982) ----------------------------------------------------------------------

/// Where a ray enters or leaves the solid: the parameter t, the primitive whose surface it
/// is, and the solid's outward unit normal there (world coordinates; a subtracted primitive's
/// surface has its normal flipped).
struct SpanEnd {
  double t = 0;
  int primitive = -1;
  Vec3 normal{0, 0, 0};
};
struct Span {
  SpanEnd in, out;  // in.t < out.t
};

/// The parts of the ray origin + t·direction, t in [t_min, t_max], inside the solid, sorted
/// and disjoint (spans that touch are merged). Each primitive's convex interval is combined
/// by the tree's operators; a span of zero length is dropped. A span cut by t_min (the ray
/// starts inside) or by t_max has that end at t_min or t_max with primitive -1, normal 0.
std::vector<Span> ray_spans(const CsgTree& tree, Vec3 origin, Vec3 direction,
                            double t_min = 0, double t_max = 1e300);

struct CsgHit {
  bool hit = false;
  double t = 0;
  Vec3 point{0, 0, 0}, normal{0, 0, 0};
  int primitive = -1;
};
/// The first surface the ray meets at t > t_min (a ray starting inside the solid meets the
/// surface where it leaves).
CsgHit first_hit(const CsgTree& tree, Vec3 origin, Vec3 direction, double t_min = 0);

/// A camera as OpenGL sets it: the inverse of projection × modelview (column-major, as
/// glGetDoublev returns the matrices) and the viewport in pixels.
struct PixelCamera {
  std::array<double, 16> inverse_mvp{};
  int x = 0, y = 0, width = 0, height = 0;  // glViewport
};
/// OpenGL's inverse(projection × modelview), column-major, from the two matrices as
/// glGetDoublev(GL_PROJECTION_MATRIX / GL_MODELVIEW_MATRIX) gives them. Throws when singular.
std::array<double, 16> inverse_mvp(const std::array<double, 16>& projection,
                                   const std::array<double, 16>& modelview);

/// Rows bottom-up like glReadPixels: pixel (i, j) at index j * width + i; the ray through the
/// pixel centre (x + i + 0.5, y + j + 0.5) from the near plane to the far plane (t in [0, 1]).
struct CastPixel {
  int primitive = -1;  // -1: background
  double depth = 1;    // window depth in [0, 1] as the depth buffer would hold it
  Vec3 normal{0, 0, 0};
};
std::vector<CastPixel> cast_image(const CsgTree& tree, const PixelCamera& camera);

// --- Volume --------------------------------------------------------------------------------

struct VolumeEstimate {
  double value = 0;
  double error = 0;  // see each function
  std::size_t samples = 0;
};
/// Uniform points in tree.bounds() (std::mt19937_64 seeded with `seed`): value = box volume ×
/// share inside, error = 3 standard errors (a 99.7 % interval).
VolumeEstimate volume_monte_carlo(const CsgTree& tree, std::size_t samples, std::uint64_t seed = 1);
/// Rays along z through the centres of an n × n grid over the bounds' x-y rectangle: each
/// ray's inside length is exact (ray_spans), so only the 2-D midpoint rule errs.
/// error = |V(n) − V(n/2)| (the change from the half grid; n even), an estimate.
VolumeEstimate volume_by_rays(const CsgTree& tree, int n);

// --- Sum of products -----------------------------------------------------------------------

struct Literal {
  int primitive = -1;
  bool complement = false;  // true: the outside of the primitive (it is subtracted)
};
/// One product: the intersection of its literals; at least one is not a complement.
using Product = std::vector<Literal>;
/// The tree as a union of products (Goldfeather et al. 1989, the normalization rules):
/// A − (B ∪ C) = (A − B) − C, A ∩ (B ∪ C) = (A ∩ B) ∪ (A ∩ C), A − (B ∩ C) = (A − B) ∪ (A − C),
/// A − (B − C) = (A − B) ∪ (A ∩ C), ... Products that hold a primitive and its complement
/// are dropped (they are empty).
std::vector<Product> sum_of_products(const CsgTree& tree);

// --- Trees to test and show ----------------------------------------------------------------

struct NamedTree {
  std::string name, formula;  // "classic", "(box ∩ sphere) − (cyl x ∪ cyl y ∪ cyl z)"
  CsgTree tree;
};
/// The trees lab 33 shows and the tests check: [0] the classic box ∩ sphere minus three
/// cylinders, then twelve more, with nested differences, transforms under operators, every
/// shape, non-uniform scales and rotations, then "sieve 4", "sieve 8" and "sieve 16" (one
/// product of 4, 8 and 16 primitives, for the benchmark). All fit in [-1.2, 1.2]^3, and no two
/// faces lie in one plane (image-based CSG cannot order coplanar faces).
const std::vector<NamedTree>& csg_catalogue();

}  // namespace gllab::space
