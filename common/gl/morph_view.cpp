// common/gl/morph_view.cpp — lab 28's drawing that is not its lesson (morph_view.h).
#include "gl/morph_view.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"

namespace gllab {

using spline::Vec2;
using spline::Vec3;

void enter_unit_square(int width, int height, double margin) {
  ortho_fit(width, height, 0.5 + margin, 0.5 + margin);
  glTranslated(-0.5, -0.5, 0);
}

Vec2 in_between(const deform::PlaneEvaluator& f2, double t, Vec2 x) {
  return (1 - t) * x + t * f2(x).f;
}

void draw_deformed_grid(const deform::PlaneEvaluator& f2, double t, int lines, Rgb colour) {
  for (int k = 1; k < lines; ++k)
    for (const bool along_y : {false, true}) {
      std::vector<Vec3> line;
      for (int i = 0; i <= 64; ++i) {
        const double a = double(k) / lines, b = i / 64.0;
        const Vec2 y = in_between(f2, t, along_y ? Vec2{a, b} : Vec2{b, a});
        line.push_back({y.x, y.y, 0});
      }
      draw_polyline(line, colour, 1.f);
    }
}

void draw_moved_points(const deform::PlaneEvaluator& f2, double t, const std::vector<Vec2>& x,
                       Rgb colour, float size) {
  std::vector<Vec3> dots;
  for (const Vec2& p : x) {
    const Vec2 y = in_between(f2, t, p);
    dots.push_back({y.x, y.y, 0});
  }
  draw_dots(dots, colour, size);
}

void draw_fold_warning(const deform::PlaneDeformation& f, int height) {
  const deform::PlaneFold fold = deform::find_plane_fold(f);
  if (fold.folds) draw_text_panel(8, height - 30, {deform::plane_fold_text(fold)}, {1.f, .4f, .35f});
}

std::vector<Vec3> grid_points(const deform::PlaneDeformation& f) {
  std::vector<Vec3> points;
  for (const Vec2& c : f.P) points.push_back({c.x, c.y, 0});
  return points;
}

deform::PlaneDeformation grid_deformation(const std::vector<Vec3>& points, int count, int degree) {
  deform::PlaneDeformation f = deform::identity_plane(count, count, degree);
  if (points.size() != f.P.size())
    throw std::invalid_argument("grid_deformation: " + std::to_string(points.size()) +
                                " points for a " + std::to_string(count) + " x " +
                                std::to_string(count) + " grid");
  for (std::size_t k = 0; k < points.size(); ++k) f.P[k] = {points[k].x, points[k].y};
  return f;
}

std::vector<Vec3> inner_net(const std::vector<Vec3>& points, int count) {
  std::vector<Vec3> inner;
  for (std::size_t k : inner_grid_points(count)) inner.push_back(points.at(k));
  return inner;
}

std::vector<std::size_t> inner_grid_points(int count) {
  std::vector<std::size_t> inner;
  for (int i = 1; i + 1 < count; ++i)
    for (int j = 1; j + 1 < count; ++j) inner.push_back(std::size_t(i * count + j));
  return inner;
}

double feature_miss(const deform::PlaneEvaluator& f, const std::vector<Vec2>& from,
                    const std::vector<Vec2>& to) {
  double miss = 0;
  for (std::size_t k = 0; k < from.size() && k < to.size(); ++k)
    miss = std::max(miss, norm(f(from[k]).f - to[k]));
  return miss;
}

}  // namespace gllab
