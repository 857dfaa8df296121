// lab 13 · B-spline curves                                    difficulty: ★★★☆
// One cubic B-spline (seed 000 §1.6, seeds 003 and 004): its basis functions
// by Cox–de Boor, knot vectors clamped, non-uniform, floating and periodic,
// the seeds' multiplicity cases A–D, knot insertion, Bézier decomposition, and
// the own curve against gluNurbsCurve of the same data.
// Notice: a knot of multiplicity m leaves a cubic C^(3-m) there: A C2, B C1,
//   C C0 (the curve runs through d3), D a gap. Inserting a knot changes the
//   control polygon, not the curve. GLU agrees with the core to float precision.
// Try: drag d3 in cases_a_d: which segments move? Press [m] in basis and watch
//   the plot: how many basis functions are non-zero at the repeated knot?
// Keys: [n]/[N] select point  [i][j][k][l] move it  [m]/[M] multiplicity
//   [u]/[U] parameter u  [t] before/after insertion  [s]/[S] GLU samples
//   [o] own curve  [g] GLU curve  [h] help  [Esc] quit
// Views: basis, cases_a_d, knot_vectors, knot_insertion, bezier_pieces, own_vs_glu
// Reference: reference_images/13_bspline_curves__*.png

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

namespace {

using gllab::PlotFrame;
using gllab::Rgb;
using gllab::State;
using gllab::spline::BsplineCurve;
using gllab::spline::Vec3;

// Lab data (edit me) -------------------------------------------------------
constexpr int kDegree = 3;  // cubic, as in the seeds
// d0..d7: seed 003's zigzag, moved into the upper half of the window.
const std::vector<Vec3> kPoints = {{-4, 1, 0}, {-3, 3, 0}, {-2, 4, 0}, {-1, 2, 0},
                                   {1, 3, 0},  {2, 1, 0}, {3, 4, 0},  {4, 2, 0}};
// Seed 000's knot insertion example: t = 0.5 goes into [u5, u6) = [0.4, 0.6).
const std::vector<double> kSeedKnots = {0, 0, 0, 0, .2, .4, .6, .8, 1, 1, 1, 1};
const std::vector<double> kNonUniform = {0, 0, 0, 0, .05, .1, .6, .95, 1, 1, 1, 1};
constexpr double kNudge = 0.125;  // [i][j][k][l] move the selected point this far
const Rgb kCurve{.35f, .8f, 1.f}, kPolygon{.55f, .55f, .6f}, kPoint{1.f, .8f, .3f}, kSelected{1.f, .3f, .4f},
    kKnot{.6f, .9f, .5f}, kNew{1.f, .5f, .2f}, kGlu{1.f, .45f, .1f}, kText{1.f, 1.f, 1.f};
const Rgb kPalette[] = {{.95f, .35f, .35f}, {.95f, .65f, .25f}, {.9f, .9f, .3f},   {.45f, .85f, .35f},
                        {.3f, .85f, .8f},   {.4f, .55f, 1.f},   {.75f, .45f, .95f}, {.95f, .5f, .75f}};

// Curves from the State ------------------------------------------------------
BsplineCurve with_knots(const State& s, const std::vector<double>& U) { return {kDegree, U, s.points("P"), {}, 2}; }

// Seed 003's cases A–D: knots 0, 1, 2, 3, then `mult` copies of 4, then 5, 6, ...
BsplineCurve seed_case(const State& s, int mult) {
  std::vector<double> U = {0, 1, 2, 3};
  U.insert(U.end(), mult, 4.0);
  for (double v = 5; U.size() < kPoints.size() + kDegree + 1; ++v) U.push_back(v);
  return with_knots(s, U);
}

BsplineCurve curve_of(const State& s) {  // the one [Ctrl+S] saves
  const std::string& v = s.view();
  if (v == "knot_insertion" || v == "bezier_pieces" || v == "knot_vectors") return with_knots(s, kSeedKnots);
  return seed_case(s, s.integer("mult"));
}
double param_at(const BsplineCurve& c, double fraction) {  // u as a fraction of the domain
  const gllab::spline::ParamInterval d = gllab::spline::domain(c);
  return d.a + fraction * (d.b - d.a);
}

std::string fmt(const char* format, double a, double b = 0, double c = 0) {
  char text[120];
  std::snprintf(text, sizeof text, format, a, b, c);
  return text;
}
std::string fraction(double a) {  // " = 5/6" for a small denominator, as the seed prints it
  for (int q = 1; q <= 12; ++q)
    if (std::abs(a * q - std::round(a * q)) < 1e-9) return fmt(" = %.0f/%.0f", std::round(a * q), q);
  return "";
}

// Drawing -------------------------------------------------------------------
void band(const std::vector<std::string>& lines) { gllab::draw_text_panel(8, 206, lines, kText); }

void draw_points(const State& s, bool numbered) {
  gllab::draw_dots({s.points("P")[s.integer("point")]}, kSelected, 15.f);  // the one [i][j][k][l] move
  gllab::draw_control_points(s, "P", kPoint, 9.f, numbered);
}

// Every basis function N_i,3(u) of the curve's knot vector, over all of it,
// by the seeds' Cox–de Boor recursion (cox_de_boor), one colour each.
PlotFrame draw_basis_plot(const BsplineCurve& c, const std::string& title, bool labels) {
  const PlotFrame f{-4, -4, 4, -.8, c.U.front(), c.U.back(), 0, 1.1};
  gllab::draw_plot_axes(f, kPolygon, title);
  const std::vector<double> peaks = gllab::spline::greville_abscissae(c.p, c.U);  // near each maximum
  for (int i = 0; i <= c.n(); ++i) {
    const Rgb colour = kPalette[i % std::size(kPalette)];
    const auto N = [&](double u) { return gllab::spline::cox_de_boor(i, u, c.p, c.U); };
    // Only on its support [U[i], U[i+p+1]]: outside, NaN is not drawn.
    gllab::draw_plot_function(f, [&](double u) { return u < c.U[i] || u > c.U[i + c.p + 1] ? NAN : N(u); }, colour, 1.f);
    if (labels) gllab::draw_label(f.at(peaks[i], 0).x, f.at(0, N(peaks[i])).y, 0, fmt("%.0f", i), colour, 0, -10);
  }
  gllab::draw_plot_ticks(f, c.U, kKnot);
  const gllab::spline::ParamInterval d = gllab::spline::domain(c);  // where the N_i sum to 1
  for (double u : {d.a, d.b}) gllab::draw_dashed_polyline({f.at(u, 0), f.at(u, 1.1)}, kKnot);
  return f;
}

// The curve with its control polygon and knots above, its basis functions below.
PlotFrame draw_panel(const State& s, const BsplineCurve& c, const std::string& title, bool labels) {
  gllab::draw_control_polygon(c.P, kPolygon);  // periodic: with the wrapped points
  gllab::draw_knot_markers(c, kKnot);
  gllab::draw_curve(c, kCurve, 2.5f);
  draw_points(s, labels);
  return draw_basis_plot(c, title, labels);
}

std::string case_title(int mult) {
  const char* continuity[] = {"C2", "C1", "C0", "a gap"};
  return std::string(1, char('A' + mult - 1)) + fmt(": knot 4 x%.0f, ", mult) + continuity[mult - 1];
}

void draw_basis(const State& s) {
  const BsplineCurve c = seed_case(s, s.integer("mult"));
  const double u = param_at(c, s.get("u"));
  const gllab::spline::DeBoorConstruction construction = gllab::spline::de_boor(c, u);
  gllab::draw_de_boor(construction, kPolygon, kText);
  const PlotFrame f = draw_panel(s, c, "U =" + gllab::knot_vector_text(c.U) + "  " + case_title(s.integer("mult")), true);
  // At u only N_span-p .. N_span are non-zero: the weights of de Boor's p + 1 points.
  const std::vector<double> N = gllab::spline::all_basis_funs(u, c.p, c.U);
  gllab::draw_polyline({f.at(u, 0), f.at(u, 1.1)}, kText, 1.f);
  std::string values;
  for (int i = construction.span - c.p; i <= construction.span; ++i) {
    gllab::draw_dots({f.at(u, N[i])}, kPalette[i % std::size(kPalette)], 7.f);
    values += fmt(" %.3f", N[i]);
  }
  const std::string range = fmt("%.0f..%.0f", construction.span - c.p, construction.span);
  band({fmt("u = %.4g: N", u) + range + " =" + values,
        "C(u) = sum N_i(u) d_i: de Boor blends d" + range + " (white)"});
}

void draw_cells(const State& s, const std::vector<BsplineCurve>& curves, const std::vector<std::string>& titles) {
  for (std::size_t k = 0; k < curves.size(); ++k) {
    glPushMatrix();
    glTranslated(k % 2 ? 2.25 : -2.25, k < 2 ? 2.25 : -2.25, 0);
    glScaled(.5, .5, 1);
    draw_panel(s, curves[k], titles[k], false);
    glPopMatrix();
  }
}

void draw_cases(const State& s) {
  draw_cells(s, {seed_case(s, 1), seed_case(s, 2), seed_case(s, 3), seed_case(s, 4)},
             {case_title(1), case_title(2), case_title(3), case_title(4)});
}

void draw_knot_vectors(const State& s) {
  const BsplineCurve periodic = gllab::spline::periodic_curve(s.points("P"), kDegree, 2);  // P, then P[0..2] again
  draw_cells(s, {with_knots(s, kSeedKnots), with_knots(s, kNonUniform), seed_case(s, 1), periodic},
             {"clamped uniform (open)", "clamped non-uniform", "floating uniform", "periodic (closed)"});
}

void draw_insertion(const State& s) {
  const BsplineCurve c = with_knots(s, kSeedKnots);
  const double t = param_at(c, s.get("u"));
  const gllab::spline::KnotInsertStep step = gllab::spline::knot_insert_step(c, t);
  const bool after = s.flag("inserted");
  std::string a;
  gllab::draw_control_polygon(c.P, kPolygon);
  if (after) gllab::draw_polyline(step.curve.P, kNew, 1.5f);  // d0 d1 d2 q3 q4 q5 d5 d6 d7 in the seed's example
  for (std::size_t j = 0; j < step.a.size(); ++j) {
    const int i = step.first + int(j);
    a += fmt("a%.0f = %.4f", i, step.a[j]) + fraction(step.a[j]) + "  ";
    if (!after) continue;
    gllab::draw_dots({step.curve.P[i]}, kNew, 8.f);
    gllab::draw_label(step.curve.P[i].x, step.curve.P[i].y, 0, fmt("q%.0f", i), kNew, -14, -12);
  }
  gllab::draw_curve(c, kCurve, 5.f);
  if (after) gllab::draw_curve(step.curve, kText, 1.5f);  // inside the thick one everywhere
  draw_points(s, true);
  band({fmt("insert t = %.4g into [u%.0f, u%.0f)", t, step.k, step.k + 1) +
            fmt(" = [%.4g, %.4g)", c.U[step.k], c.U[step.k + 1]),
        "q_i = (1 - a_i) d_i-1 + a_i d_i", "a_i = (t - u_i) / (u_i+3 - u_i):", a});
  const BsplineCurve& shown = after ? step.curve : c;
  draw_basis_plot(shown, (after ? "U' =" : "U =") + gllab::knot_vector_text(shown.U), true);
}

void draw_bezier(const State& s) {
  const BsplineCurve c = with_knots(s, kSeedKnots);
  const std::vector<gllab::spline::BezierCurve> pieces = gllab::spline::bezier_decompose(c);
  gllab::draw_control_polygon(c.P, kPolygon);
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Rgb colour = kPalette[(3 * k) % std::size(kPalette)];
    gllab::draw_polyline(pieces[k].P, colour, 1.f);
    gllab::draw_dots(pieces[k].P, colour, 6.f);
    gllab::draw_curve(pieces[k], colour, 3.f);
  }
  draw_points(s, true);
  // The same refinement as one curve: its basis functions are Bernstein
  // polynomials, span by span (seed 000 §1.6 "Displaying B-spline curves").
  std::vector<double> X;  // each interior knot U[p+1..n] raised to multiplicity p
  for (int k = c.p + 1; k <= c.n(); ++k)
    if (c.U[k] != c.U[k - 1]) X.insert(X.end(), c.p - gllab::spline::knot_multiplicity(c.U, c.U[k]), c.U[k]);
  const BsplineCurve refined = gllab::spline::knot_refine(c, X);
  band({fmt("%.0f spans -> %.0f cubic Bezier pieces, %.0f points:", pieces.size(), pieces.size(), refined.P.size()),
        "every interior knot raised to multiplicity p = 3;", "below: the basis of the refined U, Bernstein per span"});
  draw_basis_plot(refined, "U' =" + gllab::knot_vector_text(refined.U), false);
}

// Above: gluNurbsCurve (thick) under the own curve. Below: how far apart they
// are at each GLU vertex, magnified until the largest distance fills the plot.
void draw_own_vs_glu(const State& s) {
  const BsplineCurve c = seed_case(s, s.integer("mult"));
  gllab::GluNurbsProperties properties;
  properties.sampling_method = GLU_DOMAIN_DISTANCE;  // numeric: the same vertices in any viewport
  properties.u_step = float(s.get("glu_step"));
  gllab::GluNurbs glu(properties);
  gllab::draw_control_polygon(c.P, kPolygon);
  if (s.flag("glu")) {
    // GLU draws with the current colour and width. Alone, its line is as
    // thin as ours, so the two pictures can be compared pixel for pixel.
    glColor3f(kGlu.r, kGlu.g, kGlu.b);
    glLineWidth(s.flag("own") ? 7.f : 2.5f);
    glu.draw_curve(c, "seed 003 case");
  }
  if (s.flag("own")) gllab::draw_curve(c, kCurve, 2.5f);
  draw_points(s, false);
  const gllab::GluCurveDifference d = gllab::compare_with_glu(glu, c, "seed 003 case");
  if (!d.ok()) return;  // reported as frame errors
  const PlotFrame f = gllab::draw_glu_difference(d, {-4, -4, 4, -.8}, kGlu, kKnot);
  gllab::draw_plot_ticks(f, c.U, kKnot);
  band({"orange: gluNurbsCurve (GL_MAP1_VERTEX_3), blue: own",
        fmt("GLU_DOMAIN_DISTANCE, u_step %g: ", s.get("glu_step")) + fmt("%.0f vertices; ", double(d.u.size())) +
            case_title(s.integer("mult"))});
}

// init / display ----------------------------------------------------------
void display(const State& s) {
  glClearColor(.1f, .1f, .12f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  const std::string& v = s.view();
  if (v == "cases_a_d") draw_cases(s);
  else if (v == "knot_vectors") draw_knot_vectors(s);
  else if (v == "knot_insertion") draw_insertion(s);
  else if (v == "bezier_pieces") draw_bezier(s);
  else if (v == "own_vs_glu") draw_own_vs_glu(s);
  else draw_basis(s);
}

// [i][j][k][l] move the selected point up, down, left, right, snapped to the
// grid so that [p] prints a --set line that renders the same picture.
bool keyboard(State& s, unsigned char key) {
  if (key == 's' || key == 'S') {  // double or halve GLU's samples, clamped to the range
    s.step("glu_step", key == 's' ? s.get("glu_step") : -s.get("glu_step") / 2);
    return true;
  }
  const Vec3 moves[] = {{0, kNudge, 0}, {0, -kNudge, 0}, {-kNudge, 0, 0}, {kNudge, 0, 0}};
  const std::size_t m = std::string("ikjl").find(char(key)), i = std::size_t(s.integer("point"));
  if (m == std::string::npos) return false;
  const Vec3 p = s.points("P")[i] + moves[m];
  s.move_point("P", i, {gllab::snap_to_grid(p.x), gllab::snap_to_grid(p.y), 0});
  return true;
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  Lab lab{"13_bspline_curves",
          "lab 13 · B-spline curves",
          {{"basis", "seed 003's cubic, its basis functions below, de Boor at u"},
           {"cases_a_d", "cases A-D: knot 4 one to four times: C2, C1, C0, a gap"},
           {"knot_vectors", "clamped uniform and non-uniform, floating, periodic"},
           {"knot_insertion", "seed 000's example: t = 0.5 into 0x4 .2 .4 .6 .8 1x4"},
           {"bezier_pieces", "Bezier decomposition: every interior knot to multiplicity 3"},
           {"own_vs_glu", "own curve over gluNurbsCurve; below, their distance"}},
          {{"point", 3, 0, double(kPoints.size() - 1), "the selected control point ([i][j][k][l] move it)"},
           {"mult", 1, 1, kDegree + 1, "multiplicity of knot 4 (seed 003's cases A-D)"},
           {"u", .5, .0625, .9375, "de Boor's u and the inserted t, as a fraction of the domain"},
           {"inserted", 1, 0, 1, "knot_insertion: show the curve after inserting t"},
           {"glu_step", 8, 1, 256, "GLU_U_STEP: GLU's samples per unit of u (GLU_DOMAIN_DISTANCE)"},
           {"own", 1, 0, 1, "own_vs_glu: draw the own curve"}, {"glu", 1, 0, 1, "own_vs_glu: draw gluNurbsCurve"}},
          {{'n', "select the next control point", "point", +1}, {'N', "select the previous control point", "point", -1},
           {'i', "move the selected point up"}, {'k', "move the selected point down"},
           {'j', "move the selected point left"}, {'l', "move the selected point right"},
           {'m', "multiplicity of knot 4 +1", "mult", +1}, {'M', "multiplicity of knot 4 -1", "mult", -1},
           {'u', "u +1/16 of the domain", "u", +.0625}, {'U', "u -1/16 of the domain", "u", -.0625},
           {'t', "knot insertion: before/after", "inserted"},
           {'s', "GLU samples per unit of u x2"}, {'S', "GLU samples per unit of u /2"},
           {'o', "own curve on/off (own_vs_glu)", "own"}, {'g', "GLU curve on/off (own_vs_glu)", "glu"}},
          nullptr, display, keyboard};
  lab.points = {{"P", kPoints, "control points d0..d7"}};
  lab.model = [](const State& s) -> Model { return curve_of(s); };
  return lab;
}
