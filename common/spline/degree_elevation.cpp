// common/spline/degree_elevation.cpp — A5.9 DegreeElevateCurve, for any
// curve: unclamped curves are clamped first and breaks split (see
// degree_elevation.h).
#include "spline/degree_elevation.h"

#include <algorithm>
#include <string>
#include <vector>

#include "spline/bspline.h"
#include "spline/errors.h"
#include "spline/internal.h"
#include "spline/knot_insertion.h"

namespace gllab::spline {

using internal::apply_to_points;
using internal::binomial;
using internal::Ctl;
using internal::last_knot_at_or_below;

namespace {

/// A5.9 DegreeElevateCurve (The NURBS Book, p. 206) for a clamped curve whose
/// interior knots have multiplicity <= p.
template <class Pt>
Ctl<Pt> degree_elevate_impl(const Ctl<Pt>& c, int t) {
  const int p = c.p;
  const int n = static_cast<int>(c.P.size()) - 1;
  const int m = n + p + 1;
  const int ph = p + t;
  const int ph2 = ph / 2;
  const std::vector<double>& U = c.U;
  const std::vector<Pt>& Pw = c.P;
  // Bézier degree elevation coefficients.
  std::vector<std::vector<double>> bezalfs(ph + 1, std::vector<double>(p + 1, 0.0));
  bezalfs[0][0] = bezalfs[ph][p] = 1.0;
  for (int i = 1; i <= ph2; ++i) {
    const double inv = 1.0 / binomial(ph, i);
    const int mpi = std::min(p, i);
    for (int j = std::max(0, i - t); j <= mpi; ++j) bezalfs[i][j] = inv * binomial(p, j) * binomial(t, i - j);
  }
  for (int i = ph2 + 1; i <= ph - 1; ++i) {
    const int mpi = std::min(p, i);
    for (int j = std::max(0, i - t); j <= mpi; ++j) bezalfs[i][j] = bezalfs[ph - i][p - j];
  }
  // Upper bounds on the result's size: every distinct interior knot gains t.
  int distinct = 0;
  for (int i = 1; i <= m; ++i)
    if (U[i] != U[i - 1]) ++distinct;
  std::vector<double> Uh(m + 1 + (distinct + 2) * t + 1);
  std::vector<Pt> Qw(n + 1 + (distinct + 2) * t + 1);
  std::vector<Pt> bpts(p + 1), ebpts(ph + 1), Nextbpts(std::max(p - 1, 1));
  std::vector<double> alfs(std::max(p - 1, 1));

  int mh = ph;
  int kind = ph + 1;
  int r = -1;
  int a = p;
  int b = p + 1;
  int cind = 1;
  double ua = U[0];
  Qw[0] = Pw[0];
  for (int i = 0; i <= ph; ++i) Uh[i] = ua;
  for (int i = 0; i <= p; ++i) bpts[i] = Pw[i];  // the first Bézier segment
  while (b < m) {                                 // big loop through the knot vector
    int i = b;
    while (b < m && U[b] == U[b + 1]) ++b;
    const int mul = b - i + 1;
    mh = mh + mul + t;
    const double ub = U[b];
    const int oldr = r;
    r = p - mul;
    // Insert the knot U[b] r times.
    const int lbz = oldr > 0 ? (oldr + 2) / 2 : 1;
    const int rbz = r > 0 ? ph - (r + 1) / 2 : ph;
    if (r > 0) {
      const double numer = ub - ua;
      for (int k = p; k > mul; --k) alfs[k - mul - 1] = numer / (U[a + k] - ua);
      for (int j = 1; j <= r; ++j) {
        const int save = r - j;
        const int s = mul + j;
        for (int k = p; k >= s; --k) bpts[k] = alfs[k - s] * bpts[k] + (1.0 - alfs[k - s]) * bpts[k - 1];
        Nextbpts[save] = bpts[p];
      }
    }
    // Degree-elevate the Bézier segment (only points lbz..ph are used below).
    for (int e = lbz; e <= ph; ++e) {
      ebpts[e] = Pt{};
      const int mpi = std::min(p, e);
      for (int j = std::max(0, e - t); j <= mpi; ++j) ebpts[e] = ebpts[e] + bezalfs[e][j] * bpts[j];
    }
    if (oldr > 1) {  // remove the knot u = U[a] oldr - 1 times
      int first = kind - 2;
      int last = kind;
      const double den = ub - ua;
      const double bet = (ub - Uh[kind - 1]) / den;
      for (int tr = 1; tr < oldr; ++tr) {
        int ii = first;
        int j = last;
        int kj = j - kind + 1;
        while (j - ii > tr) {  // new control points for one removal step
          if (ii < cind) {
            const double alf = (ub - Uh[ii]) / (ua - Uh[ii]);
            Qw[ii] = alf * Qw[ii] + (1.0 - alf) * Qw[ii - 1];
          }
          if (j >= lbz) {
            if (j - tr <= kind - ph + oldr) {
              const double gam = (ub - Uh[j - tr]) / den;
              ebpts[kj] = gam * ebpts[kj] + (1.0 - gam) * ebpts[kj + 1];
            } else {
              ebpts[kj] = bet * ebpts[kj] + (1.0 - bet) * ebpts[kj + 1];
            }
          }
          ++ii;
          --j;
          --kj;
        }
        --first;
        ++last;
      }
    }
    if (a != p)  // load the knot ua
      for (int e = 0; e < ph - oldr; ++e) Uh[kind++] = ua;
    for (int j = lbz; j <= rbz; ++j) Qw[cind++] = ebpts[j];  // load control points
    if (b < m) {  // set up for the next pass
      for (int j = 0; j < r; ++j) bpts[j] = Nextbpts[j];
      for (int j = r; j <= p; ++j) bpts[j] = Pw[b - p + j];
      a = b;
      ++b;
      ua = ub;
    } else {
      for (int e = 0; e <= ph; ++e) Uh[kind + e] = ub;  // the end knot
    }
  }
  const int nh = mh - ph - 1;
  Ctl<Pt> q;
  q.p = ph;
  q.U.assign(Uh.begin(), Uh.begin() + (nh + ph + 2));
  q.P.assign(Qw.begin(), Qw.begin() + (nh + 1));
  return q;
}

/// Joins two clamped curves of equal degree where the first ends and the
/// second starts (the same parameter): the knot there gets multiplicity p + 1.
BsplineCurve join_clamped(const BsplineCurve& left, const BsplineCurve& right) {
  BsplineCurve out = left;
  const int p = left.p;
  out.U.resize(left.U.size() - (p + 1));
  for (int i = 0; i <= p; ++i) out.U.push_back(right.U.front());
  out.U.insert(out.U.end(), right.U.begin() + (p + 1), right.U.end());
  out.P.insert(out.P.end(), right.P.begin(), right.P.end());
  out.w.insert(out.w.end(), right.w.begin(), right.w.end());
  return out;
}

bool is_clamped(const BsplineCurve& c) {
  const int p = c.p;
  const int m = static_cast<int>(c.U.size()) - 1;
  return knot_multiplicity(c.U, c.U[p]) >= p + 1 && c.U[0] == c.U[p] && c.U[m - p] == c.U[m] &&
         knot_multiplicity(c.U, c.U[m]) >= p + 1;
}

/// The same curve on the same domain with end knots of multiplicity p + 1.
BsplineCurve clamped_copy(const BsplineCurve& curve) {
  if (is_clamped(curve)) return curve;
  const int p = curve.p;
  const ParamInterval dom = domain(curve.p, curve.U);
  BsplineCurve c = curve;
  for (const double e : {dom.a, dom.b}) {
    const int s = knot_multiplicity(c.U, e);
    if (s < p) c = knot_insert(c, e, p - s);
  }
  // Now a and b have multiplicity >= p; the points outside go.
  const int la = last_knot_at_or_below(c.U, dom.a);
  const int fb = static_cast<int>(std::lower_bound(c.U.begin(), c.U.end(), dom.b) - c.U.begin());
  // Start: with a at U[fa..la], multiplicity >= p, the first point is P[la-p].
  const int first_point = la - p;
  // End: with b at U[fb..], the last point is P[fb-1].
  const int last_point = fb - 1;
  BsplineCurve out;
  out.p = p;
  out.dimension = c.dimension;
  out.U.assign(p + 1, dom.a);
  out.U.insert(out.U.end(), c.U.begin() + (la + 1), c.U.begin() + fb);
  out.U.insert(out.U.end(), p + 1, dom.b);
  out.P.assign(c.P.begin() + first_point, c.P.begin() + (last_point + 1));
  if (c.rational()) out.w.assign(c.w.begin() + first_point, c.w.begin() + (last_point + 1));
  return out;
}

}  // namespace

BsplineCurve degree_elevate(const BsplineCurve& curve, int t) {
  validate(curve);
  if (t < 0) fail(ErrorCode::kOutOfRange, "degree_elevate: t=" + std::to_string(t) + " must be >= 0", {{"t", t}});
  if (curve.p + t > kMaxDegree)
    fail(ErrorCode::kDegreeTooHigh,
         "degree_elevate: p + t = " + std::to_string(curve.p + t) + " exceeds kMaxDegree=" + std::to_string(kMaxDegree),
         {{"p", curve.p}, {"t", t}});
  if (t == 0) return curve;
  // A5.9 needs clamped ends and interior multiplicities <= p: clamp first,
  // and elevate the pieces between breaks (multiplicity p + 1) separately.
  const BsplineCurve c = clamped_copy(curve);
  const ParamInterval dom = domain(c.p, c.U);
  for (int i = c.p + 1; i < c.n() + 1; ++i) {
    if (c.U[i] > dom.a && c.U[i] < dom.b && knot_multiplicity(c.U, c.U[i]) == c.p + 1) {
      auto [left, right] = split(c, c.U[i]);
      return join_clamped(degree_elevate(left, t), degree_elevate(right, t));
    }
  }
  BsplineCurve out = apply_to_points(c, [&](const auto& q) { return degree_elevate_impl(q, t); });
  validate(out);
  return out;
}

}  // namespace gllab::spline
