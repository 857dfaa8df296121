// common/gl/glu_nurbs.cpp — see glu_nurbs.h.
//
// Facts this file depends on (docs/glu.md, and measured with GLU
// 9.0.2 where marked):
//  - rational points go premultiplied, (w x, w y, w z, w), trims (w u, w v, w);
//  - callbacks are GLAPIENTRY functions cast to _GLUfuncptr (no CALLBACK macro);
//  - the error callback gets GLU_NURBS_ERROR1 + n - 1 for NURBS error n, and
//    GLU_INVALID_ENUM / GLU_INVALID_VALUE for a bad property (measured);
//  - choosing an object-space sampling method turns GLU_AUTO_LOAD_MATRIX off,
//    and choosing a screen-space one afterwards does not turn it back on
//    (measured with gluGetNurbsProperty): so the method is set first;
//  - in tessellator mode, surface vertices arrive projected (x, y, z), curve
//    vertices of a GL_MAP1_VERTEX_4 map homogeneous (measured, bench/peer_glu.cpp);
//  - GLU's tessellator sends GL_QUAD_STRIP, GL_TRIANGLE_FAN, ... (measured:
//    quad strips for untrimmed grids, fans and quad strips around trims, line
//    strips for GLU_OUTLINE_PATCH).
#include "gl/glu_nurbs.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

#include "gl/glu_errors.h"
#include "harness/lab.h"
#include "spline/bspline.h"
#include "spline/errors.h"
#include "spline/surface.h"
#include "spline/trim.h"

#if defined(GLLAB_ASAN)
#include <sanitizer/lsan_interface.h>
#endif

namespace gllab {

using spline::BsplineCurve;
using spline::BsplineSurface;
using spline::num;
using spline::Vec2;
using spline::Vec3;

// ---- names -------------------------------------------------------------------

std::string glu_enum_name(GLenum value) {
  switch (value) {
    case GLU_PATH_LENGTH: return "GLU_PATH_LENGTH";
    case GLU_PARAMETRIC_ERROR: return "GLU_PARAMETRIC_ERROR";
    case GLU_DOMAIN_DISTANCE: return "GLU_DOMAIN_DISTANCE";
    case GLU_OBJECT_PATH_LENGTH: return "GLU_OBJECT_PATH_LENGTH";
    case GLU_OBJECT_PARAMETRIC_ERROR: return "GLU_OBJECT_PARAMETRIC_ERROR";
    case GLU_FILL: return "GLU_FILL";
    case GLU_OUTLINE_POLYGON: return "GLU_OUTLINE_POLYGON";
    case GLU_OUTLINE_PATCH: return "GLU_OUTLINE_PATCH";
    case GLU_INVALID_ENUM: return "GLU_INVALID_ENUM";
    case GLU_INVALID_VALUE: return "GLU_INVALID_VALUE";
    case GLU_OUT_OF_MEMORY: return "GLU_OUT_OF_MEMORY";
    default: break;
  }
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%X", static_cast<unsigned>(value));
  return hex;
}

bool samples_in_screen_space(GLenum sampling_method) {
  return sampling_method == GLU_PATH_LENGTH || sampling_method == GLU_PARAMETRIC_ERROR;
}

namespace {

bool samples_in_object_space(GLenum m) { return m == GLU_OBJECT_PATH_LENGTH || m == GLU_OBJECT_PARAMETRIC_ERROR; }

bool known_method(GLenum m) { return samples_in_screen_space(m) || samples_in_object_space(m) || m == GLU_DOMAIN_DISTANCE; }

bool known_display_mode(GLenum d) { return d == GLU_FILL || d == GLU_OUTLINE_POLYGON || d == GLU_OUTLINE_PATCH; }

// ---- errors: the call in progress ---------------------------------------------

// GLU's error callback has no user data; it runs inside the gluNurbs* call
// that failed, on the calling thread. CallScope points t_call at the call in
// progress for exactly that long, and reports what was collected when it ends.
struct Call {
  std::string what;  // "gluNurbsSurface (trimmed hill)"
  std::vector<GluError> errors;
};
thread_local Call* t_call = nullptr;

GluError make_error(const std::string& what, GLenum code) {
  GluError e;
  e.code = code;
  if (code >= GLU_NURBS_ERROR1 && code <= GLU_NURBS_ERROR37) e.nurbs_error = static_cast<int>(code - GLU_NURBS_ERROR1) + 1;
  e.message = what + ": " + glu_error_text(code);
  return e;
}

void GLAPIENTRY on_glu_error(GLenum code) {
  if (t_call) {
    t_call->errors.push_back(make_error(t_call->what, code));
  } else {
    // Every GLU call of this file runs inside a CallScope; this would be a bug here.
    report_frame_error(make_error("GLU NURBS call outside gllab::GluNurbs", code).message);
  }
}

// GLU error n that GLU raised with longjmp and never reported (glu_errors.h:
// "errors GLU finds and then loses"): recorded for the call in progress.
void record_lost_error(int value) {
  if (t_call && value >= 1 && value <= static_cast<int>(GLU_NURBS_ERROR37 - GLU_NURBS_ERROR1) + 1)
    t_call->errors.push_back(make_error(t_call->what, GLU_NURBS_ERROR1 + static_cast<GLenum>(value) - 1));
}

class CallScope {
 public:
  explicit CallScope(std::string what) : previous_(t_call) {
    call_.what = std::move(what);
    t_call = &call_;
    previous_sink_ = set_lost_glu_error_sink(record_lost_error);
  }
  ~CallScope() {
    set_lost_glu_error_sink(previous_sink_);
    t_call = previous_;
  }
  CallScope(const CallScope&) = delete;
  CallScope& operator=(const CallScope&) = delete;

  const std::string& what() const { return call_.what; }
  /// The wrapper's own refusal, as one line.
  void refuse(const std::string& reason) {
    GluError e;
    e.message = call_.what + ": " + reason;
    call_.errors.push_back(std::move(e));
  }
  bool failed() const { return !call_.errors.empty(); }
  /// Reports each error once; GLU repeats some (one per trim loop or patch),
  /// and a repeat says "(N times)".
  std::vector<GluError> finish() {
    std::vector<GluError> distinct;
    std::vector<int> repeats;
    for (const GluError& e : call_.errors) {
      std::size_t k = 0;
      while (k < distinct.size() && distinct[k].message != e.message) ++k;
      if (k == distinct.size()) {
        distinct.push_back(e);
        repeats.push_back(1);
      } else {
        ++repeats[k];
      }
    }
    for (std::size_t k = 0; k < distinct.size(); ++k) {
      if (repeats[k] > 1) distinct[k].message += " (" + std::to_string(repeats[k]) + " times)";
      report_frame_error(distinct[k].message);
    }
    call_.errors.clear();
    return distinct;
  }

 private:
  Call call_;
  Call* previous_;
  LostGluErrorSink previous_sink_ = nullptr;
};

// ---- checks GLU cannot make ------------------------------------------------------

// GLU takes floats: a finite double beyond FLT_MAX would become infinity.
std::string float_problem(double v, const std::string& name) {
  if (!std::isfinite(v)) return name + "=" + num(v) + " is not finite";
  if (std::abs(v) > FLT_MAX) return name + "=" + num(v) + " is beyond float range (GLU takes floats)";
  return "";
}

std::string float_problem(Vec3 p, const std::string& name) {
  for (double c : {p.x, p.y, p.z}) {
    if (!std::isfinite(c)) return name + "=" + num(p) + " is not finite";
    if (std::abs(c) > FLT_MAX) return name + "=" + num(p) + " is beyond float range (GLU takes floats)";
  }
  return "";
}

/// GLU reads knots.size() - order control points: more than there are would be
/// read past the array.
std::string knot_count_problem(std::size_t knots, int order, std::size_t points, const char* U, const char* P) {
  const long long read = static_cast<long long>(knots) - order;
  if (read <= static_cast<long long>(points)) return "";
  return std::string(U) + " has " + std::to_string(knots) + " knots: with order " + std::to_string(order) +
         " GLU would read " + std::to_string(read) + " control points, " + P + " has " + std::to_string(points) +
         " (knots must be <= points + order = " + std::to_string(static_cast<long long>(points) + order) + ")";
}

std::string curve_problem(const BsplineCurve& c, RationalFeed feed, const std::string& prefix = "") {
  if (std::string s = knot_count_problem(c.U.size(), c.p + 1, c.P.size(), "U", "P"); !s.empty()) return prefix + s;
  if (c.rational() && c.w.size() != c.P.size())
    return prefix + "w has " + std::to_string(c.w.size()) + " weights for " + std::to_string(c.P.size()) +
           " control points";
  for (std::size_t k = 0; k < c.U.size(); ++k)
    if (std::string s = float_problem(c.U[k], spline::at("U", k)); !s.empty()) return prefix + s;
  for (std::size_t i = 0; i < c.P.size(); ++i) {
    if (std::string s = float_problem(c.P[i], spline::at("P", i)); !s.empty()) return prefix + s;
    if (!c.rational()) continue;
    if (std::string s = float_problem(c.w[i], spline::at("w", i)); !s.empty()) return prefix + s;
    if (feed == RationalFeed::kPremultiplied)
      if (std::string s = float_problem(c.w[i] * c.P[i], "w[" + std::to_string(i) + "] * P[" + std::to_string(i) + "]");
          !s.empty())
        return prefix + s;
  }
  return "";
}

std::string surface_problem(const BsplineSurface& s, RationalFeed feed) {
  if (s.nu < 0 || s.nv < 0) return "nu=" + std::to_string(s.nu) + ", nv=" + std::to_string(s.nv) + " must be >= 0";
  const std::size_t count = static_cast<std::size_t>(s.nu) * static_cast<std::size_t>(s.nv);
  if (s.P.size() != count)
    return "P has " + std::to_string(s.P.size()) + " points, nu x nv = " + std::to_string(s.nu) + " x " +
           std::to_string(s.nv) + " = " + std::to_string(count);
  if (std::string m = knot_count_problem(s.U.size(), s.p + 1, static_cast<std::size_t>(s.nu), "U", "the net (nu)");
      !m.empty())
    return m;
  if (std::string m = knot_count_problem(s.V.size(), s.q + 1, static_cast<std::size_t>(s.nv), "V", "the net (nv)");
      !m.empty())
    return m;
  if (s.rational() && s.w.size() != count)
    return "w has " + std::to_string(s.w.size()) + " weights for " + std::to_string(count) + " control points";
  for (std::size_t k = 0; k < s.U.size(); ++k)
    if (std::string m = float_problem(s.U[k], spline::at("U", k)); !m.empty()) return m;
  for (std::size_t k = 0; k < s.V.size(); ++k)
    if (std::string m = float_problem(s.V[k], spline::at("V", k)); !m.empty()) return m;
  for (std::size_t k = 0; k < count; ++k) {
    const std::string ij = "(" + std::to_string(k / s.nv) + ", " + std::to_string(k % s.nv) + ")";
    if (std::string m = float_problem(s.P[k], "P" + ij); !m.empty()) return m;
    if (!s.rational()) continue;
    if (std::string m = float_problem(s.w[k], "w" + ij); !m.empty()) return m;
    if (feed == RationalFeed::kPremultiplied)
      if (std::string m = float_problem(s.w[k] * s.P[k], "w" + ij + " * P" + ij); !m.empty()) return m;
  }
  // Trim loops GLU would crash on (measured, GLU 9.0.2: SIGSEGV in
  // gluEndSurface for a polyline piece of 0 points, an open polyline loop of
  // 3 points, and a trim curve with decreasing knots or an empty domain, the
  // last two right after reporting NURBS error 3). The core's loop flattening
  // checks exactly these (pieces, curves, closure) and names the problem; the
  // curve pieces only need their end points here. Loops without pieces go to
  // GLU, which reports NURBS error 18 for them; everything else (orientation,
  // crossings, the domain) is GLU's to judge.
  const spline::TrimCurveFlattener ends = [](const BsplineCurve& c) {
    const spline::ParamInterval dom = spline::domain(c);
    const Vec3 a = spline::curve_point(c, dom.a), b = spline::curve_point(c, dom.b);
    return std::vector<Vec2>{{a.x, a.y}, {b.x, b.y}};
  };
  for (std::size_t l = 0; l < s.trims.size(); ++l) {
    if (s.trims[l].pieces.empty()) continue;
    try {
      spline::flatten_trim_loop(s.trims[l], ends, l);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what()) + " (not passed to GLU: it crashes on open loops and broken trim curves)";
    }
    for (const spline::TrimPiece& piece : s.trims[l].pieces)
      if (piece.curve)
        if (std::string m = curve_problem(*piece.curve, feed, "trim loop " + std::to_string(l) + ": "); !m.empty())
          return m;
  }
  return "";
}

// ---- GLU's arrays ---------------------------------------------------------------

std::vector<GLfloat> to_float(const std::vector<double>& values) { return {values.begin(), values.end()}; }

/// Control points as GLU takes them: x y z (polynomial) or x y z w with the
/// weights multiplied in (or not, for the mistake). dims 2 drops z (trims).
std::vector<GLfloat> control_array(const std::vector<Vec3>& P, const std::vector<double>& w, RationalFeed feed,
                                   int dims) {
  std::vector<GLfloat> out;
  out.reserve(P.size() * static_cast<std::size_t>(dims + 1));
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double wi = w.empty() ? 1.0 : w[i];
    const double m = (w.empty() || feed == RationalFeed::kMistakeNotPremultiplied) ? 1.0 : wi;
    out.push_back(GLfloat(m * P[i].x));
    out.push_back(GLfloat(m * P[i].y));
    if (dims == 3) out.push_back(GLfloat(m * P[i].z));
    if (!w.empty()) out.push_back(GLfloat(wi));
  }
  return out;
}

/// Greville abscissae as floats, or empty when the knots are too broken to
/// have any (GLU reports those itself).
std::vector<GLfloat> greville_floats(int p, const std::vector<double>& U) {
  if (p < 1 || U.size() < static_cast<std::size_t>(p) + 2) return {};
  return to_float(spline::greville_abscissae(p, U));
}

void feed_curve(GLUnurbs* nurbs, const BsplineCurve& c, RationalFeed feed, bool with_parameter) {
  std::vector<GLfloat> knots = to_float(c.U);
  std::vector<GLfloat> ctrl = control_array(c.P, c.w, feed, 3);
  const bool rational = c.rational();
  gluNurbsCurve(nurbs, GLint(knots.size()), knots.data(), rational ? 4 : 3, ctrl.data(), c.p + 1,
                rational ? GL_MAP1_VERTEX_4 : GL_MAP1_VERTEX_3);
  // The parameter map only for a curve GLU took: for a broken one it would
  // repeat GLU's error.
  if (!with_parameter || (t_call && !t_call->errors.empty())) return;
  std::vector<GLfloat> xi = greville_floats(c.p, c.U);
  if (xi.empty()) return;
  gluNurbsCurve(nurbs, GLint(knots.size()), knots.data(), 1, xi.data(), c.p + 1, GL_MAP1_TEXTURE_COORD_1);
}

void feed_trims(GLUnurbs* nurbs, const std::vector<spline::TrimLoop>& loops, RationalFeed feed) {
  for (const spline::TrimLoop& loop : loops) {
    gluBeginTrim(nurbs);
    for (const spline::TrimPiece& piece : loop.pieces) {
      if (piece.curve) {
        const BsplineCurve& c = *piece.curve;
        std::vector<GLfloat> knots = to_float(c.U);
        std::vector<GLfloat> ctrl = control_array(c.P, c.w, feed, 2);
        gluNurbsCurve(nurbs, GLint(knots.size()), knots.data(), c.rational() ? 3 : 2, ctrl.data(), c.p + 1,
                      c.rational() ? GLU_MAP1_TRIM_3 : GLU_MAP1_TRIM_2);
      } else {
        std::vector<GLfloat> pts;
        for (const Vec2& q : piece.polyline) pts.insert(pts.end(), {GLfloat(q.x), GLfloat(q.y)});
        gluPwlCurve(nurbs, GLint(piece.polyline.size()), pts.data(), 2, GLU_MAP1_TRIM_2);
      }
    }
    gluEndTrim(nurbs);
  }
}

void feed_surface(GLUnurbs* nurbs, const BsplineSurface& s, RationalFeed feed, bool with_parameter) {
  std::vector<GLfloat> u_knots = to_float(s.U), v_knots = to_float(s.V);
  std::vector<GLfloat> ctrl = control_array(s.P, s.w, feed, 3);
  const GLint dims = s.rational() ? 4 : 3;
  // s (GLU's first parameter) = u = row index i: P[i * nv + j] is at i * nv * dims + j * dims.
  gluNurbsSurface(nurbs, GLint(u_knots.size()), u_knots.data(), GLint(v_knots.size()), v_knots.data(), s.nv * dims,
                  dims, ctrl.data(), s.p + 1, s.q + 1, s.rational() ? GL_MAP2_VERTEX_4 : GL_MAP2_VERTEX_3);
  if (with_parameter && !(t_call && !t_call->errors.empty())) {
    const std::vector<GLfloat> xi = greville_floats(s.p, s.U), eta = greville_floats(s.q, s.V);
    if (!xi.empty() && !eta.empty()) {
      std::vector<GLfloat> uv;
      uv.reserve(xi.size() * eta.size() * 2);
      for (GLfloat a : xi)
        for (GLfloat b : eta) uv.insert(uv.end(), {a, b});
      gluNurbsSurface(nurbs, GLint(u_knots.size()), u_knots.data(), GLint(v_knots.size()), v_knots.data(),
                      GLint(eta.size()) * 2, 2, uv.data(), s.p + 1, s.q + 1, GL_MAP2_TEXTURE_COORD_2);
    }
  }
  feed_trims(nurbs, s.trims, feed);
}

// ---- capture: GLU's callbacks write here -------------------------------------------

struct Sink {
  bool curve = false;
  int curve_coords = 3;  // a curve's vertices: 3 floats, or 4 homogeneous (GL_MAP1_VERTEX_4)
  Vec3 normal;
  Vec2 uv;
  GLenum mode = 0;
  std::size_t first = 0;
  std::vector<Vec3> positions, normals;
  std::vector<Vec2> uvs;
  std::vector<GluPrimitive> primitives;
};

void GLAPIENTRY on_begin(GLenum mode, void* data) {
  if (!data) return;
  auto* sink = static_cast<Sink*>(data);
  sink->mode = mode;
  sink->first = sink->positions.size();
}

void GLAPIENTRY on_vertex(GLfloat* v, void* data) {
  if (!data) return;
  auto* sink = static_cast<Sink*>(data);
  if (sink->curve && sink->curve_coords == 4) {
    const double iw = 1.0 / double(v[3]);
    sink->positions.push_back({v[0] * iw, v[1] * iw, v[2] * iw});
  } else {
    sink->positions.push_back({v[0], v[1], v[2]});
  }
  sink->normals.push_back(sink->normal);
  sink->uvs.push_back(sink->uv);
}

void GLAPIENTRY on_normal(GLfloat* n, void* data) {
  if (data) static_cast<Sink*>(data)->normal = {n[0], n[1], n[2]};
}

void GLAPIENTRY on_texcoord(GLfloat* t, void* data) {
  if (!data) return;
  auto* sink = static_cast<Sink*>(data);
  sink->uv = sink->curve ? Vec2{t[0], 0} : Vec2{t[0], t[1]};
}

void GLAPIENTRY on_end(void* data) {
  if (!data) return;
  auto* sink = static_cast<Sink*>(data);
  sink->primitives.push_back({sink->mode, sink->first, sink->positions.size() - sink->first});
}

/// GLU's (u, v) come through a float texture map and land a few float ulps
/// outside the domain at its edges (measured: u = 1.0000000596 at u = 1),
/// where the core's evaluators refuse them: clamp them back. Only for a
/// surface whose knots give a domain at all (GLU rejected the others).
void clamp_to_domain(std::vector<Vec2>& uv, const BsplineSurface& s) {
  if (s.U.size() < static_cast<std::size_t>(2 * s.p + 2) || s.V.size() < static_cast<std::size_t>(2 * s.q + 2)) return;
  const double u0 = s.U[s.p], u1 = s.U[s.U.size() - 1 - s.p], v0 = s.V[s.q], v1 = s.V[s.V.size() - 1 - s.q];
  if (!(u0 <= u1 && v0 <= v1)) return;
  for (Vec2& q : uv) q = {std::clamp(q.x, u0, u1), std::clamp(q.y, v0, v1)};
}

bool is_line_mode(GLenum mode) {
  return mode == GL_LINES || mode == GL_LINE_STRIP || mode == GL_LINE_LOOP || mode == GL_POINTS;
}

/// The triangles of one primitive, GL's rules (OpenGL 2.1 spec §2.6.1):
/// strip triangle k is (k, k+1, k+2) with every odd one's first two swapped
/// back so all keep the first one's winding; fan and polygon (0, k+1, k+2);
/// quad strip quad k is (2k, 2k+1, 2k+3, 2k+2); quads (4k .. 4k+3).
void append_triangles(const GluPrimitive& p, std::vector<std::array<int, 3>>& out) {
  const int f = static_cast<int>(p.first);
  const int n = static_cast<int>(p.count);
  switch (p.mode) {
    case GL_TRIANGLES:
      for (int k = 0; k + 2 < n; k += 3) out.push_back({f + k, f + k + 1, f + k + 2});
      break;
    case GL_TRIANGLE_STRIP:
      for (int k = 0; k + 2 < n; ++k)
        out.push_back(k % 2 == 0 ? std::array<int, 3>{f + k, f + k + 1, f + k + 2}
                                 : std::array<int, 3>{f + k + 1, f + k, f + k + 2});
      break;
    case GL_TRIANGLE_FAN:
    case GL_POLYGON:
      for (int k = 1; k + 1 < n; ++k) out.push_back({f, f + k, f + k + 1});
      break;
    case GL_QUAD_STRIP:
      for (int k = 0; 2 * k + 3 < n; ++k) {
        const int a = f + 2 * k, b = a + 1, c = a + 3, d = a + 2;
        out.push_back({a, b, c});
        out.push_back({a, c, d});
      }
      break;
    case GL_QUADS:
      for (int k = 0; k + 3 < n; k += 4) {
        out.push_back({f + k, f + k + 1, f + k + 2});
        out.push_back({f + k, f + k + 2, f + k + 3});
      }
      break;
    default:
      break;
  }
}

CapturedPolyline polyline_of(const Sink& sink, const GluPrimitive& p, bool with_u) {
  CapturedPolyline line;
  line.closed = p.mode == GL_LINE_LOOP;
  for (std::size_t k = p.first; k < p.first + p.count; ++k) {
    line.points.push_back(sink.positions[k]);
    if (with_u) line.u.push_back(sink.uvs[k].x);
  }
  return line;
}

}  // namespace

bool gl_context_current() { return glGetString(GL_VERSION) != nullptr; }

SamplingMatrices SamplingMatrices::from_gl() {
  SamplingMatrices m;
  glGetFloatv(GL_MODELVIEW_MATRIX, m.modelview.data());
  glGetFloatv(GL_PROJECTION_MATRIX, m.projection.data());
  glGetIntegerv(GL_VIEWPORT, m.viewport.data());
  return m;
}

GluNurbsProperties GluNurbsProperties::of(GLUnurbs* nurb) {
  GluNurbsProperties p;
  const auto get = [nurb](GLenum property) {
    GLfloat v = 0;
    gluGetNurbsProperty(nurb, property, &v);
    return v;
  };
  p.sampling_method = static_cast<GLenum>(get(GLU_SAMPLING_METHOD));
  p.sampling_tolerance = get(GLU_SAMPLING_TOLERANCE);
  p.parametric_tolerance = get(GLU_PARAMETRIC_TOLERANCE);
  p.u_step = get(GLU_U_STEP);
  p.v_step = get(GLU_V_STEP);
  p.display_mode = static_cast<GLenum>(get(GLU_DISPLAY_MODE));
  p.culling = get(GLU_CULLING) != 0;
  p.auto_load_matrix = get(GLU_AUTO_LOAD_MATRIX) != 0;
  const bool object_space = p.sampling_method == GLU_OBJECT_PATH_LENGTH ||
                            p.sampling_method == GLU_OBJECT_PARAMETRIC_ERROR;
  if (object_space) p.auto_load_matrix = false;
  if (!p.auto_load_matrix && !object_space && gl_context_current()) p.sampling_matrices = SamplingMatrices::from_gl();
  return p;
}

std::size_t CurveCapture::vertex_count() const {
  std::size_t n = 0;
  for (const GluPrimitive& p : primitives) n += p.count;
  return n;
}

std::size_t SurfaceCapture::count(GLenum mode) const {
  std::size_t n = 0;
  for (const GluPrimitive& p : primitives) n += p.mode == mode;
  return n;
}

// ---- the object -------------------------------------------------------------------

GluNurbs::GluNurbs(const GluNurbsProperties& properties) {
  CallScope call("gluNewNurbsRenderer");
  nurbs_ = gluNewNurbsRenderer();
  if (!nurbs_) {
    call.refuse("returned null (out of memory)");
    call.finish();
    return;
  }
  gluNurbsCallback(nurbs_, GLU_NURBS_ERROR, reinterpret_cast<_GLUfuncptr>(on_glu_error));
  // The tessellator's callbacks: used only in capture mode, where
  // gluNurbsCallbackData points them at a Sink (null otherwise: they return).
  gluNurbsCallback(nurbs_, GLU_NURBS_BEGIN_DATA, reinterpret_cast<_GLUfuncptr>(on_begin));
  gluNurbsCallback(nurbs_, GLU_NURBS_VERTEX_DATA, reinterpret_cast<_GLUfuncptr>(on_vertex));
  // A normal callback makes GLU compute surface normals in tessellator mode.
  gluNurbsCallback(nurbs_, GLU_NURBS_NORMAL_DATA, reinterpret_cast<_GLUfuncptr>(on_normal));
  gluNurbsCallback(nurbs_, GLU_NURBS_TEXTURE_COORD_DATA, reinterpret_cast<_GLUfuncptr>(on_texcoord));
  gluNurbsCallback(nurbs_, GLU_NURBS_END_DATA, reinterpret_cast<_GLUfuncptr>(on_end));
  gluNurbsCallbackData(nurbs_, nullptr);
  call.finish();
  // GLU's defaults are what a new object has; apply the caller's.
  properties_ = GluNurbsProperties{};
  set(properties);
}

GluNurbs::~GluNurbs() {
  if (nurbs_) gluDeleteNurbsRenderer(nurbs_);
}

GluNurbs::GluNurbs(GluNurbs&& other) noexcept
    : nurbs_(std::exchange(other.nurbs_, nullptr)), properties_(std::move(other.properties_)) {}

GluNurbs& GluNurbs::operator=(GluNurbs&& other) noexcept {
  if (this != &other) {
    if (nurbs_) gluDeleteNurbsRenderer(nurbs_);
    nurbs_ = std::exchange(other.nurbs_, nullptr);
    properties_ = std::move(other.properties_);
  }
  return *this;
}

const GluNurbsProperties& GluNurbs::properties() const { return properties_; }

bool GluNurbs::set(const GluNurbsProperties& wanted) {
  CallScope call("gluNurbsProperty");
  GluNurbsProperties p = wanted;
  const bool object_space = samples_in_object_space(p.sampling_method);
  if (object_space) p.auto_load_matrix = false;  // what GLU does (see the header)
  const auto positive = [&](float v, const char* name) {
    if (!(std::isfinite(v) && v > 0)) call.refuse(std::string(name) + "=" + num(v) + " must be > 0 and finite");
  };
  if (!nurbs_) {
    call.refuse("no GLU NURBS object (moved from, or gluNewNurbsRenderer failed)");
  } else if (!known_method(p.sampling_method)) {
    call.refuse("sampling_method=" + glu_enum_name(p.sampling_method) +
                " is not GLU_PATH_LENGTH, GLU_PARAMETRIC_ERROR, GLU_DOMAIN_DISTANCE, GLU_OBJECT_PATH_LENGTH or "
                "GLU_OBJECT_PARAMETRIC_ERROR");
  } else if (!known_display_mode(p.display_mode)) {
    call.refuse("display_mode=" + glu_enum_name(p.display_mode) +
                " is not GLU_FILL, GLU_OUTLINE_POLYGON or GLU_OUTLINE_PATCH");
  } else {
    positive(p.sampling_tolerance, "sampling_tolerance");
    positive(p.parametric_tolerance, "parametric_tolerance");
    positive(p.u_step, "u_step");
    positive(p.v_step, "v_step");
    if (!call.failed()) {
      const std::string method = glu_enum_name(p.sampling_method);
      if (object_space && p.culling)
        call.refuse("culling with " + method + ": object-space methods run without matrices, so GLU has no "
                    "view volume to cull against");
      else if (object_space && p.sampling_matrices)
        call.refuse("sampling_matrices with " + method + ": object-space methods take no matrices");
      else if (p.auto_load_matrix && p.sampling_matrices)
        call.refuse("sampling_matrices given while auto_load_matrix is on (GLU would ignore them)");
      else if (!object_space && !p.auto_load_matrix && !p.sampling_matrices &&
               (samples_in_screen_space(p.sampling_method) || p.culling))
        call.refuse("auto_load_matrix is off but no sampling_matrices are given (" +
                    std::string(p.culling ? "culling" : method) + " needs them)");
    }
  }
  if (call.failed()) {
    call.finish();
    return false;
  }
  gluNurbsProperty(nurbs_, GLU_SAMPLING_METHOD, GLfloat(p.sampling_method));
  gluNurbsProperty(nurbs_, GLU_SAMPLING_TOLERANCE, p.sampling_tolerance);
  gluNurbsProperty(nurbs_, GLU_PARAMETRIC_TOLERANCE, p.parametric_tolerance);
  gluNurbsProperty(nurbs_, GLU_U_STEP, p.u_step);
  gluNurbsProperty(nurbs_, GLU_V_STEP, p.v_step);
  gluNurbsProperty(nurbs_, GLU_DISPLAY_MODE, GLfloat(p.display_mode));
  gluNurbsProperty(nurbs_, GLU_CULLING, p.culling ? GL_TRUE : GL_FALSE);
  if (!object_space) gluNurbsProperty(nurbs_, GLU_AUTO_LOAD_MATRIX, p.auto_load_matrix ? GL_TRUE : GL_FALSE);
  if (p.sampling_matrices)
    gluLoadSamplingMatrices(nurbs_, p.sampling_matrices->modelview.data(), p.sampling_matrices->projection.data(),
                            p.sampling_matrices->viewport.data());
  properties_ = p;
  return call.finish().empty();
}

namespace {

/// The checks every draw and capture makes before GLU sees the data.
void check_object_and_context(CallScope& call, GLUnurbs* nurbs, const GluNurbsProperties& p, bool drawing) {
  if (!nurbs) return call.refuse("no GLU NURBS object (moved from, or gluNewNurbsRenderer failed)");
  if (drawing && !gl_context_current())
    return call.refuse("no GL context is current (drawing needs one; capture works without for " +
                       glu_enum_name(GLU_DOMAIN_DISTANCE) + " and the object-space methods)");
  if (!drawing && p.auto_load_matrix && (samples_in_screen_space(p.sampling_method) || p.culling) &&
      !gl_context_current())
    call.refuse((p.culling ? std::string("culling") : glu_enum_name(p.sampling_method)) +
                " samples in screen space and no GL context is current: GLU would read matrices that are not "
                "there and return wrong vertices without an error (use GLU_DOMAIN_DISTANCE or an object-space "
                "method, or auto_load_matrix = false with sampling_matrices)");
}

/// In capture mode GLU still calls glEnable for the curve's maps
/// (GL_MAP1_VERTEX_3 / _4, GL_MAP1_TEXTURE_COORD_1) when a context is
/// current, and leaves them enabled (measured, GLU 9.0.2; its rendering mode
/// restores them). A map left on wins over the next curve's: after one
/// rational capture, GLU drew the next polynomial curve with the old
/// GL_MAP1_VERTEX_4 map. So captures save and restore the evaluator enables
/// (GL_EVAL_BIT). The maps' control points GLU may have loaded stay, disabled.
class EvalStateGuard {
 public:
  EvalStateGuard() : active_(gl_context_current()) {
    if (active_) glPushAttrib(GL_EVAL_BIT);
  }
  ~EvalStateGuard() {
    if (active_) glPopAttrib();
  }
  EvalStateGuard(const EvalStateGuard&) = delete;
  EvalStateGuard& operator=(const EvalStateGuard&) = delete;

 private:
  bool active_;
};

/// GLU 9.0.2 leaks on the path of its lost errors (glu_errors.cpp, "errors
/// GLU finds and then loses"): the jump skips the frames that own what the
/// tessellation allocated. Measured with LeakSanitizer: 34,712 bytes from
/// operator new and ~1 KB from malloc in libGLU.so for each clockwise outer
/// loop, with gluDeleteNurbsRenderer called; nothing for a valid trim. A
/// suppression cannot name the frames (libGLU.so has no symbols) and would
/// hide every GLU leak. So in a sanitizer build, and only around
/// gluEndSurface of a surface whose trim loops the core rejects (the inputs
/// GLU answers with error 28 or 31), LeakSanitizer does not track GLU's
/// allocations (__lsan_disable: this thread, this call). Every other call,
/// and all of gllab, stays leak-checked; .ci/lsan.supp names OSMesa only.
/// (A lab's own gluEndSurface cannot be wrapped like this: glu_errors.cpp.)
class GluErrorPathLeakExemption {
 public:
  explicit GluErrorPathLeakExemption(const BsplineSurface& s) {
#if defined(GLLAB_ASAN)
    if (s.trims.empty()) return;
    try {
      spline::validate_trim_loops(s.trims, spline::uv_domain(s));
    } catch (const std::invalid_argument&) {
      __lsan_disable();
      active_ = true;
    }
#else
    (void)s;
#endif
  }
  ~GluErrorPathLeakExemption() {
#if defined(GLLAB_ASAN)
    if (active_) __lsan_enable();
#endif
  }
  GluErrorPathLeakExemption(const GluErrorPathLeakExemption&) = delete;
  GluErrorPathLeakExemption& operator=(const GluErrorPathLeakExemption&) = delete;

 private:
  [[maybe_unused]] bool active_ = false;  // read only in a sanitizer build
};

}  // namespace

std::vector<GluError> GluNurbs::draw_curve(const BsplineCurve& curve, const std::string& name, RationalFeed feed) {
  CallScope call("gluNurbsCurve (" + name + ")");
  check_object_and_context(call, nurbs_, properties_, true);
  if (!call.failed())
    if (std::string problem = curve_problem(curve, feed); !problem.empty()) call.refuse(problem);
  if (call.failed()) return call.finish();
  gluNurbsProperty(nurbs_, GLU_NURBS_MODE, GLU_NURBS_RENDERER);
  gluBeginCurve(nurbs_);
  feed_curve(nurbs_, curve, feed, false);
  gluEndCurve(nurbs_);
  return call.finish();
}

std::vector<GluError> GluNurbs::draw_surface(const BsplineSurface& surface, const std::string& name,
                                             RationalFeed feed) {
  CallScope call("gluNurbsSurface (" + name + ")");
  check_object_and_context(call, nurbs_, properties_, true);
  if (!call.failed())
    if (std::string problem = surface_problem(surface, feed); !problem.empty()) call.refuse(problem);
  if (call.failed()) return call.finish();
  gluNurbsProperty(nurbs_, GLU_NURBS_MODE, GLU_NURBS_RENDERER);
  const GluErrorPathLeakExemption exemption(surface);
  gluBeginSurface(nurbs_);
  feed_surface(nurbs_, surface, feed, false);
  gluEndSurface(nurbs_);
  return call.finish();
}

CurveCapture GluNurbs::capture_curve(const BsplineCurve& curve, const std::string& name, RationalFeed feed) {
  CurveCapture out;
  CallScope call("gluNurbsCurve (" + name + ")");
  check_object_and_context(call, nurbs_, properties_, false);
  if (!call.failed())
    if (std::string problem = curve_problem(curve, feed); !problem.empty()) call.refuse(problem);
  if (call.failed()) {
    out.errors = call.finish();
    return out;
  }
  Sink sink;
  sink.curve = true;
  sink.curve_coords = curve.rational() ? 4 : 3;
  const EvalStateGuard guard;
  gluNurbsProperty(nurbs_, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
  gluNurbsCallbackData(nurbs_, &sink);
  gluBeginCurve(nurbs_);
  feed_curve(nurbs_, curve, feed, true);
  gluEndCurve(nurbs_);
  gluNurbsCallbackData(nurbs_, nullptr);
  gluNurbsProperty(nurbs_, GLU_NURBS_MODE, GLU_NURBS_RENDERER);
  out.primitives = sink.primitives;
  for (const GluPrimitive& p : sink.primitives)
    if (is_line_mode(p.mode)) out.polylines.push_back(polyline_of(sink, p, true));
  // The parameter comes through a float map too (see clamp_to_domain).
  if (curve.U.size() >= static_cast<std::size_t>(2 * curve.p + 2)) {
    const double a = curve.U[curve.p], b = curve.U[curve.U.size() - 1 - curve.p];
    if (a <= b)
      for (CapturedPolyline& line : out.polylines)
        for (double& u : line.u) u = std::clamp(u, a, b);
  }
  out.errors = call.finish();
  return out;
}

SurfaceCapture GluNurbs::capture_surface(const BsplineSurface& surface, const std::string& name,
                                         RationalFeed feed) {
  SurfaceCapture out;
  CallScope call("gluNurbsSurface (" + name + ")");
  check_object_and_context(call, nurbs_, properties_, false);
  if (!call.failed())
    if (std::string problem = surface_problem(surface, feed); !problem.empty()) call.refuse(problem);
  if (call.failed()) {
    out.errors = call.finish();
    return out;
  }
  Sink sink;
  const EvalStateGuard guard;
  gluNurbsProperty(nurbs_, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
  gluNurbsCallbackData(nurbs_, &sink);
  const GluErrorPathLeakExemption exemption(surface);
  gluBeginSurface(nurbs_);
  feed_surface(nurbs_, surface, feed, true);
  gluEndSurface(nurbs_);
  gluNurbsCallbackData(nurbs_, nullptr);
  gluNurbsProperty(nurbs_, GLU_NURBS_MODE, GLU_NURBS_RENDERER);
  out.primitives = sink.primitives;
  out.mesh.positions = std::move(sink.positions);
  out.mesh.normals = std::move(sink.normals);
  out.mesh.uv = std::move(sink.uvs);
  clamp_to_domain(out.mesh.uv, surface);
  for (const GluPrimitive& p : out.primitives) {
    if (is_line_mode(p.mode)) {
      CapturedPolyline line;
      line.closed = p.mode == GL_LINE_LOOP;
      line.points.assign(out.mesh.positions.begin() + static_cast<std::ptrdiff_t>(p.first),
                         out.mesh.positions.begin() + static_cast<std::ptrdiff_t>(p.first + p.count));
      out.lines.push_back(std::move(line));
    } else {
      append_triangles(p, out.mesh.triangles);
    }
  }
  out.errors = call.finish();
  return out;
}

}  // namespace gllab
