// bench/bench_data.cpp — see bench_data.h.
#include "bench_data.h"

#include <cmath>
#include <cstdint>
#include <random>

namespace gllab::bench {

using spline::Vec3;
using spline::Vec4;

namespace {

// mt19937_64 is specified bit for bit by the standard; the distributions are
// not, so map its output to [0, 1) ourselves (53 random bits).
class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) { return lo + (hi - lo) * ((engine_() >> 11) * 0x1.0p-53); }

 private:
  std::mt19937_64 engine_;
};

// Clamped knots for `count` control points of degree p on [0, 1]: p + 1 zeros,
// interior knots with spacings drawn from [0.5, 1.5] (non-uniform, no repeats),
// p + 1 ones. count + p + 1 entries.
std::vector<double> clamped_random_knots(int count, int p, Random& random) {
  const int interior = count - p - 1;
  std::vector<double> steps(static_cast<std::size_t>(interior) + 1);
  double total = 0;
  for (double& s : steps) total += (s = random.uniform(0.5, 1.5));
  std::vector<double> U(static_cast<std::size_t>(p) + 1, 0.0);
  double sum = 0;
  for (int k = 0; k < interior; ++k) U.push_back((sum += steps[static_cast<std::size_t>(k)]) / total);
  U.insert(U.end(), static_cast<std::size_t>(p) + 1, 1.0);
  return U;
}

// count >= 2 evenly spaced values over [0, 1]; the last is exactly 1.
std::vector<double> even_params(std::size_t count) {
  std::vector<double> u(count);
  for (std::size_t k = 0; k < count; ++k) u[k] = static_cast<double>(k) / static_cast<double>(count - 1);
  u.back() = 1.0;
  return u;
}

BenchData make_bench_data() {
  BenchData d;
  Random random(20240601);

  // A wobbly rational helix: 50 points, weights in [0.5, 2].
  d.curve.p = kDegree;
  d.curve.dimension = 3;
  for (int i = 0; i < kCurveControlPoints; ++i) {
    const double angle = 0.4 * i;
    const double radius = 5.0 + random.uniform(-1, 1);
    d.curve.P.push_back({radius * std::cos(angle), radius * std::sin(angle), 0.3 * i + random.uniform(-0.5, 0.5)});
    d.curve.w.push_back(random.uniform(0.5, 2.0));
  }
  d.curve.U = clamped_random_knots(kCurveControlPoints, kDegree, random);
  d.curve_u = even_params(kCurveParams);

  // A rational height field over a jittered 20 x 20 grid, P[i * nv + j].
  auto& s = d.surface;
  s.p = s.q = kDegree;
  s.nu = s.nv = kSurfaceControlPoints;
  for (int i = 0; i < s.nu; ++i) {
    for (int j = 0; j < s.nv; ++j) {
      const double x = i + random.uniform(-0.2, 0.2);
      const double y = j + random.uniform(-0.2, 0.2);
      s.P.push_back({x, y, 2.0 * std::sin(0.5 * x) * std::cos(0.4 * y) + random.uniform(-0.5, 0.5)});
      s.w.push_back(random.uniform(0.5, 2.0));
    }
  }
  s.U = clamped_random_knots(s.nu, s.p, random);
  s.V = clamped_random_knots(s.nv, s.q, random);
  d.grid_u = even_params(kGridSide);
  d.grid_v = even_params(kGridSide);

  // Natural cubic spline data: nodes with random spacing, a noisy wave.
  d.spline_t.resize(kSplineNodes + 1);
  d.spline_y.resize(kSplineNodes + 1);
  d.spline_P.resize(kSplineNodes + 1);
  double t = 0;
  for (std::size_t i = 0; i <= kSplineNodes; ++i) {
    d.spline_t[i] = t;
    d.spline_y[i] = std::sin(0.01 * t) + random.uniform(-0.1, 0.1);
    d.spline_P[i] = {std::cos(0.001 * t), std::sin(0.001 * t), d.spline_y[i]};
    t += random.uniform(0.5, 1.5);
  }
  return d;
}

}  // namespace

const BenchData& bench_data() {
  static const BenchData data = make_bench_data();
  return data;
}

std::vector<Vec4> curve_homogeneous(const spline::BsplineCurve& curve) {
  std::vector<Vec4> Pw;
  for (std::size_t i = 0; i < curve.P.size(); ++i) Pw.push_back(spline::homogeneous(curve.P[i], curve.w[i]));
  return Pw;
}

std::vector<Vec4> surface_homogeneous(const spline::BsplineSurface& surface) {
  std::vector<Vec4> Pw;
  for (std::size_t k = 0; k < surface.P.size(); ++k) Pw.push_back(spline::homogeneous(surface.P[k], surface.w[k]));
  return Pw;
}

}  // namespace gllab::bench
