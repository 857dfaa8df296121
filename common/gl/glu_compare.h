// common/gl/glu_compare.h — how far GLU's curve is from the own core's.
//
//   gllab::GluNurbs glu(props);                      // GLU_DOMAIN_DISTANCE: numeric, no context needed
//   gllab::GluCurveDifference d = gllab::compare_with_glu(glu, curve, "lab curve");
//   d.max_distance;                                  // |GLU vertex - C(u)|, largest over GLU's vertices
//
// GLU tessellates the curve in capture mode (GluNurbs::capture_curve); every
// vertex comes back with GLU's own parameter u (the Greville texture map), and
// the core evaluates the curve at that u (spline::curve_point). Labs 15 and 16
// plot (draw_glu_difference) and print the result; their tests assert on it.
#pragma once

#include <cfloat>
#include <string>
#include <vector>

#include "gl/glu_nurbs.h"
#include "gl/spline_draw.h"
#include "gl/text.h"
#include "spline/types.h"
#include "spline/vec.h"

namespace gllab {

/// GLU's u arrives through a float texture map: at a knot where the curve
/// jumps (multiplicity p + 1, case D of lab 15) a vertex this close to it
/// (relative to the domain width) is compared with both one-sided limits
/// there, and the nearer counts: GLU ends one piece and starts the next at
/// the same u. Measured: GLU's u are off by at most ~1e-6 of the domain.
inline constexpr double kGluKnotSnap = 1e-5;

/// How close GLU and the core agree, in float spacings at the curve's size
/// (GluCurveDifference::spacings). Measured with GLU 9.0.2 on 200 random
/// clamped curves of degree 1..5, half of them rational (weights 0.25..4),
/// u_step 8..64: at most 20.1 (GLU evaluates in float, and its u comes back
/// through a float map, so a steep curve adds |C'| times u's rounding). 64
/// leaves a factor 3; a control point moved by 1 % of the size is thousands
/// of spacings off. Labs 15 and 16 and their tests use it.
inline constexpr double kGluAgreement = 64;

struct GluCurveDifference {
  std::vector<double> u;             // GLU's parameter of each vertex, clamped to the domain
  std::vector<spline::Vec3> glu;     // GLU's vertices, in the order GLU sent them
  std::vector<double> distance;      // |glu[k] - C(u[k])|
  double max_distance = 0;
  double u_at_max = 0;
  std::size_t polylines = 0;         // GLU's line strips (one per knot span, measured)
  double a = 0, b = 1;               // the domain of the curve measured against
  /// The largest |coordinate| of its control points: GLU computes in float,
  /// whose spacing there, size * FLT_EPSILON, is the scale to read distances by.
  double size = 0;
  std::vector<GluError> errors;      // what GLU (or the wrapper) reported; also frame errors
  bool ok() const { return errors.empty(); }
  /// max_distance in float spacings at the curve's size: size * FLT_EPSILON.
  double spacings() const { return max_distance / (size * FLT_EPSILON); }
  bool agrees() const { return ok() && spacings() <= kGluAgreement; }
};

/// Captures `fed` with GLU (as `feed` says) and measures each vertex against
/// `truth` at the same u: the same curve for the real comparison, another one
/// (the right curve beside the mistake, a moved point) to see a difference.
GluCurveDifference compare_with_glu(GluNurbs& glu, const spline::BsplineCurve& fed, const spline::BsplineCurve& truth,
                                    const std::string& name, RationalFeed feed = RationalFeed::kPremultiplied);
/// The usual case: GLU and the core on the same curve.
GluCurveDifference compare_with_glu(GluNurbs& glu, const spline::BsplineCurve& curve, const std::string& name,
                                    RationalFeed feed = RationalFeed::kPremultiplied);

/// Plots d.distance against d.u inside `area` (its left, bottom, right, top;
/// the data range is set here: u over [d.a, d.b], distance from 0 to
/// plot_ceiling of the maximum or of twice the float spacing, the larger):
/// a dot per GLU vertex joined in GLU's order, a dashed line at the float
/// spacing, the top value, and the maximum in the title. Returns the frame.
PlotFrame draw_glu_difference(const GluCurveDifference& d, const PlotFrame& area, Rgb ink, Rgb axes);

}  // namespace gllab
