// lab 33 · CSG with the stencil buffer                            difficulty: ★★★★
// A CSG tree drawn by fixed-function GL (lecture notes, "3-D Graphics", "Solid Representation",
// "Constructive Solid Geometry": primitives in the leaves, union, intersection and difference
// in the nodes). GL has no CSG: the tree becomes a union of products (Goldfeather et al.
// 1989), and each product's surface is found with the depth and stencil buffers, by
// Goldfeather's parity counting or by SCS for convex primitives (Rappoport and Spitz 1997;
// Stewart, Leach and John 1998). The core's exact ray casting (Roth 1982) is the truth.
// Notice: a subtracted primitive shows its back faces; the stencil counts how many faces of
//   the others lie in front of a surface: odd means inside a convex primitive.
// Try: in passes, step with [s] through one product: which pass removes the cylinders' holes?
//   Press [o] to make the sphere a union, then a difference: how do the products change?
// Keys: [t]/[T] tree  [o]/[O] operator box-sphere  [s]/[S] pass  [a] Goldfeather/SCS
//   left-drag the sphere  right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: goldfeather, scs, passes, ray_cast
// Reference: reference_images/33_csg_stencil__*.png

#include <algorithm>
#include <string>
#include <vector>

#include "gl/csg_view.h"
#include "gl/gl.h"
#include "gl/space_view.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "space/csg.h"

namespace {

namespace sp = gllab::space;
using gllab::State, gllab::kOrbit, gllab::format_text, gllab::Panel, gllab::Passes;
using gllab::literal_name, gllab::enter_panel;

// Lab data (edit me) -------------------------------------------------------
constexpr double kBox = 1.6, kSphere = 1.05, kHole = 0.45, kLength = 2.4;  // the classic object
const gllab::Rgb kClear{.1f, .11f, .14f};
constexpr long long kAgree = 8;  // of 256 x 256 pixels, edges aside (measured: 0 to 4)
const char* const kOps[] = {"∩", "∪", "−"};

// Tree 0: (box op sphere) − (cyl x ∪ cyl y ∪ cyl z), the sphere at S. Trees 1.. the core's.
sp::NamedTree make_tree(const State& s) {
  if (s.integer("tree") > 0) return sp::csg_catalogue()[std::size_t(s.integer("tree"))];
  const int op = s.integer("op");
  sp::NamedTree n{"classic", std::string("(box ") + kOps[op] + " sphere) − cylinders", {}};
  sp::CsgTree& t = n.tree;
  const int box = t.box({kBox, kBox, kBox}, "box");
  const int ball =
      t.transform(sp::Affine::translate(s.points("S")[0]), t.sphere(kSphere, "sphere"));
  const int body = op == 0 ? t.intersect(box, ball)
                 : op == 1 ? t.unite(box, ball) : t.subtract(box, ball);
  const int x = t.transform(sp::Affine::rotate({0, 1, 0}, 90), t.cylinder(kHole, kLength, "cyl x"));
  const int y = t.transform(sp::Affine::rotate({1, 0, 0}, 90), t.cylinder(kHole, kLength, "cyl y"));
  t.subtract(body, t.unite(t.unite(x, y), t.cylinder(kHole, kLength, "cyl z")));
  return n;
}

// Draws a primitive's faces: 1 the front ones (back ones culled), -1 the back ones, 0 all.
void faces(const sp::CsgTree& t, int primitive, int which) {
  if (which == 0) glDisable(GL_CULL_FACE);
  else glEnable(GL_CULL_FACE), glCullFace(which > 0 ? GL_BACK : GL_FRONT);
  gllab::draw_csg_primitive(t.leaves()[std::size_t(primitive)]);
}
int side(const sp::Literal& l) { return l.complement ? -1 : 1; }  // −b shows b's inside

// Merge: the depth becomes min(depth, R), and R the depth. GL has one depth buffer; the
// second that Goldfeather's algorithm needs for the result is R, in memory. Where the new
// surface won, stencil bit 4 is set, and the literals are shaded there with depth EQUAL.
void merge(const sp::CsgTree& t, const sp::Product& lits, std::vector<GLuint>& R, bool lit) {
  GLint v[4];  // the viewport: x, y, width, height
  glGetIntegerv(GL_VIEWPORT, v);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_TRUE); glDepthFunc(GL_LESS);  // R is written where it is nearer
  glEnable(GL_STENCIL_TEST), glStencilMask(4);
  glStencilFunc(GL_ALWAYS, 4, 0); glStencilOp(GL_KEEP, GL_REPLACE, GL_KEEP);  // else: won
  glWindowPos2i(v[0], v[1]);
  glDrawPixels(v[2], v[3], GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, R.data());
  glReadPixels(v[0], v[1], v[2], v[3], GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, R.data());
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_FALSE); glDepthFunc(GL_EQUAL);
  glStencilFunc(GL_EQUAL, 4, 4 | 2); glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);  // won, valid
  (lit ? glEnable : glDisable)(GL_LIGHTING);
  for (const sp::Literal& l : lits) {
    const gllab::Rgb c = gllab::primitive_colour(l.primitive);
    glColor3f(c.r, c.g, c.b), faces(t, l.primitive, side(l));
  }
  glStencilMask(0xff), glDepthMask(GL_TRUE);  // glClear obeys the write masks: leave them open
}

// Goldfeather: for every literal a of a product, a's visible faces, kept where they are inside
// every other literal (inside a convex b: an odd number of b's faces lie in front).
void goldfeather(const sp::CsgTree& t, const sp::Product& prod, std::vector<GLuint>& R,
                 Passes& p, bool lit) {
  for (const sp::Literal& a : prod) {
    const std::string an = literal_name(t, a);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDisable(GL_STENCIL_TEST), glDepthFunc(GL_LESS);
    faces(t, a.primitive, side(a));  // the depth: a's front faces (back faces for −a)
    if (!p.next(an + ": its faces into the depth buffer")) return;
    glEnable(GL_STENCIL_TEST), glDepthMask(GL_FALSE);
    for (const sp::Literal& b : prod) {
      if (b.primitive == a.primitive) continue;
      glStencilMask(1);  // bit 1 flips for each face of b in front of a's faces
      glStencilFunc(GL_ALWAYS, 0, 0); glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
      glDepthFunc(GL_LESS);
      faces(t, b.primitive, 0);
      if (!p.next(an + ": parity of " + literal_name(t, b) + "'s faces in front")) return;
      glStencilMask(2);  // bit 2 (invalid) where the parity is wrong: even for b, odd for −b
      glStencilFunc(GL_EQUAL, b.complement ? 3 : 2, 1);
      glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
      glDepthFunc(GL_ALWAYS);
      gllab::draw_screen_quad(0.5);
      glStencilMask(1); glClear(GL_STENCIL_BUFFER_BIT);  // bit 1 back to 0, bit 2 kept
      if (!p.next(an + ": outside " + literal_name(t, b) + " is invalid")) return;
    }
    glStencilFunc(GL_EQUAL, 2, 2); glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);  // the invalid ...
    glDepthMask(GL_TRUE); glDepthFunc(GL_ALWAYS);
    gllab::draw_screen_quad(1.0);  // ... go to the far plane
    merge(t, {a}, R, lit);
    if (!p.next(an + ": merged into R, shaded where it won")) return;
  }
}

// SCS: the product's depth is its intersection's farthest front face, pushed back through
// every subtracted primitive it lies in (each of k of them k times), then clipped to the
// intersection: convex primitives only.
void scs(const sp::CsgTree& t, const sp::Product& prod, std::vector<GLuint>& R, Passes& p,
         bool lit) {
  sp::Product plus, minus;
  for (const sp::Literal& l : prod) (l.complement ? minus : plus).push_back(l);
  glClearDepth(0);  // the depth starts at the near plane
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT), glClearDepth(1);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE), glDisable(GL_STENCIL_TEST);
  glDepthFunc(GL_GREATER);  // the farthest front face of the intersected primitives
  for (const sp::Literal& l : plus) faces(t, l.primitive, 1);
  if (!p.next("the farthest front face of the intersected")) return;
  glEnable(GL_STENCIL_TEST), glStencilMask(1);
  for (std::size_t round = 1; round <= minus.size(); ++round)
    for (const sp::Literal& y : minus) {
      glDepthMask(GL_FALSE); glDepthFunc(GL_LESS);  // bit 1: y's front face is in front
      glStencilFunc(GL_ALWAYS, 1, 1); glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
      faces(t, y.primitive, 1);
      glDepthMask(GL_TRUE); glDepthFunc(GL_GREATER);  // there, y's back faces behind: to them
      glStencilFunc(GL_EQUAL, 1, 1); glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
      faces(t, y.primitive, -1);
      glClear(GL_STENCIL_BUFFER_BIT);
      if (!p.next("through " + literal_name(t, y) + ", round " + std::to_string(round))) return;
    }
  glStencilMask(0xff);  // the stencil counts the intersected back faces behind the depth
  glDepthMask(GL_FALSE); glDepthFunc(GL_GEQUAL);
  glStencilFunc(GL_ALWAYS, 0, 0); glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  for (const sp::Literal& l : plus) faces(t, l.primitive, -1);
  if (!p.next("count the intersected back faces behind")) return;
  glStencilFunc(GL_NOTEQUAL, int(plus.size()), 0xff);  // fewer: outside one, to the far plane
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glDepthMask(GL_TRUE); glDepthFunc(GL_ALWAYS);
  gllab::draw_screen_quad(1.0);
  glClear(GL_STENCIL_BUFFER_BIT);
  merge(t, prod, R, lit);
  p.next("merged into R, shaded where it won");
}

// The tree by either algorithm, product by product, in the window (whole, lit) or in its
// top left quarter (flat colours); returns the caption's first lines.
std::vector<std::string> draw_csg(const State& s, const sp::NamedTree& t, bool use_scs,
                                  Passes& p, bool whole) {
  const Panel mine = enter_panel(0, 0, whole ? 1 : 2, whole ? 1 : 2, s.width, s.height);
  gllab::space_camera(s, mine.width, mine.height, 1.6);
  std::vector<GLuint> R(std::size_t(mine.width) * mine.height, 0xffffffffu);  // all far
  glEnable(GL_DEPTH_TEST), glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);  // −b lit inside
  const std::vector<sp::Product> sop = sp::sum_of_products(t.tree);
  for (const sp::Product& prod : sop) {
    if (use_scs) scs(t.tree, prod, R, p, whole);
    else goldfeather(t.tree, prod, R, p, whole);
    if (p.done >= p.limit) break;
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);  // as they were, if a pass stopped early
  glStencilMask(0xff); glDepthMask(GL_TRUE); glDepthFunc(GL_LESS);
  glDisable(GL_STENCIL_TEST), glDisable(GL_CULL_FACE), glDisable(GL_LIGHTING);
  return {format_text("tree %d: %s", s.integer("tree"), t.formula.c_str()),
          format_text("%s: %zu products, %d passes", use_scs ? "SCS" : "Goldfeather", sop.size(),
                      p.done)};
}
Panel quarter(const State& s, int c, int r) { return enter_panel(c, r, 2, 2, s.width, s.height); }

// goldfeather, scs: the picture, lit.
void draw_picture(const State& s, bool use_scs) {
  const sp::NamedTree t = make_tree(s);
  Passes p;  // all of them
  const std::vector<std::string> lines = draw_csg(s, t, use_scs, p, true);
  if (s.integer("tree") == 0) gllab::draw_control_points(s, "S", {1, 1, .3f}, 7.f);
  gllab::draw_csg_caption(t.tree, lines, s.width, s.height);
}
void draw_goldfeather(const State& s) { draw_picture(s, false); }
void draw_scs(const State& s) { draw_picture(s, true); }

// passes: the depth (left) and stencil (right) buffers after pass k, and what it did.
void draw_passes(const State& s) {
  const sp::NamedTree t = make_tree(s);
  Passes p{s.integer("pass"), 0, {}};  // stop after pass k
  std::vector<std::string> lines = draw_csg(s, t, s.flag("scs"), p, false);
  gllab::show_depth_and_stencil(quarter(s, 0, 0), quarter(s, 1, 0));
  lines.push_back(p.what + (p.done < p.limit ? " (the last pass)" : ""));
  gllab::leave_panels(s.width, s.height);
  gllab::draw_csg_caption(t.tree, lines, s.width, s.height, true);
}

// ray_cast: the picture in flat colours beside the core's ray cast, and their heat map.
void draw_ray_cast(const State& s) {
  const sp::NamedTree t = make_tree(s);
  Passes p;  // all of them
  std::vector<std::string> lines = draw_csg(s, t, s.flag("scs"), p, false);
  lines.push_back("right: ray cast (Roth 1982); below: heat map");
  const gllab::Comparison c = gllab::compare_with_ray_cast(t.tree, kClear, quarter(s, 0, 0),
                                                           quarter(s, 1, 0), quarter(s, 0, 1));
  if (s.interactive)  // edge pixels vary between renderers: not in graded text
    lines.push_back(format_text("%lld pixels differ, %lld by a 1-pixel shift", c.differing_pixels,
                                c.shifted_pixels()));
  const long long odd = c.mismatched_pixels;  // the pixels no 1-pixel shift explains
  const char* const verdict = odd <= kAgree ? "agrees: at most" : "disagrees:";
  lines.push_back(format_text("%s %lld pixels no shift explains", verdict, std::max(odd, kAgree)));
  gllab::leave_panels(s.width, s.height);
  gllab::draw_csg_caption(t.tree, lines, s.width, s.height, true);
}

void init() { glClearColor(kClear.r, kClear.g, kClear.b, 1.f); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "33_csg_stencil",
      "lab 33 · CSG with the stencil buffer",
      {{"goldfeather", "the tree by Goldfeather's parity counting, lit", draw_goldfeather, kOrbit},
       {"scs", "the tree by SCS (convex primitives), lit", draw_scs, kOrbit},
       {"passes", "the depth and stencil buffers after pass k", draw_passes, kOrbit},
       {"ray_cast", "stencil CSG beside the exact ray cast, a heat map", draw_ray_cast, kOrbit}},
      {{"tree", 0, 0, double(sp::csg_catalogue().size() - 1), "0 the classic object, 1.. others"},
       {"op", 0, 0, 2, "tree 0's operator between box and sphere: 0 ∩, 1 ∪, 2 −"},
       {"pass", 3, 1, 600, "passes: stop after this pass"},
       {"scs", 0, 0, 1, "passes, ray_cast: 0 Goldfeather, 1 SCS"}},
      {{'t', "next tree", "tree", +1}, {'T', "previous tree", "tree", -1},
       {'o', "operator ∩ → ∪ → −", "op", +1}, {'O', "operator back", "op", -1},
       {'s', "next pass", "pass", +1}, {'S', "previous pass", "pass", -1},
       {'a', "Goldfeather/SCS", "scs"}},
      init};
  lab.points = {{"S", {{0, 0, 0}}, "the sphere's centre (tree 0)", 3}};
  return lab;
}
