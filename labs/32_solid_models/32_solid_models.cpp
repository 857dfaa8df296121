// lab 32 · wire frame, surface and solid models                      difficulty: ★★
// The three kinds of 3-D model of the lecture notes ("Geometric Modeling", introduction):
// a wire frame describes an object by its boundary curves, with nothing between them; a
// surface model by its hull, with no inside; a solid model decides inside or outside for
// every point in space. The solids here are CSG trees of the core (common/space/csg.h),
// drawn by exact ray casting.
// Notice: the same two circles bound a cylinder, a barrel and a cylinder with a pit; the
//   hidden edges of a wire-frame box cannot be told; a ray from a point in the open tube
//   crosses its surface once or not at all, so the tube has no inside.
// Try: in solid, drag P and move it with [z]/[Z] through the holes: where does it become "on"? Make
//   the tolerance larger with [.]: how wide is the band of "on" in the cut?
// Keys: [z]/[Z] move the cut  [,]/[.] tolerance
//   left-drag P  right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: wire_frame, visibility, surface, solid
// Reference: reference_images/32_solid_models__*.png

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gl/csg_view.h"
#include "gl/gl.h"
#include "gl/panels.h"
#include "gl/scene.h"
#include "gl/space_view.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "space/csg.h"

namespace {

namespace sp = gllab::space;
using gllab::Rgb, gllab::State, gllab::kOrbit, gllab::format_text, gllab::Panel;
using gllab::spline::Vec3;

// Lab data (edit me) -------------------------------------------------------
constexpr double kR = 0.6, kH = 1.4;  // the wire frame: two circles of radius R, H apart
constexpr double kPit = 0.9;          // the depth of the conical pit
const Rgb kClear{.1f, .11f, .14f}, kWire{1, .9f, .3f}, kText{1, 1, 1}, kHidden{.5f, .5f, .6f};
const sp::Box3 kBlock{{-.8, -.5, -.4}, {.8, .5, .4}};  // the wire-frame box

// The wire frame: the circles z = +-H/2, and three solids whose edges are exactly them.
std::vector<Vec3> circle(double z) {
  std::vector<Vec3> c;
  for (int i = 0; i < 96; ++i)
    c.push_back({kR * std::cos(2 * M_PI * i / 96), kR * std::sin(2 * M_PI * i / 96), z});
  return c;
}
std::vector<sp::NamedTree> solids() {
  std::vector<sp::NamedTree> out(3);
  out[0].name = "a cylinder";
  out[0].tree.cylinder(kR, kH, "cylinder");
  out[1].name = "a barrel: a sphere cut by a slab";  // the sphere through both circles
  sp::CsgTree& b = out[1].tree;
  const double big = std::hypot(kR, kH / 2);
  b.intersect(b.sphere(big, "sphere"), b.box({2 * big, 2 * big, kH}, "slab"));
  out[2].name = "a cylinder with a conical pit";  // the cone's slant meets the top circle
  sp::CsgTree& p = out[2].tree;
  const double up = 0.05, cone = kPit + up;  // the cone pokes `up` out of the top
  const sp::Affine place = sp::Affine::translate({0, 0, kH / 2 - kPit + cone / 2}) *
                           sp::Affine::rotate({1, 0, 0}, 180);  // apex down
  p.subtract(p.cylinder(kR, kH, "cylinder"),
             p.transform(place, p.cone(kR * cone / kPit, cone, "cone")));
  return out;
}

// wire_frame: the two circles alone, then each solid they bound, ray cast, with the circles.
void draw_wire_frame(const State& s) {
  const std::vector<sp::NamedTree> trees = solids();
  for (int k = 0; k < 4; ++k) {
    const Panel p = gllab::enter_panel(k % 2, k / 2, 2, 2, s.width, s.height);
    gllab::space_camera(s, p.width, p.height, 1.1, -30, 25);
    if (k > 0) gllab::draw_image(gllab::ray_cast_picture(trees[k - 1].tree, kClear, true));
    gllab::draw_polyline(circle(kH / 2), kWire, 2.f, true);
    gllab::draw_polyline(circle(-kH / 2), kWire, 2.f, true);
    gllab::draw_panel_caption(p, -1, k ? trees[k - 1].name : "the wire frame: two circles");
  }
  gllab::leave_panels(s.width, s.height);
}

// visibility: a box's twelve edges (which face is in front?), and the same edges tested
// against the solid box in the depth buffer: the hidden ones dashed.
void draw_visibility(const State& s) {
  for (int k = 0; k < 2; ++k) {
    const Panel p = gllab::enter_panel(k, 0, 2, 1, s.width, s.height);
    gllab::ortho_fit(p.width, p.height, 1.1, 1.1);
    gllab::apply_orbit(s);
    glRotated(25, 1, 0, 0);  // a parallel projection: the wire frame's two readings
    glRotated(-35, 0, 1, 0);
    if (k == 0) {
      gllab::draw_box_edges(kBlock, kWire, 2.f);
    } else {
      glEnable(GL_DEPTH_TEST);
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the solid: depth only, pushed
      glEnable(GL_POLYGON_OFFSET_FILL), glPolygonOffset(1, 1);  // behind its own edges
      gllab::draw_box_faces(kBlock, kClear);
      glDisable(GL_POLYGON_OFFSET_FILL);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      glDepthFunc(GL_GREATER);  // the edges behind the solid: dashed
      glEnable(GL_LINE_STIPPLE), glLineStipple(3, 0x5555);
      gllab::draw_box_edges(kBlock, kHidden, 1.f);
      glDisable(GL_LINE_STIPPLE);
      glDepthFunc(GL_LEQUAL);  // the edges in front: solid
      gllab::draw_box_edges(kBlock, kWire, 2.f);
      glDepthFunc(GL_LESS);
    }
    gllab::draw_panel_caption(p, -1, k ? "solid: hidden edges dashed" : "which face is in front?");
  }
  gllab::leave_panels(s.width, s.height);
}

// The probe: P dragged in the plane at height z.
Vec3 probe(const State& s) { return {s.points("P")[0].x, s.points("P")[0].y, s.get("z")}; }

// surface: an open tube (a surface model), and two rays from P: parity cannot say inside.
int tube_crossings(Vec3 o, Vec3 d) {  // the ray o + t d, t > 0, against x^2 + y^2 = R^2
  const double a = d.x * d.x + d.y * d.y, b = o.x * d.x + o.y * d.y;
  const double c = o.x * o.x + o.y * o.y - kR * kR, disc = b * b - a * c;
  int n = 0;
  if (a > 0 && disc > 0)
    for (double t : {(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a})
      n += t > 0 && std::abs(o.z + t * d.z) <= kH / 2;
  return n;
}
void draw_open_tube(const State& s) {
  gllab::space_camera(s, s.width, s.height, 1.3, -30, 35);
  glEnable(GL_DEPTH_TEST);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);  // its inside is seen through the ends
  GLUquadric* q = gluNewQuadric();
  glColor3f(.35f, .65f, .95f);
  glTranslated(0, 0, -kH / 2);
  gluCylinder(q, kR, kR, kH, 48, 1);  // a tube: no caps, so no inside
  glTranslated(0, 0, kH / 2);
  gluDeleteQuadric(q), glDisable(GL_DEPTH_TEST);  // the rays and P show through the tube
  const Vec3 P = probe(s);
  std::vector<std::string> lines{format_text("P = (%.2f, %.2f, %.2f)", P.x, P.y, P.z)};
  for (Vec3 d : {Vec3{1, 0, 0}, Vec3{0, 0, 1}}) {
    const int n = tube_crossings(P, d);
    gllab::draw_polyline({P, P + 1.5 * d}, n % 2 ? Rgb{1, .4f, .3f} : Rgb{.4f, 1, .5f});
    lines.push_back(format_text("ray along %s: %d crossing%s, so %s", d.x ? "+x" : "+z", n,
                                n == 1 ? "" : "s", n % 2 ? "inside" : "outside"));
  }
  lines.push_back("a surface model has no inside: the rays disagree");
  gllab::draw_control_points_at(s, "P", {P}, kWire, 8.f);
  gllab::draw_text_panel(8, 8, lines, kText);
}

// solid: the classic CSG object, ray cast, with P; right, the cut z = P.z, every point of it
// classified inside, outside or on (within the tolerance).
void draw_solid(const State& s) {
  const sp::CsgTree& tree = sp::csg_catalogue()[0].tree;
  const Vec3 P = probe(s);
  const double tol = s.get("tolerance");
  const Panel left = gllab::enter_panel(0, 0, 2, 1, s.width, s.height);
  gllab::space_camera(s, left.width, left.height, 1.5);
  gllab::draw_image(gllab::ray_cast_picture(tree, kClear, true));
  gllab::draw_polyline({{-1.2, -1.2, P.z}, {1.2, -1.2, P.z}, {1.2, 1.2, P.z}, {-1.2, 1.2, P.z}},
                       kWire, 1.f, true);
  gllab::draw_control_points_at(s, "P", {P}, kWire, 8.f);
  const Panel right = gllab::enter_panel(1, 0, 2, 1, s.width, s.height);
  const double px = 2.6 / std::min(right.width, right.height);  // ortho_fit's pixel size
  gllab::draw_image(gllab::make_picture(right.width, right.height, [&](int i, int j) {
    const Vec3 q{(i + .5 - right.width / 2.) * px, (j + .5 - right.height / 2.) * px, P.z};
    const sp::Where w = sp::classify(tree, q, tol);  // the cut: every pixel's point classified
    return w == sp::Where::kInside ? Rgb{.95f, .62f, .25f}
           : w == sp::Where::kOn   ? Rgb{1, 1, 1}
                                   : Rgb{.2f, .22f, .28f};
  }));
  gllab::ortho_fit(right.width, right.height, 1.3, 1.3);
  gllab::draw_dots({{P.x, P.y, 0}}, {1, .3f, .3f}, 8.f);
  gllab::leave_panels(s.width, s.height);
  gllab::draw_text_panel(8, 8, {format_text("P = (%.3f, %.3f, %.3f): %s", P.x, P.y, P.z,
                                            sp::where_name(sp::classify(tree, P, tol))),
                                format_text("tolerance %.3f; right: the cut z = %.3f", tol, P.z)},
                         kText);
}

void init() { glClearColor(kClear.r, kClear.g, kClear.b, 1.f); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "32_solid_models",
      "lab 32 · wire frame, surface and solid models",
      {{"wire_frame", "two circles, and three solids with those edges", draw_wire_frame, kOrbit},
       {"visibility", "a wire-frame box; its hidden edges from the solid", draw_visibility, kOrbit},
       {"surface", "an open tube: rays from P cross it once or not at all", draw_open_tube, kOrbit},
       {"solid", "a CSG solid and a cut through P: inside, outside, on", draw_solid, kOrbit}},
      {{"tolerance", 0.01, 0.001, 0.1, "the width of \"on\" in the classification"},
       {"z", 0.1, -1.2, 1.2, "the height of P and of the cut"}},
      {{',', "less tolerance", "tolerance", -0.005}, {'.', "more tolerance", "tolerance", 0.005},
       {'z', "P and the cut down", "z", -0.05}, {'Z', "P and the cut up", "z", 0.05}},
      init};
  lab.points = {{"P", {{0.3, 0.2, 0}}, "the probe point, at the height z", 2}};
  return lab;
}
