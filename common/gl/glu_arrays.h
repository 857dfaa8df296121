// common/gl/glu_arrays.h — the spline core reads the arrays a lab hands GLU.
//
// A NURBS lab writes its GLU calls with plain arrays, as the Red Book's
// surface.c and trim.c do:
//
//   gluNurbsSurface(nurb, 8, knots, 8, knots, 4 * 3, 3, &ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
//
// and compares GLU's picture with the own core's on the same data. Each
// function here takes exactly the arguments of one GLU call and returns the
// core's object for them, so the lab converts with the same line it draws with:
//
//   const spline::BsplineSurface S =
//       gllab::core_surface(8, knots, 8, knots, 4 * 3, 3, &ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
//
// Rational types (GL_MAP1_VERTEX_4, GL_MAP2_VERTEX_4, GLU_MAP1_TRIM_3) come
// premultiplied, (w x, w y, w z, w), as GLU takes them; the core stores
// (x, y, z) and w, so the points are divided by w here. Counts that do not fit
// (fewer knots than an order needs, a stride shorter than a point) throw
// std::invalid_argument naming the values, as the core does.
#pragma once

#include <vector>

#include "gl/gl.h"
#include "spline/types.h"

namespace gllab {

/// Points as GLU's control arrays hold them: x, y, z per point (coords 3),
/// or x, y (coords 2, a trim curve's (u, v)), in float. A lab's dragged
/// points (State::points) go to gluNurbsSurface this way.
std::vector<GLfloat> glu_points(const std::vector<spline::Vec3>& points, int coords = 3);

/// gluNurbsCurve(nurb, knot_count, knots, stride, ctl, order, type) for
/// type GL_MAP1_VERTEX_3 / _4 (a 3D curve) or GLU_MAP1_TRIM_2 / _3 (a 2D
/// trim curve in (u, v), z = 0): degree order - 1, knot_count - order points.
/// A polyline as gluPwlCurve takes it (u, v, u, v, ...), with `per_edge`
/// points on each edge: `points` and per_edge - 1 more evenly between each
/// two. GLU draws every gluPwlCurve edge as a straight chord across the
/// surface and never refines it, so a coarse loop makes long slivers fanned
/// from its corners (measured: docs/glu.md; lab 25's slivers). 1 keeps the
/// points as they are.
std::vector<GLfloat> densified_pwl(const std::vector<spline::Vec2>& points, int per_edge);

spline::BsplineCurve core_curve(GLint knot_count, const GLfloat* knots, GLint stride, const GLfloat* ctl,
                                GLint order, GLenum type);

/// The trim piece of gluNurbsCurve(..., GLU_MAP1_TRIM_2 or _3) in a trim loop.
spline::TrimPiece core_trim_curve(GLint knot_count, const GLfloat* knots, GLint stride, const GLfloat* ctl,
                                  GLint order, GLenum type);

/// The trim piece of gluPwlCurve(nurb, count, array, stride, type): a
/// polyline of count (u, v) points (GLU_MAP1_TRIM_2), or of count
/// (w u, w v, w) points divided by w (GLU_MAP1_TRIM_3).
spline::TrimPiece core_pwl(GLint count, const GLfloat* array, GLint stride, GLenum type);

/// One piece of a trim loop as a lab hands it to GLU: `points` (u, v) or
/// (w u, w v, w), `stride` floats apart; a gluPwlCurve when it has no knots,
/// else a gluNurbsCurve of `order`, whose knot count GLU reads as
/// count() + order:
///   gluNurbsCurve(nurb, p.count() + p.order, p.knots, p.stride, p.points.data(), p.order, p.type);
///   gluPwlCurve(nurb, p.count(), p.points.data(), p.stride, p.type);
struct GluTrimPiece {
  GLenum type;  // GLU_MAP1_TRIM_2 or GLU_MAP1_TRIM_3
  std::vector<GLfloat> points;
  GLint stride;
  GLint order = 0;
  GLfloat* knots = nullptr;
  GLint count() const { return GLint(points.size()) / stride; }
};
/// A loop: each piece starts where the one before ends (gluBeginTrim ... gluEndTrim).
using GluTrimLoop = std::vector<GluTrimPiece>;

/// The core's loops for these pieces (core_trim_curve and core_pwl each).
std::vector<spline::TrimLoop> core_trims(const std::vector<GluTrimLoop>& loops);

/// gluNurbsSurface(nurb, s_knot_count, s_knots, t_knot_count, t_knots,
/// s_stride, t_stride, ctl, s_order, t_order, type) for GL_MAP2_VERTEX_3 / _4:
/// s is the core's u (the row index i of BsplineSurface::P, P[i * nv + j]),
/// t its v. Point (i, j) is read at ctl[i * s_stride + j * t_stride]. No trims.
spline::BsplineSurface core_surface(GLint s_knot_count, const GLfloat* s_knots, GLint t_knot_count,
                                    const GLfloat* t_knots, GLint s_stride, GLint t_stride, const GLfloat* ctl,
                                    GLint s_order, GLint t_order, GLenum type);

}  // namespace gllab
