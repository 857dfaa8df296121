// common/spline/nurbs.cpp — rational curves (see nurbs.h for the sources).
#include "spline/nurbs.h"

#include <cmath>
#include <string>

#include "spline/bspline.h"
#include "spline/errors.h"

namespace gllab::spline {

// ---- homogeneous form -----------------------------------------------------------

std::vector<Vec4> to_homogeneous(const BsplineCurve& curve) {
  validate(curve);
  std::vector<Vec4> Pw(curve.P.size());
  for (std::size_t i = 0; i < curve.P.size(); ++i)
    Pw[i] = homogeneous(curve.P[i], curve.rational() ? curve.w[i] : 1.0);
  return Pw;
}

BsplineCurve from_homogeneous(int p, const std::vector<double>& U, const std::vector<Vec4>& Pw, int dimension) {
  BsplineCurve c;
  c.p = p;
  c.U = U;
  c.dimension = dimension;
  c.P.resize(Pw.size());
  c.w.resize(Pw.size());
  for (std::size_t i = 0; i < Pw.size(); ++i) {
    require_finite(Pw[i].w, "homogeneous points", at("Pw", i) + ".w");
    if (!(Pw[i].w > 0))
      fail(ErrorCode::kWeightNotPositive, "homogeneous points: " + at("Pw", i) + ".w=" + num(Pw[i].w) + " must be > 0",
           {{"i", i}, {at("Pw", i) + ".w", Pw[i].w}});
    c.P[i] = project(Pw[i]);
    c.w[i] = Pw[i].w;
  }
  validate(c);
  return c;
}

// ---- conic sections by r ---------------------------------------------------------

namespace {
void check_r(double r) {
  require_finite(r, "conic", "r");
  if (r < 0 || r >= 1)
    fail(ErrorCode::kOutOfRange, "conic: r=" + num(r) + " must satisfy 0 <= r < 1 (ch. 1 §1.6: weight r/(1-r))",
         {{"r", r}});
}
}  // namespace

ConicType classify_conic(double r) {
  check_r(r);
  if (r == 0) return ConicType::Line;
  if (r < 0.5) return ConicType::Ellipse;
  if (r == 0.5) return ConicType::Parabola;
  return ConicType::Hyperbola;
}

const char* to_string(ConicType type) {
  switch (type) {
    case ConicType::Line: return "line";
    case ConicType::Ellipse: return "ellipse";
    case ConicType::Parabola: return "parabola";
    case ConicType::Hyperbola: return "hyperbola";
  }
  return "?";
}

double conic_weight(double r) {
  check_r(r);
  return r / (1 - r);
}

double conic_r(double w1) {
  require_finite(w1, "conic", "w1");
  if (w1 < 0) fail(ErrorCode::kOutOfRange, "conic: w1=" + num(w1) + " must be >= 0", {{"w1", w1}});
  return w1 / (1 + w1);
}

BsplineCurve conic_arc(Vec3 P0, Vec3 P1, Vec3 P2, double r, int dimension) {
  check_r(r);
  BsplineCurve c;
  c.p = 2;
  c.U = {0, 0, 0, 1, 1, 1};
  c.dimension = dimension;
  if (r == 0) {
    // Weight 0 is not a valid BsplineCurve weight: the same segment P0P2 as a
    // polynomial quadratic with its middle point halfway.
    c.P = {P0, 0.5 * (P0 + P2), P2};
  } else {
    c.P = {P0, P1, P2};
    c.w = {1.0, conic_weight(r), 1.0};
  }
  validate(c);
  return c;
}

Vec3 conic_point(Vec3 P0, Vec3 P1, Vec3 P2, double r, double u) {
  const double w1 = conic_weight(r);
  require_finite(u, "conic_point", "u");
  if (u < 0 || u > 1)
    fail(ErrorCode::kParameterOutsideDomain, "conic_point: u=" + num(u) + " is outside the domain [0, 1]",
         {{"u", u}, {"a", 0}, {"b", 1}});
  // N_{i,3} on {0,0,0,1,1,1} are the quadratic Bernstein polynomials.
  const double s = 1 - u;
  const double N0 = s * s;
  const double N1 = 2 * u * s;
  const double N2 = u * u;
  return (N0 * P0 + (w1 * N1) * P1 + N2 * P2) / (N0 + w1 * N1 + N2);
}

// ---- the exact circle -------------------------------------------------------------

BsplineCurve circle(Vec3 centre, double radius) {
  require_finite(centre, "circle", "centre");
  require_finite(radius, "circle", "radius");
  if (!(radius > 0))
    fail(ErrorCode::kOutOfRange, "circle: radius=" + num(radius) + " must be > 0", {{"radius", radius}});
  // The NURBS Book §7.5 (Fig. 7.16): the square's corners carry weight √2/2
  // (cos 45°, the half-angle of each 90° arc), the edge midpoints weight 1.
  const double s = std::sqrt(2.0) / 2.0;
  const double corner[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
  BsplineCurve c;
  c.p = 2;
  c.U = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
  c.dimension = centre.z == 0 ? 2 : 3;
  for (int i = 0; i < 9; ++i) {
    c.P.push_back({centre.x + radius * corner[i][0], centre.y + radius * corner[i][1], centre.z});
    c.w.push_back(i % 2 == 0 ? 1.0 : s);
  }
  validate(c);
  return c;
}

}  // namespace gllab::spline
