// tests/deform/morph_test.cpp — cross-fade and morph of two pictures
// (common/deform/morph.cpp).
//
// The pictures are made here: gradients, checkers and stripes (structure in
// every pixel and channel), and light pictures with small dark discs at the
// features. Every expected value names its origin: the morph's definition at
// t = 0 and t = 1 (lecture notes ch. 1, §1.7, "Morphing": m(0) = m1, m(1) =
// m2), the in-between geometry f(1/2, from) = (from + to) / 2, bilinear
// sampling by hand, or the cross-fade's arithmetic.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "deform/morph.h"
#include "deform_checks.h"

namespace gllab::deform {
namespace {

using testing::error_of;
using testing::Random;
using testing::record;

// ---- tolerances (named, never loosened to pass) -----------------------------

/// A morphed disc's centroid lies within this many pixels of f(1/2, from):
/// the disc (radius 4 px) goes through the local affine part of the warp,
/// which keeps centroids; the quadratic part shifts it by about r^2 |f''| / 8
/// (0.02 px with these fits), bilinear sampling and bytes by less (measured:
/// at most 0.04 px over the 6 features).
constexpr double kCentroidPixels = 0.25;

// ---- pictures ---------------------------------------------------------------

/// Gradients in red and green, a checker of 5-pixel cells in blue, alpha
/// falling with x: every pixel differs from its neighbours in some channel.
Image gradient_checker(int w, int h) {
  Image im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = im.pixel(x, y);
      p[0] = std::uint8_t(x * 255 / (w - 1));
      p[1] = std::uint8_t(y * 255 / (h - 1));
      p[2] = ((x / 5 + y / 5) % 2) ? 200 : 40;
      p[3] = std::uint8_t(255 - x * 128 / w);
    }
  return im;
}

/// Waves and diagonal stripes.
Image waves(int w, int h) {
  Image im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = im.pixel(x, y);
      p[0] = std::uint8_t(128 + 120 * std::sin(0.3 * x) * std::cos(0.2 * y));
      p[1] = std::uint8_t((x + 2 * y) % 256);
      p[2] = std::uint8_t((x * y) % 251);
      p[3] = std::uint8_t(200 + (x + y) % 56);
    }
  return im;
}

/// The pixel-index coordinates of a point of the unit square (morph.h:
/// pixel (px, py) has its centre at ((px + 0.5) / W, 1 - (py + 0.5) / H)).
Vec2 to_pixels(const Image& im, Vec2 at) {
  return {at.x * im.width - 0.5, (1 - at.y) * im.height - 0.5};
}

constexpr int kBackground = 220, kInk = 20;
constexpr double kDiscRadius = 4;  // pixels

/// A light grey picture with an anti-aliased dark disc (radius kDiscRadius
/// pixels) at each point: the coverage of each pixel by 8 x 8 sub-samples,
/// so the disc's darkness has its centroid at the point.
Image discs(int w, int h, const std::vector<Vec2>& centres) {
  Image im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double cover = 0;
      for (const Vec2 c : centres) {
        const Vec2 cp = to_pixels(im, c);
        for (int a = 0; a < 8; ++a)
          for (int b = 0; b < 8; ++b) {
            const double dx = x - 0.5 + (a + 0.5) / 8 - cp.x, dy = y - 0.5 + (b + 0.5) / 8 - cp.y;
            cover += (dx * dx + dy * dy <= kDiscRadius * kDiscRadius) / 64.0;
          }
      }
      const std::uint8_t v = std::uint8_t(std::lround(kBackground - (kBackground - kInk) * cover));
      std::uint8_t* p = im.pixel(x, y);
      p[0] = p[1] = p[2] = v;
      p[3] = 255;
    }
  return im;
}

/// A non-trivial f2: features on a 3 x 3 pattern moved by up to 0.03 (seeded).
PlaneDeformation warp(unsigned seed) {
  Random r(seed);
  std::vector<Vec2> from, to;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec2 p{0.25 + 0.25 * i, 0.25 + 0.25 * j};
      from.push_back(p);
      to.push_back(p + Vec2{r.real(-0.03, 0.03), r.real(-0.03, 0.03)});
    }
  return fit_features(identity_plane(8, 8, 3), from, to);
}

// ---- sample -----------------------------------------------------------------

TEST(Morph, SampleAtAPixelCentreIsThatPixel) {
  // morph.h: pixel (px, py) has its centre at ((px + 0.5) / W, 1 - (py + 0.5) / H);
  // bilinear weights there are (1, 0): the pixel's bytes exactly.
  const Image im = waves(100, 70);
  for (const auto& [px, py] : {std::array<int, 2>{0, 0}, {99, 0}, {0, 69}, {37, 51}, {99, 69}}) {
    const std::array<float, 4> c = sample(im, {(px + 0.5) / 100, 1 - (py + 0.5) / 70});
    for (int k = 0; k < 4; ++k) EXPECT_EQ(c[k], float(im.pixel(px, py)[k])) << px << " " << py;
  }
}

TEST(Morph, SampleBetweenPixelsIsBilinear) {
  // Half-way between the centres of pixels (2, 1) and (3, 1): their mean; at
  // the middle of four centres: the mean of the four (exact in float here).
  Image im(4, 4);
  im.pixel(2, 1)[0] = 10, im.pixel(3, 1)[0] = 30, im.pixel(2, 2)[0] = 50, im.pixel(3, 2)[0] = 110;
  EXPECT_EQ(sample(im, {3.0 / 4, 1 - 1.5 / 4})[0], 20.f);
  EXPECT_EQ(sample(im, {3.0 / 4, 1 - 2.0 / 4})[0], 50.f);
  // A quarter of the way from (2, 1) towards (3, 1): 10 + (30 - 10) / 4.
  EXPECT_EQ(sample(im, {2.75 / 4, 1 - 1.5 / 4})[0], 15.f);
}

TEST(Morph, SampleOutsideThePixelCentresIsClampedAtTheBorder) {
  // The corner (0, 1) of the square is the top-left pixel's outer corner:
  // every neighbour clamps to pixel (0, 0). y is up: (0, 0) is the bottom-left.
  const Image im = gradient_checker(8, 6);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(sample(im, {0, 1})[k], float(im.pixel(0, 0)[k]));
    EXPECT_EQ(sample(im, {0, 0})[k], float(im.pixel(0, 5)[k]));
    EXPECT_EQ(sample(im, {1, 0})[k], float(im.pixel(7, 5)[k]));
  }
}

// ---- cross-fade -------------------------------------------------------------

Image flat(int w, int h, std::array<std::uint8_t, 4> c) {
  Image im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) std::copy(c.begin(), c.end(), im.pixel(x, y));
  return im;
}

TEST(Morph, CrossFadeIsTheRoundedBlend) {
  // (1 - t) m1 + t m2 per channel, rounded to the nearest byte (halves up):
  // t = 1/2: (0 + 255)/2 = 127.5 -> 128, (100 + 0)/2 = 50, (200 + 50)/2 =
  // 125, 255; t = 1/4: 63.75 -> 64, 75, 150 + 12.5 = 162.5 -> 163, 255.
  const Image a = flat(3, 2, {0, 100, 200, 255}), b = flat(3, 2, {255, 0, 50, 255});
  const Image half = cross_fade(a, b, 0.5), quarter = cross_fade(a, b, 0.25);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) {
      const std::uint8_t* h = half.pixel(x, y);
      const std::uint8_t* q = quarter.pixel(x, y);
      EXPECT_EQ((std::array<int, 4>{h[0], h[1], h[2], h[3]}),
                (std::array<int, 4>{128, 50, 125, 255}));
      EXPECT_EQ((std::array<int, 4>{q[0], q[1], q[2], q[3]}),
                (std::array<int, 4>{64, 75, 163, 255}));
    }
}

TEST(Morph, CrossFadeAtTheEndsIsTheEndPictures) {
  const Image a = gradient_checker(100, 70), b = waves(100, 70);
  EXPECT_EQ(cross_fade(a, b, 0).rgba, a.rgba);
  EXPECT_EQ(cross_fade(a, b, 1).rgba, b.rgba);
}

TEST(Morph, CrossFadeOfPicturesOfDifferentSizesThrowsNamingThem) {
  EXPECT_EQ(error_of([] { cross_fade(Image(4, 4), Image(5, 4), 0.5); }),
            "cross_fade: the pictures are 4 x 4 and 5 x 4 (must be the same size)");
  EXPECT_EQ(error_of([] { cross_fade(Image(4, 3), Image(4, 4), 0.5); }),
            "cross_fade: the pictures are 4 x 3 and 4 x 4 (must be the same size)");
  EXPECT_EQ(error_of([] { cross_fade(Image(), Image(), 0.5); }),
            "cross_fade: the pictures are 0 x 0 and 0 x 0 (must be the same size)");
}

TEST(Morph, CrossFadeWithTOutsideZeroToOneThrowsNamingT) {
  EXPECT_EQ(error_of([] { cross_fade(Image(2, 2), Image(2, 2), 1.5); }),
            "cross_fade: t = 1.5 outside [0, 1]");
  EXPECT_EQ(error_of([] { cross_fade(Image(2, 2), Image(2, 2), -0.25); }),
            "cross_fade: t = -0.25 outside [0, 1]");
  EXPECT_EQ(error_of([] { cross_fade(Image(2, 2), Image(2, 2), NAN); }),
            "cross_fade: t = nan outside [0, 1]");
}

// ---- the morph at its ends --------------------------------------------------

TEST(Morph, MorphAtTimeZeroIsTheFirstPictureByteForByte) {
  // morph.h: at t = 0 the inverse is x = y exactly and m = m1.
  const PlaneDeformation f2 = warp(401);
  for (const auto& [w, h] : {std::array<int, 2>{64, 64}, {256, 256}, {100, 70}}) {
    const Image a = gradient_checker(w, h), b = waves(w, h);
    EXPECT_EQ(morph(a, b, f2, 0).rgba, a.rgba) << w << " x " << h;
  }
}

TEST(Morph, MorphAtTimeOneIsTheSecondPictureByteForByte) {
  // morph.h: at t = 1, f2(x) = y to 1e-13 and m = m2 (the samples of m2
  // fall within 1e-10 of its pixel centres).
  const PlaneDeformation f2 = warp(402);
  for (const auto& [w, h] : {std::array<int, 2>{64, 64}, {256, 256}, {100, 70}}) {
    const Image a = gradient_checker(w, h), b = waves(w, h);
    EXPECT_EQ(morph(a, b, f2, 1).rgba, b.rgba) << w << " x " << h;
  }
}

TEST(Morph, MorphWithTheIdentityIsTheCrossFade) {
  // f2 = identity: the geometry stays, x = y, and m(t) = (1 - t) m1(y) + t
  // m2(y), the cross-fade (sampled at pixel centres: the pixels themselves).
  const Image a = gradient_checker(100, 70), b = waves(100, 70);
  const PlaneDeformation id = identity_plane(6, 6, 3);
  for (const double t : {0.25, 0.5, 0.8})
    EXPECT_EQ(morph(a, b, id, t).rgba, cross_fade(a, b, t).rgba) << "t " << t;
}

// ---- the morph half-way: features, and the cross-fade's ghosts --------------

/// The centroid of darkness (kBackground - value, red channel) over the
/// pixels within kDiscRadius + 3 of `at` (pixel-index coordinates), and the
/// darkest value there.
struct Blob {
  Vec2 centroid;
  int darkest = 255;
};
Blob blob(const Image& im, Vec2 at) {
  const int reach = int(kDiscRadius) + 3;
  double sum = 0;
  Vec2 moment;
  Blob b;
  for (int y = int(at.y) - reach; y <= int(at.y) + reach + 1; ++y)
    for (int x = int(at.x) - reach; x <= int(at.x) + reach + 1; ++x) {
      if ((x - at.x) * (x - at.x) + (y - at.y) * (y - at.y) > reach * reach) continue;
      const int v = im.pixel(x, y)[0];
      b.darkest = std::min(b.darkest, v);
      const double w = std::max(0, kBackground - v);
      sum += w;
      moment += w * Vec2{double(x), double(y)};
    }
  b.centroid = sum > 0 ? moment / sum : at;
  return b;
}

/// The red byte of the pixel whose centre is nearest `at` (unit square).
int nearest(const Image& im, Vec2 at) {
  const Vec2 p = to_pixels(im, at);
  return im.pixel(int(std::lround(p.x)), int(std::lround(p.y)))[0];
}

TEST(Morph, HalfWayTheFeaturesLieWhereTheHalfWayMapPutsThem) {
  // m1 has a dark disc at each from[k], m2 at each to[k], f2(from[k]) =
  // to[k] (fit_features). At t = 1/2 the geometry is f(1/2, x) = (x + f2(x))
  // / 2, so both pictures' discs land on f(1/2, from[k]) = (from[k] + to[k])
  // / 2 and the morph shows one full-dark disc there. The cross-fade shows
  // two half-dark discs instead, at from[k] and at to[k] (ghosting), and
  // nothing half-way. 256 x 256; 6 features moved 0.06 (15 px) each, so the
  // ghosts (radius 4 px) are apart.
  const int n = 256;
  std::vector<Vec2> from, to;
  for (int k = 0; k < 6; ++k) {
    const double angle = 1.1 * k;
    const Vec2 p{0.22 + 0.28 * (k % 3), 0.3 + 0.4 * (k / 3)};
    from.push_back(p);
    to.push_back(p + 0.06 * Vec2{std::cos(angle), std::sin(angle)});
  }
  const PlaneDeformation f2 = fit_features(identity_plane(10, 10, 3), from, to);
  ASSERT_FALSE(find_plane_fold(f2).folds);
  const Image m1 = discs(n, n, from), m2 = discs(n, n, to);
  const Image m = morph(m1, m2, f2, 0.5), fade = cross_fade(m1, m2, 0.5);
  // Full dark: both discs' ink (20) where they overlap entirely; half dark:
  // (20 + 220) / 2 = 120 at a ghost's centre. Bytes and anti-aliasing: +-10.
  constexpr int kLevels = 10;
  for (std::size_t k = 0; k < from.size(); ++k) {
    const Vec2 half = to_pixels(m, 0.5 * (from[k] + to[k]));
    const Blob b = blob(m, half);
    record("centroid px " + std::to_string(k), norm(b.centroid - half));
    EXPECT_LE(b.darkest, kInk + kLevels) << "feature " << k;
    EXPECT_LE(norm(b.centroid - half), kCentroidPixels)
        << "feature " << k << ": centroid (" << b.centroid.x << ", " << b.centroid.y
        << ") expected (" << half.x << ", " << half.y << ")";
    // The morph has nothing left at from[k] or to[k] (7.7 px from the
    // disc's centre, radius 4): the pixel nearest each is background.
    EXPECT_GE(nearest(m, from[k]), kBackground - kLevels) << "feature " << k;
    EXPECT_GE(nearest(m, to[k]), kBackground - kLevels) << "feature " << k;
    // The cross-fade: two ghosts, each half dark, centred on from[k] and to[k].
    for (const Vec2 ghost : {from[k], to[k]}) {
      const Vec2 at = to_pixels(fade, ghost);
      const Blob g = blob(fade, at);
      EXPECT_NEAR(g.darkest, (kInk + kBackground) / 2, kLevels) << "feature " << k;
      EXPECT_LE(norm(g.centroid - at), kCentroidPixels) << "feature " << k;
    }
    EXPECT_GE(nearest(fade, 0.5 * (from[k] + to[k])), kBackground - kLevels) << "feature " << k;
  }
}

// ---- the morph: bad input ---------------------------------------------------

TEST(Morph, MorphOfPicturesOfDifferentSizesOrTOutsideThrowsNamingThem) {
  const PlaneDeformation id = identity_plane(4, 4, 3);
  EXPECT_EQ(error_of([&] { morph(Image(4, 4), Image(4, 5), id, 0.5); }),
            "morph: the pictures are 4 x 4 and 4 x 5 (must be the same size)");
  EXPECT_EQ(error_of([&] { morph(Image(4, 4), Image(4, 4), id, 2); }),
            "morph: t = 2 outside [0, 1]");
  EXPECT_EQ(error_of([&] { morph(Image(4, 4), Image(4, 4), id, NAN); }),
            "morph: t = nan outside [0, 1]");
}

TEST(Morph, MorphOfAFoldedDeformationThrowsNamingTheFold) {
  // morph.h: throws when f2 folds, with plane_fold_text.
  PlaneDeformation f2 = identity_plane(7, 7, 2);
  f2.point(3, 3).x = 0.85;  // dragged past its neighbour at 0.7
  const PlaneFold fold = find_plane_fold(f2);
  ASSERT_TRUE(fold.folds);
  EXPECT_EQ(error_of([&] { morph(waves(32, 32), waves(32, 32), f2, 0.5); }),
            "morph: " + plane_fold_text(fold) +
                " (the backward warp needs a map without folds)");
}

TEST(Morph, MorphWhoseInverseDoesNotConvergeThrowsNamingThePixel) {
  // morph.h: "a pixel's inverse does not converge (naming the pixel)". f2 =
  // 1/4 + x/2 (the border moved in; no fold, det J = 1/4) has no preimage in
  // the square for the pixels near the border: the first one, (0, 0), fails.
  PlaneDeformation shrink = identity_plane(2, 2, 1);
  for (Vec2& c : shrink.P) c = Vec2{0.25, 0.25} + 0.5 * c;
  EXPECT_EQ(error_of([&] { morph(waves(16, 16), waves(16, 16), shrink, 1); }),
            "morph: pixel (0, 0): f(t, x) = y did not converge at t = 1");
}

}  // namespace
}  // namespace gllab::deform
