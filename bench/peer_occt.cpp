// bench/peer_occt.cpp — OpenCASCADE (Debian libocct-*-dev), see peers.h.
// Compiled only when CMake found OpenCASCADE's FoundationClasses and ModelingData.
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <cmath>

#include "peers.h"

namespace gllab::bench {

using spline::Vec3;

namespace {

Vec3 vec3(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

Vec3 unit_normal(const gp_Vec& du, const gp_Vec& dv) {
  const gp_XYZ n = du.XYZ() ^ dv.XYZ();
  const double length = n.Modulus();
  return {n.X() / length, n.Y() / length, n.Z() / length};
}

// OCCT keeps distinct knots and their multiplicities (1-based arrays).
struct OcctKnots {
  TColStd_Array1OfReal knots;
  TColStd_Array1OfInteger mults;
};

OcctKnots occt_knots(const std::vector<double>& U) {
  std::vector<double> values;
  std::vector<int> counts;
  for (double u : U) {
    if (!values.empty() && values.back() == u) {
      ++counts.back();
    } else {
      values.push_back(u);
      counts.push_back(1);
    }
  }
  OcctKnots k{TColStd_Array1OfReal(1, int(values.size())), TColStd_Array1OfInteger(1, int(values.size()))};
  for (std::size_t i = 0; i < values.size(); ++i) {
    k.knots.SetValue(int(i) + 1, values[i]);
    k.mults.SetValue(int(i) + 1, counts[i]);
  }
  return k;
}

}  // namespace

struct OcctPeer::Impl {
  Handle(Geom_BSplineCurve) curve;
  Handle(Geom_BSplineSurface) surface;
  GeomAdaptor_Curve curve_adaptor;
  GeomAdaptor_Surface surface_adaptor;
};

OcctPeer::OcctPeer(const BenchData& data) : impl_(std::make_unique<Impl>()) {
  const auto& c = data.curve;
  const int n = int(c.P.size());
  TColgp_Array1OfPnt poles(1, n);
  TColStd_Array1OfReal weights(1, n);
  for (int i = 0; i < n; ++i) {
    const Vec3& P = c.P[std::size_t(i)];
    poles.SetValue(i + 1, gp_Pnt(P.x, P.y, P.z));
    weights.SetValue(i + 1, c.w[std::size_t(i)]);
  }
  const OcctKnots ck = occt_knots(c.U);
  impl_->curve = new Geom_BSplineCurve(poles, weights, ck.knots, ck.mults, c.p);
  impl_->curve_adaptor.Load(impl_->curve);

  const auto& s = data.surface;
  TColgp_Array2OfPnt spoles(1, s.nu, 1, s.nv);
  TColStd_Array2OfReal sweights(1, s.nu, 1, s.nv);
  for (int i = 0; i < s.nu; ++i)
    for (int j = 0; j < s.nv; ++j) {
      const Vec3& P = s.point(i, j);
      spoles.SetValue(i + 1, j + 1, gp_Pnt(P.x, P.y, P.z));
      sweights.SetValue(i + 1, j + 1, s.weight(i, j));
    }
  const OcctKnots uk = occt_knots(s.U), vk = occt_knots(s.V);
  impl_->surface = new Geom_BSplineSurface(spoles, sweights, uk.knots, vk.knots, uk.mults, vk.mults, s.p, s.q);
  impl_->surface_adaptor.Load(impl_->surface);
}

OcctPeer::~OcctPeer() = default;

void OcctPeer::curve_points(Via via, const std::vector<double>& u, Points& out) {
  gp_Pnt P;
  if (via == Via::kGeom) {
    const Geom_BSplineCurve& curve = *impl_->curve;
    for (std::size_t k = 0; k < u.size(); ++k) {
      curve.D0(u[k], P);
      out[k] = vec3(P.XYZ());
    }
  } else {
    const GeomAdaptor_Curve& curve = impl_->curve_adaptor;
    for (std::size_t k = 0; k < u.size(); ++k) {
      curve.D0(u[k], P);
      out[k] = vec3(P.XYZ());
    }
  }
}

void OcctPeer::curve_derivs(Via via, const std::vector<double>& u, Points& out, Points& derivs) {
  gp_Pnt P;
  gp_Vec D;
  if (via == Via::kGeom) {
    const Geom_BSplineCurve& curve = *impl_->curve;
    for (std::size_t k = 0; k < u.size(); ++k) {
      curve.D1(u[k], P, D);
      out[k] = vec3(P.XYZ());
      derivs[k] = vec3(D.XYZ());
    }
  } else {
    const GeomAdaptor_Curve& curve = impl_->curve_adaptor;
    for (std::size_t k = 0; k < u.size(); ++k) {
      curve.D1(u[k], P, D);
      out[k] = vec3(P.XYZ());
      derivs[k] = vec3(D.XYZ());
    }
  }
}

void OcctPeer::surface_normals(Via via, const std::vector<double>& us, const std::vector<double>& vs, Points& out,
                               Points& normals) {
  gp_Pnt P;
  gp_Vec du, dv;
  std::size_t k = 0;
  if (via == Via::kGeom) {
    const Geom_BSplineSurface& surface = *impl_->surface;
    for (double u : us)
      for (double v : vs) {
        surface.D1(u, v, P, du, dv);
        out[k] = vec3(P.XYZ());
        normals[k++] = unit_normal(du, dv);
      }
  } else {
    const GeomAdaptor_Surface& surface = impl_->surface_adaptor;
    for (double u : us)
      for (double v : vs) {
        surface.D1(u, v, P, du, dv);
        out[k] = vec3(P.XYZ());
        normals[k++] = unit_normal(du, dv);
      }
  }
}

}  // namespace gllab::bench
