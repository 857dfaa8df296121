// lab 14 · NURBS curves                                       difficulty: ★★★☆
// Rational B-splines (seed 000 §1.6): weights that pull the curve towards a
// control point or push it away, the seeds' conic sections from r, the exact
// circle, and gluNurbsCurve with GL_MAP1_VERTEX_4 against the own core, fed
// right (w x, w y, w z, w) and wrong (x, y, z, w).
// Notice: as one weight changes, C(u) at a fixed u slides along a straight
//   line through its control point. C(1/2) of a conic is (1 - r) M + r P1.
//   The mistake is invisible while every weight is 1.
// Try: press [w] until the curve nearly touches P3; press [r] past 1/2 and
//   watch the ellipse become a parabola, then a hyperbola.
// Keys: [w]/[W] weight x2 /2  [n]/[N] weighted point  [r]/[R] conic r
//   [s]/[S] GLU samples  [m] not premultiplied  [o] own curve  [g] GLU curve
//   [h] help  [Esc] quit
// Views: weights, conics, circle, own_vs_glu, not_premultiplied
// Reference: reference_images/14_nurbs_curves__*.png

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/glu_compare.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/bspline.h"
#include "spline/nurbs.h"

namespace {

using gllab::RationalFeed;
using gllab::Rgb;
using gllab::State;
using gllab::spline::BsplineCurve;
using gllab::spline::Vec3;

// Lab data (edit me) -------------------------------------------------------
constexpr int kDegree = 3;
const std::vector<Vec3> kPoints = {{-4, -3, 0}, {-3.5, 1.5, 0}, {-1.5, -.5, 0}, {0, 3.5, 0},
                                   {1.5, -.5, 0}, {3.5, 1.5, 0}, {4, -3, 0}};
const double kFamily[] = {.25, .5, 1, 2, 4, 16};  // weights of the selected point, drawn thin
const std::vector<Vec3> kTriangle = {{-3.5, -2.5, 0}, {0, 4, 0}, {3.5, -2.5, 0}};  // conic: P0, apex P1, P2
const double kConics[] = {0, .25, .5, .75};  // line, ellipse, parabola, hyperbola (seed 000 §1.6)
const Vec3 kCentre{-1.8, 1.3, 0};
constexpr double kRadius = 2.2;
const Rgb kCurve{.35f, .8f, 1.f}, kPolygon{.55f, .55f, .6f}, kPoint{1.f, .8f, .3f}, kGlu{1.f, .45f, .1f},
    kWrong{1.f, .25f, .35f}, kUsed{1.f, .6f, .7f}, kAxes{.6f, .9f, .5f}, kText{1.f, 1.f, 1.f};
const Rgb kPalette[] = {{.95f, .35f, .35f}, {.95f, .65f, .25f}, {.9f, .9f, .3f},
                        {.45f, .85f, .35f}, {.3f, .85f, .8f},   {.75f, .45f, .95f}};

// Curves from the State ------------------------------------------------------
// The cubic on P with every weight 1 but the selected point's: a NURBS curve.
BsplineCurve weighted(const State& s, double w) {
  BsplineCurve c = gllab::spline::clamped_curve(s.points("P"), kDegree, 2);
  c.w.assign(c.P.size(), 1.0);
  c.w[s.integer("point")] = w;
  return c;
}
BsplineCurve conic(const State& s, double r) {
  const std::vector<Vec3>& T = s.points("T");
  return gllab::spline::conic_arc(T[0], T[1], T[2], r, 2);
}

std::string fmt(const char* format, double a, double b = 0, double c = 0) {
  char text[120];
  std::snprintf(text, sizeof text, format, a, b, c);
  return text;
}
std::string weight_text(double w) { return w < 1 ? fmt("1/%g", 1 / w) : fmt("%g", w); }

gllab::GluNurbs glu_of(const State& s) {
  gllab::GluNurbsProperties p;
  p.sampling_method = GLU_DOMAIN_DISTANCE;  // numeric: the same vertices in any viewport
  p.u_step = float(s.get("glu_step"));
  return gllab::GluNurbs(p);
}
// GLU draws with the current colour and line width.
void draw_glu(gllab::GluNurbs& glu, const BsplineCurve& c, RationalFeed feed, Rgb colour, float width) {
  glColor3f(colour.r, colour.g, colour.b);
  glLineWidth(width);
  glu.draw_curve(c, "lab 14 curve", feed);
}

// Drawing -------------------------------------------------------------------
void draw_weights(const State& s) {
  const int i = s.integer("point");
  const double xi = gllab::spline::greville_abscissae(kDegree, weighted(s, 1).U)[i];  // u "of" P_i
  gllab::draw_control_polygon(s.points("P"), kPolygon);
  std::vector<Vec3> line;  // C(xi) for every weight: on one line through P_i
  for (std::size_t k = 0; k < std::size(kFamily); ++k) {
    const BsplineCurve c = weighted(s, kFamily[k]);
    gllab::draw_curve(c, kPalette[k], 1.f);
    line.push_back(gllab::spline::curve_point(c, xi));
    gllab::draw_label(line.back().x, line.back().y, 0, "w=" + weight_text(kFamily[k]), kPalette[k], 34, 4);
  }
  gllab::draw_dots(line, kText, 5.f);
  line.push_back(s.points("P")[i]);
  gllab::draw_dashed_polyline(line, kText);
  gllab::draw_curve(weighted(s, s.get("weight")), kCurve, 4.f);
  gllab::draw_control_points(s, "P", kPoint, 9.f, true);
  gllab::draw_text_panel(8, 420,
                         {fmt("blue: w%.0f = ", i) + weight_text(s.get("weight")) + ", the other weights 1",
                          "X(u) = sum w_i N_i(u) P_i / sum w_i N_i(u)",
                          fmt("dots: C(%.3g) for each weight, on a line through P%.0f", xi, i)},
                         kText);
}

void draw_conics(const State& s) {
  const std::vector<Vec3>& T = s.points("T");
  const Vec3 M = 0.5 * (T[0] + T[2]);  // C(1/2) = (1 - r) M + r P1: r measures the shoulder
  gllab::draw_control_polygon(T, kPolygon);
  gllab::draw_dashed_polyline({M, T[1]}, kPolygon);
  const double current = s.get("r");
  for (std::size_t k = 0; k <= std::size(kConics); ++k) {
    const double r = k < std::size(kConics) ? kConics[k] : current;
    const Rgb colour = k < std::size(kConics) ? kPalette[k] : kCurve;
    const Vec3 shoulder = gllab::spline::lerp(M, T[1], r);
    gllab::draw_dots({shoulder}, k < std::size(kConics) ? colour : kText, 7.f);  // under the curve: does it pass?
    gllab::draw_curve(conic(s, r), colour, k < std::size(kConics) ? 1.5f : 3.f);
    if (k < std::size(kConics))
      gllab::draw_label(shoulder.x, shoulder.y, 0, fmt("r=%g ", r) + to_string(gllab::spline::classify_conic(r)),
                        colour, 0, -14);
  }
  gllab::draw_control_points(s, "T", kPoint, 9.f, true);
  gllab::draw_text_panel(8, 424,
                         {fmt("blue: r = %g, ", current) + to_string(gllab::spline::classify_conic(current)) +
                              fmt(", w1 = r/(1-r) = %.4g", gllab::spline::conic_weight(current)),
                          "r > 1/2 hyperbola, = 1/2 parabola, < 1/2 ellipse, 0 a line",
                          "dots: C(1/2) = (1 - r) M + r P1, M the middle of P0 P2"},
                         kText);
}

void draw_circle() {
  const BsplineCurve exact = gllab::spline::circle(kCentre, kRadius);
  BsplineCurve polynomial = exact;  // the same 9 points and knots, no weights
  polynomial.w.clear();
  const auto radial_error = [](const BsplineCurve& c) {
    return [&c](double u) { return gllab::spline::norm(gllab::spline::curve_point(c, u) - kCentre) / kRadius - 1; };
  };
  double worst[2] = {0, 0};
  for (int k = 0; k <= 1000; ++k)
    for (int j = 0; j < 2; ++j) worst[j] = std::max(worst[j], std::abs(radial_error(j ? polynomial : exact)(k / 1000.)));
  gllab::draw_control_polygon(exact.P, kPolygon);
  gllab::draw_curve(polynomial, kGlu, 2.f);
  gllab::draw_curve(exact, kCurve, 2.f);
  const double top = gllab::plot_ceiling(worst[1]);
  const gllab::PlotFrame f{-4, -4.2, 4, -1.5, 0, 1, -.2 * top, top};
  gllab::draw_plot_axes(f, kPolygon, "radial error |C(u) - centre| / R - 1");
  gllab::draw_plot_function(f, radial_error(polynomial), kGlu);
  gllab::draw_plot_function(f, radial_error(exact), kCurve);
  gllab::draw_plot_ticks(f, exact.U, kAxes);
  gllab::draw_label(f.left, f.top, 0, fmt("%g", top), kText, 20, 10);
  gllab::draw_text_panel(292, 40,
                         {"blue: NURBS circle,", "9 points, degree 2,", "w = 1, 0.7071, 1, ...", "U = 0x3 1/4x2 1/2x2",
                          "    3/4x2 1x3", fmt("max error %.1e", worst[0]), "", "orange: no weights",
                          "(same points, knots)", fmt("max error %.2f %%", 100 * worst[1])},
                         kText);
}

void draw_own_vs_glu(const State& s) {
  const RationalFeed feed = s.flag("mistake") ? RationalFeed::kMistakeNotPremultiplied : RationalFeed::kPremultiplied;
  gllab::GluNurbs glu = glu_of(s);
  const BsplineCurve curves[] = {weighted(s, s.get("weight")), gllab::spline::circle({}, 1.5), conic(s, s.get("r"))};
  const Vec3 at[] = {{-2.25, 2.5, 0}, {-2.25, -2.25, 0}, {2.25, 2.25, 0}};  // where each is drawn
  const double scale[] = {.5, 1, .5};
  std::vector<std::string> lines = {"GL_MAP1_VERTEX_4, fed", s.flag("mistake") ? "(x, y, z, w): the mistake" : "(w x, w y, w z, w)",
                                    fmt("GLU_DOMAIN_DISTANCE, u_step %g", s.get("glu_step")), "",
                                    "max |GLU vertex - own C(u)|:"};
  const char* names[] = {"cubic", "circle", "conic"};
  for (int k = 0; k < 3; ++k) {
    glPushMatrix();
    glTranslated(at[k].x, at[k].y, 0);
    glScaled(scale[k], scale[k], 1);
    gllab::draw_control_polygon(curves[k].P, kPolygon);
    // Alone, GLU's line is as thin as ours, so the pictures compare pixel for pixel.
    if (s.flag("glu")) draw_glu(glu, curves[k], feed, kGlu, s.flag("own") ? 7.f : 2.5f);
    if (s.flag("own")) gllab::draw_curve(curves[k], kCurve, 2.5f);
    if (k != 1) gllab::draw_control_points(s, k == 0 ? "P" : "T", kPoint, 7.f);
    glPopMatrix();
    const gllab::GluCurveDifference d = gllab::compare_with_glu(glu, curves[k], names[k], feed);
    std::string name = names[k];
    name.resize(7, ' ');
    lines.push_back(name + fmt("%3.0f vertices  %.1e", double(d.u.size()), d.max_distance));
  }
  gllab::draw_text_panel(252, 300, lines, kText);
}

void draw_mistake(const State& s) {
  gllab::GluNurbs glu = glu_of(s);
  const BsplineCurve curves[] = {gllab::spline::circle({}, 1.3), weighted(s, s.get("weight"))};
  for (int row = 0; row < 2; ++row)
    for (int column = 0; column < 2; ++column) {
      const BsplineCurve& c = curves[row];
      glPushMatrix();
      glTranslated(column ? 2.25 : -2.25, row ? -2.75 : 2, 0);
      if (row) glScaled(.5, .5, 1);
      gllab::draw_control_polygon(c.P, kPolygon);
      if (column == 0) {
        draw_glu(glu, c, RationalFeed::kPremultiplied, kCurve, 2.5f);
      } else {
        // What GLU really used: (x, y, z, w) read as (w x', w y', w z', w), so P' = P / w.
        std::vector<Vec3> used;
        for (std::size_t i = 0; i < c.P.size(); ++i) used.push_back(c.P[i] / c.w[i]);
        gllab::draw_dashed_polyline(used, kUsed);
        gllab::draw_dots(used, kUsed, 6.f);
        gllab::draw_curve(c, kPolygon, 1.f);  // the right curve, thin grey
        draw_glu(glu, c, RationalFeed::kMistakeNotPremultiplied, kWrong, 2.5f);
      }
      if (row) gllab::draw_control_points(s, "P", kPoint, 7.f);
      glPopMatrix();
    }
  const gllab::GluCurveDifference d =
      gllab::compare_with_glu(glu, curves[0], "circle", RationalFeed::kMistakeNotPremultiplied);
  gllab::draw_label(-2.25, 4.2, 0, "right: (w x, w y, w z, w)", kCurve);
  gllab::draw_label(2.25, 4.2, 0, "mistake: (x, y, z, w)", kWrong);
  gllab::draw_text_panel(8, 256,
                         {fmt("pink: what GLU used, P_i / w_i. Circle: off by %.2f R", d.max_distance / 1.3),
                          fmt("cubic: w%.0f = ", s.integer("point")) + weight_text(s.get("weight")) +
                              "; at w = 1 the mistake shows nothing"},
                         kText);
}

// init / display ----------------------------------------------------------
void display(const State& s) {
  glClearColor(.1f, .1f, .12f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  const std::string& v = s.view();
  if (v == "conics") draw_conics(s);
  else if (v == "circle") draw_circle();
  else if (v == "own_vs_glu") draw_own_vs_glu(s);
  else if (v == "not_premultiplied") draw_mistake(s);
  else draw_weights(s);
}

// [w]/[W] and [s]/[S] double or halve (powers of two stay exact), clamped to the range.
bool keyboard(State& s, unsigned char key) {
  const char* name = key == 'w' || key == 'W' ? "weight" : key == 's' || key == 'S' ? "glu_step" : nullptr;
  if (!name) return false;
  s.step(name, key == 'w' || key == 's' ? s.get(name) : -s.get(name) / 2);
  return true;
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  Lab lab{"14_nurbs_curves",
          "lab 14 · NURBS curves",
          {{"weights", "one weight pulls the curve to its point or pushes it away"},
           {"conics", "conics from r: line, ellipse, parabola, hyperbola"},
           {"circle", "the exact NURBS circle vs the same points without weights"},
           {"own_vs_glu", "gluNurbsCurve with GL_MAP1_VERTEX_4 under the own curves"},
           {"not_premultiplied", "GLU fed (x, y, z, w) instead of (w x, w y, w z, w)"}},
          {{"point", 3, 0, double(kPoints.size() - 1), "the control point whose weight [w] changes"},
           {"weight", 4, 1.0 / 64, 64, "its weight w (the others are 1)"},
           {"r", .875, 0, .9375, "the conic's r (seed 000): w1 = r / (1 - r)"},
           {"glu_step", 32, 1, 256, "GLU_U_STEP: GLU's samples per unit of u (GLU_DOMAIN_DISTANCE)"},
           {"mistake", 0, 0, 1, "own_vs_glu: feed GLU (x, y, z, w), not premultiplied"},
           {"own", 1, 0, 1, "own_vs_glu: draw the own curves"}, {"glu", 1, 0, 1, "own_vs_glu: draw gluNurbsCurve"}},
          {{'w', "weight x2"}, {'W', "weight /2"},
           {'n', "weight the next control point", "point", +1}, {'N', "weight the previous control point", "point", -1},
           {'r', "conic r +1/16", "r", +.0625}, {'R', "conic r -1/16", "r", -.0625},
           {'s', "GLU samples per unit of u x2"}, {'S', "GLU samples per unit of u /2"},
           {'m', "own_vs_glu: weights not premultiplied on/off", "mistake"},
           {'o', "own curves on/off (own_vs_glu)", "own"}, {'g', "GLU curves on/off (own_vs_glu)", "glu"}},
          nullptr, display, keyboard};
  lab.points = {{"P", kPoints, "control points of the weighted cubic"}, {"T", kTriangle, "the conic's P0, P1, P2"}};
  lab.model = [](const State& s) -> Model { return weighted(s, s.get("weight")); };
  return lab;
}
