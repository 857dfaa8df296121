// common/space/csg.cpp — CSG trees, point classification, Roth's ray casting, volumes and the
// sum-of-products form (csg.h).
#include "space/csg.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>

#include "space/symmetric_eigen.h"

namespace gllab::space {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("csg: " + what); }

std::string number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}
std::string vec_text(Vec3 v) {
  return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")";
}
double length(Vec3 v) { return spline::norm(v); }
bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void require_size(double v, const char* shape, const char* what) {
  if (!std::isfinite(v) || v <= 0)
    fail(std::string(shape) + " " + what + " " + number(v) + " (must be > 0)");
}

}  // namespace

// --- Affine ---------------------------------------------------------------------------------

Vec3 Affine::apply(Vec3 p) const { return apply_linear(p) + Vec3{m[3], m[7], m[11]}; }
Vec3 Affine::apply_linear(Vec3 v) const {
  return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[4] * v.x + m[5] * v.y + m[6] * v.z,
          m[8] * v.x + m[9] * v.y + m[10] * v.z};
}
Vec3 Affine::apply_transpose(Vec3 v) const {
  return {m[0] * v.x + m[4] * v.y + m[8] * v.z, m[1] * v.x + m[5] * v.y + m[9] * v.z,
          m[2] * v.x + m[6] * v.y + m[10] * v.z};
}
double Affine::determinant() const {
  return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
         m[2] * (m[4] * m[9] - m[5] * m[8]);
}
Affine Affine::inverse() const {
  const double det = determinant();
  if (det == 0 || !std::isfinite(det)) fail("the transform is singular (det = " + number(det) + ")");
  Affine r;  // the adjugate over the determinant, then -L^-1 t
  r.m[0] = (m[5] * m[10] - m[6] * m[9]) / det;
  r.m[1] = (m[2] * m[9] - m[1] * m[10]) / det;
  r.m[2] = (m[1] * m[6] - m[2] * m[5]) / det;
  r.m[4] = (m[6] * m[8] - m[4] * m[10]) / det;
  r.m[5] = (m[0] * m[10] - m[2] * m[8]) / det;
  r.m[6] = (m[2] * m[4] - m[0] * m[6]) / det;
  r.m[8] = (m[4] * m[9] - m[5] * m[8]) / det;
  r.m[9] = (m[1] * m[8] - m[0] * m[9]) / det;
  r.m[10] = (m[0] * m[5] - m[1] * m[4]) / det;
  const Vec3 t = r.apply_linear({m[3], m[7], m[11]});
  r.m[3] = -t.x;
  r.m[7] = -t.y;
  r.m[11] = -t.z;
  return r;
}
double Affine::norm() const {
  // The largest singular value: the square root of L^T L's largest eigenvalue.
  double a[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) a[i][j] += m[4 * k + i] * m[4 * k + j];
  return std::sqrt(std::max(0.0, symmetric_eigen(a).values[0]));
}
std::array<double, 16> Affine::gl_matrix() const {
  return {m[0], m[4], m[8], 0, m[1], m[5], m[9], 0, m[2], m[6], m[10], 0, m[3], m[7], m[11], 1};
}
Affine Affine::translate(Vec3 t) {
  if (!finite(t)) fail("translation " + vec_text(t) + " is not finite");
  Affine a;
  a.m[3] = t.x;
  a.m[7] = t.y;
  a.m[11] = t.z;
  return a;
}
Affine Affine::scale(Vec3 s) {
  if (!finite(s) || s.x == 0 || s.y == 0 || s.z == 0)
    fail("scale " + vec_text(s) + " is singular or not finite");
  Affine a;
  a.m[0] = s.x;
  a.m[5] = s.y;
  a.m[10] = s.z;
  return a;
}
Affine Affine::rotate(Vec3 axis, double degrees) {
  const double len = length(axis);
  if (!finite(axis) || !(len > 0) || !std::isfinite(degrees))
    fail("rotation about " + vec_text(axis) + " by " + number(degrees) + " degrees");
  const Vec3 u = (1 / len) * axis;  // Rodrigues: R = cI + s[u]x + (1 - c) u u^T
  const double r = degrees * M_PI / 180, c = std::cos(r), s = std::sin(r), k = 1 - c;
  Affine a;
  a.m = {c + k * u.x * u.x,       k * u.x * u.y - s * u.z, k * u.x * u.z + s * u.y, 0,
         k * u.y * u.x + s * u.z, c + k * u.y * u.y,       k * u.y * u.z - s * u.x, 0,
         k * u.z * u.x - s * u.y, k * u.z * u.y + s * u.x, c + k * u.z * u.z,       0};
  return a;
}
Affine operator*(const Affine& a, const Affine& b) {
  Affine r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) {
      double v = j == 3 ? a.m[4 * i + 3] : 0;
      for (int k = 0; k < 3; ++k) v += a.m[4 * i + k] * b.m[4 * k + j];
      r.m[4 * i + j] = v;
    }
  return r;
}

const char* shape_name(Shape s) {
  switch (s) {
    case Shape::kSphere: return "sphere";
    case Shape::kCylinder: return "cylinder";
    case Shape::kBox: return "box";
    case Shape::kCone: return "cone";
  }
  return "?";
}
const char* op_name(Op o) {
  switch (o) {
    case Op::kPrimitive: return "primitive";
    case Op::kUnion: return "union";
    case Op::kIntersection: return "intersection";
    case Op::kDifference: return "difference";
    case Op::kTransform: return "transform";
  }
  return "?";
}
const char* op_symbol(Op o) {
  switch (o) {
    case Op::kUnion: return "∪";
    case Op::kIntersection: return "∩";
    case Op::kDifference: return "−";
    case Op::kTransform: return "T";
    default: return "";
  }
}
const char* where_name(Where w) {
  return w == Where::kInside ? "inside" : w == Where::kOutside ? "outside" : "on";
}

// --- The tree -------------------------------------------------------------------------------

int CsgTree::add(CsgNode n) {
  for (int child : {n.left, n.right})
    if (child >= int(nodes_.size()))
      fail(std::string(op_name(n.op)) + ": child " + std::to_string(child) + " does not exist (" +
           std::to_string(nodes_.size()) + " nodes)");
  nodes_.push_back(std::move(n));
  root_ = int(nodes_.size()) - 1;
  rebuild_leaves();
  return root_;
}
int CsgTree::sphere(double radius, std::string name) {
  require_size(radius, "sphere", "radius");
  CsgNode n;
  n.shape = Shape::kSphere, n.radius = radius, n.name = std::move(name);
  return add(std::move(n));
}
int CsgTree::cylinder(double radius, double height, std::string name) {
  require_size(radius, "cylinder", "radius");
  require_size(height, "cylinder", "height");
  CsgNode n;
  n.shape = Shape::kCylinder, n.radius = radius, n.height = height, n.name = std::move(name);
  return add(std::move(n));
}
int CsgTree::cone(double radius, double height, std::string name) {
  require_size(radius, "cone", "radius");
  require_size(height, "cone", "height");
  CsgNode n;
  n.shape = Shape::kCone, n.radius = radius, n.height = height, n.name = std::move(name);
  return add(std::move(n));
}
int CsgTree::box(Vec3 size, std::string name) {
  require_size(size.x, "box", "size x");
  require_size(size.y, "box", "size y");
  require_size(size.z, "box", "size z");
  CsgNode n;
  n.shape = Shape::kBox, n.size = size, n.name = std::move(name);
  return add(std::move(n));
}
namespace {
CsgNode binary(Op op, int a, int b) {
  if (a < 0 || b < 0) fail(std::string(op_name(op)) + ": child " + std::to_string(std::min(a, b)));
  CsgNode n;
  n.op = op, n.left = a, n.right = b;
  return n;
}
}  // namespace
int CsgTree::unite(int a, int b) { return add(binary(Op::kUnion, a, b)); }
int CsgTree::intersect(int a, int b) { return add(binary(Op::kIntersection, a, b)); }
int CsgTree::subtract(int a, int b) { return add(binary(Op::kDifference, a, b)); }
int CsgTree::transform(const Affine& t, int child) {
  for (double v : t.m)
    if (!std::isfinite(v)) fail("a transform entry is " + number(v));
  t.inverse();  // throws when singular
  if (child < 0) fail("transform: child " + std::to_string(child));
  CsgNode n;
  n.op = Op::kTransform, n.transform = t, n.left = child;
  return add(std::move(n));
}
void CsgTree::set_root(int node) {
  if (node < 0 || node >= int(nodes_.size()))
    fail("root " + std::to_string(node) + " does not exist");
  root_ = node;
  rebuild_leaves();
}

void CsgTree::rebuild_leaves() {
  leaves_.clear();
  const std::function<void(int, const Affine&, int)> walk = [&](int i, const Affine& to_world,
                                                                int depth) {
    if (depth > 10000) fail("the tree is deeper than 10000 levels");
    const CsgNode& n = nodes_[std::size_t(i)];
    if (n.op == Op::kPrimitive) {
      CsgLeaf l;
      l.node = i, l.shape = n.shape, l.radius = n.radius, l.height = n.height, l.size = n.size;
      l.to_world = to_world, l.to_local = to_world.inverse(), l.name = n.name;
      if (l.name.empty()) l.name = shape_name(n.shape);
      leaves_.push_back(l);
    } else if (n.op == Op::kTransform) {
      walk(n.left, to_world * n.transform, depth + 1);
    } else {
      walk(n.left, to_world, depth + 1);
      walk(n.right, to_world, depth + 1);
    }
  };
  if (root_ >= 0) walk(root_, Affine{}, 0);
}

namespace {
Box3 local_box(const CsgLeaf& l) {
  const double r = l.radius, h = l.height / 2;
  switch (l.shape) {
    case Shape::kSphere: return {{-r, -r, -r}, {r, r, r}};
    case Shape::kBox: return {-0.5 * l.size, 0.5 * l.size};
    default: return {{-r, -r, -h}, {r, r, h}};
  }
}
Box3 world_box(const CsgLeaf& l) {
  const Box3 b = local_box(l);
  Box3 out{{kInf, kInf, kInf}, {-kInf, -kInf, -kInf}};
  for (int c = 0; c < 8; ++c) {
    const Vec3 p = l.to_world.apply(
        {c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y, c & 4 ? b.hi.z : b.lo.z});
    out.lo = {std::min(out.lo.x, p.x), std::min(out.lo.y, p.y), std::min(out.lo.z, p.z)};
    out.hi = {std::max(out.hi.x, p.x), std::max(out.hi.y, p.y), std::max(out.hi.z, p.z)};
  }
  return out;
}
// Which leaf each primitive node is (by node index).
std::vector<int> leaf_index(const CsgTree& t) {
  std::vector<int> of(t.nodes().size(), -1);
  for (std::size_t i = 0; i < t.leaves().size(); ++i) of[std::size_t(t.leaves()[i].node)] = int(i);
  return of;
}
}  // namespace

Box3 CsgTree::bounds() const {
  if (root_ < 0) return {};
  const std::vector<int> leaf = leaf_index(*this);
  const std::function<Box3(int)> box_of = [&](int i) -> Box3 {
    const CsgNode& n = nodes_[std::size_t(i)];
    if (n.op == Op::kPrimitive) return world_box(leaves_[std::size_t(leaf[std::size_t(i)])]);
    if (n.op == Op::kTransform) return box_of(n.left);
    const Box3 a = box_of(n.left);
    if (n.op == Op::kDifference) return a;
    const Box3 b = box_of(n.right);
    if (n.op == Op::kUnion)
      return {{std::min(a.lo.x, b.lo.x), std::min(a.lo.y, b.lo.y), std::min(a.lo.z, b.lo.z)},
              {std::max(a.hi.x, b.hi.x), std::max(a.hi.y, b.hi.y), std::max(a.hi.z, b.hi.z)}};
    Box3 c{{std::max(a.lo.x, b.lo.x), std::max(a.lo.y, b.lo.y), std::max(a.lo.z, b.lo.z)},
           {std::min(a.hi.x, b.hi.x), std::min(a.hi.y, b.hi.y), std::min(a.hi.z, b.hi.z)}};
    c.hi = {std::max(c.hi.x, c.lo.x), std::max(c.hi.y, c.lo.y), std::max(c.hi.z, c.lo.z)};
    return c;
  };
  return box_of(root_);
}

// --- Classification -------------------------------------------------------------------------

namespace {
// The exact signed distance of each shape in its own coordinates.
double local_distance(const CsgLeaf& l, Vec3 p) {
  const double r = l.radius, h = l.height / 2;
  switch (l.shape) {
    case Shape::kSphere:
      return length(p) - r;
    case Shape::kBox: {
      const Vec3 q{std::abs(p.x) - l.size.x / 2, std::abs(p.y) - l.size.y / 2,
                   std::abs(p.z) - l.size.z / 2};
      const Vec3 out{std::max(q.x, 0.0), std::max(q.y, 0.0), std::max(q.z, 0.0)};
      return length(out) + std::min(std::max({q.x, q.y, q.z}), 0.0);
    }
    case Shape::kCylinder: {
      const double a = std::hypot(p.x, p.y) - r, b = std::abs(p.z) - h;
      return std::hypot(std::max(a, 0.0), std::max(b, 0.0)) + std::min(std::max(a, b), 0.0);
    }
    case Shape::kCone: {
      // In the (rho, z) half-plane the cone is the triangle (0, -h), (r, -h), (0, h); the
      // axis side is no boundary. Outside: the distance to the base or the slant segment;
      // inside: the nearer of their lines.
      const double rho = std::hypot(p.x, p.y), z = p.z;
      const auto segment = [&](double ax, double az, double bx, double bz) {
        const double dx = bx - ax, dz = bz - az;
        const double t = std::clamp(((rho - ax) * dx + (z - az) * dz) / (dx * dx + dz * dz), 0.0, 1.0);
        return std::hypot(rho - ax - t * dx, z - az - t * dz);
      };
      const double slant = std::hypot(r, 2 * h);
      const double to_slant_line = (2 * h * rho + r * z - r * h) / slant;  // > 0 outside
      const bool inside = z >= -h && to_slant_line <= 0;
      if (inside) return -std::min(z + h, -to_slant_line);
      return std::min(segment(0, -h, r, -h), segment(r, -h, 0, h));
    }
  }
  return kInf;
}

Where combine(Op op, Where a, Where b) {
  using W = Where;
  switch (op) {
    case Op::kUnion:
      if (a == W::kInside || b == W::kInside) return W::kInside;
      return a == W::kOn || b == W::kOn ? W::kOn : W::kOutside;
    case Op::kIntersection:
      if (a == W::kOutside || b == W::kOutside) return W::kOutside;
      return a == W::kOn || b == W::kOn ? W::kOn : W::kInside;
    default:  // a − b
      if (a == W::kOutside || b == W::kInside) return W::kOutside;
      return a == W::kInside && b == W::kOutside ? W::kInside : W::kOn;
  }
}
}  // namespace

double leaf_distance(const CsgLeaf& leaf, Vec3 p) {
  return local_distance(leaf, leaf.to_local.apply(p)) / leaf.to_local.norm();
}

Where classify(const CsgTree& tree, Vec3 p, double tolerance) {
  if (!finite(p)) fail("point " + vec_text(p) + " is not finite");
  if (!(tolerance >= 0) || !std::isfinite(tolerance))
    fail("tolerance " + number(tolerance) + " (must be >= 0)");
  if (tree.root() < 0) fail("the tree is empty");
  const std::vector<int> leaf = leaf_index(tree);
  const std::function<Where(int)> at = [&](int i) {
    const CsgNode& n = tree.nodes()[std::size_t(i)];
    if (n.op == Op::kPrimitive) {
      const double d = leaf_distance(tree.leaves()[std::size_t(leaf[std::size_t(i)])], p);
      return std::abs(d) <= tolerance ? Where::kOn : d < 0 ? Where::kInside : Where::kOutside;
    }
    if (n.op == Op::kTransform) return at(n.left);
    return combine(n.op, at(n.left), at(n.right));
  };
  return at(tree.root());
}

// --- Rays (Roth 1982) ---------------------------------------------------------------------

namespace {

using Spans = std::vector<Span>;

// Narrows [in, out] to where the ray is between two parallel planes coord = -c .. c along the
// local axis `axis` (0 x, 1 y, 2 z); false when nothing is left.
bool clip_slab(double o, double d, double c, int axis, SpanEnd& in, SpanEnd& out) {
  Vec3 n{0, 0, 0};
  if (d == 0) return std::abs(o) <= c;
  double t0 = (-c - o) / d, t1 = (c - o) / d;
  double s0 = -1, s1 = 1;  // the outward normal's sign at t0 and t1
  if (t0 > t1) std::swap(t0, t1), std::swap(s0, s1);
  if (t0 > in.t) {
    in.t = t0;
    n = {0, 0, 0};
    (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = s0;
    in.normal = n;
  }
  if (t1 < out.t) {
    out.t = t1;
    n = {0, 0, 0};
    (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = s1;
    out.normal = n;
  }
  return in.t < out.t;
}

// Narrows [in, out] to where q(t) = A t^2 + B t + C <= 0, the quadric's inside, when that is
// one interval within [in, out] (a convex piece); grad gives the outward normal at a point.
bool clip_quadric(double A, double B, double C, Vec3 o, Vec3 d,
                  const std::function<Vec3(Vec3)>& grad, SpanEnd& in, SpanEnd& out) {
  double lo = -kInf, hi = kInf;  // the part of {q <= 0} that meets [in, out]
  if (std::abs(A) < 1e-300) {
    if (B == 0) return C <= 0 && in.t < out.t;
    (B > 0 ? hi : lo) = -C / B;
  } else {
    const double disc = B * B - 4 * A * C;
    if (disc < 0) {
      if (A > 0) return false;  // never inside
    } else {
      const double s = std::sqrt(disc), q = -0.5 * (B + (B >= 0 ? s : -s));
      double r0 = q / A, r1 = q != 0 ? C / q : r0;  // the stable pair of roots
      if (r0 > r1) std::swap(r0, r1);
      if (A > 0) {
        lo = r0, hi = r1;
      } else if (r1 <= in.t) {  // inside outside [r0, r1]: keep the piece that meets [in, out]
        lo = r1;
      } else {
        hi = r0;
      }
    }
  }
  if (lo > in.t) in.t = lo, in.normal = normalized(grad(o + lo * d));
  if (hi < out.t) out.t = hi, out.normal = normalized(grad(o + hi * d));
  return in.t < out.t;
}

// The primitive's ray interval in its own coordinates (local normals), or none.
bool primitive_span(const CsgLeaf& l, Vec3 o, Vec3 d, Span& s) {
  s.in = {-kInf, 0, {0, 0, 0}};
  s.out = {kInf, 0, {0, 0, 0}};
  const double r = l.radius, h = l.height / 2;
  switch (l.shape) {
    case Shape::kSphere:
      return clip_quadric(dot(d, d), 2 * dot(o, d), dot(o, o) - r * r, o, d,
                          [](Vec3 p) { return p; }, s.in, s.out);
    case Shape::kBox:
      return clip_slab(o.x, d.x, l.size.x / 2, 0, s.in, s.out) &&
             clip_slab(o.y, d.y, l.size.y / 2, 1, s.in, s.out) &&
             clip_slab(o.z, d.z, l.size.z / 2, 2, s.in, s.out);
    case Shape::kCylinder:
      return clip_slab(o.z, d.z, h, 2, s.in, s.out) &&
             clip_quadric(d.x * d.x + d.y * d.y, 2 * (o.x * d.x + o.y * d.y),
                          o.x * o.x + o.y * o.y - r * r, o, d,
                          [](Vec3 p) { return Vec3{p.x, p.y, 0}; }, s.in, s.out);
    case Shape::kCone: {
      // x^2 + y^2 <= k^2 (h - z)^2 with k = r / 2h; in the slab only the nappe below the apex.
      const double k2 = (r / (2 * h)) * (r / (2 * h));
      const double ez = h - o.z;  // (h - z) = ez - t dz
      return clip_slab(o.z, d.z, h, 2, s.in, s.out) &&
             clip_quadric(d.x * d.x + d.y * d.y - k2 * d.z * d.z,
                          2 * (o.x * d.x + o.y * d.y + k2 * ez * d.z),
                          o.x * o.x + o.y * o.y - k2 * ez * ez, o, d,
                          [k2, h](Vec3 p) { return Vec3{p.x, p.y, k2 * (h - p.z)}; }, s.in, s.out);
    }
  }
  return false;
}

// Roth's combination of two sorted span lists by an operator: a sweep over their ends.
Spans combine_spans(Op op, const Spans& a, const Spans& b) {
  struct Event {
    double t;
    int side;  // 0 a, 1 b
    bool enter;
    SpanEnd end;
  };
  std::vector<Event> ev;
  for (int side = 0; side < 2; ++side)
    for (const Span& s : side ? b : a) {
      Span x = s;
      if (side == 1 && op == Op::kDifference) x.in.normal = -1 * x.in.normal, x.out.normal = -1 * x.out.normal;
      ev.push_back({x.in.t, side, true, x.in});
      ev.push_back({x.out.t, side, false, x.out});
    }
  std::stable_sort(ev.begin(), ev.end(), [](const Event& x, const Event& y) { return x.t < y.t; });
  const auto value = [op](bool x, bool y) {
    return op == Op::kUnion ? x || y : op == Op::kIntersection ? x && y : x && !y;
  };
  Spans out;
  bool in[2] = {false, false};
  for (std::size_t i = 0; i < ev.size();) {
    std::size_t j = i;
    bool next[2] = {in[0], in[1]};
    while (j < ev.size() && ev[j].t == ev[i].t) next[ev[j].side] = ev[j].enter, ++j;
    const bool before = value(in[0], in[1]), after = value(next[0], next[1]);
    if (before != after) {
      const Event* cause = &ev[i];  // an end whose change alone makes the change
      for (std::size_t k = i; k < j; ++k) {
        bool only[2] = {in[0], in[1]};
        only[ev[k].side] = ev[k].enter;
        if (value(only[0], only[1]) == after) {
          cause = &ev[k];
          break;
        }
      }
      if (after) out.push_back({cause->end, {}});
      else out.back().out = cause->end;
    }
    in[0] = next[0], in[1] = next[1];
    i = j;
  }
  Spans kept;
  for (const Span& s : out)
    if (s.in.t < s.out.t) kept.push_back(s);
  return kept;
}

Spans tree_spans(const CsgTree& t, const std::vector<int>& leaf, int i, Vec3 o, Vec3 d) {
  const CsgNode& n = t.nodes()[std::size_t(i)];
  if (n.op == Op::kPrimitive) {
    const int id = leaf[std::size_t(i)];
    const CsgLeaf& l = t.leaves()[std::size_t(id)];
    Span s;
    if (!primitive_span(l, l.to_local.apply(o), l.to_local.apply_linear(d), s)) return {};
    s.in.primitive = s.out.primitive = id;
    s.in.normal = normalized(l.to_local.apply_transpose(s.in.normal));
    s.out.normal = normalized(l.to_local.apply_transpose(s.out.normal));
    return {s};
  }
  if (n.op == Op::kTransform) return tree_spans(t, leaf, n.left, o, d);
  const Spans a = tree_spans(t, leaf, n.left, o, d);
  if (a.empty() && n.op != Op::kUnion) return {};
  return combine_spans(n.op, a, tree_spans(t, leaf, n.right, o, d));
}

void check_ray(const CsgTree& tree, Vec3 o, Vec3 d) {
  if (tree.root() < 0) fail("the tree is empty");
  if (!finite(o)) fail("ray origin " + vec_text(o) + " is not finite");
  if (!finite(d) || dot(d, d) == 0) fail("ray direction " + vec_text(d) + " is zero or not finite");
}

}  // namespace

std::vector<Span> ray_spans(const CsgTree& tree, Vec3 origin, Vec3 direction, double t_min,
                            double t_max) {
  check_ray(tree, origin, direction);
  Spans all = tree_spans(tree, leaf_index(tree), tree.root(), origin, direction), out;
  for (Span s : all) {
    if (s.out.t <= t_min || s.in.t >= t_max) continue;
    if (s.in.t < t_min) s.in = {t_min, -1, {0, 0, 0}};  // the ray starts inside
    if (s.out.t > t_max) s.out = {t_max, -1, {0, 0, 0}};
    if (s.in.t < s.out.t) out.push_back(s);
  }
  return out;
}

CsgHit first_hit(const CsgTree& tree, Vec3 origin, Vec3 direction, double t_min) {
  check_ray(tree, origin, direction);
  for (const Span& s : tree_spans(tree, leaf_index(tree), tree.root(), origin, direction)) {
    const SpanEnd* e = s.in.t > t_min ? &s.in : s.out.t > t_min ? &s.out : nullptr;
    if (!e) continue;
    return {true, e->t, origin + e->t * direction, e->normal, e->primitive};
  }
  return {};
}

// --- Cameras and images ---------------------------------------------------------------------

namespace {
std::array<double, 16> invert4(const std::array<double, 16>& m) {
  // Gauss-Jordan with partial pivoting on [m | I], column-major storage (m[col * 4 + row]).
  double a[4][8];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 8; ++c) a[r][c] = c < 4 ? m[std::size_t(c * 4 + r)] : (c - 4 == r);
  for (int c = 0; c < 4; ++c) {
    int p = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    if (!(std::abs(a[p][c]) > 1e-300)) fail("the camera matrix is singular");
    for (int k = 0; k < 8; ++k) std::swap(a[c][k], a[p][k]);
    const double inv = 1 / a[c][c];
    for (int k = 0; k < 8; ++k) a[c][k] *= inv;
    for (int r = 0; r < 4; ++r)
      if (r != c) {
        const double f = a[r][c];
        for (int k = 0; k < 8; ++k) a[r][k] -= f * a[c][k];
      }
  }
  std::array<double, 16> out{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[std::size_t(c * 4 + r)] = a[r][c + 4];
  return out;
}
std::array<double, 4> times(const std::array<double, 16>& m, std::array<double, 4> v) {
  std::array<double, 4> r{};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 4; ++k) r[std::size_t(i)] += m[std::size_t(k * 4 + i)] * v[std::size_t(k)];
  return r;
}
}  // namespace

std::array<double, 16> inverse_mvp(const std::array<double, 16>& projection,
                                   const std::array<double, 16>& modelview) {
  std::array<double, 16> pm{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        pm[std::size_t(j * 4 + i)] += projection[std::size_t(k * 4 + i)] * modelview[std::size_t(j * 4 + k)];
  return invert4(pm);
}

std::vector<CastPixel> cast_image(const CsgTree& tree, const PixelCamera& c) {
  if (c.width <= 0 || c.height <= 0)
    fail("camera viewport " + std::to_string(c.width) + "x" + std::to_string(c.height));
  const std::array<double, 16> mvp = invert4(c.inverse_mvp);
  const auto unproject = [&](double x, double y, double z) {
    const std::array<double, 4> p = times(c.inverse_mvp, {x, y, z, 1});
    return Vec3{p[0] / p[3], p[1] / p[3], p[2] / p[3]};
  };
  std::vector<CastPixel> out(std::size_t(c.width) * c.height);
  for (int j = 0; j < c.height; ++j)
    for (int i = 0; i < c.width; ++i) {
      const double x = 2 * (i + 0.5) / c.width - 1, y = 2 * (j + 0.5) / c.height - 1;
      const Vec3 near = unproject(x, y, -1), far = unproject(x, y, 1);
      const CsgHit hit = first_hit(tree, near, far - near, 0);
      CastPixel& px = out[std::size_t(j) * c.width + i];
      if (!hit.hit || hit.t > 1) continue;
      const std::array<double, 4> clip = times(mvp, {hit.point.x, hit.point.y, hit.point.z, 1});
      px.primitive = hit.primitive;
      px.depth = (clip[2] / clip[3] + 1) / 2;
      px.normal = hit.normal;
    }
  return out;
}

// --- Volume ---------------------------------------------------------------------------------

VolumeEstimate volume_monte_carlo(const CsgTree& tree, std::size_t samples, std::uint64_t seed) {
  if (samples == 0) fail("Monte Carlo volume with 0 samples");
  const Box3 b = tree.bounds();
  const Vec3 size = b.size();
  const double box = size.x * size.y * size.z;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::size_t inside = 0;
  for (std::size_t k = 0; k < samples; ++k) {
    const double x = u(rng), y = u(rng), z = u(rng);  // one draw per statement: fixed order
    const Vec3 p{b.lo.x + x * size.x, b.lo.y + y * size.y, b.lo.z + z * size.z};
    inside += classify(tree, p, 0) == Where::kInside;
  }
  const double share = double(inside) / double(samples);
  return {box * share, 3 * box * std::sqrt(share * (1 - share) / double(samples)), samples};
}

namespace {
double rays_volume(const CsgTree& tree, const Box3& b, int n) {
  const Vec3 size = b.size();
  const double dx = size.x / n, dy = size.y / n;
  double sum = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec3 o{b.lo.x + (i + 0.5) * dx, b.lo.y + (j + 0.5) * dy, b.lo.z - 1};
      for (const Span& s : ray_spans(tree, o, {0, 0, 1}, 0, size.z + 2)) sum += s.out.t - s.in.t;
    }
  return sum * dx * dy;
}
}  // namespace

VolumeEstimate volume_by_rays(const CsgTree& tree, int n) {
  if (n < 2 || n % 2) fail("ray grid n = " + std::to_string(n) + " (must be even and >= 2)");
  const Box3 b = tree.bounds();
  const double v = rays_volume(tree, b, n);
  return {v, std::abs(v - rays_volume(tree, b, n / 2)), std::size_t(n) * std::size_t(n)};
}

// --- Sum of products ------------------------------------------------------------------------

namespace {
// Sorted, without repeats; false when it holds a primitive and its complement, or no
// primitive that is not complemented (an unbounded product).
bool tidy(Product& p) {
  std::sort(p.begin(), p.end(), [](const Literal& a, const Literal& b) {
    return a.primitive != b.primitive ? a.primitive < b.primitive : a.complement < b.complement;
  });
  p.erase(std::unique(p.begin(), p.end(),
                      [](const Literal& a, const Literal& b) {
                        return a.primitive == b.primitive && a.complement == b.complement;
                      }),
          p.end());
  bool positive = false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    positive |= !p[i].complement;
    if (i + 1 < p.size() && p[i].primitive == p[i + 1].primitive) return false;
  }
  return positive;
}
std::vector<Product> intersect_all(const std::vector<Product>& a, const std::vector<Product>& b) {
  std::vector<Product> out;
  for (const Product& x : a)
    for (const Product& y : b) {
      Product p = x;
      p.insert(p.end(), y.begin(), y.end());
      if (tidy(p)) out.push_back(p);
    }
  return out;
}
}  // namespace

std::vector<Product> sum_of_products(const CsgTree& tree) {
  if (tree.root() < 0) fail("the tree is empty");
  const std::vector<int> leaf = leaf_index(tree);
  const std::function<std::vector<Product>(int)> of = [&](int i) -> std::vector<Product> {
    const CsgNode& n = tree.nodes()[std::size_t(i)];
    switch (n.op) {
      case Op::kPrimitive:
        return {{{leaf[std::size_t(i)], false}}};
      case Op::kTransform:
        return of(n.left);
      case Op::kUnion: {
        std::vector<Product> a = of(n.left), b = of(n.right);
        a.insert(a.end(), b.begin(), b.end());
        return a;
      }
      case Op::kIntersection:
        return intersect_all(of(n.left), of(n.right));
      case Op::kDifference: {
        // A − (q1 ∪ q2 ∪ ...) = A ∩ ¬q1 ∩ ¬q2 ...; ¬(l1 ∩ l2 ...) = ¬l1 ∪ ¬l2 ∪ ... (De Morgan).
        std::vector<Product> result = of(n.left);
        for (const Product& q : of(n.right)) {
          std::vector<Product> complement;
          for (const Literal& l : q) complement.push_back({{l.primitive, !l.complement}});
          result = intersect_all(result, complement);
        }
        return result;
      }
    }
    return {};
  };
  return of(tree.root());
}

// --- The catalogue --------------------------------------------------------------------------

const std::vector<NamedTree>& csg_catalogue() {
  static const std::vector<NamedTree> trees = [] {
    std::vector<NamedTree> out;
    const auto add = [&](const char* name, const char* formula) -> CsgTree& {
      out.push_back({name, formula, {}});
      return out.back().tree;
    };
    const Affine along_x = Affine::rotate({0, 1, 0}, 90), along_y = Affine::rotate({1, 0, 0}, 90);
    {
      CsgTree& t = add("classic", "(box ∩ sphere) − (cyl x ∪ cyl y ∪ cyl z)");
      const int body = t.intersect(t.box({1.6, 1.6, 1.6}, "box"), t.sphere(1.05, "sphere"));
      const int x = t.transform(along_x, t.cylinder(0.45, 2.4, "cyl x"));
      const int y = t.transform(along_y, t.cylinder(0.45, 2.4, "cyl y"));
      t.subtract(body, t.unite(t.unite(x, y), t.cylinder(0.45, 2.4, "cyl z")));
    }
    {
      CsgTree& t = add("union", "sphere ∪ box");
      t.unite(t.transform(Affine::translate({-0.35, 0, 0}), t.sphere(0.7, "sphere")),
              t.transform(Affine::translate({0.4, 0.1, 0.1}), t.box({0.9, 0.9, 0.9}, "box")));
    }
    {
      CsgTree& t = add("lens", "sphere a ∩ sphere b");
      t.intersect(t.transform(Affine::translate({-0.4, 0, 0}), t.sphere(0.9, "sphere a")),
                  t.transform(Affine::translate({0.4, 0, 0}), t.sphere(0.9, "sphere b")));
    }
    {
      CsgTree& t = add("bite", "box − sphere");
      t.subtract(t.box({1.4, 1.4, 1.4}, "box"),
                 t.transform(Affine::translate({0.6, 0.6, 0.6}), t.sphere(0.75, "sphere")));
    }
    {
      CsgTree& t = add("nested difference", "box − (sphere − cyl z)");
      t.subtract(t.box({1.5, 1.5, 1.5}, "box"),
                 t.subtract(t.transform(Affine::translate({0, 0, 0.7}), t.sphere(0.8, "sphere")),
                            t.cylinder(0.3, 2.2, "cyl z")));
    }
    {
      CsgTree& t = add("double nesting", "sphere − (box − (cyl x − sphere s))");
      const int inner = t.subtract(t.transform(along_x, t.cylinder(0.5, 2.2, "cyl x")),
                                   t.sphere(0.35, "sphere s"));
      t.subtract(t.sphere(1.1, "sphere"),
                 t.subtract(t.transform(Affine::translate({0, 0, 0.8}), t.box({2, 2, 1.2}, "box")),
                            inner));
    }
    {
      CsgTree& t = add("transform under ∩", "sphere ∩ T(box)");
      const Affine turn = Affine::rotate({1, 1, 0}, 40) * Affine::scale({1.5, 0.8, 1});
      t.intersect(t.sphere(1.0, "sphere"), t.transform(turn, t.box({1.1, 1.1, 1.1}, "box")));
    }
    {
      CsgTree& t = add("cone", "cone − box");
      t.subtract(t.transform(Affine::rotate({1, 0, 0}, -90), t.cone(0.9, 1.8, "cone")),
                 t.transform(Affine::translate({0.5, 0.5, 0.3}), t.box({0.8, 0.8, 0.8}, "box")));
    }
    {
      CsgTree& t = add("rocket", "cyl z ∪ cone ∪ (sphere − cyl x)");
      const int tip = t.transform(Affine::translate({0, 0, 0.8}), t.cone(0.45, 0.7, "cone"));
      const int body = t.unite(t.cylinder(0.45, 1.0, "cyl z"), tip);
      const int ball = t.transform(Affine::translate({0, 0, -0.6}), t.sphere(0.55, "sphere"));
      t.unite(body, t.subtract(ball, t.transform(along_x, t.cylinder(0.2, 1.4, "cyl x"))));
    }
    {
      CsgTree& t = add("shell", "(sphere − sphere in) − box");
      t.subtract(t.subtract(t.sphere(1.0, "sphere"), t.sphere(0.8, "sphere in")),
                 t.transform(Affine::translate({0.6, -0.6, 0.6}), t.box({1.2, 1.2, 1.2}, "box")));
    }
    {
      CsgTree& t = add("pipe cross", "(cyl x ∪ cyl y) − (bore x ∪ bore y)");
      const int outer = t.unite(t.transform(along_x, t.cylinder(0.45, 2.2, "cyl x")),
                                t.transform(along_y, t.cylinder(0.45, 2.2, "cyl y")));
      const int bores = t.unite(t.transform(along_x, t.cylinder(0.3, 2.4, "bore x")),
                                t.transform(along_y, t.cylinder(0.3, 2.4, "bore y")));
      t.subtract(outer, bores);
    }
    {
      CsgTree& t = add("three boxes", "box ∩ T(box) ∩ T(box)");
      // No two faces in one plane: image-based CSG cannot order coplanar faces.
      const int b2 = t.transform(Affine::rotate({0, 0, 1}, 45), t.box({1.3, 1.3, 1.7}, "box z"));
      const int b3 = t.transform(Affine::rotate({1, 0, 0}, 45), t.box({1.7, 1.2, 1.2}, "box x"));
      t.intersect(t.intersect(t.box({1.4, 1.4, 1.4}, "box"), b2), b3);
    }
    {
      CsgTree& t = add("union of differences", "(box − sphere) ∪ (sphere b − cyl z)");
      const int left = t.subtract(t.transform(Affine::translate({-0.5, 0, 0}), t.box({1, 1, 1}, "box")),
                                  t.transform(Affine::translate({-0.5, 0, 0.5}), t.sphere(0.45, "sphere")));
      const int right =
          t.subtract(t.transform(Affine::translate({0.5, 0, 0}), t.sphere(0.6, "sphere b")),
                     t.transform(Affine::translate({0.5, 0, 0}), t.cylinder(0.25, 1.6, "cyl z")));
      t.unite(left, right);
    }
    // Sieves: box ∩ sphere minus thin cylinders through the centre, one product of 4, 8 and
    // 16 primitives (the frame-time benchmark's trees): the axes, then the face diagonals,
    // then the body diagonals and one off-centre bore.
    const std::vector<Vec3> bores = {{1, 0, 0},  {0, 1, 0},  {0, 0, 1},   {1, 1, 0},  {1, 0, 1},
                                     {0, 1, 1},  {1, -1, 0}, {1, 0, -1},  {0, 1, -1}, {1, 1, 1},
                                     {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}};
    for (std::size_t count : {2u, 6u, 14u}) {
      const std::string name = "sieve " + std::to_string(count + 2);
      const std::string formula = "(box ∩ sphere) − " + std::to_string(count) + " bores";
      CsgTree& t = add(name.c_str(), formula.c_str());
      const int body = t.intersect(t.box({1.6, 1.6, 1.6}, "box"), t.sphere(1.05, "sphere"));
      int holes = -1;
      for (std::size_t k = 0; k < count; ++k) {
        const Vec3 d = k < bores.size() ? bores[k] : Vec3{0, 0, 1};
        const Vec3 axis = cross(Vec3{0, 0, 1}, d);
        const double angle = std::acos(d.z / length(d)) * 180 / M_PI;
        Affine place = length(axis) > 0 ? Affine::rotate(axis, angle) : Affine{};
        if (k >= bores.size()) place = Affine::translate({0.45, 0.45, 0});  // off the centre
        const int bore = t.transform(place, t.cylinder(0.12, 2.4, "bore " + std::to_string(k + 1)));
        holes = holes < 0 ? bore : t.unite(holes, bore);
      }
      t.subtract(body, holes);
    }
    return out;
  }();
  return trees;
}

}  // namespace gllab::space
