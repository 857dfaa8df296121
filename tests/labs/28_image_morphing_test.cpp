// tests/labs/28_image_morphing_test.cpp — what lab 28 promises (lecture notes
// ch. 1, §1.7 Surface representations, "Morphing": m(t) with m(0) = m1 and
// m(1) = m2; f(t, x) = (1 - t) x + t f2(x)):
//  - at t = 0 both pictures of cross_fade_vs_morph are face A, at t = 1 face B,
//    as common/deform/faces.h draws them (the shipped PNGs are those pictures:
//    tests/deform/faces_test.cpp);
//  - at t = 1/2 the morph's pupils lie at f(1/2, p) = (p + q) / 2, p and q the
//    eye features of A and B (f2(p) = q: the deformation view's miss is 0);
//    the cross-fade has no dark pupil there (ghosting: two grey half-pupils);
//  - the lab's feature arrays are the pictures' features;
//  - the fold view reports the core's fold with det J < 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "deform/faces.h"
#include "lab_test_support.h"

namespace {

using gllab::Image;
using gllab::deform::Face;
using gllab::testing::numbers_after;
using gllab::testing::render_view;
using gllab::testing::ScratchDir;
using gllab::testing::view_text;

const std::string kLab = "28_image_morphing";
constexpr int kSize = 512, kPicture = 256;  // the default window; the pictures' size
// cross_fade_vs_morph draws each 256-pixel picture pixel for texel in a 256 x 512 panel:
// columns 0..255 (cross-fade) and 256..511 (morph), rows 128..383 (the unit square centred).
constexpr int kTop = (kSize - kPicture) / 2;

// Pixels of panel `col` of the view that differ from the face picture, and by how much at most.
struct Difference {
  long long pixels = 0;
  int largest = 0;
};
Difference against_face(const Image& view, int col, Face face) {
  const Image picture = gllab::deform::face_picture(face, kPicture);
  Difference d;
  for (int y = 0; y < kPicture; ++y)
    for (int x = 0; x < kPicture; ++x) {
      const std::uint8_t *a = view.pixel(col * kPicture + x, kTop + y), *b = picture.pixel(x, y);
      int worst = 0;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a[c]) - int(b[c])));
      d.pixels += worst > 0;
      d.largest = std::max(d.largest, worst);
    }
  return d;
}

TEST(ImageMorphingLab, AtTZeroBothPanelsAreFaceAAndAtTOneFaceB) {
  ScratchDir dir("lab28");
  for (const auto& [t, face] : {std::pair{"t=0", Face::kA}, std::pair{"t=1", Face::kB}}) {
    const Image view = render_view(kLab, dir, "cross_fade_vs_morph", {t, "grid_lines=0"});
    for (int col = 0; col < 2; ++col) {
      const Difference d = against_face(view, col, face);
      // Byte for byte: every fragment samples its texel's centre (t = 0: the mesh is the
      // square; t = 1: vertex and texture coordinate are both f2(x), so they interpolate alike).
      EXPECT_EQ(d.pixels, 0) << t << " panel " << col << ": largest difference " << d.largest;
    }
  }
}

// The centroid (window pixels) of the dark pixels (pupils: every channel <= 40 in the
// pictures, faces.h) within `radius` of (x, y), and how many there are.
struct Blob {
  double x = 0, y = 0;
  int count = 0;
};
Blob dark_blob(const Image& im, double x, double y, int radius) {
  Blob b;
  for (int py = int(y) - radius; py <= int(y) + radius; ++py)
    for (int px = int(x) - radius; px <= int(x) + radius; ++px) {
      const std::uint8_t* p = im.pixel(px, py);
      if (p[0] > 64 || p[1] > 64 || p[2] > 64) continue;
      b.x += px + 0.5, b.y += py + 0.5, ++b.count;
    }
  if (b.count) b.x /= b.count, b.y /= b.count;
  return b;
}

TEST(ImageMorphingLab, HalfwayTheMorphsPupilsAreWhereTheDeformationPutsThem) {
  ScratchDir dir("lab28");
  const Image view = render_view(kLab, dir, "cross_fade_vs_morph", {"t=0.5", "grid_lines=0"});
  const auto& a = gllab::deform::face_features(Face::kA);
  const auto& b = gllab::deform::face_features(Face::kB);
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k].name != "left_eye" && a[k].name != "right_eye") continue;
    // f(1/2, p) = (p + q) / 2 in the unit square, y up; in the morph panel's pixels:
    const double ux = (a[k].at.x + b[k].at.x) / 2, uy = (a[k].at.y + b[k].at.y) / 2;
    const double x = kPicture + ux * kPicture, y = kTop + (1 - uy) * kPicture;
    const Blob morph = dark_blob(view, x, y, 12);
    // A pupil is a disc of radius 5 (A) or 4.5 (B) texels: about 70 dark pixels when both
    // land on each other. Its centre within half a pixel: the mesh is linear over cells of
    // 8 pixels, where f bends by far less than a pixel (the miss of f2 itself is 0).
    EXPECT_GT(morph.count, 40) << a[k].name;
    EXPECT_NEAR(morph.x, x, 0.5) << a[k].name;
    EXPECT_NEAR(morph.y, y, 0.5) << a[k].name;
    // The cross-fade at the same place: a pupil over the other face's eye white or skin is
    // grey (about 113 per channel, faces.h's colours), never dark.
    EXPECT_EQ(dark_blob(view, x - kPicture, y, 12).count, 0) << a[k].name;
  }
}

TEST(ImageMorphingLab, DeformationCarriesEveryFeatureOntoFaceB) {
  ScratchDir dir("lab28");
  const std::vector<double> miss = numbers_after(view_text(kLab, dir, "deformation"),
                                                 "max |f2(p_k) - q_k| = ");
  ASSERT_EQ(miss.size(), 1u);
  EXPECT_EQ(miss[0], 0.0);  // fit_features meets every feature to 1e-9 (deform/plane.h)
}

// The numbers in the braces after `name` in the lab's source, in order.
std::vector<double> array_in_source(const std::string& name) {
  std::ifstream in(gllab::testing::kSourceDir / "labs" / kLab / (kLab + ".cpp"));
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::size_t start = s.find(name + "[] = {"), end = s.find("};", start);
  EXPECT_NE(start, std::string::npos) << name;
  std::vector<double> v;
  std::string body = s.substr(start + name.size() + 6, end - start - name.size() - 6);
  for (char& c : body)
    if (c == '{' || c == '}' || c == ',') c = ' ';
  std::stringstream numbers(body);
  for (double x; numbers >> x;) v.push_back(x);
  return v;
}

TEST(ImageMorphingLab, FeatureArraysAreThePicturesFeatures) {
  for (const auto& [name, face] : {std::pair{"kFeaturesA", Face::kA}, {"kFeaturesB", Face::kB}}) {
    const std::vector<double> v = array_in_source(name);
    const auto& features = gllab::deform::face_features(face);
    ASSERT_EQ(v.size(), 2 * features.size()) << name;
    for (std::size_t k = 0; k < features.size(); ++k) {
      EXPECT_EQ(v[2 * k], features[k].at.x) << name << " " << features[k].name;
      EXPECT_EQ(v[2 * k + 1], features[k].at.y) << name << " " << features[k].name;
    }
  }
}

TEST(ImageMorphingLab, FoldViewShowsTheCoresFold) {
  ScratchDir dir("lab28");
  const std::vector<double> det = numbers_after(view_text(kLab, dir, "fold"),
                                                "the grid folds: det J = ");
  ASSERT_EQ(det.size(), 1u);
  EXPECT_LT(det[0], 0);
  // The default grid does not fold: no other view shows the warning.
  for (const char* view : {"deformation", "morph", "cross_fade_vs_morph", "sequence"})
    EXPECT_TRUE(numbers_after(view_text(kLab, dir, view), "the grid folds: det J = ").empty())
        << view;
}

}  // namespace
