// bench/submission_bench.cpp — the four ways to send a mesh to OpenGL (lab 05):
// immediate mode, display list, vertex arrays (client memory, glDrawElements)
// and VBO (interleaved buffer + element buffer, GL_STATIC_DRAW), timed in one
// run on the same lit torus at about 1k, 10k, 100k and 1M triangles, in an
// offscreen OSMesa context of 512 x 512 (llvmpipe, the reference renderer).
//
// The paths are lab 05's own code, not a copy: the lab defines them in the
// named namespace lab05 (external linkage) and this program links the lab's
// object code (CMake target 05_submission_modes_code, bench/CMakeLists.txt).
// They are declared again below. A C++ function's link name carries its
// namespace and parameter types, so a declaration whose parameters no longer
// match the lab's fails the link instead of calling something else (the return
// type is not part of the name: keep it the lab's). The scene (the
// projection, light and tilt of the lab's headless default) and the clear
// colour come from the lab too: lab05::set_up_scene and the lab's init().
//
// One iteration = glClear + one draw of the whole mesh + glFinish, timed in
// wall-clock time (UseRealTime): llvmpipe rasterises on its own threads, which
// the CPU time of this thread would not see. Counters: Mtri/s (millions of
// triangles per wall-clock second), Mtri/cpu_s (per CPU second of this thread:
// the GL calls and llvmpipe's vertex stage) and x_immediate (this path's
// Mtri/s / immediate mode's at the same size, in the same run). Two summary
// tables (wall clock, CPU) with the ratios follow the run.
//
// First every path renders each mesh once and its image is compared with
// immediate mode's: they must be byte-identical (lab 05's promise); the
// program exits 1 when one differs.
//
//   build-bench/bin/submission_bench [Google Benchmark flags, e.g. --benchmark_filter=/1000000]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <map>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "harness/lab.h"
#include "harness/offscreen.h"
#include "image/image.h"
#include "mesh/indexed_mesh.h"

// Lab 05's functions (labs/05_submission_modes/05_submission_modes.cpp).
namespace lab05 {
void set_up_scene(const gllab::State& s);
GLuint compile_list(const gllab::IndexedMesh& m);
void fill_buffers(const gllab::IndexedMesh& m, GLuint buffers[2]);
void draw(int path, const gllab::IndexedMesh& m, GLuint list, const GLuint buffers[2]);
void release(GLuint list, const GLuint buffers[2]);
}  // namespace lab05

namespace {

const std::size_t kSizes[] = {1000, 10000, 100000, 1000000};  // asked of torus_with_triangles
constexpr int kFrame = 512;
// lab05::draw's paths are numbered as the lab's views, in order: path p is
// view p, and the view's name names it here. A path the lab adds with its
// view is timed too.
std::vector<std::string> g_names;
int paths() { return int(g_names.size()); }

// One mesh per size, with its list and buffers made before timing.
struct Prepared {
  gllab::IndexedMesh mesh;
  GLuint list = 0, buffers[2] = {0, 0};
  std::size_t triangles() const { return mesh.triangle_count(); }
};
std::vector<Prepared> g_meshes;

void frame(const Prepared& m, int path) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  lab05::draw(path, m.mesh, m.list, m.buffers);
  glFinish();
}

// Lab 05's init() (depth test, clear colour) and its scene at the headless
// default (camera, --time 0), in a kFrame x kFrame frame.
void set_up_scene() {
  const gllab::Lab lab = gllab::define_lab();
  lab.init();
  gllab::State state(lab.views, lab.params);
  state.width = state.height = kFrame;
  glViewport(0, 0, kFrame, kFrame);
  lab05::set_up_scene(state);
  for (const gllab::View& v : lab.views) g_names.push_back(v.name);
}

Prepared prepare(std::size_t asked) {
  Prepared m;
  m.mesh = gllab::torus_with_triangles(asked);
  m.list = lab05::compile_list(m.mesh);
  lab05::fill_buffers(m.mesh, m.buffers);
  return m;
}

std::string run_name(int path, std::size_t triangles) {
  return g_names[std::size_t(path)] + "/" + std::to_string(triangles);
}

// Prints like the console reporter, adds two counters to each row and keeps
// the rates for the summary (the median when --benchmark_repetitions is given):
//   Mtri/cpu_s   triangles per CPU second of this thread: the GL calls and
//                llvmpipe's vertex stage, without its rasteriser threads;
//   x_immediate  Mtri/s / immediate mode's at the same size (immediate mode
//                runs first at every size).
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  enum Clock { kWall, kCpu };
  RatioReporter() : ConsoleReporter(OO_Tabular) {}
  void ReportRuns(const std::vector<Run>& runs) override {
    std::vector<Run> out = runs;
    // First keep every rate of this batch (immediate mode's included), then
    // add the ratios: a row is compared with immediate mode's row of the same
    // kind (an iteration with the median of immediate's iterations, a mean
    // with its mean, a median with its median).
    for (Run& run : out) {
      const auto c = run.counters.find("Mtri/s");
      if (run.error_occurred || c == run.counters.end()) continue;
      const bool iteration = run.run_type == Run::RT_Iteration;
      // Rates on every row, so the table keeps one header; on the stddev and
      // cv rows of --benchmark_repetitions they would mean nothing: 0.
      const bool rate_row = iteration || run.aggregate_name == "mean" || run.aggregate_name == "median";
      const double wall = c->second.value;
      const double cpu = run.cpu_accumulated_time > 0 ? wall * run.real_accumulated_time / run.cpu_accumulated_time : 0;
      run.counters["Mtri/cpu_s"] = rate_row ? cpu : 0;
      run.counters["x_immediate"] = 0;
      if (!rate_row) continue;
      const std::string key = run.run_name.function_name + "#" + run.aggregate_name;
      rates_[kWall][key].push_back(wall);
      rates_[kCpu][key].push_back(cpu);
    }
    for (Run& run : out) {
      const auto c = run.counters.find("Mtri/s");
      if (run.error_occurred || c == run.counters.end() || run.counters["Mtri/cpu_s"] == 0) continue;
      const std::string name = run.run_name.function_name;
      const double immediate =
          rate(g_names[0] + name.substr(name.find('/')), kWall, run.aggregate_name);
      if (immediate > 0) run.counters["x_immediate"] = c->second.value / immediate;
    }
    ConsoleReporter::ReportRuns(out);
  }
  // The median of the iterations' rates, or the given aggregate's rate.
  double rate(const std::string& name, Clock k, const std::string& aggregate = "") const {
    const auto it = rates_[k].find(name + "#" + aggregate);
    if (it == rates_[k].end()) return 0;
    std::vector<double> r = it->second;
    std::sort(r.begin(), r.end());
    return r[r.size() / 2];
  }
  // What the summary shows: the median aggregate when there is one.
  double summary_rate(const std::string& name, Clock k) const {
    const double median = rate(name, k, "median");
    return median > 0 ? median : rate(name, k);
  }

 private:
  std::map<std::string, std::vector<double>> rates_[2];
};

void print_summary(const RatioReporter& reporter, RatioReporter::Clock clock) {
  std::printf("\n%s\n", clock == RatioReporter::kWall
                              ? "Mtri/s, wall clock (what a frame costs), and the ratio to immediate mode:"
                              : "Mtri/s per CPU second of the submitting thread (GL calls + vertex stage), ratio:");
  std::printf("%-12s", "triangles");
  for (const std::string& name : g_names) std::printf(" %22s", name.c_str());
  std::printf("\n");
  for (const Prepared& m : g_meshes) {
    const std::size_t t = m.triangles();
    const double immediate = reporter.summary_rate(run_name(0, t), clock);
    std::printf("%-12zu", t);
    for (int path = 0; path < paths(); ++path) {
      const double r = reporter.summary_rate(run_name(path, t), clock);
      char cell[32] = "-";
      if (r > 0 && immediate > 0) std::snprintf(cell, sizeof cell, "%.2f (%.2fx)", r, r / immediate);
      else if (r > 0) std::snprintf(cell, sizeof cell, "%.2f", r);
      std::printf(" %22s", cell);
    }
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  try {
    gllab::OffscreenContext context(kFrame, kFrame);
    std::printf("renderer: %s, %dx%d, %s\n", context.renderer().c_str(), kFrame, kFrame,
                reinterpret_cast<const char*>(glGetString(GL_VERSION)));
    set_up_scene();
    for (std::size_t asked : kSizes) g_meshes.push_back(prepare(asked));

    // Agreement: every path must give immediate mode's pixels exactly.
    bool differ = false;
    std::printf("\nAgreement with immediate mode (one frame each, 512x512 RGBA bytes):\n");
    for (const Prepared& m : g_meshes) {
      frame(m, 0);
      const gllab::Image reference = context.read_pixels();
      for (int path = 1; path < paths(); ++path) {
        frame(m, path);
        const bool same = context.read_pixels().rgba == reference.rgba;
        differ |= !same;
        std::printf("  %-28s %s\n", run_name(path, m.triangles()).c_str(),
                    same ? "identical" : "DIFFERS  <-- MISMATCH");
      }
    }
    std::printf("\n");
    std::fflush(stdout);

    for (const Prepared& m : g_meshes)
      for (int path = 0; path < paths(); ++path)
        benchmark::RegisterBenchmark(run_name(path, m.triangles()).c_str(),
                                     [&m, path](benchmark::State& state) {
                                       for (auto _ : state) frame(m, path);
                                       state.counters["Mtri/s"] = benchmark::Counter(
                                           double(m.triangles()) / 1e6,
                                           benchmark::Counter::kIsIterationInvariantRate);
                                     })
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);

    std::printf("\nSummary (512x512 OSMesa, lab 05's scene)");
    print_summary(reporter, RatioReporter::kWall);
    print_summary(reporter, RatioReporter::kCpu);
    benchmark::Shutdown();
    for (const Prepared& m : g_meshes) lab05::release(m.list, m.buffers);
    if (differ) std::fprintf(stderr, "submission_bench: a path's image differs from immediate mode's\n");
    return differ ? 1 : 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "submission_bench: %s\n", e.what());
    return 1;
  }
}
