// tests/gl/nurbs_compare.h — measuring the own spline core against GLU on
// the suite (nurbs_suite.h): vertex positions, normals, trims, images.
//
// Numbers: GLU tessellates each case in capture mode (gllab::GluNurbs) with
// GLU_DOMAIN_DISTANCE, kGluSteps samples across the domain in each
// direction; every vertex comes back with its (u, v) (the Greville texture
// map). The own core evaluates the same (u, v) (curve_point, surface_point,
// surface_normal), and the distance is taken relative to the diagonal of the
// control points' bounding box.
//
// Images: the same case rendered twice with the same camera and light,
// kImageSize x kImageSize, under OSMesa: once by GLU in rendering mode
// (GL_AUTO_NORMAL for surfaces), once from the own tessellation
// (tessellate.h; curves: flatten_curve) drawn with glBegin. Compared with
// compare_images at kImageThreshold, kImageShift.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "gl/glu_nurbs.h"
#include "image/compare.h"
#include "image/image.h"
#include "nurbs_suite.h"

namespace gllab::testing {

// ---- tolerances, with where they come from -------------------------------------

/// GLU computes in float (24-bit mantissa, about 6e-8 relative): docs/glu.md
/// measured its tessellator vertices within about 1e-6 of the true surface.
/// 1e-5 of the box diagonal leaves a factor of 10 over that, and is 1000
/// times smaller than the 1 % mistakes the negative checks make.
inline constexpr double kDistanceTolerance = 1e-5;
/// docs/glu.md: GLU's normals measured within 0.02 degrees; 0.1 leaves a factor 5.
inline constexpr double kNormalToleranceDeg = 0.1;
/// GLU's (u, v) come back through a float texture map: a vertex whose u is
/// this close (relative to the domain width) to an interior knot where the
/// curve or surface is only C0 or jumps is compared with both one-sided
/// limits there, and the closer one counts (GLU emits such a vertex once
/// for each side).
inline constexpr double kKnotSnap = 1e-6;
/// Samples per domain direction given to GLU_DOMAIN_DISTANCE (u_step = this
/// / domain width).
inline constexpr int kGluSteps = 32;

// ---- numbers ---------------------------------------------------------------------

struct CurveNumbers {
  std::size_t vertices = 0;
  std::size_t polylines = 0;
  double max_distance = 0;  // relative to the control points' box diagonal
  std::vector<std::string> errors;
};

struct SurfaceNumbers {
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  double max_distance = 0;        // relative to the box diagonal
  double max_normal_angle = 0;    // degrees
  std::size_t zero_normals = 0;   // GLU normals of length 0 (not compared)
  // Trimmed cases (all zero otherwise):
  std::size_t outside_trims = 0;      // vertices outside the trimmed region by more than kTrimBand
  std::size_t on_trim_boundary = 0;   // vertices not inside, but within kTrimBand of a trim edge
  double max_boundary_distance = 0;   // (u, v) distance of those from the nearest trim edge
  double uv_area = 0;                 // area of GLU's triangles in (u, v)
  double trimmed_area = 0;            // area of the trimmed region (own polygons; the domain when untrimmed)
  /// Length of all trim loops: GLU's region is within kTrimBand of the own
  /// one along them, so the areas may differ by at most perimeter x kTrimBand.
  double trim_perimeter = 0;
  std::vector<std::string> errors;
};

/// GLU is fed `fed` (with `feed`), the core evaluates `truth`: the same curve
/// for the real comparison, a deliberately different one for negative checks.
CurveNumbers measure_curve(const spline::BsplineCurve& fed, const spline::BsplineCurve& truth,
                           RationalFeed feed = RationalFeed::kPremultiplied);
SurfaceNumbers measure_surface(const spline::BsplineSurface& fed, const spline::BsplineSurface& truth,
                               RationalFeed feed = RationalFeed::kPremultiplied);

/// GLU vertices on a trim edge cannot be told inside or outside exactly: GLU
/// puts them on its own chords of a NURBS trim curve (and on the float
/// polyline of a gluPwlCurve). A vertex that the own inside test
/// (spline::inside_trimmed on the loops flattened to kTrimFlatten, in effect
/// the exact curves) calls outside passes when it lies within kTrimBand
/// ((u, v) units) of a trim edge. With GLU_DOMAIN_DISTANCE GLU samples a
/// trim curve at about u_step points per unit of its extent in the domain
/// (measured: a circle of diameter 0.7 came back as 22 chords at 32 steps),
/// so its chords sag by h^2 k / 8 for chord length h and curvature k. The
/// suite's worst case, the r = 0.4 conic arc, measured 2.3e-3 (summary);
/// 4e-3 leaves a margin and is still a quarter of the narrowest trim
/// feature's size (the island, 0.15 from its centre to a corner), so a
/// misplaced loop fails.
inline constexpr double kTrimBand = 4e-3;
inline constexpr double kTrimFlatten = 1e-6;

// ---- images ------------------------------------------------------------------------

inline constexpr int kImageSize = 256;
/// The own tessellation's tolerance for the images, relative to the diagonal.
inline constexpr double kOwnTessellationTolerance = 1e-3;
/// compare_images settings: a pixel differs when a channel moves by more than
/// kImageThreshold; differences explained by a 1-pixel shift are excused.
inline constexpr int kImageThreshold = 24;
inline constexpr int kImageShift = 1;
/// Pass when at most this share of pixels is mismatched (see
/// nurbs_comparison.md for the measured benign and wrong cases).
inline constexpr double kImageTolerance = 0.001;

/// Needs a current GL context (OffscreenContext of kImageSize).
Image render_glu_curve(const spline::BsplineCurve& curve, const spline::BsplineCurve& framing,
                       RationalFeed feed = RationalFeed::kPremultiplied);
Image render_own_curve(const spline::BsplineCurve& curve, const spline::BsplineCurve& framing);
/// auto_normal = false is a negative check: GLU then sends no normals and
/// the whole surface is lit with one (the current) normal.
Image render_glu_surface(const spline::BsplineSurface& surface, const spline::BsplineSurface& framing,
                         RationalFeed feed = RationalFeed::kPremultiplied, bool auto_normal = true);
Image render_own_surface(const spline::BsplineSurface& surface, const spline::BsplineSurface& framing);

struct ImageScore {
  Comparison comparison;
  double share() const { return comparison.mismatched_share(); }
  bool passes() const { return share() <= kImageTolerance; }
};
ImageScore score_images(const Image& glu, const Image& own);

/// Writes <dir>/<name>__glu.png, __own.png and __heat.png; returns the paths.
std::vector<std::string> write_images(const std::string& dir, const std::string& name, const Image& glu,
                                      const Image& own);

// ---- bad input -----------------------------------------------------------------------

/// What GLU (through the wrapper, capture mode, GLU_DOMAIN_DISTANCE, no
/// context) and the own core do with one bad input.
struct BadInputResult {
  std::vector<int> glu_errors;     // GLU NURBS error numbers, in the order GLU raised them
  bool refused_by_wrapper = false; // not passed to GLU (it would crash: glu_nurbs.cpp)
  std::string wrapper_message;     // the wrapper's line when it refused
  std::size_t glu_vertices = 0;    // what GLU emitted anyway
  std::string core_message;        // the core's std::invalid_argument text; empty: accepted
};
BadInputResult measure_bad_input(const spline::BsplineCurve& curve);
BadInputResult measure_bad_input(const spline::BsplineSurface& surface);

// ---- negative checks --------------------------------------------------------------------

/// A deliberately wrong comparison that the tolerances must reject, with
/// the measured numbers (NaN where a check does not measure that side).
struct NegativeCheck {
  std::string name;
  std::string what;
  double distance = std::numeric_limits<double>::quiet_NaN();     // max distance / diagonal
  double normal_angle = std::numeric_limits<double>::quiet_NaN();  // degrees
  double image_share = std::numeric_limits<double>::quiet_NaN();   // mismatched share
  bool numbers_must_fail = false;
  bool image_must_fail = false;
};
/// All of them (needs a current GL context of kImageSize).
std::vector<NegativeCheck> negative_checks();

// ---- the summary ----------------------------------------------------------------------

/// The Markdown of tests/gl/nurbs_comparison.md: every case's numbers and
/// image score, the tolerances and their margins, the negative checks, the
/// GLU artefact case and the bad-input table. Needs a current GL context of
/// kImageSize (it renders every case).
std::string comparison_summary();

/// Compares a committed summary with a fresh one: the same lines, except that
/// numbers may differ by one unit in their last printed digit (rounding of a
/// value that sits on a boundary). Returns "" when they agree, else the first
/// difference, naming the line.
std::string summary_difference(const std::string& committed, const std::string& fresh);

/// A copy of the surface with control point (i, j) moved by `fraction` of the
/// box diagonal along +z (negative checks).
spline::BsplineSurface with_moved_point(const spline::BsplineSurface& s, int i, int j, double fraction);
spline::BsplineCurve with_moved_point(const spline::BsplineCurve& c, int i, double fraction);

}  // namespace gllab::testing
