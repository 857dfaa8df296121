// common/spline/patch_trims.cpp — the trims of the patch tessellator
// (patch_tessellator.h): flattened, refined, cut at the cell lines and given
// to the leaves; and the inside test.
//
// Curve pieces are flattened on the surface (flatten_curve on S(C(t)), chordal
// error). Trim-edge refinement follows no paper: each trim edge is split until
// its image on the surface is within the tolerance (flatten_curve, parametric
// error), because GLU leaves gluPwlCurve edges alone and fans slivers across
// the trimmed region (docs/glu.md, "Coarse gluPwlCurve trims make slivers").
// Runs of a loop along the domain edge are moved outside the domain. Inside or
// outside is trim.h's winding rule (Sunday's crossing rule), read per cell row.
#include "spline/patch_tessellator.h"

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "spline/bspline.h"
#include "spline/errors.h"

namespace gllab::spline::detail {

namespace {

/// x moved onto a line (sorted) within eps of it: the first at or above x, else the one below.
double snap(double x, const std::vector<double>& lines, double eps) {
  const auto it = std::lower_bound(lines.begin(), lines.end(), x);
  if (it != lines.end() && *it - x <= eps) return *it;
  if (it != lines.begin() && x - *(it - 1) <= eps) return *(it - 1);
  return x;
}

/// The index of the line at exactly x, or -1.
int line_index(const std::vector<double>& lines, double x) {
  const auto it = std::lower_bound(lines.begin(), lines.end(), x);
  return it != lines.end() && *it == x ? static_cast<int>(it - lines.begin()) : -1;
}

/// The finest row (column) whose half-open interval [Y_k, Y_k+1) holds y.
int band(const std::vector<double>& lines, double y) {
  const auto k = static_cast<int>(std::upper_bound(lines.begin(), lines.end(), y) - lines.begin()) - 1;
  return std::clamp(k, 0, static_cast<int>(lines.size()) - 2);
}

}  // namespace

void PatchTessellator::prepare_trims(const std::vector<TrimLoop>& trims) {
  trimmed_ = true;
  // Piece-level checks with trim.h's messages (closure, domain, curves).
  validate_trim_loops(trims, dom_, kTrimFlattenTolerance * std::max(dom_.u1 - dom_.u0, dom_.v1 - dom_.v0));

  // Curve pieces: flattened on the surface (3D chordal error), or for fixed
  // steps in (u, v) to a small fraction of a cell.
  const double cell =
      std::min((dom_.u1 - dom_.u0) / static_cast<double>(nu_), (dom_.v1 - dom_.v0) / static_cast<double>(nv_));
  const TrimCurveFlattener flatten_piece = [&](const BsplineCurve& c) {
    const CurveEvaluator trim(c);  // checked once, not at every sample
    const ParamInterval d = trim.domain();
    const auto uv_at = [&](double t) {
      const Vec3 p = trim.point(t);
      return clamp_uv({p.x, p.y});
    };
    FlattenOptions fo;
    fo.error = ChordError::Chordal;
    std::vector<CurveSample> samples;
    if (adaptive_) {
      fo.tolerance = opt_.tolerance;
      const auto on_surface = [&](double t) { const Vec2 q = uv_at(t); return evaluate(q.x, q.y).point; };
      samples = flatten_curve(on_surface, d.a, d.b, fo);
    } else {
      fo.tolerance = 1e-3 * cell;
      const auto in_uv = [&](double t) { const Vec2 q = uv_at(t); return Vec3{q.x, q.y, 0}; };
      samples = flatten_curve(in_uv, d.a, d.b, fo);
    }
    std::vector<Vec2> points;
    for (const CurveSample& s : samples) points.push_back(uv_at(s.t));
    return points;
  };
  const double eps_u = 1e-10 * (dom_.u1 - dom_.u0), eps_v = 1e-10 * (dom_.v1 - dom_.v0);
  const std::vector<double> edges_u{dom_.u0, dom_.u1}, edges_v{dom_.v0, dom_.v1};
  std::vector<TrimPolygon> polygons;
  for (std::size_t l = 0; l < trims.size(); ++l) {
    TrimPolygon poly = flatten_trim_loop(trims[l], flatten_piece, l);
    check_trim_points(poly.size());
    for (Vec2& p : poly) p = clamp_uv({snap(p.x, edges_u, eps_u), snap(p.y, edges_v, eps_v)});
    polygons.push_back(std::move(poly));
  }
  validate_trim_polygons(polygons, dom_);
  for (TrimPolygon& poly : polygons) {
    poly = move_runs_off_domain_edge(poly);
    std::vector<char> refined(poly.size(), 0);
    if (adaptive_) poly = refine_trim_edges(poly, refined);
    for (const Vec2& p : poly)
      if (!outside_domain(p)) trim_points_.push_back(p);
    trim_refined_.push_back(std::move(refined));
  }
  trim_polygons_ = std::move(polygons);
}

void PatchTessellator::cut_trims() {
  const double eps_u = 1e-10 * (dom_.u1 - dom_.u0), eps_v = 1e-10 * (dom_.v1 - dom_.v0);
  std::vector<TrimPolygon> polygons = trim_polygons_;
  // Cut every trim edge at the finest cell lines, so each piece lies in one
  // leaf (or on a line between two). Points within a hair of a line are moved
  // onto it first: a trim vertex at u = 0.25 on a line at 0.25000000000000006
  // would otherwise leave a sliver.
  leaf_trims_.assign(leaves_.size(), {});
  row_segments_.assign(line_v_.size(), {});  // the last: above the domain
  for (std::size_t l = 0; l < polygons.size(); ++l) {
    TrimPolygon& poly = polygons[l];
    for (Vec2& p : poly) p = {snap(p.x, line_u_, eps_u), snap(p.y, line_v_, eps_v)};
    // What made each point: the loop (kept), refinement (may go), a cell line (kept).
    constexpr char kGiven = 0, kRefined = 1, kCrossing = 2;
    std::vector<Vec2> cut;
    std::vector<char> kind;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Vec2 a = poly[k], b = poly[(k + 1) % poly.size()];
      std::vector<std::pair<double, Vec2>> hits;
      if (a.x != b.x) {
        const auto lo = std::upper_bound(line_u_.begin(), line_u_.end(), std::min(a.x, b.x));
        for (auto it = lo; it != line_u_.end() && *it < std::max(a.x, b.x); ++it) {
          const double t = (*it - a.x) / (b.x - a.x);
          hits.push_back({t, {*it, snap(a.y + t * (b.y - a.y), line_v_, eps_v)}});
        }
      }
      if (a.y != b.y) {
        const auto lo = std::upper_bound(line_v_.begin(), line_v_.end(), std::min(a.y, b.y));
        for (auto it = lo; it != line_v_.end() && *it < std::max(a.y, b.y); ++it) {
          const double t = (*it - a.y) / (b.y - a.y);
          hits.push_back({t, {snap(a.x + t * (b.x - a.x), line_u_, eps_u), *it}});
        }
      }
      std::sort(hits.begin(), hits.end(), [](const auto& h1, const auto& h2) { return h1.first < h2.first; });
      cut.push_back(a);
      // A point on a cell line is a crossing, whatever made it.
      const bool on_line = line_index(line_u_, a.x) >= 0 || line_index(line_v_, a.y) >= 0;
      kind.push_back(on_line ? kCrossing : trim_refined_[l][k] ? kRefined : kGiven);
      for (const auto& h : hits) cut.push_back(h.second), kind.push_back(kCrossing);
    }
    // Drop repeats (two crossings at one corner; a point on a line). A
    // refinement point a hair from a crossing would leave a tiny trim
    // segment, and a needle on it: it lies on a straight (u, v) edge, so
    // dropping it changes nothing in (u, v); drop it when the longer chord
    // still meets the tolerance.
    std::vector<Vec2> clean;
    std::vector<char> clean_kind;
    const std::size_t n = cut.size();
    for (std::size_t k = 0; k < n; ++k) {
      if (!clean.empty() && cut[k] == clean.back()) {  // one point: a crossing if either is
        char& merged = clean_kind.back();
        merged = merged == kCrossing || kind[k] == kCrossing ? kCrossing : std::min(merged, kind[k]);
        continue;
      }
      if (adaptive_ && kind[k] == kRefined && !clean.empty()) {
        const Vec2 prev = clean.back(), next = cut[(k + 1) % n];
        const bool near_prev = clean_kind.back() == kCrossing && norm(cut[k] - prev) < 0.25 * norm(next - cut[k]);
        const bool near_next = kind[(k + 1) % n] == kCrossing && norm(next - cut[k]) < 0.25 * norm(cut[k] - prev);
        if ((near_prev || near_next) && chord_within(prev, next)) continue;
      }
      clean.push_back(cut[k]);
      clean_kind.push_back(kind[k]);
    }
    while (clean.size() > 1 && clean.back() == clean.front()) clean.pop_back();
    register_trim_polygon(clean);
  }
  for (auto* lines : {&trim_on_vline_, &trim_on_hline_})
    for (auto& [line, list] : *lines) {
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
    }
}

bool PatchTessellator::outside_domain(Vec2 p) const {
  return p.x < dom_.u0 || p.x > dom_.u1 || p.y < dom_.v0 || p.y > dom_.v1;
}

/// Trim edges that run along the domain's edge only repeat it (the Red
/// Book's outer loop is the domain square). Each maximal run of such edges,
/// p_i ... p_j, is replaced by a detour outside the domain: p_i, p_i', ...,
/// p_j', p_j, every point pushed out by the domain's size. Inside the domain
/// the winding numbers, hence the trimmed region, are unchanged; but no trim
/// point is left on the patch edge except where a loop really leaves it, so
/// the edge keeps its own samples (and stays crack-free).
TrimPolygon PatchTessellator::move_runs_off_domain_edge(const TrimPolygon& poly) const {
  const double push = std::max(dom_.u1 - dom_.u0, dom_.v1 - dom_.v0);
  // Bit k of sides(p): p lies on side k (0 bottom, 1 right, 2 top, 3 left).
  const auto sides = [&](Vec2 p) {
    return (p.y == dom_.v0 ? 1 : 0) | (p.x == dom_.u1 ? 2 : 0) | (p.y == dom_.v1 ? 4 : 0) | (p.x == dom_.u0 ? 8 : 0);
  };
  const auto pushed = [&](Vec2 p, int run_sides) {
    if (run_sides & 1) p.y -= push;
    if (run_sides & 2) p.x += push;
    if (run_sides & 4) p.y += push;
    if (run_sides & 8) p.x -= push;
    return p;
  };
  const std::size_t n = poly.size();
  std::vector<int> run(n);  // run[k]: the side bits edge k (poly[k] -> poly[k+1]) runs along
  bool any_run = false, all_run = true;
  for (std::size_t k = 0; k < n; ++k) {
    run[k] = sides(poly[k]) & sides(poly[(k + 1) % n]);
    any_run = any_run || run[k];
    all_run = all_run && run[k];
  }
  if (!any_run) return poly;
  TrimPolygon out;
  if (all_run) {
    for (std::size_t k = 0; k < n; ++k) out.push_back(pushed(poly[k], run[(k + n - 1) % n] | run[k]));
    return out;
  }
  // Start after a run ends, so that runs are not cut in two by the wrap-around.
  std::size_t start = 0;
  while (!(run[(start + n - 1) % n] == 0)) ++start;
  for (std::size_t s = 0; s < n; ++s) {
    const std::size_t k = (start + s) % n, prev = (k + n - 1) % n;
    const Vec2 p = poly[k];
    const bool ends_run = run[prev] != 0, starts_run = run[k] != 0;
    if (ends_run && starts_run) {
      out.push_back(pushed(p, run[prev] | run[k]));  // inside a run: only the detour
    } else if (starts_run) {
      out.push_back(p);
      out.push_back(pushed(p, run[k]));
    } else if (ends_run) {
      out.push_back(pushed(p, run[prev]));
      out.push_back(p);
    } else {
      out.push_back(p);
    }
  }
  return out;
}

/// Splits each trim edge until its image on the surface is within the
/// tolerance (parametric error): GLU leaves gluPwlCurve edges alone and fans
/// slivers across the trimmed region (docs/glu.md); this is the fix.
void PatchTessellator::check_trim_points(std::size_t count) const {
  if (count > kMaxTrimPoints)
    fail(ErrorCode::kOutOfRange,
         "tessellate: the trims need more than " + std::to_string(kMaxTrimPoints) + " points at tolerance=" +
             num(opt_.tolerance) + " (kMaxTrimPoints; a coarser tolerance needs fewer)",
         {{"tolerance", opt_.tolerance}, {"points", count}});
}

TrimPolygon PatchTessellator::refine_trim_edges(const TrimPolygon& poly, std::vector<char>& refined) {
  TrimPolygon out;
  refined.clear();
  FlattenOptions fo;
  fo.tolerance = opt_.tolerance;
  fo.error = ChordError::Parametric;
  fo.min_depth = 0;
  fo.max_depth = opt_.max_depth;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Vec2 a = poly[k], b = poly[(k + 1) % poly.size()];
    out.push_back(a);
    refined.push_back(0);
    if (outside_domain(a) || outside_domain(b)) continue;  // a detour of move_runs_off_domain_edge
    const auto at = [&](double s) { return clamp_uv(a + s * (b - a)); };
    const auto on_surface = [&](double s) { const Vec2 q = at(s); return evaluate(q.x, q.y).point; };
    const auto samples = flatten_curve(on_surface, 0, 1, fo);
    for (std::size_t i = 1; i + 1 < samples.size(); ++i) out.push_back(at(samples[i].t)), refined.push_back(1);
    check_trim_points(trim_points_.size() + out.size());
  }
  return out;
}

/// Is the chord a-b (a straight (u, v) segment) within the tolerance on the
/// surface? The parametric test of flatten_curve at 1/4, 1/2, 3/4.
bool PatchTessellator::chord_within(Vec2 a, Vec2 b) const {
  const Vec3 pa = evaluate(a.x, a.y).point, pb = evaluate(b.x, b.y).point;
  for (double f : {0.25, 0.5, 0.75}) {
    const Vec2 q = clamp_uv(a + f * (b - a));
    if (norm(evaluate(q.x, q.y).point - lerp(pa, pb, f)) > kFlattenSafety * opt_.tolerance) return false;
  }
  return true;
}

/// Gives each cut trim segment to the leaf it lies in (both leaves when it
/// runs along the line between them), and records trim points on lines.
void PatchTessellator::register_trim_polygon(const std::vector<Vec2>& poly) {
  std::vector<int> ids;
  for (const Vec2& p : poly) {
    const int id = vertex(p);
    verts_[id].trim = true;
    ids.push_back(id);
    if (outside_domain(p)) continue;  // on a detour (move_runs_off_domain_edge)
    const int vi = line_index(line_u_, p.x), hj = line_index(line_v_, p.y);
    if (vi >= 0) trim_on_vline_[line_i_[vi]].push_back({p.y, id});
    if (hj >= 0) trim_on_hline_[line_j_[hj]].push_back({p.x, id});
  }
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const Seg s{ids[k], ids[(k + 1) % ids.size()]};
    const Vec2 p = uv(s.a), q = uv(s.b), m = (p + q) / 2;
    // Rays from the domain go towards +u: they meet detours right of it
    // too, and a ray along the top edge v = v1 meets those above it.
    if (m.y < dom_.v0) continue;
    if (p.y != q.y) row_segments_[winding_row(m.y)].push_back(s);
    if (outside_domain(m)) continue;
    const int row = band(line_v_, m.y);
    const int vi = p.x == q.x ? line_index(line_u_, p.x) : -1;
    const int hj = p.y == q.y ? line_index(line_v_, p.y) : -1;
    const int col = band(line_u_, m.x);
    const Index ci = line_i_[col], rj = line_j_[row];
    if (vi >= 0) {
      const Index li = line_i_[vi];
      const int left = li > 0 ? leaf_at(li - 1, rj) : -1, right = li < nu_ ? leaf_at(li, rj) : -1;
      if (left == right) {
        leaf_trims_[left].push_back({s, -1});
      } else {
        if (left >= 0) leaf_trims_[left].push_back({s, 1});
        if (right >= 0) leaf_trims_[right].push_back({s, 3});
      }
    } else if (hj >= 0) {
      const Index lj = line_j_[hj];
      const int below = lj > 0 ? leaf_at(ci, lj - 1) : -1, above = lj < nv_ ? leaf_at(ci, lj) : -1;
      if (below == above) {
        leaf_trims_[below].push_back({s, -1});
      } else {
        if (below >= 0) leaf_trims_[below].push_back({s, 2});
        if (above >= 0) leaf_trims_[above].push_back({s, 0});
      }
    } else {
      leaf_trims_[leaf_at(ci, rj)].push_back({s, -1});
    }
  }
}

/// Rows of the winding buckets: the finest rows, and one more above v1.
int PatchTessellator::winding_row(double y) const {
  return y > dom_.v1 || y == dom_.v1 ? static_cast<int>(line_v_.size()) - 1 : band(line_v_, y);
}

/// The winding rule of trim.h (inside_trimmed), reading only the trim
/// segments of p's row: they are cut at every row line, so no other
/// segment can cross the ray from p.
bool PatchTessellator::inside(Vec2 p) const {
  if (!trimmed_) return true;
  int w = 0;
  for (const Seg& s : row_segments_[winding_row(p.y)]) w += edge_winding(uv(s.a), uv(s.b), p);
  return w > 0;
}

}  // namespace gllab::spline::detail
