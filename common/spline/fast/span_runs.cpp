// common/spline/fast/span_runs.cpp — the span walk the batched curve and
// surface evaluators share (see fast/kernels.h).
#include <algorithm>

#include "spline/basis.h"
#include "spline/fast/kernels.h"

namespace gllab::spline::fast {

std::vector<SpanRun> span_runs(int n, int p, const std::vector<double>& U, const double* u, std::size_t count,
                               bool sorted) {
  std::vector<SpanRun> runs;
  if (count == 0) return runs;
  if (!sorted) {  // A2.1 for every parameter; neighbours in one span share a run
    for (std::size_t k = 0; k < count; ++k) {
      const int span = find_span(n, p, u[k], U);
      if (!runs.empty() && runs.back().span == span)
        runs.back().end = k + 1;
      else
        runs.push_back({span, k, k + 1});
    }
    return runs;
  }
  const double* K = U.data();
  const int last = last_span(n, p, U);  // u == U[n+1] is evaluated here
  int span = find_span(n, p, u[0], U);
  std::size_t k = 0;
  while (true) {
    // U[span] <= u[k] < U[span+1] (or span == last): the run ends at the
    // first parameter >= U[span+1].
    const std::size_t end =
        span == last ? count : static_cast<std::size_t>(std::lower_bound(u + k, u + count, K[span + 1]) - u);
    runs.push_back({span, k, end});
    k = end;
    if (k == count) break;
    // The next non-empty span that holds u[k]: the last i <= last with U[i] <= u[k].
    span = static_cast<int>(std::upper_bound(K + span + 1, K + last + 1, u[k]) - K) - 1;
  }
  return runs;
}

}  // namespace gllab::spline::fast
