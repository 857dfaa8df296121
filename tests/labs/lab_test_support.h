// tests/labs/lab_test_support.h — rendering a lab's view from a test.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "image/compare.h"
#include "image/image.h"
#include "test_support.h"

namespace gllab::testing {

/// Renders `view` of `lab` headless with `--set` for each of `sets` (and
/// `--time` when given) into a file in dir. A failed run fails the test (the
/// read that follows then throws, naming the missing file).
inline Image render_view(const std::string& lab, const ScratchDir& dir, const std::string& view,
                         const std::vector<std::string>& sets = {}, const std::string& time = "") {
  std::string name = lab + "__" + view;
  std::vector<std::string> argv = {headless(lab), "--view", view};
  for (const std::string& s : sets) {
    argv.insert(argv.end(), {"--set", s});
    name += "_" + s;
  }
  if (!time.empty()) {
    argv.insert(argv.end(), {"--time", time});
    name += "_t" + time;
  }
  const std::string out = (dir / (name + ".png")).string();
  argv.insert(argv.end(), {"--out", out});
  const ProcessResult r = run_process(argv);
  EXPECT_EQ(r.exit_status, 0) << r.err;
  return read_png(out);
}

/// The text a view draws, one string per line in drawing order (the headless
/// runner's --print-text: captions, labels, the numbers a view shows).
inline std::vector<std::string> view_text(const std::string& lab, const ScratchDir& dir, const std::string& view,
                                          const std::vector<std::string>& sets = {}) {
  std::vector<std::string> argv = {headless(lab), "--view", view, "--print-text", "--out",
                                   (dir / (lab + "__" + view + "_text.png")).string()};
  for (const std::string& s : sets) argv.insert(argv.end(), {"--set", s});
  const ProcessResult r = run_process(argv);
  EXPECT_EQ(r.exit_status, 0) << r.err;
  std::vector<std::string> lines;
  std::stringstream in(r.out);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// The numbers that follow `prefix` in the lines that start with it, in
/// order: numbers_after(lines, "max deviation ") of "max deviation 7.6e-03"
/// is {0.0076}. A line whose rest does not start with a number fails the test.
inline std::vector<double> numbers_after(const std::vector<std::string>& lines, const std::string& prefix) {
  std::vector<double> out;
  for (const std::string& line : lines) {
    if (line.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = line.substr(prefix.size());
    char* end = nullptr;
    const double v = std::strtod(rest.c_str(), &end);
    EXPECT_NE(end, rest.c_str()) << "no number after '" << prefix << "' in '" << line << "'";
    out.push_back(v);
  }
  return out;
}

/// The number before `suffix` in each line that ends with it: numbers_before(
/// lines, " triangles") of "716 triangles" and "direct call: 716 triangles" is {716, 716}.
inline std::vector<double> numbers_before(const std::vector<std::string>& lines, const std::string& suffix) {
  std::vector<double> out;
  for (const std::string& line : lines) {
    if (line.size() < suffix.size() || line.compare(line.size() - suffix.size(), suffix.size(), suffix) != 0) continue;
    const std::string head = line.substr(0, line.size() - suffix.size());
    const std::size_t start = head.find_last_of(' ') == std::string::npos ? 0 : head.find_last_of(' ') + 1;
    out.push_back(std::strtod(head.c_str() + start, nullptr));
  }
  return out;
}

/// Pixels that differ at all (channel threshold 0, no shift excused).
inline long long pixels_differing(const Image& a, const Image& b) {
  return compare_images(a, b, 0).differing_pixels;
}

}  // namespace gllab::testing
