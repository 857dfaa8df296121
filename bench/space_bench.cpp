// bench/space_bench.cpp — ray queries against 10^5 triangles: the scene octree
// (common/space/scene_octree.h, lecture notes ch. 1, §1.8 Space partitioning,
// "Octrees") against brute force and against Embree 3's BVH, the state of the
// art (libembree-dev; `./lab bench` installs it), on one thread, in one run.
// Then the octree's build time and memory as the triangle count grows.
//
// The scene: torus_with_triangles(10^5) (R = 1, r = 0.4; 100,352 triangles).
// The rays: origins uniform in [-2, 2]^3 outside the torus's box, aimed at
// points uniform in [-1.5, 1.5] x [-1.5, 1.5] x [-0.5, 0.5] (fixed seed): about
// 60 % hit (the count is printed). The same rays for every row.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "mesh/indexed_mesh.h"
#include "rate_reporter.h"
#include "space/scene_octree.h"

#ifdef GLLAB_BENCH_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace {

namespace sp = gllab::space;
using sp::Vec3;

constexpr std::size_t kTriangles = 100000, kRays = 1 << 16, kBruteRays = 256;

const gllab::IndexedMesh& mesh() {
  static const gllab::IndexedMesh m = gllab::torus_with_triangles(kTriangles);
  return m;
}
const std::vector<sp::Ray>& rays() {
  static const std::vector<sp::Ray> r = [] {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(-2, 2), x(-1.5, 1.5), z(-.5, .5);
    std::vector<sp::Ray> out;
    while (out.size() < kRays) {
      const Vec3 o{u(rng), u(rng), u(rng)}, target{x(rng), x(rng), z(rng)};
      if (std::abs(o.x) < 1.4 && std::abs(o.y) < 1.4 && std::abs(o.z) < 0.4) continue;
      out.push_back({o, target - o});
    }
    return out;
  }();
  return r;
}
const sp::SceneOctree& octree() {
  static const sp::SceneOctree o(mesh());
  return o;
}

void BM_brute_force(benchmark::State& state) {
  std::size_t i = 0, hits = 0;
  for (auto _ : state) {
    hits += sp::first_hit_brute_force(mesh(), rays()[i++ % kBruteRays]).hit;
  }
  benchmark::DoNotOptimize(hits);
  state.counters["rays/s"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_octree(benchmark::State& state) {
  const sp::SceneOctree& o = octree();
  std::size_t i = 0, hits = 0;
  for (auto _ : state) hits += o.first_hit(rays()[i++ % kRays]).hit;
  benchmark::DoNotOptimize(hits);
  state.counters["rays/s"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

#ifdef GLLAB_BENCH_HAVE_EMBREE
struct Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  Embree() {
    device = rtcNewDevice(nullptr);
    scene = rtcNewScene(device);
    const gllab::IndexedMesh& m = mesh();
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    float* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), m.vertex_count()));
    std::copy(m.positions.begin(), m.positions.end(), v);
    unsigned* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), m.triangle_count()));
    std::copy(m.indices.begin(), m.indices.end(), t);
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene);
  }
  ~Embree() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
  // The first hit: the triangle, or -1.
  long hit(const sp::Ray& r, float* t = nullptr) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit h{};
    h.ray.org_x = float(r.origin.x), h.ray.org_y = float(r.origin.y),
    h.ray.org_z = float(r.origin.z);
    h.ray.dir_x = float(r.direction.x), h.ray.dir_y = float(r.direction.y);
    h.ray.dir_z = float(r.direction.z);
    h.ray.tnear = 0, h.ray.tfar = INFINITY, h.ray.mask = ~0u;
    h.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &h);
    if (t) *t = h.ray.tfar;
    return h.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1 : long(h.hit.primID);
  }
};
const Embree& embree() {
  static const Embree e;
  return e;
}
void BM_embree(benchmark::State& state) {
  const Embree& e = embree();
  std::size_t i = 0, hits = 0;
  for (auto _ : state) hits += e.hit(rays()[i++ % kRays]) >= 0;
  benchmark::DoNotOptimize(hits);
  state.counters["rays/s"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
#endif

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  const bool color = gllab::bench::console_color(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;

  // The rays' mix, and what the octree does per ray (from its statistics).
  std::size_t hits = 0;
  sp::RayStats stats;
  for (const sp::Ray& r : rays()) hits += octree().first_hit(r, &stats).hit;
  std::printf("Scene: %zu triangles (torus_with_triangles); %zu rays, %.1f %% hit.\n",
              mesh().triangle_count(), kRays, 100.0 * hits / kRays);
  std::printf(
      "Octree: %zu nodes, %zu leaves, depth %d, %zu references, %.1f MB; per ray "
      "%.1f triangles tested in %.1f leaves.\n",
      octree().node_count(), octree().leaf_count(), octree().depth(), octree().references(),
      octree().bytes() / 1048576.0, double(stats.triangles_tested) / kRays,
      double(stats.cells_visited) / kRays);
  std::size_t same = 0;
  for (std::size_t i = 0; i < kBruteRays; ++i) {
    const sp::Hit a = octree().first_hit(rays()[i]),
                  b = sp::first_hit_brute_force(mesh(), rays()[i]);
    same += a.hit == b.hit && (!a.hit || (a.triangle == b.triangle && a.t == b.t));
  }
  std::printf("Octree = brute force on %zu of %zu rays.\n", same, kBruteRays);
#ifdef GLLAB_BENCH_HAVE_EMBREE
  const auto start = std::chrono::steady_clock::now();
  embree();
  std::printf("Embree %s: BVH built in %.1f ms (its own threads).\n", RTC_VERSION_STRING,
              1e3 * seconds_since(start));
  std::size_t agree = 0;
  for (const sp::Ray& r : rays()) {
    const sp::Hit a = octree().first_hit(r);
    agree += (a.hit ? long(a.triangle) : -1) == embree().hit(r);
  }
  std::printf("Octree and Embree (float) agree on the triangle hit for %zu of %zu rays.\n", agree,
              kRays);
#else
  std::printf("Embree: not installed (libembree-dev; ./lab bench installs it): skipped.\n");
#endif
  // Build time and memory as the scene grows (one build each; single thread).
  std::printf("\n%12s %12s %10s %10s %8s\n", "triangles", "build ms", "nodes", "MB", "depth");
  for (const std::size_t n : {1000u, 10000u, 100000u, 1000000u}) {
    const gllab::IndexedMesh m = gllab::torus_with_triangles(n);
    const auto t0 = std::chrono::steady_clock::now();
    const sp::SceneOctree o(m);
    const double ms = 1e3 * seconds_since(t0);
    std::printf("%12zu %12.1f %10zu %10.2f %8d\n", m.triangle_count(), ms, o.node_count(),
                o.bytes() / 1048576.0, o.depth());
  }
  std::printf("\n");
  std::fflush(stdout);

  benchmark::RegisterBenchmark("rays/brute_force", BM_brute_force)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("rays/octree", BM_octree)->Unit(benchmark::kNanosecond);
#ifdef GLLAB_BENCH_HAVE_EMBREE
  benchmark::RegisterBenchmark("rays/embree", BM_embree)->Unit(benchmark::kNanosecond);
#endif
  gllab::bench::RateReporter reporter(color, {"rays/s"});
  benchmark::RunSpecifiedBenchmarks(&reporter);
  const double brute = reporter.rate("rays/brute_force"), oct = reporter.rate("rays/octree");
  std::printf("\nrays/s on one thread: brute force %.3g, octree %.3g (%.0fx brute force)", brute,
              oct, oct / brute);
#ifdef GLLAB_BENCH_HAVE_EMBREE
  const double emb = reporter.rate("rays/embree");
  std::printf(", Embree %.3g (Embree / octree %.1fx)", emb, emb / oct);
#endif
  std::printf("\n");
  benchmark::Shutdown();
  return 0;
}
