// tests/gl/nurbs_suite.h — the curves and surfaces on which the own spline core
// is compared with GLU (nurbs_comparison_test.cpp, nurbs_summary.cpp), and the
// bad inputs both must reject.
//
// Every case has a name (used in test names, file names and the summary
// table) and one line saying what it exercises. The data is written here or
// read from examples/ (named in the case). Polyline trims are densified
// (dense_loop): GLU does not subdivide gluPwlCurve edges and fans slivers from
// a coarse polyline's corners (docs/glu.md), which would compare GLU's slivers
// rather than the surface; the one example file with a coarse 5-point loop is
// kept as it is, to show what that costs.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "spline/types.h"
#include "spline/vec.h"

namespace gllab::testing {

struct CurveCase {
  std::string name;
  std::string what;
  spline::BsplineCurve curve;
};

struct SurfaceCase {
  std::string name;
  std::string what;
  spline::BsplineSurface surface;
};

/// At least 12 curves: degrees 1 to 5, clamped, unclamped, periodic/closed,
/// rational (the NURBS circle, a conic), interior knots of multiplicity p and
/// p + 1, 2D and 3D.
std::vector<CurveCase> curve_suite();

/// At least 12 surfaces: degrees 1 to 5, clamped, unclamped, periodic in one
/// direction, rational (torus, vase, the example patch), multiplicity p and
/// p + 1, a flat (2D, z = 0) patch, and trimmed ones: polyline and NURBS trim
/// pieces, a hole made of several pieces, an island in a hole, a rational
/// outer trim curve.
std::vector<SurfaceCase> surface_suite();

/// examples/trimmed_nurbs_surface.json as it is, with its coarse 5-point
/// polyline outer loop: GLU fans slivers from its corners and does not follow
/// the surface along the loop's long edges (docs/glu.md). Kept out of the
/// suite; nurbs_comparison_test.cpp shows that GLU artefact on it.
SurfaceCase coarse_trim_example();

/// The closed polygon through `corners` (first corner repeated at the end),
/// each edge split into `per_edge` equal pieces.
std::vector<spline::Vec2> dense_loop(const std::vector<spline::Vec2>& corners, int per_edge);

/// A bad input: the data, and what the own core's validation says about it.
/// The GLU side (which codes it raises) is measured and asserted in
/// nurbs_comparison_test.cpp next to each case.
struct BadCurve {
  std::string name;
  spline::BsplineCurve curve;
  std::string core_message;  // a substring of the core's std::invalid_argument text
};
struct BadSurface {
  std::string name;
  spline::BsplineSurface surface;
  std::string core_message;  // from validate(surface) or validate_trim_loops
};
std::vector<BadCurve> bad_curves();
std::vector<BadSurface> bad_surfaces();

/// gtest prints a parameter by its name.
inline void PrintTo(const CurveCase& c, std::ostream* os) { *os << c.name; }
inline void PrintTo(const SurfaceCase& c, std::ostream* os) { *os << c.name; }
inline void PrintTo(const BadCurve& c, std::ostream* os) { *os << c.name; }
inline void PrintTo(const BadSurface& c, std::ostream* os) { *os << c.name; }

/// Looks a case up by name; throws std::out_of_range naming it.
const CurveCase& curve_case(const std::vector<CurveCase>& suite, const std::string& name);
const SurfaceCase& surface_case(const std::vector<SurfaceCase>& suite, const std::string& name);

}  // namespace gllab::testing
