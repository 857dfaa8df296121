// common/deform/morph.cpp — cross-fade and morph of two pictures (morph.h).
#include "deform/morph.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "deform/internal.h"

namespace gllab::deform {

namespace {

void check_pair(const char* what, const Image& m1, const Image& m2, double t) {
  if (m1.width != m2.width || m1.height != m2.height || m1.width <= 0 || m1.height <= 0)
    throw std::invalid_argument(std::string(what) + ": the pictures are " +
                                std::to_string(m1.width) + " x " + std::to_string(m1.height) +
                                " and " + std::to_string(m2.width) + " x " +
                                std::to_string(m2.height) + " (must be the same size)");
  if (!(t >= 0 && t <= 1))
    throw std::invalid_argument(std::string(what) + ": t = " + detail::number_text(t) +
                                " outside [0, 1]");
}

std::uint8_t to_byte(double v) { return std::uint8_t(std::clamp(std::floor(v + 0.5), 0.0, 255.0)); }

// The centre of pixel (px, py) in the unit square.
Vec2 centre(const Image& im, int px, int py) {
  return {(px + 0.5) / im.width, 1 - (py + 0.5) / im.height};
}

}  // namespace

std::array<float, 4> sample(const Image& image, Vec2 at) {
  // Pixel coordinates of `at`, measured between pixel centres.
  const double fx = at.x * image.width - 0.5, fy = (1 - at.y) * image.height - 0.5;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const double ax = fx - x0, ay = fy - y0;
  const auto px = [&](int x, int y) {
    return image.pixel(std::clamp(x, 0, image.width - 1), std::clamp(y, 0, image.height - 1));
  };
  const std::uint8_t *p00 = px(x0, y0), *p10 = px(x0 + 1, y0), *p01 = px(x0, y0 + 1),
                     *p11 = px(x0 + 1, y0 + 1);
  std::array<float, 4> c;
  for (int k = 0; k < 4; ++k)
    c[k] = float((1 - ay) * ((1 - ax) * p00[k] + ax * p10[k]) +
                 ay * ((1 - ax) * p01[k] + ax * p11[k]));
  return c;
}

Image cross_fade(const Image& m1, const Image& m2, double t) {
  check_pair("cross_fade", m1, m2, t);
  Image out(m1.width, m1.height);
  for (std::size_t k = 0; k < out.rgba.size(); ++k)
    out.rgba[k] = to_byte((1 - t) * m1.rgba[k] + t * m2.rgba[k]);
  return out;
}

Image morph(const Image& m1, const Image& m2, const PlaneDeformation& f2, double t) {
  check_pair("morph", m1, m2, t);
  const PlaneFold fold = find_plane_fold(f2);
  if (fold.folds)
    throw std::invalid_argument("morph: " + plane_fold_text(fold) +
                                " (the backward warp needs a map without folds)");
  const PlaneEvaluator eval(f2);
  Image out(m1.width, m1.height);
  Vec2 above = centre(m1, 0, 0);  // the solution for the row above: the next row's first guess
  for (int py = 0; py < out.height; ++py) {
    Vec2 guess = above;
    for (int px = 0; px < out.width; ++px) {
      const Vec2 y = centre(out, px, py);
      // Where did this pixel come from? Start from the neighbour's answer
      // (the map is smooth), or y itself at t = 0 (where it is exact).
      const std::optional<Vec2> x = inverse_point(eval, t, y, t == 0 ? y : guess);
      if (!x)
        throw std::invalid_argument("morph: pixel (" + std::to_string(px) + ", " +
                                    std::to_string(py) + "): f(t, x) = y did not converge at t = " +
                                    detail::number_text(t));
      guess = *x;
      if (px == 0) above = *x;
      const std::array<float, 4> a = sample(m1, *x), b = sample(m2, eval(*x).f);
      std::uint8_t* o = out.pixel(px, py);
      for (int k = 0; k < 4; ++k) o[k] = to_byte((1 - t) * a[k] + t * b[k]);
    }
  }
  return out;
}

}  // namespace gllab::deform
