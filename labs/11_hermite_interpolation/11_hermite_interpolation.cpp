// lab 11 · Hermite interpolation                             difficulty: ★★☆☆
// Interpolating derivatives as well as values (lecture notes ch. 1, §1.6
// Spline representations, "Interpolating derivatives", "Hermite
// interpolation"): the four cubic Hermite polynomials H0, H0bar, H1, H1bar and
// the Hermite matrix of the notes' example, and a piecewise cubic Hermite
// curve through draggable points with draggable tangent handles.
// Notice: H0 and H1 carry the values, H0bar and H1bar the slopes: each is 1
//   in its own value or slope at t = 0 or 1 and 0 in the other three. Two
//   segments that share a point share its tangent m_i, so the curve is C1.
// Try: make one handle of hermite very long. Which segments change, and what
//   happens to the curvature at the middle point?
// Keys: [n] labels  [mouse] drag  [p] print  [h] help  [Esc] quit
// Views: hermite, hermite_basis
// Reference: reference_images/11_hermite_interpolation__*.png

#include <array>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/interpolation.h"

namespace {

namespace sp = gllab::spline;
using gllab::format_text;
using gllab::Rgb;
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// The points p_i and the tips of their tangent handles; m_i = 3 (tip_i - p_i),
// so a tip is the Bézier point b_1 of the segment it starts (lab 12).
const std::vector<Vec3> kHermite = {{-2.5, -0.5, 0}, {0, 1.5, 0}, {2.5, 0, 0}};
const std::vector<Vec3> kHandles = {{-2, 1.5, 0}, {1, 2, 0}, {3.3, 1, 0}};
constexpr double kTangentPerHandle = 3;

const Rgb kText{0.9f, 0.9f, 0.9f}, kPoints{1.f, 0.8f, 0.3f}, kTips{1.f, 0.4f, 0.3f};
// Where the plots go, in ortho_fit(7, 7) units: [kLeft, kRight] x [.., kTop].
constexpr double kLeft = -6.2, kRight = 6.6, kTop = 6.3;

// A text panel with its top-left corner at lab point (x, y), one colour per line.
void panel(const gllab::State& s, double x, double y, const std::vector<std::string>& lines,
           const std::vector<Rgb>& ink = {kText}) {
  if (s.flag("labels")) gllab::draw_text_panel_at(x, y, 0, lines, ink);
}

// Drawing -------------------------------------------------------------------
// Segment i over [i, i + 1]: X(t) = H0 p_i + H1 p_(i+1) + H0bar m_i + H1bar m_(i+1).
void draw_hermite(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 7, 7);
  const std::vector<Vec3>&H = s.points("H"), &T = s.points("T");
  gllab::enter_plot({kLeft, -4.4, kRight, kTop, -3.1, 3.9, -1.1, 2.3}, true);
  for (std::size_t i = 0; i + 1 < H.size(); ++i) {
    const Vec3 m0 = kTangentPerHandle * (T[i] - H[i]);
    const Vec3 m1 = kTangentPerHandle * (T[i + 1] - H[i + 1]);
    const double a = double(i), b = a + 1;
    const auto X = [&](double t) { return sp::hermite_point(H[i], m0, H[i + 1], m1, t, a, b); };
    gllab::draw_curve(X, a, b, gllab::series_colour(int(i) + 2), 3.f);
  }
  for (std::size_t i = 0; i < H.size(); ++i) gllab::draw_arrow(H[i], T[i], kText, 1.5f);
  gllab::draw_control_points(s, "H", kPoints, 10.f, true);
  gllab::draw_control_points(s, "T", kTips, 8.f);
  glPopMatrix();
  panel(s, -6.8, -4.7, {"X(t) = H0 p_i + H1 p_(i+1) + H0bar m_i + H1bar m_(i+1)",
                        "on [i, i+1]; m_i = 3 (tip - p_i) is shared: C1 at p_i"});
}

// The notes' example: the cubic through f(0), f'(0), f(1), f'(1); the
// coefficients are M times these four, and column k of M is basis polynomial k.
void draw_hermite_basis(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 7, 7);
  const char* names[] = {"H0 (value at 0)", "H0bar (slope at 0)", "H1 (value at 1)",
                         "H1bar (slope at 1)"};
  const gllab::PlotFrame f = gllab::enter_plot({kLeft, 0.5, kRight, kTop, 0, 1, -0.3, 1.1});
  gllab::draw_plot_axes(f, kText, "cubic Hermite basis on [0, 1]");
  for (int k = 0; k < 4; ++k) {
    const auto basis = [k](double t) {
      const sp::HermiteBasis h = sp::cubic_hermite_basis(t);
      return std::array<double, 4>{h.H0, h.H0bar, h.H1, h.H1bar}[k];
    };
    gllab::draw_plot_function(f, basis, gllab::series_colour(k), 3.f);
  }
  gllab::draw_plot_ticks(f, {0, 0.5, 1}, kText);
  glPopMatrix();
  const auto& M = sp::hermite_matrix();
  std::vector<std::string> lines = {"(c0 c1 c2 c3) = M (f(0) f'(0) f(1) f'(1)):"};
  for (const auto& row : M)
    lines.push_back(format_text("  %4g %4g %4g %4g", row[0], row[1], row[2], row[3]));
  for (int k = 0; k < 4; ++k)
    lines.push_back(std::string(names[k]) + ": " +
                    gllab::polynomial_text({M[0][k], M[1][k], M[2][k], M[3][k]}, "t"));
  const auto c = gllab::series_colour;
  panel(s, -6.8, -0.65, lines, {kText, kText, kText, kText, kText, c(0), c(1), c(2), c(3)});
}

// init ----------------------------------------------------------------------
void init() { glClearColor(0.1f, 0.1f, 0.12f, 1.f); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "11_hermite_interpolation",
      "lab 11 · Hermite interpolation",
      {{"hermite", "piecewise cubic Hermite curve, draggable tangent handles", draw_hermite},
       {"hermite_basis", "H0, H0bar, H1, H1bar and the Hermite matrix (the notes' example)",
        draw_hermite_basis}},
      {{"labels", 1, 0, 1, "text panels"}},
      {{'n', "text panels on/off", "labels"}},
      init};
  lab.points = {{"H", kHermite, "the points p_i"}, {"T", kHandles, "the tips of their handles"}};
  return lab;
}
