// common/spline/fast/kernels.h — what the fast layer's kernels share: the
// instruction-set clones, and the span walk (the runs of sorted parameters that
// fall into one knot span). Internal: not part of the core's API.
//
// The fast layer (fast/*.cpp) computes what the textbook layer computes, for
// many parameters at once, and is tested to agree with it: curve points and
// derivatives to 1e-12 of the curve's size (tests/spline/bspline_test.cpp),
// surface points to 1e-11 relative and normals to 1e-9 (SurfaceGrid in
// tests/spline/surface_test.cpp). It is the only place with
// target_clones and unroll pragmas. bench/README.md has the measurements.
#pragma once

#include <cstddef>
#include <vector>

namespace gllab::spline::fast {

// GLLAB_SPLINE_NO_CLONES (a compile definition) turns the clones off: then the
// kernels are compiled for whatever -march the build uses. That is how the
// variants are compared with each other (bench/README.md).
#if defined(__GNUC__) && defined(__x86_64__) && defined(__ELF__) && !defined(GLLAB_SPLINE_NO_CLONES)
#define GLLAB_SPLINE_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define GLLAB_SPLINE_CLONES
#endif

/// Consecutive parameters u[begin..end) in the knot span U[span] <= u < U[span+1]
/// (the last non-empty span also holds u == U[n+1]).
struct SpanRun {
  int span;
  std::size_t begin, end;
};

/// The span walk: splits u[0..count) (inside the domain [U[p], U[n+1]]) into
/// runs of one knot span. For a non-decreasing list (sorted == true) each run
/// costs one span search (A2.1, The NURBS Book p. 68) and one binary search for
/// where it ends, and nothing is tested per parameter; otherwise every
/// parameter is searched for (A2.1) and runs are the stretches that share a span.
std::vector<SpanRun> span_runs(int n, int p, const std::vector<double>& U, const double* u, std::size_t count,
                               bool sorted);

}  // namespace gllab::spline::fast
