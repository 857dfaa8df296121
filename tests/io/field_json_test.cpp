// tests/io/field_json_test.cpp — blob scene files (common/io/field_json.cpp):
// the examples round-trip, defaults, and every bad input is one line naming
// its JSON path.
#include "io/field_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/spline_json.h"
#include "io_test_support.h"

namespace gllab::io {
namespace {

using field::Density;
using testing::kExamplesDir;
using testing::ScratchDir;

void expect_same(const BlobScene& a, const BlobScene& b) {
  EXPECT_EQ(a.field.density, b.field.density);
  EXPECT_EQ(a.iso, b.iso);
  ASSERT_EQ(a.field.blobs.size(), b.field.blobs.size());
  for (std::size_t i = 0; i < a.field.blobs.size(); ++i) {
    const field::Blob &p = a.field.blobs[i], &q = b.field.blobs[i];
    EXPECT_EQ(p.centre.x, q.centre.x) << i;
    EXPECT_EQ(p.centre.y, q.centre.y) << i;
    EXPECT_EQ(p.centre.z, q.centre.z) << i;
    EXPECT_EQ(p.a, q.a) << i;
    EXPECT_EQ(p.b, q.b) << i;
  }
  ASSERT_EQ(a.bounds.has_value(), b.bounds.has_value());
  if (a.bounds) {
    EXPECT_EQ(a.bounds->lo.x, b.bounds->lo.x);
    EXPECT_EQ(a.bounds->hi.z, b.bounds->hi.z);
  }
}

TEST(BlobScene, ExamplesRoundTrip) {
  for (const char* name : {"two_blobs.json", "molecule.json"}) {
    SCOPED_TRACE(name);
    const BlobScene s = read_blob_scene(kExamplesDir / name);
    const std::string text = to_text(to_json(s));
    const BlobScene again = parse_blob_scene(text, name);
    expect_same(s, again);
    EXPECT_EQ(to_text(to_json(again)), text);
  }
}

TEST(BlobScene, ExamplesHoldWhatTheReadmeSays) {
  const BlobScene two = read_blob_scene(kExamplesDir / "two_blobs.json");
  EXPECT_EQ(two.field.density, Density::kHermite);
  EXPECT_EQ(two.iso, 0.5);
  ASSERT_EQ(two.field.blobs.size(), 2u);
  // Just merged: the field at the midpoint, 2 H0(0.65) = 2 (1 - 3 0.65^2 +
  // 2 0.65^3) = 0.5635, is above the iso-value 0.5 (apart they would merge
  // at a distance of 1.348: H0(s) = 0.25 at s = 0.674).
  const double s = 0.65, h0 = 1 - 3 * s * s + 2 * s * s * s;
  EXPECT_NEAR(2 * h0, 0.5635, 1e-12);
  EXPECT_GT(2 * h0, two.iso);
  EXPECT_FALSE(two.bounds);

  const BlobScene molecule = read_blob_scene(kExamplesDir / "molecule.json");
  EXPECT_EQ(molecule.field.density, Density::kWyvill);
  EXPECT_EQ(molecule.field.blobs.size(), 5u);
  ASSERT_TRUE(molecule.bounds);
  EXPECT_EQ(molecule.bounds->lo.x, -1.3);
}

TEST(BlobScene, DefaultsAndDefaultBounds) {
  const BlobScene s = parse_blob_scene(
      R"({"type": "blob_scene", "blobs": [{"centre": [-0.65, 0, 0]}, {"centre": [0.65, 0, 0], "b": 2}]})");
  EXPECT_EQ(s.field.density, Density::kHermite);
  EXPECT_EQ(s.iso, 0.5);
  EXPECT_EQ(s.field.blobs[0].a, 1.0);
  EXPECT_EQ(s.field.blobs[0].b, 1.0);
  EXPECT_EQ(s.field.blobs[1].b, 2.0);
  // The blobs' boxes: x from -1.65 to 2.65, y and z from -2 to 2; grown by
  // 5% of the size on every side.
  const Box box = bounds_of(s);
  EXPECT_NEAR(box.lo.x, -1.65 - 0.05 * 4.3, 1e-12);
  EXPECT_NEAR(box.hi.x, 2.65 + 0.05 * 4.3, 1e-12);
  EXPECT_NEAR(box.lo.y, -2.2, 1e-12);
  EXPECT_NEAR(box.hi.z, 2.2, 1e-12);
  // Written back with every key, and without the bounds it did not have.
  const Json j = to_json(s);
  EXPECT_EQ(j["density"], "hermite");
  EXPECT_EQ(j["blobs"][0]["a"], 1.0);
  EXPECT_FALSE(j.contains("bounds"));
}

TEST(BlobScene, WriteThenReadFile) {
  ScratchDir dir("blobs");
  BlobScene s;
  s.field.density = Density::kBlinn;
  s.iso = 0.1;
  s.field.blobs = {{{0.1, 1.0 / 3, -2}, 0.7, 1.5}};
  s.bounds = Box{{-3, -3, -4}, {3, 3.5, 0}};
  write_blob_scene(dir / "s.json", s);
  expect_same(read_blob_scene(dir / "s.json"), s);
}

struct BadScene {
  std::string name, text, expected;  // expected: "<json path>: <problem...>"
};
void PrintTo(const BadScene& b, std::ostream* out) { *out << b.name; }

const std::string kBlob = R"({"centre": [0, 0, 0], "a": 1, "b": 1})";
std::string scene(const std::string& extra, const std::string& blobs = "[" + kBlob + "]") {
  return R"({"type": "blob_scene", "blobs": )" + blobs + extra + "}";
}

std::vector<BadScene> bad_scenes() {
  return {
      {"unknown_key", scene(R"(, "radius": 2)"),
       "radius: unknown key in a blob_scene (known keys: type, density, iso, blobs, bounds)"},
      {"unknown_blob_key", scene("", "[" + kBlob + R"(, {"centre": [1, 0, 0], "r": 1}])"),
       "blobs[1].r: unknown key in a blob"},
      {"duplicate_key", scene(R"(, "iso": 0.5, "iso": 0.6)"),
       "iso: key appears twice in one object"},
      {"duplicate_blob_key", scene("", R"([{"centre": [0, 0, 0], "b": 1, "b": 2}])"),
       "blobs[0].b: key appears twice"},
      {"type_missing", R"({"blobs": []})", "type: missing"},
      {"type_wrong", R"({"type": "bspline_curve", "blobs": []})",
       R"(type: "bspline_curve" (this file holds a "blob_scene"))"},
      {"not_an_object", "[1, 2]", "expected a JSON object"},
      {"density_unknown", scene(R"(, "density": "metaball")"),
       R"(density: "metaball" (one of "hermite", "wyvill" or "blinn"))"},
      {"density_number", scene(R"(, "density": 3)"), "density: expected a string, got 3"},
      {"iso_string", scene(R"(, "iso": "abc")"), R"(iso: expected a number, got "abc")"},
      {"iso_null", scene(R"(, "iso": null)"), "iso: expected a number, got null"},
      {"iso_overflow", scene(R"(, "iso": 1e999)"),
       "iso: 1e999 overflows to inf (numbers must be finite)"},
      {"iso_zero", scene(R"(, "iso": 0)"), "iso: 0 (must be > 0"},
      {"blobs_missing", R"({"type": "blob_scene"})", "blobs: missing"},
      {"blobs_empty", scene("", "[]"), "blobs: empty (a blob_scene needs at least one blob)"},
      {"blobs_object", scene("", kBlob), "blobs: expected an array of blobs, got an object"},
      {"blob_not_object", scene("", "[[0, 0, 0]]"), "blobs[0]: expected a blob"},
      {"centre_missing", scene("", R"([{"a": 1}])"), "blobs[0].centre: missing"},
      {"centre_two_coordinates", scene("", R"([{"centre": [0, 0]}])"),
       "blobs[0].centre: has 2 coordinates (expected [x, y, z])"},
      {"centre_string", scene("", "[" + kBlob + R"(, {"centre": [0, "x", 0]}])"),
       R"(blobs[1].centre[1]: expected a number, got "x")"},
      {"centre_overflow", scene("", R"([{"centre": [0, 0, -1e400]}])"),
       "blobs[0].centre[2]: -1e400 overflows to -inf"},
      {"a_zero", scene("", R"([{"centre": [0, 0, 0], "a": 0}])"),
       "blobs[0].a: 0 (must be > 0: the density at the centre)"},
      {"b_negative", scene("", "[" + kBlob + R"(, {"centre": [0, 0, 0], "b": -1}])"),
       "blobs[1].b: -1 (must be > 0: the radius of the blob)"},
      {"b_bool", scene("", R"([{"centre": [0, 0, 0], "b": true}])"),
       "blobs[0].b: expected a number, got true"},
      {"bounds_reversed", scene(R"(, "bounds": [[0, 0, 0], [1, -1, 1]])"),
       "bounds[1][1]: -1 <= bounds[0][1] = 0 (the upper corner must be above the lower one)"},
      {"bounds_three", scene(R"(, "bounds": [[0, 0, 0], [1, 1, 1], [2, 2, 2]])"),
       "bounds: has 3 entries"},
      {"bounds_point", scene(R"(, "bounds": [[0, 0, 0], [1, 1]])"), "bounds[1]: has 2 coordinates"},
      {"syntax", R"({"type": "blob_scene", "blobs": [})", "JSON syntax error at line 1"},
      {"empty", "  \n", "empty file"},
  };
}

class BadBlobScene : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadBlobScene, OneLineWithTheJsonPath) {
  const BadScene& b = GetParam();
  try {
    parse_blob_scene(b.text, "scene.json");
    FAIL() << "accepted: " << b.text;
  } catch (const FileError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("scene.json: " + b.expected, 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(Json, BadBlobScene, ::testing::ValuesIn(bad_scenes()),
                         [](const auto& info) { return info.param.name; });

TEST(BlobScene, MissingFileNamesIt) {
  try {
    read_blob_scene("/no/such/scene.json");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("/no/such/scene.json: cannot open", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace gllab::io
