// tests/field/skimage_peer_test.cpp — field::marching_cubes against
// scikit-image's skimage.measure.marching_cubes (method='lorensen',
// allow_degenerate=True; tests/field/skimage_peer.py says why these) on the
// grids of peer_support.h. The script runs in its own process (tools/process.h):
// it reads the grid's raw floats and sizes, and writes its vertices in index
// space, (i, j, k) order; here they become origin + index * spacing (double)
// and are compared with the own vertices as sets, to 1e-6. The triangle counts
// are printed (skimage's table is Lorensen and Cline's, as VTK's: they differ
// from the own decider's in cells with a saddle face).
//
// Skips, with the reason, when no python3 can import numpy and skimage
// (Debian: python3-skimage, for /usr/bin/python3; ./lab bench installs it).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "peer_support.h"
#include "process.h"

namespace gllab::field::peer {
namespace {

namespace fs = std::filesystem;

// The python3 programs to try: each python3 on PATH (posix_spawn does not
// search it), then Debian's, which python3-skimage installs for (a pyenv or
// venv python3 first on PATH usually lacks it).
std::vector<std::string> python_candidates() {
  std::vector<std::string> found;
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    if (dir.empty()) continue;
    const fs::path p = fs::path(dir) / "python3";
    if (::access(p.c_str(), X_OK) == 0) found.push_back(p.string());
  }
  found.push_back("/usr/bin/python3");
  std::vector<std::string> unique;
  for (const std::string& p : found) {
    std::error_code ec;
    const fs::path real = fs::canonical(p, ec);
    bool seen = false;
    for (const std::string& u : unique) seen |= !ec && fs::equivalent(u, real, ec);
    if (!seen && fs::exists(p)) unique.push_back(p);
  }
  return unique;
}

std::string last_line(std::string text) {
  while (!text.empty() && text.back() == '\n') text.pop_back();
  return text.substr(text.rfind('\n') + 1);
}

// The first python3 that imports numpy and skimage; else empty and why.
std::string find_python(std::string& why) {
  const std::vector<std::string> candidates = python_candidates();
  if (candidates.empty()) {
    why = "python3 not found (on PATH or /usr/bin)";
    return "";
  }
  why = "no python3 imports scikit-image (python3-skimage; ./lab bench installs it):";
  for (const std::string& py : candidates) {
    const ProcessResult r = run_process({py, "-c", "import numpy, skimage.measure"}, {}, 60);
    if (r.exit_status == 0) return py;
    why +=
        " " + py + ": " + (r.started ? last_line(r.err) : std::string("cannot be executed")) + ";";
  }
  return "";
}

struct ScratchDir {
  fs::path path;
  ScratchDir() {
    path = fs::temp_directory_path() / ("gllab_skimage_peer_" + std::to_string(::getpid()));
    fs::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

std::size_t json_count(const std::string& text, const std::string& key) {
  const std::size_t at = text.find("\"" + key + "\":");
  if (at == std::string::npos) return std::size_t(-1);
  return std::size_t(std::strtoull(text.c_str() + at + key.size() + 3, nullptr, 10));
}

class SkimagePeer : public ::testing::TestWithParam<int> {};

TEST_P(SkimagePeer, SameVertices) {
  static std::string why;
  static const std::string python = find_python(why);
  if (python.empty()) GTEST_SKIP() << why;

  const PeerCase pc = peer_case(GetParam());
  const Grid3& g = pc.grid;
  ASSERT_EQ(values_equal_to(g, pc.c), 0u) << pc.name;

  ScratchDir dir;
  const fs::path volume = dir.path / "volume.f32", sizes = dir.path / "sizes.json",
                 out = dir.path / "vertices.f32";
  {
    std::ofstream v(volume, std::ios::binary);
    v.write(reinterpret_cast<const char*>(g.values.data()),
            std::streamsize(g.values.size() * sizeof(float)));
    ASSERT_TRUE(v.good());
    char json[200];
    std::snprintf(json, sizeof json, "{\"nx\": %d, \"ny\": %d, \"nz\": %d, \"level\": %.17g}\n",
                  g.nx, g.ny, g.nz, pc.c);
    std::ofstream(sizes) << json;
  }
  const std::string script = std::string(GLLAB_SOURCE_DIR) + "/tests/field/skimage_peer.py";
  const ProcessResult r =
      run_process({python, script, volume.string(), sizes.string(), out.string()}, {}, 600);
  ASSERT_EQ(r.exit_status, 0) << python << " " << script << ": " << r.err;
  const std::size_t vertices = json_count(r.out, "vertices"),
                    triangles = json_count(r.out, "triangles");

  std::vector<float> raw(vertices * 3);
  std::ifstream in(out, std::ios::binary);
  in.read(reinterpret_cast<char*>(raw.data()), std::streamsize(raw.size() * sizeof(float)));
  ASSERT_TRUE(in.good()) << "reading " << vertices << " vertices from " << out;
  std::vector<P3> peer(vertices);
  for (std::size_t k = 0; k < vertices; ++k)
    peer[k] = {g.origin.x + raw[3 * k] * g.spacing.x, g.origin.y + raw[3 * k + 1] * g.spacing.y,
               g.origin.z + raw[3 * k + 2] * g.spacing.z};

  McOptions options;
  options.normals = false;
  options.record_cells = true;
  const McResult own = marching_cubes(g, pc.c, options);
  options.faces = FaceRule::kLorensenCline;
  options.record_cells = false;
  const std::size_t own_lc = marching_cubes(g, pc.c, options).mesh.triangle_count();

  const SetComparison cmp = compare_sets(positions(own.mesh), peer);
  EXPECT_TRUE(cmp.agree()) << pc.name << ": " << describe(cmp, "own", "skimage");
  std::printf(
      "[ peer     ] %s: vertices own %zu, skimage %zu; max distance own->skimage %.2e, "
      "skimage->own %.2e; "
      "triangles own decider %zu, own Lorensen-Cline %zu, skimage lorensen %zu; cells with a "
      "saddle face %zu "
      "(python %s)\n",
      pc.name.c_str(), cmp.a_count, cmp.b_count, cmp.a_to_b, cmp.b_to_a, own.mesh.triangle_count(),
      own_lc, triangles, ambiguous_cells(own), python.c_str());
}

INSTANTIATE_TEST_SUITE_P(Grids, SkimagePeer, ::testing::Range(0, kPeerCases),
                         [](const ::testing::TestParamInfo<int>& info) {
                           return peer_case_name(info.param);
                         });

}  // namespace
}  // namespace gllab::field::peer
