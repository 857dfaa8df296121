// common/spline/trim.cpp — see trim.h.
#include "spline/trim.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "spline/bspline.h"
#include "spline/errors.h"
#include "spline/tessellate.h"

namespace gllab::spline {

namespace {

std::string loop_name(std::size_t loop) { return "trim loop " + std::to_string(loop); }

using Kind = TrimLoopError::Kind;

/// Throws TrimLoopError with values {loop, values...}.
[[noreturn]] void fail_loop(ErrorCode code, Kind kind, std::size_t loop, std::initializer_list<ErrorArg> values,
                            const std::string& message, std::string summary, std::string rule = "") {
  std::vector<ErrorValue> all = error_values({{"loop", loop}});
  for (const ErrorArg& a : values) a.append_to(all);
  throw TrimLoopError(code, std::move(all), kind, loop, message, std::move(summary), std::move(rule));
}

/// One point of a flattened loop, with where it came from (for messages).
struct TaggedPoint {
  Vec2 p;
  std::size_t piece = 0;
  std::size_t index = 0;  // polyline point index; unused for curves
  double t = 0;           // curve parameter; unused for polylines
  bool from_curve = false;
};

Vec2 uv_of(Vec3 p) { return {p.x, p.y}; }

/// Checks one piece and returns its points (polyline as given, curve
/// flattened by `custom`, or else to the chordal `tolerance` in (u, v)).
std::vector<TaggedPoint> piece_points(const TrimPiece& piece, std::size_t loop, std::size_t k, double tolerance,
                                      const TrimCurveFlattener* custom) {
  const std::string where = loop_name(loop) + ": piece " + std::to_string(k);
  std::vector<TaggedPoint> out;
  if (!piece.curve) {
    const std::size_t n = piece.polyline.size();
    if (n < 2)
      fail_loop(ErrorCode::kTooFewPoints, Kind::kBadPiece, loop, {{"piece", k}, {"points", n}},
                where + " has " + std::to_string(n) + (n == 1 ? " point" : " points") +
                " (a polyline piece needs at least 2)", "has a polyline piece with too few points",
                "a polyline piece needs at least 2 points");
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 p = piece.polyline[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        fail_loop(ErrorCode::kNotFinite, Kind::kBadPiece, loop, {{"piece", k}, {"point", i}, {"u", p.x}, {"v", p.y}},
                  where + " point " + std::to_string(i) + " " + num(p) + " is not finite",
                  "has a point that is not finite");
      out.push_back({p, k, i, 0, false});
    }
    return out;
  }
  const BsplineCurve& curve = *piece.curve;
  try {
    validate(curve);
  } catch (const SplineError& e) {  // the curve's own code and values, after {loop, piece}
    std::vector<ErrorValue> values = error_values({{"loop", loop}, {"piece", k}});
    values.insert(values.end(), e.values().begin(), e.values().end());
    throw TrimLoopError(e.code(), std::move(values), Kind::kBadPiece, loop, where + " (curve): " + e.what(),
                        "has a broken trim curve");
  }
  for (std::size_t i = 0; i < curve.P.size(); ++i)
    if (curve.P[i].z != 0)
      fail_loop(ErrorCode::kNotPlanar, Kind::kBadPiece, loop, {{"piece", k}, {"i", i}, {at("P", i), curve.P[i]}},
                where + " (curve): " + at("P", i) + "=" + num(curve.P[i]) +
                    " has z != 0 (trim curves lie in the (u, v) plane)",
                "has a trim curve off the (u, v) plane", "trim curves lie in the (u, v) plane");
  if (custom) {
    const std::vector<Vec2> points = (*custom)(curve);
    if (points.size() < 2)
      fail_loop(ErrorCode::kTooFewPoints, Kind::kBadPiece, loop, {{"piece", k}, {"points", points.size()}},
                where + " (curve): the flattener returned fewer than 2 points",
                "has a curve piece that flattens to fewer than 2 points");
    for (std::size_t i = 0; i < points.size(); ++i) out.push_back({points[i], k, i, 0, false});
    return out;
  }
  const CurveEvaluator evaluator(curve);  // checked once, not at every sample
  const ParamInterval dom = evaluator.domain();
  FlattenOptions options;
  options.tolerance = tolerance;
  options.error = ChordError::Chordal;
  const auto samples = flatten_curve([&evaluator](double t) { return evaluator.point(t); }, dom.a, dom.b, options);
  for (const CurveSample& s : samples) out.push_back({uv_of(s.point), k, 0, s.t, true});
  return out;
}

std::string describe(const TaggedPoint& q, std::size_t loop) {
  std::string s = loop_name(loop) + ": piece " + std::to_string(q.piece);
  if (q.from_curve) return s + " (curve) at t=" + num(q.t) + " " + num(q.p);
  return s + " point " + std::to_string(q.index) + " " + num(q.p);
}

/// Flattens a loop, checking pieces and closure; keeps the tags.
std::vector<TaggedPoint> flatten_tagged(const TrimLoop& loop, double tolerance, std::size_t index,
                                        const TrimCurveFlattener* custom) {
  if (!custom && (!(tolerance > 0) || !std::isfinite(tolerance)))
    fail(ErrorCode::kToleranceNotPositive,
         loop_name(index) + ": flattening tolerance=" + num(tolerance) + " must be > 0",
         {{"loop", index}, {"tolerance", tolerance}});
  if (loop.pieces.empty())
    fail_loop(ErrorCode::kTrimBadPiece, Kind::kBadPiece, index, {}, loop_name(index) + ": has no pieces",
              "has no pieces");
  std::vector<std::vector<TaggedPoint>> pieces;
  for (std::size_t k = 0; k < loop.pieces.size(); ++k)
    pieces.push_back(piece_points(loop.pieces[k], index, k, tolerance, custom));

  // Closure: each piece starts where the previous one ends (GLU: "every loop closed").
  const std::size_t n = pieces.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t next = (k + 1) % n;
    const Vec2 end = pieces[k].back().p, start = pieces[next].front().p;
    if (norm(end - start) > kTrimClosureTolerance)
      fail_loop(ErrorCode::kTrimNotClosed, Kind::kNotClosed, index,
                {{"piece", k}, {"end", end}, {"next", next}, {"start", start}},
                loop_name(index) + ": not closed: piece " + std::to_string(k) + " ends at " + num(end) +
                    ", piece " + std::to_string(next) + " starts at " + num(start),
                "is not closed", "every loop is closed: each piece starts where the one before ends");
  }

  // Concatenate: each piece's first point is the previous piece's last one.
  std::vector<TaggedPoint> out;
  for (std::size_t k = 0; k < n; ++k)
    out.insert(out.end(), pieces[k].begin() + (k == 0 ? 0 : 1), pieces[k].end());
  out.pop_back();  // the last point closes the loop onto the first
  // Drop exact repeats (a polyline that lists a point twice).
  std::vector<TaggedPoint> unique;
  for (const TaggedPoint& q : out)
    if (unique.empty() || q.p != unique.back().p) unique.push_back(q);
  while (unique.size() > 1 && unique.back().p == unique.front().p) unique.pop_back();
  return unique;
}

bool outside(Vec2 p, UvDomain d) {
  return p.x < d.u0 - kTrimDomainSlack || p.x > d.u1 + kTrimDomainSlack || p.y < d.v0 - kTrimDomainSlack ||
         p.y > d.v1 + kTrimDomainSlack;
}

double orient(Vec2 a, Vec2 b, Vec2 c) { return cross(b - a, c - a); }
int sign(double x) { return (x > 0) - (x < 0); }

/// Is c (known collinear with a-b) within the closed box of segment a-b?
bool within(Vec2 a, Vec2 b, Vec2 c) {
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
         c.y <= std::max(a.y, b.y);
}

/// Where the closed segments a-b and c-d meet, if they do: the crossing point
/// for a proper crossing, else a shared point (touching, or the first point of
/// a collinear overlap, taken along a-b).
bool segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d, Vec2& at) {
  const int o1 = sign(orient(a, b, c)), o2 = sign(orient(a, b, d));
  const int o3 = sign(orient(c, d, a)), o4 = sign(orient(c, d, b));
  if (o1 * o2 < 0 && o3 * o4 < 0) {
    const double t = cross(c - a, d - c) / cross(b - a, d - c);
    at = a + t * (b - a);
    return true;
  }
  // Touching or collinear: report the touching point nearest to a along a-b.
  bool found = false;
  double best = std::numeric_limits<double>::infinity();
  const auto consider = [&](Vec2 p) {
    const double s = dot(p - a, b - a);
    if (!found || s < best) best = s, at = p, found = true;
  };
  if (o1 == 0 && within(a, b, c)) consider(c);
  if (o2 == 0 && within(a, b, d)) consider(d);
  if (o3 == 0 && within(c, d, a)) consider(a);
  if (o4 == 0 && within(c, d, b)) consider(b);
  return found;
}

struct Edge {
  std::size_t loop, index;  // edge `index` of loop `loop`: points[index] -> points[index + 1]
  Vec2 a, b;
  double xmin, xmax, ymin, ymax;
};

}  // namespace

ErrorCode TrimLoopError::code_of(Kind kind) {
  switch (kind) {
    case Kind::kBadPiece: return ErrorCode::kTrimBadPiece;
    case Kind::kNotClosed: return ErrorCode::kTrimNotClosed;
    case Kind::kOutsideDomain: return ErrorCode::kTrimOutsideDomain;
    case Kind::kRepeatedPoint: return ErrorCode::kTrimRepeatedPoint;
    case Kind::kTooFewPoints: return ErrorCode::kTooFewPoints;
    case Kind::kCrossing: return ErrorCode::kTrimCrossing;
    case Kind::kZeroArea: return ErrorCode::kTrimZeroArea;
    case Kind::kOuterClockwise: return ErrorCode::kTrimOuterClockwise;
    case Kind::kHoleCounterClockwise: return ErrorCode::kTrimHoleCounterClockwise;
  }
  return ErrorCode::kTrimBadPiece;
}

// ---- flattening ------------------------------------------------------------------

TrimPolygon flatten_trim_loop(const TrimLoop& loop, double tolerance, std::size_t loop_index) {
  TrimPolygon polygon;
  for (const TaggedPoint& q : flatten_tagged(loop, tolerance, loop_index, nullptr)) polygon.push_back(q.p);
  return polygon;
}

TrimPolygon flatten_trim_loop(const TrimLoop& loop, const TrimCurveFlattener& flatten_piece, std::size_t loop_index) {
  TrimPolygon polygon;
  for (const TaggedPoint& q : flatten_tagged(loop, 0, loop_index, &flatten_piece)) polygon.push_back(q.p);
  return polygon;
}

// ---- area and orientation ------------------------------------------------------------

double signed_area(const TrimPolygon& polygon) {
  // Shoelace formula: A = 1/2 sum (x_k y_{k+1} - x_{k+1} y_k); taken about the
  // first point to lose less precision far from the origin.
  const std::size_t n = polygon.size();
  if (n < 3) return 0;
  double twice = 0;
  const Vec2 o = polygon[0];
  for (std::size_t k = 1; k + 1 < n; ++k) twice += cross(polygon[k] - o, polygon[k + 1] - o);
  return twice / 2;
}

Orientation orientation(const TrimPolygon& polygon) {
  const double a = signed_area(polygon);
  return a > 0 ? Orientation::CounterClockwise : a < 0 ? Orientation::Clockwise : Orientation::Degenerate;
}

const char* to_string(Orientation orientation) {
  switch (orientation) {
    case Orientation::CounterClockwise: return "counter-clockwise";
    case Orientation::Clockwise: return "clockwise";
    case Orientation::Degenerate: return "degenerate";
  }
  return "?";
}

TrimPolygon reversed(const TrimPolygon& polygon) { return TrimPolygon(polygon.rbegin(), polygon.rend()); }

std::string to_string(UvDomain d) {
  return "[" + num(d.u0) + ", " + num(d.u1) + "] x [" + num(d.v0) + ", " + num(d.v1) + "]";
}

// ---- validation -------------------------------------------------------------------

std::vector<TrimLoopInfo> validate_trim_polygons(const std::vector<TrimPolygon>& polygons, UvDomain domain) {
  // 1. Points: finite, inside the domain, no repeats.
  for (std::size_t l = 0; l < polygons.size(); ++l) {
    const TrimPolygon& poly = polygons[l];
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2 p = poly[i];
      const std::string where = loop_name(l) + ": point " + std::to_string(i) + " " + num(p);
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        fail_loop(ErrorCode::kNotFinite, Kind::kBadPiece, l, {{"point", i}, {"u", p.x}, {"v", p.y}},
                  where + " is not finite", "has a point that is not finite");
      if (outside(p, domain))
        fail_loop(ErrorCode::kTrimOutsideDomain, Kind::kOutsideDomain, l,
                  {{"point", i}, {"u", p.x}, {"v", p.y}, {"u0", domain.u0}, {"u1", domain.u1}, {"v0", domain.v0},
                   {"v1", domain.v1}},
                  where + " lies outside the domain " + to_string(domain), "leaves the domain",
                  "trim loops lie in the surface's (u, v) domain");
    }
    for (std::size_t i = 1; i < poly.size(); ++i)
      if (poly[i] == poly[i - 1])
        fail_loop(ErrorCode::kTrimRepeatedPoint, Kind::kRepeatedPoint, l,
                  {{"point", i}, {"repeats", i - 1}, {"u", poly[i].x}, {"v", poly[i].y}},
                  loop_name(l) + ": point " + std::to_string(i) + " " + num(poly[i]) + " repeats point " +
                      std::to_string(i - 1),
                  "repeats a point");
    if (poly.size() > 1 && poly.back() == poly.front())
      fail_loop(ErrorCode::kTrimRepeatedPoint, Kind::kRepeatedPoint, l,
                {{"point", poly.size() - 1}, {"repeats", 0}, {"u", poly.back().x}, {"v", poly.back().y}},
                loop_name(l) + ": point " + std::to_string(poly.size() - 1) + " " + num(poly.back()) +
                    " repeats point 0 (a TrimPolygon does not repeat its first point)",
                "repeats its first point");
    if (poly.size() < 3)
      fail_loop(ErrorCode::kTooFewPoints, Kind::kTooFewPoints, l, {{"points", poly.size()}},
                loop_name(l) + ": has " + std::to_string(poly.size()) + (poly.size() == 1 ? " point" : " points") +
                    " (a loop needs at least 3)",
                "has too few points", "a loop needs at least 3 points");
  }

  // 2. No two edges meet, except neighbours in one loop at their shared point.
  //    Sort-and-sweep on x (bounding boxes), then an exact-sign segment test.
  std::vector<Edge> edges;
  for (std::size_t l = 0; l < polygons.size(); ++l) {
    const TrimPolygon& poly = polygons[l];
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
      edges.push_back({l, i, a, b, std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)});
    }
  }
  // Edges are numbered in loop order; order[] visits them by xmin.
  std::vector<std::size_t> order(edges.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return edges[i].xmin < edges[j].xmin; });
  // Report the pair (later, earlier) that a plain double loop in loop order meets first.
  std::size_t best_later = edges.size(), best_earlier = 0;
  Vec2 best_at;
  for (std::size_t s = 0; s < order.size(); ++s) {
    const Edge& e = edges[order[s]];
    for (std::size_t r = s + 1; r < order.size() && edges[order[r]].xmin <= e.xmax; ++r) {
      const Edge& f = edges[order[r]];
      if (f.ymin > e.ymax || f.ymax < e.ymin) continue;
      std::size_t later = std::max(order[s], order[r]), earlier = std::min(order[s], order[r]);
      if (later > best_later || (later == best_later && earlier >= best_earlier)) continue;
      const Edge& E = edges[later];
      const Edge& F = edges[earlier];
      Vec2 at;
      bool meet = false;
      const std::size_t n = polygons[E.loop].size();
      const bool same_loop = E.loop == F.loop;
      const bool e_follows_f = same_loop && (F.index + 1) % n == E.index;
      const bool f_follows_e = same_loop && (E.index + 1) % n == F.index;
      if (e_follows_f || f_follows_e) {
        // Neighbours share one point; they overlap only if they fold back onto each other.
        const Vec2 shared = e_follows_f ? E.a : E.b;
        const Vec2 e_far = e_follows_f ? E.b : E.a, f_far = e_follows_f ? F.a : F.b;
        if (orient(shared, e_far, f_far) == 0 && dot(e_far - shared, f_far - shared) > 0) {
          at = norm(e_far - shared) < norm(f_far - shared) ? e_far : f_far;
          meet = true;
        }
        // A triangle's edges are all neighbours; nothing else to test.
      } else {
        meet = segments_meet(E.a, E.b, F.a, F.b, at);
      }
      if (meet) best_later = later, best_earlier = earlier, best_at = at;
    }
  }
  if (best_later < edges.size()) {
    const Edge& E = edges[best_later];
    const Edge& F = edges[best_earlier];
    fail_loop(ErrorCode::kTrimCrossing, Kind::kCrossing, E.loop,
              {{"edge", E.index}, {"other_loop", F.loop}, {"other_edge", F.index}, {"u", best_at.x}, {"v", best_at.y}},
              loop_name(E.loop) + ": edge " + std::to_string(E.index) + " " + num(E.a) + "-" + num(E.b) +
                  " crosses edge " + std::to_string(F.index) + " of loop " + std::to_string(F.loop) + " at " +
                  num(best_at),
              "crosses loop " + std::to_string(F.loop), "no two trim curves cross");
  }

  // 3. Area, nesting depth and orientation.
  std::vector<TrimLoopInfo> info(polygons.size());
  for (std::size_t l = 0; l < polygons.size(); ++l) {
    info[l].area = signed_area(polygons[l]);
    if (info[l].area == 0)
      fail_loop(ErrorCode::kTrimZeroArea, Kind::kZeroArea, l, {{"area", info[l].area}},
                loop_name(l) + ": has zero area (signed area 0)", "has zero area");
  }
  for (std::size_t l = 0; l < polygons.size(); ++l) {
    // Loops do not meet, so any point of loop l is strictly inside or outside another loop.
    double parent_area = std::numeric_limits<double>::infinity();
    for (std::size_t m = 0; m < polygons.size(); ++m) {
      if (m == l || winding_number(polygons[m], polygons[l][0]) == 0) continue;
      ++info[l].depth;
      if (std::abs(info[m].area) < parent_area) parent_area = std::abs(info[m].area), info[l].parent = static_cast<int>(m);
    }
  }
  for (std::size_t l = 0; l < polygons.size(); ++l) {
    const bool outer = info[l].depth % 2 == 0;
    const std::string area = "(signed area " + num(info[l].area) + ")";
    if (outer && info[l].area < 0)
      fail_loop(ErrorCode::kTrimOuterClockwise, Kind::kOuterClockwise, l,
                {{"area", info[l].area}, {"depth", info[l].depth}},
                loop_name(l) + " (outer) runs clockwise " + area + "; outer loops must run counter-clockwise",
                "(outer) runs clockwise", "outer loops must run counter-clockwise");
    if (!outer && info[l].area > 0)
      fail_loop(ErrorCode::kTrimHoleCounterClockwise, Kind::kHoleCounterClockwise, l,
                {{"area", info[l].area}, {"depth", info[l].depth}, {"parent", info[l].parent}},
                loop_name(l) + " (hole in loop " + std::to_string(info[l].parent) + ") runs counter-clockwise " +
                    area + "; holes must run clockwise",
                "(a hole) runs counter-clockwise", "holes must run clockwise");
  }
  return info;
}

std::vector<TrimPolygon> validate_trim_loops(const std::vector<TrimLoop>& loops, UvDomain domain, double tolerance) {
  if (!(domain.u0 < domain.u1) || !(domain.v0 < domain.v1) || !std::isfinite(domain.u0) || !std::isfinite(domain.u1) ||
      !std::isfinite(domain.v0) || !std::isfinite(domain.v1))
    fail(std::isfinite(domain.u0) && std::isfinite(domain.u1) && std::isfinite(domain.v0) && std::isfinite(domain.v1)
             ? ErrorCode::kEmptyDomain
             : ErrorCode::kNotFinite,
         "trim domain " + to_string(domain) + " is empty or not finite",
         {{"u0", domain.u0}, {"u1", domain.u1}, {"v0", domain.v0}, {"v1", domain.v1}});
  std::vector<TrimPolygon> polygons;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    // Pieces and closure (flatten_tagged), then the domain: the message can name the piece.
    TrimPolygon polygon;
    for (const TaggedPoint& q : flatten_tagged(loops[l], tolerance, l, nullptr)) {
      if (outside(q.p, domain)) {
        const double where = q.from_curve ? q.t : static_cast<double>(q.index);  // the curve's t, or the point
        fail_loop(ErrorCode::kTrimOutsideDomain, Kind::kOutsideDomain, l,
                  {{"piece", q.piece}, {q.from_curve ? "t" : "point", where}, {"u", q.p.x}, {"v", q.p.y},
                   {"u0", domain.u0}, {"u1", domain.u1}, {"v0", domain.v0}, {"v1", domain.v1}},
                  describe(q, l) + " lies outside the domain " + to_string(domain), "leaves the domain",
                  "trim loops lie in the surface's (u, v) domain");
      }
      polygon.push_back(q.p);
    }
    polygons.push_back(std::move(polygon));
  }
  validate_trim_polygons(polygons, domain);
  return polygons;
}

// ---- inside test -------------------------------------------------------------------

int edge_winding(Vec2 a, Vec2 b, Vec2 p) {
  if (a.y <= p.y) {
    if (b.y > p.y && orient(a, b, p) > 0) return +1;  // upward crossing, p left of a->b
  } else if (b.y <= p.y && orient(a, b, p) < 0) {
    return -1;  // downward crossing, p right of a->b
  }
  return 0;
}

int winding_number(const TrimPolygon& polygon, Vec2 p) {
  int w = 0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) w += edge_winding(polygon[i], polygon[(i + 1) % n], p);
  return w;
}

int winding_number(const std::vector<TrimPolygon>& polygons, Vec2 p) {
  int w = 0;
  for (const TrimPolygon& polygon : polygons) w += winding_number(polygon, p);
  return w;
}

bool inside_trimmed(const std::vector<TrimPolygon>& polygons, Vec2 p) {
  return polygons.empty() || winding_number(polygons, p) > 0;
}

}  // namespace gllab::spline
