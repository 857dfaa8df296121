// lab 13 · cubic splines                                     difficulty: ★★★☆
// Interpolating cubic splines (lecture notes ch. 1, §1.6 Spline representations, "Cubic
// splines", "Parameterizations"): natural, clamped and periodic end conditions on the same
// points; the parameterization (uniform, chordal, centripetal, Foley) with curvature combs;
// the affine-invariant Nielson metric under a shear; a wing section whose trailing edge is a
// cusp; a B-spline through a tripled control point (notes "B-Spline Polynomials").
// Notice: the same points give four different curves: the parameter is time,
//   and uniform time over uneven chords makes the curve overshoot (long comb
//   teeth). Nielson's parameters do not change under a shear, so the spline
//   of the sheared points is the sheared spline; chord lengths do change.
// Try: drag P[2] towards P[1] in parameterizations. Which curve loops first?
//   In wing_cusp, why does the periodic spline round the trailing edge off?
// Keys: [m]/[M] parameterization  [c] combs  [s]/[S] shear  [o]/[O] overlay
//   [n] labels  [mouse] drag  [p] print  [h] help  [Esc] quit
// Views: end_conditions, parameterizations, nielson_shear, wing_cusp, forced_point
// Reference: reference_images/13_cubic_splines__*.png

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/cubic_spline.h"
#include "spline/parameterization.h"

namespace {

namespace sp = gllab::spline;
using gllab::format_text;
using gllab::Rgb;
using gllab::unit_parameters_text;
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// Open data with uneven gaps: two short chords between long ones.
const std::vector<Vec3> kPoints = {{-5, -1.5, 0}, {-3.5, 1.5, 0}, {-3, 1.9, 0}, {-0.5, 1.6, 0},
                                   {1.5, -1.2, 0}, {2.1, -1.3, 0}, {4.6, 1, 0}};
// Clamped ends: handle tips; the end tangent is dX/dt = (tip - end point).
const std::vector<Vec3> kTangentTips = {{-5, -0.3, 0}, {5.8, 0.7, 0}};
// A wing section, trailing edge first, over the upper side to the nose and
// back along the lower side. The natural spline starts and ends at W[0].
const std::vector<Vec3> kWing = {
    {4, 0, 0},       {2.5, 0.55, 0}, {0.8, 0.95, 0}, {-1, 1.05, 0},  {-2.6, 0.8, 0},
    {-3.6, 0.35, 0}, {-3.9, -0.1, 0}, {-3.3, -0.45, 0}, {-1.5, -0.55, 0}, {0.5, -0.4, 0},
    {2.4, -0.15, 0}};
const Rgb kText{0.9f, 0.9f, 0.9f}, kData{1.f, 0.8f, 0.3f}, kFaint{0.5f, 0.5f, 0.55f};
const Rgb kNatural{0.3f, 0.8f, 1.f}, kClamped{1.f, 0.45f, 0.35f}, kPeriodic{0.45f, 0.9f, 0.4f};

sp::Parameterization method_of(int m) { return static_cast<sp::Parameterization>(m); }
Rgb method_colour(int m) { return gllab::series_colour(m); }  // in enum order

// A text panel with its top-left corner at lab point (x, y), one colour per line.
void panel(const gllab::State& s, double x, double y, const std::vector<std::string>& lines,
           const std::vector<Rgb>& ink = {kText}) {
  if (s.flag("labels")) gllab::draw_text_panel_at(x, y, 0, lines, ink);
}

// Window box [l, r] x [b, t] of ortho_fit(7, 7) showing lab box around
// (cx, cy) of half-size (hx, hy), one scale. Pop with glPopMatrix.
void enter_cell(double l, double b, double r, double t, double cx, double cy, double hx,
                double hy) {
  gllab::enter_plot({l, b, r, t, cx - hx, cx + hx, cy - hy, cy + hy}, true);
}

// A spline drawn from its own evaluator; with its curvature comb when asked and [c] is on.
void draw_spline(const gllab::State& s, const sp::CubicSpline& c, Rgb colour, bool comb = false) {
  gllab::draw_curve(c, colour, 3.f);
  const Rgb dim{colour.r * 0.6f, colour.g * 0.6f, colour.b * 0.6f};
  if (comb && s.flag("combs")) gllab::draw_curvature_comb(c, s.get("comb"), dim);
}

// Drawing -------------------------------------------------------------------
void draw_end_conditions(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 7, 7);
  const std::vector<Vec3>&P = s.points("P"), &T = s.points("T");
  const sp::Parameterization method = method_of(s.integer("method"));
  const std::vector<double> t = sp::parameters(P, method), closed = sp::parameters(P, method, true);
  enter_cell(-6.8, -4.0, 6.8, 6.8, 0, 0.5, 6.3, 3.6);
  draw_spline(s, sp::periodic_cubic_spline(closed, P), kPeriodic);
  draw_spline(s, sp::natural_cubic_spline(t, P), kNatural);
  draw_spline(s, sp::clamped_cubic_spline(t, P, T[0] - P.front(), T[1] - P.back()), kClamped);
  gllab::draw_arrow(P.front(), T[0], kClamped, 1.5f);
  gllab::draw_arrow(P.back(), T[1], kClamped, 1.5f);
  gllab::draw_control_points(s, "T", kClamped, 8.f);
  gllab::draw_control_points(s, "P", kData, 9.f, true);
  glPopMatrix();
  panel(s, -6.8, -4.05,
        {std::string("parameterization: ") + sp::parameterization_name(method) + " ([m])",
         "natural: S''(t_0) = S''(t_N) = 0",
         "clamped: S'(t_0), S'(t_N) = the handles (tip - point)",
         "periodic: closed, C2 also at P[0]", "t_i: " + unit_parameters_text(t)},
        {kText, kNatural, kClamped, kPeriodic, kText});
}

void draw_parameterizations(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 7, 7);
  const std::vector<Vec3>& P = s.points("P");
  for (int m = 0; m < 4; ++m) {  // uniform, chordal, centripetal, Foley: one cell each
    const double l = m % 2 ? 0.05 : -6.95, top = m < 2 ? 6.95 : -0.05, r = l + 6.9, b = top - 6.9;
    gllab::draw_polyline({{l, b, 0}, {r, b, 0}, {r, top, 0}, {l, top, 0}}, kFaint, 1.f, true);
    gllab::scissor_to({l, b, r, top, 0, 1, 0, 1});  // combs that spike stay in their cell
    const std::vector<double> t = sp::parameters(P, method_of(m));
    enter_cell(l, b, r, top - 1.2, 0, 0.2, 5.8, 3.4);
    draw_spline(s, sp::natural_cubic_spline(t, P), method_colour(m), true);
    gllab::draw_control_points(s, "P", kData, 7.f);
    glPopMatrix();
    glDisable(GL_SCISSOR_TEST);
    panel(s, l + 0.1, top - 0.1, {sp::parameterization_name(method_of(m)), unit_parameters_text(t)},
          {method_colour(m), kText});
  }
}

// Row 1 the points, row 2 a sheared copy; left the Nielson metric, right chord lengths.
void draw_nielson_shear(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 7, 7);
  const std::vector<Vec3>& P = s.points("P");
  const double k = s.get("shear");
  std::vector<Vec3> Q;  // the sheared copy x' = x + k y (an affine map)
  for (const Vec3& p : P) Q.push_back({p.x + k * p.y, p.y, p.z});
  // The same shear as a GL matrix, column-major: x += k y.
  const GLdouble shear_matrix[16] = {1, 0, 0, 0, k, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const sp::Parameterization methods[] = {sp::Parameterization::kNielson,
                                          sp::Parameterization::kChordal};
  const int only = s.integer("overlay");
  std::vector<std::string> lines;
  for (int c = 0; c < 2; ++c) {
    const auto tp = sp::parameters(P, methods[c]), tq = sp::parameters(Q, methods[c]);
    const sp::CubicSpline original = sp::natural_cubic_spline(tp, P);
    const sp::CubicSpline sheared = sp::natural_cubic_spline(tq, Q);
    const Rgb ink = method_colour(c == 0 ? 4 : 1);
    const double l = c ? 0.1 : -6.9, half = 5.4 + 1.9 * std::fabs(k);  // one scale for both rows
    enter_cell(l, 2.4, l + 6.8, 6.9, 0, 0.2, half, 2.2);  // row 1: the data
    draw_spline(s, original, ink);
    gllab::draw_control_points(s, "P", kData, 7.f);
    glPopMatrix();
    enter_cell(l, -3.6, l + 6.8, 2.2, 0.2 * k, 0.2, half, 2.2);  // row 2: the sheared copy
    // overlay 1 or 2: one of the two alone, in the same ink, at the same 400 parameters of
    // [0, 1] (the tests): where the parameterizations agree, these are the same curve points.
    const auto at_q = [&](double u) { return sp::spline_point(sheared, u); };
    const auto at_p = [&](double u) { return sp::spline_point(original, u); };
    if (only == 0) gllab::draw_curve(sheared, ink, 5.f);
    if (only == 1) gllab::draw_sampled_curve(at_q, tq.front(), tq.back(), ink);
    glPushMatrix();
    glMultMatrixd(shear_matrix);  // GL shears the first row's spline: does it fall on the new one?
    if (only == 0) gllab::draw_curve(original, kText, 1.f);
    if (only == 2) gllab::draw_sampled_curve(at_p, tp.front(), tp.back(), ink);
    glPopMatrix();
    gllab::draw_dots(Q, kData, 7.f);
    glPopMatrix();
    double moved = 0;  // how far the unit parameters move under the shear
    const auto up = sp::unit_interval_parameters(tp), uq = sp::unit_interval_parameters(tq);
    for (std::size_t i = 0; i < up.size(); ++i) moved = std::max(moved, std::fabs(up[i] - uq[i]));
    lines.push_back(format_text("%-8s t_i of P: ", sp::parameterization_name(methods[c])) +
                    unit_parameters_text(tp));
    lines.push_back("   of shear(P): " + unit_parameters_text(tq) +
                    format_text("  change %.1g", moved));
  }
  const Rgb n = method_colour(4), ch = method_colour(1);
  panel(s, -6.8, -3.95, lines, {n, n, ch, ch});
  panel(s, -6.8, -5.85,
        {format_text("row 2: x' = x + %.4g y; white: row 1's spline sheared by GL", k)});
  if (!s.flag("labels")) return;
  gllab::draw_label(-3.5, 6.9, 0, "Nielson metric", n, 0, 10);
  gllab::draw_label(3.5, 6.9, 0, "chord length", ch, 0, 10);
}

// The notes' wing section: a natural spline from the cusp round and back (above), periodic below.
void draw_wing_cusp(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 7, 7);
  const std::vector<Vec3>& W = s.points("W");
  const sp::Parameterization method = method_of(s.integer("method"));
  std::vector<Vec3> open = W;
  open.push_back(W.front());  // natural: start and end at the cusp, p_0 = p_N
  const sp::CubicSpline natural = sp::natural_cubic_spline(sp::parameters(open, method), open);
  const sp::CubicSpline periodic = sp::periodic_cubic_spline(sp::parameters(W, method, true), W);
  for (int row = 0; row < 2; ++row) {
    gllab::scissor_to({-7.0, row ? -7.0 : 0.0, 7.0, row ? 0.0 : 7.0});  // the half of the window
    enter_cell(-6.8, row ? -6.2 : 0.6, 6.8, row ? -0.6 : 6.2, 0.2, 0.25, 5.4, 1.8);
    draw_spline(s, row ? periodic : natural, row ? kPeriodic : kNatural, true);
    glDisable(GL_SCISSOR_TEST);
    gllab::draw_control_points(s, "W", kData, 7.f, row == 0);
    glPopMatrix();
  }
  panel(s, -6.8, 6.8,
        {"natural spline from the trailing edge round and back:",
         "  a cusp at W[0], as the lecture notes' wing section"}, {kNatural});
  panel(s, -6.8, -0.2,
        {"periodic spline through the same points:",
         "  C2 at W[0], so the trailing edge is rounded"}, {kPeriodic});
}

// Notes "B-Spline Polynomials", "Forcing Interpolation": P[3] 1, 2, 3 times; 3: (P+4P+P)/6 = P.
void draw_forced_point(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 5.5, 5.5);
  const std::vector<Vec3>& P = s.points("P");
  for (int m = 1; m <= 3; ++m) {  // P[3] taken m times
    std::vector<Vec3> Q = P;
    Q.insert(Q.begin() + 3, m - 1, P[3]);
    const Rgb c = std::array<Rgb, 3>{kClamped, kNatural, kPeriodic}[m - 1];
    glColor3f(c.r, c.g, c.b);
    glLineWidth(9.5f - 2.5f * m);  // 7, 4.5, 2 px: all three show
    double d = 1e300;              // distance from P[3] to the nearest curve point
    glBegin(GL_LINE_STRIP);  // segment i (Q[i..i+3]) at t = k / 64, the joints t = 0 among them
    for (int i = 0; i + 3 < int(Q.size()); ++i)
      for (int k = 0; k <= 64; ++k) {
        const Vec3 q = sp::uniform_cubic_point(Q, i, k / 64.0);
        glVertex3d(q.x, q.y, q.z);
        d = std::min(d, sp::norm(q - P[3]));
      }
    glEnd();
    panel(s, -5.3, -2.6 - 0.6 * m, {format_text("P[3] %d times: distance %.4f", m, d)}, {c});
  }
  gllab::draw_control_points(s, "P", kData, 9.f, true);
}

// init ----------------------------------------------------------------------
void init() { glClearColor(0.1f, 0.1f, 0.12f, 1.f); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "13_cubic_splines",
      "lab 13 · cubic splines",
      {{"end_conditions", "natural, clamped, periodic splines, one data set", draw_end_conditions},
       {"parameterizations", "uniform, chordal, centripetal, Foley; combs", draw_parameterizations},
       {"nielson_shear", "Nielson metric vs chord length under a shear", draw_nielson_shear},
       {"wing_cusp", "wing section: natural spline, cusp at both ends; periodic", draw_wing_cusp},
       {"forced_point", "uniform cubic B-spline, P[3] taken 1, 2, 3 times", draw_forced_point}},
      {{"method", 1, 0, 4, "0 uniform 1 chordal 2 centripetal 3 Foley 4 Nielson"},
       {"combs", 1, 0, 1, "curvature combs (parameterizations, wing_cusp)"},
       {"comb", 0.2, 0, 3, "comb tooth length per unit of curvature"},
       {"shear", 1.5, -3, 3, "nielson_shear: x' = x + shear * y"},
       {"overlay", 0, 0, 2, "nielson_shear row 2: 0 both, 1 of sheared points, 2 sheared"},
       {"labels", 1, 0, 1, "text panels"}},
      {{'m', "next parameterization", "method", +1}, {'M', "previous one", "method", -1},
       {'c', "curvature combs on/off", "combs"}, {'n', "text panels on/off", "labels"},
       {'s', "shear +0.25", "shear", +0.25}, {'S', "shear -0.25", "shear", -0.25},
       {'o', "row 2: both > new > sheared", "overlay", +1}, {'O', "overlay back", "overlay", -1}},
      init};
  lab.points = {{"P", kPoints, "data points"}, {"T", kTangentTips, "clamped ends: handle tips"},
                {"W", kWing, "wing section, trailing edge first"}};
  return lab;
}
