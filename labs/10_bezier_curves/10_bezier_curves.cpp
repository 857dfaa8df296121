// lab 10 · Bézier curves                                     difficulty: ★★☆☆
// One cubic Bézier segment, the seeds' example (seed 000 §1.6; seeds 001, 004):
// de Casteljau's construction at t with every intermediate polygon, the
// Bernstein basis, the convex hull, subdivision, repeated degree elevation,
// the hodograph, and the same points through OpenGL's evaluator (glMap1f).
// Notice: X(t) is the last point of the scheme and the last leg is the tangent
//   (X' = 3 x that leg). At t = 0.6 the seed's scheme gives X = (6.624, 4.536)
//   exactly; the seed prints (6.63, 4.54). Subdividing at t keeps the scheme's
//   outer points; every elevated polygon lies closer to the curve.
// Try: drag b2 below the chord b0-b3. When does the hodograph pass through
//   the origin, and what does the curve do there? Then --set grid=4 in
//   own_vs_evaluator: is GL's curve still the curve?
// Keys: [t]/[T] t +-0.05  [e]/[E] elevate  [s]/[S] split depth  [g]/[G] grid
//   [c]/[C] curve source  [n] labels  [mouse] drag  [p] print  [Ctrl+S] save  [h] help
// Views: de_casteljau, bernstein, convex_hull, subdivision, degree_elevation,
//   hodograph, own_vs_evaluator          Reference: reference_images/10_bezier_curves__*.png

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gl/feedback.h"
#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/bezier.h"

namespace {

namespace sp = gllab::spline;
using gllab::Rgb;
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// The control polygon of seed 000 §1.6, "Example (de Casteljau algorithm)".
const std::vector<Vec3> kPolygon = {{0, 0, 0}, {2, 4.5, 0}, {8.5, 6.5, 0}, {11, 2, 0}};
const Rgb kText{0.9f, 0.9f, 0.9f}, kCurve{0.3f, 0.8f, 1.f}, kPoints{1.f, 0.8f, 0.3f};
const Rgb kLeft{1.f, 0.45f, 0.35f}, kRight{0.45f, 0.9f, 0.4f}, kGl{1.f, 0.3f, 0.9f}, kFaint{0.45f, 0.45f, 0.5f};
sp::BezierCurve curve_of(const gllab::State& s) { return {s.points("P"), 0, 1, 2}; }

using gllab::format_text;
std::string xy(const Vec3& p) { return format_text("(%.5g, %.5g)", p.x, p.y); }
std::string points_text(const std::vector<Vec3>& P) {
  std::string r;
  for (const Vec3& p : P) r += (r.empty() ? "" : " ") + xy(p);
  return r;
}

// The seed polygon with room around it, in window box [-6.8, 6.8] x [bottom,
// top] of ortho_fit(7, 7), one scale for both axes. Pop with glPopMatrix.
void enter_curve_cell(double bottom, double top = 6.8, double left = -6.8, double right = 6.8) {
  gllab::enter_plot({left, bottom, right, top, -0.8, 11.8, -0.8, 7.2}, true);
}

// A text panel at the left edge, its top at lab height y (ortho_fit(7, 7) units).
void panel(const gllab::State& s, double y, const std::vector<std::string>& lines) {
  if (s.flag("labels")) gllab::draw_text_panel_at(-6.8, y, 0, lines, {kText});
}

// Drawing -------------------------------------------------------------------
void draw_scheme(const gllab::State& s) {
  const sp::BezierCurve c = curve_of(s);
  const sp::DeCasteljau d = sp::de_casteljau(c, s.get("t"));
  const std::vector<Vec3> der = sp::bezier_derivatives(c, d.t, 2);
  const int n = sp::bezier_degree(c);
  enter_curve_cell(-3.2);
  gllab::draw_curve(c, kCurve, 3.f);
  gllab::draw_de_casteljau(d, kFaint, kLeft);
  // Scaled so X'/n ends at b_1^(n-1): the last leg. X''/(n(n-1)) likewise.
  gllab::draw_arrow(d.point, d.point + der[1] / n, kRight);
  if (n > 1) gllab::draw_arrow(d.point, d.point + der[2] / (n * (n - 1)), kGl);
  gllab::draw_control_points(s, "P", kPoints, 9.f, true);
  gllab::draw_label(d.point.x, d.point.y, 0, "X(t)", kText, 0, -18);
  glPopMatrix();
  std::vector<std::string> lines = {format_text("de Casteljau at t = %.4g:  b_i^j", d.t)};
  for (std::size_t j = 0; j < d.levels.size(); ++j)
    lines.push_back(format_text("j=%zu: ", j) + points_text(d.levels[j]));
  lines.push_back("X(t) = " + xy(d.point) + " = b_0^" + std::to_string(n));
  lines.push_back("X'(t) = " + xy(der[1]) + format_text(" (green, / %d)", n));
  lines.push_back("X''(t) = " + xy(der[2]) + format_text(" (pink, / %d)", n * (n - 1)));
  panel(s, -3.15, lines);
}

void draw_bernstein(const gllab::State& s) {
  const sp::BezierCurve c = curve_of(s);
  const double t = s.get("t");
  const int n = sp::bezier_degree(c);
  const std::vector<double> B = sp::bernstein_all(n, t);
  enter_curve_cell(-0.4, 5.9);
  gllab::draw_control_polygon(c.P, kFaint);
  gllab::draw_curve(c, kCurve, 3.f);
  gllab::draw_control_points(s, "P", kText, 11.f, true);
  for (int i = 0; i <= n; ++i) gllab::draw_dots({c.P[i]}, gllab::series_colour(i), 7.f);  // b_i in B_i's colour
  gllab::draw_dots({sp::bezier_point(c, t)}, kText, 10.f);
  glPopMatrix();
  const gllab::PlotFrame f{-6.3, -6.3, 6.5, -1.2, 0, 1, -0.05, 1.05};
  gllab::draw_plot_axes(f, kText, "Bernstein basis B_i^" + std::to_string(n) + "(t): >= 0, sum 1");
  gllab::draw_dashed_polyline({f.at(t, -0.05), f.at(t, 1.05)}, kText);
  std::string weights = "X(" + format_text("%.4g", t) + ") =";
  for (int i = 0; i <= n; ++i) {
    gllab::draw_plot_function(f, [&](double x) { return sp::bernstein(i, n, x); }, gllab::series_colour(i));
    gllab::draw_dots({f.at(t, B[i])}, gllab::series_colour(i), 8.f);
    weights += format_text("%s%.4g b%d", i ? " + " : " ", B[i], i);
  }
  gllab::draw_plot_ticks(f, {0, 0.25, 0.5, 0.75, 1}, kFaint);
  panel(s, 6.8, {weights});
}

void draw_hulls(const gllab::State& s) {
  const sp::BezierCurve c = curve_of(s);
  std::vector<sp::BezierCurve> pieces = {c};  // halved `split` times: 2^split pieces
  for (int d = 0; d < s.integer("split"); ++d) {
    std::vector<sp::BezierCurve> halves;
    for (const sp::BezierCurve& p : pieces) {
      const sp::BezierSplit h = sp::subdivide(p, (p.a + p.b) / 2);
      halves.insert(halves.end(), {h.left, h.right});
    }
    pieces = halves;
  }
  enter_curve_cell(-4.5);
  gllab::draw_convex_hull(c.P, kCurve, 0.25f);
  for (std::size_t i = 0; pieces.size() > 1 && i < pieces.size(); ++i)
    gllab::draw_convex_hull(pieces[i].P, i % 2 ? kLeft : kRight);
  gllab::draw_curve(c, kText, 2.f);
  gllab::draw_control_points(s, "P", kPoints, 9.f, true);
  glPopMatrix();
  panel(s, -4.8, {"the curve lies in the convex hull of its points",
                 format_text("split depth %d: %zu pieces, each inside its own hull", s.integer("split"), pieces.size()),
                 "(seed 000 §1.6 property 1 and comment 1)"});
}

void draw_subdivision(const gllab::State& s) {
  const sp::BezierCurve c = curve_of(s);
  const double t = s.get("t");
  std::vector<std::string> lines = {"t = 0 or 1: nothing to split (choose 0 < t < 1)"};
  enter_curve_cell(-3.0);
  if (t > 0 && t < 1) {  // subdivide needs a < t < b
    const sp::BezierSplit h = sp::subdivide(c, t);
    gllab::draw_de_casteljau(sp::de_casteljau(c, t), kFaint, kFaint);
    for (const auto& [piece, colour] : {std::pair{h.left, kLeft}, std::pair{h.right, kRight}}) {
      gllab::draw_polyline(piece.P, colour, 2.f);
      gllab::draw_dots(piece.P, colour, 8.f);
      gllab::draw_curve(piece, colour, 3.f);
    }
    lines = {format_text("split at t = %.4g into [0, t] and [t, 1]:", t), "left  b_0^j:     " + points_text(h.left.P),
             "right b_j^(n-j): " + points_text(h.right.P)};
  } else {
    gllab::draw_curve(c, kCurve, 3.f);
  }
  gllab::draw_control_points(s, "P", kPoints, 9.f, true);
  glPopMatrix();
  panel(s, -4.5, lines);
}

void draw_degree_elevation(const gllab::State& s) {
  const sp::BezierCurve c = curve_of(s);
  const int times = s.integer("elevate");
  enter_curve_cell(-4.5);
  gllab::draw_curve(c, kCurve, 3.f);
  sp::BezierCurve e = c;
  for (int k = 1; k <= times; ++k) {  // one step at a time: seed 000 §1.6 property 9
    e = sp::degree_elevate(e);
    gllab::draw_polyline(e.P, k < times ? kFaint : kLeft, k < times ? 1.f : 2.f);
  }
  gllab::draw_dashed_polyline(c.P, kPoints);
  if (times > 0) gllab::draw_dots(e.P, kLeft, 7.f);
  gllab::draw_control_points(s, "P", kPoints, 9.f, true);
  glPopMatrix();
  panel(s, -4.8, {format_text("degree %d elevated %d times:", sp::bezier_degree(c), times),
                 format_text("degree %d, %zu points, the same curve", sp::bezier_degree(e), e.P.size()),
                 "b'_i = i/(n+1) b_(i-1) + (1 - i/(n+1)) b_i"});
}

void draw_hodograph(const gllab::State& s) {
  const sp::BezierCurve c = curve_of(s), h = sp::bezier_derivative(c);
  const double t = s.get("t");
  const Vec3 x = sp::bezier_point(c, t), d = sp::bezier_point(h, t);
  enter_curve_cell(-3.5, 6.0, -6.9, -0.2);
  gllab::draw_curve(c, kCurve, 3.f);
  gllab::draw_arrow(x, x + d / sp::bezier_degree(c), kRight);
  gllab::draw_dots({x}, kText, 8.f);
  gllab::draw_control_points(s, "P", kPoints, 9.f, true);
  glPopMatrix();
  // The hodograph and the origin, fitted to their own box (nothing here is dragged).
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  for (const Vec3& p : h.P) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y);
  for (const Vec3& p : h.P) y1 = std::max(y1, p.y);
  const double m = 0.1 * std::max(x1 - x0, y1 - y0) + 1e-9;
  gllab::enter_plot({0.2, -3.5, 6.9, 6.0, x0 - m, x1 + m, y0 - m, y1 + m}, true);
  gllab::draw_polyline({{x0 - m, 0, 0}, {x1 + m, 0, 0}}, kFaint, 1.f);
  gllab::draw_polyline({{0, y0 - m, 0}, {0, y1 + m, 0}}, kFaint, 1.f);
  gllab::draw_control_polygon(h.P, kPoints);
  gllab::draw_curve(h, kLeft, 3.f);
  gllab::draw_arrow({0, 0, 0}, d, kRight);
  gllab::draw_label(0, 0, 0, "0", kText, -10, 10);
  glPopMatrix();
  panel(s, -4.5, {format_text("left: X(t) at t = %.4g with its tangent X'(t)/n", t),
                 "right: the hodograph X'(t), a Bezier curve of degree n-1",
                 "  with the points n (b_(i+1) - b_i), and the vector X'(t)", "X'(t) = " + xy(d)});
}

// OpenGL's one-dimensional evaluator: the driver evaluates the same Bernstein
// form in float, at u = 0, 1/grid, ..., 1 (the own samples below).
void gl_evaluator_mesh(const std::vector<Vec3>& P, int grid) {
  std::vector<GLfloat> ctrl;
  for (const Vec3& p : P) ctrl.insert(ctrl.end(), {GLfloat(p.x), GLfloat(p.y), GLfloat(p.z)});
  glMap1f(GL_MAP1_VERTEX_3, 0.f, 1.f, 3, GLint(P.size()), ctrl.data());  // stride 3, order n + 1
  glEnable(GL_MAP1_VERTEX_3);
  glMapGrid1f(grid, 0.f, 1.f);
  glEvalMesh1(GL_LINE, 0, grid);  // a line strip through glEvalCoord1f(k / grid), k = 0..grid
}

void draw_own_vs_evaluator(const gllab::State& s) {
  const sp::BezierCurve c = curve_of(s);
  const int grid = s.integer("grid"), source = s.integer("source");
  const double t = s.get("t");
  std::vector<Vec3> own;
  for (int k = 0; k <= grid; ++k) own.push_back(sp::bezier_point(c, double(k) / grid));
  enter_curve_cell(-3.8);
  // What GL receives from both, side by side: the largest distance, in pixels.
  const std::vector<Vec3> a = gllab::feedback_line_vertices([&] { gllab::draw_polyline(own, kCurve); }, grid);
  const std::vector<Vec3> b = gllab::feedback_line_vertices([&] { gl_evaluator_mesh(c.P, grid); }, grid);
  double worst = 0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
    worst = std::max(worst, std::hypot(a[k].x - b[k].x, a[k].y - b[k].y));
  // source 0: own wide underneath, GL thin on top; 1 or 2: one of them alone, in the same ink.
  if (source != 2) gllab::draw_polyline(own, kCurve, source == 0 ? 6.f : 2.f);
  if (source != 2) gllab::draw_dots({sp::bezier_point(c, t)}, kCurve, source == 0 ? 14.f : 9.f);
  if (source != 1) {
    const Rgb ink = source == 0 ? kGl : kCurve;
    glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_LINE_BIT | GL_POINT_BIT | GL_EVAL_BIT);
    glColor3f(ink.r, ink.g, ink.b);
    glLineWidth(2.f);
    gl_evaluator_mesh(c.P, grid);
    glPointSize(source == 0 ? 5.f : 9.f);
    glBegin(GL_POINTS);
    glEvalCoord1f(GLfloat(t));  // X(t) by the evaluator
    glEnd();
    glPopAttrib();
  }
  gllab::draw_control_points(s, "P", kPoints, 9.f);  // unnumbered: only the curves differ between sources
  glPopMatrix();
  const char* shown[] = {"own (wide, blue) and GL (thin, pink)", "own points only", "GL evaluator only"};
  panel(s, -3.2, {format_text("glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, %zu, P)", c.P.size()),
                 format_text("glMapGrid1f(%d, 0, 1); glEvalMesh1(GL_LINE, 0, %d)", grid, grid),
                 format_text("own bezier_point(k/%d) vs GL, read back by feedback:", grid),
                 format_text("  largest distance %.2g px over %zu vertices", worst, b.size()),
                 std::string("showing: ") + shown[source], "dot: X(t) (own) and glEvalCoord1f(t) (GL)"});
}

// init / display ----------------------------------------------------------
void display(const gllab::State& s) {
  glClearColor(0.1f, 0.1f, 0.12f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT);
  gllab::ortho_fit(s.width, s.height, 7, 7);
  const std::string& v = s.view();
  if (v == "bernstein") draw_bernstein(s);
  else if (v == "convex_hull") draw_hulls(s);
  else if (v == "subdivision") draw_subdivision(s);
  else if (v == "degree_elevation") draw_degree_elevation(s);
  else if (v == "hodograph") draw_hodograph(s);
  else if (v == "own_vs_evaluator") draw_own_vs_evaluator(s);
  else draw_scheme(s);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{"10_bezier_curves",
                 "lab 10 · Bézier curves",
                 {{"de_casteljau", "de Casteljau at t: every intermediate polygon, X, X', X''"},
                  {"bernstein", "the curve, its Bernstein basis B_i^n(t), the weights at t"},
                  {"convex_hull", "the convex hull of the points; hulls of the split pieces"},
                  {"subdivision", "split at t into two control polygons (the scheme's sides)"},
                  {"degree_elevation", "the same curve as degree n+1, n+2, ...: polygons close in"},
                  {"hodograph", "the derivative X'(t), a Bezier curve of degree n-1"},
                  {"own_vs_evaluator", "the core's points against glMap1f/glEvalMesh1 on one grid"}},
                 {{"t", 0.6, 0, 1, "the parameter of the construction, the split, the tangent"},
                  {"elevate", 3, 0, 24, "degree_elevation: how many times to raise the degree"},
                  {"split", 2, 0, 6, "convex_hull: halve the curve this many times"},
                  {"grid", 64, 1, 256, "own_vs_evaluator: segments of glMapGrid1f and of the own points"},
                  {"source", 0, 0, 2, "own_vs_evaluator: 0 both, 1 own points only, 2 GL evaluator only"},
                  {"labels", 1, 0, 1, "text panels"}},
                 {{'t', "t +0.05", "t", +0.05}, {'T', "t -0.05", "t", -0.05},
                  {'e', "elevate once more", "elevate", +1}, {'E', "elevate once less", "elevate", -1},
                  {'s', "split depth +1 (convex_hull)", "split", +1}, {'S', "split depth -1", "split", -1},
                  {'g', "evaluator grid +8 segments", "grid", +8}, {'G', "grid -8 segments", "grid", -8},
                  {'c', "curve source: both > own > GL", "source", +1}, {'C', "curve source back", "source", -1},
                  {'n', "text panels on/off", "labels"}},
                 nullptr,
                 display};
  lab.points = {{"P", kPolygon, "control points b_0..b_n (the seed's example)"}};
  lab.model = [](const gllab::State& s) -> gllab::Model { return curve_of(s); };
  return lab;
}
