// common/spline/types.h — the curves and surfaces the core works on.
// Notation (common/spline/README.md): p degree, n last control index (n + 1
// points), U knots with m + 1 = n + p + 2 entries (knots = control points +
// order), P points, w weights.
#pragma once

#include <optional>
#include <vector>

#include "spline/vec.h"

namespace gllab::spline {

/// A B-spline curve of degree p, or a NURBS curve when w is not empty.
struct BsplineCurve {
  int p = 3;
  std::vector<double> U;  // non-decreasing, U.size() == P.size() + p + 1
  std::vector<Vec3> P;    // control points P[0..n]
  std::vector<double> w;  // empty: polynomial; else w.size() == P.size(), all > 0
  int dimension = 3;      // 2 or 3: how the points are written to files (2D has z = 0)

  bool rational() const { return !w.empty(); }
  int n() const { return static_cast<int>(P.size()) - 1; }
};

/// A Bézier curve of degree P.size() - 1 over the parameter interval [a, b].
struct BezierCurve {
  std::vector<Vec3> P;
  double a = 0, b = 1;
  int dimension = 3;
};

/// One piece of a trim loop in the (u, v) domain: a polyline, or a 2D
/// B-spline/NURBS curve (its points use x = u, y = v, z = 0).
struct TrimPiece {
  std::vector<Vec2> polyline;         // used when curve is empty
  std::optional<BsplineCurve> curve;  // used when present
};

/// A closed loop of pieces, each starting where the previous one ends.
/// Outer loops run counter-clockwise, holes clockwise (GLU's rule: the
/// trimmed surface keeps what lies left of the curve).
struct TrimLoop {
  std::vector<TrimPiece> pieces;
};

/// A tensor-product B-spline surface, degrees p (along u) and q (along v);
/// NURBS when w is not empty. Control points are stored row by row:
/// P[i * nv + j] with i = 0..nu-1 along u and j = 0..nv-1 along v.
struct BsplineSurface {
  int p = 3, q = 3;
  std::vector<double> U, V;  // U.size() == nu + p + 1, V.size() == nv + q + 1
  int nu = 0, nv = 0;
  std::vector<Vec3> P;
  std::vector<double> w;     // empty, or nu * nv weights in the layout of P
  std::vector<TrimLoop> trims;

  bool rational() const { return !w.empty(); }
  const Vec3& point(int i, int j) const { return P[static_cast<std::size_t>(i) * nv + j]; }
  Vec3& point(int i, int j) { return P[static_cast<std::size_t>(i) * nv + j]; }
  double weight(int i, int j) const { return w.empty() ? 1.0 : w[static_cast<std::size_t>(i) * nv + j]; }
};

}  // namespace gllab::spline
