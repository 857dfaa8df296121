// common/spline/curvature.cpp — curvature.h: the formulas of do Carmo §1-5.
#include "spline/curvature.h"

#include <cmath>

#include "spline/errors.h"

namespace gllab::spline {

namespace {

/// |d1|, after checking both vectors are finite and d1 is not zero.
double speed(Vec3 d1, Vec3 d2, const char* what) {
  require_finite(d1, what, "d1");
  require_finite(d2, what, "d2");
  const double s = norm(d1);
  if (!(s > 0))
    fail(ErrorCode::kDegenerate,
         std::string(what) + ": d1=" + num(d1) + " is zero (no tangent: the curve is not regular here)", {{"d1", d1}});
  return s;
}

}  // namespace

double curvature(Vec3 d1, Vec3 d2) {
  const double s = speed(d1, d2, "curvature");
  return norm(cross(d1, d2)) / (s * s * s);
}

double signed_curvature(Vec3 d1, Vec3 d2) {
  require_finite(d1, "signed_curvature", "d1");
  const Vec3 planar{d1.x, d1.y, 0};
  if (!(norm(planar) > 0))
    fail(ErrorCode::kDegenerate, "signed_curvature: d1=" + num(d1) + " has no xy component (no tangent in the plane)",
         {{"d1", d1}});
  const double s = speed(planar, d2, "signed_curvature");
  return (d1.x * d2.y - d1.y * d2.x) / (s * s * s);
}

Vec3 curvature_vector(Vec3 d1, Vec3 d2) {
  const double s = speed(d1, d2, "curvature_vector");
  return cross(cross(d1, d2), d1) / (s * s * s * s);
}

}  // namespace gllab::spline
