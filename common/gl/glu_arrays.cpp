// common/gl/glu_arrays.cpp — see glu_arrays.h.
#include "gl/glu_arrays.h"

#include <stdexcept>
#include <string>

#include "gl/glu_nurbs.h"
#include "spline/bspline.h"
#include "spline/surface.h"

namespace gllab {

namespace {

[[noreturn]] void refuse(const std::string& call, const std::string& why) {
  throw std::invalid_argument(call + ": " + why);
}

// Coordinates per point of a GLU map type, and whether the last is a weight.
struct Layout {
  int coords;
  bool rational;
  bool trim;  // (u, v) only: z = 0
};

Layout layout_of(GLenum type, const std::string& call) {
  switch (type) {
    case GL_MAP1_VERTEX_3: return {3, false, false};
    case GL_MAP1_VERTEX_4: return {4, true, false};
    case GLU_MAP1_TRIM_2: return {2, false, true};
    case GLU_MAP1_TRIM_3: return {3, true, true};
    case GL_MAP2_VERTEX_3: return {3, false, false};
    case GL_MAP2_VERTEX_4: return {4, true, false};
    default: break;
  }
  refuse(call, "type " + glu_enum_name(type) +
                   " is not GL_MAP1_VERTEX_3/4, GLU_MAP1_TRIM_2/3 or GL_MAP2_VERTEX_3/4");
}

// Point k of an array with this layout, divided by its weight if rational.
spline::Vec3 point_at(const GLfloat* p, Layout l, double* weight) {
  const double w = l.rational ? p[l.coords - 1] : 1.0;
  if (weight) *weight = w;
  const double x = p[0], y = p[1], z = l.trim ? 0.0 : p[2];
  return l.rational ? spline::Vec3{x / w, y / w, z / w} : spline::Vec3{x, y, z};
}

void check_counts(const std::string& call, GLint knot_count, GLint order, GLint stride, Layout l,
                  const char* knots_name, const char* stride_name) {
  if (order < 1) refuse(call, "order " + std::to_string(order) + " must be >= 1");
  if (knot_count < 2 * order)
    refuse(call, std::string(knots_name) + " " + std::to_string(knot_count) + " < 2 x order " +
                     std::to_string(order) + " (at least order control points)");
  if (stride < l.coords)
    refuse(call, std::string(stride_name) + " " + std::to_string(stride) + " is shorter than one point (" +
                     std::to_string(l.coords) + " floats)");
}

std::vector<double> knot_vector(GLint count, const GLfloat* knots) { return {knots, knots + count}; }

}  // namespace

std::vector<GLfloat> glu_points(const std::vector<spline::Vec3>& points, int coords) {
  if (coords != 2 && coords != 3) refuse("glu_points", "coords " + std::to_string(coords) + " is not 2 or 3");
  std::vector<GLfloat> out;
  for (const spline::Vec3& p : points) {
    out.insert(out.end(), {GLfloat(p.x), GLfloat(p.y)});
    if (coords == 3) out.push_back(GLfloat(p.z));
  }
  return out;
}

std::vector<GLfloat> densified_pwl(const std::vector<spline::Vec2>& p, int per_edge) {
  if (p.size() < 2) refuse("densified_pwl", std::to_string(p.size()) + " points (a polyline needs 2)");
  if (per_edge < 1) refuse("densified_pwl", "per_edge " + std::to_string(per_edge) + " must be >= 1");
  std::vector<GLfloat> out;
  for (std::size_t k = 0; k + 1 < p.size(); ++k)
    for (int i = 0; i < per_edge; ++i) {
      const spline::Vec2 q = p[k] + (double(i) / per_edge) * (p[k + 1] - p[k]);
      out.insert(out.end(), {GLfloat(q.x), GLfloat(q.y)});
    }
  out.insert(out.end(), {GLfloat(p.back().x), GLfloat(p.back().y)});
  return out;
}

spline::BsplineCurve core_curve(GLint knot_count, const GLfloat* knots, GLint stride, const GLfloat* ctl,
                                GLint order, GLenum type) {
  const std::string call = "gluNurbsCurve";
  const Layout l = layout_of(type, call);
  if (type == GL_MAP2_VERTEX_3 || type == GL_MAP2_VERTEX_4) refuse(call, "a surface type: use core_surface");
  check_counts(call, knot_count, order, stride, l, "knot_count", "stride");
  spline::BsplineCurve c;
  c.p = order - 1;
  c.U = knot_vector(knot_count, knots);
  c.dimension = l.trim ? 2 : 3;
  for (GLint i = 0; i < knot_count - order; ++i) {
    double w = 1;
    c.P.push_back(point_at(ctl + i * stride, l, &w));
    if (l.rational) c.w.push_back(w);
  }
  spline::validate(c);
  return c;
}

spline::TrimPiece core_trim_curve(GLint knot_count, const GLfloat* knots, GLint stride, const GLfloat* ctl,
                                  GLint order, GLenum type) {
  if (type != GLU_MAP1_TRIM_2 && type != GLU_MAP1_TRIM_3)
    refuse("gluNurbsCurve", "a trim curve takes GLU_MAP1_TRIM_2 or GLU_MAP1_TRIM_3, not " + glu_enum_name(type));
  return {{}, core_curve(knot_count, knots, stride, ctl, order, type)};
}

spline::TrimPiece core_pwl(GLint count, const GLfloat* array, GLint stride, GLenum type) {
  const std::string call = "gluPwlCurve";
  if (type != GLU_MAP1_TRIM_2 && type != GLU_MAP1_TRIM_3)
    refuse(call, "type " + glu_enum_name(type) + " is not GLU_MAP1_TRIM_2 or GLU_MAP1_TRIM_3");
  const Layout l = layout_of(type, call);
  if (count < 2) refuse(call, "count " + std::to_string(count) + " < 2 (a polyline needs 2 points)");
  if (stride < l.coords)
    refuse(call, "stride " + std::to_string(stride) + " is shorter than one point (" + std::to_string(l.coords) +
                     " floats)");
  spline::TrimPiece piece;
  for (GLint i = 0; i < count; ++i) {
    const spline::Vec3 p = point_at(array + i * stride, l, nullptr);
    piece.polyline.push_back({p.x, p.y});
  }
  return piece;
}

std::vector<spline::TrimLoop> core_trims(const std::vector<GluTrimLoop>& loops) {
  std::vector<spline::TrimLoop> out;
  for (const GluTrimLoop& loop : loops) {
    out.emplace_back();
    for (const GluTrimPiece& p : loop)
      out.back().pieces.push_back(
          p.knots ? core_trim_curve(p.count() + p.order, p.knots, p.stride, p.points.data(), p.order, p.type)
                  : core_pwl(p.count(), p.points.data(), p.stride, p.type));
  }
  return out;
}

spline::BsplineSurface core_surface(GLint s_knot_count, const GLfloat* s_knots, GLint t_knot_count,
                                    const GLfloat* t_knots, GLint s_stride, GLint t_stride, const GLfloat* ctl,
                                    GLint s_order, GLint t_order, GLenum type) {
  const std::string call = "gluNurbsSurface";
  if (type != GL_MAP2_VERTEX_3 && type != GL_MAP2_VERTEX_4)
    refuse(call, "type " + glu_enum_name(type) + " is not GL_MAP2_VERTEX_3 or GL_MAP2_VERTEX_4");
  const Layout l = layout_of(type, call);
  check_counts(call, s_knot_count, s_order, s_stride, l, "s_knot_count", "s_stride");
  check_counts(call, t_knot_count, t_order, t_stride, l, "t_knot_count", "t_stride");
  spline::BsplineSurface S;
  S.p = s_order - 1;
  S.q = t_order - 1;
  S.U = knot_vector(s_knot_count, s_knots);
  S.V = knot_vector(t_knot_count, t_knots);
  S.nu = s_knot_count - s_order;
  S.nv = t_knot_count - t_order;
  for (int i = 0; i < S.nu; ++i)
    for (int j = 0; j < S.nv; ++j) {
      double w = 1;
      S.P.push_back(point_at(ctl + i * s_stride + j * t_stride, l, &w));
      if (l.rational) S.w.push_back(w);
    }
  spline::validate(S);
  return S;
}

}  // namespace gllab
