// bench/iso_bench.cpp — iso-surface extraction: field::marching_cubes against
// VTK 9.1's vtkFlyingEdges3D and vtkMarchingCubes, single thread, on one grid:
// the 256^3 float field of two Hermite blobs (field::two_blob_benchmark_field,
// 64 MB), iso value 0.5. A number, not a timed test (bench/README.md).
//
// Like with like: every contestant returns positions and triangles of the
// same surface, each grid-edge vertex once; the rows "normals" also compute
// unit vertex normals from central-difference gradients (the own core's
// McOptions::normals, VTK's ComputeNormals), the rows "no_normals" do not.
// VTK's gradients and scalars are off (ComputeGradients, ComputeScalars).
// VTK reads the grid's own floats (a vtkFloatArray over them, no copy) and is
// held to one thread (vtkSMPTools::Initialize(1); the backend is printed).
//
// The physical bound: each contestant reads the 64 MB at least once. The row
// "bound/stream_sum" sums the same floats (a streaming read, vectorised); its
// rate in voxels per second is what an extraction that only read the field
// would reach here.
//
// Output: the agreement (vertex sets of the peers against the own core's, to
// 1e-6; triangle counts, which differ in cells with a saddle face), Google
// Benchmark's table (items/s = voxels/s, wall clock), and a summary with M
// voxels/s, the ratios own / peer (same normals setting, same run) and the
// fraction of the bound. Exit status 1 when a peer's vertices disagree.
//
//   build-bench/bin/iso_bench [Google Benchmark flags, e.g. --benchmark_repetitions=3]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "field/grid.h"
#include "field/marching_cubes.h"
#include "iso_bench_config.h"
#include "peer_support.h"  // tests/field: the vertex-set comparison the peer tests use
#include "rate_reporter.h"

#ifdef GLLAB_BENCH_HAVE_VTK
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkMarchingCubes.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>
#include <vtkVersion.h>

#include "vtk_grid.h"  // tests/field: the grid as vtkImageData, no copy
#endif

namespace {

namespace fd = gllab::field;

constexpr int kN = 256;
constexpr double kIso = 0.5;

struct Counts {
  std::size_t vertices = 0, triangles = 0;
};

enum class Role { kOwn, kPeer, kBound };
const char* role_name(Role r) {
  return r == Role::kOwn ? "own" : r == Role::kPeer ? "peer" : "bound";
}

struct Row {
  std::string name;
  Role role = Role::kPeer;
  int normals = -1;  // 1 on, 0 off, -1 n/a (the bound)
  std::string skip;
  std::function<Counts()> run;  // one extraction (or one streaming sum)
  std::function<std::vector<fd::peer::P3>()>
      vertices;  // the last run's vertices, for the agreement
  Counts counts;
  std::string agreement;
  bool mismatch = false;
  double rate = 0;  // voxels per second, from the benchmark
};

std::vector<std::unique_ptr<Row>> g_rows;

Row& add(const std::string& name, Role role, int normals) {
  g_rows.push_back(std::make_unique<Row>());
  Row& r = *g_rows.back();
  r.name = name;
  r.role = role;
  r.normals = normals;
  return r;
}

// ---- the bound: one streaming read of the 64 MB ------------------------------
// 16 independent float sums (lane-wise, so GCC vectorises without reassociating).
float stream_sum(const float* v, std::size_t n) {
  float acc[16] = {};
  std::size_t i = 0;
  for (; i + 16 <= n; i += 16)
    for (int l = 0; l < 16; ++l) acc[l] += v[i + l];
  float s = 0;
  for (; i < n; ++i) s += v[i];
  for (float a : acc) s += a;
  return s;
}

// ---- own -----------------------------------------------------------------------
struct Own {
  const fd::Grid3* grid;
  fd::McOptions options;
  fd::McResult last;
  Counts run() {
    last = fd::marching_cubes(*grid, kIso, options);
    return {last.mesh.vertex_count(), last.mesh.triangle_count()};
  }
};

// ---- VTK -------------------------------------------------------------------------
#ifdef GLLAB_BENCH_HAVE_VTK
template <class Filter>
struct Vtk {
  vtkSmartPointer<Filter> filter = vtkSmartPointer<Filter>::New();
  Vtk(vtkImageData* image, bool normals) {
    filter->SetInputData(image);
    filter->SetValue(0, kIso);
    filter->SetComputeNormals(normals);
    filter->ComputeGradientsOff();
    filter->ComputeScalarsOff();
  }
  Counts run() {
    filter->Modified();  // else Update() returns the last output
    filter->Update();
    vtkPolyData* out = filter->GetOutput();
    return {std::size_t(out->GetNumberOfPoints()), std::size_t(out->GetNumberOfPolys())};
  }
  std::vector<fd::peer::P3> vertices() {
    vtkPoints* p = filter->GetOutput()->GetPoints();
    std::vector<fd::peer::P3> v(p ? std::size_t(p->GetNumberOfPoints()) : 0);
    for (std::size_t k = 0; k < v.size(); ++k) p->GetPoint(vtkIdType(k), v[k].data());
    return v;
  }
};
#endif

std::string vtk_setup(const fd::Grid3& g) {
#ifdef GLLAB_BENCH_HAVE_VTK
  vtkSMPTools::Initialize(1);
  static vtkSmartPointer<vtkImageData> image = gllab::field::testing::vtk_image(g);
  struct Spec {
    const char* name;
    bool fe, normals;
  };
  for (const Spec s : {Spec{"vtk_flying_edges_normals", true, true},
                       Spec{"vtk_flying_edges_no_normals", true, false},
                       Spec{"vtk_marching_cubes_normals", false, true},
                       Spec{"vtk_marching_cubes_no_normals", false, false}}) {
    Row& r = add(s.name, Role::kPeer, s.normals);
    if (s.fe) {
      auto v = std::make_shared<Vtk<vtkFlyingEdges3D>>(image, s.normals);
      r.run = [v] { return v->run(); };
      r.vertices = [v] { return v->vertices(); };
    } else {
      auto v = std::make_shared<Vtk<vtkMarchingCubes>>(image, s.normals);
      r.run = [v] { return v->run(); };
      r.vertices = [v] { return v->vertices(); };
    }
  }
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "VTK %s, vtkSMPTools backend %s, %d thread(s) (vtkSMPTools::Initialize(1))",
                vtkVersion::GetVTKVersion(), vtkSMPTools::GetBackend(),
                vtkSMPTools::GetEstimatedNumberOfThreads());
  return buf;
#else
  (void)g;
  for (const char* name : {"vtk_flying_edges_normals", "vtk_flying_edges_no_normals",
                           "vtk_marching_cubes_normals", "vtk_marching_cubes_no_normals"})
    add(name, Role::kPeer, std::strstr(name, "no_normals") ? 0 : 1).skip = GLLAB_BENCH_VTK_MISSING;
  return std::string("VTK: skipped: ") + GLLAB_BENCH_VTK_MISSING;
#endif
}

// ---- agreement: one run of each, before timing --------------------------------------
void run_checks(const Own& own_plain) {
  for (auto& rp : g_rows)
    if (rp->skip.empty()) rp->counts = rp->run();
  const std::vector<fd::peer::P3> own_v = fd::peer::positions(own_plain.last.mesh);
  for (auto& rp : g_rows) {
    Row& r = *rp;
    if (!r.skip.empty() || r.role == Role::kBound) continue;
    if (r.role == Role::kOwn) {
      r.agreement = r.normals ? "reference (the same vertices as no_normals)" : "reference";
      continue;
    }
    const fd::peer::SetComparison c = fd::peer::compare_sets(own_v, r.vertices());
    r.mismatch = !c.agree();
    char buf[160];
    std::snprintf(buf, sizeof buf, "vertex sets: max distance %.1e / %.1e%s", c.a_to_b, c.b_to_a,
                  c.a_count == c.b_count ? ", same count" : ", COUNTS DIFFER");
    r.agreement = buf;
  }
}

void register_benchmarks(std::size_t voxels) {
  for (auto& rp : g_rows) {
    Row* r = rp.get();
    benchmark::RegisterBenchmark(
        ("iso/" + r->name).c_str(),
        [r, voxels](benchmark::State& state) {
          if (!r->skip.empty()) {
            state.SkipWithError(r->skip.c_str());
            return;
          }
          Counts c;
          for (auto _ : state) {
            c = r->run();
            benchmark::ClobberMemory();
          }
          state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(voxels));
          if (r->role != Role::kBound) {
            state.counters["triangles"] = double(c.triangles);
            state.counters["vertices"] = double(c.vertices);
          } else {
            state.SetBytesProcessed(std::int64_t(state.iterations()) *
                                    std::int64_t(voxels * sizeof(float)));
          }
          state.SetLabel(role_name(r->role));
        })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
}

void print_summary(const fd::Grid3& g, const std::string& vtk_info, std::size_t ambiguous) {
  const double voxels = double(g.values.size());
  std::printf(
      "\nSummary: iso-surface of the %d^3 two-blob float field (%.1f M voxels, %.0f MB), iso "
      "%.1f,\n",
      g.nx, voxels / 1e6, voxels * 4 / 1048576.0, kIso);
  std::printf("single thread, wall clock; ratio = own (same normals setting) / this row. %s.\n",
              vtk_info.c_str());
  std::printf("\n  %-30s %-5s %-7s %11s %9s %10s %10s %9s %9s  %s\n", "contestant", "role",
              "normals", "M voxels/s", "ms", "triangles", "vertices", "own/this", "of bound",
              "agreement");
  double bound = 0;
  for (auto& rp : g_rows)
    if (rp->role == Role::kBound) bound = rp->rate;
  for (auto& rp : g_rows) {
    const Row& r = *rp;
    double own = 0;
    for (auto& op : g_rows)
      if (op->role == Role::kOwn && op->normals == r.normals) own = op->rate;
    char rate[32] = "-", ms[32] = "-", ratio[32] = "", frac[32] = "";
    if (r.rate > 0) {
      std::snprintf(rate, sizeof rate, "%.1f", r.rate / 1e6);
      std::snprintf(ms, sizeof ms, "%.1f", voxels / r.rate * 1e3);
      if (bound > 0 && r.role != Role::kBound)
        std::snprintf(frac, sizeof frac, "%.1f%%", 100 * r.rate / bound);
      if (r.role == Role::kPeer && own > 0)
        std::snprintf(ratio, sizeof ratio, "%.2fx", own / r.rate);
    }
    char gbs[64];
    std::snprintf(gbs, sizeof gbs, "%.1f GB/s read", r.rate * 4 / 1e9);
    const std::string status = !r.skip.empty() ? "SKIPPED: " + r.skip
                               : r.rate <= 0   ? "not run (filtered out)"
                               : r.role == Role::kBound
                                   ? std::string(gbs)
                                   : r.agreement + (r.mismatch ? "  <-- MISMATCH" : "");
    const bool mesh = r.role != Role::kBound && r.skip.empty();
    std::printf("  %-30s %-5s %-7s %11s %9s %10s %10s %9s %9s  %s\n", r.name.c_str(),
                role_name(r.role),
                r.normals < 0 ? ""
                : r.normals   ? "on"
                              : "off",
                rate, ms, mesh ? std::to_string(r.counts.triangles).c_str() : "",
                mesh ? std::to_string(r.counts.vertices).c_str() : "", ratio, frac, status.c_str());
  }
  std::printf(
      "\nThe bound: a streaming read of the %.0f MB field (bound/stream_sum), in voxels/s at that "
      "bandwidth.\n",
      voxels * 4 / 1048576.0);
  std::printf(
      "Triangles differ where a cell has a saddle face (the own core decides each with the "
      "asymptotic\n");
  std::printf("decider, VTK by the case alone): %zu of the own core's crossed cells have one.\n",
              ambiguous);
}

}  // namespace

int main(int argc, char** argv) {
  const bool color = gllab::bench::console_color(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;

  static const fd::Grid3 grid = fd::two_blob_benchmark_field(kN);
  const std::size_t voxels = grid.values.size();

  static Own own_normals{&grid, {}, {}};
  own_normals.options.faces = fd::FaceRule::kDecider;
  own_normals.options.normals = true;
  static Own own_plain{&grid, {}, {}};
  own_plain.options.faces = fd::FaceRule::kDecider;
  own_plain.options.normals = false;
  add("own_decider_normals", Role::kOwn, 1).run = [] { return own_normals.run(); };
  add("own_decider_no_normals", Role::kOwn, 0).run = [] { return own_plain.run(); };
  const std::string vtk_info = vtk_setup(grid);
  add("stream_sum", Role::kBound, -1).run = [voxels] {
    float sum = stream_sum(grid.values.data(), voxels);
    benchmark::DoNotOptimize(sum);
    return Counts{};
  };

  std::printf("%s\n", vtk_info.c_str());
  std::printf(
      "Agreement with the own core (one run of each before timing; vertices as sets, 1e-6):\n");
  run_checks(own_plain);
  fd::McOptions cells;
  cells.normals = false;
  cells.record_cells = true;
  const std::size_t ambiguous = fd::peer::ambiguous_cells(fd::marching_cubes(grid, kIso, cells));
  for (auto& r : g_rows) {
    if (r->role == Role::kBound) continue;
    std::printf("  %-32s %s\n", r->name.c_str(),
                !r->skip.empty() ? ("SKIPPED: " + r->skip).c_str()
                                 : (std::to_string(r->counts.triangles) + " triangles, " +
                                    std::to_string(r->counts.vertices) + " vertices; " +
                                    r->agreement + (r->mismatch ? "  <-- MISMATCH" : ""))
                                       .c_str());
  }
  std::printf("  cells with a saddle face (own, record_cells): %zu\n\n", ambiguous);
  std::fflush(stdout);

  register_benchmarks(voxels);
  gllab::bench::RateReporter reporter(color, {"items_per_second"});
  benchmark::RunSpecifiedBenchmarks(&reporter);
  for (auto& r : g_rows) r->rate = reporter.rate("iso/" + r->name);
  print_summary(grid, vtk_info, ambiguous);
  benchmark::Shutdown();

  bool mismatch = false;
  for (auto& r : g_rows) mismatch |= r->mismatch;
  if (mismatch)
    std::fprintf(stderr,
                 "iso_bench: a peer's vertices disagree with the own core (MISMATCH above)\n");
  return mismatch ? 1 : 0;
}
