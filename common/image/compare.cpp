// common/image · comparing a rendered image with its reference (see compare.h)
#include "image/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

namespace gllab {
namespace {

constexpr int kChannels = 4;     // R, G, B, A
constexpr double kPeak = 255.0;  // the largest 8-bit value, the "peak" in PSNR
constexpr int kMaxThreshold = 255;

std::string size_text(const Image& img) {
  return std::to_string(img.width) + "x" + std::to_string(img.height);
}

// Both images must be well formed and the same size; the threshold a channel value.
void check_inputs(const Image& reference, const Image& test, int channel_threshold,
                  const char* who) {
  const std::string where = std::string(who) + ": ";
  for (const Image* img : {&reference, &test}) {
    const char* name = img == &reference ? "reference" : "test";
    if (img->width <= 0 || img->height <= 0)
      throw std::invalid_argument(where + name + " image is empty (" + size_text(*img) + ")");
    const std::size_t expected = std::size_t(img->width) * std::size_t(img->height) * kChannels;
    if (img->rgba.size() != expected)
      throw std::invalid_argument(where + name + " image is " + size_text(*img) + " but rgba has " +
                                  std::to_string(img->rgba.size()) + " bytes (expected " +
                                  std::to_string(expected) + ")");
  }
  if (reference.width != test.width || reference.height != test.height)
    throw ImageError(where + "size mismatch: reference " + size_text(reference) + ", test " +
                     size_text(test));
  if (channel_threshold < 0 || channel_threshold > kMaxThreshold)
    throw std::invalid_argument(where + "channel_threshold " + std::to_string(channel_threshold) +
                                " is outside 0..255");
}

// The largest |a[c] - b[c]| over the 4 channels of one pixel.
int max_channel_delta(const std::uint8_t* a, const std::uint8_t* b) {
  int largest = 0;
  for (int c = 0; c < kChannels; ++c) largest = std::max(largest, std::abs(a[c] - b[c]));
  return largest;
}

void check_radius(int shift_radius, const char* who) {
  if (shift_radius < 0 || shift_radius > kMaxShiftRadius)
    throw std::invalid_argument(std::string(who) + ": shift_radius " + std::to_string(shift_radius) +
                                " is outside 0.." + std::to_string(kMaxShiftRadius));
}

// Does `b` have, within `radius` pixels of (x, y), a pixel whose colour is
// within `threshold` of a's pixel at (x, y)?
bool matched_nearby(const Image& a, const Image& b, int x, int y, int radius, int threshold) {
  const std::uint8_t* wanted = a.pixel(x, y);
  for (int yy = std::max(0, y - radius); yy <= std::min(b.height - 1, y + radius); ++yy)
    for (int xx = std::max(0, x - radius); xx <= std::min(b.width - 1, x + radius); ++xx)
      if (max_channel_delta(wanted, b.pixel(xx, yy)) <= threshold) return true;
  return false;
}

// The largest channel difference between the pixel (x, y) of `img` and its 8 neighbours.
int local_contrast(const Image& img, int x, int y) {
  const std::uint8_t* centre = img.pixel(x, y);
  int largest = 0;
  for (int yy = std::max(0, y - 1); yy <= std::min(img.height - 1, y + 1); ++yy)
    for (int xx = std::max(0, x - 1); xx <= std::min(img.width - 1, x + 1); ++xx)
      largest = std::max(largest, max_channel_delta(centre, img.pixel(xx, yy)));
  return largest;
}

// A differing pixel is excused when the difference is explained by a shift
// both ways: the test's colour appears near (x, y) in the reference, and the
// reference's colour appears near (x, y) in the test; and, with an
// edge_contrast, when the pixel lies on a thin feature in either image.
bool shift_explains(const Image& reference, const Image& test, int x, int y, int radius,
                    int threshold, int edge_contrast) {
  if (radius == 0 || !matched_nearby(test, reference, x, y, radius, threshold) ||
      !matched_nearby(reference, test, x, y, radius, threshold))
    return false;
  return edge_contrast == 0 || local_contrast(reference, x, y) >= edge_contrast ||
         local_contrast(test, x, y) >= edge_contrast;
}

void check_edge(int edge_contrast, const char* who) {
  if (edge_contrast < 0 || edge_contrast > kMaxThreshold)
    throw std::invalid_argument(std::string(who) + ": edge_contrast " + std::to_string(edge_contrast) +
                                " is outside 0..255");
}

}  // namespace

double Comparison::mismatched_share() const {
  return total_pixels == 0 ? 0.0 : double(mismatched_pixels) / double(total_pixels);
}

double Comparison::differing_share() const {
  return total_pixels == 0 ? 0.0 : double(differing_pixels) / double(total_pixels);
}

double Comparison::shifted_share() const {
  return total_pixels == 0 ? 0.0 : double(shifted_pixels()) / double(total_pixels);
}

bool Comparison::passes(const Tolerance& t) const {
  score(t);  // checks that t is the tolerance the counts were made with
  return mismatched_share() <= t.max_differing_share && shifted_share() <= t.max_shifted_share;
}

double Comparison::score(const Tolerance& t) const {
  const auto mismatch = [](const char* what, int asked, int used) {
    return std::invalid_argument("Comparison::score: tolerance " + std::string(what) + " " +
                                 std::to_string(asked) + " != the " + what +
                                 " the comparison used (" + std::to_string(used) + ")");
  };
  if (t.channel_threshold != channel_threshold)
    throw mismatch("channel_threshold", t.channel_threshold, channel_threshold);
  if (t.shift_radius != shift_radius) throw mismatch("shift_radius", t.shift_radius, shift_radius);
  if (t.edge_contrast != edge_contrast) throw mismatch("edge_contrast", t.edge_contrast, edge_contrast);
  const auto ratio = [](double share, double limit) {
    if (share == 0.0) return 0.0;
    return limit > 0.0 ? share / limit : std::numeric_limits<double>::infinity();
  };
  return std::max(ratio(mismatched_share(), t.max_differing_share),
                  ratio(shifted_share(), t.max_shifted_share));
}

Comparison compare_images(const Image& reference, const Image& test, const Tolerance& t) {
  return compare_images(reference, test, t.channel_threshold, t.shift_radius, t.edge_contrast);
}

Comparison compare_images(const Image& reference, const Image& test, int channel_threshold,
                          int shift_radius, int edge_contrast) {
  check_inputs(reference, test, channel_threshold, "compare");
  check_radius(shift_radius, "compare");
  check_edge(edge_contrast, "compare");

  Comparison result;
  result.channel_threshold = channel_threshold;
  result.shift_radius = shift_radius;
  result.edge_contrast = edge_contrast;
  result.total_pixels = static_cast<long long>(reference.width) * reference.height;

  // Sums over every channel of every pixel. Integers, so the result does not
  // depend on the summation order: at most 255^2 * 4 * 2^28 < 2^63.
  long long sum_abs = 0;
  long long sum_squared = 0;
  const std::size_t bytes = reference.rgba.size();
  for (std::size_t i = 0; i < bytes; i += kChannels) {
    const std::uint8_t* r = &reference.rgba[i];
    const std::uint8_t* t = &test.rgba[i];
    for (int c = 0; c < kChannels; ++c) {
      const int d = std::abs(r[c] - t[c]);
      sum_abs += d;
      sum_squared += d * d;
    }
    const int delta = max_channel_delta(r, t);
    result.max_delta = std::max(result.max_delta, delta);
    if (delta > channel_threshold) {
      ++result.differing_pixels;
      const auto pixel = static_cast<int>(i / kChannels);
      if (!shift_explains(reference, test, pixel % reference.width, pixel / reference.width,
                          shift_radius, channel_threshold, edge_contrast))
        ++result.mismatched_pixels;
    }
  }

  const double samples = double(result.total_pixels) * kChannels;
  result.mean_abs_error = double(sum_abs) / samples;
  // PSNR = 10 log10(peak^2 / MSE); identical images have MSE 0 and PSNR +inf.
  const double mse = double(sum_squared) / samples;
  result.psnr = mse == 0.0 ? std::numeric_limits<double>::infinity()
                           : 10.0 * std::log10(kPeak * kPeak / mse);
  return result;
}

Image heat_map(const Image& reference, const Image& test, int channel_threshold,
               int shift_radius, int edge_contrast) {
  check_inputs(reference, test, channel_threshold, "heat_map");
  check_radius(shift_radius, "heat_map");
  check_edge(edge_contrast, "heat_map");

  Image map(reference.width, reference.height);
  // The ramp runs over deltas threshold+1 (yellow) .. 255 (red).
  const int first = channel_threshold + 1;
  const int span = kMaxThreshold - first;  // 0 when the threshold is 254
  for (int y = 0; y < reference.height; ++y) {
    for (int x = 0; x < reference.width; ++x) {
      const std::uint8_t* r = reference.pixel(x, y);
      const int delta = max_channel_delta(r, test.pixel(x, y));
      std::uint8_t* out = map.pixel(x, y);
      if (delta <= channel_threshold) {
        // Luma with the Rec. 601 weights 0.299, 0.587, 0.114 as 77/256, 150/256,
        // 29/256 (they sum to 256), rounded; then a quarter of it, a dark grey.
        const int luma = (77 * r[0] + 150 * r[1] + 29 * r[2] + 128) >> 8;
        const auto grey = static_cast<std::uint8_t>(luma / 4);
        out[0] = out[1] = out[2] = grey;
      } else if (shift_explains(reference, test, x, y, shift_radius, channel_threshold,
                                edge_contrast)) {
        out[0] = 0;  // tolerated: a shift of at most shift_radius explains it
        out[1] = 96;
        out[2] = 255;
      } else {
        // Green fades from 255 at `first` to 0 at 255: yellow -> orange -> red.
        const int green = span == 0 ? 0 : (255 * (255 - delta) + span / 2) / span;
        out[0] = 255;
        out[1] = static_cast<std::uint8_t>(green);
        out[2] = 0;
      }
      out[3] = 255;  // opaque, so viewers don't show a checkerboard through it
    }
  }
  return map;
}

}  // namespace gllab
