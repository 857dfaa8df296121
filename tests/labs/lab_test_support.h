// tests/labs/lab_test_support.h — rendering a lab's view from a test.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
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

/// An 8-bit colour as the framebuffer holds it: round(255 * the lab's float).
struct Rgb8 {
  int r, g, b;
};

/// Within `tolerance` in every channel of one of `colours` (the rounding of a
/// float colour to 8 bits may go either way).
inline bool has_colour(const Image& im, int x, int y, const std::vector<Rgb8>& colours, int tolerance = 2) {
  const std::uint8_t* p = im.pixel(x, y);
  for (const Rgb8& c : colours)
    if (std::abs(p[0] - c.r) <= tolerance && std::abs(p[1] - c.g) <= tolerance && std::abs(p[2] - c.b) <= tolerance)
      return true;
  return false;
}

/// A black image, white where `im` has one of the colours inside the pixel
/// rectangle [x0, x1) x [y0, y1) (default: everywhere), so that what a lab drew
/// in one colour can be compared with what it drew in another.
inline Image colour_mask(const Image& im, const std::vector<Rgb8>& colours, int x0 = 0, int y0 = 0, int x1 = -1,
                         int y1 = -1) {
  Image mask(im.width, im.height);
  for (int y = std::max(0, y0); y < (y1 < 0 ? im.height : std::min(y1, im.height)); ++y)
    for (int x = std::max(0, x0); x < (x1 < 0 ? im.width : std::min(x1, im.width)); ++x) {
      std::uint8_t* m = mask.pixel(x, y);
      m[3] = 255;
      if (has_colour(im, x, y, colours)) m[0] = m[1] = m[2] = 255;
    }
  return mask;
}

/// How many pixels of a mask are set.
inline long long mask_count(const Image& mask) {
  long long n = 0;
  for (std::size_t k = 0; k < mask.rgba.size(); k += 4) n += mask.rgba[k] != 0;
  return n;
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
