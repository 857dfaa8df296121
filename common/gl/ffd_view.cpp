// common/gl/ffd_view.cpp — lab 29's drawing that is not its lesson (ffd_view.h).
#include "gl/ffd_view.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "deform/teapot.h"
#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"

namespace gllab {

using spline::Vec3;

deform::Lattice cube_lattice(const deform::Frame& frame, int count, int degree) {
  return deform::identity_lattice(frame, degree == 0
                                             ? deform::bernstein_volume(count, count, count)
                                             : deform::bspline_volume(count, count, count, degree));
}

std::vector<Vec3> lattice_points(const deform::Lattice& lattice,
                                 const std::function<Vec3(Vec3)>& move) {
  std::vector<Vec3> points;
  for (const Vec3& p : lattice.volume.P) points.push_back(move(p));
  return points;
}

deform::Lattice with_points(deform::Lattice lattice, const std::vector<Vec3>& points) {
  if (points.size() != lattice.volume.P.size())
    throw std::invalid_argument("with_points: " + std::to_string(points.size()) + " points for " +
                                std::to_string(lattice.volume.P.size()));
  lattice.volume.P = points;
  return lattice;
}

void draw_lattice_lines(const std::vector<Vec3>& points, int count, Rgb colour) {
  const auto at = [&](int i, int j, int k) { return points[std::size_t((i * count + j) * count + k)]; };
  std::vector<std::array<Vec3, 2>> lines;
  for (int i = 0; i < count; ++i)
    for (int j = 0; j < count; ++j)
      for (int k = 0; k < count; ++k) {
        if (i + 1 < count) lines.push_back({at(i, j, k), at(i + 1, j, k)});
        if (j + 1 < count) lines.push_back({at(i, j, k), at(i, j + 1, k)});
        if (k + 1 < count) lines.push_back({at(i, j, k), at(i, j, k + 1)});
      }
  draw_segments(lines, colour, 1.f);
}

namespace {

// The colour of det J (det_colours) as r, g, b.
std::array<float, 3> det_colour(float det) {
  if (!(det > 0)) return {1.f, 0.f, 1.f};  // folded
  const float a = std::clamp(float(std::log2(det)), -1.f, 1.f);
  const std::array<float, 3> white{.95f, .95f, .95f}, blue{.2f, .4f, 1.f}, red{1.f, .25f, .2f};
  const std::array<float, 3>& end = a < 0 ? blue : red;
  const float w = std::fabs(a);
  return {(1 - w) * white[0] + w * end[0], (1 - w) * white[1] + w * end[1],
          (1 - w) * white[2] + w * end[2]};
}

}  // namespace

std::vector<float> det_colours(const std::vector<float>& det) {
  std::vector<float> out;
  out.reserve(3 * det.size());
  for (const float d : det) {
    const std::array<float, 3> c = det_colour(d);
    out.insert(out.end(), c.begin(), c.end());
  }
  return out;
}

void draw_det_legend(int x, int y) {
  constexpr int kWidth = 160, kHeight = 12;
  {
    PixelSpace px;
    const int top = px.height - y - 20;
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= 32; ++i) {
      const std::array<float, 3> c = det_colour(float(std::exp2(2.0 * i / 32 - 1)));
      glColor3f(c[0], c[1], c[2]);
      glVertex2i(x + i * kWidth / 32, top);
      glVertex2i(x + i * kWidth / 32, top - kHeight);
    }
    glEnd();
    glColor3f(1.f, 0.f, 1.f);
    glRecti(x + kWidth + 12, top, x + kWidth + 12 + kHeight, top - kHeight);
  }
  draw_text(x, y, "det J  1/2      1       2", {1.f, 1.f, 1.f});
  draw_text(x + kWidth + 30, y + 18, "<= 0", {1.f, 1.f, 1.f});
}

void ffd_camera(const State& s, int width, int height, double half, Vec3 centre, double elevation,
                double azimuth) {
  ortho_fit(width, height, half, half, 4 * half);
  enable_headlight();
  const GLfloat white[] = {1.f, 1.f, 1.f, 1.f};
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  apply_orbit(s);
  look_from_above(elevation, azimuth);
  glTranslated(-centre.x, -centre.y, -centre.z);
}

const IndexedMesh& cached_teapot(int resolution) {
  static int made = -1;
  static IndexedMesh mesh;
  if (made != resolution) {
    mesh = deform::teapot_mesh(resolution);
    made = resolution;
  }
  return mesh;
}

std::size_t moved_vertices(const std::vector<float>& before, const std::vector<float>& after,
                           float tolerance) {
  std::size_t moved = 0;
  for (std::size_t v = 0; v + 2 < before.size() && v + 2 < after.size(); v += 3)
    moved += std::fabs(before[v] - after[v]) > tolerance ||
             std::fabs(before[v + 1] - after[v + 1]) > tolerance ||
             std::fabs(before[v + 2] - after[v + 2]) > tolerance;
  return moved;
}

}  // namespace gllab
