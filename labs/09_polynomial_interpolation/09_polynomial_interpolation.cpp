// lab 09 · polynomial interpolation                          difficulty: ★★☆☆
// The polynomial through given points (seed 000 §1.6): the Lagrange basis and
// the curve it gives, Newton's divided differences growing one node at a time,
// Hermite interpolation of values and tangents, and Runge's oscillation of
// equidistant nodes against a cubic spline. The seeds' worked examples are views.
// Notice: each L_i is 1 at its own node and 0 at every other, so p passes
//   through every point; dragging one point moves the whole curve. A new
//   Newton node adds one diagonal to the table and leaves the rest alone.
//   Three nodes can give a line (the seed's p(x) = 1 + x).
// Try: in runge press [r] up to 21 nodes. Where does the polynomial go wrong,
//   and does the spline care? Drag two Lagrange points to the same x.
// Keys: [a]/[A] add/remove a Newton node  [r]/[R] Runge nodes  [n] labels
//   [mouse] drag  [p] print  [h] help  [Esc] quit
// Views: lagrange, newton_example, newton_add_node, hermite, hermite_basis,
//   runge, lagrange_example, cubic_lagrange_basis
// Reference: reference_images/09_polynomial_interpolation__*.png

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
#include "spline/interpolation.h"

namespace {

namespace sp = gllab::spline;
using gllab::format_text;
using gllab::PlotFrame;
using gllab::Rgb;
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// Points (x_i, f_i): x is the node, y the value. Nodes must differ.
const std::vector<Vec3> kLagrange = {{-2, 0.4, 0}, {-1, 2, 0}, {0, 1.2, 0}, {1.2, 0.6, 0}, {2.1, 2, 0}};
// The seed's Newton example (0,1), (2,3), (4,5), then nodes to add one by one.
const std::vector<Vec3> kNewton = {{0, 1, 0}, {2, 3, 0}, {4, 5, 0}, {1, 3, 0}, {3, 2.5, 0}, {5, 4, 0}};
// Hermite: points and the tips of their tangent handles; m_i = 3 (tip_i - p_i),
// so a tip is the Bezier point b_1 of the segment it starts (lab 10).
const std::vector<Vec3> kHermite = {{-2.5, -0.5, 0}, {0, 1.5, 0}, {2.5, 0, 0}};
const std::vector<Vec3> kHandles = {{-2, 1.5, 0}, {1, 2, 0}, {3.3, 1, 0}};
constexpr double kTangentPerHandle = 3;
// The seed's Lagrange example and the cubic Lagrange basis on t_i = i/3.
const std::vector<double> kExampleX = {0, 1, 2}, kExampleF = {1, 0.5, 0.2}, kThirds = {0, 1.0 / 3, 2.0 / 3, 1};
double runge(double x) { return 1 / (1 + 25 * x * x); }  // Runge's function on [-1, 1]

const Rgb kText{0.9f, 0.9f, 0.9f}, kCurve{0.3f, 0.8f, 1.f}, kPoints{1.f, 0.8f, 0.3f}, kNew{1.f, 0.4f, 0.3f};
const Rgb kSpline{0.45f, 0.9f, 0.4f}, kFaint{0.5f, 0.5f, 0.55f};
// Where the plots go, in ortho_fit(7, 7) units: a curve above, a basis below.
constexpr double kLeft = -6.2, kRight = 6.6, kTop[] = {6.3, -0.9}, kBottom[] = {0.5, -6.2};

// c_0 + c_1 x + ... as the seeds write it, highest power first: "0.1x² - 0.6x + 1".
std::string poly_text(const std::vector<double>& c, const std::string& x = "x") {
  const char* powers[] = {"", "", "²", "³"};
  std::string r;
  for (int j = int(c.size()) - 1; j >= 0; --j) {
    if (std::fabs(c[j]) < 1e-12) continue;
    r += r.empty() ? (c[j] < 0 ? "-" : "") : (c[j] < 0 ? " - " : " + ");
    if (std::fabs(c[j]) != 1 || j == 0) r += format_text("%.4g", std::fabs(c[j]));
    if (j > 0) r += x + (j < 4 ? powers[j] : "^" + std::to_string(j));
  }
  return r.empty() ? "0" : r;
}

// L_i in monomial form, one line each: the polynomial through (t_j, delta_ij).
std::vector<std::string> basis_lines(const std::vector<double>& t, const std::string& x) {
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::vector<double> e(t.size(), 0.0);
    e[i] = 1;
    lines.push_back(format_text("L%zu(%s) = ", i, x.c_str()) + poly_text(sp::vandermonde_coefficients(t, e), x));
  }
  return lines;
}

std::vector<double> column(const std::vector<Vec3>& P, double Vec3::*coordinate) {  // the x or y of each point
  std::vector<double> v;
  for (const Vec3& p : P) v.push_back(p.*coordinate);
  return v;
}

// A plot in slot 0 (top) or 1 (bottom) showing data [x0, x1] x [y0, y1], from
// the slot's top or `top`; its model-view maps data units, so points drawn in
// it can be dragged. Pop with glPopMatrix.
PlotFrame enter_slot(int slot, double x0, double x1, double y0, double y1, const std::string& title, double top = 0) {
  const PlotFrame f = gllab::enter_plot({kLeft, kBottom[slot], kRight, top ? top : kTop[slot], x0, x1, y0, y1});
  gllab::draw_plot_axes(f, kText, title);
  return f;
}

// The Lagrange basis of the nodes in the bottom slot: L_i in colour i, with a
// dot at every (t_j, L_i(t_j)) = (t_j, delta_ij).
void plot_lagrange_basis(const std::vector<double>& t, double x0, double x1, double y0, double y1, double top = 0) {
  const PlotFrame f = enter_slot(1, x0, x1, y0, y1, "L_i = prod_(k!=i) (t - t_k) / (t_i - t_k)", top);
  for (int i = 0; i < int(t.size()); ++i) {
    gllab::draw_plot_function(f, [&](double x) { return sp::lagrange_basis(t, i, x); }, gllab::series_colour(i));
    for (int j = 0; j < int(t.size()); ++j)
      gllab::draw_dots({{t[j], i == j ? 1.0 : 0.0, 0}}, gllab::series_colour(i), i == j ? 8.f : 5.f);
  }
  gllab::draw_plot_ticks(f, t, kText);
  glPopMatrix();
}

void panel(const gllab::State& s, double x, double y, const std::vector<std::string>& lines,  // top-left at (x, y)
           const std::vector<Rgb>& ink = {kText}) {
  if (s.flag("labels")) gllab::draw_text_panel_at(x, y, 0, lines, ink);
}

// Drawing -------------------------------------------------------------------
void draw_lagrange(const gllab::State& s) {
  const std::vector<Vec3>& P = s.points("P");
  const std::vector<double> t = column(P, &Vec3::x), f = column(P, &Vec3::y);
  const PlotFrame top = enter_slot(0, -2.7, 2.7, -1.2, 3.4, "p(x) = sum f_i L_i(x)");
  gllab::draw_plot_function(top, [&](double x) { return sp::lagrange_value(t, f, x); }, kCurve, 3.f);
  gllab::draw_control_points(s, "P", kPoints, 9.f, true);
  for (int i = 0; i < int(P.size()); ++i) gllab::draw_dots({P[i]}, gllab::series_colour(i), 6.f);
  glPopMatrix();
  plot_lagrange_basis(t, -2.7, 2.7, -1.5, 2.0);
}

// The divided-difference table as a text panel, row j = t_j, f[t_j], f[t_j, t_j+1], ...;
// the entries of node `fresh` (the diagonal k + j = fresh) drawn again in kNew.
void draw_table(const gllab::State& s, const sp::NewtonInterpolant<double>& p, int fresh, double at_x, double at_y) {
  const auto& T = p.table();
  const auto cell = [](const std::string& v) { return v + std::string(std::max<std::size_t>(1, 9 - v.size()), ' '); };
  std::vector<std::string> lines = {"f[t_j..t_(j+k)]; row 0 holds a_k", cell("t_j")};
  for (std::size_t k = 0; k < T.size(); ++k) lines[1] += cell("k=" + std::to_string(k));
  for (int j = 0; j < p.size(); ++j) {
    lines.push_back(cell(format_text("%.4g", p.nodes()[j])));
    for (std::size_t k = 0; k + j < T.size(); ++k) lines.back() += cell(format_text("%.4g", T[k][j]));
  }
  panel(s, at_x, at_y, lines);
  int x = 0, y = 0;  // the panel's top-left pixel: draw_text_panel has 6 px padding
  for (int k = 0; s.flag("labels") && gllab::window_pixel(at_x, at_y, 0, x, y) && fresh >= 0 && k <= fresh; ++k)
    gllab::draw_text(x + 6 + 9 * (k + 1) * gllab::kGlyphWidth, y + 6 + gllab::kGlyphHeight * (fresh - k + 2),
                     format_text("%.4g", T[k][fresh - k]), kNew);
}

void draw_newton(const gllab::State& s, bool example) {
  const std::vector<Vec3>& N = s.points("N");
  const int count = example ? 3 : s.integer("nodes");
  sp::NewtonInterpolant<double> before, after;  // after = before + one node, added at run time
  std::vector<double> values;
  for (int i = 0; i < count; ++i) after.add_node(N[i].x, N[i].y), values.push_back(N[i].y);
  for (int i = 0; i + 1 < count; ++i) before.add_node(N[i].x, N[i].y);
  const std::vector<double> a = after.coefficients();
  const PlotFrame f = enter_slot(0, -0.5, 5.5, -1.5, 7, example ? "the seed's example" : "before (grey), after (blue)");
  if (!example) {  // what the new node adds, a_n N_n(x): zero at every old node
    const auto term = [&](double x) { return a.back() * sp::newton_basis(after.nodes(), count - 1, x); };
    gllab::draw_plot_function(f, term, kNew, 1.f);
    gllab::draw_plot_function(f, [&](double x) { return before(x); }, kFaint, 2.f);
  }
  gllab::draw_plot_function(f, [&](double x) { return after(x); }, kCurve, 3.f);
  gllab::draw_control_points_prefix(s, "N", count, kPoints, 9.f, true);
  if (!example) gllab::draw_dots({N[count - 1]}, kNew, 6.f);
  glPopMatrix();
  std::string sum = "p(x) = ", product;
  for (int i = 0; i < after.size(); ++i) {
    sum += (i ? " + " : "") + format_text("%.4g", a[i]) + product;
    product += format_text("(x-%.4g)", after.nodes()[i]);
  }
  std::vector<std::string> form = {sum, "     = " + poly_text(sp::vandermonde_coefficients(after.nodes(), values))};
  if (example) form.push_back("3 nodes, degree 1: 'at most degree n' (seed)");
  else form.insert(form.end(), {format_text("node %d added: %d new entries (red), the rest kept;", count - 1, count),
                                "the new term a_n N_n(x) (red line) is 0 at the old nodes"});
  panel(s, -6.8, -0.55, form);
  draw_table(s, after, example ? -1 : count - 1, -6.8, example ? -2.3 : -2.75);
}

void draw_hermite(const gllab::State& s) {
  const std::vector<Vec3>&H = s.points("H"), &T = s.points("T");
  gllab::enter_plot({kLeft, -4.4, kRight, kTop[0], -3.1, 3.9, -1.1, 2.3}, true);
  for (std::size_t i = 0; i + 1 < H.size(); ++i) {
    const Vec3 m0 = kTangentPerHandle * (T[i] - H[i]), m1 = kTangentPerHandle * (T[i + 1] - H[i + 1]);
    const double a = double(i), b = a + 1;  // segment i over [i, i + 1]
    gllab::draw_curve([&](double t) { return sp::hermite_point(H[i], m0, H[i + 1], m1, t, a, b); }, a, b,
                      gllab::series_colour(int(i) + 2), 3.f);
  }
  for (std::size_t i = 0; i < H.size(); ++i) gllab::draw_arrow(H[i], T[i], kText, 1.5f);
  gllab::draw_control_points(s, "H", kPoints, 10.f, true);
  gllab::draw_control_points(s, "T", kNew, 8.f);
  glPopMatrix();
  panel(s, -6.8, -4.7, {"X(t) = H0 p_i + H1 p_(i+1) + H0bar m_i + H1bar m_(i+1)",
                        "on [i, i+1]; m_i = 3 (tip - p_i) is shared: C1 at p_i"});
}

void draw_hermite_basis(const gllab::State& s) {
  const char* names[] = {"H0 (value at 0)", "H0bar (slope at 0)", "H1 (value at 1)", "H1bar (slope at 1)"};
  const PlotFrame f = enter_slot(0, 0, 1, -0.3, 1.1, "cubic Hermite basis on [0, 1]");
  for (int k = 0; k < 4; ++k) {
    const auto basis = [k](double t) {
      const sp::HermiteBasis h = sp::cubic_hermite_basis(t);
      return std::array<double, 4>{h.H0, h.H0bar, h.H1, h.H1bar}[k];
    };
    gllab::draw_plot_function(f, basis, gllab::series_colour(k), 3.f);
  }
  gllab::draw_plot_ticks(f, {0, 0.5, 1}, kText);
  glPopMatrix();
  const auto& M = sp::hermite_matrix();  // column k: the coefficients of basis polynomial k
  std::vector<std::string> lines = {"(c0 c1 c2 c3) = M (f(0) f'(0) f(1) f'(1)):"};
  for (const auto& row : M) lines.push_back(format_text("  %4g %4g %4g %4g", row[0], row[1], row[2], row[3]));
  for (int k = 0; k < 4; ++k)
    lines.push_back(std::string(names[k]) + ": " + poly_text({M[0][k], M[1][k], M[2][k], M[3][k]}, "t"));
  const auto c = gllab::series_colour;
  panel(s, -6.8, -0.65, lines, {kText, kText, kText, kText, kText, c(0), c(1), c(2), c(3)});
}

void draw_runge(const gllab::State& s) {
  const int n = s.integer("runge_nodes");
  std::vector<Vec3> dots;  // (x_i, f(x_i)), x_i = -1 + 2i/(n-1)
  for (int i = 0; i < n; ++i) dots.push_back({-1 + 2.0 * i / (n - 1), runge(-1 + 2.0 * i / (n - 1)), 0});
  const std::vector<double> t = column(dots, &Vec3::x), f = column(dots, &Vec3::y);
  const sp::ScalarCubicSpline spline = sp::natural_cubic_spline(t, f);
  double poly_error = 0, spline_error = 0;  // sampled at 2001 points
  for (int k = 0; k <= 2000; ++k) {
    const double x = -1 + k / 1000.0;
    poly_error = std::max(poly_error, std::fabs(sp::lagrange_value(t, f, x) - runge(x)));
    spline_error = std::max(spline_error, std::fabs(sp::spline_value(spline, x) - runge(x)));
  }
  const PlotFrame p = enter_slot(1, -1, 1, -0.8, 1.6, "f(x) = 1 / (1 + 25x²) at equidistant nodes", kTop[0]);
  gllab::draw_plot_function(p, runge, kText, 1.f, 400);
  gllab::draw_plot_function(p, [&](double x) { return sp::lagrange_value(t, f, x); }, kNew, 2.f, 800);
  gllab::draw_plot_function(p, [&](double x) { return sp::spline_value(spline, x); }, kSpline, 2.f, 800);
  gllab::draw_dots(dots, kPoints, 7.f);
  glPopMatrix();
  panel(s, -3.3, -4.45, {format_text("%d nodes: polynomial of degree %d (red)", n, n - 1),
                    "natural cubic spline (green), f (white)", format_text("max |p - f| = %.3g", poly_error),
                    format_text("max |S - f| = %.3g", spline_error)});
}

void draw_lagrange_example(const gllab::State& s) {
  const PlotFrame f = enter_slot(0, -0.3, 2.3, -0.1, 1.2, "seed example: (0, 1), (1, 0.5), (2, 0.2)");
  gllab::draw_plot_function(f, [](double x) { return sp::lagrange_value(kExampleX, kExampleF, x); }, kCurve, 3.f);
  for (int i = 0; i < 3; ++i) gllab::draw_dots({{kExampleX[i], kExampleF[i], 0}}, gllab::series_colour(i), 10.f);
  glPopMatrix();
  plot_lagrange_basis(kExampleX, -0.3, 2.3, -0.3, 1.2);
  std::vector<std::string> lines = basis_lines(kExampleX, "x");
  lines.push_back("P(x) = " + poly_text(sp::vandermonde_coefficients(kExampleX, kExampleF)));
  panel(s, -5.9, 2.9, lines, {gllab::series_colour(0), gllab::series_colour(1), gllab::series_colour(2), kCurve});
}

void draw_cubic_lagrange_basis(const gllab::State& s) {
  plot_lagrange_basis(kThirds, 0, 1, -0.4, 1.2, 2.2);
  std::vector<std::string> lines = basis_lines(kThirds, "t");
  lines.insert(lines.begin(), "cubic Lagrange basis, t_i = i/3:");
  lines.insert(lines.end(), {"L2(t) = L1(1-t), L3(t) = L0(1-t) (symmetric nodes)",
                             "(the seed prints L1 with the opposite sign)"});
  const auto c = gllab::series_colour;
  panel(s, -6.8, 6.8, lines, {kText, c(0), c(1), c(2), c(3), kText});
}

// init / display ----------------------------------------------------------
void display(const gllab::State& s) {
  glClearColor(0.1f, 0.1f, 0.12f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT);
  gllab::ortho_fit(s.width, s.height, 7, 7);
  const std::string& v = s.view();
  // Nodes that coincide (two points dragged to one x) make the core throw;
  // the runners show its message (headless: exit 1).
  if (v == "newton_example" || v == "newton_add_node") draw_newton(s, v == "newton_example");
  else if (v == "hermite") draw_hermite(s);
  else if (v == "hermite_basis") draw_hermite_basis(s);
  else if (v == "runge") draw_runge(s);
  else if (v == "lagrange_example") draw_lagrange_example(s);
  else if (v == "cubic_lagrange_basis") draw_cubic_lagrange_basis(s);
  else draw_lagrange(s);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{"09_polynomial_interpolation",
                 "lab 09 · polynomial interpolation",
                 {{"lagrange", "p(x) = sum f_i L_i(x) through the points; the L_i below"},
                  {"newton_example", "seed Newton example (0,1), (2,3), (4,5): p(x) = 1 + x"},
                  {"newton_add_node", "divided differences after adding a node at run time"},
                  {"hermite", "piecewise cubic Hermite curve, draggable tangent handles"},
                  {"hermite_basis", "H0, H0bar, H1, H1bar and the Hermite matrix (seed example)"},
                  {"runge", "1/(1+25x²): equidistant polynomial vs natural spline"},
                  {"lagrange_example", "seed example (0,1), (1,0.5), (2,0.2): 0.1x² - 0.6x + 1"},
                  {"cubic_lagrange_basis", "the cubic Lagrange basis on t_i = i/3 (seed example)"}},
                 {{"nodes", 4, 2, double(kNewton.size()), "newton_add_node: nodes used (the last one is new)"},
                  {"runge_nodes", 11, 2, 25, "runge: number of equidistant nodes on [-1, 1]"},
                  {"labels", 1, 0, 1, "text panels"}},
                 {{'a', "add a Newton node", "nodes", +1}, {'A', "remove the last Newton node", "nodes", -1},
                  {'r', "Runge nodes +1", "runge_nodes", +1}, {'R', "Runge nodes -1", "runge_nodes", -1},
                  {'n', "text panels on/off", "labels"}},
                 nullptr,
                 display};
  lab.points = {{"P", kLagrange, "lagrange: points (x_i, f_i)"}, {"N", kNewton, "newton: (t_i, f_i), in order"},
                {"H", kHermite, "hermite: the points p_i"}, {"T", kHandles, "hermite: handle tips"}};
  return lab;
}
