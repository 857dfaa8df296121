// bench/csg_bench.cpp — lab 33's CSG rendering with the stencil buffer against OpenCSG 1.5
// (Kirsch and Döllner; libopencsg-dev, `./lab bench` installs it), in one run, in one GLX
// window of 512 x 512 (under xvfb-run on this machine: llvmpipe), and the core's exact ray
// casting (common/space/csg.h, Roth 1982) in rays per second.
//
// Frames: the "sieve" trees of space::csg_catalogue(), box ∩ sphere minus 2, 6 and 14 bores,
// one product of 4, 8 and 16 primitives. Ours is lab 33's own view (its draw function, from
// the lab's object code) by Goldfeather and by SCS, lit, with its caption and tree diagram;
// OpenCSG's is OpenCSG::render and a shading pass with GL_EQUAL, lit. Every frame ends with
// glFinish, so a frame's time is the time to draw it.
#include <GL/glew.h>  // before any other GL header
#include <opencsg.h>

#include <GL/freeglut.h>
#include <benchmark/benchmark.h>

#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "gl/scene.h"
#include "harness/lab.h"
#include "opencsg_peer.h"
#include "rate_reporter.h"
#include "space/csg.h"

namespace {

namespace sp = gllab::space;
constexpr int kSize = 512;
const gllab::Rgb kClear{.1f, .11f, .14f};

int tree_index(int primitives) {
  const auto& trees = sp::csg_catalogue();
  for (std::size_t k = 0; k < trees.size(); ++k)
    if (trees[k].name == "sieve " + std::to_string(primitives)) return int(k);
  return -1;
}

// Lab 33's view `view` of the sieve with `primitives` primitives.
void BM_lab33(benchmark::State& state, const std::string& view, int primitives) {
  static gllab::Lab lab = [] {
    gllab::Lab l = gllab::define_lab();
    l.init();
    return l;
  }();
  gllab::State s(lab.views, lab.params, lab.points);
  s.width = s.height = kSize;
  s.select_view(view);
  s.set("tree", tree_index(primitives));
  const gllab::View& v = s.current_view();
  for (auto _ : state) {
    glViewport(0, 0, kSize, kSize);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    v.draw(s);
    glFinish();
  }
  state.counters["frames/s"] = benchmark::Counter(double(state.iterations()),
                                                  benchmark::Counter::kIsRate);
}

void BM_opencsg(benchmark::State& state, gllab::OpenCsgAlgorithm algorithm, int primitives) {
  const sp::CsgTree& tree = sp::csg_catalogue()[std::size_t(tree_index(primitives))].tree;
  for (auto _ : state) {
    glViewport(0, 0, kSize, kSize);
    gllab::ortho_fit(kSize, kSize, 1.6, 1.6);  // lab 33's camera
    gllab::enable_headlight();
    gllab::look_from_above(30, 30);
    gllab::draw_with_opencsg(tree, algorithm, kClear, true);
    glFinish();
  }
  state.counters["frames/s"] = benchmark::Counter(double(state.iterations()),
                                                  benchmark::Counter::kIsRate);
}

// Rays through the classic object and the 16-primitive sieve: origins on a sphere of radius
// 3, aimed at points in [-1, 1]^3 (fixed seed).
void BM_rays(benchmark::State& state, int tree) {
  const sp::CsgTree& t = sp::csg_catalogue()[std::size_t(tree)].tree;
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<std::pair<sp::Vec3, sp::Vec3>> rays;
  for (int k = 0; k < 4096; ++k) {
    const double x = g(rng), y = g(rng), z = g(rng), a = u(rng), b = u(rng), c = u(rng);
    const sp::Vec3 o = (3 / std::sqrt(x * x + y * y + z * z)) * sp::Vec3{x, y, z};
    rays.push_back({o, sp::Vec3{a, b, c} - o});
  }
  std::size_t i = 0, hits = 0;
  for (auto _ : state) {
    const auto& r = rays[i++ % rays.size()];
    hits += sp::first_hit(t, r.first, r.second).hit;
  }
  benchmark::DoNotOptimize(hits);
  state.counters["rays/s"] = benchmark::Counter(double(state.iterations()),
                                                benchmark::Counter::kIsRate);
}

}  // namespace

int main(int argc, char** argv) {
  const bool color = gllab::bench::console_color(argc, argv);
  benchmark::Initialize(&argc, argv);
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_SINGLE | GLUT_RGBA | GLUT_DEPTH | GLUT_STENCIL);
  glutInitWindowSize(kSize, kSize);
  const int window = glutCreateWindow("csg_bench");
  std::printf("GL_RENDERER %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  const int sizes[] = {4, 8, 16};
  for (int n : sizes) {
    const std::string k = std::to_string(n);
    benchmark::RegisterBenchmark(("frame/lab33_goldfeather/" + k).c_str(), BM_lab33, "goldfeather", n)
        ->Unit(benchmark::kMillisecond)->UseRealTime();
    benchmark::RegisterBenchmark(("frame/opencsg_goldfeather/" + k).c_str(), BM_opencsg,
                                 gllab::OpenCsgAlgorithm::kGoldfeather, n)
        ->Unit(benchmark::kMillisecond)->UseRealTime();
    benchmark::RegisterBenchmark(("frame/lab33_scs/" + k).c_str(), BM_lab33, "scs", n)
        ->Unit(benchmark::kMillisecond)->UseRealTime();
    benchmark::RegisterBenchmark(("frame/opencsg_scs/" + k).c_str(), BM_opencsg,
                                 gllab::OpenCsgAlgorithm::kScs, n)
        ->Unit(benchmark::kMillisecond)->UseRealTime();
  }
  benchmark::RegisterBenchmark("rays/classic", BM_rays, 0)->Unit(benchmark::kNanosecond);
  benchmark::RegisterBenchmark("rays/sieve_16", BM_rays, tree_index(16))
      ->Unit(benchmark::kNanosecond);
  gllab::bench::RateReporter reporter(color, {"frames/s", "rays/s"});
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf("\nframes/s (512 x 512)  lab 33 Goldfeather / OpenCSG Goldfeather   "
              "lab 33 SCS / OpenCSG SCS\n");
  for (int n : sizes) {
    const std::string k = std::to_string(n);
    const double lg = reporter.rate("frame/lab33_goldfeather/" + k);
    const double og = reporter.rate("frame/opencsg_goldfeather/" + k);
    const double ls = reporter.rate("frame/lab33_scs/" + k), os = reporter.rate("frame/opencsg_scs/" + k);
    std::printf("%2d primitives        %7.1f / %7.1f = %5.2fx               %7.1f / %7.1f = %5.2fx\n",
                n, lg, og, og > 0 ? lg / og : 0, ls, os, os > 0 ? ls / os : 0);
  }
  std::printf("ray-CSG first hits/s (one thread): classic %.3g, sieve 16 %.3g\n",
              reporter.rate("rays/classic"), reporter.rate("rays/sieve_16"));
  benchmark::Shutdown();
  OpenCSG::freeResources();
  glutDestroyWindow(window);
  glutExit();
  return 0;
}
