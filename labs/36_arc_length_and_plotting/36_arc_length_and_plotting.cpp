// lab 36 · arc length and plotting a curve                         difficulty: ★★☆☆
// Walking along a curve (lecture notes ch. 1, §1.6 Spline representations,
// "Parameter transformation": L = ∫ |X'(t)| dt; notes "Higher Order Surfaces",
// "Arc Length Parameterization"; notes "B-Spline Polynomials", "Plotting Uniform
// Cubic B-Splines"): equal steps of u are not equal steps along the curve, and
// the notes' loop "for (t = 0; t <= 1; t += delta)" both misses t = 1 and, done
// by forward differences, drifts.
// Notice: the cyan ticks (equal s) crowd where |X'| is high; with delta = 0.05
//   every segment stops at t = 0.95, so every joint has a gap; float forward
//   differences lose a digit per tenfold more steps, Horner does not.
// Try: drag P[2] and watch the speed plot; press [d] until delta = 0.1: why do
//   the gaps go away, and come back at 0.04?
// Keys: [n]/[N] ticks  [d]/[D] delta of the loop  [h] help  [Esc] quit
// Views: arc_length, brute_force, forward_differences
// Reference: reference_images/36_arc_length_and_plotting__*.png

#include <cmath>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/arc_length.h"
#include "spline/bspline.h"
#include "spline/forward_differences.h"

namespace {

namespace sp = gllab::spline;
using gllab::format_text;
using gllab::PlotFrame;
using gllab::Rgb;
using gllab::State;
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// A clamped cubic B-spline with its points bunched at the left and spread at the
// right: it runs slowly, then fast.
const std::vector<Vec3> kPoints = {{-4.2, 0.1, 0}, {-3.9, 2.5, 0}, {-3.2, 0.3, 0}, {-2.0, 2.9, 0},
                                   {0.5, -0.3, 0}, {2.5, 3.0, 0},  {4.2, 0.3, 0}};
const double kDeltas[] = {0.05, 0.1, 0.125, 0.2, 0.04, 0.02};  // [d] steps through them
const Rgb kCurve{.85f, .85f, .9f}, kByU{1.f, .6f, .2f}, kByS{.3f, .85f, 1.f}, kText{1.f, 1.f, 1.f};
const Rgb kPolygon{.45f, .45f, .5f};

// Arc length --------------------------------------------------------------------
sp::BsplineCurve curve(const State& s) { return sp::clamped_curve(s.points("P"), 3, 2); }

// A tick across the curve at u: `side` +1 left of the direction of travel, -1 right.
void tick(const sp::BsplineCurve& c, double u, int side, Rgb colour) {
  const std::vector<Vec3> d = sp::curve_derivs(c, u, 1);
  const Vec3 n = 0.28 * side * sp::normalized(Vec3{-d[1].y, d[1].x, 0});
  gllab::draw_polyline({d[0], d[0] + n}, colour, 2.f);
}

// Above: the curve with ticks at equal steps of u (orange, left) and of s (cyan,
// right). Below: the speed |X'(u)| over u, with the same two sets of u as ticks.
void draw_arc_length(const State& s) {
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  const sp::BsplineCurve c = curve(s);
  const sp::ArcLength al(c);  // Gauss–Legendre panels; s(u) and u(s)
  const int n = s.integer("ticks");
  const std::vector<double> by_s = al.equal_steps(n + 1);
  gllab::draw_control_polygon(c.P, kPolygon);
  gllab::draw_curve(c, kCurve, 2.5f);
  for (int k = 0; k <= n; ++k) tick(c, double(k) / n, +1, kByU);
  for (double u : by_s) tick(c, u, -1, kByS);
  gllab::draw_control_points(s, "P", kPolygon);
  double top = 0;
  for (int k = 0; k <= 400; ++k) top = std::max(top, al.speed(k / 400.0));
  const PlotFrame f{-4, -4.2, 4, -1.1, 0, 1, 0, gllab::plot_ceiling(top)};
  gllab::draw_plot_axes(f, kPolygon, format_text("white: |X'(u)|, 0 to %g   cyan: s(u) / L", f.y1));
  gllab::draw_plot_function(f, [&](double u) { return al.speed(u); }, kCurve);
  gllab::draw_plot_function(f, [&](double u) { return f.y1 * al.s(u) / al.length(); }, kByS, 1.5f);
  for (double u : by_s) {  // equal heights of s(u) / L drop to the u that reach them
    gllab::draw_polyline({f.at(u, 0), f.at(u, f.y1 * al.s(u) / al.length())}, kByS, 1.f);
  }
  std::vector<double> by_u;
  for (int k = 0; k <= n; ++k) by_u.push_back(double(k) / n);
  gllab::draw_plot_ticks(f, by_u, kByU);
  gllab::draw_text_panel(8, 8,
                         {format_text("L = %.9f  (error estimate %.0e, %zu Gauss panels)",
                                      al.length(), al.error_estimate(), al.panels()),
                          format_text("orange: %d equal steps of u", n),
                          format_text("cyan: %d equal steps of s, %.6f", n, al.length() / n)},
                         {kText, kByU, kByS});
}

// The notes' brute-force loop, as written ---------------------------------------
// For each segment: the coefficients, then t = 0, delta, 2 delta, ... while t <= 1.
// glBegin(GL_LINE_STRIP) is the notes' MoveTo at t == 0; each glVertex a LineTo.
// Above: the loop. Below: the same curve by forward differences with the steps
// counted (an integer loop cannot miss the last one).
void draw_brute_force(const State& s) {
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  const std::vector<Vec3> P = s.points("P");
  const double delta = kDeltas[s.integer("delta")];
  int points = 0;
  double last = 0;
  glLineWidth(3.f);
  glColor3f(kCurve.r, kCurve.g, kCurve.b);
  for (std::size_t i = 3; i < P.size(); ++i) {
    const auto [a, b, c, d] = sp::uniform_cubic_coefficients(P[i - 3], P[i - 2], P[i - 1], P[i]);
    glBegin(GL_LINE_STRIP);  // MoveTo
    for (double t = 0; t <= 1; t += delta) {
      const Vec3 x = ((a * t + b) * t + c) * t + d;
      glVertex2d(x.x, x.y);  // LineTo
      points += i == 3;
      last = t;
    }
    glEnd();
  }
  const int steps = static_cast<int>(std::lround(1 / delta));
  std::vector<Vec3> counted = sp::plot_uniform_cubic_bspline(P, steps);
  for (Vec3& x : counted) x.y -= 3.6;  // the lower copy
  gllab::draw_polyline(counted, kByS, 3.f);
  gllab::draw_dots(counted, kByS, 5.f);
  for (std::size_t i = 3; i + 1 < P.size(); ++i) {  // the joints, marked below the curve
    const Vec3 joint = (P[i - 2] + 4.0 * P[i - 1] + P[i]) / 6.0;
    gllab::draw_polyline({joint - Vec3{0, 0.2, 0}, joint - Vec3{0, 0.55, 0}}, kByU, 2.f);
  }
  gllab::draw_control_polygon(P, kPolygon);
  gllab::draw_control_points(s, "P", kPolygon);
  gllab::draw_text_panel(8, 8,
                         {format_text("above: for (t = 0; t <= 1; t += %g): %d points per segment,",
                                      delta, points),
                          format_text("  the last at t = %.17g", last),
                          format_text("below: %d counted steps of forward differences", steps)},
                         {kText, kText, kByS});
}

// Forward differences against Horner ---------------------------------------------
// The largest error over one segment's n + 1 points against the exact cubic, for
// n = 10 .. 10^6, log-log: forward differences drift with n, Horner does not.
void draw_forward_differences(const State& s) {
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  const std::vector<Vec3> P = s.points("P");
  const auto abcd = sp::uniform_cubic_coefficients(P[2], P[3], P[4], P[5]);
  const PlotFrame f{-3.6, -3.8, 4, 2.3, 1, 6, -17, 0};
  gllab::draw_plot_axes(f, kPolygon, "log10 of the largest error over n steps");
  for (int e = -16; e <= -1; ++e) {  // grid lines every decade, labelled every second
    gllab::draw_polyline({f.at(1, e), f.at(6, e)}, {.22f, .22f, .26f}, 1.f);
    const double y = f.at(1, e).y - .08;
    if (e % 2 == 0) gllab::draw_label(f.left - .55, y, 0, std::to_string(e), kPolygon);
  }
  for (int e = 1; e <= 6; ++e)
    gllab::draw_label(f.at(e, 0).x - .2, f.bottom - .4, 0, format_text("n=10^%d", e), kPolygon);
  using M = sp::CubicMethod;
  const M methods[] = {M::kForwardFloat, M::kHornerFloat, M::kForwardDouble, M::kHornerDouble};
  const char* names[] = {"forward differences, float", "Horner, float",
                         "forward differences, double", "Horner, double"};
  std::vector<std::string> legend;
  std::vector<Rgb> colours;
  for (int m = 0; m < 4; ++m) {
    std::vector<Vec3> line;
    double at_million = 0;
    for (int e = 1; e <= 6; ++e) {
      const int n = static_cast<int>(std::pow(10, e));
      const double error = sp::cubic_plot_error(abcd, n, methods[m]);
      line.push_back(f.at(e, std::log10(std::max(error, 1e-17))));
      at_million = error;
    }
    gllab::draw_polyline(line, gllab::series_colour(m), 2.5f);
    gllab::draw_dots(line, gllab::series_colour(m), 8.f);
    legend.push_back(format_text("%-27s %.1e at n = 10^6", names[m], at_million));
    colours.push_back(gllab::series_colour(m));
  }
  gllab::draw_text_panel(8, 8, legend, colours);
}

// init ----------------------------------------------------------------------
void init() { glClearColor(0.12f, 0.13f, 0.16f, 1.f); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{"36_arc_length_and_plotting",
                 "lab 36 · arc length and plotting a curve",
                 {{"arc_length", "equal steps of u and of arc length s", draw_arc_length},
                  {"brute_force", "the notes' loop t += delta: gaps at joints", draw_brute_force},
                  {"forward_differences", "error of forward differences and Horner against n",
                   draw_forward_differences}},
                 {{"ticks", 12, 2, 40, "equal steps of u and of s in arc_length"},
                  {"delta", 0, 0, 5, "the loop's delta: 0.05, 0.1, 0.125, 0.2, 0.04, 0.02"}},
                 {{'n', "ticks -1", "ticks", -1},
                  {'N', "ticks +1", "ticks", +1},
                  {'d', "next delta", "delta", +1},
                  {'D', "previous delta", "delta", -1}},
                 init};
  lab.points = {{"P", kPoints, "the control points (drag them)", 2}};
  return lab;
}
