// lab 10 · polynomial interpolation                          difficulty: ★★☆☆
// The polynomial through given points (lecture notes ch. 1, §1.6 Spline
// representations, "Lagrange interpolation", "Newton interpolation"): the
// Lagrange basis and the curve it gives, Newton's divided differences growing
// one node at a time, and Runge's oscillation of equidistant nodes against a
// cubic spline. The lecture notes' worked examples are views; lab 11 adds
// derivatives (Hermite interpolation).
// Notice: each L_i is 1 at its own node and 0 at every other, so p passes
//   through every point; dragging one point moves the whole curve. A new
//   Newton node adds one diagonal to the table and leaves the rest alone.
//   Three nodes can give a line (the notes' p(x) = 1 + x).
// Try: in runge press [r] up to 21 nodes. Where does the polynomial go wrong,
//   and does the spline care? Drag two Lagrange points to the same x.
// Keys: [a]/[A] add/remove a Newton node  [r]/[R] Runge nodes  [n] labels
//   [mouse] drag  [p] print  [h] help  [Esc] quit
// Views: lagrange, lagrange_example, cubic_lagrange_basis, newton_example,
//   newton_add_node, runge
// Reference: reference_images/10_polynomial_interpolation__*.png

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/cubic_spline.h"
#include "spline/interpolation.h"

namespace {

namespace sp = gllab::spline;
using gllab::format_text;
using gllab::PlotFrame;
using gllab::polynomial_text;
using gllab::Rgb;
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// Points (x_i, f_i): x is the node, y the value. Nodes must differ.
const std::vector<Vec3> kLagrange = {
    {-2, 0.4, 0}, {-1, 2, 0}, {0, 1.2, 0}, {1.2, 0.6, 0}, {2.1, 2, 0}};
// The notes' Newton example (0,1), (2,3), (4,5), then nodes to add one by one.
const std::vector<Vec3> kNewton = {
    {0, 1, 0}, {2, 3, 0}, {4, 5, 0}, {1, 3, 0}, {3, 2.5, 0}, {5, 4, 0}};
// The notes' Lagrange example and the cubic Lagrange basis on t_i = i/3.
const std::vector<double> kExampleX = {0, 1, 2}, kExampleF = {1, 0.5, 0.2};
const std::vector<double> kThirds = {0, 1.0 / 3, 2.0 / 3, 1};
double runge(double x) { return 1 / (1 + 25 * x * x); }  // Runge's function on [-1, 1]

const Rgb kText{0.9f, 0.9f, 0.9f}, kCurve{0.3f, 0.8f, 1.f}, kPoints{1.f, 0.8f, 0.3f};
const Rgb kNew{1.f, 0.4f, 0.3f}, kSpline{0.45f, 0.9f, 0.4f}, kFaint{0.5f, 0.5f, 0.55f};
// Where the plots go, in ortho_fit(7, 7) units: a curve above, a basis below.
constexpr double kLeft = -6.2, kRight = 6.6, kTop[] = {6.3, -0.9}, kBottom[] = {0.5, -6.2};

// L_i in monomial form, one line each: the polynomial through (t_j, delta_ij).
std::vector<std::string> basis_lines(const std::vector<double>& t, const std::string& x) {
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::vector<double> e(t.size(), 0.0);
    e[i] = 1;
    lines.push_back(format_text("L%zu(%s) = ", i, x.c_str()) +
                    polynomial_text(sp::vandermonde_coefficients(t, e), x));
  }
  return lines;
}

// The x or the y of each point.
std::vector<double> column(const std::vector<Vec3>& P, double Vec3::*coordinate) {
  std::vector<double> v;
  for (const Vec3& p : P) v.push_back(p.*coordinate);
  return v;
}

// A plot in slot 0 (top) or 1 (bottom) showing data [x0, x1] x [y0, y1], from
// the slot's top or `top`; its model-view maps data units, so points drawn in
// it can be dragged. Pop with glPopMatrix.
PlotFrame enter_slot(int slot, double x0, double x1, double y0, double y1,
                     const std::string& title, double top = 0) {
  const double t = top ? top : kTop[slot];
  const PlotFrame f = gllab::enter_plot({kLeft, kBottom[slot], kRight, t, x0, x1, y0, y1});
  gllab::draw_plot_axes(f, kText, title);
  return f;
}

// The Lagrange basis of the nodes in the bottom slot: L_i in colour i, with a
// dot at every (t_j, L_i(t_j)) = (t_j, delta_ij).
void plot_lagrange_basis(const std::vector<double>& t, double x0, double x1, double y0, double y1,
                         double top = 0) {
  const PlotFrame f =
      enter_slot(1, x0, x1, y0, y1, "L_i = prod_(k!=i) (t - t_k) / (t_i - t_k)", top);
  for (int i = 0; i < int(t.size()); ++i) {
    const Rgb ink = gllab::series_colour(i);
    gllab::draw_plot_function(f, [&](double x) { return sp::lagrange_basis(t, i, x); }, ink);
    for (int j = 0; j < int(t.size()); ++j)
      gllab::draw_dots({{t[j], i == j ? 1.0 : 0.0, 0}}, ink, i == j ? 8.f : 5.f);
  }
  gllab::draw_plot_ticks(f, t, kText);
  glPopMatrix();
}

// A text panel with its top-left corner at lab point (x, y), one colour per line.
void panel(const gllab::State& s, double x, double y, const std::vector<std::string>& lines,
           const std::vector<Rgb>& ink = {kText}) {
  if (s.flag("labels")) gllab::draw_text_panel_at(x, y, 0, lines, ink);
}

// Drawing -------------------------------------------------------------------
// Nodes that coincide (two points dragged to one x) make the core throw;
// the runners show its message (headless: exit 1).
void draw_lagrange(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 7, 7);
  const std::vector<Vec3>& P = s.points("P");
  const std::vector<double> t = column(P, &Vec3::x), f = column(P, &Vec3::y);
  const PlotFrame top = enter_slot(0, -2.7, 2.7, -1.2, 3.4, "p(x) = sum f_i L_i(x)");
  gllab::draw_plot_function(top, [&](double x) { return sp::lagrange_value(t, f, x); }, kCurve,
                            3.f);
  gllab::draw_control_points(s, "P", kPoints, 9.f, true);
  for (int i = 0; i < int(P.size()); ++i) gllab::draw_dots({P[i]}, gllab::series_colour(i), 6.f);
  glPopMatrix();
  plot_lagrange_basis(t, -2.7, 2.7, -1.5, 2.0);
}

void draw_lagrange_example(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 7, 7);
  const PlotFrame f = enter_slot(0, -0.3, 2.3, -0.1, 1.2,
                                 "lecture notes' example: (0, 1), (1, 0.5), (2, 0.2)");
  const auto p = [](double x) { return sp::lagrange_value(kExampleX, kExampleF, x); };
  gllab::draw_plot_function(f, p, kCurve, 3.f);
  for (int i = 0; i < 3; ++i)
    gllab::draw_dots({{kExampleX[i], kExampleF[i], 0}}, gllab::series_colour(i), 10.f);
  glPopMatrix();
  plot_lagrange_basis(kExampleX, -0.3, 2.3, -0.3, 1.2);
  std::vector<std::string> lines = basis_lines(kExampleX, "x");
  lines.push_back("P(x) = " + polynomial_text(sp::vandermonde_coefficients(kExampleX, kExampleF)));
  const auto c = gllab::series_colour;
  panel(s, -5.9, 2.9, lines, {c(0), c(1), c(2), kCurve});
}

void draw_cubic_lagrange_basis(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 7, 7);
  plot_lagrange_basis(kThirds, 0, 1, -0.4, 1.2, 2.2);
  std::vector<std::string> lines = basis_lines(kThirds, "t");
  lines.insert(lines.begin(), "cubic Lagrange basis, t_i = i/3:");
  lines.insert(lines.end(), {"L2(t) = L1(1-t), L3(t) = L0(1-t) (symmetric nodes)",
                             "(the lecture notes print L1 with the opposite sign)"});
  const auto c = gllab::series_colour;
  panel(s, -6.8, 6.8, lines, {kText, c(0), c(1), c(2), c(3), kText});
}

void draw_newton(const gllab::State& s, bool example) {
  gllab::ortho_fit(s.width, s.height, 7, 7);
  const std::vector<Vec3>& N = s.points("N");
  const int count = example ? 3 : s.integer("nodes");
  sp::NewtonInterpolant<double> before, after;  // after = before + one node, added at run time
  std::vector<double> values;
  for (int i = 0; i < count; ++i) after.add_node(N[i].x, N[i].y), values.push_back(N[i].y);
  for (int i = 0; i + 1 < count; ++i) before.add_node(N[i].x, N[i].y);
  const std::vector<double> a = after.coefficients();
  const char* title = example ? "the lecture notes' example" : "before (grey), after (blue)";
  const PlotFrame f = enter_slot(0, -0.5, 5.5, -1.5, 7, title);
  if (!example) {  // what the new node adds, a_n N_n(x): zero at every old node
    const auto term = [&](double x) {
      return a.back() * sp::newton_basis(after.nodes(), count - 1, x);
    };
    gllab::draw_plot_function(f, term, kNew, 1.f);
    gllab::draw_plot_function(f, [&](double x) { return before(x); }, kFaint, 2.f);
  }
  gllab::draw_plot_function(f, [&](double x) { return after(x); }, kCurve, 3.f);
  gllab::draw_control_points_prefix(s, "N", count, kPoints, 9.f, true);
  if (!example) gllab::draw_dots({N[count - 1]}, kNew, 6.f);
  glPopMatrix();
  std::vector<std::string> form = {
      "p(x) = " + gllab::newton_form_text(a, after.nodes()),
      "     = " + polynomial_text(sp::vandermonde_coefficients(after.nodes(), values))};
  if (example) form.push_back("3 nodes, degree 1: 'at most degree n' (lecture notes)");
  else form.insert(form.end(), {format_text("node %d added: %d new entries (red), the rest kept;",
                                            count - 1, count),
                                "the new term a_n N_n(x) (red line) is 0 at the old nodes"});
  panel(s, -6.8, -0.55, form);
  // The table f[t_j..t_(j+k)]; the diagonal of the node just added in red.
  if (s.flag("labels"))
    gllab::draw_divided_differences(after.nodes(), after.table(), -6.8, example ? -2.3 : -2.75,
                                    kText, example ? -1 : count - 1, kNew);
}

void draw_newton_example(const gllab::State& s) { draw_newton(s, true); }
void draw_newton_add_node(const gllab::State& s) { draw_newton(s, false); }

void draw_runge(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 7, 7);
  const int n = s.integer("runge_nodes");
  std::vector<Vec3> dots;  // (x_i, f(x_i)) at x_i = -1 + 2i/(n-1)
  for (double i = 0; i < n; ++i)
    dots.push_back({-1 + 2 * i / (n - 1), runge(-1 + 2 * i / (n - 1))});
  const std::vector<double> t = column(dots, &Vec3::x), f = column(dots, &Vec3::y);
  const sp::ScalarCubicSpline spline = sp::natural_cubic_spline(t, f);
  const auto p = [&](double x) { return sp::lagrange_value(t, f, x); };
  const auto S = [&](double x) { return sp::spline_value(spline, x); };
  const double poly_error = gllab::max_difference(p, runge, -1, 1, 2000);  // at 2001 points
  const double spline_error = gllab::max_difference(S, runge, -1, 1, 2000);
  const PlotFrame plot =
      enter_slot(1, -1, 1, -0.8, 1.6, "f(x) = 1 / (1 + 25x²) at equidistant nodes", kTop[0]);
  gllab::draw_plot_function(plot, runge, kText, 1.f, 400);
  gllab::draw_plot_function(plot, p, kNew, 2.f, 800);
  gllab::draw_plot_function(plot, S, kSpline, 2.f, 800);
  gllab::draw_dots(dots, kPoints, 7.f);
  glPopMatrix();
  panel(s, -3.3, -4.45, {format_text("%d nodes: polynomial of degree %d (red)", n, n - 1),
                         "natural cubic spline (green), f (white)",
                         format_text("max |p - f| = %.3g", poly_error),
                         format_text("max |S - f| = %.3g", spline_error)});
}

// init ----------------------------------------------------------------------
void init() { glClearColor(0.1f, 0.1f, 0.12f, 1.f); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "10_polynomial_interpolation",
      "lab 10 · polynomial interpolation",
      {{"lagrange", "p(x) = sum f_i L_i(x) through the points; the L_i below", draw_lagrange},
       {"lagrange_example", "the notes' example: P(x) = 0.1x² - 0.6x + 1", draw_lagrange_example},
       {"cubic_lagrange_basis", "the cubic Lagrange basis on t_i = i/3", draw_cubic_lagrange_basis},
       {"newton_example", "the notes' Newton example: p(x) = 1 + x", draw_newton_example},
       {"newton_add_node", "divided differences after adding a node", draw_newton_add_node},
       {"runge", "1/(1+25x²): equidistant polynomial vs natural spline", draw_runge}},
      {{"nodes", 4, 2, double(kNewton.size()), "newton_add_node: nodes used (the last one is new)"},
       {"runge_nodes", 11, 2, 25, "runge: number of equidistant nodes on [-1, 1]"},
       {"labels", 1, 0, 1, "text panels"}},
      {{'a', "add a Newton node", "nodes", +1}, {'A', "remove the last Newton node", "nodes", -1},
       {'r', "Runge nodes +1", "runge_nodes", +1}, {'R', "Runge nodes -1", "runge_nodes", -1},
       {'n', "text panels on/off", "labels"}},
      init};
  lab.points = {{"P", kLagrange, "lagrange: points (x_i, f_i)"},
                {"N", kNewton, "newton: (t_i, f_i), in order"}};
  return lab;
}
