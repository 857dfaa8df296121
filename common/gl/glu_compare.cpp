// common/gl/glu_compare.cpp — see glu_compare.h.
#include "gl/glu_compare.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "gl/scene.h"
#include "spline/bspline.h"

namespace gllab {

namespace {

// The interior knots where the curve jumps (multiplicity p + 1).
std::vector<double> breaks_of(const spline::BsplineCurve& c) {
  const spline::ParamInterval dom = spline::domain(c);
  std::vector<double> breaks;
  for (double u : c.U)
    if (u > dom.a && u < dom.b && (breaks.empty() || breaks.back() != u) && spline::knot_multiplicity(c.U, u) > c.p)
      breaks.push_back(u);
  return breaks;
}

}  // namespace

GluCurveDifference compare_with_glu(GluNurbs& glu, const spline::BsplineCurve& fed, const spline::BsplineCurve& truth,
                                    const std::string& name, RationalFeed feed) {
  GluCurveDifference d;
  const CurveCapture capture = glu.capture_curve(fed, name, feed);
  d.errors = capture.errors;
  d.polylines = capture.polylines.size();
  if (!capture.ok()) return d;
  const spline::ParamInterval dom = spline::domain(truth);
  d.a = dom.a, d.b = dom.b;
  for (const spline::Vec3& p : truth.P) d.size = std::max({d.size, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const std::vector<double> breaks = breaks_of(truth);
  const double snap = kGluKnotSnap * (dom.b - dom.a);
  for (const CapturedPolyline& line : capture.polylines)
    for (std::size_t k = 0; k < line.points.size(); ++k) {
      const double u = std::clamp(line.u[k], dom.a, dom.b);
      double dist = spline::norm(line.points[k] - spline::curve_point(truth, u));
      for (double b : breaks)
        if (std::abs(u - b) <= snap)
          for (spline::Side side : {spline::Side::Left, spline::Side::Right})
            dist = std::min(dist, spline::norm(line.points[k] - spline::curve_point(truth, b, side)));
      d.u.push_back(u);
      d.glu.push_back(line.points[k]);
      d.distance.push_back(dist);
      if (dist > d.max_distance) d.max_distance = dist, d.u_at_max = u;
    }
  return d;
}

GluCurveDifference compare_with_glu(GluNurbs& glu, const spline::BsplineCurve& curve, const std::string& name,
                                    RationalFeed feed) {
  return compare_with_glu(glu, curve, curve, name, feed);
}

PlotFrame draw_glu_difference(const GluCurveDifference& d, const PlotFrame& area, Rgb ink, Rgb axes) {
  const double spacing = d.size * FLT_EPSILON;
  PlotFrame f = area;
  f.x0 = d.a, f.x1 = d.b, f.y0 = 0, f.y1 = plot_ceiling(std::max(d.max_distance, 2 * spacing));
  char text[96];
  std::snprintf(text, sizeof text, "|GLU vertex - own C(u)|: max %.2e at u = %.4g", d.max_distance, d.u_at_max);
  draw_plot_axes(f, axes, text);
  draw_dashed_polyline({f.at(f.x0, spacing), f.at(f.x1, spacing)}, axes);
  std::snprintf(text, sizeof text, "float spacing at |x| = %g: %.1e", d.size, spacing);
  draw_label((f.left + f.right) / 2, f.at(0, spacing).y, 0, text, axes, 0, -10);
  std::snprintf(text, sizeof text, "%.0e", f.y1);
  draw_label(f.left, f.top, 0, text, axes, 28, 10);
  std::vector<spline::Vec3> plot;
  for (std::size_t k = 0; k < d.u.size(); ++k) plot.push_back(f.at(d.u[k], d.distance[k]));
  draw_polyline(plot, ink, 1.f);
  draw_dots(plot, ink, 5.f);
  return f;
}

}  // namespace gllab
