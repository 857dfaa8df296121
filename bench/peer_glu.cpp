// bench/peer_glu.cpp — GLU NURBS in tessellator mode, no GL context (see peers.h).
//
// docs/glu.md: GLU_NURBS_TESSELLATOR with GLU_DOMAIN_DISTANCE works without a
// context and returns vertices and normals through callbacks; rational points
// are premultiplied; callbacks are GLAPIENTRY and cast with (_GLUfuncptr).
#include <GL/gl.h>
#include <GL/glu.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "peers.h"

namespace gllab::bench {

using spline::Vec3;
using spline::Vec4;

namespace {

// Where the callbacks write. The timed runs write into vectors sized by the
// calibration (no allocation while timing); a vertex past the end is counted
// but not stored.
struct Sink {
  std::size_t count = 0;
  Points* points = nullptr;
  Points* normals = nullptr;
  std::vector<double>* u = nullptr;
  std::vector<double>* v = nullptr;
};

// Surface vertices arrive projected (x, y, z).
void GLAPIENTRY on_vertex(GLfloat* p, void* data) {
  auto* sink = static_cast<Sink*>(data);
  if (sink->points && sink->count < sink->points->size()) (*sink->points)[sink->count] = {p[0], p[1], p[2]};
  ++sink->count;
}

// Curve vertices of a GL_MAP1_VERTEX_4 map arrive homogeneous, (w x, w y, w z, w),
// as glVertex4fv would take them (measured with GLU 9.0.2): project here.
void GLAPIENTRY on_curve_vertex(GLfloat* p, void* data) {
  auto* sink = static_cast<Sink*>(data);
  if (sink->points && sink->count < sink->points->size()) {
    const double iw = 1.0 / p[3];
    (*sink->points)[sink->count] = {p[0] * iw, p[1] * iw, p[2] * iw};
  }
  ++sink->count;
}

// Normals and texture coordinates arrive before the vertex they belong to.
void GLAPIENTRY on_normal(GLfloat* n, void* data) {
  auto* sink = static_cast<Sink*>(data);
  if (sink->normals && sink->count < sink->normals->size()) (*sink->normals)[sink->count] = {n[0], n[1], n[2]};
}

void GLAPIENTRY on_texcoord(GLfloat* t, void* data) {
  auto* sink = static_cast<Sink*>(data);
  if (sink->u && sink->count < sink->u->size()) (*sink->u)[sink->count] = t[0];
  if (sink->v && sink->count < sink->v->size()) (*sink->v)[sink->count] = t[1];
}

// GLU's error callback has no user data: keep the first error here.
GLenum g_glu_error = 0;
void GLAPIENTRY on_error(GLenum code) {
  if (g_glu_error == 0) g_glu_error = code;
}

void throw_if_glu_error(const char* what) {
  if (g_glu_error == 0) return;
  const GLenum code = std::exchange(g_glu_error, 0);
  throw std::runtime_error(std::string("GLU ") + what + ": NURBS error " + std::to_string(code) + " (" +
                           reinterpret_cast<const char*>(gluErrorString(code)) + ")");
}

std::vector<GLfloat> to_float(const std::vector<double>& values) { return {values.begin(), values.end()}; }

std::vector<GLfloat> to_float(const std::vector<Vec4>& Pw) {
  std::vector<GLfloat> out;
  for (const Vec4& h : Pw) out.insert(out.end(), {GLfloat(h.x), GLfloat(h.y), GLfloat(h.z), GLfloat(h.w)});
  return out;
}

// Greville abscissae xi_i = (U[i+1] + ... + U[i+p]) / p: a polynomial B-spline
// with these control values is the parameter itself (linear precision), so
// GLU's texture-coordinate output tells the (u, v) of each vertex.
std::vector<GLfloat> greville(int p, const std::vector<double>& U, int count) {
  std::vector<GLfloat> xi;
  for (int i = 0; i < count; ++i) {
    double sum = 0;
    for (int k = 1; k <= p; ++k) sum += U[static_cast<std::size_t>(i + k)];
    xi.push_back(GLfloat(sum / p));
  }
  return xi;
}

}  // namespace

struct GluPeer::Impl {
  GLUnurbs* nurbs = nullptr;
  // Curve in GLU's form.
  int curve_order = 0, curve_count = 0;
  std::vector<GLfloat> curve_knots, curve_ctrl, curve_xi;
  // Surface in GLU's form: s = u (first index), t = v.
  int s_order = 0, t_order = 0, nu = 0, nv = 0;
  std::vector<GLfloat> u_knots, v_knots, surface_ctrl, surface_uv;
  double curve_step = 0, surface_step = 0;
  std::size_t surface_distinct = 0;

  void set_step(double step) {
    gluNurbsProperty(nurbs, GLU_U_STEP, GLfloat(step));
    gluNurbsProperty(nurbs, GLU_V_STEP, GLfloat(step));
  }

  std::size_t tessellate_curve(Sink& sink, bool with_parameter) {
    gluNurbsCallback(nurbs, GLU_NURBS_VERTEX_DATA, (_GLUfuncptr)on_curve_vertex);
    gluNurbsCallbackData(nurbs, &sink);
    gluBeginCurve(nurbs);
    gluNurbsCurve(nurbs, GLint(curve_knots.size()), curve_knots.data(), 4, curve_ctrl.data(), curve_order,
                  GL_MAP1_VERTEX_4);
    if (with_parameter)
      gluNurbsCurve(nurbs, GLint(curve_knots.size()), curve_knots.data(), 1, curve_xi.data(), curve_order,
                    GL_MAP1_TEXTURE_COORD_1);
    gluEndCurve(nurbs);
    throw_if_glu_error("curve");
    return sink.count;
  }

  std::size_t tessellate_surface(Sink& sink, bool with_parameter) {
    gluNurbsCallback(nurbs, GLU_NURBS_VERTEX_DATA, (_GLUfuncptr)on_vertex);
    gluNurbsCallbackData(nurbs, &sink);
    gluBeginSurface(nurbs);
    gluNurbsSurface(nurbs, GLint(u_knots.size()), u_knots.data(), GLint(v_knots.size()), v_knots.data(), nv * 4, 4,
                    surface_ctrl.data(), s_order, t_order, GL_MAP2_VERTEX_4);
    if (with_parameter)
      gluNurbsSurface(nurbs, GLint(u_knots.size()), u_knots.data(), GLint(v_knots.size()), v_knots.data(), nv * 2,
                      2, surface_uv.data(), s_order, t_order, GL_MAP2_TEXTURE_COORD_2);
    gluEndSurface(nurbs);
    throw_if_glu_error("surface");
    return sink.count;
  }

  // The step (points per unit parameter) whose vertex count is closest to
  // target. The count grows with the step, so bisect.
  template <class Count>
  double calibrate(std::size_t target, Count count_at) {
    double lo = 1, hi = 2;
    while (count_at(hi) < target) {
      if ((hi *= 2) > 1e9)
        throw std::runtime_error("GLU returns fewer than " + std::to_string(target) + " vertices at any step");
    }
    for (int k = 0; k < 40 && hi - lo > 1e-3; ++k) {
      const double mid = 0.5 * (lo + hi);
      (count_at(mid) < target ? lo : hi) = mid;
    }
    const auto miss = [&](double step) {
      const std::size_t n = count_at(step);
      return n > target ? n - target : target - n;
    };
    const double best = miss(lo) < miss(hi) ? lo : hi;
    count_at(best);  // leave the renderer at the chosen step
    return best;
  }
};

GluPeer::GluPeer(const BenchData& data) : impl_(std::make_unique<Impl>()) {
  Impl& g = *impl_;
  g.nurbs = gluNewNurbsRenderer();
  if (!g.nurbs) throw std::runtime_error("GLU: gluNewNurbsRenderer returned null");
  gluNurbsProperty(g.nurbs, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
  gluNurbsProperty(g.nurbs, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(g.nurbs, GLU_DISPLAY_MODE, GLU_FILL);
  gluNurbsCallback(g.nurbs, GLU_NURBS_ERROR, (_GLUfuncptr)on_error);
  gluNurbsCallback(g.nurbs, GLU_NURBS_TEXTURE_COORD_DATA, (_GLUfuncptr)on_texcoord);
  // A normal callback makes GLU compute surface normals (GL_AUTO_NORMAL
  // cannot be asked without a context; GLU's tessellator uses the callback).
  gluNurbsCallback(g.nurbs, GLU_NURBS_NORMAL_DATA, (_GLUfuncptr)on_normal);

  const auto& c = data.curve;
  g.curve_order = c.p + 1;
  g.curve_count = int(c.P.size());
  g.curve_knots = to_float(c.U);
  g.curve_ctrl = to_float(curve_homogeneous(c));
  g.curve_xi = greville(c.p, c.U, g.curve_count);

  const auto& s = data.surface;
  g.s_order = s.p + 1;
  g.t_order = s.q + 1;
  g.nu = s.nu;
  g.nv = s.nv;
  g.u_knots = to_float(s.U);
  g.v_knots = to_float(s.V);
  g.surface_ctrl = to_float(surface_homogeneous(s));
  const std::vector<GLfloat> xi = greville(s.p, s.U, s.nu), eta = greville(s.q, s.V, s.nv);
  for (int i = 0; i < s.nu; ++i)
    for (int j = 0; j < s.nv; ++j) g.surface_uv.insert(g.surface_uv.end(), {xi[std::size_t(i)], eta[std::size_t(j)]});

  g.curve_step = g.calibrate(data.curve_u.size(), [&](double step) {
    g.set_step(step);
    Sink sink;
    return g.tessellate_curve(sink, false);
  });
  g.surface_step = g.calibrate(data.grid_u.size() * data.grid_v.size(), [&](double step) {
    g.set_step(step);
    Sink sink;
    return g.tessellate_surface(sink, false);
  });
}

GluPeer::~GluPeer() {
  if (impl_ && impl_->nurbs) gluDeleteNurbsRenderer(impl_->nurbs);
}

std::size_t GluPeer::curve_points(Points& out) {
  impl_->set_step(impl_->curve_step);
  Sink sink;
  sink.points = &out;
  return impl_->tessellate_curve(sink, false);
}

std::size_t GluPeer::surface_normals(Points& out, Points& normals) {
  impl_->set_step(impl_->surface_step);
  Sink sink;
  sink.points = &out;
  sink.normals = &normals;
  return impl_->tessellate_surface(sink, false);
}

GluPeer::Samples GluPeer::curve_samples() {
  impl_->set_step(impl_->curve_step);
  Samples samples;
  Sink counter;
  const std::size_t n = impl_->tessellate_curve(counter, true);
  samples.points.resize(n);
  samples.u.resize(n);
  Sink sink;
  sink.points = &samples.points;
  sink.u = &samples.u;
  impl_->tessellate_curve(sink, true);
  return samples;
}

GluPeer::Samples GluPeer::surface_samples() {
  impl_->set_step(impl_->surface_step);
  Samples samples;
  Sink counter;
  const std::size_t n = impl_->tessellate_surface(counter, true);
  samples.points.resize(n);
  samples.normals.resize(n);
  samples.u.resize(n);
  samples.v.resize(n);
  Sink sink;
  sink.points = &samples.points;
  sink.normals = &samples.normals;
  sink.u = &samples.u;
  sink.v = &samples.v;
  impl_->tessellate_surface(sink, true);

  std::vector<std::pair<double, double>> uv;
  for (std::size_t k = 0; k < n; ++k) uv.emplace_back(samples.u[k], samples.v[k]);
  std::sort(uv.begin(), uv.end());
  impl_->surface_distinct = std::size_t(std::unique(uv.begin(), uv.end()) - uv.begin());
  return samples;
}

double GluPeer::curve_step() const { return impl_->curve_step; }
double GluPeer::surface_step() const { return impl_->surface_step; }
std::size_t GluPeer::surface_distinct() const { return impl_->surface_distinct; }

}  // namespace gllab::bench
