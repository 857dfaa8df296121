// bench/ffd_bench.cpp — free-form deformation of a mesh: the textbook layer
// (deform::deform_mesh: A2.1 and A2.3 per vertex and direction, the triple
// sum) against the fast layer (deform::deform_mesh_fast, fast_deform.h), one
// thread, in the same run. A number, not a timed test (bench/README.md).
//
// Data: Newell's teapot, teapot_mesh(176): 991,938 vertices with normals,
// 1,981,056 triangles, in lab 29's box, through
//   (a) a Bernstein lattice of 4 x 4 x 4 points (degree 3, one cell), and
//   (b) a cubic B-spline lattice of 7 x 7 x 7 points (4 spans per direction,
//       64 cells; the same 4^3 = 64 control points per vertex),
// both twisted as lab 29's twist preset (90 degrees about the vertical, in
// proportion to the height). And lab 29's own case, the 10^5-vertex teapot
// (teapot_mesh(56)) through its 5 x 5 x 5 Bernstein (degree 4) and cubic
// B-spline lattices with one point pulled: milliseconds per deform.
//
// Rows per lattice: textbook (deform_mesh, a new DeformedMesh), fast
// (deform_mesh_fast, a new DeformedMesh: like for like), fast_reuse
// (deform_mesh_fast into the same DeformedMesh every time: what a window does).
// Bounds: copy_new and copy_reuse move the bytes any deform_mesh must move
// (read positions, normals and indices; write them and det J) and compute
// nothing; the arithmetic bound is printed from the kernel's operation count
// and the clock measured here.
//
// Before timing every lattice runs once through both layers and the outputs
// are compared (exit status 1 when they disagree beyond float rounding).
//
//   build-bench/bin/ffd_bench [Google Benchmark flags, e.g. --benchmark_repetitions=3]
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "deform/fast_deform.h"
#include "deform/ffd.h"
#include "deform/teapot.h"
#include "rate_reporter.h"

namespace {

namespace df = gllab::deform;
using gllab::IndexedMesh;
using gllab::spline::Vec3;

constexpr int kPerPatch = 176;     // 991,938 vertices
constexpr int kLabPerPatch = 56;   // 100,578 vertices: lab 29's finest
const df::Frame kBox = df::box_frame({-3.3, -2.3, -.2}, {3.7, 2.3, 3.4});  // lab 29's
const Vec3 kCentre{.2, 0, 1.6};                                             // the box's centre

// lab 29's twist: every control point turned about the vertical through the
// centre, by 90 degrees times (z - centre) / 3.6.
df::Lattice twisted(df::Lattice l) {
  for (Vec3& p : l.volume.P) {
    const double a = M_PI / 2 * (p.z - kCentre.z) / 3.6, dx = p.x - kCentre.x;
    p = {kCentre.x + dx * std::cos(a) - p.y * std::sin(a), dx * std::sin(a) + p.y * std::cos(a),
         p.z};
  }
  return l;
}
// lab 29's global_vs_local: the point (4, 2, 4) of the 5 x 5 x 5 lattice pulled.
df::Lattice pulled(df::Lattice l) {
  l.volume.P[(4 * 5 + 2) * 5 + 4] += Vec3{1.6, 0, .5};
  return l;
}

// ---- the arithmetic per vertex, counted from fast_deform.cpp ------------------
// Per vertex inside the box, degree p (all directions), normals on; "mul"
// counts multiplications, "add" additions and subtractions:
//   local pass: x - X0 (3 add), M^-1 (x - X0) (9 mul, 6 add), M^T n (9 mul, 6 add);
//   cell pass (B-spline only): w * segments (3 mul), the fraction (3 add);
//   kernel: the offsets from the cell's centre (3 add); per component the
//     Horner scheme: in u (p + 1)^2 polynomials, value p mul p add, u-derivative
//     p - 1 and p - 1; in t, per power of s: value p, t-derivative p - 1,
//     u-derivative p (each a mul and an add); in s: p, p - 1, p, p;
//   finish: Xt x Xu (6 mul 3 add), det (3 mul 2 add, 1 division), Xu x Xs,
//     Xs x Xt (12 mul 6 add), cof (M^T n) (9 mul 6 add), |n|^2 (3 mul 2 add),
//     the square root, 1 / |n| (a division), n / |n| (3 mul).
struct Ops {
  int mul = 0, add = 0, div = 0, sqrt = 0;
};
Ops ops_per_vertex(int p, bool bspline) {
  const int horner = (p + 1) * (p + 1) * (2 * p - 1) + (p + 1) * (3 * p - 1) + (4 * p - 1);
  Ops o;
  o.mul = 9 + 9 + (bspline ? 3 : 0) + 3 * horner + 6 + 3 + 12 + 9 + 3 + 3;
  o.add = 3 + 6 + 6 + (bspline ? 3 : 0) + 3 + 3 * horner + 3 + 2 + 6 + 6 + 2;
  o.div = 2;
  o.sqrt = 1;
  return o;
}

/// The clock, from a chain of dependent 64-bit multiplications (3 cycles
/// each on AMD Zen and Intel cores since Nehalem): what bench/README.md uses.
double measure_ghz() {
#if defined(__x86_64__) && defined(__GNUC__)
  double best = 0;
  for (int r = 0; r < 5; ++r) {
    std::uint64_t x = 3;
    const std::uint64_t n = 50000000;
    const auto t0 = std::chrono::steady_clock::now();
    for (std::uint64_t i = 0; i < n; ++i) asm volatile("imul %0, %0" : "+r"(x));
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    best = std::max(best, 3.0 * double(n) / s / 1e9);
  }
  return best;
#else
  return 0;
#endif
}

// ---- rows ------------------------------------------------------------------------------

enum class Kind { kTextbook, kFast, kFastReuse, kCopyNew, kCopyReuse };
const char* kind_name(Kind k) {
  switch (k) {
    case Kind::kTextbook: return "textbook";
    case Kind::kFast: return "fast";
    case Kind::kFastReuse: return "fast_reuse";
    case Kind::kCopyNew: return "copy_new";
    case Kind::kCopyReuse: return "copy_reuse";
  }
  return "?";
}

struct Case {
  std::string name;      // e.g. "bernstein_4x4x4"
  const IndexedMesh* mesh;
  df::Lattice lattice;
  int degree = 3;
  bool bspline = false;
  std::string agreement;
  bool mismatch = false;
};

struct Row {
  std::string name;
  const Case* c = nullptr;  // null: a bound (on the 10^6-vertex mesh)
  const IndexedMesh* mesh = nullptr;
  Kind kind = Kind::kTextbook;
  double rate = 0;          // vertices per CPU second
  df::DeformedMesh out;     // reused by the *_reuse rows
};

std::vector<std::unique_ptr<Case>> g_cases;
std::vector<std::unique_ptr<Row>> g_rows;

/// What deform_mesh must move, computing nothing: the mesh's arrays copied,
/// det J written.
void copy_mesh(const IndexedMesh& m, df::DeformedMesh& out) {
  out.mesh.indices = m.indices;
  out.mesh.colours = m.colours;
  out.mesh.positions = m.positions;
  out.mesh.normals = m.normals;
  out.det.assign(m.vertex_count(), 1.0f);
}

void run(Row& r) {
  switch (r.kind) {
    case Kind::kTextbook: {
      const df::DeformedMesh d = df::deform_mesh(r.c->lattice, *r.mesh);
      benchmark::DoNotOptimize(d.mesh.positions.data());
      break;
    }
    case Kind::kFast: {
      const df::DeformedMesh d = df::deform_mesh_fast(r.c->lattice, *r.mesh);
      benchmark::DoNotOptimize(d.mesh.positions.data());
      break;
    }
    case Kind::kFastReuse: df::deform_mesh_fast(r.c->lattice, *r.mesh, r.out); break;
    case Kind::kCopyNew: {
      df::DeformedMesh d;
      copy_mesh(*r.mesh, d);
      benchmark::DoNotOptimize(d.mesh.positions.data());
      break;
    }
    case Kind::kCopyReuse: copy_mesh(*r.mesh, r.out); break;
  }
  benchmark::ClobberMemory();
}

// ---- agreement ------------------------------------------------------------------------

/// Both layers once; the floats compared. The fast layer agrees with the
/// textbook to 1e-12 in double (tests/deform/fast_deform_test.cpp), so in
/// float a value differs from the textbook's by at most one rounding, or,
/// where it is far below its scale (a coordinate 0 in the input), by the
/// double-level difference. Mismatch: counts that differ, or a difference of
/// more than 2^-22 of the scale (the box's longest side; 1 for unit normals;
/// the largest |det J|).
void check(Case& c) {
  const df::DeformedMesh a = df::deform_mesh(c.lattice, *c.mesh);
  const df::DeformedMesh b = df::deform_mesh_fast(c.lattice, *c.mesh);
  const double size = std::max({kBox.S.x, kBox.T.y, kBox.U.z});  // the box's longest side
  double det_scale = 0;
  for (float d : a.det) det_scale = std::max(det_scale, double(std::fabs(d)));
  std::size_t differ_p = 0, differ_n = 0, differ_d = 0;
  double dp = 0, dn = 0, dd = 0;
  for (std::size_t i = 0; i < a.mesh.positions.size(); ++i) {
    differ_p += a.mesh.positions[i] != b.mesh.positions[i];
    dp = std::max(dp, double(std::fabs(a.mesh.positions[i] - b.mesh.positions[i])));
  }
  for (std::size_t i = 0; i < a.mesh.normals.size() && i < b.mesh.normals.size(); ++i) {
    differ_n += a.mesh.normals[i] != b.mesh.normals[i];
    dn = std::max(dn, double(std::fabs(a.mesh.normals[i] - b.mesh.normals[i])));
  }
  for (std::size_t i = 0; i < a.det.size(); ++i) {
    differ_d += a.det[i] != b.det[i];
    dd = std::max(dd, double(std::fabs(a.det[i] - b.det[i])));
  }
  const double limit = 0x1p-22;
  c.mismatch = a.outside != b.outside || a.folded != b.folded ||
               a.mesh.normals.size() != b.mesh.normals.size() || dp > limit * size ||
               dn > limit || dd > limit * det_scale;
  char buf[400];
  const std::size_t n = a.det.size();
  std::snprintf(buf, sizeof buf,
                "floats differing: positions %zu of %zu (max %.1e of the box), normals %zu "
                "(max %.1e), det J %zu (max %.1e of max |det J|); outside %zu = %zu, folded "
                "%zu = %zu, min det J %.6f / %.6f",
                differ_p, 3 * n, dp / size, differ_n, dn, differ_d, dd / det_scale, a.outside,
                b.outside, a.folded, b.folded, a.min_det, b.min_det);
  c.agreement = buf;
}

/// Minor page faults of this thread so far.
long minor_faults() {
  rusage u{};
  getrusage(RUSAGE_THREAD, &u);
  return u.ru_minflt;
}

void register_benchmarks() {
  for (auto& rp : g_rows) {
    Row* r = rp.get();
    benchmark::RegisterBenchmark(("ffd/" + r->name).c_str(), [r](benchmark::State& state) {
      run(*r);  // warm: the reuse rows' buffers exist
      const long faults = minor_faults();
      for (auto _ : state) run(*r);
      state.counters["vertices/s"] = benchmark::Counter(
          double(r->mesh->vertex_count()), benchmark::Counter::kIsIterationInvariantRate);
      // Pages the kernel had to map in per deform: a new result that the
      // allocator does not recycle is first-touched page by page.
      state.counters["faults"] = benchmark::Counter(
          double(minor_faults() - faults), benchmark::Counter::kAvgIterations);
      state.SetLabel(r->c ? kind_name(r->kind) : "bound");
    })->Unit(benchmark::kMillisecond);
  }
}

double rate_of(const Case* c, Kind k) {
  for (auto& r : g_rows)
    if (r->c == c && r->kind == k) return r->rate;
  return 0;
}

void print_summary(double ghz) {
  const IndexedMesh& big = *g_cases.front()->mesh;
  const double v = double(big.vertex_count());
  const double bytes_in = double(big.positions.size() + big.normals.size()) * 4 +
                          double(big.indices.size()) * 4;
  const double bytes_out = bytes_in + v * 4;
  std::printf("\nSummary: millions of vertices per CPU second, single thread; ms per deform;\n"
              "ratio = this row / textbook on the same lattice.\n\n");
  std::printf("  %-44s %10s %10s %9s %10s\n", "row", "M vert/s", "ms", "ratio", "of bound");
  double copy_reuse = 0;
  for (auto& r : g_rows)
    if (!r->c && r->kind == Kind::kCopyReuse) copy_reuse = r->rate;
  for (auto& r : g_rows) {
    char rate[32] = "-", ms[32] = "-", ratio[32] = "", frac[64] = "";
    if (r->rate > 0) {
      std::snprintf(rate, sizeof rate, "%.2f", r->rate / 1e6);
      std::snprintf(ms, sizeof ms, "%.2f", double(r->mesh->vertex_count()) / r->rate * 1e3);
      const double t = r->c ? rate_of(r->c, Kind::kTextbook) : 0;
      if (t > 0 && r->kind != Kind::kTextbook)
        std::snprintf(ratio, sizeof ratio, "%.1fx", r->rate / t);
      if (r->c && ghz > 0 && r->kind != Kind::kTextbook) {
        const Ops o = ops_per_vertex(r->c->degree, r->c->bspline);
        const double arith = ghz * 1e9 * 16 / o.mul;  // 2 multiply pipes x 8 doubles per cycle
        std::snprintf(frac, sizeof frac, "%.0f%% arith", 100 * r->rate / arith);
      }
    }
    std::printf("  %-44s %10s %10s %9s %10s\n", r->name.c_str(), rate, ms, ratio, frac);
  }
  std::printf("\nThe bounds (the 10^6-vertex teapot):\n");
  std::printf("  memory: %.1f bytes read and %.1f written per vertex (positions, normals, the\n"
              "  triangles' indices; det J); copy_reuse moves them at %.1f M vertices/s "
              "(%.1f GB/s),\n  copy_new also allocates and first-touches the output.\n",
              bytes_in / v, bytes_out / v, copy_reuse / 1e6,
              copy_reuse * (bytes_in + bytes_out) / v / 1e9);
  if (ghz > 0) {
    std::printf("  arithmetic: clock %.2f GHz (dependent imul chain); 2 multiply and 2 add pipes\n"
                "  of 8 doubles (AVX-512; -ffp-contract=off: no FMA), so multiplications bind:\n",
                ghz);
    for (const auto& c : g_cases) {
      const Ops o = ops_per_vertex(c->degree, c->bspline);
      std::printf("    %-32s degree %d: %d mul, %d add, %d div, %d sqrt per vertex: %.0f M "
                  "vertices/s\n",
                  c->name.c_str(), c->degree, o.mul, o.add, o.div, o.sqrt,
                  ghz * 1e9 * 16 / o.mul / 1e6);
    }
  }
  std::printf("\nAgreement (deform_mesh_fast against deform_mesh, one run each):\n");
  for (const auto& c : g_cases)
    std::printf("  %-32s %s%s\n", c->name.c_str(), c->agreement.c_str(),
                c->mismatch ? "  <-- MISMATCH" : "");
}

}  // namespace

int main(int argc, char** argv) {
  const bool color = gllab::bench::console_color(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;

  static const IndexedMesh big = df::teapot_mesh(kPerPatch);
  static const IndexedMesh lab = df::teapot_mesh(kLabPerPatch);
  const auto add_case = [](std::string name, const IndexedMesh* m, df::Lattice l, int degree,
                           bool bspline) {
    g_cases.push_back(std::make_unique<Case>());
    Case& c = *g_cases.back();
    c.name = std::move(name), c.mesh = m, c.lattice = std::move(l), c.degree = degree;
    c.bspline = bspline;
    return &c;
  };
  const Case* cases[4] = {
      add_case("bernstein_4x4x4", &big,
               twisted(df::identity_lattice(kBox, df::bernstein_volume(4, 4, 4))), 3, false),
      add_case("bspline_7x7x7_cubic", &big,
               twisted(df::identity_lattice(kBox, df::bspline_volume(7, 7, 7, 3))), 3, true),
      add_case("lab29_bernstein_5x5x5", &lab,
               pulled(df::identity_lattice(kBox, df::bernstein_volume(5, 5, 5))), 4, false),
      add_case("lab29_bspline_5x5x5_cubic", &lab,
               pulled(df::identity_lattice(kBox, df::bspline_volume(5, 5, 5, 3))), 3, true)};
  for (const Case* c : cases)
    for (const Kind k : {Kind::kTextbook, Kind::kFast, Kind::kFastReuse}) {
      g_rows.push_back(std::make_unique<Row>());
      Row& r = *g_rows.back();
      r.name = c->name + "/" + kind_name(k), r.c = c, r.mesh = c->mesh, r.kind = k;
    }
  for (const Kind k : {Kind::kCopyNew, Kind::kCopyReuse}) {
    g_rows.push_back(std::make_unique<Row>());
    Row& r = *g_rows.back();
    r.name = std::string("bound/") + kind_name(k), r.mesh = &big, r.kind = k;
  }

  std::printf("Teapot: %zu vertices with normals, %zu triangles (teapot_mesh(%d)); the lab's: "
              "%zu vertices (teapot_mesh(%d)).\n",
              big.vertex_count(), big.triangle_count(), kPerPatch, lab.vertex_count(),
              kLabPerPatch);
  for (auto& c : g_cases) check(*c);
  const double ghz = measure_ghz();
  std::printf("Clock: %.2f GHz (dependent imul chain, best of 5).\n\n", ghz);
  std::fflush(stdout);

  register_benchmarks();
  gllab::bench::RateReporter reporter(color, {"vertices/s"});
  benchmark::RunSpecifiedBenchmarks(&reporter);
  for (auto& r : g_rows) r->rate = reporter.rate("ffd/" + r->name);
  print_summary(ghz);
  benchmark::Shutdown();

  bool mismatch = false;
  for (auto& c : g_cases) mismatch |= c->mismatch;
  if (mismatch)
    std::fprintf(stderr, "ffd_bench: the fast layer disagrees with deform_mesh (MISMATCH above)\n");
  return mismatch ? 1 : 0;
}
