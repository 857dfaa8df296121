// tests/fuzz/fuzz_options.cpp — the command line both lab runners share
// (common/harness/options.h): parse_options, parse_size, make_state (--view,
// --views, --camera, --set key=value and P[i]=x,y[,z], --load) on a lab made here.
//
// The input is the arguments, one per line, then optionally a NUL byte and the
// bytes of the file that --load names (written to a temporary file; the path
// given on the command line is ignored, so the fuzzer never opens the machine's files).
// Both runners parse it. A refusal must be a UsageError of one line. A state that
// was made must survive a round trip: State::as_arguments() (what the window's `p`
// prints) parsed and applied again gives the same view, camera, parameters and points.
//
// The lab: three views (one kOrbit, one kErrorView), an integer, a real and a toggle
// parameter, a 2D point list P of 5 points and a 3D list Q of 3, and a model (the
// clamped B-spline of degree `degree` on P) so that --load has something to check.
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <typeinfo>
#include <vector>

#include "fuzz_common.h"
#include "harness/lab.h"
#include "harness/options.h"
#include "spline/bspline.h"

namespace {

using namespace gllab;
using gllab::fuzz::check;
using gllab::fuzz::fail;

Lab make_lab() {
  Lab lab;
  lab.id = "99_fuzz";
  lab.title = "lab 99 · fuzz";
  const auto nothing = [](const State&) {};
  lab.views = {{"default", "the curve", nothing},
               {"orbit_view", "turns", nothing, kOrbit},
               {"refused", "an error view", nothing, kErrorView}};
  lab.params = {{"degree", 3, 1, 4, "degree of the curve"},
                {"tolerance", 0.25, 1e-6, 1e3, "a real number"},
                {"lighting", 1, 0, 1, "a toggle"}};
  lab.keys = {{'d', "degree +1", "degree", 1}, {'l', "lighting on/off", "lighting"}};
  lab.points = {{"P", {{0, 0, 0}, {1, 2, 0}, {2, -1, 0}, {3, 1.5, 0}, {4, 0, 0}}, "control points", 2},
                {"Q", {{0, 0, 1}, {1, 1, 1}, {2, 0, -1}}, "3D points", 3}};
  lab.model = [](const State& s) -> Model {
    return spline::clamped_curve(s.points("P"), s.integer("degree"), 2);
  };
  validate_lab(lab);
  return lab;
}

const Lab& lab() {
  static const Lab l = make_lab();
  return l;
}

/// The --load file: one per process, rewritten for each input.
const std::string& load_path() {
  static const std::string path = [] {
    char name[] = "/tmp/gllab_fuzz_options_XXXXXX";
    const int fd = mkstemp(name);
    check(fd >= 0, "cannot make a temporary file");
    close(fd);
    return std::string(name);
  }();
  static const struct Remove {
    ~Remove() { std::remove(path.c_str()); }
  } remove_at_exit;
  return path;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto end = text.find(sep, start);
    parts.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) return parts;
    start = end + 1;
  }
}

bool same_state(const State& a, const State& b) {
  if (a.view_index() != b.view_index() || a.camera != b.camera) return false;
  for (std::size_t i = 0; i < a.params().size(); ++i)
    if (a.params()[i].value != b.params()[i].value) return false;
  for (const PointList& l : a.point_lists()) {
    const auto& pa = a.points(l.name);
    const auto& pb = b.points(l.name);
    for (std::size_t i = 0; i < pa.size(); ++i)
      if (pa[i] != pb[i]) return false;
  }
  return true;
}

/// The state must come back from the arguments it prints.
void round_trip(const State& state) {
  const std::string printed = state.as_arguments();
  std::vector<std::string> args = split(printed, ' ');
  args.insert(args.end(), {"--out", "round_trip.png"});
  try {
    const State again = make_state(lab(), parse_options(args, Runner::kHeadless));
    check(same_state(state, again), "as_arguments() does not reproduce the state: " + printed);
    check(again.as_arguments() == printed, "as_arguments() changed on a round trip: " + printed + " then " +
                                               again.as_arguments());
  } catch (const UsageError& e) {
    fail("as_arguments() printed arguments that are refused: " + printed + ": " + e.what());
  }
}

void run(const std::vector<std::string>& args, Runner runner, const std::string& file) {
  Options o;
  try {
    o = parse_options(args, runner);
  } catch (const UsageError& e) {
    gllab::fuzz::check_one_line(e, "parse_options");
    return;
  } catch (const std::exception& e) {
    fail(std::string("parse_options threw ") + typeid(e).name() + " (not UsageError): " + e.what());
  }
  check(o.width >= 1 && o.width <= kMaxSize && o.height >= 1 && o.height <= kMaxSize,
        "parse_options accepted a size outside 1.." + std::to_string(kMaxSize));
  if (!o.load.empty()) {
    std::FILE* f = std::fopen(load_path().c_str(), "wb");
    check(f != nullptr, "cannot write " + load_path());
    check(std::fwrite(file.data(), 1, file.size(), f) == file.size(), "cannot write " + load_path());
    std::fclose(f);
    o.load = load_path();
  }
  try {
    const State state = make_state(lab(), o);
    check(state.view_index() < lab().views.size(), "view index out of range");
    round_trip(state);
  } catch (const UsageError& e) {
    gllab::fuzz::check_one_line(e, "make_state");
  } catch (const std::exception& e) {
    fail(std::string("make_state threw ") + typeid(e).name() + " (not UsageError): " + e.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const auto nul = input.find('\0');
  const std::string file = nul == std::string::npos ? std::string() : input.substr(nul + 1);
  const std::vector<std::string> args = split(input.substr(0, nul), '\n');
  run(args, Runner::kHeadless, file);
  run(args, Runner::kWindow, file);
  // The lab program's choice (lab_main.cpp): headless only when an option, not a
  // value, asks for it; and then that runner's parser is the one that runs.
  const Runner chosen = gllab::runner_for(args);
  if (chosen == Runner::kHeadless &&
      std::none_of(args.begin(), args.end(), [](const std::string& a) { return a.rfind("--", 0) == 0; }))
    fail("runner_for chose headless without any option");
  return 0;
}
