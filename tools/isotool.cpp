// tools/isotool.cpp — iso-surfaces from the command line (lecture notes ch. 1,
// §1.7 Surface representations, Iso-surfaces; §1.5 Blobby objects).
//
//   isotool INPUT [--iso C] [--grid N] [--faces decider|lorensen-cline]
//                 [--out FILE.obj] [--stats]
//
// INPUT is a NRRD volume (.nrrd, .nhdr), a blob_scene (.json) or a built-in
// field (sphere, torus, two_blobs); common/io/README.md describes the files.
// Runs field::marching_cubes and writes the surface as Wavefront OBJ.
// Errors: one line on stderr; exit 2 for bad input or usage, 1 when the
// output cannot be written, 0 otherwise (splinetool's conventions).
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "field/density.h"
#include "field/grid.h"
#include "field/marching_cubes.h"
#include "field/mesh_measures.h"
#include "io/field_json.h"
#include "cli.h"
#include "io/obj.h"
#include "io/spline_json.h"
#include "io/volume_nrrd.h"

namespace {

using gllab::cli::kBadInput, gllab::cli::kFailed, gllab::cli::kOk;
using gllab::cli::OutputError, gllab::cli::UsageError;
using gllab::cli::parse_count, gllab::cli::parse_number;
using gllab::io::FileError;
using gllab::io::shortest_text;
using gllab::spline::Vec3;
namespace field = gllab::field;

constexpr int kDefaultGrid = 64;
constexpr int kMaxGrid = 512;

const char* const kHelp =
    "usage: isotool INPUT [--iso C] [--grid N] [--faces decider|lorensen-cline]\n"
    "               [--out FILE.obj] [--stats]\n"
    "\n"
    "The iso-surface {f = C} of a scalar field, by marching cubes, as Wavefront OBJ\n"
    "(v, vn, f a//a; triangles counter-clockwise seen from outside, where f < C).\n"
    "\n"
    "INPUT is one of\n"
    "  FILE.nrrd, FILE.nhdr  a 3-D NRRD volume (any scalar type, read as float with\n"
    "                        its values unchanged: a uint8 volume is 0..255); the\n"
    "                        grid is the volume's own, so --grid is an error, and\n"
    "                        --iso is required (the message names the value range)\n"
    "  FILE.json             a blob_scene (common/io/README.md), sampled at N^3 points\n"
    "                        over its bounds; --iso defaults to the file's \"iso\"\n"
    "  sphere                1 - |x| over [-1.25, 1.25]^3; default iso 0 (the unit sphere)\n"
    "  torus                 0.4 - dist(x, the unit circle around z) over\n"
    "                        [-1.5, 1.5]^2 x [-0.6, 0.6]; default iso 0 (tube radius 0.4)\n"
    "  two_blobs             two Hermite blobs (a = b = 1) at (+-0.65, 0, 0), just\n"
    "                        merged at iso 0.5 (the default), as examples/two_blobs.json\n"
    "\n"
    "  --iso C      the iso-value (finite)\n"
    "  --grid N     fields: N points per axis, 2..512 (default 64)\n"
    "  --faces R    decider (default): the asymptotic decider on every saddle face,\n"
    "               closed surfaces; lorensen-cline: the 1987 table, holes possible\n"
    "  --out FILE   write the OBJ to FILE (atomically) instead of stdout\n"
    "  --stats      print one line per measure: iso, grid, vertices, triangles,\n"
    "               components, euler, closed (yes/no: no boundary, non-manifold or\n"
    "               misoriented edges), area, volume (enclosed), time (marching cubes,\n"
    "               seconds). Without --out only these lines go to stdout (no OBJ).\n"
    "\n"
    "Errors: one line on stderr; exit 2 for bad input or usage, 1 when the output\n"
    "cannot be written, 0 otherwise.\n";

bool ends_with(const std::string& s, const std::string& tail) {
  if (s.size() < tail.size()) return false;
  std::string end = s.substr(s.size() - tail.size());
  std::transform(end.begin(), end.end(), end.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return end == tail;
}

/// What marching cubes runs on, and the iso-value when none is given.
struct Input {
  field::Grid3 grid;
  std::optional<double> default_iso;
};

field::Grid3 sample_box(const field::Field3& f, const gllab::io::Box& box, int n) {
  return field::sample(f, box.lo, box.hi, n, n, n);
}

/// The built-in two_blobs scene (the same as examples/two_blobs.json).
gllab::io::BlobScene two_blobs_scene() {
  gllab::io::BlobScene s;
  s.field.density = field::Density::kHermite;
  s.field.blobs = {{{-0.65, 0, 0}, 1, 1}, {{0.65, 0, 0}, 1, 1}};
  s.iso = 0.5;
  return s;
}

Input read_input(const std::string& input, const std::optional<std::string>& grid_text) {
  Input in;
  const bool volume = ends_with(input, ".nrrd") || ends_with(input, ".nhdr");
  if (volume) {
    if (grid_text)
      throw UsageError("--grid applies to fields, not to volume files ('" + input + "')");
    in.grid = gllab::io::read_nrrd(input);
    return in;
  }
  const int n = grid_text ? parse_count(*grid_text, "--grid", 2, kMaxGrid) : kDefaultGrid;
  if (ends_with(input, ".json")) {
    const gllab::io::BlobScene scene = gllab::io::read_blob_scene(input);
    in.grid = sample_box([&](const Vec3& x) { return scene.field.value(x); },
                         gllab::io::bounds_of(scene), n);
    in.default_iso = scene.iso;
  } else if (input == "sphere") {
    in.grid = sample_box(
        [](const Vec3& x) {
          return field::sphere_field(x, {0, 0, 0}, 1);
        },
        {{-1.25, -1.25, -1.25}, {1.25, 1.25, 1.25}}, n);
    in.default_iso = 0;
  } else if (input == "torus") {
    in.grid = sample_box([](const Vec3& x) { return field::torus_field(x, 1, 0.4); },
                         {{-1.5, -1.5, -0.6}, {1.5, 1.5, 0.6}}, n);
    in.default_iso = 0;
  } else if (input == "two_blobs") {
    const gllab::io::BlobScene scene = two_blobs_scene();
    in.grid = sample_box([&](const Vec3& x) { return scene.field.value(x); },
                         gllab::io::bounds_of(scene), n);
    in.default_iso = scene.iso;
  } else {
    throw UsageError("unknown field '" + input +
                     "' (a .nrrd or .nhdr volume, a blob_scene .json, or sphere, torus, "
                     "two_blobs; isotool --help)");
  }
  return in;
}

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", x);
  return buffer;
}

/// The range of a volume's values, for the message when --iso is missing.
std::string value_range(const field::Grid3& g) {
  const auto [lo, hi] = std::minmax_element(g.values.begin(), g.values.end());
  return "[" + number(*lo) + ", " + number(*hi) + "]";
}

int run(int argc, char** argv) {
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;
  bool stats = false;
  static const std::vector<std::string> kValued = {"iso", "grid", "faces", "out"};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h" || (arg == "help" && argc == 2)) {
      std::cout << kHelp;
      std::cout.flush();
      if (!std::cout) throw OutputError("stdout: cannot write the help text");
      return kOk;
    }
    if (arg.rfind("--", 0) != 0 || arg.size() == 2) {
      positional.push_back(arg);
      continue;
    }
    const std::size_t eq = arg.find('=');
    const std::string key = arg.substr(2, eq == std::string::npos ? std::string::npos : eq - 2);
    if (key == "stats") {
      if (eq != std::string::npos) throw UsageError("--stats takes no value ('" + arg + "')");
      if (stats) throw UsageError("--stats given twice");
      stats = true;
      continue;
    }
    if (std::find(kValued.begin(), kValued.end(), key) == kValued.end())
      throw UsageError("unknown option '--" + key + "' (isotool --help)");
    if (options.count(key)) throw UsageError("--" + key + " given twice");
    if (eq != std::string::npos) {
      options[key] = arg.substr(eq + 1);
    } else {
      if (i + 1 >= argc) throw UsageError("--" + key + " needs a value");
      options[key] = argv[++i];
    }
  }
  if (positional.empty()) throw UsageError("no INPUT (isotool --help)");
  if (positional.size() > 1) throw UsageError("unexpected argument '" + positional[1] + "'");
  const std::string input = positional[0];
  auto option = [&](const std::string& name) -> std::optional<std::string> {
    const auto it = options.find(name);
    if (it == options.end()) return std::nullopt;
    return it->second;
  };

  // Options first, so that a bad value is reported before any work is done.
  std::optional<double> iso;
  if (const auto text = option("iso")) iso = parse_number(*text, "--iso");
  field::McOptions mc;
  if (const auto faces = option("faces")) {
    if (*faces == "decider")
      mc.faces = field::FaceRule::kDecider;
    else if (*faces == "lorensen-cline")
      mc.faces = field::FaceRule::kLorensenCline;
    else
      throw UsageError("--faces: '" + *faces + "' (decider or lorensen-cline)");
  }
  const std::optional<std::string> out = option("out");
  if (out && out->empty()) throw UsageError("--out: empty file name");

  const Input in = read_input(input, option("grid"));
  if (!iso) {
    if (!in.default_iso)
      throw UsageError("a volume needs --iso (the values of '" + input + "' run over " +
                       value_range(in.grid) + ")");
    iso = in.default_iso;
  }

  const auto start = std::chrono::steady_clock::now();
  const field::McResult result = field::marching_cubes(in.grid, *iso, mc);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const gllab::IndexedMesh& mesh = result.mesh;

  const std::string grid_text = std::to_string(in.grid.nx) + " x " + std::to_string(in.grid.ny) +
                                " x " + std::to_string(in.grid.nz);
  const std::string comment =
      "isotool " + input + ": iso " + shortest_text(*iso) + ", grid " + grid_text + ", faces " +
      (mc.faces == field::FaceRule::kDecider ? "decider" : "lorensen-cline");
  if (out) {
    try {
      gllab::io::write_obj(*out, mesh, comment);
    } catch (const FileError& e) {
      throw OutputError(e.what());
    }
  } else if (!stats) {
    std::cout << gllab::io::obj_text(mesh, comment);
  }
  if (stats) {
    const field::MeshTopology t = field::topology(mesh);
    std::cout << "iso " << shortest_text(*iso) << "\n"
              << "grid " << grid_text << "\n"
              << "vertices " << mesh.vertex_count() << "\n"
              << "triangles " << mesh.triangle_count() << "\n"
              << "components " << t.components << "\n"
              << "euler " << t.euler() << "\n"
              << "closed " << (t.closed_and_oriented() ? "yes" : "no") << "\n"
              << "area " << number(field::surface_area(mesh)) << "\n"
              << "volume " << number(field::enclosed_volume(mesh)) << "\n"
              << "time " << number(seconds) << "\n";
  }
  std::cout.flush();
  if (!std::cout)
    throw OutputError("stdout: cannot write (" + std::string(std::strerror(errno)) + ")");
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  return gllab::cli::main_reporting("isotool: ", run, argc, argv);
}
