// tests/labs/lab_test_support.h — rendering a lab's view from a test.
#pragma once

#include <gtest/gtest.h>

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

/// Pixels that differ at all (channel threshold 0, no shift excused).
inline long long pixels_differing(const Image& a, const Image& b) {
  return compare_images(a, b, 0).differing_pixels;
}

}  // namespace gllab::testing
