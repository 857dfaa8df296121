// bench/bench_data.h — the one data set every contestant of spline_bench gets.
//
// Built without the spline core (the core is what the benchmark measures, and
// a stub must not stop the data from existing): clamped non-uniform knots,
// weights in [0.5, 2], control points from a fixed-seed generator.
#pragma once

#include <cstddef>
#include <vector>

#include "spline/types.h"
#include "spline/vec.h"

namespace gllab::bench {

// The sizes the issue fixes. Counts in the code come from these, never from literals.
inline constexpr int kDegree = 3;                      // cubic curve, bicubic surface
inline constexpr int kCurveControlPoints = 50;
inline constexpr std::size_t kCurveParams = 100'000;   // sorted parameters
inline constexpr int kSurfaceControlPoints = 20;       // 20 x 20
inline constexpr std::size_t kGridSide = 300;          // 300 x 300 grid
inline constexpr std::size_t kSplineNodes = 1'000'000; // natural cubic spline, n = 10^6 intervals

struct BenchData {
  spline::BsplineCurve curve;        // cubic, rational, 3D, 50 control points, domain [0, 1]
  std::vector<double> curve_u;       // kCurveParams evenly spaced over [0, 1], last exactly 1
  spline::BsplineSurface surface;    // bicubic, rational, 20 x 20, domain [0, 1]^2
  std::vector<double> grid_u, grid_v;  // kGridSide each, evenly spaced, last exactly 1
  std::vector<double> spline_t;      // kSplineNodes + 1 strictly increasing nodes
  std::vector<double> spline_y;      // values at the nodes
  std::vector<spline::Vec3> spline_P;  // 3D points at the nodes (the parametric form)
};

/// The data set, built on first use (deterministic: the same on every run).
const BenchData& bench_data();

/// Homogeneous control points Pw = (w x, w y, w z, w) of the curve, and of the
/// surface in its row-by-row layout Pw[i * nv + j]: what GLU and SISL take.
std::vector<spline::Vec4> curve_homogeneous(const spline::BsplineCurve& curve);
std::vector<spline::Vec4> surface_homogeneous(const spline::BsplineSurface& surface);

}  // namespace gllab::bench
