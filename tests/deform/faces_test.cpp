// tests/deform/faces_test.cpp — the two cartoon faces of the morphing lab
// (common/deform/faces.h) and the shipped pictures examples/face_a.png and
// examples/face_b.png (tools/make_faces.cpp): the files are what the core
// draws, the feature points are where the pictures say they are, and the
// faces differ enough for a cross-fade to show ghosting.
#include "deform/faces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/image.h"

namespace gllab::deform {
namespace {

using spline::Vec2;

const std::filesystem::path kExamples = std::filesystem::path(GLLAB_SOURCE_DIR) / "examples";
constexpr int kSize = 256;  // the shipped pictures are make_faces 256
constexpr double kPx = 1.0 / kSize;
const char* const kRemake = "build/bin/make_faces 256 examples/face_a.png examples/face_b.png";

struct Shipped {
  Face face;
  const char* file;
};
const Shipped kShipped[] = {{Face::kA, "face_a.png"}, {Face::kB, "face_b.png"}};
const Face kFaces[] = {Face::kA, Face::kB};

Face other(Face f) { return f == Face::kA ? Face::kB : Face::kA; }

/// The pixel that contains p (faces.h: (floor(x N), floor((1 - y) N))).
Rgb8 colour_at(const Image& image, Vec2 p) {
  const int px = static_cast<int>(std::floor(p.x * image.width));
  const int py = static_cast<int>(std::floor((1 - p.y) * image.height));
  if (px < 0 || py < 0 || px >= image.width || py >= image.height)
    throw std::out_of_range("colour_at: outside the picture");
  const std::uint8_t* c = image.pixel(px, py);
  return {c[0], c[1], c[2]};
}

std::string text(Rgb8 c) {
  return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

/// The pupils' threshold (faces.h): the pupil has every channel <= 40, every
/// other colour some channel >= 90; between them a pupil blends with its iris.
bool dark(Rgb8 c) { return c.r < 64 && c.g < 64 && c.b < 64; }

const Feature& feature(Face face, const std::string& name) {
  for (const Feature& f : face_features(face))
    if (f.name == name) return f;
  throw std::invalid_argument("no feature " + name);
}

TEST(ShippedFaces, AreWhatFacePictureDraws) {
  for (const Shipped& s : kShipped) {
    SCOPED_TRACE(s.file);
    const Image shipped = read_png((kExamples / s.file).string());
    const Image drawn = face_picture(s.face, kSize);
    ASSERT_EQ(shipped.width, kSize);
    ASSERT_EQ(shipped.height, kSize);
    int differ = 0;
    for (std::size_t i = 0; i < drawn.rgba.size(); i += 4)
      for (std::size_t c = 0; c < 4; ++c)
        if (drawn.rgba[i + c] != shipped.rgba[i + c]) {
          ++differ;
          break;
        }
    EXPECT_EQ(differ, 0) << "pixels differ: examples/" << s.file << " is stale: " << kRemake;
  }
}

TEST(FaceFeatures, SameNamesInTheSameOrder) {
  // The list of faces.h, top to bottom.
  const std::vector<std::string> expected = {
      "top_of_head", "left_brow", "right_brow", "left_eye",   "right_eye",    "face_left",
      "face_right",  "nose_tip",  "mouth_left", "mouth_right", "mouth_centre", "chin"};
  for (Face face : kFaces) {
    std::vector<std::string> names;
    for (const Feature& f : face_features(face)) names.push_back(f.name);
    EXPECT_EQ(names, expected) << "face " << face_letter(face);
  }
  ASSERT_EQ(face_features(Face::kA).size(), face_features(Face::kB).size());
  for (std::size_t i = 0; i < face_features(Face::kA).size(); ++i)
    EXPECT_EQ(face_features(Face::kA)[i].name, face_features(Face::kB)[i].name) << "index " << i;
}

TEST(FaceFeatures, StayATenthAwayFromTheBorder) {
  // faces.h: the plane deformation keeps the border fixed (deform/plane.h).
  for (Face face : kFaces)
    for (const Feature& f : face_features(face)) {
      EXPECT_GE(std::min(f.at.x, f.at.y), 0.1) << face_letter(face) << " " << f.name;
      EXPECT_LE(std::max(f.at.x, f.at.y), 0.9) << face_letter(face) << " " << f.name;
    }
}

TEST(FaceFeatures, SymmetricPairsMirrorAboutTheMiddle) {
  // Both faces are drawn symmetric about x = 1/2 (faces.cpp paint_pair).
  const char* const pairs[][2] = {
      {"left_brow", "right_brow"}, {"left_eye", "right_eye"}, {"face_left", "face_right"},
      {"mouth_left", "mouth_right"}};
  for (Face face : kFaces)
    for (const auto& p : pairs) {
      const Vec2 l = feature(face, p[0]).at, r = feature(face, p[1]).at;
      EXPECT_EQ(l.x + r.x, 1.0) << face_letter(face) << " " << p[0];
      EXPECT_EQ(l.y, r.y) << face_letter(face) << " " << p[0];
      EXPECT_LT(l.x, r.x) << face_letter(face) << " " << p[0] << ": left is the smaller x";
    }
}

TEST(FacePicture, FeaturePointsHaveThePromisedColours) {
  // faces.h lists what each point's pixel is; 2 px at size 256 is 2/256.
  for (Face face : kFaces) {
    const Image image = face_picture(face, kSize);
    const FaceColours& k = face_colours(face);
    for (const Feature& f : face_features(face)) {
      SCOPED_TRACE(std::string("face ") + face_letter(face) + " " + f.name);
      const Vec2 p = f.at;
      const auto at = [&](double dx, double dy) {
        return text(colour_at(image, p + Vec2{dx, dy}));
      };
      const std::string& n = f.name;
      if (n == "left_eye" || n == "right_eye") {
        EXPECT_EQ(at(0, 0), text(k.pupil));
      } else if (n == "left_brow" || n == "right_brow") {
        EXPECT_EQ(at(0, 0), text(k.brow));
      } else if (n == "nose_tip") {
        EXPECT_EQ(at(0, 0), text(k.nose));
      } else if (n == "mouth_left" || n == "mouth_right" || n == "mouth_centre") {
        EXPECT_EQ(at(0, 0), text(k.mouth));
      } else if (n == "top_of_head") {
        EXPECT_EQ(at(0, -2 * kPx), text(k.hair));
        EXPECT_EQ(at(0, 2 * kPx), text(k.background));
      } else if (n == "face_left" || n == "face_right") {
        const double inward = n == "face_left" ? 2 * kPx : -2 * kPx;
        EXPECT_EQ(at(inward, 0), text(k.skin));
        EXPECT_EQ(at(-inward, 0), text(k.hair));
      } else if (n == "chin") {
        EXPECT_EQ(at(0, 2 * kPx), text(k.skin));
        EXPECT_EQ(at(0, -2 * kPx), text(k.neck));
      } else {
        ADD_FAILURE() << "a feature faces.h does not promise a colour for";
      }
    }
  }
}

TEST(FacePicture, OnlyThePupilsAreDarkAndTheyAreCentredOnTheEyes) {
  // faces.h: only the pupils are dark. A dark pixel lies within the pupil's
  // radius plus a pixel's diagonal of an eye point, and the dark pixels
  // around an eye are centred on it: the disc is centred on the point and
  // the 4 x 4 samples are symmetric, so the centroid is exact up to the sum's
  // rounding (1e-9 px allows for it).
  for (Face face : kFaces) {
    SCOPED_TRACE(face_letter(face));
    const Image image = face_picture(face, kSize);
    const Vec2 eyes[2] = {feature(face, "left_eye").at, feature(face, "right_eye").at};
    const double reach = pupil_radius(face) + std::sqrt(2.0) * kPx;
    Vec2 sum[2];
    int count[2] = {0, 0}, stray = 0;
    for (int py = 0; py < kSize; ++py)
      for (int px = 0; px < kSize; ++px) {
        const Vec2 centre{(px + 0.5) * kPx, 1 - (py + 0.5) * kPx};
        if (!dark(colour_at(image, centre))) continue;
        const int e = norm(centre - eyes[0]) <= norm(centre - eyes[1]) ? 0 : 1;
        if (norm(centre - eyes[e]) > reach) {
          ++stray;
          continue;
        }
        sum[e] += centre;
        ++count[e];
      }
    EXPECT_EQ(stray, 0) << "dark pixels away from the pupils";
    for (int e = 0; e < 2; ++e) {
      ASSERT_GT(count[e], 0);
      const Vec2 c = sum[e] / count[e];
      EXPECT_NEAR(c.x, eyes[e].x, 1e-9 * kPx) << "eye " << e;
      EXPECT_NEAR(c.y, eyes[e].y, 1e-9 * kPx) << "eye " << e;
    }
  }
}

TEST(FaceColours, OnlyThePupilIsDark) {
  // faces.h: the pupil has every channel <= 40, every other colour a channel >= 90.
  for (Face face : kFaces) {
    const FaceColours& k = face_colours(face);
    const Rgb8 others[] = {k.background, k.hair,  k.skin,  k.ear,    k.cheek,
                          k.brow,       k.eye_white, k.iris, k.nose, k.mouth,
                          k.teeth,      k.tongue, k.neck, k.shirt};
    EXPECT_LE(std::max({k.pupil.r, k.pupil.g, k.pupil.b}), 40) << face_letter(face);
    for (Rgb8 c : others) EXPECT_GE(std::max({c.r, c.g, c.b}), 90) << face_letter(face) << text(c);
  }
}

TEST(Faces, DifferEnoughForACrossFadeToGhost) {
  // The eyes move further than the width of either face's eye white (A 26,
  // B 30 of 256 = 0.117; faces.cpp), so in a cross-fade the two pairs of eyes
  // stand side by side: 0.12. The mouths' centres move 30.5/256 (A 88, B 57.5),
  // more than either mouth is deep (A 20, B 14): 0.1.
  for (const char* name : {"left_eye", "right_eye"})
    EXPECT_GE(norm(feature(Face::kA, name).at - feature(Face::kB, name).at), 0.12) << name;
  EXPECT_GE(norm(feature(Face::kA, "mouth_centre").at - feature(Face::kB, "mouth_centre").at),
            0.1);
  // And what each face has at the other's eyes and mouth is something else:
  // the cross-fade shows each pupil and mouth at half strength over the
  // other face (two pairs of eyes, two mouths).
  for (Face face : kFaces) {
    const Image there = face_picture(other(face), kSize);
    const FaceColours& k = face_colours(other(face));
    for (const char* name : {"left_eye", "right_eye"})
      EXPECT_FALSE(dark(colour_at(there, feature(face, name).at)))
          << face_letter(other(face)) << " at " << face_letter(face) << "'s " << name;
    EXPECT_NE(text(colour_at(there, feature(face, "mouth_centre").at)), text(k.mouth))
        << face_letter(other(face)) << " at " << face_letter(face) << "'s mouth_centre";
  }
}

TEST(FacePicture, RefusesSizesOutside16To4096) {
  for (int size : {15, 0, -3, 4097}) {
    try {
      face_picture(Face::kA, size);
      ADD_FAILURE() << "size " << size << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("size " + std::to_string(size)), std::string::npos)
          << e.what();
    }
  }
  const Image smallest = face_picture(Face::kB, 16);
  EXPECT_EQ(smallest.width, 16);
  EXPECT_EQ(smallest.height, 16);
}

TEST(FacePicture, IsDeterministicAndOpaque) {
  for (Face face : kFaces) {
    const Image first = face_picture(face, kSize), second = face_picture(face, kSize);
    EXPECT_EQ(first.rgba, second.rgba) << face_letter(face);
    for (std::size_t i = 3; i < first.rgba.size(); i += 4) ASSERT_EQ(first.rgba[i], 255);
  }
  // A size that is no power of two draws the same face: the pupils are where
  // the features say (pupil colour at the eye's pixel, size 300).
  const Image odd = face_picture(Face::kA, 300);
  EXPECT_EQ(text(colour_at(odd, feature(Face::kA, "left_eye").at)),
            text(face_colours(Face::kA).pupil));
}

}  // namespace
}  // namespace gllab::deform
