// bench/peers.h — the libraries the spline core is measured against.
//
// Each peer converts the bench data into its own form once (outside the timed
// part) and then evaluates the same curve at the same parameters, or the same
// surface on the same grid, writing Vec3 points (and derivatives or unit
// normals) like the own core does. GLU chooses its own parameters; it is given
// a sampling step that makes it return as many points as the others.
//
// GLU is always there (the project needs it). SISL and OpenCASCADE are
// optional: their sources are compiled only when CMake found them, and then
// GLLAB_BENCH_HAVE_SISL / GLLAB_BENCH_HAVE_OCCT are defined.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "bench_data.h"
#include "spline/vec.h"

namespace gllab::bench {

using Points = std::vector<spline::Vec3>;

/// GLU 9.0 NURBS in tessellator mode (GLU_NURBS_TESSELLATOR, GLU_DOMAIN_DISTANCE):
/// no GL context; vertices and normals come back through callbacks (curve
/// vertices homogeneous, surface vertices projected: see peer_glu.cpp). GLU
/// takes floats, so it agrees with the others to float precision only.
class GluPeer {
 public:
  /// Picks the U/V steps so that GLU returns (close to) as many vertices as
  /// the others compute: kCurveParams for the curve, kGridSide^2 for the surface.
  explicit GluPeer(const BenchData& data);
  ~GluPeer();
  GluPeer(const GluPeer&) = delete;
  GluPeer& operator=(const GluPeer&) = delete;

  /// One tessellation of the curve; returns the number of vertices GLU returned.
  std::size_t curve_points(Points& out);
  /// One tessellation of the surface with normals (GLU computes them when a
  /// normal callback is set); returns the number of vertices.
  std::size_t surface_normals(Points& out, Points& normals);

  /// For the agreement check: the same tessellations with a texture-coordinate
  /// map whose control points are the Greville abscissae, so that GLU also
  /// returns the parameter (u) or (u, v) of every vertex.
  struct Samples {
    std::vector<double> u, v;
    Points points, normals;
  };
  Samples curve_samples();
  Samples surface_samples();

  double curve_step() const;
  double surface_step() const;
  /// Distinct (u, v) among the surface vertices: GLU sends a vertex once per
  /// triangle strip that uses it, so fewer points than vertices are evaluated.
  std::size_t surface_distinct() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

#ifdef GLLAB_BENCH_HAVE_SISL
/// SISL 4.6 (SINTEF): s1221 evaluates a curve and its derivatives, s1421 a
/// surface, its partial derivatives and its (unnormalised) normal. Both keep
/// the knot interval of the previous call (ileft), so sorted parameters cost
/// no search. Rational coefficients are given premultiplied (w x, w y, w z, w).
class SislPeer {
 public:
  explicit SislPeer(const BenchData& data);
  ~SislPeer();
  SislPeer(const SislPeer&) = delete;
  SislPeer& operator=(const SislPeer&) = delete;

  void curve_points(const std::vector<double>& u, Points& out);
  void curve_derivs(const std::vector<double>& u, Points& out, Points& derivs);
  void surface_normals(const std::vector<double>& us, const std::vector<double>& vs, Points& out, Points& normals);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
#endif

#ifdef GLLAB_BENCH_HAVE_OCCT
/// OpenCASCADE 7.6: Geom_BSplineCurve / Geom_BSplineSurface evaluated directly
/// (D0, D1) and through GeomAdaptor_Curve / GeomAdaptor_Surface, which cache
/// the polynomial of the current span. Normals: D1U ^ D1V, normalised.
class OcctPeer {
 public:
  explicit OcctPeer(const BenchData& data);
  ~OcctPeer();
  OcctPeer(const OcctPeer&) = delete;
  OcctPeer& operator=(const OcctPeer&) = delete;

  enum class Via { kGeom, kAdaptor };
  void curve_points(Via via, const std::vector<double>& u, Points& out);
  void curve_derivs(Via via, const std::vector<double>& u, Points& out, Points& derivs);
  void surface_normals(Via via, const std::vector<double>& us, const std::vector<double>& vs, Points& out,
                       Points& normals);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
#endif

}  // namespace gllab::bench
