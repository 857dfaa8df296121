// bench/peer_sisl.cpp — SISL (SINTEF Spline Library, Debian libsisl-dev), see peers.h.
// Compiled only when CMake found sisl.h and libsisl.
#include <sisl.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "peers.h"

namespace gllab::bench {

using spline::Vec3;
using spline::Vec4;

namespace {

// SISL's rational kind; its newCurve/newSurf take (w x, w y, w z, w) and copy
// the arrays (icopy = 1).
constexpr int kRationalBspline = 2;
constexpr int kCopyArrays = 1;

void check(int status, const char* what, double u) {
  if (status < 0) throw std::runtime_error(std::string("SISL ") + what + ": status " + std::to_string(status) +
                                           " at u=" + std::to_string(u));
}

std::vector<double> flat(const std::vector<Vec4>& Pw) {
  std::vector<double> out;
  for (const Vec4& h : Pw) out.insert(out.end(), {h.x, h.y, h.z, h.w});
  return out;
}

Vec3 unit(const double* n) {
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  return {n[0] / length, n[1] / length, n[2] / length};
}

}  // namespace

struct SislPeer::Impl {
  SISLCurve* curve = nullptr;
  SISLSurf* surface = nullptr;
};

SislPeer::SislPeer(const BenchData& data) : impl_(std::make_unique<Impl>()) {
  const auto& c = data.curve;
  std::vector<double> knots = c.U;
  std::vector<double> coef = flat(curve_homogeneous(c));
  impl_->curve = newCurve(int(c.P.size()), c.p + 1, knots.data(), coef.data(), kRationalBspline, 3, kCopyArrays);
  if (!impl_->curve) throw std::runtime_error("SISL newCurve returned null");

  // SISL runs the first parameter direction fastest: coef[(j * nu + i) * 4],
  // where the bench data has P[i * nv + j] (i along u).
  const auto& s = data.surface;
  const std::vector<Vec4> Pw = surface_homogeneous(s);
  std::vector<double> scoef;
  for (int j = 0; j < s.nv; ++j)
    for (int i = 0; i < s.nu; ++i) {
      const Vec4& h = Pw[std::size_t(i) * std::size_t(s.nv) + std::size_t(j)];
      scoef.insert(scoef.end(), {h.x, h.y, h.z, h.w});
    }
  std::vector<double> U = s.U, V = s.V;
  impl_->surface = newSurf(s.nu, s.nv, s.p + 1, s.q + 1, U.data(), V.data(), scoef.data(), kRationalBspline, 3,
                           kCopyArrays);
  if (!impl_->surface) throw std::runtime_error("SISL newSurf returned null");
}

SislPeer::~SislPeer() {
  if (impl_->curve) freeCurve(impl_->curve);
  if (impl_->surface) freeSurf(impl_->surface);
}

void SislPeer::curve_points(const std::vector<double>& u, Points& out) {
  int left = 0, status = 0;
  double d[3];
  for (std::size_t k = 0; k < u.size(); ++k) {
    s1221(impl_->curve, 0, u[k], &left, d, &status);
    check(status, "s1221", u[k]);
    out[k] = {d[0], d[1], d[2]};
  }
}

void SislPeer::curve_derivs(const std::vector<double>& u, Points& out, Points& derivs) {
  int left = 0, status = 0;
  double d[6];
  for (std::size_t k = 0; k < u.size(); ++k) {
    s1221(impl_->curve, 1, u[k], &left, d, &status);
    check(status, "s1221", u[k]);
    out[k] = {d[0], d[1], d[2]};
    derivs[k] = {d[3], d[4], d[5]};
  }
}

void SislPeer::surface_normals(const std::vector<double>& us, const std::vector<double>& vs, Points& out,
                               Points& normals) {
  int left_u = 0, left_v = 0, status = 0;
  double d[9], n[3];
  std::size_t k = 0;
  for (double u : us)
    for (double v : vs) {
      double uv[2] = {u, v};
      // Position and both first partials; n = Su x Sv (not normalised).
      s1421(impl_->surface, 1, uv, &left_u, &left_v, d, n, &status);
      check(status, "s1421", u);
      out[k] = {d[0], d[1], d[2]};
      normals[k++] = unit(n);
    }
}

}  // namespace gllab::bench
