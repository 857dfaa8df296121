// common/gl/spline_draw.cpp — spline_draw.h: the core's results, handed to GL.
#include "gl/spline_draw.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gl/gl.h"
#include "gl/pick.h"
#include "gl/scene.h"
#include "spline/curvature.h"
#include "spline/parameterization.h"

namespace gllab {

namespace {

// Unlit lines and points in one colour; the destructor restores the state.
// GL_LIGHTING_BIT too: with GL_COLOR_MATERIAL on, glColor also sets the
// material, and restoring only the current colour would leave the material
// of the last line behind (Mesa then skips a glColor of the same value).
// Lines test depth but do not write it: where two lines cross or run on top
// of each other, the one drawn later wins on every rasteriser. (Written
// depths tie there, and llvmpipe and softpipe break the ties differently.)
// So draw surfaces first, then what goes on them.
// GL_COLOR_MATERIAL goes off too: else the ink's glColor would become the
// lit material of whatever is drawn next (popping GL_CURRENT_BIT restores
// the colour, not the material; measured with Mesa 22.3).
struct Ink {
  Ink(Rgb colour, float line_width, float point_size = 1.f) {
    glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_LIGHTING_BIT | GL_LINE_BIT | GL_POINT_BIT |
                 GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDepthMask(GL_FALSE);
    glDisable(GL_LIGHTING);
    glDisable(GL_COLOR_MATERIAL);
    glDisable(GL_TEXTURE_2D);
    glColor3f(colour.r, colour.g, colour.b);
    glLineWidth(line_width);
    glPointSize(point_size);
  }
  ~Ink() { glPopAttrib(); }
  Ink(const Ink&) = delete;
  Ink& operator=(const Ink&) = delete;
};

void vertex(const spline::Vec3& p) { glVertex3d(p.x, p.y, p.z); }

Rgb blend(Rgb a, Rgb b, double f) {
  const auto mix = [f](float x, float y) { return static_cast<float>(x + (y - x) * f); };
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

void draw_levels(const std::vector<std::vector<spline::Vec3>>& levels, const spline::Vec3& point, Rgb first,
                 Rgb last) {
  const std::size_t n = levels.size();
  for (std::size_t j = 0; j < n; ++j) {
    const Rgb c = blend(first, last, n > 1 ? static_cast<double>(j) / (n - 1) : 0.0);
    if (levels[j].size() > 1) draw_polyline(levels[j], c, j == 0 ? 1.5f : 1.f);
    draw_dots(levels[j], c, j == 0 ? 7.f : 5.f);
  }
  draw_dots({point}, last, 10.f);
}

// The current matrices, to place things a number of pixels from a point.
struct Projection {
  GLdouble model[16], projection[16];
  GLint viewport[4];
  Projection() {
    glGetDoublev(GL_MODELVIEW_MATRIX, model);
    glGetDoublev(GL_PROJECTION_MATRIX, projection);
    glGetIntegerv(GL_VIEWPORT, viewport);
  }
  bool to_window(const spline::Vec3& p, spline::Vec3& w) const {
    return gluProject(p.x, p.y, p.z, model, projection, viewport, &w.x, &w.y, &w.z) == GL_TRUE;
  }
  spline::Vec3 to_lab(const spline::Vec3& w) const {
    spline::Vec3 p;
    gluUnProject(w.x, w.y, w.z, model, projection, viewport, &p.x, &p.y, &p.z);
    return p;
  }
};

}  // namespace

// ---- points and polygons ----------------------------------------------------

void draw_polyline(const std::vector<spline::Vec3>& points, Rgb colour, float width, bool closed) {
  Ink ink(colour, width);
  glBegin(closed ? GL_LINE_LOOP : GL_LINE_STRIP);
  for (const spline::Vec3& p : points) vertex(p);
  glEnd();
}

void draw_dashed_polyline(const std::vector<spline::Vec3>& points, Rgb colour, float width) {
  Ink ink(colour, width);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x3333);  // 4 pixels on, 4 off (each bit twice)
  glBegin(GL_LINE_STRIP);
  for (const spline::Vec3& p : points) vertex(p);
  glEnd();
}

void draw_dots(const std::vector<spline::Vec3>& points, Rgb colour, float size) {
  Ink ink(colour, 1.f, size);
  glBegin(GL_POINTS);
  for (const spline::Vec3& p : points) vertex(p);
  glEnd();
}

void draw_control_points(const State& state, const std::string& list, Rgb colour, float size, bool numbered) {
  draw_control_points_prefix(state, list, state.points(list).size(), colour, size, numbered);
}

void draw_control_points_prefix(const State& state, const std::string& list, std::size_t count, Rgb colour,
                                float size, bool numbered) {
  const std::vector<spline::Vec3>& all = state.points(list);
  const std::vector<spline::Vec3> points(all.begin(), all.begin() + std::min(count, all.size()));
  int dimension = 2;
  for (const PointList& l : state.point_lists())
    if (l.name == list) dimension = l.dimension;
  draw_dots(points, colour, size);
  for (std::size_t i = 0; i < points.size(); ++i) {
    register_pickable(list, i, points[i], dimension);
    if (numbered) draw_label(points[i].x, points[i].y, points[i].z, std::to_string(i), colour, 12, -12);
  }
}

void draw_control_points(const State& state, const std::string& list, const std::vector<std::size_t>& indices,
                         Rgb colour, float size, bool numbered) {
  const std::vector<spline::Vec3>& points = state.points(list);
  std::vector<spline::Vec3> at;
  for (std::size_t i : indices) at.push_back(points.at(i));
  draw_control_points_at(state, list, indices, at, colour, size);
  if (numbered)
    for (std::size_t k = 0; k < indices.size(); ++k)
      draw_label(at[k].x, at[k].y, at[k].z, std::to_string(indices[k]), colour, 12, -12);
}

void draw_control_points_at(const State& state, const std::string& list, const std::vector<std::size_t>& indices,
                            const std::vector<spline::Vec3>& at, Rgb colour, float size) {
  const std::size_t count = state.points(list).size();  // throws for an unknown list
  int dimension = 2;
  for (const PointList& l : state.point_lists())
    if (l.name == list) dimension = l.dimension;
  draw_dots(at, colour, size);
  for (std::size_t k = 0; k < indices.size() && k < at.size(); ++k)
    if (indices[k] < count) register_pickable(list, indices[k], at[k], dimension);
}

void draw_handles(const State& state, const std::string& list,
                  const std::vector<std::array<std::size_t, 2>>& handles, Rgb line, Rgb points) {
  const std::vector<spline::Vec3>& p = state.points(list);
  for (const auto& [base, tip] : handles) draw_polyline({p.at(base), p.at(tip)}, line, 2.f);
  draw_control_points(state, list, points);
}

void draw_control_points_at(const State& state, const std::string& list,
                            const std::vector<spline::Vec3>& at, Rgb colour, float size) {
  std::vector<std::size_t> all(state.points(list).size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  draw_control_points_at(state, list, all, at, colour, size);
}

void draw_control_polygon(const std::vector<spline::Vec3>& P, Rgb colour) {
  draw_dashed_polyline(P, colour, 1.f);
  draw_dots(P, colour, 6.f);
}

void draw_convex_hull(const std::vector<spline::Vec3>& P, Rgb colour, float fill_alpha, float width) {
  const std::vector<spline::Vec3> hull = spline::convex_hull_xy(P);
  if (fill_alpha > 0) {
    Ink ink(colour, width);
    glEnable(GL_BLEND);
    // Blend colour only and keep the destination alpha, as text panels do (text.cpp).
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glColor4f(colour.r, colour.g, colour.b, fill_alpha);
    glBegin(GL_POLYGON);  // convex, so GL_POLYGON is defined
    for (const spline::Vec3& p : hull) vertex(p);
    glEnd();
  }
  draw_polyline(hull, colour, width, true);
}

void draw_control_net(const std::vector<spline::Vec3>& P, int rows, int columns, Rgb colour) {
  Ink ink(colour, 1.f, 5.f);
  for (int i = 0; i < rows; ++i) {
    glBegin(GL_LINE_STRIP);
    for (int j = 0; j < columns; ++j) vertex(P[static_cast<std::size_t>(i) * columns + j]);
    glEnd();
  }
  for (int j = 0; j < columns; ++j) {
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < rows; ++i) vertex(P[static_cast<std::size_t>(i) * columns + j]);
    glEnd();
  }
  glBegin(GL_POINTS);
  for (const spline::Vec3& p : P) vertex(p);
  glEnd();
}

void draw_arrow(const spline::Vec3& from, const spline::Vec3& to, Rgb colour, float width, double head_px) {
  draw_polyline({from, to}, colour, width);
  // The head in window pixels: two barbs at +-25 degrees from the reversed direction.
  const Projection m;
  spline::Vec3 a, b;
  if (!m.to_window(from, a) || !m.to_window(to, b)) return;
  const double dx = a.x - b.x, dy = a.y - b.y, len = std::hypot(dx, dy);
  if (!(len > 0)) return;
  const double c = std::cos(0.44), s = std::sin(0.44), ux = dx / len * head_px, uy = dy / len * head_px;
  Ink ink(colour, width);
  glBegin(GL_TRIANGLES);
  vertex(to);
  vertex(m.to_lab({b.x + c * ux - s * uy, b.y + s * ux + c * uy, b.z}));
  vertex(m.to_lab({b.x + c * ux + s * uy, b.y - s * ux + c * uy, b.z}));
  glEnd();
}

// ---- curves -------------------------------------------------------------------

void draw_curve(const std::function<spline::Vec3(double)>& curve, double a, double b, Rgb colour, float width,
                double tolerance) {
  spline::FlattenOptions options;
  options.tolerance = tolerance;
  std::vector<spline::Vec3> points;
  for (const spline::CurveSample& s : spline::flatten_curve(curve, a, b, options)) points.push_back(s.point);
  draw_polyline(points, colour, width);
}

void draw_curve(const spline::BsplineCurve& curve, Rgb colour, float width, double tolerance) {
  // Pieces between the interior knots of multiplicity p + 1, where the curve
  // jumps (notes "B-Spline Polynomials", case D); each piece ends with its left limit.
  const spline::ParamInterval dom = spline::domain(curve);
  std::vector<double> breaks = {dom.a};
  for (int i = curve.p + 1; i <= curve.n(); ++i)
    if (curve.U[i] > breaks.back() && curve.U[i] < dom.b &&
        spline::knot_multiplicity(curve.U, curve.U[i]) > curve.p)
      breaks.push_back(curve.U[i]);
  breaks.push_back(dom.b);
  const spline::CurveEvaluator evaluator(curve);  // checked once, not at every sample
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double a = breaks[k], b = breaks[k + 1];
    draw_curve(
        [&](double u) { return evaluator.point(u, u == b ? spline::Side::Left : spline::Side::Right); },
        a, b, colour, width, tolerance);
  }
}

void draw_curve(const spline::BezierCurve& curve, Rgb colour, float width, double tolerance) {
  draw_curve([&](double t) { return spline::bezier_point(curve, t); }, curve.a, curve.b, colour, width, tolerance);
}

void draw_knot_markers(const spline::BsplineCurve& curve, Rgb colour, bool show_multiplicity) {
  const spline::ParamInterval dom = spline::domain(curve);
  Ink ink(colour, 1.5f);
  double last = -HUGE_VAL;
  for (double u : curve.U) {
    if (u == last || u < dom.a || u > dom.b) continue;
    last = u;
    const spline::Vec3 c = spline::curve_point(curve, u);
    // A diamond of 5 pixels: its size in lab units from the current matrices.
    GLdouble model[16], projection[16];
    GLint viewport[4];
    glGetDoublev(GL_MODELVIEW_MATRIX, model);
    glGetDoublev(GL_PROJECTION_MATRIX, projection);
    glGetIntegerv(GL_VIEWPORT, viewport);
    GLdouble wx, wy, wz;
    if (gluProject(c.x, c.y, c.z, model, projection, viewport, &wx, &wy, &wz) != GL_TRUE) continue;
    glBegin(GL_LINE_LOOP);
    for (const auto& d : {std::pair{5, 0}, std::pair{0, 5}, std::pair{-5, 0}, std::pair{0, -5}}) {
      GLdouble ox, oy, oz;
      gluUnProject(wx + d.first, wy + d.second, wz, model, projection, viewport, &ox, &oy, &oz);
      glVertex3d(ox, oy, oz);
    }
    glEnd();
    const int m = spline::knot_multiplicity(curve.U, u);
    if (show_multiplicity && m > 1) draw_label(c.x, c.y, c.z, "x" + std::to_string(m), colour, 0, 14);
  }
}

void draw_de_casteljau(const spline::DeCasteljau& scheme, Rgb first, Rgb last) {
  draw_levels(scheme.levels, scheme.point, first, last);
}

void draw_de_boor(const spline::DeBoorConstruction& construction, Rgb first, Rgb last) {
  draw_levels(construction.levels, construction.point, first, last);
}

void draw_curvature_comb(const std::function<std::array<spline::Vec3, 3>(double)>& derivatives, double a, double b,
                         double scale, Rgb colour, int teeth) {
  std::vector<spline::Vec3> tips;
  {
    Ink ink(colour, 1.f);
    glBegin(GL_LINES);
    for (int k = 0; k <= teeth; ++k) {
      const std::array<spline::Vec3, 3> d = derivatives(k == teeth ? b : a + (b - a) * k / teeth);
      if (!(spline::norm(d[1]) > 0)) continue;
      tips.push_back(d[0] - scale * spline::curvature_vector(d[1], d[2]));
      vertex(d[0]);
      vertex(tips.back());
    }
    glEnd();
  }
  draw_polyline(tips, colour, 1.f);
}

void draw_curvature_comb(const spline::CubicSpline& spline, double scale, Rgb colour,
                         int teeth_per_segment) {
  const auto derivatives = [&](double u) {
    return std::array<spline::Vec3, 3>{spline::spline_point(spline, u), spline::spline_derivative(spline, u, 1),
                                       spline::spline_derivative(spline, u, 2)};
  };
  draw_curvature_comb(derivatives, spline.t.front(), spline.t.back(), scale, colour,
                      teeth_per_segment * int(spline.segments()));
}

void draw_curve(const spline::CubicSpline& spline, Rgb colour, float width, double tolerance) {
  draw_curve([&](double u) { return spline::spline_point(spline, u); }, spline.t.front(), spline.t.back(),
             colour, width, tolerance);
}

void draw_sampled_curve(const std::function<spline::Vec3(double)>& curve, double a, double b,
                        Rgb colour, int samples, float width) {
  std::vector<spline::Vec3> points;
  for (int k = 0; k <= samples; ++k) points.push_back(curve(k == samples ? b : a + (b - a) * k / samples));
  draw_polyline(points, colour, width);
}

// ---- meshes -----------------------------------------------------------------------

void draw_mesh(const spline::Mesh& mesh) {
  glBegin(GL_TRIANGLES);
  for (const auto& t : mesh.triangles)
    for (int k : t) {
      const spline::Vec3& n = mesh.normals[k];
      glNormal3d(n.x, n.y, n.z);
      vertex(mesh.positions[k]);
    }
  glEnd();
}

// glPolygonOffset(factor, units) for draw_surface: lines drawn on a surface
// must win the depth test on llvmpipe, softpipe and GLX alike. A flattened
// iso-curve's chords sag below the curved surface; with (1, 1) one pixel of
// lab 17's iso_lines_normals went to the surface under GLX and to the line
// under OSMesa. (2, 4) clears it (and softpipe's line pixels).
constexpr GLfloat kSurfaceOffsetFactor = 2.f, kSurfaceOffsetUnits = 4.f;

void draw_surface(const spline::Mesh& mesh, Rgb colour) {
  draw_surface(mesh, std::vector<Rgb>(mesh.positions.size(), colour));
}

void draw_surface(const spline::Mesh& mesh, const std::vector<Rgb>& colours) {
  // GL_LIGHTING_BIT too: the colours set the material (see Ink).
  glPushAttrib(GL_CURRENT_BIT | GL_LIGHTING_BIT | GL_POLYGON_BIT);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(kSurfaceOffsetFactor, kSurfaceOffsetUnits);
  glBegin(GL_TRIANGLES);
  for (const auto& t : mesh.triangles)
    for (int k : t) {
      const Rgb& c = colours[static_cast<std::size_t>(k)];
      const spline::Vec3& n = mesh.normals[k];
      glColor3f(c.r, c.g, c.b);
      glNormal3d(n.x, n.y, n.z);
      vertex(mesh.positions[k]);
    }
  glEnd();
  glPopAttrib();
}

void draw_segments(const std::vector<std::array<spline::Vec3, 2>>& segments, Rgb colour, float width) {
  Ink ink(colour, width);
  glBegin(GL_LINES);
  for (const auto& s : segments) {
    vertex(s[0]);
    vertex(s[1]);
  }
  glEnd();
}

void draw_mesh_wireframe(const spline::Mesh& mesh, Rgb colour, float width) {
  Ink ink(colour, width);
  glBegin(GL_LINES);
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) {
      vertex(mesh.positions[t[e]]);
      vertex(mesh.positions[t[(e + 1) % 3]]);
    }
  glEnd();
}

void draw_trim_loops(const std::vector<spline::TrimLoop>& loops, Rgb pwl, Rgb polynomial, Rgb rational) {
  for (const spline::TrimLoop& loop : loops)
    for (const spline::TrimPiece& piece : loop.pieces) {
      std::vector<spline::Vec3> line;
      for (spline::Vec2 q : piece.polyline) line.push_back({q.x, q.y, 0});
      const Rgb c = !piece.curve ? pwl : piece.curve->rational() ? rational : polynomial;
      if (piece.curve) {
        draw_curve(*piece.curve, c);
        const auto [a, b] = spline::domain(*piece.curve);  // the arrow on its last 2 %
        line = {spline::curve_point(*piece.curve, b - 0.02 * (b - a)), spline::curve_point(*piece.curve, b)};
      } else {
        draw_polyline(line, c);
      }
      const spline::Vec3 tip = line.back(), d = 0.03 * normalized(tip - line[line.size() - 2]);
      const spline::Vec3 n{-d.y, d.x, 0};
      draw_polyline({tip - d + 0.6 * n, tip, tip - d - 0.6 * n}, c, 2.f);
    }
}

void draw_mesh_faces(const spline::Mesh& mesh, const std::vector<std::size_t>& faces, Rgb colour, float width) {
  Ink ink(colour, std::max(width, 1.f));
  glPushAttrib(GL_POLYGON_BIT);
  if (width > 0) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLES);
  for (std::size_t f : faces)
    for (int k : mesh.triangles[f]) vertex(mesh.positions[k]);
  glEnd();
  glPopAttrib();
}

void draw_normal_needles(const spline::Mesh& mesh, double length, Rgb colour, int every) {
  Ink ink(colour, 1.f);
  glBegin(GL_LINES);
  for (std::size_t k = 0; k < mesh.positions.size(); k += static_cast<std::size_t>(std::max(1, every))) {
    vertex(mesh.positions[k]);
    vertex(mesh.positions[k] + length * spline::normalized(mesh.normals[k]));
  }
  glEnd();
}

// ---- plots ----------------------------------------------------------------------

spline::Vec3 PlotFrame::at(double x, double y) const {
  return {left + (x - x0) / (x1 - x0) * (right - left), bottom + (y - y0) / (y1 - y0) * (top - bottom), 0};
}

PlotFrame enter_plot(const PlotFrame& frame, bool equal_aspect) {
  double kx = (frame.right - frame.left) / (frame.x1 - frame.x0);
  double ky = (frame.top - frame.bottom) / (frame.y1 - frame.y0);
  PlotFrame data = frame;
  if (equal_aspect) {
    kx = ky = std::min(std::fabs(kx), std::fabs(ky));
    const double cx = (frame.x0 + frame.x1) / 2, cy = (frame.y0 + frame.y1) / 2;
    const double hx = (frame.right - frame.left) / kx / 2, hy = (frame.top - frame.bottom) / ky / 2;
    data.x0 = cx - hx, data.x1 = cx + hx, data.y0 = cy - hy, data.y1 = cy + hy;
  }
  glPushMatrix();
  glTranslated(frame.left, frame.bottom, 0);
  glScaled(kx, ky, 1);
  glTranslated(-data.x0, -data.y0, 0);
  data.left = data.x0, data.right = data.x1, data.bottom = data.y0, data.top = data.y1;
  return data;
}

void scissor_to(const PlotFrame& frame) {
  const Projection m;
  spline::Vec3 a, b;
  if (!m.to_window({frame.left, frame.bottom, 0}, a) || !m.to_window({frame.right, frame.top, 0}, b)) return;
  const auto px = [](double v) { return static_cast<int>(std::lround(v)); };
  const int x0 = px(std::min(a.x, b.x)), y0 = px(std::min(a.y, b.y));
  const int x1 = px(std::max(a.x, b.x)), y1 = px(std::max(a.y, b.y));
  glScissor(x0, y0, x1 - x0, y1 - y0);
  glEnable(GL_SCISSOR_TEST);
}

Rgb series_colour(int i) {
  static const Rgb kSeries[] = {{1.f, 0.45f, 0.35f}, {1.f, 0.8f, 0.3f},  {0.45f, 0.9f, 0.4f}, {0.4f, 0.7f, 1.f},
                                {0.8f, 0.5f, 1.f},   {0.3f, 0.9f, 0.9f}, {1.f, 0.5f, 0.8f},  {0.8f, 0.8f, 0.8f}};
  return kSeries[((i % 8) + 8) % 8];
}

void draw_plot_axes(const PlotFrame& frame, Rgb colour, const std::string& title) {
  draw_polyline({{frame.left, frame.bottom, 0}, {frame.right, frame.bottom, 0}, {frame.right, frame.top, 0},
                 {frame.left, frame.top, 0}},
                blend(colour, {0.f, 0.f, 0.f}, 0.4), 1.f, true);
  if (frame.y0 < 0 && frame.y1 > 0) draw_dashed_polyline({frame.at(frame.x0, 0), frame.at(frame.x1, 0)}, colour);
  if (!title.empty()) draw_label((frame.left + frame.right) / 2, frame.top, 0, title, colour, 0, -12);
}

void draw_plot_function(const PlotFrame& frame, const std::function<double(double)>& f, Rgb colour, float width,
                        int samples) {
  // Clip to the box: a point outside ends the strip, the next inside starts one.
  Ink ink(colour, width);
  bool open = false;
  for (int k = 0; k <= samples; ++k) {
    const double x = frame.x0 + (frame.x1 - frame.x0) * k / samples;
    const double y = f(x);
    const bool inside = std::isfinite(y) && y >= std::min(frame.y0, frame.y1) && y <= std::max(frame.y0, frame.y1);
    if (inside && !open) glBegin(GL_LINE_STRIP), open = true;
    if (inside) vertex(frame.at(x, y));
    if (!inside && open) glEnd(), open = false;
  }
  if (open) glEnd();
}

void draw_plot_ticks(const PlotFrame& frame, const std::vector<double>& xs, Rgb colour) {
  const double h = 0.04 * (frame.top - frame.bottom);
  Ink ink(colour, 1.5f);
  glBegin(GL_LINES);
  for (double x : xs) {
    const spline::Vec3 p = frame.at(x, frame.y0);
    glVertex3d(p.x, frame.bottom, 0);
    glVertex3d(p.x, frame.bottom - h, 0);
  }
  glEnd();
}

double plot_ceiling(double x) {
  if (!(x > 0) || !std::isfinite(x)) return 1;  // nothing to scale (all zero), or nothing sensible
  const double e = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * e >= x) return m * e;
  return 10 * e;
}

double max_difference(const std::function<double(double)>& f, const std::function<double(double)>& g,
                      double x0, double x1, int samples) {
  double largest = 0;
  for (int k = 0; k <= samples; ++k) {
    const double x = x0 + (x1 - x0) * k / samples;
    largest = std::max(largest, std::fabs(f(x) - g(x)));
  }
  return largest;
}

// ---- labels ------------------------------------------------------------------------

std::string knot_vector_text(const std::vector<double>& U) {
  std::string text;
  for (std::size_t k = 0; k < U.size(); ++k) {
    if (k > 0 && U[k] == U[k - 1]) continue;
    char number[32];
    std::snprintf(number, sizeof number, " %g", U[k]);
    const int m = spline::knot_multiplicity(U, U[k]);
    text += number + (m > 1 ? "x" + std::to_string(m) : "");
  }
  return text;
}

std::string xy_text(const spline::Vec3& p) { return format_text("(%.5g, %.5g)", p.x, p.y); }

std::string points_text(const std::vector<spline::Vec3>& points) {
  std::string text;
  for (const spline::Vec3& p : points) text += (text.empty() ? "" : " ") + xy_text(p);
  return text;
}

std::vector<Rgb> height_colours(const std::vector<HeightColour>& ramp, const spline::Mesh& mesh) {
  std::vector<Rgb> colours;
  for (const spline::Vec3& p : mesh.positions) {
    std::size_t k = 1;
    while (k + 1 < ramp.size() && p.z > ramp[k].height) ++k;
    const HeightColour &a = ramp[k - 1], &b = ramp[k];
    const float f = float(std::clamp((p.z - a.height) / (b.height - a.height), 0.0, 1.0));
    const Rgb &c0 = a.colour, &c1 = b.colour;
    colours.push_back({c0.r + f * (c1.r - c0.r), c0.g + f * (c1.g - c0.g), c0.b + f * (c1.b - c0.b)});
  }
  return colours;
}

std::vector<std::string> bezier_joint_report(const std::vector<spline::BezierCurve>& segments) {
  std::vector<std::string> lines;
  for (std::size_t i = 1; i < segments.size(); ++i) {
    const spline::BezierCurve &before = segments[i - 1], &after = segments[i];
    const spline::Vec3 d1a = spline::bezier_end_derivative(before, 1);
    const spline::Vec3 d1b = spline::bezier_start_derivative(after, 1);
    const spline::Vec3 d2a = spline::bezier_end_derivative(before, 2);
    const spline::Vec3 d2b = spline::bezier_start_derivative(after, 2);
    const double angle = std::fabs(std::atan2(cross(d1a, d1b).z, dot(d1a, d1b))) * 180 / M_PI;
    lines.push_back(format_text("b%zu: angle %5.1f deg  |S'| %.2f|%.2f  S'' jump %.2f",
                                (before.P.size() - 1) * i, angle, norm(d1a), norm(d1b), norm(d2b - d2a)));
  }
  return lines;
}

std::string unit_parameters_text(const std::vector<double>& t) {
  std::string r;
  for (double u : spline::unit_interval_parameters(t))
    r += std::lround(u * 100) >= 100 ? " 1" : format_text(" .%02ld", std::lround(u * 100));
  return r.substr(1);
}

std::string polynomial_text(const std::vector<double>& c, const std::string& x) {
  const char* powers[] = {"", "", "²", "³"};
  std::string r;
  for (int j = int(c.size()) - 1; j >= 0; --j) {
    if (std::fabs(c[j]) < 1e-12) continue;
    r += r.empty() ? (c[j] < 0 ? "-" : "") : (c[j] < 0 ? " - " : " + ");
    if (std::fabs(c[j]) != 1 || j == 0) r += format_text("%.4g", std::fabs(c[j]));
    if (j > 0) r += x + (j < 4 ? powers[j] : "^" + std::to_string(j));
  }
  return r.empty() ? "0" : r;
}

std::string newton_form_text(const std::vector<double>& a, const std::vector<double>& nodes) {
  std::string sum, product;
  for (std::size_t i = 0; i < a.size() && i < nodes.size(); ++i) {
    sum += (i ? " + " : "") + format_text("%.4g", a[i]) + product;
    product += format_text("(x-%.4g)", nodes[i]);
  }
  return sum;
}

void draw_divided_differences(const std::vector<double>& nodes,
                              const std::vector<std::vector<double>>& table, double x, double y,
                              Rgb colour, int fresh, Rgb fresh_colour) {
  const auto cell = [](const std::string& v) {
    return v + std::string(std::max<std::size_t>(1, 9 - v.size()), ' ');
  };
  std::vector<std::string> lines = {"f[t_j..t_(j+k)]; row 0 holds a_k", cell("t_j")};
  for (std::size_t k = 0; k < table.size(); ++k) lines[1] += cell("k=" + std::to_string(k));
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    lines.push_back(cell(format_text("%.4g", nodes[j])));
    for (std::size_t k = 0; k + j < table.size(); ++k) lines.back() += cell(format_text("%.4g", table[k][j]));
  }
  draw_text_panel_at(x, y, 0, lines, {colour});
  int px = 0, py = 0;  // the panel's top-left pixel: draw_text_panel has 6 px padding
  if (fresh < 0 || !window_pixel(x, y, 0, px, py)) return;
  for (int k = 0; k <= fresh; ++k)
    draw_text(px + 6 + 9 * (k + 1) * kGlyphWidth, py + 6 + kGlyphHeight * (fresh - k + 2),
              format_text("%.4g", table[k][fresh - k]), fresh_colour);
}

}  // namespace gllab
