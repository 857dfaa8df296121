// lab 16 · NURBS curves                                       difficulty: ★★★☆
// Rational B-splines (lecture notes ch. 1, §1.6 Spline representations, "Rational
// B-splines", "Conic sections", "Displaying NURBS with OpenGL"): a weight pulls the curve
// to its point or pushes it away, conics from r, the exact circle, and gluNurbsCurve
// with GL_MAP1_VERTEX_4, fed (w x, w y, w z, w) and, the classic mistake, (x, y, z, w).
// Notice: as one weight changes, C(u) at a fixed u slides along a straight
//   line through its control point. C(1/2) of a conic is (1 - r) M + r P1.
//   The mistake is invisible while every weight is 1.
// Try: press [w] until the curve nearly touches P3; press [r] past 1/2 and
//   watch the ellipse become a parabola, then a hyperbola.
// Keys: [w]/[W] weight x2 /2  [n]/[N] weighted point  [r]/[R] conic r
//   [s]/[S] GLU samples per unit of u  [h] help  [Esc] quit
// Views: weights, conics, circle, own_vs_glu, not_premultiplied
// Reference: reference_images/16_nurbs_curves__*.png

#include <iterator>
#include <string>
#include <vector>

#include "gl/curve_view.h"
#include "gl/gl.h"
#include "gl/glu_arrays.h"
#include "gl/glu_errors.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/bspline.h"
#include "spline/nurbs.h"

namespace {

namespace spline = gllab::spline;
using gllab::Rgb;
using gllab::State;
using spline::BsplineCurve;
using spline::Vec3;

// Lab data (edit me) -------------------------------------------------------
// A clamped cubic on P0..P6: 7 points + order 4 = 11 knots; every weight 1 but P3's.
const std::vector<Vec3> kPoints = {{-4, -3, 0}, {-3.5, 1.5, 0}, {-1.5, -.5, 0}, {0, 3.5, 0},
                                   {1.5, -.5, 0}, {3.5, 1.5, 0}, {4, -3, 0}};
const GLfloat kCubicKnots[11] = {0, 0, 0, 0, .25f, .5f, .75f, 1, 1, 1, 1};
const double kFamily[] = {.25, .5, 1, 2, 4, 16};  // weights of the selected point, drawn thin
// The conic's P0, apex P1, P2; r = 0, 1/4, 1/2, 3/4: line, ellipse, parabola, hyperbola.
const std::vector<Vec3> kTriangle = {{-3.5, -2.5, 0}, {0, 4, 0}, {3.5, -2.5, 0}};
const double kConics[] = {0, .25, .5, .75};
// The circle view's circle (spline::circle, The NURBS Book §7.5: 9 points, weights 1, √2/2).
const Vec3 kCentre{-1.8, 1.3, 0};
constexpr double kRadius = 2.2;
const Rgb kCurve{.35f, .8f, 1.f}, kPolygon{.55f, .55f, .6f}, kPoint{1.f, .8f, .3f}, kText{1, 1, 1},
    kGlu{1.f, .45f, .1f}, kWrong{1.f, .25f, .35f}, kUsed{1.f, .6f, .7f}, kAxes{.6f, .9f, .5f};
const Rgb kPalette[] = {{.95f, .35f, .35f}, {.95f, .65f, .25f}, {.9f, .9f, .3f},
                        {.45f, .85f, .35f}, {.3f, .85f, .8f},   {.75f, .45f, .95f}};

// One GLU NURBS object, made in init() (§1.6 "Displaying NURBS with OpenGL").
GLUnurbs* g_nurb = nullptr;

// GLU calls this from inside the failed call: the window shows it, headless exits 1.
void GLAPIENTRY on_nurbs_error(GLenum code) { gllab::report_glu_error(code, "gluNurbsCurve"); }

// Curves from the data: the cubic with weight w at the selected point ------------
BsplineCurve weighted(const State& s, double w) {
  BsplineCurve c{3, {std::begin(kCubicKnots), std::end(kCubicKnots)}, s.points("P"), {}, 2};
  c.w.assign(c.P.size(), 1.0);
  c.w[s.integer("point")] = w;
  return c;
}
BsplineCurve conic(const State& s, double r) {  // w1 = r / (1 - r); at r = 0 a polynomial line
  const std::vector<Vec3>& T = s.points("T");
  return spline::conic_arc(T[0], T[1], T[2], r, 2);
}

// A curve as gluNurbsCurve takes it: float knots, GL_MAP1_VERTEX_4's points, the order.
struct GluCurve { std::vector<GLfloat> knots, ctl; GLint order; };
// "The vertices have the weights as their fourth component" (§1.6 "Displaying
// NURBS with OpenGL"), and GLU divides by it: each point goes premultiplied.
GluCurve glu_curve(const BsplineCurve& c, bool premultiplied) {
  GluCurve g{{c.U.begin(), c.U.end()}, {}, c.p + 1};
  for (std::size_t i = 0; i < c.P.size(); ++i) {
    const Vec3 p = c.P[i];
    const double w = c.rational() ? c.w[i] : 1;
    if (premultiplied)
      g.ctl.insert(g.ctl.end(), {GLfloat(w * p.x), GLfloat(w * p.y), GLfloat(w * p.z), GLfloat(w)});
    else  // the classic mistake: GLU then draws the curve of the points P_i / w_i
      g.ctl.insert(g.ctl.end(), {GLfloat(p.x), GLfloat(p.y), GLfloat(p.z), GLfloat(w)});
  }
  return g;
}
// GLU draws with the current colour and line width.
void draw_glu(GluCurve g, Rgb colour, float width) {
  glColor3f(colour.r, colour.g, colour.b);
  glLineWidth(width);
  gluBeginCurve(g_nurb);
  gluNurbsCurve(g_nurb, GLint(g.knots.size()), g.knots.data(), 4, g.ctl.data(), g.order,
                GL_MAP1_VERTEX_4);
  gluEndCurve(g_nurb);
}
// The own core reads the same arguments (gl/glu_arrays.h).
BsplineCurve own(const GluCurve& g) {
  return gllab::core_curve(GLint(g.knots.size()), g.knots.data(), 4, g.ctl.data(), g.order,
                           GL_MAP1_VERTEX_4);
}

// Drawing -------------------------------------------------------------------
void draw_weights(const State& s) {
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  const int i = s.integer("point");
  const double xi = spline::greville_abscissae(3, weighted(s, 1).U)[i];  // u "of" P_i
  gllab::draw_control_polygon(s.points("P"), kPolygon);
  std::vector<Vec3> line;  // C(xi) for every weight: on one line through P_i
  for (std::size_t k = 0; k < std::size(kFamily); ++k) {
    const BsplineCurve c = weighted(s, kFamily[k]);
    gllab::draw_curve(c, kPalette[k], 1.f);
    line.push_back(spline::curve_point(c, xi));
    const std::string w = "w=" + gllab::weight_text(kFamily[k]);
    gllab::draw_label(line.back().x, line.back().y, 0, w, kPalette[k], 34, 4);
  }
  gllab::draw_dots(line, kText, 5.f);
  line.push_back(s.points("P")[i]);
  gllab::draw_dashed_polyline(line, kText);
  gllab::draw_curve(weighted(s, s.get("weight")), kCurve, 4.f);
  gllab::draw_control_points(s, "P", kPoint, 9.f, true);
  gllab::draw_text_panel(8, 420, gllab::weights_caption(i, s.get("weight"), xi), kText);
}

void draw_conics(const State& s) {
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  const std::vector<Vec3>& T = s.points("T");
  const Vec3 M = 0.5 * (T[0] + T[2]);  // C(1/2) = (1 - r) M + r P1: r measures the shoulder
  gllab::draw_control_polygon(T, kPolygon);
  gllab::draw_dashed_polyline({M, T[1]}, kPolygon);
  for (std::size_t k = 0; k < std::size(kConics); ++k) {
    const Vec3 q = spline::lerp(M, T[1], kConics[k]);  // the shoulder point
    gllab::draw_dots({q}, kPalette[k], 7.f);  // under the curve: does it pass?
    gllab::draw_curve(conic(s, kConics[k]), kPalette[k], 1.5f);
    gllab::draw_label(q.x, q.y, 0, gllab::conic_label(kConics[k]), kPalette[k], 0, -14);
  }
  const double r = s.get("r");
  gllab::draw_dots({spline::lerp(M, T[1], r)}, kText, 7.f);
  gllab::draw_curve(conic(s, r), kCurve, 3.f);
  gllab::draw_control_points(s, "T", kPoint, 9.f, true);
  gllab::draw_text_panel(8, 424, gllab::conics_caption(r), kText);
}

void draw_circle(const State& s) {
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  const BsplineCurve exact = spline::circle(kCentre, kRadius);
  BsplineCurve polynomial = exact;  // the same 9 points and knots, no weights
  polynomial.w.clear();
  gllab::draw_circle_comparison(exact, polynomial, kCentre, kRadius, {-4, -4.2, 4, -1.5}, kCurve,
                                kGlu, kPolygon, kAxes, kText);  // below: |C(u) - centre| / R - 1
}

// The weighted cubic, a circle and the conic: GLU's curve (thick) under the own one.
void draw_own_vs_glu(const State& s) {
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  gluNurbsProperty(g_nurb, GLU_U_STEP, GLfloat(s.get("glu_step")));  // samples per unit of u
  const BsplineCurve curves[] = {weighted(s, s.get("weight")), spline::circle({}, 1.5),
                                 conic(s, s.get("r"))};
  const double at[3][3] = {{-2.25, 2.5, .5}, {-2.25, -2.25, 1}, {2.25, 2.25, .5}};  // x, y, scale
  std::vector<std::string> lines = gllab::glu_table_caption(s.get("glu_step"));
  const char* names[] = {"cubic", "circle", "conic"};
  for (int k = 0; k < 3; ++k) {
    const GluCurve g = glu_curve(curves[k], true);
    const BsplineCurve mine = own(g);
    gllab::push_placed(at[k][0], at[k][1], at[k][2]);
    gllab::draw_control_polygon(mine.P, kPolygon);
    // Alone, GLU's line is as thin as ours, so the pictures compare pixel for pixel.
    if (s.flag("glu")) draw_glu(g, kGlu, s.flag("own") ? 7.f : 2.5f);
    if (s.flag("own")) gllab::draw_curve(mine, kCurve, 2.5f);
    if (k != 1) gllab::draw_control_points(s, k == 0 ? "P" : "T", kPoint, 7.f);
    glPopMatrix();
    lines.push_back(gllab::glu_row(names[k], gllab::glu_difference(g_nurb, mine, mine, names[k])));
  }
  gllab::draw_text_panel(252, 300, lines, kText);
}

// Left: GLU fed (w x, w y, w z, w); right: fed (x, y, z, w), over the right curve (thin).
void draw_mistake(const State& s) {
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  gluNurbsProperty(g_nurb, GLU_U_STEP, GLfloat(s.get("glu_step")));
  const BsplineCurve curves[] = {spline::circle({}, 1.3), weighted(s, s.get("weight"))};
  for (int row = 0; row < 2; ++row) {
    const BsplineCurve& c = curves[row];
    const GluCurve right = glu_curve(c, true), wrong = glu_curve(c, false);
    for (int column = 0; column < 2; ++column) {
      gllab::push_placed(column ? 2.25 : -2.25, row ? -2.75 : 2, row ? .5 : 1);
      gllab::draw_control_polygon(c.P, kPolygon);
      if (column) {
        const std::vector<Vec3> used = own(wrong).P;  // what GLU used: P_i / w_i
        gllab::draw_dashed_polyline(used, kUsed);
        gllab::draw_dots(used, kUsed, 6.f);
        gllab::draw_curve(c, kPolygon, 1.f);  // the right curve, thin grey
      }
      draw_glu(column ? wrong : right, column ? kWrong : kCurve, 2.5f);
      if (row) gllab::draw_control_points(s, "P", kPoint, 7.f);
      glPopMatrix();
    }
  }
  const BsplineCurve wrong = own(glu_curve(curves[0], false));
  const double off = gllab::glu_difference(g_nurb, wrong, curves[0], "circle").max_distance / 1.3;
  gllab::draw_mistake_captions(off, s.integer("point"), s.get("weight"), kCurve, kWrong, kText);
}

// init / shutdown ------------------------------------------------------------
void init() {
  glClearColor(.1f, .1f, .12f, 1.f);
  g_nurb = gluNewNurbsRenderer();
  gluNurbsCallback(g_nurb, GLU_NURBS_ERROR, reinterpret_cast<_GLUfuncptr>(on_nurbs_error));
  // GLU_U_STEP samples per unit of u, whatever the window: the same vertices
  // in a window and headless (GLU's default, GLU_PATH_LENGTH, counts pixels).
  gluNurbsProperty(g_nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  // GLU's default. A curve is one line in every mode (measured: the outlines draw the same).
  gluNurbsProperty(g_nurb, GLU_DISPLAY_MODE, GLU_FILL);
}

// [w]/[W] and [s]/[S] double or halve (powers of two stay exact), clamped to the range.
bool keyboard(State& s, unsigned char key) {
  if (std::string("wWsS").find(char(key)) == std::string::npos) return false;
  const char* name = key == 'w' || key == 'W' ? "weight" : "glu_step";
  s.step(name, key == 'w' || key == 's' ? s.get(name) : -s.get(name) / 2);
  return true;
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  Lab lab{"16_nurbs_curves",
          "lab 16 · NURBS curves",
          {{"weights", "one weight pulls the curve to its point or pushes it away", draw_weights},
           {"conics", "conics from r: line, ellipse, parabola, hyperbola", draw_conics},
           {"circle", "the exact NURBS circle vs the same points without weights", draw_circle},
           {"own_vs_glu", "gluNurbsCurve, GL_MAP1_VERTEX_4, under the own curves", draw_own_vs_glu},
           {"not_premultiplied", "GLU fed (x, y, z, w), not (w x, w y, w z, w)", draw_mistake}},
          {{"point", 3, 0, double(kPoints.size() - 1), "the point whose weight [w] changes"},
           {"weight", 4, 1.0 / 64, 64, "its weight w (the others are 1)"},
           {"r", .875, 0, .9375, "the conic's r: w1 = r / (1 - r)"},
           {"glu_step", 32, 1, 256, "GLU_U_STEP: GLU's samples per unit of u"},
           {"own", 1, 0, 1, "own_vs_glu: the own curves"}, {"glu", 1, 0, 1, "own_vs_glu: GLU's"}},
          {{'w', "weight x2"}, {'W', "weight /2"}, {'s', "GLU samples x2"}, {'S', "GLU samples /2"},
           {'n', "weight next point", "point", +1}, {'N', "weight previous point", "point", -1},
           {'r', "conic r +1/16", "r", +.0625}, {'R', "conic r -1/16", "r", -.0625}},
          init};
  lab.keyboard = keyboard;
  lab.shutdown = [] { gluDeleteNurbsRenderer(g_nurb); };
  lab.points = {{"P", kPoints, "the weighted cubic's points"}, {"T", kTriangle, "the conic's"}};
  lab.model = [](const State& s) -> Model { return weighted(s, s.get("weight")); };
  return lab;
}
