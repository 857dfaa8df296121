// lab 12 · Bézier curves                                     difficulty: ★★☆☆
// One cubic Bézier segment, the lecture notes' example (lecture notes ch. 1, §1.6 Spline
// representations, "Bézier segments: the de Casteljau algorithm", "Properties of Bézier
// segments", "Example (de Casteljau algorithm)"; "Geometric Modeling", "Bernstein Basis"):
// de Casteljau's construction at t with every intermediate polygon, the Bernstein basis, the
// convex hull, subdivision, repeated degree elevation and the hodograph. Lab 19 hands the
// same points to OpenGL's evaluator (glMap1f).
// Notice: X(t) is the last point of the scheme and the last leg is the tangent (X' = 3 x
//   that leg). At t = 0.6 the notes' scheme gives X = (6.624, 4.536) exactly; the notes
//   print (6.63, 4.54). Subdividing at t keeps the scheme's outer points; every elevated
//   polygon lies closer to the curve.
// Try: drag b2 below the chord b0-b3. When does the hodograph pass through the origin,
//   and what does the curve do there?
// Keys: [t]/[T] t +-0.05  [e]/[E] elevate  [s]/[S] split depth  [n] labels
//   [mouse] drag  [p] print  [Ctrl+S] save  [h] help  [Esc] quit
// Views: de_casteljau, bernstein, convex_hull, subdivision, degree_elevation, hodograph
// Reference: reference_images/12_bezier_curves__*.png

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/bezier.h"

namespace {

namespace sp = gllab::spline;
using gllab::format_text;
using gllab::Rgb;
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// The control polygon of the notes' "Example (de Casteljau algorithm)".
const std::vector<Vec3> kPolygon = {{0, 0, 0}, {2, 4.5, 0}, {8.5, 6.5, 0}, {11, 2, 0}};
const Rgb kText{0.9f, 0.9f, 0.9f}, kCurve{0.3f, 0.8f, 1.f}, kPoints{1.f, 0.8f, 0.3f};
const Rgb kLeft{1.f, 0.45f, 0.35f}, kRight{0.45f, 0.9f, 0.4f}, kPink{1.f, 0.3f, 0.9f},
    kFaint{0.45f, 0.45f, 0.5f};
sp::BezierCurve curve_of(const gllab::State& s) { return {s.points("P"), 0, 1, 2}; }

// The polygon with room around it, in the window box [left, right] x [bottom,
// top] of ortho_fit(7, 7), one scale for both axes. Pop with glPopMatrix.
void enter_curve_cell(const gllab::State& s, double bottom, double top = 6.8,
                      double left = -6.8, double right = 6.8) {
  gllab::ortho_fit(s.width, s.height, 7, 7);
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
  enter_curve_cell(s, -3.2);
  gllab::draw_curve(c, kCurve, 3.f);
  gllab::draw_de_casteljau(d, kFaint, kLeft);
  // Scaled so X'/n ends at b_1^(n-1): the last leg. X''/(n(n-1)) likewise.
  gllab::draw_arrow(d.point, d.point + der[1] / n, kRight);
  if (n > 1) gllab::draw_arrow(d.point, d.point + der[2] / (n * (n - 1)), kPink);
  gllab::draw_control_points(s, "P", kPoints, 9.f, true);
  gllab::draw_label(d.point.x, d.point.y, 0, "X(t)", kText, 0, -18);
  glPopMatrix();
  std::vector<std::string> lines = {format_text("de Casteljau at t = %.4g:  b_i^j", d.t)};
  for (std::size_t j = 0; j < d.levels.size(); ++j)
    lines.push_back(format_text("j=%zu: ", j) + gllab::points_text(d.levels[j]));
  lines.insert(lines.end(),
               {"X(t) = " + gllab::xy_text(d.point) + " = b_0^" + std::to_string(n),
                "X'(t) = " + gllab::xy_text(der[1]) + format_text(" (green, / %d)", n),
                "X''(t) = " + gllab::xy_text(der[2]) + format_text(" (pink, / %d)", n * (n - 1))});
  panel(s, -3.15, lines);
}

void draw_bernstein(const gllab::State& s) {
  const sp::BezierCurve c = curve_of(s);
  const double t = s.get("t");
  const int n = sp::bezier_degree(c);
  const std::vector<double> B = sp::bernstein_all(n, t);
  enter_curve_cell(s, -0.4, 5.9);
  gllab::draw_control_polygon(c.P, kFaint);
  gllab::draw_curve(c, kCurve, 3.f);
  gllab::draw_control_points(s, "P", kText, 11.f, true);
  for (int i = 0; i <= n; ++i)  // b_i in B_i's colour
    gllab::draw_dots({c.P[i]}, gllab::series_colour(i), 7.f);
  gllab::draw_dots({sp::bezier_point(c, t)}, kText, 10.f);
  glPopMatrix();
  const gllab::PlotFrame f{-6.3, -6.3, 6.5, -1.2, 0, 1, -0.05, 1.05};
  gllab::draw_plot_axes(f, kText, format_text("Bernstein basis B_i^%d(t): >= 0, sum 1", n));
  gllab::draw_dashed_polyline({f.at(t, -0.05), f.at(t, 1.05)}, kText);
  std::string weights = format_text("X(%.4g) =", t);
  for (int i = 0; i <= n; ++i) {
    const Rgb colour = gllab::series_colour(i);
    gllab::draw_plot_function(f, [&](double x) { return sp::bernstein(i, n, x); }, colour);
    gllab::draw_dots({f.at(t, B[i])}, colour, 8.f);
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
  enter_curve_cell(s, -4.5);
  gllab::draw_convex_hull(c.P, kCurve, 0.25f);
  for (std::size_t i = 0; pieces.size() > 1 && i < pieces.size(); ++i)
    gllab::draw_convex_hull(pieces[i].P, i % 2 ? kLeft : kRight);
  gllab::draw_curve(c, kText, 2.f);
  gllab::draw_control_points(s, "P", kPoints, 9.f, true);
  glPopMatrix();
  panel(s, -4.8, {"the curve lies in the convex hull of its points",
                  format_text("split depth %d: %zu pieces, each inside its own hull",
                              s.integer("split"), pieces.size()),
                  "(lecture notes ch. 1, §1.6: property 1, comment 1)"});
}

void draw_subdivision(const gllab::State& s) {
  const sp::BezierCurve c = curve_of(s);
  const double t = s.get("t");
  std::vector<std::string> lines = {"t = 0 or 1: nothing to split (choose 0 < t < 1)"};
  enter_curve_cell(s, -3.0);
  if (t > 0 && t < 1) {  // subdivide needs a < t < b
    const sp::BezierSplit h = sp::subdivide(c, t);
    gllab::draw_de_casteljau(sp::de_casteljau(c, t), kFaint, kFaint);
    for (const auto& [piece, colour] : {std::pair{h.left, kLeft}, std::pair{h.right, kRight}}) {
      gllab::draw_polyline(piece.P, colour, 2.f);
      gllab::draw_dots(piece.P, colour, 8.f);
      gllab::draw_curve(piece, colour, 3.f);
    }
    lines = {format_text("split at t = %.4g into [0, t] and [t, 1]:", t),
             "left  b_0^j:     " + gllab::points_text(h.left.P),
             "right b_j^(n-j): " + gllab::points_text(h.right.P)};
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
  enter_curve_cell(s, -4.5);
  gllab::draw_curve(c, kCurve, 3.f);
  sp::BezierCurve e = c;
  for (int k = 1; k <= times; ++k) {  // one step at a time: §1.6 property 9
    e = sp::degree_elevate(e);
    gllab::draw_polyline(e.P, k < times ? kFaint : kLeft, k < times ? 1.f : 2.f);
  }
  gllab::draw_dashed_polyline(c.P, kPoints);
  if (times > 0) gllab::draw_dots(e.P, kLeft, 7.f);
  gllab::draw_control_points(s, "P", kPoints, 9.f, true);
  glPopMatrix();
  panel(s, -4.8, {format_text("degree %d elevated %d times:", sp::bezier_degree(c), times),
                  format_text("degree %d, %zu points, the same curve", sp::bezier_degree(e),
                              e.P.size()),
                  "b'_i = i/(n+1) b_(i-1) + (1 - i/(n+1)) b_i"});
}

void draw_hodograph(const gllab::State& s) {
  const sp::BezierCurve c = curve_of(s), h = sp::bezier_derivative(c);
  const double t = s.get("t");
  const Vec3 x = sp::bezier_point(c, t), d = sp::bezier_point(h, t);
  enter_curve_cell(s, -3.5, 6.0, -6.9, -0.2);
  gllab::draw_curve(c, kCurve, 3.f);
  gllab::draw_arrow(x, x + d / sp::bezier_degree(c), kRight);
  gllab::draw_dots({x}, kText, 8.f);
  gllab::draw_control_points(s, "P", kPoints, 9.f, true);
  glPopMatrix();
  // The hodograph and the origin, fitted to their own box (nothing here is dragged).
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  for (const Vec3& p : h.P)
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
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
                  "  with the points n (b_(i+1) - b_i), and the vector X'(t)",
                  "X'(t) = " + gllab::xy_text(d)});
}

// init ----------------------------------------------------------------------
void init() { glClearColor(0.1f, 0.1f, 0.12f, 1.f); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "12_bezier_curves",
      "lab 12 · Bézier curves",
      {{"de_casteljau", "de Casteljau at t: every intermediate polygon, X, X', X''", draw_scheme},
       {"bernstein", "the curve, its Bernstein basis B_i^n(t), the weights at t", draw_bernstein},
       {"convex_hull", "the convex hull of the points; hulls of the split pieces", draw_hulls},
       {"subdivision", "split at t: two control polygons, the scheme's sides", draw_subdivision},
       {"degree_elevation", "the same curve as degree n+1, n+2, ...", draw_degree_elevation},
       {"hodograph", "the derivative X'(t), a Bezier curve of degree n-1", draw_hodograph}},
      {{"t", 0.6, 0, 1, "the parameter of the construction, the split, the tangent"},
       {"elevate", 3, 0, 24, "degree_elevation: how many times to raise the degree"},
       {"split", 2, 0, 6, "convex_hull: halve the curve this many times"},
       {"labels", 1, 0, 1, "text panels"}},
      {{'t', "t +0.05", "t", +0.05}, {'T', "t -0.05", "t", -0.05},
       {'e', "elevate once more", "elevate", +1}, {'E', "elevate once less", "elevate", -1},
       {'s', "split depth +1 (convex_hull)", "split", +1}, {'S', "split depth -1", "split", -1},
       {'n', "text panels on/off", "labels"}},
      init};
  lab.points = {{"P", kPolygon, "control points b_0..b_n (the lecture notes' example)"}};
  lab.model = [](const gllab::State& s) -> gllab::Model { return curve_of(s); };
  return lab;
}
