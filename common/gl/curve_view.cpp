// common/gl/curve_view.cpp — see curve_view.h.
#include "gl/curve_view.h"

#include <algorithm>
#include <cmath>

#include "gl/glu_nurbs.h"
#include "gl/scene.h"
#include "spline/bspline.h"
#include "spline/nurbs.h"

namespace gllab {

PlotFrame draw_basis_functions(const spline::BsplineCurve& c, const PlotFrame& area,
                               const std::string& title, const std::vector<Rgb>& colours, Rgb axes,
                               Rgb knots, bool labels) {
  PlotFrame f = area;
  f.x0 = c.U.front(), f.x1 = c.U.back(), f.y0 = 0, f.y1 = 1.1;
  draw_plot_axes(f, axes, title);
  const std::vector<double> peaks = spline::greville_abscissae(c.p, c.U);  // near each maximum
  for (int i = 0; i <= c.n(); ++i) {
    const Rgb colour = colours[std::size_t(i) % colours.size()];
    const auto N = [&](double u) { return spline::cox_de_boor(i, u, c.p, c.U); };
    // Only on its support [U[i], U[i+p+1]]: outside, NaN is not drawn.
    const auto on_support = [&](double u) {
      return u < c.U[i] || u > c.U[i + c.p + 1] ? NAN : N(u);
    };
    draw_plot_function(f, on_support, colour, 1.f);
    if (labels)
      draw_label(f.at(peaks[i], 0).x, f.at(0, N(peaks[i])).y, 0, format_text("%d", i), colour, 0,
                 -10);
  }
  draw_plot_ticks(f, c.U, knots);
  const spline::ParamInterval d = spline::domain(c);  // where the N_i sum to 1
  for (double u : {d.a, d.b}) draw_dashed_polyline({f.at(u, 0), f.at(u, f.y1)}, knots);
  return f;
}

std::string mark_basis_at(const PlotFrame& f, const spline::BsplineCurve& c, double u, int span,
                          const std::vector<Rgb>& colours, Rgb ink) {
  const std::vector<double> N = spline::all_basis_funs(u, c.p, c.U);
  draw_polyline({f.at(u, 0), f.at(u, f.y1)}, ink, 1.f);
  std::string values;
  for (int i = span - c.p; i <= span; ++i) {
    draw_dots({f.at(u, N[i])}, colours[std::size_t(i) % colours.size()], 7.f);
    values += format_text(" %.3f", N[i]);
  }
  return format_text("u = %.4g: N%d..%d =", u, span - c.p, span) + values;
}

void push_placed(double x, double y, double scale) {
  glPushMatrix();
  glTranslated(x, y, 0);
  glScaled(scale, scale, 1);
}

void draw_quarters(double half, const std::function<void(int k)>& draw) {
  for (int k = 0; k < 4; ++k) {
    glPushMatrix();
    glTranslated(k % 2 ? half / 2 : -half / 2, k < 2 ? half / 2 : -half / 2, 0);
    glScaled(.5, .5, 1);
    draw(k);
    glPopMatrix();
  }
}

void draw_knot_insertion(const spline::BsplineCurve& c, const spline::KnotInsertStep& step,
                         bool after, Rgb polygon, Rgb fresh, Rgb curve, Rgb thin) {
  draw_control_polygon(c.P, polygon);
  if (after) {
    draw_polyline(step.curve.P, fresh, 1.5f);  // d0 d1 d2 q3 q4 q5 d5 d6 d7 for t in [u5, u6)
    for (std::size_t j = 0; j < step.a.size(); ++j) {
      const spline::Vec3 q = step.curve.P[std::size_t(step.first) + j];
      draw_dots({q}, fresh, 8.f);
      draw_label(q.x, q.y, 0, format_text("q%d", step.first + int(j)), fresh, -14, -12);
    }
  }
  draw_curve(c, curve, 5.f);
  if (after) draw_curve(step.curve, thin, 1.5f);
}

std::vector<std::string> knot_insertion_text(const spline::BsplineCurve& c,
                                             const spline::KnotInsertStep& step, double t) {
  std::string a;
  for (std::size_t j = 0; j < step.a.size(); ++j)
    a += format_text("a%d = %.4f", step.first + int(j), step.a[j]) + fraction_text(step.a[j]) +
         "  ";
  return {format_text("insert t = %.4g into [u%d, u%d) = [%.4g, %.4g)", t, step.k, step.k + 1,
                      c.U[step.k], c.U[step.k + 1]),
          "q_i = (1 - a_i) d_i-1 + a_i d_i", "a_i = (t - u_i) / (u_i+3 - u_i):", a};
}

void draw_bezier_pieces(const std::vector<spline::BezierCurve>& pieces,
                        const std::vector<Rgb>& colours) {
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Rgb colour = colours[(3 * k) % colours.size()];
    draw_polyline(pieces[k].P, colour, 1.f);
    draw_dots(pieces[k].P, colour, 6.f);
    draw_curve(pieces[k], colour, 3.f);
  }
}

std::string fraction_text(double a) {
  for (int q = 1; q <= 12; ++q)
    if (std::abs(a * q - std::round(a * q)) < 1e-9)
      return format_text(" = %.0f/%d", std::round(a * q), q);
  return "";
}

GluCurveDifference glu_difference(GLUnurbs* nurb, const spline::BsplineCurve& fed,
                                  const spline::BsplineCurve& truth, const std::string& name) {
  GluNurbs glu(GluNurbsProperties::of(nurb));
  return compare_with_glu(glu, fed, truth, name);
}

GluCurveDifference plot_glu_difference(GLUnurbs* nurb, const spline::BsplineCurve& curve,
                                       const std::string& name, const PlotFrame& area, Rgb ink,
                                       Rgb axes) {
  const GluCurveDifference d = glu_difference(nurb, curve, curve, name);
  if (!d.ok()) return d;  // reported as frame errors
  const PlotFrame f = draw_glu_difference(d, area, ink, axes);
  draw_plot_ticks(f, curve.U, axes);
  return d;
}

std::vector<double> draw_radial_errors(const std::vector<spline::BsplineCurve>& curves,
                                       const std::vector<Rgb>& colours, spline::Vec3 centre,
                                       double radius, const PlotFrame& area, Rgb axes, Rgb ticks,
                                       Rgb text) {
  const auto radial_error = [&](const spline::BsplineCurve& c) {
    return [&c, centre, radius](double u) {
      return spline::norm(spline::curve_point(c, u) - centre) / radius - 1;
    };
  };
  std::vector<double> worst(curves.size(), 0.0);
  for (int k = 0; k <= 1000; ++k)
    for (std::size_t j = 0; j < curves.size(); ++j)
      worst[j] = std::max(worst[j], std::abs(radial_error(curves[j])(k / 1000.)));
  const double top = plot_ceiling(*std::max_element(worst.begin(), worst.end()));
  PlotFrame f = area;
  f.x0 = 0, f.x1 = 1, f.y0 = -.2 * top, f.y1 = top;
  draw_plot_axes(f, axes, "radial error |C(u) - centre| / R - 1");
  for (std::size_t j = 0; j < curves.size(); ++j)
    draw_plot_function(f, radial_error(curves[j]), colours[j % colours.size()]);
  draw_plot_ticks(f, curves.front().U, ticks);
  draw_label(f.left, f.top, 0, format_text("%g", top), text, 20, 10);
  return worst;
}

std::string weight_text(double w) { return w < 1 ? format_text("1/%g", 1 / w) : format_text("%g", w); }

std::vector<std::string> weights_caption(int i, double w, double xi) {
  return {format_text("blue: w%d = ", i) + weight_text(w) + ", the other weights 1",
          "X(u) = sum w_i N_i(u) P_i / sum w_i N_i(u)",
          format_text("dots: C(%.3g) for each weight, on a line through P%d", xi, i)};
}

std::string conic_label(double r) { return format_text("r=%g ", r) + to_string(spline::classify_conic(r)); }

std::vector<std::string> conics_caption(double r) {
  return {format_text("blue: r = %g, ", r) + to_string(spline::classify_conic(r)) +
              format_text(", w1 = r/(1-r) = %.4g", spline::conic_weight(r)),
          "r > 1/2 hyperbola, = 1/2 parabola, < 1/2 ellipse, 0 a line",
          "dots: C(1/2) = (1 - r) M + r P1, M the middle of P0 P2"};
}

namespace {

std::vector<std::string> circle_caption(double exact_error, double polynomial_error) {
  return {"blue: NURBS circle,", "9 points, degree 2,", "w = 1, 0.7071, 1, ...", "U = 0x3 1/4x2 1/2x2",
          "    3/4x2 1x3", format_text("max error %.1e", exact_error), "", "orange: no weights",
          "(same points, knots)", format_text("max error %.2f %%", 100 * polynomial_error)};
}

}  // namespace

void draw_circle_comparison(const spline::BsplineCurve& exact, const spline::BsplineCurve& polynomial,
                            spline::Vec3 centre, double radius, const PlotFrame& area, Rgb exact_ink,
                            Rgb polynomial_ink, Rgb axes, Rgb ticks, Rgb text) {
  draw_control_polygon(exact.P, axes);
  draw_curve(polynomial, polynomial_ink, 2.f);
  draw_curve(exact, exact_ink, 2.f);
  const std::vector<double> worst = draw_radial_errors({polynomial, exact}, {polynomial_ink, exact_ink},
                                                       centre, radius, area, axes, ticks, text);
  draw_text_panel(292, 40, circle_caption(worst[1], worst[0]), text);
}

std::vector<std::string> glu_table_caption(double u_step) {
  return {"GL_MAP1_VERTEX_4, fed", "(w x, w y, w z, w)",
          format_text("GLU_DOMAIN_DISTANCE, u_step %g", u_step), "", "max |GLU vertex - own C(u)|:"};
}

std::string glu_row(const std::string& name, const GluCurveDifference& d) {
  std::string row = name;
  row.resize(std::max<std::size_t>(row.size(), 7), ' ');
  return row + format_text("%3zu vertices  %.1e", d.u.size(), d.max_distance);
}

void draw_mistake_captions(double off_in_radii, int i, double w, Rgb right, Rgb wrong, Rgb text) {
  draw_label(-2.25, 4.2, 0, "right: (w x, w y, w z, w)", right);
  draw_label(2.25, 4.2, 0, "mistake: (x, y, z, w)", wrong);
  draw_text_panel(8, 256,
                  {format_text("pink: what GLU used, P_i / w_i. Circle: off by %.2f R", off_in_radii),
                   format_text("cubic: w%d = ", i) + weight_text(w) + "; at w = 1 the mistake shows nothing"},
                  text);
}

}  // namespace gllab
