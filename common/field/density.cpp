// common/field/density.cpp — blob densities and their sums (lecture notes
// ch. 1, §1.5 Blobby objects). See density.h for the conditions each meets.
#include "field/density.h"

#include <cmath>

#include "field/internal.h"

namespace gllab::field {

using detail::fail;
using detail::num;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kBlinnK = 4;  // B = kBlinnK / b^2 (density.h)

void check_blob(const char* what, double a, double b) {
  if (!(a > 0) || !std::isfinite(a))
    fail(std::string(what) + ": a=" + num(a) + " (must be positive)");
  if (!(b > 0) || !std::isfinite(b))
    fail(std::string(what) + ": b=" + num(b) + " (must be positive)");
}

}  // namespace

// f(t) = a H0(t / b), H0(s) = 1 - 3 s^2 + 2 s^3 (the cubic Hermite basis, notes §1.5).
double hermite_density(double t, double a, double b) {
  const double s = t / b;
  if (s >= 1) return 0;
  return a * (1 + s * s * (2 * s - 3));
}

// f'(t) = (a / b) H0'(s), H0'(s) = -6 s (1 - s).
double hermite_density_derivative(double t, double a, double b) {
  const double s = t / b;
  if (s >= 1) return 0;
  return (a / b) * (-6 * s * (1 - s));
}

// Wyvill, McPheeters and Wyvill 1986: a (1 - 4/9 s^6 + 17/9 s^4 - 22/9 s^2).
double wyvill_density(double t, double a, double b) {
  const double s = t / b;
  if (s >= 1) return 0;
  const double s2 = s * s;
  return a * (1 + s2 * (-22.0 / 9 + s2 * (17.0 / 9 - s2 * (4.0 / 9))));
}

// d/dt: (a / b) (-44/9 s + 68/9 s^3 - 24/9 s^5).
double wyvill_density_derivative(double t, double a, double b) {
  const double s = t / b;
  if (s >= 1) return 0;
  const double s2 = s * s;
  return (a / b) * s * (-44.0 / 9 + s2 * (68.0 / 9 - s2 * (24.0 / 9)));
}

// Blinn 1982: a exp(-B t^2), B = k / b^2.
double blinn_density(double t, double a, double b) {
  return a * std::exp(-kBlinnK * (t * t) / (b * b));
}

double blinn_density_derivative(double t, double a, double b) {
  return -2 * kBlinnK * t / (b * b) * blinn_density(t, a, b);
}

const char* density_name(Density d) {
  switch (d) {
    case Density::kHermite:
      return "hermite";
    case Density::kWyvill:
      return "wyvill";
    case Density::kBlinn:
      return "blinn";
  }
  return "?";
}

double density_value(Density d, double t, double a, double b) {
  switch (d) {
    case Density::kWyvill:
      return wyvill_density(t, a, b);
    case Density::kBlinn:
      return blinn_density(t, a, b);
    default:
      return hermite_density(t, a, b);
  }
}

namespace {

double density_slope(Density d, double t, double a, double b) {
  switch (d) {
    case Density::kWyvill:
      return wyvill_density_derivative(t, a, b);
    case Density::kBlinn:
      return blinn_density_derivative(t, a, b);
    default:
      return hermite_density_derivative(t, a, b);
  }
}

}  // namespace

double BlobField::value(const Vec3& x) const {
  double sum = 0;
  for (const Blob& blob : blobs)
    sum += density_value(this->density, norm(x - blob.centre), blob.a, blob.b);
  return sum;
}

// grad f(|x - P|) = f'(r) (x - P) / r; at the centre f'(0) = 0 for the compact
// densities and the limit is 0 for Blinn's as well.
Vec3 BlobField::gradient(const Vec3& x) const {
  Vec3 sum{0, 0, 0};
  for (const Blob& blob : blobs) {
    const Vec3 d = x - blob.centre;
    const double r = norm(d);
    if (r > 0) sum += (density_slope(this->density, r, blob.a, blob.b) / r) * d;
  }
  return sum;
}

namespace {

// H0(s) = q on (0, 1). With s = 1/2 + w, H0 = 1/2 - 3/2 w + 2 w^3, so
// w^3 - 3/4 w + (1 - 2 q) / 4 = 0: a depressed cubic with three real roots
// w_k = cos((theta - 2 pi k) / 3), cos theta = 2 q - 1 (Viete's trigonometric
// solution); k = 1 is the one in (-1/2, 1/2).
double hermite_root(double q) {
  const double theta = std::acos(2 * q - 1);
  return 0.5 + std::cos((theta - 2 * kPi) / 3);
}

// f decreases on [0, b] from a to 0 (density.h): bisection on f(t) - c.
double bisect(Density d, double a, double b, double c) {
  double lo = 0, hi = b;
  while (hi - lo > 1e-15 * b) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (density_value(d, mid, a, b) > c ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double iso_radius(Density d, double a, double b, double c) {
  check_blob("iso_radius", a, b);
  if (!(c > 0 && c < a))
    fail("iso_radius: c=" + num(c) + " (must be in (0, a) with a=" + num(a) + ")");
  switch (d) {
    case Density::kHermite:
      return b * hermite_root(c / a);
    case Density::kWyvill:
      return bisect(d, a, b, c);
    case Density::kBlinn:
      return b * std::sqrt(std::log(a / c) / kBlinnK);  // a exp(-k r^2 / b^2) = c
  }
  return 0;
}

double merge_distance(Density d, double a, double b, double c) {
  check_blob("merge_distance", a, b);
  if (!(c > 0 && c < 2 * a))
    fail("merge_distance: c=" + num(c) + " (must be in (0, 2a) with a=" + num(a) + ")");
  return 2 * iso_radius(d, a, b, c / 2);
}

}  // namespace gllab::field
