// common/deform/internal.h — what the volume and the plane deformation
// share inside common/deform: the nonzero basis functions of one direction.
#pragma once

#include <string>
#include <vector>

#include "deform/volume.h"

namespace gllab::deform::detail {

/// The p + 1 basis functions that are not zero at w and their derivatives:
/// N_{first + r}(w) = N[r], N'_{first + r}(w) = dN[r], r = 0..p. A2.1 FindSpan
/// and A2.3 DersBasisFuns (The NURBS Book, 2nd ed., pp. 68, 72) over the knots
/// U of `count` control points of degree p (w in the domain: not checked).
struct AxisBasis {
  int first = 0;
  double N[kMaxLatticeDegree + 1], dN[kMaxLatticeDegree + 1];
};
AxisBasis axis_basis(int count, int p, const std::vector<double>& U, double w);

/// v with 17 significant digits (%.17g), which read back as v: for messages.
std::string number_text(double v);

}  // namespace gllab::deform::detail
