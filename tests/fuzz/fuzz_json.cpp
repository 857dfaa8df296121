// tests/fuzz/fuzz_json.cpp — the JSON readers of common/io and the core on what they load.
//
// The input is the text of a file. Its "type" picks the reader, as a tool would:
// "csg" parse_csg, "blob_scene" parse_blob_scene, no "type" at all parse_points
// (splinetool interpolate's points file), anything else parse_any (spline files).
// A refusal must be an io::FileError of one line. What loads must then:
//   - write back and read again to the same text (to_text(to_json(x)) is a fixed
//     point after one round: the format prints every double bit-identically);
//   - go through the core at a fixed, small number of places (bounded work per
//     input): a curve at 7 parameters with derivatives, a surface on a 3 x 3 grid,
//     a trimmed surface's loops validated and 9 inside tests, a CSG tree's 8
//     classified points and 2 rays, a blob field's value and gradient at 8 points,
//     a points file's chordal parameters and natural cubic spline.
//   The core may refuse (std::invalid_argument, one line); it may not crash.
#include <cstddef>
#include <cstdint>
#include <string>
#include <typeinfo>
#include <variant>

#include "fuzz_common.h"
#include "io/csg_json.h"
#include "io/field_json.h"
#include "io/spline_json.h"
#include "space/csg.h"
#include "spline/bezier.h"
#include "spline/bspline.h"
#include "spline/cubic_spline.h"
#include "spline/parameterization.h"
#include "spline/surface.h"
#include "spline/trim.h"

namespace {

using namespace gllab;
using gllab::fuzz::check;
using gllab::fuzz::fail;

constexpr double kFractions[] = {0.0, 0.125, 0.25, 0.5, 0.6180339887498949, 0.875, 1.0};

double lerp(double a, double b, double f) { return a + (b - a) * f; }

/// Runs core work; the core may refuse with a one-line std::invalid_argument.
template <class Work>
void core(const char* what, Work work) {
  try {
    work();
  } catch (const std::invalid_argument& e) {
    gllab::fuzz::check_one_line(e, what);
  } catch (const std::exception& e) {
    fail(std::string(what) + " threw " + typeid(e).name() + ": " + e.what());
  }
}

void use(const spline::BsplineCurve& c) {
  core("curve", [&] {
    spline::validate(c);
    const spline::ParamInterval d = spline::domain(c);
    const int derivs = c.p < 2 ? c.p : 2;
    for (double f : kFractions) {
      const double u = lerp(d.a, d.b, f);
      if (c.rational()) {
        (void)spline::rational_curve_point(c, u);
        (void)spline::rational_curve_derivs(c, u, derivs);
      } else {
        (void)spline::curve_point(c, u);
        (void)spline::curve_derivs(c, u, derivs);
      }
    }
    (void)spline::uniform_params(c, 5);
    (void)spline::reversed(c);
  });
}

void use(const spline::BezierCurve& c) {
  core("bezier", [&] {
    spline::validate(c);
    for (double f : kFractions) {
      const double t = lerp(c.a, c.b, f);
      (void)spline::bezier_point(c, t);
      if (c.P.size() > 1) (void)spline::bezier_derivative_at(c, t, 1);
    }
  });
}

void use(const spline::BsplineSurface& s) {
  core("surface", [&] {
    spline::validate(s);
    const spline::ParamInterval du = spline::domain_u(s), dv = spline::domain_v(s);
    for (double fu : {0.0, 0.5, 1.0})
      for (double fv : {0.0, 0.3819660112501051, 1.0})
        (void)spline::surface_point(s, lerp(du.a, du.b, fu), lerp(dv.a, dv.b, fv));
  });
  if (s.trims.empty()) return;
  core("trims", [&] {
    const spline::ParamInterval du = spline::domain_u(s), dv = spline::domain_v(s);
    const spline::UvDomain domain{du.a, du.b, dv.a, dv.b};
    const std::vector<spline::TrimPolygon> polygons = spline::validate_trim_loops(s.trims, domain);
    for (double fu : {0.1, 0.5, 0.9})
      for (double fv : {0.2, 0.5, 0.7})
        (void)spline::inside_trimmed(polygons, {lerp(du.a, du.b, fu), lerp(dv.a, dv.b, fv)});
  });
}

void use(const io::PointsFile& points) {
  core("points", [&] {
    const std::vector<double> t = spline::parameters(points.points, spline::Parameterization::kChordal);
    const spline::CubicSpline s = spline::natural_cubic_spline(t, points.points);
    for (double f : kFractions) (void)spline::spline_point(s, lerp(t.front(), t.back(), f));
  });
}

void use(const io::CsgFile& csg) {
  core("csg", [&] {
    const space::Box3 box = csg.tree.bounds();
    for (int corner = 0; corner < 8; ++corner) {
      const spline::Vec3 p{lerp(box.lo.x, box.hi.x, corner & 1 ? 0.75 : 0.25),
                           lerp(box.lo.y, box.hi.y, corner & 2 ? 0.75 : 0.25),
                           lerp(box.lo.z, box.hi.z, corner & 4 ? 0.75 : 0.25)};
      (void)space::classify(csg.tree, p);
    }
    (void)space::first_hit(csg.tree, {0, 0, 10}, {0, 0, -1});
    (void)space::ray_spans(csg.tree, {-10, 0.1, 0.2}, {1, 0, 0});
  });
}

void use(const io::BlobScene& scene) {
  core("blob_scene", [&] {
    const io::Box box = io::bounds_of(scene);
    for (int corner = 0; corner < 8; ++corner) {
      const spline::Vec3 p{lerp(box.lo.x, box.hi.x, corner & 1 ? 0.7 : 0.3),
                           lerp(box.lo.y, box.hi.y, corner & 2 ? 0.7 : 0.3),
                           lerp(box.lo.z, box.hi.z, corner & 4 ? 0.7 : 0.3)};
      (void)scene.field.value(p);
      (void)scene.field.gradient(p);
    }
  });
}

/// Writes what loaded, reads it again, writes again: the two texts must agree and
/// the second read must succeed (a file the writer makes is a file the reader takes).
template <class Parse, class Value>
void round_trip(const char* what, Parse parse, const Value& loaded) {
  std::string first;
  try {
    first = io::to_text(io::to_json(loaded));
  } catch (const std::exception& e) {
    fail(std::string(what) + ": writing what loaded threw " + typeid(e).name() + ": " + e.what());
  }
  std::string second;
  try {
    second = io::to_text(io::to_json(parse(first, "round_trip")));
  } catch (const std::exception& e) {
    fail(std::string(what) + ": reading back what was written threw " + typeid(e).name() + ": " +
         e.what() + "\nwritten:\n" + first);
  }
  check(first == second, std::string(what) + ": round trip changed the text\nfirst:\n" + first +
                             "\nsecond:\n" + second);
}

/// Loads with parse; a refusal must be a one-line io::FileError.
template <class Parse, class Use>
void load(const char* what, const std::string& text, Parse parse, Use use_loaded) {
  try {
    const auto loaded = parse(text, "fuzz.json");
    round_trip(what, parse, loaded);
    use_loaded(loaded);
  } catch (const io::FileError& e) {
    gllab::fuzz::check_one_line(e, what);
  } catch (const std::exception& e) {
    fail(std::string(what) + " threw " + typeid(e).name() + " (not io::FileError): " + e.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (text.find("\"csg\"") != std::string::npos) {
    load("parse_csg", text, [](const std::string& t, const std::string& s) { return io::parse_csg(t, s); },
         [](const io::CsgFile& c) { use(c); });
  } else if (text.find("\"blob_scene\"") != std::string::npos) {
    load("parse_blob_scene", text,
         [](const std::string& t, const std::string& s) { return io::parse_blob_scene(t, s); },
         [](const io::BlobScene& b) { use(b); });
  } else if (text.find("\"type\"") == std::string::npos) {
    load("parse_points", text, [](const std::string& t, const std::string& s) { return io::parse_points(t, s); },
         [](const io::PointsFile& p) { use(p); });
  } else {
    load("parse_any", text, [](const std::string& t, const std::string& s) { return io::parse_any(t, s); },
         [](const io::SplineFile& f) { std::visit([](const auto& x) { use(x); }, f); });
  }
  return 0;
}
