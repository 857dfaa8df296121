// tools/splinetool.cpp — the spline core from the command line.
//
//   splinetool eval FILE --at 0,0.25,1 [--derivatives K]     points (and derivatives)
//   splinetool insert-knot FILE --knot U [--times R]         the refined curve
//   splinetool elevate FILE [--times T]                      the curve at degree p + T
//   splinetool split FILE --at U                             {"curves": [a, b]}
//   splinetool to-bezier FILE                                {"curves": [...]}
//   splinetool interpolate POINTS.json --method M [--param P]
//   splinetool tessellate FILE --tolerance T [--obj OUT.obj]
//
// Files use the format of common/io/README.md; results go to stdout as JSON.
// Errors: one line on stderr, exit 2 for bad input or usage, 1 when an output
// file cannot be written, 0 otherwise. `splinetool COMMAND --help` explains each.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "cli.h"
#include "io/obj.h"
#include "io/spline_json.h"
#include "spline/bezier.h"
#include "spline/bspline.h"
#include "spline/cubic_spline.h"
#include "spline/errors.h"
#include "spline/interpolation.h"
#include "spline/parameterization.h"
#include "spline/surface.h"
#include "spline/tessellate.h"

namespace {

using gllab::cli::kBadInput, gllab::cli::kFailed, gllab::cli::kOk;
using gllab::cli::OutputError, gllab::cli::UsageError;
using gllab::cli::parse_count, gllab::cli::parse_number;
using gllab::io::FileError;
using gllab::io::Json;
using gllab::io::shortest_text;
using gllab::io::SplineFile;
using gllab::io::to_json;
using namespace gllab::spline;

// --- command line ---------------------------------------------------------------

struct Command {
  const char* name;
  const char* summary;
  const char* help;                      // printed by `splinetool NAME --help`
  std::vector<std::string> options;      // each takes a value: --name VALUE or --name=VALUE
  std::function<int(const std::string& file, const std::map<std::string, std::string>& options)> run;
};

/// The text of an option, or none.
std::optional<std::string> option(const std::map<std::string, std::string>& options, const std::string& name) {
  const auto it = options.find(name);
  if (it == options.end()) return std::nullopt;
  return it->second;
}

std::vector<std::string> split_list(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.push_back("");
  return parts;
}

/// The most parameter values one call evaluates (--at's list, --samples).
constexpr int kMaxParameters = 1000000;

/// count parameters from a to b, both ends included (the last is exactly b).
std::vector<double> even_parameters(double a, double b, int count) {
  std::vector<double> t;
  for (int i = 0; i < count; ++i) t.push_back(i + 1 == count ? b : a + (b - a) * i / (count - 1));
  return t;
}

void require_inside(double u, ParamInterval dom, const std::string& what) {
  if (!(u >= dom.a && u <= dom.b))
    throw UsageError(what + ": " + shortest_text(u) + " is outside the domain [" + shortest_text(dom.a) + ", " +
                     shortest_text(dom.b) + "]");
}

// --- JSON output -----------------------------------------------------------------

std::string point_text(const Vec3& p) {
  return "(" + shortest_text(p.x) + ", " + shortest_text(p.y) + ", " + shortest_text(p.z) + ")";
}

Json point_json(const Vec3& p, int dimension) {
  for (double c : {p.x, p.y, p.z})
    if (!std::isfinite(c))
      fail(ErrorCode::kNotFinite,
           "a result is not finite: " + point_text(p) + " (coordinates too large for doubles?)", {{"result", p}});
  Json out = Json::array({p.x, p.y});
  if (dimension == 3) out.push_back(p.z);
  return out;
}

int print(const Json& value) {
  std::cout << gllab::io::to_text(value);
  std::cout.flush();
  return kOk;
}

// --- reading -------------------------------------------------------------------------

/// The curve of a curve file; a Bézier curve comes back as the same curve in
/// B-spline form.
BsplineCurve curve_in(const SplineFile& file, const std::string& path, const std::string& command) {
  if (const auto* c = std::get_if<BsplineCurve>(&file)) return *c;
  if (const auto* b = std::get_if<BezierCurve>(&file)) return gllab::io::as_bspline(*b);
  throw FileError(path, "type", "\"bspline_surface\": " + command + " works on curves");
}

/// A curve as eval and tessellate see it: its domain and its derivatives
/// C(u), C'(u), ..., C^(K)(u). A B-spline goes through de Boor (A3.2, or A4.2
/// when rational), a Bézier segment through de Casteljau (any degree).
struct CurveView {
  ParamInterval domain;
  int dimension = 3;
  std::function<std::vector<Vec3>(double u, int K)> derivs;
};

CurveView curve_view(const SplineFile& file, const std::string& path, const std::string& command) {
  CurveView view;
  if (const auto* b = std::get_if<BezierCurve>(&file)) {
    view.domain = {b->a, b->b};
    view.dimension = b->dimension;
    view.derivs = [curve = *b](double u, int K) { return bezier_derivatives(curve, u, K); };
  } else {
    // Checked once here; each evaluation then checks only u (no O(n) pass per point).
    const auto curve = std::make_shared<const CurveEvaluator>(curve_in(file, path, command));
    view.domain = curve->domain();
    view.dimension = curve->curve().dimension;
    view.derivs = [curve](double u, int K) { return curve->derivs(u, K); };
  }
  return view;
}

// --- eval ----------------------------------------------------------------------------

std::vector<double> curve_parameters(const std::map<std::string, std::string>& options, ParamInterval dom) {
  const auto at = option(options, "at");
  const auto samples = option(options, "samples");
  if (at && samples) throw UsageError("give --at or --samples, not both");
  if (samples) return even_parameters(dom.a, dom.b, parse_count(*samples, "--samples", 2, kMaxParameters));
  if (!at) throw UsageError("eval needs --at U,U,... or --samples N");
  std::vector<double> t;
  const std::vector<std::string> parts = split_list(*at, ',');
  if (parts.size() > static_cast<std::size_t>(kMaxParameters))
    throw UsageError("--at: " + std::to_string(parts.size()) + " parameters, more than the limit of " +
                     std::to_string(kMaxParameters) + " per call");
  for (const std::string& part : parts) {
    const double u = parse_number(part, "--at");
    require_inside(u, dom, "--at");
    t.push_back(u);
  }
  return t;
}

int eval_curve(const CurveView& c, const std::map<std::string, std::string>& options) {
  const auto derivatives_text = option(options, "derivatives");
  const int K = derivatives_text ? parse_count(*derivatives_text, "--derivatives", 0, 30) : 0;
  const std::vector<double> t = curve_parameters(options, c.domain);
  Json points = Json::array(), derivatives = Json::array();
  for (int k = 0; k < K; ++k) derivatives.push_back(Json::array());
  for (double u : t) {
    const std::vector<Vec3> CK = c.derivs(u, K);
    points.push_back(point_json(CK[0], c.dimension));
    for (std::size_t k = 1; k < CK.size(); ++k) derivatives[k - 1].push_back(point_json(CK[k], c.dimension));
  }
  Json out = Json::object();
  out["points"] = std::move(points);
  if (K > 0) out["derivatives"] = std::move(derivatives);
  out["parameters"] = t;
  return print(out);
}

/// (u, v) pairs from --at u:v,u:v or an N x N grid from --samples N (u outer).
std::vector<std::pair<double, double>> surface_parameters(const std::map<std::string, std::string>& options,
                                                          ParamInterval du, ParamInterval dv) {
  const auto at = option(options, "at");
  const auto samples = option(options, "samples");
  if (at && samples) throw UsageError("give --at or --samples, not both");
  std::vector<std::pair<double, double>> uv;
  if (samples) {
    const int count = parse_count(*samples, "--samples", 2, 1000);
    for (double u : even_parameters(du.a, du.b, count))
      for (double v : even_parameters(dv.a, dv.b, count)) uv.emplace_back(u, v);
    return uv;
  }
  if (!at) throw UsageError("eval needs --at u:v,u:v,... or --samples N");
  for (const std::string& part : split_list(*at, ',')) {
    const std::size_t colon = part.find(':');
    if (colon == std::string::npos) throw UsageError("--at: '" + part + "' is not u:v (a surface takes u:v pairs)");
    const double u = parse_number(part.substr(0, colon), "--at (u)");
    const double v = parse_number(part.substr(colon + 1), "--at (v)");
    require_inside(u, du, "--at (u)");
    require_inside(v, dv, "--at (v)");
    uv.emplace_back(u, v);
  }
  return uv;
}

int eval_surface(const BsplineSurface& s, const std::map<std::string, std::string>& options) {
  if (option(options, "derivatives"))
    throw UsageError("--derivatives is for curves (a surface prints du and dv)");
  const auto uv = surface_parameters(options, domain_u(s), domain_v(s));
  Json points = Json::array(), normals = Json::array(), du = Json::array(), dv = Json::array(),
       params = Json::array();
  for (const auto& [u, v] : uv) {
    const std::vector<std::vector<Vec3>> SKL = surface_derivs(s, u, v, 1);
    points.push_back(point_json(SKL[0][0], 3));
    du.push_back(point_json(SKL[1][0], 3));
    dv.push_back(point_json(SKL[0][1], 3));
    // The unit normal du x dv (with surface.h's fallback at a pole).
    normals.push_back(point_json(surface_normal(s, u, v), 3));
    params.push_back(Json::array({u, v}));
  }
  Json out = Json::object();
  out["points"] = std::move(points);
  out["normals"] = std::move(normals);
  out["du"] = std::move(du);
  out["dv"] = std::move(dv);
  out["parameters"] = std::move(params);
  return print(out);
}

int eval(const std::string& path, const std::map<std::string, std::string>& options) {
  const SplineFile file = gllab::io::read_any(path);
  if (const auto* s = std::get_if<BsplineSurface>(&file)) return eval_surface(*s, options);
  return eval_curve(curve_view(file, path, "eval"), options);
}

// --- refinement and conversion ---------------------------------------------------------

int insert_knot(const std::string& path, const std::map<std::string, std::string>& options) {
  BsplineCurve c = curve_in(gllab::io::read_any(path), path, "insert-knot");
  const auto knot = option(options, "knot");
  if (!knot) throw UsageError("insert-knot needs --knot U");
  const double u = parse_number(*knot, "--knot");
  require_inside(u, domain(c), "--knot");
  const int r = option(options, "times") ? parse_count(*option(options, "times"), "--times", 1, kMaxDegree) : 1;
  BsplineCurve refined = knot_insert(c, u, r);
  refined.dimension = c.dimension;
  return print(to_json(refined));
}

int elevate(const std::string& path, const std::map<std::string, std::string>& options) {
  const SplineFile file = gllab::io::read_any(path);
  const int t = option(options, "times") ? parse_count(*option(options, "times"), "--times", 0, kMaxDegree) : 1;
  if (const auto* b = std::get_if<BezierCurve>(&file)) {
    BezierCurve e = degree_elevate(*b, t);
    e.dimension = b->dimension;
    return print(to_json(e));
  }
  const BsplineCurve c = curve_in(file, path, "elevate");
  BsplineCurve e = degree_elevate(c, t);
  e.dimension = c.dimension;
  return print(to_json(e));
}

int split_curve(const std::string& path, const std::map<std::string, std::string>& options) {
  const SplineFile file = gllab::io::read_any(path);
  const auto at = option(options, "at");
  if (!at) throw UsageError("split needs --at U");
  const double u = parse_number(*at, "--at");
  Json curves = Json::array();
  if (const auto* b = std::get_if<BezierCurve>(&file)) {
    if (!(u > b->a && u < b->b))
      throw UsageError("--at: " + shortest_text(u) + " is not inside the interval (" + shortest_text(b->a) + ", " +
                       shortest_text(b->b) + ")");
    BezierSplit halves = subdivide(*b, u);
    halves.left.dimension = halves.right.dimension = b->dimension;
    curves.push_back(to_json(halves.left));
    curves.push_back(to_json(halves.right));
  } else {
    const BsplineCurve c = curve_in(file, path, "split");
    const ParamInterval dom = domain(c);
    if (!(u > dom.a && u < dom.b))
      throw UsageError("--at: " + shortest_text(u) + " is not inside the domain (" + shortest_text(dom.a) + ", " +
                       shortest_text(dom.b) + ")");
    auto [first, second] = split(c, u);
    first.dimension = second.dimension = c.dimension;
    curves.push_back(to_json(first));
    curves.push_back(to_json(second));
  }
  Json out = Json::object();
  out["curves"] = std::move(curves);
  return print(out);
}

int to_bezier(const std::string& path, const std::map<std::string, std::string>&) {
  const SplineFile file = gllab::io::read_any(path);
  Json curves = Json::array();
  if (const auto* b = std::get_if<BezierCurve>(&file)) {
    curves.push_back(to_json(*b));
  } else {
    const BsplineCurve c = curve_in(file, path, "to-bezier");
    if (c.rational()) {
      // A BezierCurve has no weights: a rational piece stays a one-span
      // bspline_curve (knots a x (p+1), b x (p+1)), the rational Bézier form.
      for (BsplineCurve piece : bezier_segments(c)) {
        piece.dimension = c.dimension;
        curves.push_back(to_json(piece));
      }
    } else {
      for (BezierCurve piece : bezier_decompose(c)) {
        piece.dimension = c.dimension;
        curves.push_back(to_json(piece));
      }
    }
  }
  Json out = Json::object();
  out["curves"] = std::move(curves);
  return print(out);
}

// --- interpolate -------------------------------------------------------------------------

Parameterization parameterization_named(const std::string& name) {
  if (name == "uniform") return Parameterization::kUniform;
  if (name == "chordal") return Parameterization::kChordal;
  if (name == "centripetal") return Parameterization::kCentripetal;
  if (name == "foley") return Parameterization::kFoley;
  if (name == "nielson") return Parameterization::kNielson;
  throw UsageError("--param: '" + name + "' (one of uniform, chordal, centripetal, foley, nielson)");
}

/// q(s) = (s - r) p(s) for ascending monomial coefficients.
template <class T>
std::vector<T> times_linear(const std::vector<T>& p, double r) {
  std::vector<T> q(p.size() + 1);
  for (std::size_t j = 0; j < p.size(); ++j) {
    q[j + 1] += p[j];
    q[j] -= r * p[j];
  }
  return q;
}

/// Lagrange form -> monomial form: sum_i f_i L_i(s), each L_i(s) =
/// prod_{k != i} (s - s_k) / (s_i - s_k) multiplied out (ch. 1 §1.6, Theorem 2).
std::vector<Vec3> monomial_from_lagrange(const std::vector<double>& s, const std::vector<Vec3>& f) {
  std::vector<Vec3> c(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    std::vector<double> L = {1};
    double denominator = 1;
    for (std::size_t k = 0; k < s.size(); ++k) {
      if (k == i) continue;
      L = times_linear(L, s[k]);
      denominator *= s[i] - s[k];
    }
    for (std::size_t j = 0; j < L.size(); ++j)
      c[j] += (L[j] / denominator) * f[i];
  }
  return c;
}

/// Newton form -> monomial form by the nested (Horner) scheme:
/// p = a_n; p = p (s - s_k) + a_k for k = n-1 .. 0 (ch. 1 §1.6, Newton interpolation).
std::vector<Vec3> monomial_from_newton(const std::vector<double>& s, const std::vector<Vec3>& a) {
  std::vector<Vec3> p = {a.back()};
  for (std::size_t k = a.size() - 1; k-- > 0;) {
    p = times_linear(p, s[k]);
    p[0] += a[k];
  }
  return p;
}

int interpolate(const std::string& path, const std::map<std::string, std::string>& options) {
  const gllab::io::PointsFile input = gllab::io::read_points(path);
  const auto method = option(options, "method");
  if (!method) throw UsageError("interpolate needs --method natural|clamped|periodic|lagrange|newton|bezier");
  const Parameterization param = parameterization_named(option(options, "param").value_or("chordal"));
  const std::vector<Vec3>& P = input.points;
  const bool closed = *method == "periodic";
  const std::vector<double> t = parameters(P, param, closed);

  Json curve;
  if (*method == "natural" || *method == "clamped" || *method == "periodic") {
    CubicSpline s;
    if (*method == "natural") {
      s = natural_cubic_spline(t, P);
    } else if (*method == "clamped") {
      if (!input.start_tangent || !input.end_tangent)
        throw FileError(path, input.start_tangent ? "end_tangent" : "start_tangent",
                        "missing (--method clamped needs start_tangent and end_tangent)");
      s = clamped_cubic_spline(t, P, *input.start_tangent, *input.end_tangent);
    } else {
      s = periodic_cubic_spline(t, P);
    }
    BsplineCurve c = bspline_curve(s);
    c.dimension = input.dimension;
    curve = to_json(c);
  } else if (*method == "lagrange" || *method == "newton" || *method == "bezier") {
    const double a = t.front(), b = t.back();
    BezierCurve c;
    if (*method == "bezier") {
      c = bezier_interpolate(P, t, a, b);
    } else {
      // The polynomial in the local parameter s = (t - a) / (b - a) in [0, 1]:
      // its Bézier points on [0, 1] are those of the curve on [a, b], and
      // powers of s stay well scaled where powers of t may not.
      std::vector<double> s;
      for (double ti : t) s.push_back((ti - a) / (b - a));
      std::vector<Vec3> monomial;
      if (*method == "lagrange") {
        monomial = monomial_from_lagrange(s, P);
      } else {
        NewtonInterpolant<Vec3> newton;
        for (std::size_t i = 0; i < P.size(); ++i) newton.add_node(s[i], P[i]);
        monomial = monomial_from_newton(s, newton.coefficients());
      }
      c = bezier_from_monomial(monomial, 0, 1);
      c.a = a;
      c.b = b;
    }
    c.dimension = input.dimension;
    curve = to_json(c);
  } else {
    throw UsageError("--method: '" + *method + "' (one of natural, clamped, periodic, lagrange, newton, bezier)");
  }
  curve["parameters"] = t;
  return print(curve);
}

// --- tessellate ----------------------------------------------------------------------------

int tessellate(const std::string& path, const std::map<std::string, std::string>& options) {
  const SplineFile file = gllab::io::read_any(path);
  const auto tolerance_text = option(options, "tolerance");
  if (!tolerance_text) throw UsageError("tessellate needs --tolerance T (T > 0, in object units)");
  const double tolerance = parse_number(*tolerance_text, "--tolerance");
  if (!(tolerance > 0)) throw UsageError("--tolerance: " + shortest_text(tolerance) + " (must be > 0)");
  const auto obj = option(options, "obj");
  const std::string comment = "splinetool tessellate " + path + " --tolerance " + *tolerance_text;

  Json out = Json::object();
  auto write = [&](const auto& geometry) {
    if (!obj) return;
    try {
      gllab::io::write_obj(*obj, geometry, comment);
    } catch (const FileError& e) {
      throw OutputError(e.what());
    }
  };
  if (const auto* s = std::get_if<BsplineSurface>(&file)) {
    // Adaptive quadtree to the parametric error, trims honoured (tessellate.h).
    const Mesh mesh =
        tessellate_surface(surface_evaluator(*s), uv_domain(*s), TessellationOptions::adaptive(tolerance), s->trims);
    write(mesh);
    out["type"] = "mesh";
    out["vertices"] = mesh.positions.size();
    out["triangles"] = mesh.triangles.size();
    out["boundary_edges"] = boundary_edges(mesh).size();
    out["area"] = mesh_area(mesh);
  } else {
    // Recursive bisection until every chord is within the tolerance (chordal error).
    const CurveView c = curve_view(file, path, "tessellate");
    FlattenOptions flatten;
    flatten.tolerance = tolerance;
    flatten.error = ChordError::Chordal;
    std::vector<Vec3> polyline;
    const auto point = [&c](double t) { return c.derivs(t, 0)[0]; };
    for (const CurveSample& sample : flatten_curve(point, c.domain.a, c.domain.b, flatten))
      polyline.push_back(sample.point);
    write(polyline);
    double length = 0;
    for (std::size_t i = 1; i < polyline.size(); ++i) length += norm(polyline[i] - polyline[i - 1]);
    out["type"] = "polyline";
    out["vertices"] = polyline.size();
    out["segments"] = polyline.size() - 1;
    out["length"] = length;
  }
  out["tolerance"] = tolerance;
  if (obj) out["obj"] = *obj;
  return print(out);
}

// --- the command table ---------------------------------------------------------------

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"eval", "points (and derivatives) of a curve at parameters",
       "usage: splinetool eval FILE (--at U,U,... | --samples N) [--derivatives K]\n"
       "       splinetool eval SURFACE_FILE (--at u:v,u:v,... | --samples N)\n"
       "\n"
       "A curve (bspline_curve or bezier_curve) prints\n"
       "  {\"points\": [...], \"derivatives\": [[...], ...], \"parameters\": [...]}\n"
       "derivatives[k-1][i] is the k-th derivative at the i-th parameter (only with\n"
       "--derivatives K >= 1), in the dimension of the points.\n"
       "A surface (bspline_surface; trims are ignored) prints\n"
       "  {\"points\": [...], \"normals\": [...], \"du\": [...], \"dv\": [...], \"parameters\": [[u, v], ...]}\n"
       "with the partial derivatives du = dS/du, dv = dS/dv and the unit normal du x dv.\n"
       "\n"
       "  --at U,U,...       curve parameters inside the domain [U[p], U[n+1]]\n"
       "  --at u:v,u:v,...   surface parameters inside [U[p], U[nu]] x [V[q], V[nv]]\n"
       "  --samples N        N >= 2 parameters evenly spaced over the domain, ends included\n"
       "                     (a surface: the N x N grid, u outer, v inner; N <= 1000)\n"
       "  --derivatives K    curves: also the derivatives of order 1..K (0..30, default 0)\n",
       {"at", "samples", "derivatives"}, eval},
      {"insert-knot", "insert a knot (the curve does not change)",
       "usage: splinetool insert-knot FILE --knot U [--times R]\n"
       "\n"
       "Inserts the knot U (inside the domain) R times (default 1; A5.1 CurveKnotIns,\n"
       "The NURBS Book p. 151) and prints the new bspline_curve. The multiplicity of U\n"
       "may not exceed the degree.\n",
       {"knot", "times"}, insert_knot},
      {"elevate", "raise the degree (the curve does not change)",
       "usage: splinetool elevate FILE [--times T]\n"
       "\n"
       "Prints the same curve at degree p + T (default T = 1; A5.9 DegreeElevateCurve,\n"
       "The NURBS Book p. 206). A bezier_curve stays a bezier_curve.\n",
       {"times"}, elevate},
      {"split", "split a curve in two at a parameter",
       "usage: splinetool split FILE --at U\n"
       "\n"
       "Prints {\"curves\": [first, second]}: first covers [start, U], second [U, end],\n"
       "both keep the original parameters. U must lie strictly inside the domain.\n",
       {"at"}, split_curve},
      {"to-bezier", "the Bézier pieces of a curve",
       "usage: splinetool to-bezier FILE\n"
       "\n"
       "Prints {\"curves\": [...]}, one piece per non-empty knot span (A5.6\n"
       "DecomposeCurve, The NURBS Book p. 173), each with its \"interval\". A rational\n"
       "curve's pieces are one-span bspline_curves with weights (a bezier_curve has none).\n",
       {}, to_bezier},
      {"interpolate", "a curve through points",
       "usage: splinetool interpolate POINTS.json --method M [--param P]\n"
       "\n"
       "POINTS.json: {\"points\": [[x, y], ...]} (or 3D); --method clamped also needs\n"
       "\"start_tangent\" and \"end_tangent\" there. Prints the curve in the file format\n"
       "plus \"parameters\": [t0, ..., tn] (closed: t0 .. t(n+1)).\n"
       "\n"
       "  --method natural    C2 cubic spline, S'' = 0 at both ends  -> bspline_curve on [t0, tn]\n"
       "           clamped    C2 cubic spline with the given end tangents (dX/dt)\n"
       "           periodic   closed C2 cubic spline (give the first point once) -> [t0, t(n+1)]\n"
       "           lagrange   the interpolating polynomial, from the Lagrange form -> bezier_curve\n"
       "           newton     the same polynomial, from the Newton form            -> bezier_curve\n"
       "           bezier     the same polynomial as the lecture's Bézier system    -> bezier_curve\n"
       "  --param uniform|chordal|centripetal|foley|nielson   the parameters t_i (default chordal)\n",
       {"method", "param"}, interpolate},
      {"tessellate", "a curve as a polyline, a surface as a triangle mesh",
       "usage: splinetool tessellate FILE --tolerance T [--obj OUT.obj]\n"
       "\n"
       "A curve becomes a polyline whose chords stay within T of the curve\n"
       "(recursive bisection); a surface becomes a triangle mesh with one unit normal\n"
       "per vertex, within T of the surface (parametric error, adaptive quadtree), with\n"
       "its trim loops cut out. Prints a summary:\n"
       "  curve:   {\"type\": \"polyline\", \"vertices\", \"segments\", \"length\", \"tolerance\"}\n"
       "  surface: {\"type\": \"mesh\", \"vertices\", \"triangles\", \"boundary_edges\", \"area\", \"tolerance\"}\n"
       "\n"
       "  --tolerance T   the largest distance from the curve or surface (> 0, object units)\n"
       "  --obj OUT.obj   also write Wavefront OBJ (v, vn, f a//a; a polyline as v and l),\n"
       "                  atomically; exit 1 when it cannot be written\n",
       {"tolerance", "obj"}, tessellate},
  };
  return table;
}

void print_overview(std::ostream& out) {
  out << "usage: splinetool COMMAND FILE [options]   (splinetool COMMAND --help for details)\n\n";
  for (const Command& c : commands())
    out << "  " << c.name << std::string(14 - std::string(c.name).size(), ' ') << c.summary << "\n";
  out << "\nFiles: common/io/README.md. Output: JSON on stdout. Errors: one line on stderr;\n"
         "exit 2 for bad input or usage, 1 when an output file cannot be written, 0 otherwise.\n";
}

int run(int argc, char** argv) {
  if (argc < 2) throw UsageError("no command (splinetool --help lists them)");
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    print_overview(std::cout);
    return kOk;
  }
  const Command* command = nullptr;
  for (const Command& c : commands())
    if (name == c.name) command = &c;
  if (!command) throw UsageError("unknown command '" + name + "' (splinetool --help lists them)");

  const gllab::cli::SubcommandArgs args =
      gllab::cli::parse_subcommand(argc, argv, 2, command->options, "splinetool", name);
  if (args.help) {
    std::cout << command->help;
    return kOk;
  }
  const std::vector<std::string>& positional = args.positional;
  if (positional.empty()) throw UsageError(name + " needs a FILE (splinetool " + name + " --help)");
  if (positional.size() > 1) throw UsageError("unexpected argument '" + positional[1] + "'");
  return command->run(positional[0], args.options);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string prefix = argc >= 2 ? std::string("splinetool ") + argv[1] + ": " : "splinetool: ";
  return gllab::cli::main_reporting(prefix, run, argc, argv);
}
