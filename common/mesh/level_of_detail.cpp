// common/mesh/level_of_detail.cpp — see level_of_detail.h.
#include "mesh/level_of_detail.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace gllab {

namespace {

constexpr double kMaxSegments = 1e9;  // beyond this the answer is no use to a renderer

template <class T>
[[noreturn]] void refuse(const char* what, T value, const char* rule) {
  std::ostringstream m;
  m << what << "=" << value << " (" << rule << ")";
  throw std::invalid_argument(m.str());
}

}  // namespace

double chord_error(double radius, int segments) {
  if (!(std::isfinite(radius) && radius >= 0)) refuse("radius", radius, "must be >= 0");
  if (segments < 2) refuse("segments", segments, "must be >= 2");
  return radius * (1 - std::cos(M_PI / segments));
}

int segments_for_chord_error(double radius, double max_error, int min_segments) {
  if (!(std::isfinite(radius) && radius >= 0)) refuse("radius", radius, "must be >= 0");
  if (!(std::isfinite(max_error) && max_error > 0)) refuse("max error", max_error, "must be > 0");
  if (min_segments < 2) refuse("min segments", min_segments, "must be >= 2");
  const double ratio = 1 - max_error / radius;  // cos(pi / n) >= ratio
  if (radius == 0 || ratio <= -1) return min_segments;
  const double estimate = std::ceil(M_PI / std::acos(ratio));
  if (!(estimate < kMaxSegments)) refuse("max error / radius", max_error / radius, "too small");
  int n = std::max(min_segments, int(estimate));
  // The closed form can be one off where cos rounds; settle it on the definition.
  while (n > min_segments && chord_error(radius, n - 1) <= max_error) --n;
  while (chord_error(radius, n) > max_error) ++n;
  return n;
}

double projected_length(double length, double depth, double focal_px) {
  if (!(std::isfinite(depth) && depth > 0)) refuse("eye depth", depth, "must be > 0");
  return length * focal_px / depth;
}

double focal_length_px(double fovy_degrees, int height_px) {
  if (!(fovy_degrees > 0 && fovy_degrees < 180)) refuse("fovy", fovy_degrees, "degrees in (0, 180)");
  if (height_px < 1) refuse("viewport height", height_px, "must be >= 1");
  return height_px / 2.0 / std::tan(fovy_degrees * M_PI / 360);
}

}  // namespace gllab
