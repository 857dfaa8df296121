// tests/image/test_images.h — small images the image tests share.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "image/image.h"

namespace gllab::testing {

using Bytes = std::vector<std::uint8_t>;

// Each byte uniform in 0..255, from a fixed seed so a failure can be replayed.
inline Image random_image(int width, int height, unsigned seed) {
  Image img(width, height);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> byte(0, 255);
  for (auto& b : img.rgba) b = static_cast<std::uint8_t>(byte(rng));
  return img;
}

// The four channels of pixel (x, y).
inline Bytes rgba_at(const Image& img, int x, int y) {
  const std::uint8_t* p = img.pixel(x, y);
  return Bytes(p, p + 4);
}

}  // namespace gllab::testing
