// bench/spline_bench.cpp — the spline core against GLU, SISL and OpenCASCADE:
// a number, not a timed test. One program, one run, the same data for every
// contestant (bench_data.h):
//   curve_points     C(u) of a cubic rational 3D curve, 50 control points, 100,000 sorted u
//   curve_derivs     C(u) and C'(u) for the same
//   surface_normals  S(u, v) and the unit normal of a bicubic rational 20 x 20 surface, 300 x 300 grid
//   natural_spline   the natural cubic spline through 10^6 + 1 nodes (the O(n) tridiagonal solve)
//   uniform_plot     the notes' plot of a uniform cubic B-spline, 1,000 points x 100 steps per segment:
//                    forward differences against Horner and against the batched evaluator
// First every contestant runs once and is compared with the own core (the
// agreement table); then Google Benchmark times them (points/s counters); then
// a summary prints points/s, the ratios own / peer and the agreement again.
// Exit status 1 when a contestant disagrees with the own core beyond its
// tolerance; a contestant that cannot run is reported as skipped, never dropped.
//
//   build-bench/bin/spline_bench [Google Benchmark flags, e.g. --benchmark_filter=curve]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "bench_config.h"
#include "bench_data.h"
#include "peers.h"
#include "rate_reporter.h"
#include "spline/bspline.h"
#include "spline/cubic_spline.h"
#include "spline/forward_differences.h"
#include "spline/surface.h"
#include "spline/tessellate.h"

namespace {

using gllab::bench::BenchData;
using gllab::bench::Points;
using gllab::spline::Vec3;
namespace sp = gllab::spline;

// ---- agreement tolerances (relative to the largest reference value) ---------
// Double-precision peers evaluate the same formulas in another order: a few
// ulps of the data's scale. GLU works in float (docs/glu.md: vertices within
// ~1e-6 of the true surface, normals within 0.02 degrees).
constexpr double kDoubleRelTolerance = 1e-10;
constexpr double kFloatRelTolerance = 1e-5;
constexpr double kDoubleNormalTolerance = 1e-9;  // |n - n_ref| of unit normals
constexpr double kFloatNormalTolerance = 1e-3;   // 0.06 degrees
// The natural spline: |S'' jump| at interior nodes and |S''| at the ends,
// relative to max |S''|.
constexpr double kSplineC2Tolerance = 1e-9;

enum class Role { kOwn, kPeer };

const char* role_name(Role role) {
  switch (role) {
    case Role::kOwn: return "own";
    case Role::kPeer: return "peer";
  }
  return "?";
}

// One contestant in one task.
struct Entry {
  std::string task, name;
  Role role = Role::kPeer;
  std::string skip;                         // why it cannot run (empty: it can)
  std::function<std::size_t(Entry&)> run;   // one pass; returns points (or nodes) produced
  std::function<void(Entry&)> check;        // custom agreement check (GLU, spline); else vs the reference
  Points out, aux;                          // points; derivatives or normals
  // Filled in by the check and by the benchmark run.
  std::string agreement;
  bool mismatch = false;
  double rate = 0;
  std::string run_error;

  std::string full_name() const { return task + "/" + name; }
};

std::vector<std::unique_ptr<Entry>> g_entries;

Entry& add(const std::string& task, const std::string& name, Role role, std::function<std::size_t(Entry&)> run) {
  auto e = std::make_unique<Entry>();
  e->task = task;
  e->name = name;
  e->role = role;
  e->run = std::move(run);
  g_entries.push_back(std::move(e));
  return *g_entries.back();
}

Entry& add_skipped(const std::string& task, const std::string& name, const std::string& why) {
  Entry& e = add(task, name, Role::kPeer, nullptr);
  e.skip = why;
  return e;
}

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", v);
  return buf;
}

double max_norm(const Points& a) {
  double m = 0;
  for (const Vec3& p : a) m = std::max(m, sp::norm(p));
  return m;
}

double max_diff(const Points& a, const Points& b) {
  double m = 0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) m = std::max(m, sp::norm(a[k] - b[k]));
  return m;
}

// ---- the contestants ------------------------------------------------------------

// The peers, each built once from the bench data; a peer that is missing or
// failed to build has a reason instead.
struct Peers {
  std::unique_ptr<gllab::bench::GluPeer> glu;
  std::string glu_missing;
#ifdef GLLAB_BENCH_HAVE_SISL
  std::unique_ptr<gllab::bench::SislPeer> sisl;
#endif
  std::string sisl_missing = "SISL not installed (libsisl-dev; ./lab bench installs it)";
#ifdef GLLAB_BENCH_HAVE_OCCT
  std::unique_ptr<gllab::bench::OcctPeer> occt;
  std::string occt_missing;
#else
  std::string occt_missing = GLLAB_BENCH_OCCT_MISSING;
#endif
};

template <class Peer>
void build_peer(std::unique_ptr<Peer>& peer, std::string& missing, const BenchData& data, const char* what) {
  try {
    peer = std::make_unique<Peer>(data);
  } catch (const std::exception& ex) {
    missing = std::string(what) + " failed to set up: " + ex.what();
  } catch (...) {
    missing = std::string(what) + " failed to set up (non-standard exception)";
  }
}

Peers build_peers(const BenchData& data) {
  Peers peers;
  build_peer(peers.glu, peers.glu_missing, data, "GLU");
#ifdef GLLAB_BENCH_HAVE_SISL
  build_peer(peers.sisl, peers.sisl_missing, data, "SISL");
#endif
#ifdef GLLAB_BENCH_HAVE_OCCT
  build_peer(peers.occt, peers.occt_missing, data, "OpenCASCADE");
#endif
  return peers;
}

void add_curve_entries(const BenchData& d, const Peers& peers) {
  const auto& c = d.curve;
  const auto& u = d.curve_u;
  gllab::bench::GluPeer* glu = peers.glu.get();

  // curve_points ---------------------------------------------------------------
  add("curve_points", "own_per_point", Role::kOwn, [&c, &u](Entry& e) {
    for (std::size_t k = 0; k < u.size(); ++k) e.out[k] = sp::curve_point(c, u[k]);
    return u.size();
  });
  add("curve_points", "own_batched", Role::kOwn, [&c, &u](Entry& e) {
    sp::curve_points(c, u, e.out);
    return u.size();
  });
  if (glu) {
    Entry& e = add("curve_points", "glu_tessellator", Role::kPeer, [glu](Entry& e) { return glu->curve_points(e.out); });
    e.check = [glu, &c](Entry& e) {
      const auto samples = glu->curve_samples();
      Points ref(samples.points.size());
      for (std::size_t k = 0; k < ref.size(); ++k) ref[k] = sp::curve_point(c, std::clamp(samples.u[k], 0.0, 1.0));
      const double diff = max_diff(samples.points, ref), scale = max_norm(ref);
      e.mismatch = diff > kFloatRelTolerance * scale;
      e.agreement = "|dP| " + sci(diff) + " (float; " + std::to_string(samples.points.size()) + " vertices, step " +
                    std::to_string(glu->curve_step()) + ")";
    };
  } else {
    add_skipped("curve_points", "glu_tessellator", peers.glu_missing);
  }
#ifdef GLLAB_BENCH_HAVE_SISL
  gllab::bench::SislPeer* sisl = peers.sisl.get();
  if (sisl) {
    add("curve_points", "sisl_s1221", Role::kPeer, [sisl, &u](Entry& e) {
      sisl->curve_points(u, e.out);
      return u.size();
    });
  } else
#endif
  {
    add_skipped("curve_points", "sisl_s1221", peers.sisl_missing);
  }
#ifdef GLLAB_BENCH_HAVE_OCCT
  gllab::bench::OcctPeer* occt = peers.occt.get();
  using Via = gllab::bench::OcctPeer::Via;
  if (occt) {
    add("curve_points", "occt_geom_D0", Role::kPeer, [occt, &u](Entry& e) {
      occt->curve_points(Via::kGeom, u, e.out);
      return u.size();
    });
    add("curve_points", "occt_adaptor_D0", Role::kPeer, [occt, &u](Entry& e) {
      occt->curve_points(Via::kAdaptor, u, e.out);
      return u.size();
    });
  } else
#endif
  {
    add_skipped("curve_points", "occt_geom_D0", peers.occt_missing);
    add_skipped("curve_points", "occt_adaptor_D0", peers.occt_missing);
  }

  // curve_derivs -----------------------------------------------------------------
  add("curve_derivs", "own_per_point", Role::kOwn, [&c, &u](Entry& e) {
    for (std::size_t k = 0; k < u.size(); ++k) {
      const std::vector<Vec3> CK = sp::curve_derivs(c, u[k], 1);
      e.out[k] = CK[0];
      e.aux[k] = CK[1];
    }
    return u.size();
  });
  add("curve_derivs", "own_batched", Role::kOwn, [&c, &u](Entry& e) {
    sp::curve_points(c, u, e.out, e.aux);
    return u.size();
  });
  add_skipped("curve_derivs", "glu_tessellator", "GLU returns no derivatives (its tessellator gives points and normals)");
#ifdef GLLAB_BENCH_HAVE_SISL
  if (sisl) {
    add("curve_derivs", "sisl_s1221", Role::kPeer, [sisl, &u](Entry& e) {
      sisl->curve_derivs(u, e.out, e.aux);
      return u.size();
    });
  } else
#endif
  {
    add_skipped("curve_derivs", "sisl_s1221", peers.sisl_missing);
  }
#ifdef GLLAB_BENCH_HAVE_OCCT
  if (occt) {
    add("curve_derivs", "occt_geom_D1", Role::kPeer, [occt, &u](Entry& e) {
      occt->curve_derivs(Via::kGeom, u, e.out, e.aux);
      return u.size();
    });
    add("curve_derivs", "occt_adaptor_D1", Role::kPeer, [occt, &u](Entry& e) {
      occt->curve_derivs(Via::kAdaptor, u, e.out, e.aux);
      return u.size();
    });
  } else
#endif
  {
    add_skipped("curve_derivs", "occt_geom_D1", peers.occt_missing);
    add_skipped("curve_derivs", "occt_adaptor_D1", peers.occt_missing);
  }
}

void add_surface_entries(const BenchData& d, const Peers& peers) {
  const auto& s = d.surface;
  const auto& us = d.grid_u;
  const auto& vs = d.grid_v;
  gllab::bench::GluPeer* glu = peers.glu.get();

  add("surface_normals", "own_per_point", Role::kOwn, [&s, &us, &vs](Entry& e) {
    std::size_t k = 0;
    for (double u : us)
      for (double v : vs) {
        e.out[k] = sp::surface_point(s, u, v);
        e.aux[k++] = sp::surface_normal(s, u, v);
      }
    return k;
  });
  // The evaluator the tessellator samples (surface.h surface_evaluator): checks
  // the surface once, then one call per (u, v) for point and normal together.
  static sp::SurfaceEvaluator evaluator;
  add("surface_normals", "own_evaluator", Role::kOwn, [&s, &us, &vs](Entry& e) {
    if (!evaluator) evaluator = sp::surface_evaluator(s);
    std::size_t k = 0;
    for (double u : us)
      for (double v : vs) {
        const sp::SurfaceSample sample = evaluator(u, v);
        e.out[k] = sample.point;
        e.aux[k++] = sample.normal;
      }
    return k;
  });
  add("surface_normals", "own_batched", Role::kOwn, [&s, &us, &vs](Entry& e) {
    sp::surface_grid(s, us, vs, e.out, &e.aux);
    return us.size() * vs.size();
  });
  if (glu) {
    Entry& e = add("surface_normals", "glu_tessellator", Role::kPeer,
                   [glu](Entry& e) { return glu->surface_normals(e.out, e.aux); });
    e.check = [glu, &s](Entry& e) {
      const auto samples = glu->surface_samples();
      Points ref(samples.points.size()), ref_normals(samples.points.size());
      for (std::size_t k = 0; k < ref.size(); ++k) {
        const double u = std::clamp(samples.u[k], 0.0, 1.0), v = std::clamp(samples.v[k], 0.0, 1.0);
        ref[k] = sp::surface_point(s, u, v);
        ref_normals[k] = sp::surface_normal(s, u, v);
      }
      const double diff = max_diff(samples.points, ref), ndiff = max_diff(samples.normals, ref_normals);
      e.mismatch = diff > kFloatRelTolerance * max_norm(ref) || ndiff > kFloatNormalTolerance;
      e.agreement = "|dP| " + sci(diff) + ", |dN| " + sci(ndiff) + " (float; " +
                    std::to_string(samples.points.size()) + " vertices, " + std::to_string(glu->surface_distinct()) +
                    " distinct (u,v), step " + std::to_string(glu->surface_step()) + ")";
    };
  } else {
    add_skipped("surface_normals", "glu_tessellator", peers.glu_missing);
  }
#ifdef GLLAB_BENCH_HAVE_SISL
  if (gllab::bench::SislPeer* sisl = peers.sisl.get()) {
    add("surface_normals", "sisl_s1421", Role::kPeer, [sisl, &us, &vs](Entry& e) {
      sisl->surface_normals(us, vs, e.out, e.aux);
      return us.size() * vs.size();
    });
  } else
#endif
  {
    add_skipped("surface_normals", "sisl_s1421", peers.sisl_missing);
  }
#ifdef GLLAB_BENCH_HAVE_OCCT
  using Via = gllab::bench::OcctPeer::Via;
  if (gllab::bench::OcctPeer* occt = peers.occt.get()) {
    add("surface_normals", "occt_geom_D1", Role::kPeer, [occt, &us, &vs](Entry& e) {
      occt->surface_normals(Via::kGeom, us, vs, e.out, e.aux);
      return us.size() * vs.size();
    });
    add("surface_normals", "occt_adaptor_D1", Role::kPeer, [occt, &us, &vs](Entry& e) {
      occt->surface_normals(Via::kAdaptor, us, vs, e.out, e.aux);
      return us.size() * vs.size();
    });
  } else
#endif
  {
    add_skipped("surface_normals", "occt_geom_D1", peers.occt_missing);
    add_skipped("surface_normals", "occt_adaptor_D1", peers.occt_missing);
  }
}

// Output buffers, sized once outside the timing: GLU's to twice its
// calibrated count (a vertex past the end is counted, not stored).
void size_buffers(const BenchData& d) {
  const std::size_t curve = d.curve_u.size(), grid = d.grid_u.size() * d.grid_v.size();
  for (auto& e : g_entries) {
    const std::size_t n = (e->task == "surface_normals" ? grid : curve) * (e->name == "glu_tessellator" ? 2 : 1);
    if (e->task == "natural_spline" || e->task == "uniform_plot") continue;
    e->out.resize(n);
    if (e->task != "curve_points") e->aux.resize(n);
  }
}

// The natural cubic spline has no peer here: GLU has no interpolation, and
// SISL's and OpenCASCADE's interpolators solve other (B-spline) systems.
void add_spline_entries(const BenchData& d) {
  const auto check = [](const std::vector<double>& h, auto c_of, auto d_of, std::size_t segments) {
    // S''(t_i) from the left, 2 c[i-1] + 6 d[i-1] h, must equal 2 c[i] from the right.
    double jump = 0, scale = 0, ends = std::abs(c_of(0));
    for (std::size_t i = 1; i < segments; ++i) {
      const double left = 2 * c_of(i - 1) + 6 * d_of(i - 1) * h[i - 1];
      jump = std::max(jump, std::abs(left - 2 * c_of(i)));
      scale = std::max(scale, std::abs(2 * c_of(i)));
    }
    const std::size_t last = segments - 1;
    ends = std::max(ends, std::abs(2 * c_of(last) + 6 * d_of(last) * h[last]));
    return std::make_pair(jump / std::max(scale, 1.0), ends / std::max(scale, 1.0));
  };
  static std::vector<double> h;
  h.resize(d.spline_t.size() - 1);
  for (std::size_t i = 0; i + 1 < d.spline_t.size(); ++i) h[i] = d.spline_t[i + 1] - d.spline_t[i];

  static sp::ScalarCubicSpline scalar;
  Entry& a = add("natural_spline", "own_scalar", Role::kOwn, [&d](Entry&) {
    scalar = sp::natural_cubic_spline(d.spline_t, d.spline_y);
    return d.spline_t.size();
  });
  a.check = [check](Entry& e) {
    const auto [jump, ends] = check(
        h, [](std::size_t i) { return scalar.c[i]; }, [](std::size_t i) { return scalar.d[i]; }, scalar.segments());
    e.mismatch = jump > kSplineC2Tolerance || ends > kSplineC2Tolerance;
    e.agreement = "C2 jump " + sci(jump) + ", |S''| at ends " + sci(ends) + " (relative)";
  };
  static sp::CubicSpline curve;
  Entry& b = add("natural_spline", "own_curve3d", Role::kOwn, [&d](Entry&) {
    curve = sp::natural_cubic_spline(d.spline_t, d.spline_P);
    return d.spline_t.size();
  });
  b.check = [check](Entry& e) {
    double jump = 0, ends = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const auto pick = [axis](const Vec3& v) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; };
      const auto [j, en] = check(
          h, [&](std::size_t i) { return pick(curve.c[i]); }, [&](std::size_t i) { return pick(curve.d[i]); },
          curve.segments());
      jump = std::max(jump, j);
      ends = std::max(ends, en);
    }
    e.mismatch = jump > kSplineC2Tolerance || ends > kSplineC2Tolerance;
    e.agreement = "C2 jump " + sci(jump) + ", |S''| at ends " + sci(ends) + " (relative)";
  };
}

// The notes' "Plotting Uniform Cubic B-Splines": the first kPlotPoints 3D
// points of the spline data as control points, kPlotSteps steps per segment.
// All own: the question is what forward differences buy over Horner (the
// brute-force loop) and over the general batched B-spline evaluator.
constexpr std::size_t kPlotPoints = 1000;
constexpr int kPlotSteps = 100;

void add_plot_entries(const BenchData& d) {
  static const std::vector<Vec3> P(d.spline_P.begin(), d.spline_P.begin() + kPlotPoints);
  const auto plot = [](sp::CubicMethod method) {
    return [method](Entry& e) {
      e.out = sp::plot_uniform_cubic_bspline(P, kPlotSteps, method);
      return e.out.size();
    };
  };
  add("uniform_plot", "own_horner", Role::kOwn, plot(sp::CubicMethod::kHornerDouble));
  add("uniform_plot", "own_forward_diff", Role::kOwn, plot(sp::CubicMethod::kForwardDouble));
  Entry& f = add("uniform_plot", "own_forward_float", Role::kOwn, plot(sp::CubicMethod::kForwardFloat));
  f.check = [](Entry& e) {  // float: within float's tolerance of Horner in double
    const auto exact = sp::plot_uniform_cubic_bspline(P, kPlotSteps, sp::CubicMethod::kHornerDouble);
    const double dp = max_diff(e.out, exact);
    e.agreement = "|dP| " + sci(dp) + " (float)";
    e.mismatch = dp > kFloatRelTolerance * max_norm(exact);
  };
  // The same curve as a B-spline on uniform knots 0, 1, ..., n + 4: segment i
  // (P[i..i+3]) is u in [3 + i, 4 + i]; the parameters in the plot's order.
  static sp::BsplineCurve curve;
  curve.p = 3;
  curve.P = P;
  curve.U = sp::uniform_knots(static_cast<int>(P.size()) - 1, 3);
  static std::vector<double> u;
  for (std::size_t i = 0; i + 3 < P.size(); ++i)
    for (int k = i == 0 ? 0 : 1; k <= kPlotSteps; ++k) u.push_back(3.0 + i + double(k) / kPlotSteps);
  add("uniform_plot", "own_batched", Role::kOwn, [](Entry& e) {
    e.out.resize(u.size());
    sp::curve_points(curve, u, e.out);
    return u.size();
  });
}

// ---- agreement ---------------------------------------------------------------------

// The tasks that --benchmark_filter (a regular expression; a leading '-'
// negates it) selects at least one contestant of: only those are checked.
std::set<std::string> selected_tasks(const std::string& filter) {
  std::set<std::string> tasks;
  const bool negate = !filter.empty() && filter[0] == '-';
  const std::string pattern = negate ? filter.substr(1) : filter;
  for (auto& e : g_entries) {
    bool match = true;
    if (!pattern.empty() && pattern != "all") {
      try {
        match = std::regex_search(e->full_name(), std::regex(pattern, std::regex::extended)) != negate;
      } catch (const std::regex_error&) {
        match = true;  // let Google Benchmark report the bad expression
      }
    }
    if (match) tasks.insert(e->task);
  }
  return tasks;
}

// Runs every contestant of the selected tasks once. The reference of a task is
// its first own entry that runs (own_per_point: the textbook algorithms, A4.1
// / A4.2 / A4.4).
void run_checks(const std::set<std::string>& tasks) {
  std::map<std::string, const Entry*> reference;
  for (auto& ep : g_entries) {
    Entry& e = *ep;
    if (!e.skip.empty()) continue;
    if (!tasks.count(e.task)) {
      e.agreement = "not checked (filtered out)";
      continue;
    }
    try {
      e.run(e);
    } catch (const std::exception& ex) {
      e.skip = std::string("failed: ") + ex.what();
      continue;
    }
    if (e.check) {
      try {
        e.check(e);
      } catch (const std::exception& ex) {
        e.agreement = std::string("n/a: the own core threw: ") + ex.what();
      }
      continue;
    }
    const auto ref = reference.find(e.task);
    if (ref == reference.end()) {
      if (e.role == Role::kOwn) {
        reference[e.task] = &e;
        e.agreement = "reference";
      } else {
        e.agreement = "n/a: no own-core reference ran";
      }
      continue;
    }
    const Entry& r = *ref->second;
    // Only GLU works in float, and it has its own check.
    const double dp = max_diff(e.out, r.out);
    e.agreement = "|dP| " + sci(dp);
    e.mismatch = dp > kDoubleRelTolerance * max_norm(r.out);
    if (!r.aux.empty()) {
      const double da = max_diff(e.aux, r.aux);
      const bool normals = e.task == "surface_normals";
      e.agreement += (normals ? ", |dN| " : ", |dD| ") + sci(da);
      e.mismatch |= da > (normals ? kDoubleNormalTolerance : kDoubleRelTolerance * max_norm(r.aux));
    }
  }
}

// ---- benchmark registration and the summary ---------------------------------------

void register_benchmarks() {
  for (auto& ep : g_entries) {
    Entry* e = ep.get();
    const char* counter = e->task == "natural_spline" ? "nodes/s" : "points/s";
    benchmark::RegisterBenchmark(e->full_name().c_str(), [e, counter](benchmark::State& state) {
      if (!e->skip.empty()) {
        state.SkipWithError(e->skip.c_str());
        return;
      }
      std::size_t count = 0;
      try {
        for (auto _ : state) {
          count = e->run(*e);
          benchmark::ClobberMemory();
        }
      } catch (const std::exception& ex) {
        e->run_error = ex.what();
        state.SkipWithError(e->run_error.c_str());
        return;
      }
      state.counters[counter] = benchmark::Counter(double(count), benchmark::Counter::kIsIterationInvariantRate);
      state.SetLabel(role_name(e->role));
    })->Unit(benchmark::kMillisecond);
  }
}

std::string ratio_text(double own, double other) {
  if (own <= 0 || other <= 0) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2fx", own / other);
  return buf;
}

void print_summary() {
  std::printf("\nSummary: millions of points (natural_spline: nodes) per second, single thread; ratio = own / this\n");
  std::printf("row; agreement = max |difference| against the own core's per-point API (the reference).\n");
  std::string task;
  for (auto& ep : g_entries) {
    const Entry& e = *ep;
    if (e.task != task) {
      task = e.task;
      std::printf("\n%-16s %-18s %-9s %10s %10s %10s  %s\n", task.c_str(), "contestant", "role", "M/s",
                  "batched/", "per-point/", "agreement");
    }
    double own_batched = 0, own_point = 0;
    for (auto& op : g_entries) {
      if (op->task != e.task) continue;
      if (op->name == "own_batched") own_batched = op->rate;
      if (op->name == "own_per_point") own_point = op->rate;
    }
    const std::string status = !e.skip.empty() ? "SKIPPED: " + e.skip
                               : !e.run_error.empty() ? "FAILED: " + e.run_error
                               : e.rate <= 0          ? "not run (filtered out)"
                                                      : e.agreement + (e.mismatch ? "  <-- MISMATCH" : "");
    char rate[32] = "-";
    if (e.rate > 0) std::snprintf(rate, sizeof rate, "%.2f", e.rate / 1e6);
    const bool peer = e.role != Role::kOwn;
    std::printf("  %-32s %-9s %10s %10s %10s  %s\n", e.name.c_str(), role_name(e.role), rate,
                peer ? ratio_text(own_batched, e.rate).c_str() : "",
                peer ? ratio_text(own_point, e.rate).c_str() : "", status.c_str());
  }

  std::printf("\nTarget: own batched >= 3x the fastest peer.\n");
  for (const char* t : {"curve_points", "curve_derivs", "surface_normals"}) {
    const Entry *best = nullptr, *own = nullptr;
    for (auto& ep : g_entries) {
      const Entry& e = *ep;
      if (e.task != t || e.rate <= 0) continue;
      if (e.role == Role::kPeer && (!best || e.rate > best->rate)) best = &e;
      if (e.name == "own_batched") own = &e;
    }
    if (!best || !own) {
      std::printf("  %-16s n/a (%s)\n", t, best ? "own_batched did not run" : "no peer ran");
      continue;
    }
    const double r = own->rate / best->rate;
    std::printf("  %-16s fastest peer %s %.1f M/s; own_batched %.1f M/s = %.2fx: %s", t, best->name.c_str(),
                best->rate / 1e6, own->rate / 1e6, r, r >= 3 ? "met" : "NOT met");
    std::printf("\n");
  }
  // uniform_plot has no peer: the ratios that matter are forward differences
  // against the two ways of evaluating every point afresh.
  const auto rate_of = [](const char* name) {
    for (auto& ep : g_entries)
      if (ep->task == "uniform_plot" && ep->name == name) return ep->rate;
    return 0.0;
  };
  const double fd = rate_of("own_forward_diff");
  std::printf("\nuniform_plot: forward differences %s Horner, %s the batched B-spline evaluator\n",
              ratio_text(fd, rate_of("own_horner")).c_str(), ratio_text(fd, rate_of("own_batched")).c_str());
}

}  // namespace

int main(int argc, char** argv) {
  // Two Google Benchmark flags this program reads too: the filter (only the
  // selected tasks are checked) and the colour (a custom reporter ignores it).
  std::string filter;
  const bool color = gllab::bench::console_color(argc, argv);
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg.rfind("--benchmark_filter=", 0) == 0) filter = arg.substr(std::strlen("--benchmark_filter="));
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;

  const BenchData& data = gllab::bench::bench_data();
  const Peers peers = build_peers(data);
  add_curve_entries(data, peers);
  add_surface_entries(data, peers);
  add_spline_entries(data);
  add_plot_entries(data);
  size_buffers(data);

  std::printf("Agreement with the own core (one run of each contestant before timing):\n");
  run_checks(selected_tasks(filter));
  for (auto& e : g_entries)
    std::printf("  %-36s %s\n", e->full_name().c_str(),
                e->skip.empty() ? (e->agreement + (e->mismatch ? "  <-- MISMATCH" : "")).c_str()
                                : ("SKIPPED: " + e->skip).c_str());
  std::printf("\n");
  std::fflush(stdout);

  register_benchmarks();
  gllab::bench::RateReporter reporter(color, {"points/s", "nodes/s"});
  benchmark::RunSpecifiedBenchmarks(&reporter);
  for (auto& e : g_entries) e->rate = reporter.rate(e->full_name());
  print_summary();
  benchmark::Shutdown();

  bool mismatch = false;
  for (auto& e : g_entries) mismatch |= e->mismatch;
  if (mismatch) std::fprintf(stderr, "spline_bench: a contestant disagrees with the own core (MISMATCH above)\n");
  return mismatch ? 1 : 0;
}
