// tests/gl/nurbs_compare.cpp — see nurbs_compare.h.
#include "nurbs_compare.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>

#include "gl/gl.h"
#include "gl/scene.h"
#include "harness/lab.h"
#include "spline/bspline.h"
#include "spline/errors.h"
#include "spline/surface.h"
#include "spline/tessellate.h"
#include "spline/trim.h"

namespace gllab::testing {

using spline::BsplineCurve;
using spline::BsplineSurface;
using spline::ParamInterval;
using spline::Vec2;
using spline::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Box {
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec3 hi{-std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
          -std::numeric_limits<double>::max()};
  void add(Vec3 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  double diagonal() const { return spline::norm(hi - lo); }
  Vec3 centre() const { return 0.5 * (lo + hi); }
  bool flat() const { return hi.z == lo.z; }
};

Box box_of(const std::vector<Vec3>& P) {
  Box b;
  for (const Vec3& q : P) b.add(q);
  return b;
}

/// Interior knots of U (inside the open domain) where the function is at
/// most C0: multiplicity >= p.
std::vector<double> weak_knots(int p, const std::vector<double>& U, ParamInterval dom) {
  std::vector<double> out;
  for (std::size_t k = 0; k < U.size(); ++k) {
    if (!(U[k] > dom.a && U[k] < dom.b)) continue;
    if (!out.empty() && out.back() == U[k]) continue;
    if (spline::knot_multiplicity(U, U[k]) >= p) out.push_back(U[k]);
  }
  return out;
}

/// The weak knot u snaps to, or NaN.
double snapped(double u, const std::vector<double>& knots, ParamInterval dom) {
  for (double k : knots)
    if (std::abs(u - k) <= kKnotSnap * (dom.b - dom.a)) return k;
  return std::numeric_limits<double>::quiet_NaN();
}

/// u clamped onto the domain when it misses by round-off (GLU's float map);
/// NaN when it misses by more.
double onto_domain(double u, ParamInterval dom) {
  const double slack = kKnotSnap * (dom.b - dom.a);
  if (u < dom.a - slack || u > dom.b + slack || std::isnan(u)) return std::numeric_limits<double>::quiet_NaN();
  return std::clamp(u, dom.a, dom.b);
}

double angle_deg(Vec3 a, Vec3 b) {
  const double c = spline::dot(a, b) / (spline::norm(a) * spline::norm(b));
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180 / kPi;
}

double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a, ap = p - a;
  const double len2 = spline::dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(spline::dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
  return spline::norm(ap - t * ab);
}

std::vector<std::string> messages(const std::vector<GluError>& errors) {
  std::vector<std::string> out;
  for (const GluError& e : errors) out.push_back(e.message);
  return out;
}

GluNurbsProperties domain_distance(double width_u, double width_v) {
  GluNurbsProperties p;
  p.sampling_method = GLU_DOMAIN_DISTANCE;
  p.u_step = float(kGluSteps / width_u);
  p.v_step = float(kGluSteps / width_v);
  return p;
}

}  // namespace

// ---- numbers ---------------------------------------------------------------------

CurveNumbers measure_curve(const BsplineCurve& fed, const BsplineCurve& truth, RationalFeed feed) {
  CurveNumbers out;
  const ParamInterval dom = spline::domain(truth);
  GluNurbs glu(domain_distance(dom.b - dom.a, dom.b - dom.a));
  const CurveCapture cap = glu.capture_curve(fed, "suite curve", feed);
  take_frame_errors();  // the errors are in cap.errors; the test reads them there
  out.errors = messages(cap.errors);
  out.vertices = cap.vertex_count();
  out.polylines = cap.polylines.size();
  const double diag = box_of(truth.P).diagonal();
  const std::vector<double> weak = weak_knots(truth.p, truth.U, dom);
  for (const CapturedPolyline& line : cap.polylines)
    for (std::size_t k = 0; k < line.points.size(); ++k) {
      const double u = onto_domain(line.u[k], dom);
      double d = std::numeric_limits<double>::infinity();
      if (!std::isnan(u)) {
        const double knot = snapped(u, weak, dom);
        if (std::isnan(knot)) {
          d = spline::norm(line.points[k] - spline::curve_point(truth, u));
        } else {
          for (spline::Side side : {spline::Side::Left, spline::Side::Right})
            d = std::min(d, spline::norm(line.points[k] - spline::curve_point(truth, knot, side)));
        }
      }
      out.max_distance = std::max(out.max_distance, d / diag);
    }
  return out;
}

SurfaceNumbers measure_surface(const BsplineSurface& fed, const BsplineSurface& truth, RationalFeed feed) {
  SurfaceNumbers out;
  const ParamInterval du = spline::domain_u(truth), dv = spline::domain_v(truth);
  GluNurbs glu(domain_distance(du.b - du.a, dv.b - dv.a));
  const SurfaceCapture cap = glu.capture_surface(fed, "suite surface", feed);
  take_frame_errors();
  out.errors = messages(cap.errors);
  out.vertices = cap.mesh.positions.size();
  out.triangles = cap.mesh.triangles.size();
  const double diag = box_of(truth.P).diagonal();
  const std::vector<double> weak_u = weak_knots(truth.p, truth.U, du), weak_v = weak_knots(truth.q, truth.V, dv);
  const double hu = 1e-9 * (du.b - du.a), hv = 1e-9 * (dv.b - dv.a);  // one-sided limits at a crease

  std::vector<spline::TrimPolygon> polygons;
  if (!truth.trims.empty()) polygons = spline::validate_trim_loops(truth.trims, spline::uv_domain(truth), kTrimFlatten);

  for (std::size_t k = 0; k < cap.mesh.positions.size(); ++k) {
    const double u = onto_domain(cap.mesh.uv[k].x, du), v = onto_domain(cap.mesh.uv[k].y, dv);
    if (std::isnan(u) || std::isnan(v)) {
      out.max_distance = std::numeric_limits<double>::infinity();
      continue;
    }
    out.max_distance = std::max(out.max_distance, spline::norm(cap.mesh.positions[k] - spline::surface_point(truth, u, v)) / diag);

    const Vec3 n = cap.mesh.normals[k];
    if (spline::norm(n) == 0) {
      ++out.zero_normals;
    } else {
      const double ku = snapped(u, weak_u, du), kv = snapped(v, weak_v, dv);
      std::vector<double> us = {u}, vs = {v};
      if (!std::isnan(ku)) us = {std::max(du.a, ku - hu), std::min(du.b, ku + hu)};
      if (!std::isnan(kv)) vs = {std::max(dv.a, kv - hv), std::min(dv.b, kv + hv)};
      double best = 180;
      for (double a : us)
        for (double b : vs) best = std::min(best, angle_deg(n, spline::surface_normal(truth, a, b)));
      out.max_normal_angle = std::max(out.max_normal_angle, best);
    }

    if (polygons.empty()) continue;
    const Vec2 p{u, v};
    if (spline::inside_trimmed(polygons, p)) continue;
    double d = std::numeric_limits<double>::infinity();
    for (const spline::TrimPolygon& poly : polygons)
      for (std::size_t e = 0; e < poly.size(); ++e) d = std::min(d, segment_distance(p, poly[e], poly[(e + 1) % poly.size()]));
    if (d <= kTrimBand) ++out.on_trim_boundary;
    else ++out.outside_trims;
    out.max_boundary_distance = std::max(out.max_boundary_distance, d);
  }

  for (const auto& t : cap.mesh.triangles) {
    const Vec2 a = cap.mesh.uv[t[0]], b = cap.mesh.uv[t[1]], c = cap.mesh.uv[t[2]];
    out.uv_area += 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  if (polygons.empty()) {
    out.trimmed_area = (du.b - du.a) * (dv.b - dv.a);
  } else {
    for (const spline::TrimPolygon& poly : polygons) {
      out.trimmed_area += spline::signed_area(poly);
      for (std::size_t e = 0; e < poly.size(); ++e) out.trim_perimeter += spline::norm(poly[(e + 1) % poly.size()] - poly[e]);
    }
  }
  return out;
}

// ---- images ------------------------------------------------------------------------

namespace {

/// The camera of one case, from its control points: an orthographic view of
/// the bounding sphere of the box; flat cases face on, others tilted.
void begin_frame(const Box& box, bool lit) {
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glViewport(0, 0, kImageSize, kImageSize);
  glClearColor(0.1f, 0.1f, 0.12f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const double r = 0.5 * box.diagonal();
  ortho_fit(kImageSize, kImageSize, 1.05 * r, 1.05 * r, 2 * r);
  if (lit) {
    enable_headlight();
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glColor3f(0.85f, 0.62f, 0.3f);
  } else {
    glDisable(GL_LIGHTING);
    glColor3f(1.f, 1.f, 1.f);
    glLineWidth(2.f);
  }
  glEnable(GL_DEPTH_TEST);
  if (!box.flat()) {
    glRotated(-60, 1, 0, 0);
    glRotated(-30, 0, 0, 1);
  }
  const Vec3 c = box.centre();
  glTranslated(-c.x, -c.y, -c.z);
}

Image end_frame() {
  glFinish();
  std::vector<std::uint8_t> rows(static_cast<std::size_t>(kImageSize) * kImageSize * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kImageSize, kImageSize, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  glPopAttrib();
  return image_from_bottom_up(rows.data(), kImageSize, kImageSize);
}

}  // namespace

Image render_glu_curve(const BsplineCurve& curve, const BsplineCurve& framing, RationalFeed feed) {
  const ParamInterval dom = spline::domain(framing);
  GluNurbs glu(domain_distance(dom.b - dom.a, dom.b - dom.a));
  begin_frame(box_of(framing.P), false);
  glu.draw_curve(curve, "suite curve", feed);
  return end_frame();
}

Image render_own_curve(const BsplineCurve& curve, const BsplineCurve& framing) {
  const Box box = box_of(framing.P);
  begin_frame(box, false);
  spline::FlattenOptions options;
  options.tolerance = kOwnTessellationTolerance * box.diagonal();
  // One strip per piece between breaks (interior knots of multiplicity p + 1,
  // where the curve may jump); the left piece ends on its left limit.
  const ParamInterval dom = spline::domain(curve);
  std::vector<double> ends = {dom.a};
  for (double k : weak_knots(curve.p, curve.U, dom))
    if (spline::knot_multiplicity(curve.U, k) > curve.p) ends.push_back(k);
  ends.push_back(dom.b);
  for (std::size_t k = 0; k + 1 < ends.size(); ++k) {
    const double a = ends[k], b = ends[k + 1];
    const auto point = [&](double t) {
      return spline::curve_point(curve, t, t == b && k + 2 < ends.size() ? spline::Side::Left : spline::Side::Right);
    };
    glBegin(GL_LINE_STRIP);
    for (const spline::CurveSample& s : spline::flatten_curve(point, a, b, options))
      glVertex3d(s.point.x, s.point.y, s.point.z);
    glEnd();
  }
  return end_frame();
}

Image render_glu_surface(const BsplineSurface& surface, const BsplineSurface& framing, RationalFeed feed,
                         bool auto_normal) {
  const ParamInterval du = spline::domain_u(framing), dv = spline::domain_v(framing);
  GluNurbs glu(domain_distance(du.b - du.a, dv.b - dv.a));
  begin_frame(box_of(framing.P), true);
  // GLU's surfaces get normals only with GL_AUTO_NORMAL (docs/glu.md).
  if (auto_normal) glEnable(GL_AUTO_NORMAL);
  glu.draw_surface(surface, "suite surface", feed);
  return end_frame();
}

Image render_own_surface(const BsplineSurface& surface, const BsplineSurface& framing) {
  const Box box = box_of(framing.P);
  const spline::Mesh mesh =
      spline::tessellate_surface(spline::surface_evaluator(surface), spline::uv_domain(surface),
                                 spline::TessellationOptions::adaptive(kOwnTessellationTolerance * box.diagonal()),
                                 surface.trims);
  begin_frame(box, true);
  glBegin(GL_TRIANGLES);
  for (const auto& t : mesh.triangles)
    for (int k : t) {
      const Vec3 n = mesh.normals[static_cast<std::size_t>(k)], p = mesh.positions[static_cast<std::size_t>(k)];
      glNormal3d(n.x, n.y, n.z);
      glVertex3d(p.x, p.y, p.z);
    }
  glEnd();
  return end_frame();
}

ImageScore score_images(const Image& glu, const Image& own) {
  return {compare_images(glu, own, kImageThreshold, kImageShift)};
}

std::vector<std::string> write_images(const std::string& dir, const std::string& name, const Image& glu,
                                      const Image& own) {
  std::filesystem::create_directories(dir);
  const std::string base = (std::filesystem::path(dir) / name).string();
  const std::vector<std::string> paths = {base + "__glu.png", base + "__own.png", base + "__heat.png"};
  write_png(paths[0], glu);
  write_png(paths[1], own);
  write_png(paths[2], heat_map(glu, own, kImageThreshold, kImageShift));
  return paths;
}

// ---- negative checks ----------------------------------------------------------------------

BsplineSurface with_moved_point(const BsplineSurface& s, int i, int j, double fraction) {
  BsplineSurface moved = s;
  moved.point(i, j).z += fraction * box_of(s.P).diagonal();
  return moved;
}

BsplineCurve with_moved_point(const BsplineCurve& c, int i, double fraction) {
  BsplineCurve moved = c;
  moved.P[static_cast<std::size_t>(i)].y += fraction * box_of(c.P).diagonal();
  return moved;
}

// ---- bad input -----------------------------------------------------------------------

namespace {

template <class Capture>
void take_glu_side(const Capture& cap, BadInputResult& out) {
  for (const GluError& e : cap.errors) {
    if (e.nurbs_error > 0) {
      out.glu_errors.push_back(e.nurbs_error);
    } else if (e.code == 0) {
      out.refused_by_wrapper = true;
      out.wrapper_message = e.message;
    }
  }
}

}  // namespace

BadInputResult measure_bad_input(const BsplineCurve& curve) {
  BadInputResult out;
  GluNurbs glu(domain_distance(kGluSteps / 8.0, kGluSteps / 8.0));  // 8 samples per unit of parameter
  const CurveCapture cap = glu.capture_curve(curve, "bad curve");
  take_frame_errors();
  take_glu_side(cap, out);
  out.glu_vertices = cap.vertex_count();
  try {
    spline::validate(curve);
  } catch (const std::invalid_argument& e) {
    out.core_message = e.what();
  }
  return out;
}

BadInputResult measure_bad_input(const BsplineSurface& surface) {
  BadInputResult out;
  GluNurbs glu(domain_distance(kGluSteps / 8.0, kGluSteps / 8.0));
  const SurfaceCapture cap = glu.capture_surface(surface, "bad surface");
  take_frame_errors();
  take_glu_side(cap, out);
  out.glu_vertices = cap.mesh.positions.size();
  try {
    spline::validate(surface);
    if (!surface.trims.empty()) spline::validate_trim_loops(surface.trims, spline::uv_domain(surface));
  } catch (const std::invalid_argument& e) {
    out.core_message = e.what();
  }
  return out;
}

// ---- negative checks ------------------------------------------------------------------

std::vector<NegativeCheck> negative_checks() {
  const std::vector<CurveCase> curves = curve_suite();
  const std::vector<SurfaceCase> surfaces = surface_suite();
  std::vector<NegativeCheck> out;

  const auto moved_surface = [&](const std::string& name, int i, int j, double fraction, bool image_must_fail) {
    const BsplineSurface& s = surface_case(surfaces, name).surface;
    const BsplineSurface moved = with_moved_point(s, i, j, fraction);
    NegativeCheck c;
    c.name = name + "_point_moved_" + std::to_string(int(std::lround(fraction * 100))) + "pct";
    c.what = "own core: control point (" + std::to_string(i) + ", " + std::to_string(j) + ") moved by " +
             std::to_string(int(std::lround(fraction * 100))) + " % of the box diagonal along z; GLU: the original";
    const SurfaceNumbers n = measure_surface(s, moved);
    c.distance = n.max_distance;
    c.normal_angle = n.max_normal_angle;
    c.image_share = score_images(render_glu_surface(s, s), render_own_surface(moved, s)).share();
    c.numbers_must_fail = true;
    c.image_must_fail = image_must_fail;
    out.push_back(c);
  };
  const auto moved_curve = [&](const std::string& name, int i, double fraction, bool image_must_fail) {
    const BsplineCurve& k = curve_case(curves, name).curve;
    const BsplineCurve moved = with_moved_point(k, i, fraction);
    NegativeCheck c;
    c.name = name + "_point_moved_" + std::to_string(int(std::lround(fraction * 100))) + "pct";
    c.what = "own core: control point " + std::to_string(i) + " moved by " +
             std::to_string(int(std::lround(fraction * 100))) + " % of the box diagonal along y; GLU: the original";
    c.distance = measure_curve(k, moved).max_distance;
    c.image_share = score_images(render_glu_curve(k, k), render_own_curve(moved, k)).share();
    c.numbers_must_fail = true;
    c.image_must_fail = image_must_fail;
    out.push_back(c);
  };
  // 1 % is far outside the numbers' tolerance but below what a 256 x 256
  // image shows (measured: well under a pixel, a few grey levels); 10 % shows.
  moved_surface("bicubic_hill", 2, 2, 0.01, false);
  moved_surface("biquadratic_clamped", 1, 1, 0.10, true);
  moved_curve("cubic_clamped_3d", 3, 0.01, false);
  moved_curve("quadratic_clamped_2d", 3, 0.10, true);

  for (const CurveCase& k : curves) {
    if (!k.curve.rational()) continue;
    NegativeCheck c;
    c.name = k.name + "_weights_not_premultiplied";
    c.what = "GLU fed (x, y, z, w) instead of (w x, w y, w z, w)";
    c.distance = measure_curve(k.curve, k.curve, RationalFeed::kMistakeNotPremultiplied).max_distance;
    c.image_share = score_images(render_glu_curve(k.curve, k.curve, RationalFeed::kMistakeNotPremultiplied),
                                 render_own_curve(k.curve, k.curve))
                        .share();
    c.numbers_must_fail = c.image_must_fail = true;
    out.push_back(c);
  }
  for (const SurfaceCase& k : surfaces) {
    if (!k.surface.rational()) continue;
    NegativeCheck c;
    c.name = k.name + "_weights_not_premultiplied";
    c.what = "GLU fed (x, y, z, w) instead of (w x, w y, w z, w)";
    const SurfaceNumbers n = measure_surface(k.surface, k.surface, RationalFeed::kMistakeNotPremultiplied);
    c.distance = n.max_distance;
    c.normal_angle = n.max_normal_angle;
    c.image_share = score_images(render_glu_surface(k.surface, k.surface, RationalFeed::kMistakeNotPremultiplied),
                                 render_own_surface(k.surface, k.surface))
                        .share();
    c.numbers_must_fail = c.image_must_fail = true;
    out.push_back(c);
  }
  for (const std::string name : {"bicubic_hill", "nurbs_torus", "trimmed_island_in_hole"}) {
    const BsplineSurface& s = surface_case(surfaces, name).surface;
    NegativeCheck c;
    c.name = name + "_without_auto_normal";
    c.what = "GLU drawn without glEnable(GL_AUTO_NORMAL): one normal for the whole surface";
    c.image_share =
        score_images(render_glu_surface(s, s, RationalFeed::kPremultiplied, false), render_own_surface(s, s)).share();
    c.image_must_fail = true;
    out.push_back(c);
  }
  return out;
}

// ---- the summary ------------------------------------------------------------------------

namespace {

std::string fmt(const char* format, double v) {
  if (std::isnan(v)) return "–";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

std::string percent(double share) { return fmt("%.4f %%", 100 * share); }

std::string join_numbers(const std::vector<int>& v) {
  std::string s;
  for (int x : v) s += (s.empty() ? "" : ", ") + std::to_string(x);
  return s.empty() ? "none" : s;
}

/// Markdown table cells may not hold a bare '|'.
std::string cell(std::string text) {
  for (std::size_t k = 0; (k = text.find('|', k)) != std::string::npos; k += 2) text.replace(k, 1, "\\|");
  return text;
}

}  // namespace

std::string comparison_summary() {
  std::ostringstream md;
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* glu_version = reinterpret_cast<const char*>(gluGetString(GLU_VERSION));
  md << "# The own spline core against GLU\n\n"
     << "Generated by `tests/gl/nurbs_summary`; do not edit. Regenerate with\n\n"
     << "    cmake --build build --target nurbs_summary && build/tests/gl/nurbs_summary > tests/gl/nurbs_comparison.md\n\n"
     << "The test `gl/NurbsSummary.CommittedFileIsCurrent` fails when this file no longer matches the code.\n"
     << "How the numbers are made: `tests/gl/README.md`. Renderer: " << (renderer ? renderer : "?")
     << ", GLU " << (glu_version ? glu_version : "?") << ".\n\n"
     << "- **Vertices**: GLU in capture mode (`gllab::GluNurbs`, `GLU_DOMAIN_DISTANCE`, " << kGluSteps
     << " steps across the domain each way), each vertex with its (u, v); the own core evaluated at the same (u, v).\n"
     << "  Distance relative to the diagonal of the control points' box; tolerance " << fmt("%.0e", kDistanceTolerance)
     << ". Normal angle tolerance " << fmt("%.1f", kNormalToleranceDeg) << "°.\n"
     << "- **Trims**: GLU vertices outside the own trimmed region must lie within " << fmt("%.0e", kTrimBand)
     << " (u, v units) of a trim edge (GLU's chords of NURBS trim curves); the column gives how many did and their largest distance.\n"
     << "- **Image**: " << kImageSize << "×" << kImageSize << " under OSMesa, GLU rendering (`GL_AUTO_NORMAL`) against the own "
     << "tessellation drawn with GL; share of pixels off by more than " << kImageThreshold << " in a channel, not explained by a "
     << kImageShift << "-pixel shift. Tolerance " << percent(kImageTolerance) << ".\n\n";

  double worst_distance = 0, worst_angle = 0, worst_image = 0, worst_band = 0;
  std::string worst_distance_case, worst_angle_case, worst_image_case, worst_band_case;
  const auto track = [](double v, const std::string& name, double& worst, std::string& which) {
    if (v > worst) {
      worst = v;
      which = name;
    }
  };

  md << "## Curves\n\n| case | GLU vertices | max distance / diagonal | image mismatch |\n|---|---:|---:|---:|\n";
  for (const CurveCase& c : curve_suite()) {
    const CurveNumbers n = measure_curve(c.curve, c.curve);
    const ImageScore img = score_images(render_glu_curve(c.curve, c.curve), render_own_curve(c.curve, c.curve));
    track(n.max_distance, c.name, worst_distance, worst_distance_case);
    track(img.share(), c.name, worst_image, worst_image_case);
    md << "| `" << c.name << "` | " << n.vertices << " | " << fmt("%.2e", n.max_distance) << " | " << percent(img.share())
       << " |\n";
  }
  md << "\n## Surfaces\n\n| case | GLU vertices | GLU triangles | max distance / diagonal | max normal angle (°) | "
        "trim boundary: vertices, max (u, v) distance | image mismatch |\n|---|---:|---:|---:|---:|---:|---:|\n";
  for (const SurfaceCase& c : surface_suite()) {
    const SurfaceNumbers n = measure_surface(c.surface, c.surface);
    const ImageScore img = score_images(render_glu_surface(c.surface, c.surface), render_own_surface(c.surface, c.surface));
    track(n.max_distance, c.name, worst_distance, worst_distance_case);
    track(n.max_normal_angle, c.name, worst_angle, worst_angle_case);
    track(img.share(), c.name, worst_image, worst_image_case);
    track(n.max_boundary_distance, c.name, worst_band, worst_band_case);
    md << "| `" << c.name << "` | " << n.vertices << " | " << n.triangles << " | " << fmt("%.2e", n.max_distance) << " | "
       << fmt("%.4f", n.max_normal_angle) << " | "
       << (c.surface.trims.empty() ? std::string("–")
                                   : std::to_string(n.on_trim_boundary) + ", " + fmt("%.1e", n.max_boundary_distance))
       << " | " << percent(img.share()) << " |\n";
  }

  const std::vector<NegativeCheck> negatives = negative_checks();
  double best_wrong_image = 1, best_wrong_distance = std::numeric_limits<double>::infinity();
  std::string best_wrong_image_case, best_wrong_distance_case;
  for (const NegativeCheck& c : negatives) {
    if (c.image_must_fail && c.image_share < best_wrong_image) {
      best_wrong_image = c.image_share;
      best_wrong_image_case = c.name;
    }
    if (c.numbers_must_fail && c.distance < best_wrong_distance) {
      best_wrong_distance = c.distance;
      best_wrong_distance_case = c.name;
    }
  }

  md << "\n## Tolerances and their margins\n\n"
     << "| measure | tolerance | worst benign case | smallest deliberately wrong case |\n|---|---:|---|---|\n"
     << "| max distance / diagonal | " << fmt("%.0e", kDistanceTolerance) << " | " << fmt("%.2e", worst_distance) << " (`"
     << worst_distance_case << "`), " << fmt("%.0f", kDistanceTolerance / worst_distance) << "× below | "
     << fmt("%.2e", best_wrong_distance) << " (`" << best_wrong_distance_case << "`), "
     << fmt("%.0f", best_wrong_distance / kDistanceTolerance) << "× above |\n"
     << "| max normal angle | " << fmt("%.1f", kNormalToleranceDeg) << "° | " << fmt("%.4f", worst_angle) << "° (`"
     << worst_angle_case << "`) | see the negative checks |\n"
     << "| trim boundary band | " << fmt("%.0e", kTrimBand) << " | " << fmt("%.1e", worst_band) << " (`" << worst_band_case
     << "`), " << fmt("%.1f", kTrimBand / worst_band) << "× below | – |\n"
     << "| image mismatch | " << percent(kImageTolerance) << " | " << percent(worst_image) << " (`" << worst_image_case
     << "`), " << fmt("%.1f", kImageTolerance / worst_image) << "× below | " << percent(best_wrong_image) << " (`"
     << best_wrong_image_case << "`), " << fmt("%.1f", best_wrong_image / kImageTolerance) << "× above |\n";

  md << "\n## Negative checks (each must fail where marked)\n\n"
     << "| check | what is wrong | max distance / diagonal | max normal angle (°) | image mismatch |\n|---|---|---:|---:|---:|\n";
  for (const NegativeCheck& c : negatives)
    md << "| `" << c.name << "` | " << c.what << " | " << fmt("%.2e", c.distance) << (c.numbers_must_fail ? " (must fail)" : "")
       << " | " << fmt("%.3f", c.normal_angle) << " | " << percent(c.image_share)
       << (c.image_must_fail ? " (must fail)" : "") << " |\n";

  {
    const SurfaceCase coarse = coarse_trim_example();
    const SurfaceNumbers n = measure_surface(coarse.surface, coarse.surface);
    const ImageScore img =
        score_images(render_glu_surface(coarse.surface, coarse.surface), render_own_surface(coarse.surface, coarse.surface));
    md << "\n## A GLU artefact: coarse polyline trims\n\n"
       << "`" << coarse.name << "`: " << coarse.what << ". GLU does not refine `gluPwlCurve` edges, so along the loop's "
       << "long edges its surface follows straight chords, and slivers fan from the corners (docs/glu.md); the own "
       << "tessellator refines trim edges. The vertices still agree (max distance " << fmt("%.2e", n.max_distance)
       << ", normals " << fmt("%.4f", n.max_normal_angle) << "°), the image does not: " << percent(img.share())
       << " mismatched. The suite therefore feeds the same loop densified (`trimmed_nurbs_circle_hole`).\n";
  }

  md << "\n## Bad input: GLU and the own core\n\n"
     << "GLU through the wrapper (capture mode, no context). \"GLU errors\" are GLU NURBS error numbers as GLU raised them; "
     << "\"refused\" means the wrapper did not pass the data on because GLU 9.0.2 crashes on it.\n\n"
     << "| input | GLU errors | GLU vertices | own core |\n|---|---|---:|---|\n";
  const auto bad_row = [&](const std::string& name, const BadInputResult& r) {
    md << "| `" << name << "` | " << (r.refused_by_wrapper ? "refused by the wrapper" : join_numbers(r.glu_errors)) << " | "
       << r.glu_vertices << " | " << (r.core_message.empty() ? "accepted" : cell(r.core_message)) << " |\n";
  };
  for (const BadCurve& b : bad_curves()) bad_row("curve " + b.name, measure_bad_input(b.curve));
  for (const BadSurface& b : bad_surfaces()) bad_row("surface " + b.name, measure_bad_input(b.surface));
  take_frame_errors();
  return md.str();
}

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

/// Splits a line into runs of number characters and the rest.
std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> out;
  const auto numeric = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == 'e' || c == '-' || c == '+'; };
  std::size_t k = 0;
  while (k < line.size()) {
    const bool num = std::isdigit(static_cast<unsigned char>(line[k]));
    std::size_t e = k;
    if (num) {
      while (e < line.size() && numeric(line[e])) ++e;
    } else {
      while (e < line.size() && !std::isdigit(static_cast<unsigned char>(line[e]))) ++e;
    }
    out.push_back(line.substr(k, e - k));
    k = e;
  }
  return out;
}

/// One unit in the last printed digit of a number's text: "1.23e-05" -> 1e-7.
double last_digit_unit(const std::string& text) {
  const std::size_t e = text.find('e');
  const std::string mantissa = text.substr(0, e);
  const std::size_t dot = mantissa.find('.');
  const int decimals = dot == std::string::npos ? 0 : int(mantissa.size() - dot - 1);
  const int exponent = e == std::string::npos ? 0 : std::stoi(text.substr(e + 1));
  return std::pow(10.0, exponent - decimals);
}

}  // namespace

std::string summary_difference(const std::string& committed, const std::string& fresh) {
  const std::vector<std::string> a = lines_of(committed), b = lines_of(fresh);
  for (std::size_t k = 0; k < std::max(a.size(), b.size()); ++k) {
    if (k >= a.size()) return "line " + std::to_string(k + 1) + " is new: " + b[k];
    if (k >= b.size()) return "line " + std::to_string(k + 1) + " is gone: " + a[k];
    if (a[k] == b[k]) continue;
    const std::vector<std::string> ta = tokens(a[k]), tb = tokens(b[k]);
    bool same = ta.size() == tb.size();
    for (std::size_t t = 0; same && t < ta.size(); ++t) {
      if (ta[t] == tb[t]) continue;
      const bool numbers = std::isdigit(static_cast<unsigned char>(ta[t][0])) && std::isdigit(static_cast<unsigned char>(tb[t][0]));
      try {
        same = numbers && std::abs(std::stod(ta[t]) - std::stod(tb[t])) <= 1.000001 * last_digit_unit(ta[t]);
      } catch (const std::exception&) {
        same = false;
      }
    }
    if (!same) return "line " + std::to_string(k + 1) + " differs:\n  committed: " + a[k] + "\n  now:       " + b[k];
  }
  return "";
}

}  // namespace gllab::testing
