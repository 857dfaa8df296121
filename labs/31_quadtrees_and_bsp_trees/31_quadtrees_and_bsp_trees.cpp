// lab 31 · quadtrees and BSP trees                                difficulty: ★★★
// One 2-D scene cut up two ways (lecture notes ch. 1, §1.8 Space partitioning): a quadtree
// splits every cell at its centre into four until each holds at most one object; a BSP tree
// splits a cell in two at any line, here across the main axis of the objects' points (PCA).
// In 3-D the BSP tree sorts polygons by depth: drawn far to near with the depth test off,
// near pieces paint over far ones and the picture equals the z-buffer's (Fuchs, Kedem and
// Naylor 1980).
// Notice: the BSP tree needs fewer regions than the quadtree has cells, but cuts objects that
//   straddle its lines. The three sticks of painter overlap in a cycle that no order of
//   whole polygons can draw: the BSP tree splits them.
// Try: in painter, step through the order with [s]: which piece is drawn last, and why?
//   In pca, drag points across the split line: how far must e1 turn to move the split?
// Keys: [s]/[S] step the drawing order  [b]/[B] plane rule  [o] order numbers on/off
//   left-drag points  right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: quadtree_vs_bsp, pca, painter, split_rules
// Reference: reference_images/31_quadtrees_and_bsp_trees__*.png

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/panels.h"
#include "gl/scene.h"
#include "gl/space_view.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "space/bsp.h"
#include "space/pca.h"
#include "space/quadtree.h"

namespace {

namespace sp = gllab::space;
using gllab::Rgb, gllab::State, gllab::kOrbit, gllab::format_text;
using gllab::spline::Vec2, gllab::spline::Vec3;

// Lab data (edit me) -------------------------------------------------------
// The 2-D scene in the unit square: six convex objects, counter-clockwise.
const std::vector<sp::ConvexPolygon2> kScene = {
    {{.08, .10}, {.34, .12}, {.18, .36}},                          // A
    {{.55, .08}, {.92, .08}, {.92, .24}, {.55, .24}},              // B
    {{.66, .52}, {.86, .50}, {.90, .66}, {.76, .76}, {.64, .66}},  // C
    {{.12, .55}, {.36, .50}, {.42, .76}, {.16, .86}},              // D
    {{.50, .38}, {.58, .38}, {.58, .46}, {.50, .46}},              // E
    {{.62, .84}, {.95, .88}, {.72, .97}}};                         // F
constexpr int kMaxDepth = 6;  // the quadtree's: touching objects would split forever
// The 3-D scene: three sticks overlapping in a cycle (each lies over the next at one end and
// under the previous at the other: no order of whole polygons draws them right), a floor and
// a triangle through two of them. Stick k: 3.2 long, 0.56 wide, its middle 0.55 from the
// centre towards 120 k degrees, rising from z = -0.5 to 0.5 along its length.
std::vector<std::vector<Vec3>> scene3() {
  std::vector<std::vector<Vec3>> P;
  for (int k = 0; k < 3; ++k) {
    const double a = 2 * M_PI * k / 3;
    const Vec3 c{.55 * std::cos(a), .55 * std::sin(a), 0}, u{-std::sin(a), std::cos(a), 0},
        v{std::cos(a), std::sin(a), 0}, up{0, 0, .5};
    P.push_back({c - 1.6 * u - .28 * v - up, c + 1.6 * u - .28 * v + up, c + 1.6 * u + .28 * v + up,
                 c - 1.6 * u + .28 * v - up});
  }
  P.push_back({{-1.8, -1.8, -.9}, {1.8, -1.8, -.9}, {1.8, 1.8, -.9}, {-1.8, 1.8, -.9}});
  P.push_back({{-.9, -.6, -.7}, {.3, -.2, .9}, {-.2, .6, -.3}});
  return P;
}
const Rgb kText{1, 1, 1}, kLine{1, 1, 1}, kAxis1{1, .4f, .3f}, kAxis2{.4f, .8f, 1};

Rgb object_colour(int i) { return gllab::series_colour(i); }

// quadtree_vs_bsp: left the quadtree's cells and tree, right the BSP tree's lines and tree.
void draw_quadtree_vs_bsp(const State& s) {
  const sp::Quadtree quad(kScene, {{0, 0}, {1, 1}}, kMaxDepth);
  const sp::BspTree bsp(gllab::in_plane(kScene), sp::SplitRule::kPca);
  for (int side = 0; side < 2; ++side) {
    const gllab::Panel p = gllab::enter_panel(side, 0, 2, 1, s.width, s.height);
    gllab::ortho_fit(p.width, p.height, .55, .55 * p.height / p.width);
    glTranslated(-.5, .55 * p.height / p.width - 1.05, 0);  // the square at the panel's top
    gllab::draw_convex_objects(kScene, object_colour);
    glColor3f(kLine.r, kLine.g, kLine.b);
    glBegin(GL_LINES);
    if (side == 0) {  // every inner cell: its two centre lines
      for (const sp::QuadNode& n : quad.nodes()) {
        if (n.first_child < 0) continue;
        const Vec2 c = n.box.centre();
        glVertex2d(n.box.lo.x, c.y), glVertex2d(n.box.hi.x, c.y);
        glVertex2d(c.x, n.box.lo.y), glVertex2d(c.x, n.box.hi.y);
      }
    }
    glEnd();
    if (side == 1)  // every node's line, clipped to its region (the unit square split down)
      gllab::draw_bsp_cuts(bsp, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, kLine);
    gllab::draw_box_edges({{0, 0, 0}, {1, 1, 0}}, kLine);
    gllab::leave_panels(s.width, s.height);
  }
  const auto name = [](int object) { return std::string(1, char('A' + object)); };
  const int w = s.width / 2 - 16, top = s.width / 2 + 24, h = s.height - top - 60;
  gllab::draw_tree_diagram(gllab::quadtree_diagram(quad, object_colour, name), 8, top, w, h);
  gllab::draw_tree_diagram(gllab::bsp_diagram(bsp, object_colour, name), w + 24, top, w, h);
  gllab::draw_text_panel(8, s.height - 52, {
      format_text("quadtree: %zu cells, depth %d, %zu with more than one object",
                  quad.leaf_count(), quad.depth(), quad.crowded_leaves()),
      format_text("BSP tree (PCA): %zu regions, depth %d, %zu splits",
                  std::size_t(std::count_if(bsp.nodes().begin(), bsp.nodes().end(),
                                            [](const sp::BspNode& n) { return n.leaf; })),
                  bsp.stats().depth, bsp.stats().splits)}, kText);
}

// pca: the cloud P, its centre c, the axes e1, e2 drawn 2 sqrt(lambda) long, and the BSP
// split across the main axis: the line through c perpendicular to e1.
void draw_pca(const State& s) {
  std::vector<Vec2> cloud;
  for (const Vec3& p : s.points("P")) cloud.push_back({p.x, p.y});
  const sp::Pca a = sp::pca(cloud);
  gllab::ortho_fit(s.width, s.height, 1.3, 1.3);
  const Vec3 c = a.centre, e1 = a.axis[0], e2 = a.axis[1];
  const double l1 = 2 * std::sqrt(a.variance[0]), l2 = 2 * std::sqrt(a.variance[1]);
  gllab::draw_polyline({c - 3 * e2, c + 3 * e2}, {.6f, .6f, .6f}, 1.f);  // the split
  gllab::draw_arrow(c, c + l1 * e1, kAxis1, 3.f);
  gllab::draw_arrow(c, c + l2 * e2, kAxis2, 3.f);
  std::vector<std::size_t> front, back;  // the two sides of the split
  for (std::size_t i = 0; i < cloud.size(); ++i)
    (dot(s.points("P")[i] - c, e1) > 0 ? front : back).push_back(i);
  gllab::draw_control_points(s, "P", front, kAxis1, 8.f);
  gllab::draw_control_points(s, "P", back, kAxis2, 8.f);
  gllab::draw_text_panel(
      8, 8,
      {format_text("c = (%.3f, %.3f), %zu points", c.x, c.y, a.count),
       format_text("lambda1 = %.4f  e1 = (%.3f, %.3f)", a.variance[0], e1.x, e1.y),
       format_text("lambda2 = %.4f  e2 = (%.3f, %.3f)", a.variance[1], e2.x, e2.y),
       format_text("split across e1: %zu points in front, %zu behind", front.size(), back.size())},
      kText);
}

// The 3-D scene's polygons, one object each, for the BSP tree.
std::vector<sp::Polygon3> polygons3() {
  std::vector<sp::Polygon3> out;
  const std::vector<std::vector<Vec3>> P = scene3();
  for (std::size_t i = 0; i < P.size(); ++i) out.push_back({P[i], int(i), int(i)});
  return out;
}
void draw_piece(const sp::Polygon3& piece) {
  const Rgb c = object_colour(piece.id);
  glColor3f(c.r, c.g, c.b);
  glBegin(GL_POLYGON);
  for (const Vec3& q : piece.points) glVertex3d(q.x, q.y, q.z);
  glEnd();
}
// The eye of an orthographic camera: far back along the view's ray through the origin.
Vec3 eye_point() { return gllab::view_ray({0, 0, 0}, 100).origin; }

// painter: left the BSP tree's order from the eye, depth test off (the first `step` pieces,
// numbered); right the same polygons through the z-buffer. Below: how many pixels differ.
void draw_painter(const State& s) {
  const sp::BspTree bsp(polygons3(), sp::SplitRule(s.integer("rule")));
  const int step = s.integer("step");
  std::vector<const sp::Polygon3*> order;
  gllab::Panel panel[2];
  for (int side = 0; side < 2; ++side) {
    panel[side] = gllab::enter_panel(side, 0, 2, 1, s.width, s.height);
    gllab::space_camera(s, panel[side].width, panel[side].height, 1.8, -30, 55);
    glDisable(GL_LIGHTING);
    if (side == 0) {
      order = bsp.back_to_front(eye_point());
      glDisable(GL_DEPTH_TEST);  // the order alone decides what covers what
      for (std::size_t i = 0; i < order.size() && (step == 0 || int(i) < step); ++i)
        draw_piece(*order[i]);
    } else {
      glEnable(GL_DEPTH_TEST);
      for (const sp::Polygon3& p : polygons3()) draw_piece(p);
      glDisable(GL_DEPTH_TEST);
    }
  }
  const gllab::PanelDifference d = gllab::compare_panels(panel[0], panel[1]);
  if (s.flag("numbers")) {  // the order, at each piece's centre
    gllab::enter_panel(0, 0, 2, 1, s.width, s.height);
    gllab::space_camera(s, panel[0].width, panel[0].height, 1.8, -30, 55);
    gllab::draw_piece_numbers(order, step == 0 ? order.size() : std::size_t(step), kText);
  }
  gllab::leave_panels(s.width, s.height);
  gllab::draw_panel_caption(panel[0], 0,
                            format_text("BSP order (%s)",
                                        sp::split_rule_name(sp::SplitRule(s.integer("rule")))));
  gllab::draw_panel_caption(panel[1], 0, "z-buffer");
  std::vector<std::string> lines{
      format_text("%zu polygons -> %zu pieces (%zu splits), drawn %d", bsp.stats().polygons,
                  bsp.stats().fragments, bsp.stats().splits,
                  step == 0 ? int(order.size()) : std::min(step, int(order.size())))};
  if (step == 0)
    lines.push_back(format_text("pixels differing: %zu of %zu, away from edges: %zu", d.differing,
                                d.pixels, d.away_from_edges));
  gllab::draw_text_panel(8, s.height - 16 * int(lines.size()) - 12, lines, kText);
}

// split_rules: the same scene split by each rule; the pieces outlined.
void draw_split_rules(const State& s) {
  const sp::SplitRule rules[] = {sp::SplitRule::kOwnPlane, sp::SplitRule::kFewestSplits,
                                 sp::SplitRule::kPca};
  for (int r = 0; r < 3; ++r) {
    const sp::BspTree bsp(polygons3(), rules[r]);
    const gllab::Panel p = gllab::enter_panel(r, 0, 3, 1, s.width, s.height);
    gllab::space_camera(s, p.width, p.height, 1.8, -30, 55);
    glDisable(GL_LIGHTING);
    for (const sp::Polygon3* piece : bsp.back_to_front(eye_point())) {
      draw_piece(*piece);
      gllab::draw_polyline(piece->points, {0, 0, 0}, 1.5f, true);
    }
    gllab::leave_panels(s.width, s.height);
    const sp::BspStats& t = bsp.stats();
    gllab::draw_panel_caption(p, 0, sp::split_rule_name(rules[r]));
    gllab::draw_panel_caption(p, -3, format_text("%zu splits", t.splits));
    gllab::draw_panel_caption(p, -2, format_text("%zu pieces, %zu nodes", t.fragments, t.nodes));
    gllab::draw_panel_caption(p, -1, format_text("depth %d", t.depth));
  }
}

void init() { glClearColor(0.1f, 0.11f, 0.14f, 1.f); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "31_quadtrees_and_bsp_trees",
      "lab 31 · quadtrees and BSP trees",
      {{"quadtree_vs_bsp", "the 2-D scene as a quadtree and as a BSP tree, with their trees",
        draw_quadtree_vs_bsp},
       {"pca", "PCA axes of a point cloud and the split across e1", draw_pca},
       {"painter", "BSP back-to-front order with the depth test off, beside the z-buffer",
        draw_painter, kOrbit},
       {"split_rules", "own plane, fewest splits, PCA: the pieces each makes", draw_split_rules,
        kOrbit}},
      {{"step", 0, 0, 64, "pieces drawn in the painter's order (0: all)"},
       {"rule", 0, 0, 2, "painter's plane rule: 0 own plane, 1 fewest splits, 2 PCA"},
       {"numbers", 1, 0, 1, "the painter's order numbers"}},
      {{'s', "one piece more", "step", +1},
       {'S', "one piece fewer", "step", -1},
       {'b', "next plane rule", "rule", +1},
       {'B', "previous plane rule", "rule", -1},
       {'o', "order numbers on/off", "numbers"}},
      init};
  lab.points = {{"P", gllab::elongated_cloud(24), "the point cloud of pca", 2}};
  return lab;
}
