// common/spline/fast/surface_batch.h — the fast layer for surfaces: a whole
// grid of points and unit normals at once. Computes what surface_point and
// surface_normal (surface.h) compute; tested to agree with them (points to
// 1e-11 relative, normals to 1e-9: SurfaceGrid.EqualsPerPointEvaluation in
// tests/spline/surface_test.cpp); how it is made fast: fast/surface_batch.cpp.
#pragma once

#include <vector>

#include "spline/types.h"
#include "spline/vec.h"

namespace gllab::spline {

/// Batched evaluation on the grid us x vs, for tessellation and benchmarks:
/// points[a * vs.size() + b] = S(us[a], vs[b]) and, when normals is not null,
/// (*normals)[...] = the unit normal there. The basis functions (and their
/// first derivatives, for normals) are computed once per us[a] and once per
/// vs[b]; each row a first blends the control rows along u into nv
/// homogeneous points (and their u-derivatives), then every point of the row
/// costs one short sum along v. Degenerate normals take surface_normal()'s
/// fallback. Checks the surface once; every parameter must lie in the domain
/// (the lists need not be sorted, though sorted grids are the usual case).
void surface_grid(const BsplineSurface& surface, const std::vector<double>& us, const std::vector<double>& vs,
                  std::vector<Vec3>& points, std::vector<Vec3>* normals);

}  // namespace gllab::spline
