// tests/spline/trim_test.cpp — trim loops (common/spline/trim.cpp).
//
// Expected messages are the ones trim.h documents. Coordinates are multiples
// of 1/8 so that areas and crossing points are exact in binary and the
// messages can be compared as text.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "spline/bspline.h"
#include "spline/errors.h"
#include "spline/nurbs.h"
#include "spline/trim.h"

namespace gllab::spline {
namespace {

constexpr UvDomain kUnit{0, 1, 0, 1};
/// Room for round-off in areas summed from a few dozen exact products, and in
/// points of the NURBS circle (radius 1/4) evaluated in floating point.
constexpr double kAreaEps = 1e-12;
constexpr double kCircleRadiusEps = 1e-12;
/// A step off a loop's edge, far below its 1/8 grid, far above round-off.
constexpr double kNudge = 1e-9;

/// One polyline piece, exactly as given.
TrimLoop polyline_loop(std::vector<Vec2> points) {
  TrimLoop loop;
  loop.pieces.push_back({std::move(points), std::nullopt});
  return loop;
}

/// One polyline piece closed as GLU wants it (gluPwlCurve; the Red Book's
/// trim example): the first point again at the end.
TrimLoop closed_loop(std::vector<Vec2> points) {
  points.push_back(points.front());
  return polyline_loop(std::move(points));
}

/// The axis-aligned square [a, b]^2, counter-clockwise (outer) or clockwise (hole).
TrimPolygon square(double a, double b, bool ccw = true) {
  TrimPolygon p{{a, a}, {b, a}, {b, b}, {a, b}};
  return ccw ? p : reversed(p);
}
TrimLoop square_loop(double a, double b, bool ccw = true) { return closed_loop(square(a, b, ccw)); }

/// The message of the std::invalid_argument that f throws ("" if none).
template <class F>
std::string message_of(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// ---- validation: each rule GLU enforces (docs/glu.md), with the exact message ----

TEST(TrimLoop, ClockwiseOuterLoopIsRejected) {
  // GLU keeps the left side, so an outer loop must run counter-clockwise.
  const std::vector<TrimLoop> loops{square_loop(0.25, 0.75, false)};
  EXPECT_EQ(message_of([&] { validate_trim_loops(loops, kUnit); }),
            "trim loop 0 (outer) runs clockwise (signed area -0.25); outer loops must run counter-clockwise");
}

TEST(TrimLoop, CounterClockwiseHoleIsRejected) {
  // A hole inside an outer loop must run clockwise; side 0.25 -> area 0.0625.
  const std::vector<TrimLoop> loops{square_loop(0.125, 0.875), square_loop(0.375, 0.625, true)};
  EXPECT_EQ(message_of([&] { validate_trim_loops(loops, kUnit); }),
            "trim loop 1 (hole in loop 0) runs counter-clockwise (signed area 0.0625); holes must run clockwise");
}

TEST(TrimLoop, HoleOutsideEveryOuterLoopIsRejected) {
  // A clockwise loop in no other loop is an outer loop (depth 0) running clockwise.
  const std::vector<TrimLoop> loops{square_loop(0.125, 0.375), square_loop(0.5, 0.75, false)};
  EXPECT_EQ(message_of([&] { validate_trim_loops(loops, kUnit); }),
            "trim loop 1 (outer) runs clockwise (signed area -0.0625); outer loops must run counter-clockwise");
}

TEST(TrimLoop, OpenLoopIsRejected) {
  // trim.h's example: the last piece ends at (0.5, 0.9), the first starts at (0.5, 1).
  TrimLoop open;
  open.pieces.push_back({{{0.5, 1}, {0.125, 0.5}}, std::nullopt});
  open.pieces.push_back({{{0.125, 0.5}, {0.5, 0.125}, {0.875, 0.5}}, std::nullopt});
  open.pieces.push_back({{{0.875, 0.5}, {0.5, 0.9}}, std::nullopt});
  const std::vector<TrimLoop> loops{square_loop(0.0625, 0.9375), open};
  EXPECT_EQ(message_of([&] { validate_trim_loops(loops, kUnit); }),
            "trim loop 1: not closed: piece 2 ends at (0.5, 0.9), piece 0 starts at (0.5, 1)");
}

TEST(TrimLoop, GapBetweenPiecesIsRejected) {
  TrimLoop loop;
  loop.pieces.push_back({{{0.25, 0.25}, {0.75, 0.25}}, std::nullopt});
  loop.pieces.push_back({{{0.75, 0.375}, {0.75, 0.75}, {0.25, 0.25}}, std::nullopt});
  EXPECT_EQ(message_of([&] { validate_trim_loops({loop}, kUnit); }),
            "trim loop 0: not closed: piece 0 ends at (0.75, 0.25), piece 1 starts at (0.75, 0.375)");
}

TEST(TrimLoop, GapWithinClosureToleranceIsAccepted) {
  // kTrimClosureTolerance absorbs a file's rounding; the joint takes the first piece's end.
  TrimLoop loop;
  loop.pieces.push_back({{{0.25, 0.25}, {0.75, 0.25}}, std::nullopt});
  loop.pieces.push_back({{{0.75, 0.25 + kTrimClosureTolerance / 2}, {0.75, 0.75}, {0.25, 0.25}}, std::nullopt});
  const auto polygons = validate_trim_loops({loop}, kUnit);
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0].size(), 3u);
  EXPECT_EQ(polygons[0][1].y, 0.25);
}

TEST(TrimLoop, SelfIntersectingBowTieIsRejected) {
  // Edges 0 and 2 of the bow-tie cross at its centre.
  const std::vector<TrimLoop> loops{closed_loop({{0.25, 0.25}, {0.75, 0.75}, {0.75, 0.25}, {0.25, 0.75}})};
  EXPECT_EQ(message_of([&] { validate_trim_loops(loops, kUnit); }),
            "trim loop 0: edge 2 (0.75, 0.25)-(0.25, 0.75) crosses edge 0 of loop 0 at (0.5, 0.5)");
}

TEST(TrimLoop, LoopsCrossingAreRejected) {
  // Two overlapping squares: loop 1's edge 0 (y = 0.375) meets loop 0's edge 1 (x = 0.625) first.
  const std::vector<TrimLoop> loops{square_loop(0.125, 0.625), square_loop(0.375, 0.875)};
  EXPECT_EQ(message_of([&] { validate_trim_loops(loops, kUnit); }),
            "trim loop 1: edge 0 (0.375, 0.375)-(0.875, 0.375) crosses edge 1 of loop 0 at (0.625, 0.375)");
}

TEST(TrimLoop, LoopsTouchingAtAPointAreRejected) {
  // GLU's "no intersections" includes touching: the hole's corner lies on the outer edge.
  const std::vector<TrimLoop> loops{square_loop(0.125, 0.875),
                                    closed_loop({{0.5, 0.125}, {0.25, 0.5}, {0.5, 0.75}, {0.75, 0.5}})};
  EXPECT_EQ(message_of([&] { validate_trim_loops(loops, kUnit); }),
            "trim loop 1: edge 0 (0.5, 0.125)-(0.25, 0.5) crosses edge 0 of loop 0 at (0.5, 0.125)");
}

TEST(TrimLoop, EdgeFoldingBackIsRejected) {
  // Point 2 walks back along edge 1: neighbours that overlap.
  const std::vector<TrimLoop> loops{closed_loop({{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.75, 0.5}})};
  EXPECT_EQ(message_of([&] { validate_trim_loops(loops, kUnit); }),
            "trim loop 0: edge 2 (0.75, 0.75)-(0.75, 0.5) crosses edge 1 of loop 0 at (0.75, 0.5)");
}

TEST(TrimLoop, PointOutsideDomainIsRejected) {
  const std::vector<TrimLoop> loops{closed_loop({{0.25, 0.25}, {1.25, 0.5}, {0.25, 0.75}})};
  EXPECT_EQ(message_of([&] { validate_trim_loops(loops, kUnit); }),
            "trim loop 0: piece 0 point 1 (1.25, 0.5) lies outside the domain [0, 1] x [0, 1]");
  // The same for a polygon given directly, and for a domain that is not the unit square.
  EXPECT_EQ(message_of([&] { validate_trim_polygons({square(0.5, 2.5)}, UvDomain{0, 2, -1, 3}); }),
            "trim loop 0: point 1 (2.5, 0.5) lies outside the domain [0, 2] x [-1, 3]");
}

TEST(TrimLoop, PointOnDomainEdgeIsAccepted) {
  // The outer loop may run along the domain's own edges (the Red Book's trim example).
  const auto info = validate_trim_polygons({square(0, 1)}, kUnit);
  EXPECT_EQ(info[0].depth, 0);
  EXPECT_EQ(info[0].area, 1);
}

TEST(TrimLoop, DegenerateInputIsRejected) {
  EXPECT_EQ(message_of([&] { validate_trim_loops({TrimLoop{}}, kUnit); }), "trim loop 0: has no pieces");
  EXPECT_EQ(message_of([&] { validate_trim_loops({polyline_loop({{0.5, 0.5}})}, kUnit); }),
            "trim loop 0: piece 0 has 1 point (a polyline piece needs at least 2)");
  EXPECT_EQ(message_of([&] { validate_trim_loops({polyline_loop({{0.5, 0.5}, {NAN, 0.5}, {0.5, 0.5}})}, kUnit); }),
            "trim loop 0: piece 0 point 1 (nan, 0.5) is not finite");
  EXPECT_EQ(message_of([&] { validate_trim_loops({polyline_loop({{0.25, 0.5}, {0.75, 0.5}, {0.25, 0.5}})}, kUnit); }),
            "trim loop 0: has 2 points (a loop needs at least 3)");
  EXPECT_EQ(message_of([&] { validate_trim_polygons({{{0.25, 0.5}, {0.75, 0.5}, {0.75, 0.5}, {0.5, 0.75}}}, kUnit); }),
            "trim loop 0: point 2 (0.75, 0.5) repeats point 1");
  EXPECT_EQ(message_of([&] { validate_trim_loops({}, UvDomain{1, 0, 0, 1}); }),
            "trim domain [1, 0] x [0, 1] is empty or not finite");
}

TEST(TrimLoop, NestedIslandIsAccepted) {
  // Outer (ccw) > hole (cw) > island (ccw): depths 0, 1, 2 and the parents.
  const auto info = validate_trim_polygons({square(0.125, 0.875), square(0.25, 0.75, false), square(0.375, 0.625)},
                                           kUnit);
  ASSERT_EQ(info.size(), 3u);
  EXPECT_EQ(info[0].depth, 0);
  EXPECT_EQ(info[1].depth, 1);
  EXPECT_EQ(info[2].depth, 2);
  EXPECT_EQ(info[0].parent, -1);
  EXPECT_EQ(info[1].parent, 0);
  EXPECT_EQ(info[2].parent, 1);
  // The island is at even depth, so it is an outer loop: clockwise is wrong there.
  EXPECT_EQ(message_of([&] {
              validate_trim_polygons({square(0.125, 0.875), square(0.25, 0.75, false), square(0.375, 0.625, false)},
                                     kUnit);
            }),
            "trim loop 2 (outer) runs clockwise (signed area -0.0625); outer loops must run counter-clockwise");
}

TEST(TrimLoop, ClosedPolylineRepeatingItsFirstPointFlattensOnce) {
  // examples/trimmed_nurbs_surface.json writes the square with its first point again at the end.
  const TrimPolygon p =
      flatten_trim_loop(polyline_loop({{0.05, 0.05}, {0.95, 0.05}, {0.95, 0.95}, {0.05, 0.95}, {0.05, 0.05}}));
  ASSERT_EQ(p.size(), 4u);
  EXPECT_EQ(p.front().x, 0.05);
  EXPECT_EQ(p.back().y, 0.95);
}

TEST(TrimLoop, PiecesJoinWithoutRepeatingPoints) {
  TrimLoop loop;
  loop.pieces.push_back({{{0.25, 0.25}, {0.75, 0.25}}, std::nullopt});
  loop.pieces.push_back({{{0.75, 0.25}, {0.75, 0.75}}, std::nullopt});
  loop.pieces.push_back({{{0.75, 0.75}, {0.25, 0.75}, {0.25, 0.25}}, std::nullopt});
  EXPECT_EQ(flatten_trim_loop(loop).size(), 4u);
}

// ---- area, orientation, inside test --------------------------------------------------

TEST(SignedArea, UnitSquareIsOneCounterClockwise) {
  EXPECT_EQ(signed_area(square(0, 1)), 1);
  EXPECT_EQ(signed_area(square(0, 1, false)), -1);
  EXPECT_EQ(orientation(square(0, 1)), Orientation::CounterClockwise);
  EXPECT_EQ(orientation(square(0, 1, false)), Orientation::Clockwise);
  EXPECT_EQ(orientation(TrimPolygon{{0, 0}, {1, 1}, {2, 2}}), Orientation::Degenerate);
  EXPECT_STREQ(to_string(Orientation::Clockwise), "clockwise");
}

TEST(SignedArea, ShoelaceMatchesTriangleFormula) {
  // Property: for 200 pseudo-random triangles, shoelace == cross / 2.
  unsigned state = 12345;
  const auto rnd = [&] { return (state = state * 1103515245u + 12345u) / 4294967296.0; };
  for (int k = 0; k < 200; ++k) {
    const Vec2 a{rnd(), rnd()}, b{rnd(), rnd()}, c{rnd(), rnd()};
    EXPECT_NEAR(signed_area({a, b, c}), cross(b - a, c - a) / 2, kAreaEps);
  }
}

TEST(InsideTrimmed, SquareWithSquareHole) {
  // Outer [0.125, 0.875]^2 ccw, hole [0.375, 0.625]^2 cw: the ring is kept.
  const std::vector<TrimPolygon> region{square(0.125, 0.875), square(0.375, 0.625, false)};
  EXPECT_TRUE(inside_trimmed(region, {0.25, 0.25}));    // in the ring
  EXPECT_TRUE(inside_trimmed(region, {0.75, 0.5}));     // in the ring, right of the hole
  EXPECT_FALSE(inside_trimmed(region, {0.5, 0.5}));     // in the hole
  EXPECT_FALSE(inside_trimmed(region, {0.0625, 0.5}));  // outside the outer loop
  EXPECT_FALSE(inside_trimmed(region, {0.95, 0.95}));
  EXPECT_EQ(winding_number(region, {0.25, 0.25}), 1);
  EXPECT_EQ(winding_number(region, {0.5, 0.5}), 0);
  // A ray through a vertex (y = 0.375 passes the hole's corners) counts once.
  EXPECT_TRUE(inside_trimmed(region, {0.25, 0.375}));
  EXPECT_FALSE(inside_trimmed(region, {0.5, 0.375 + kNudge}));
}

TEST(InsideTrimmed, IslandInHoleIsKept) {
  const std::vector<TrimPolygon> region{square(0.125, 0.875), square(0.25, 0.75, false), square(0.375, 0.625)};
  EXPECT_TRUE(inside_trimmed(region, {0.1875, 0.5}));
  EXPECT_FALSE(inside_trimmed(region, {0.3125, 0.5}));
  EXPECT_TRUE(inside_trimmed(region, {0.5, 0.5}));
}

TEST(InsideTrimmed, NoLoopsKeepsEverythingAndReversedLoopKeepsNothing) {
  EXPECT_TRUE(inside_trimmed({}, {0.5, 0.5}));
  // The winding rule reads orientation: a lone clockwise loop winds -1 (trim.h).
  EXPECT_FALSE(inside_trimmed({square(0.25, 0.75, false)}, {0.5, 0.5}));
  EXPECT_EQ(winding_number(square(0.25, 0.75, false), {0.5, 0.5}), -1);
}

TEST(InsideTrimmed, AgreesWithEvenOddOnValidLoops) {
  // Property: for valid nested loops, winding > 0 <=> an odd number of crossings.
  const std::vector<TrimPolygon> region{square(0.125, 0.875), square(0.25, 0.75, false), square(0.375, 0.625)};
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      const Vec2 p{(i + 0.3) / 41, (j + 0.7) / 41};
      int crossings = 0;
      for (const TrimPolygon& poly : region) crossings += std::abs(winding_number(poly, p));
      EXPECT_EQ(inside_trimmed(region, p), crossings % 2 == 1) << num(p);
    }
}

// ---- curve pieces (bspline.h, nurbs.h) ------------------------------------------------

TEST(TrimLoop, NurbsCircleHoleFlattensWithinTolerance) {
  // The exact NURBS circle (nurbs.h), reversed to run clockwise: a round hole.
  const double r = 0.25;
  const BsplineCurve c = reversed(circle({0.5, 0.5, 0}, r));
  TrimLoop hole;
  hole.pieces.push_back({{}, c});
  const double tol = 1e-5;
  const std::vector<TrimPolygon> polygons = validate_trim_loops({square_loop(0.125, 0.875), hole}, kUnit, tol);
  ASSERT_EQ(polygons.size(), 2u);
  for (const Vec2& p : polygons[1]) EXPECT_NEAR(norm(p - Vec2{0.5, 0.5}), r, kCircleRadiusEps);
  // Chords of a circle cut inside it by at most tol: area between pi r^2 (1 - 2 tol / r) and pi r^2.
  const double area = -signed_area(polygons[1]);
  const double pi_r2 = std::acos(-1.0) * r * r;
  EXPECT_LE(area, pi_r2);
  EXPECT_GE(area, pi_r2 * (1 - 2 * tol / r));
  EXPECT_FALSE(inside_trimmed(polygons, {0.5, 0.5}));
  EXPECT_TRUE(inside_trimmed(polygons, {0.5, 0.5 + r + 0.01}));
}

TEST(TrimLoop, CurvePieceWithZIsRejected) {
  // A 2D curve with z != 0 is caught by validate(BsplineCurve) (bspline.h), a
  // 3D one by the trim check: trim curves live in the (u, v) plane.
  BsplineCurve c = circle({0.5, 0.5, 0}, 0.25);
  c.P[3].z = 0.5;
  TrimLoop loop;
  loop.pieces.push_back({{}, c});
  EXPECT_EQ(message_of([&] { validate_trim_loops({loop}, kUnit); }),
            "trim loop 0: piece 0 (curve): control points: P[3]=(0.25, 0.75, 0.5) has z != 0 in a 2D curve");
  loop.pieces[0].curve->dimension = 3;
  EXPECT_EQ(message_of([&] { validate_trim_loops({loop}, kUnit); }),
            "trim loop 0: piece 0 (curve): P[3]=(0.25, 0.75, 0.5) has z != 0 (trim curves lie in the (u, v) plane)");
}

TEST(TrimLoop, CurveAndPolylinePiecesJoin) {
  // A half disc: the upper half of the NURBS circle (t in [0, 1/2] of its
  // knots {0,0,0,1/4,1/4,1/2,...}), then a polyline back along the diameter.
  const auto halves = split(circle({0.5, 0.5, 0}, 0.25), 0.5);
  TrimLoop loop;
  loop.pieces.push_back({{}, halves.first});
  loop.pieces.push_back({{{0.25, 0.5}, {0.75, 0.5}}, std::nullopt});
  const double tol = 1e-6;
  const auto polygons = validate_trim_loops({loop}, kUnit, tol);
  // Chords cut inside the arc by at most tol: the area is short by at most 2 tol / r of it.
  const double half_disc = std::acos(-1.0) * 0.25 * 0.25 / 2;
  EXPECT_NEAR(signed_area(polygons[0]), half_disc, half_disc * 2 * tol / 0.25);
  // The joints are not doubled: no two neighbours coincide.
  for (std::size_t k = 0; k < polygons[0].size(); ++k)
    EXPECT_NE(polygons[0][k], polygons[0][(k + 1) % polygons[0].size()]);
}

}  // namespace
}  // namespace gllab::spline

namespace gllab::spline {
namespace {

// The same failures as data (trim.h TrimLoopError), so a program can show the
// loop and the rule without parsing the message: lab 22's error view does.
TrimLoopError error_of(const std::vector<TrimLoop>& loops) {
  try {
    validate_trim_loops(loops, kUnit);
  } catch (const TrimLoopError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted";
  return TrimLoopError(TrimLoopError::Kind::kBadPiece, 99, "", "");
}

TEST(TrimLoopError, CarriesTheLoopTheKindAndTheRule) {
  const TrimLoopError outer = error_of({square_loop(0.25, 0.75, false)});
  EXPECT_EQ(outer.kind, TrimLoopError::Kind::kOuterClockwise);
  EXPECT_EQ(outer.loop, 0u);
  EXPECT_EQ(outer.summary, "(outer) runs clockwise");
  EXPECT_EQ(outer.rule, "outer loops must run counter-clockwise");
  const TrimLoopError hole = error_of({square_loop(0.125, 0.875), square_loop(0.375, 0.625, true)});
  EXPECT_EQ(hole.kind, TrimLoopError::Kind::kHoleCounterClockwise);
  EXPECT_EQ(hole.loop, 1u);
  EXPECT_EQ(hole.rule, "holes must run clockwise");
  TrimLoop open;
  open.pieces.push_back({{{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}}, std::nullopt});
  const TrimLoopError gap = error_of({square_loop(0.0625, 0.9375), open});
  EXPECT_EQ(gap.kind, TrimLoopError::Kind::kNotClosed);
  EXPECT_EQ(gap.loop, 1u);
  // It is still the std::invalid_argument every caller catches, with the documented message.
  EXPECT_EQ(std::string(gap.what()).rfind("trim loop 1: not closed:", 0), 0u) << gap.what();
}

}  // namespace
}  // namespace gllab::spline
