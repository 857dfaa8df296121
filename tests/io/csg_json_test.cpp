// tests/io/csg_json_test.cpp — CSG tree files (common/io/csg_json.cpp): the
// examples read and mean what their names say (the same solids as
// space::csg_catalogue()), files round-trip, the README example reads, and every
// bad input is one line naming its JSON path.
#include "io/csg_json.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/spline_json.h"
#include "io_test_support.h"
#include "space/csg.h"

namespace gllab::io {
namespace {

namespace fs = std::filesystem;
using space::CsgTree;
using space::Where;
using spline::Vec3;
using testing::kExamplesDir;
using testing::ScratchDir;

const fs::path kCsgDir = kExamplesDir / "csg";

/// Random points in the cube [-1.3, 1.3]^3, which holds every example and the catalogue.
std::vector<Vec3> random_points(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(-1.3, 1.3);
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < count; ++i) points.push_back({u(random), u(random), u(random)});
  return points;
}

/// Same classification of many random points (the trees are built by the same
/// arithmetic, so even "on" must agree), and some points inside and outside.
void expect_same_solid(const CsgTree& a, const CsgTree& b, const std::string& what) {
  int inside = 0, outside = 0;
  for (const Vec3& p : random_points(4000, 7)) {
    const Where wa = space::classify(a, p), wb = space::classify(b, p);
    ASSERT_EQ(wa, wb) << what << " at (" << p.x << ", " << p.y << ", " << p.z << ")";
    inside += wa == Where::kInside;
    outside += wa == Where::kOutside;
  }
  EXPECT_GT(inside, 0) << what;
  EXPECT_GT(outside, 0) << what;
}

const CsgTree& catalogue(const std::string& name) {
  for (const space::NamedTree& t : space::csg_catalogue())
    if (t.name == name) return t.tree;
  throw std::runtime_error("no tree named '" + name + "' in space::csg_catalogue()");
}

std::vector<fs::path> example_files() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(kCsgDir))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  return files;
}

// ---- examples ----------------------------------------------------------------------------

TEST(CsgExamples, EveryExampleReadsAndRoundTrips) {
  const std::vector<fs::path> files = example_files();
  EXPECT_GE(files.size(), 4u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const CsgFile csg = read_csg(file);
    EXPECT_GE(csg.tree.root(), 0);
    EXPECT_EQ(csg.node_names.size(), csg.tree.nodes().size());
    // parse -> to_json -> parse: the same solid, and the text is stable.
    const std::string text = to_text(to_json(csg));
    const CsgFile again = parse_csg(text, file.filename().string());
    expect_same_solid(csg.tree, again.tree, file.filename().string());
    EXPECT_EQ(again.node_names, csg.node_names);
    EXPECT_EQ(to_text(to_json(again)), text);
  }
}

TEST(CsgExamples, ClassicIsTheCataloguesClassic) {
  const CsgFile classic = read_csg(kCsgDir / "classic.json");
  // box ∩ sphere − (cyl x ∪ cyl y ∪ cyl z): five primitives in this order.
  ASSERT_EQ(classic.tree.leaves().size(), 5u);
  const char* names[] = {"box", "sphere", "cyl x", "cyl y", "cyl z"};
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(classic.tree.leaves()[i].name, names[i]);
  EXPECT_EQ(classic.tree.leaves()[0].size.x, 1.6);
  EXPECT_EQ(classic.tree.leaves()[1].radius, 1.05);
  EXPECT_EQ(classic.tree.leaves()[2].radius, 0.45);
  EXPECT_EQ(classic.tree.leaves()[2].height, 2.4);
  EXPECT_EQ(classic.node_names[static_cast<std::size_t>(classic.tree.root())], "classic");
  expect_same_solid(classic.tree, catalogue("classic"), "classic");
}

TEST(CsgExamples, StepsActInTheOrderGiven) {
  // tilted_slab.json scales, then rotates: the catalogue's rotate * scale.
  expect_same_solid(read_csg(kCsgDir / "tilted_slab.json").tree, catalogue("transform under ∩"), "tilted slab");
  expect_same_solid(read_csg(kCsgDir / "nested_difference.json").tree, catalogue("nested difference"),
                    "nested difference");
  // translate (1, 0, 0) first, then scale x by 2: the sphere of radius 0.5 becomes
  // an ellipsoid centred at (2, 0, 0) reaching x = 1..3 (the other order: 0..2).
  const CsgFile f = parse_csg(R"({"type": "csg", "root": {"transform": [{"translate": [1, 0, 0]},
      {"scale": [2, 1, 1]}], "child": {"primitive": "sphere", "radius": 0.5}}})");
  EXPECT_EQ(space::classify(f.tree, {2.9, 0, 0}), Where::kInside);
  EXPECT_EQ(space::classify(f.tree, {1.1, 0, 0}), Where::kInside);
  EXPECT_EQ(space::classify(f.tree, {0.9, 0, 0}), Where::kOutside);
  EXPECT_EQ(space::classify(f.tree, {2, 0.45, 0}), Where::kInside);
  EXPECT_EQ(space::classify(f.tree, {2, 0.55, 0}), Where::kOutside);
}

TEST(CsgExamples, DifferenceFoldsFromTheLeft) {
  // a − b − c = (a − b) − c: a box minus two slabs; a − (b − c) would keep the
  // part of the box inside c (x > 0.5 and y > 0.5).
  const CsgFile f = parse_csg(R"({"type": "csg", "root": {"op": "difference", "children": [
      {"primitive": "box", "size": [2, 2, 2]},
      {"transform": [{"translate": [0.75, 0, 0]}], "child": {"primitive": "box", "size": [0.5, 4, 4]}},
      {"transform": [{"translate": [0, 0.75, 0]}], "child": {"primitive": "box", "size": [4, 0.5, 4]}}]}})");
  EXPECT_EQ(space::classify(f.tree, {0, 0, 0}), Where::kInside);
  EXPECT_EQ(space::classify(f.tree, {0.8, 0, 0}), Where::kOutside);
  EXPECT_EQ(space::classify(f.tree, {0, 0.8, 0}), Where::kOutside);
  EXPECT_EQ(space::classify(f.tree, {0.8, 0.8, 0}), Where::kOutside);
  EXPECT_EQ(f.tree.leaves().size(), 3u);
}

TEST(CsgExamples, MatrixStepIsTheSameAsItsSteps) {
  // rotate z by 90° then translate (0.5, 0, 0): x' = (-y + 0.5, x, z).
  const CsgFile steps = parse_csg(R"({"type": "csg", "root": {"transform": [
      {"rotate": {"axis": [0, 0, 1], "degrees": 90}}, {"translate": [0.5, 0, 0]}],
      "child": {"primitive": "box", "size": [1, 0.4, 0.6]}}})");
  const CsgFile matrix = parse_csg(R"({"type": "csg", "root": {"transform": [
      {"matrix": [0, -1, 0, 0.5, 1, 0, 0, 0, 0, 0, 1, 0]}],
      "child": {"primitive": "box", "size": [1, 0.4, 0.6]}}})");
  for (const Vec3& p : random_points(2000, 3)) {
    const Where a = space::classify(steps.tree, p, 1e-9), b = space::classify(matrix.tree, p, 1e-9);
    if (a == Where::kOn || b == Where::kOn) continue;  // round-off of cos 90°
    ASSERT_EQ(a, b) << p.x << " " << p.y << " " << p.z;
  }
  // The box is 0.4 wide in x after the turn, centred on x = 0.5, and 1 long in y.
  EXPECT_EQ(space::classify(matrix.tree, {0.5, 0.45, 0}), Where::kInside);
  EXPECT_EQ(space::classify(matrix.tree, {0.75, 0, 0}), Where::kOutside);
}

TEST(CsgFormat, EveryCatalogueTreeRoundTrips) {
  for (const space::NamedTree& t : space::csg_catalogue()) {
    SCOPED_TRACE(t.name);
    const Json json = to_json(t.tree);
    EXPECT_EQ(json["type"], "csg");
    const CsgFile again = parse_csg(to_text(json), t.name);
    expect_same_solid(t.tree, again.tree, t.name);
    ASSERT_EQ(again.tree.leaves().size(), t.tree.leaves().size());
    for (std::size_t i = 0; i < t.tree.leaves().size(); ++i) EXPECT_EQ(again.tree.leaves()[i].name, t.tree.leaves()[i].name);
  }
}

TEST(CsgFormat, WritesChainsAsOneNodeAndTransformsAsMatrices) {
  const Json j = to_json(read_csg(kCsgDir / "classic.json"));
  const Json& root = j["root"];
  EXPECT_EQ(root["op"], "difference");
  EXPECT_EQ(root["name"], "classic");
  ASSERT_EQ(root["children"].size(), 2u);
  const Json& cylinders = root["children"][1];
  EXPECT_EQ(cylinders["op"], "union");
  ASSERT_EQ(cylinders["children"].size(), 3u);  // (x ∪ y) ∪ z written as [x, y, z]
  const Json& step = cylinders["children"][0]["transform"];
  ASSERT_EQ(step.size(), 1u);
  ASSERT_TRUE(step[0].contains("matrix"));
  EXPECT_EQ(step[0]["matrix"].size(), 12u);
  EXPECT_EQ(cylinders["children"][2]["primitive"], "cylinder");
  EXPECT_EQ(cylinders["children"][2]["height"], 2.4);
}

TEST(CsgFormat, NamesOfOperatorsAndTransformsSurvive) {
  const CsgFile f = parse_csg(R"({"type": "csg", "root": {"op": "union", "name": "pair", "children": [
      {"op": "union", "name": "inner", "children": [{"primitive": "sphere", "radius": 1, "name": "a"},
                                                      {"primitive": "cone", "radius": 1, "height": 2}]},
      {"transform": [{"translate": [1, 2, 3]}], "name": "moved", "child": {"primitive": "box", "size": [1, 2, 3]}}]}})");
  const Json j = to_json(f);
  EXPECT_EQ(j["root"]["name"], "pair");
  ASSERT_EQ(j["root"]["children"].size(), 2u);  // the named inner union keeps its level
  EXPECT_EQ(j["root"]["children"][0]["name"], "inner");
  EXPECT_EQ(j["root"]["children"][0]["children"][0]["name"], "a");
  EXPECT_FALSE(j["root"]["children"][0]["children"][1].contains("name"));
  EXPECT_EQ(j["root"]["children"][1]["name"], "moved");
  // Without node_names only the primitives' names are written.
  const Json bare = to_json(f.tree);
  EXPECT_FALSE(bare["root"].contains("name"));
  EXPECT_EQ(bare["root"]["children"].size(), 3u);  // an unnamed chain is one node
}

TEST(CsgFormat, WriteThenReadFile) {
  ScratchDir dir("csg");
  const CsgFile classic = read_csg(kCsgDir / "classic.json");
  write_csg(dir / "tree.json", classic);
  write_csg(dir / "bare.json", classic.tree);
  expect_same_solid(read_csg(dir / "tree.json").tree, classic.tree, "tree.json");
  expect_same_solid(read_csg(dir / "bare.json").tree, classic.tree, "bare.json");
  EXPECT_EQ(read_csg(dir / "tree.json").node_names, classic.node_names);
  // Atomic: nothing but the two files is left in the directory.
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir.path())) names.insert(e.path().filename().string());
  EXPECT_EQ(names, (std::set<std::string>{"bare.json", "tree.json"}));
  EXPECT_THROW(write_csg(dir / "no_dir" / "x.json", classic.tree), FileError);
}

TEST(CsgFormat, AnEmptyTreeCannotBeWritten) {
  EXPECT_THROW(to_json(CsgTree{}), std::invalid_argument);
}

TEST(CsgFormat, TheReadmeExampleReads) {
  // The README's CSG example is a ```jsonc block (a ```json block is read by
  // spline_json_test as a spline file).
  const std::string readme = testing::read_file(testing::kSourceDir / "common" / "io" / "README.md");
  int blocks = 0;
  for (std::size_t start = readme.find("```jsonc\n"); start != std::string::npos;
       start = readme.find("```jsonc\n", start + 1)) {
    const std::size_t begin = start + 9, end = readme.find("```", begin);
    const std::string block = readme.substr(begin, end - begin);
    if (block.find(R"("type": "csg")") == std::string::npos) continue;
    SCOPED_TRACE(block);
    const CsgFile f = parse_csg(block, "README.md");
    // The README's example is examples/csg/classic.json.
    expect_same_solid(f.tree, read_csg(kCsgDir / "classic.json").tree, "README");
    ++blocks;
  }
  EXPECT_GE(blocks, 1);
}

// ---- bad input -----------------------------------------------------------------------------

struct BadTree {
  std::string name, text, expected;  // expected: "<json path>: <problem...>"
};
void PrintTo(const BadTree& b, std::ostream* out) { *out << b.name; }

const std::string kSphere = R"({"primitive": "sphere", "radius": 1})";
std::string tree(const std::string& root) { return R"({"type": "csg", "root": )" + root + "}"; }
std::string unite(const std::string& a, const std::string& b) {
  return R"({"op": "union", "children": [)" + a + ", " + b + "]}";
}
std::string moved(const std::string& steps, const std::string& child = kSphere) {
  return R"({"transform": [)" + steps + R"(], "child": )" + child + "}";
}

std::vector<BadTree> bad_trees() {
  return {
      // The messages of the README.
      {"sphere_radius_negative", tree(unite(kSphere, R"({"primitive": "sphere", "radius": -1})")),
       "root.children[1].radius: -1 (must be > 0: the sphere's radius)"},
      {"op_unknown", tree(R"({"op": "xor", "children": [)" + kSphere + ", " + kSphere + "]}"),
       R"(root.op: "xor" (known operators: union, intersection, difference))"},
      {"scale_zero",
       tree(unite(moved(R"({"translate": [1, 0, 0]}, {"rotate": {"axis": [0, 0, 1], "degrees": 5}}, {"scale": [1, 0, 1]})"),
                  kSphere)),
       "root.children[0].transform[2].scale[1]: 0 (a scale must not be zero: it flattens the solid)"},
      {"rotate_zero_axis", tree(moved(R"({"rotate": {"axis": [0, 0, 0], "degrees": 30}})")),
       "root.transform[0].rotate.axis: [0, 0, 0] (a rotation needs a non-zero axis)"},
      {"radius_overflow", tree(R"({"primitive": "sphere", "radius": 1e999})"),
       "root.radius: 1e999 overflows to inf (numbers must be finite)"},
      {"translate_overflow", tree(moved(R"({"translate": [0, -1e400, 0]})")),
       "root.transform[0].translate[1]: -1e400 overflows to -inf (numbers must be finite)"},
      {"height_missing", tree(R"({"primitive": "cylinder", "radius": 1})"),
       "root.height: missing (a cylinder needs it)"},
      {"radius_string", tree(R"({"primitive": "cone", "radius": "big", "height": 1})"),
       R"(root.radius: expected a number, got "big")"},
      {"one_child", tree(R"({"op": "union", "children": [)" + kSphere + "]}"),
       "root.children: 1 child (a union needs at least 2)"},
      {"no_children", tree(R"({"op": "intersection", "children": []})"),
       "root.children: 0 children (an intersection needs at least 2)"},
      {"children_object", tree(R"({"op": "difference", "children": )" + kSphere + "}"),
       "root.children: expected an array of nodes, got an object"},
      {"children_missing", tree(R"({"op": "difference"})"), "root.children: missing"},
      // Keys and kinds.
      {"unknown_key", tree(R"({"primitive": "box", "size": [1, 1, 1], "radius": 2})"),
       "root.radius: unknown key in a box (known keys: primitive, size, name)"},
      {"unknown_top_key", R"({"type": "csg", "root": )" + kSphere + R"(, "bounds": []})",
       "bounds: unknown key in a csg file (known keys: type, root)"},
      {"duplicate_key", tree(R"({"primitive": "sphere", "radius": 1, "radius": 2})"),
       "root.radius: key appears twice"},
      {"type_wrong", R"({"type": "blob_scene", "root": {}})", R"(type: "blob_scene" (this file holds a "csg" tree))"},
      {"type_missing", R"({"root": {}})", "type: missing"},
      {"root_missing", R"({"type": "csg"})", "root: missing (a csg file needs it)"},
      {"not_an_object", "[1, 2]", "expected a JSON object"},
      {"node_not_object", tree(unite(kSphere, "[1, 2, 3]")), "root.children[1]: expected a node"},
      {"node_without_kind", tree(unite(R"({"radius": 1})", kSphere)),
       R"(root.children[0]: a node needs "primitive", "op" or "transform" (it has only radius))"},
      {"node_two_kinds", tree(R"({"primitive": "sphere", "radius": 1, "op": "union"})"),
       R"(root.op: a node is one of primitive, op, transform (this one also has "primitive"))"},
      {"primitive_unknown", tree(R"({"primitive": "torus", "radius": 1})"),
       R"(root.primitive: "torus" (known primitives: sphere, cylinder, cone, box))"},
      {"primitive_number", tree(R"({"primitive": 3})"), "root.primitive: expected a string, got 3"},
      {"name_number", tree(R"({"primitive": "sphere", "radius": 1, "name": 3})"),
       "root.name: expected a string, got 3"},
      {"box_two_numbers", tree(R"({"primitive": "box", "size": [1, 2]})"),
       "root.size: has 2 numbers (expected [x, y, z])"},
      {"box_edge_negative", tree(R"({"primitive": "box", "size": [1, 2, -0.5]})"),
       "root.size[2]: -0.5 (must be > 0: the box's edge along z)"},
      {"box_size_null", tree(R"({"primitive": "box", "size": [1, null, 1]})"),
       "root.size[1]: expected a number, got null"},
      {"cone_height_zero", tree(R"({"primitive": "cone", "radius": 1, "height": 0})"),
       "root.height: 0 (must be > 0: the cone's height)"},
      {"cylinder_radius_bool", tree(R"({"primitive": "cylinder", "radius": true, "height": 1})"),
       "root.radius: expected a number, got true"},
      // Transforms.
      {"transform_empty", tree(moved("")), "root.transform: empty (a transform needs at least one step)"},
      {"transform_object", tree(R"({"transform": {"translate": [1, 0, 0]}, "child": )" + kSphere + "}"),
       "root.transform: expected an array of steps, got an object"},
      {"transform_child_missing", tree(R"({"transform": [{"translate": [1, 0, 0]}]})"),
       "root.child: missing (a transform needs it)"},
      {"transform_unknown_key", tree(R"({"transform": [{"translate": [1, 0, 0]}], "children": [], "child": )" +
                                     kSphere + "}"),
       "root.children: unknown key in a transform (known keys: transform, child, name)"},
      {"step_unknown", tree(moved(R"({"shear": [1, 0, 0]})")),
       "root.transform[0].shear: unknown key in a transform step (known keys: translate, scale, rotate, matrix)"},
      {"step_two_keys", tree(moved(R"({"translate": [1, 0, 0], "scale": [1, 1, 1]})")),
       "root.transform[0]: has 2 keys (a step has exactly one"},
      {"step_empty", tree(moved("{}")), "root.transform[0]: empty (a step is one of"},
      {"step_array", tree(moved("[1, 0, 0]")), "root.transform[0]: expected a step"},
      {"translate_two", tree(moved(R"({"translate": [1, 0]})")),
       "root.transform[0].translate: has 2 numbers (expected [x, y, z])"},
      {"rotate_degrees_missing", tree(moved(R"({"rotate": {"axis": [0, 0, 1]}})")),
       "root.transform[0].rotate.degrees: missing (a rotation needs it)"},
      {"rotate_degrees_string", tree(moved(R"({"rotate": {"axis": [0, 0, 1], "degrees": "90"}})")),
       R"(root.transform[0].rotate.degrees: expected a number, got "90")"},
      {"rotate_unknown_key", tree(moved(R"({"rotate": {"axis": [0, 0, 1], "degrees": 9, "angle": 9}})")),
       "root.transform[0].rotate.angle: unknown key in a rotation (known keys: axis, degrees)"},
      {"rotate_array", tree(moved(R"({"rotate": [0, 0, 1, 90]})")), "root.transform[0].rotate: expected a rotation"},
      {"matrix_nine", tree(moved(R"({"matrix": [1, 0, 0, 0, 1, 0, 0, 0, 1]})")),
       "root.transform[0].matrix: has 9 numbers (expected 12: a row-major 3 x 4 matrix [L | t])"},
      {"matrix_singular", tree(moved(R"({"matrix": [1, 0, 0, 5, 0, 1, 0, 0, 1, 1, 0, 0]})")),
       "root.transform[0].matrix: singular (det = 0: it flattens the solid)"},
      {"matrix_string", tree(moved(R"({"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, "x"]})")),
       R"(root.transform[0].matrix[11]: expected a number, got "x")"},
      {"steps_underflow", tree(moved(R"({"scale": [1e-200, 1, 1]}, {"scale": [1e-200, 1, 1]})")),
       "root.transform: the steps multiply to a singular matrix (det = 0: it flattens the solid)"},
      {"steps_overflow", tree(moved(R"({"scale": [1e200, 1, 1]}, {"scale": [1e200, 1, 1]})")),
       "root.transform: the steps multiply to a matrix that is not finite"},
      // The file itself.
      {"syntax", R"({"type": "csg", "root": {)", "JSON syntax error at line 1"},
      {"empty", "  \n", "empty file"},
  };
}

class BadCsgFile : public ::testing::TestWithParam<BadTree> {};

TEST_P(BadCsgFile, OneLineWithTheJsonPath) {
  const BadTree& b = GetParam();
  try {
    parse_csg(b.text, "tree.json");
    FAIL() << "accepted: " << b.text;
  } catch (const FileError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("tree.json: " + b.expected, 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(Json, BadCsgFile, ::testing::ValuesIn(bad_trees()),
                         [](const auto& info) { return info.param.name; });

/// n nested single-step transforms around a sphere: n + 1 levels.
std::string nested(int n) {
  std::string text;
  for (int i = 0; i < n; ++i) text += R"({"transform": [{"translate": [0.001, 0, 0]}], "child": )";
  text += kSphere;
  text += std::string(static_cast<std::size_t>(n), '}');
  return tree(text);
}

std::string child_path(int levels) {
  std::string path = "root";
  for (int i = 0; i < levels; ++i) path += ".child";
  return path;
}

TEST(CsgLimits, SixtyFourLevelsReadSixtyFiveDoNot) {
  const CsgFile ok = parse_csg(nested(kCsgMaxDepth - 1), "tree.json");
  EXPECT_EQ(space::classify(ok.tree, {0.063, 0, 0}), Where::kInside);  // moved 0.063 along x
  try {
    parse_csg(nested(kCsgMaxDepth), "tree.json");
    FAIL() << "accepted 65 levels";
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()),
              "tree.json: " + child_path(kCsgMaxDepth) + ": nested more than 64 levels deep (a csg file allows at most 64)");
  }
}

TEST(CsgLimits, AHostileDepthIsRefusedWithoutExhaustingTheStack) {
  // 100000 levels: the JSON parser itself stops at kMaxJsonDepth (256) levels
  // of arrays and objects (spline_json.h), long before the tree's own limit of
  // 64 nodes could be checked, and builds nothing deeper.
  const std::string json_limit = "nested more than " + std::to_string(kMaxJsonDepth) + " arrays or objects deep";
  try {
    parse_csg(nested(100000), "deep.json");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(json_limit), std::string::npos) << e.what();
    EXPECT_EQ(e.json_path().rfind(child_path(kCsgMaxDepth), 0), 0u);
  }
  // The same with operators: root.children[0].children[0]...
  std::string text;
  for (int i = 0; i < 100000; ++i) text += R"({"op": "union", "children": [)";
  text += kSphere;
  for (int i = 0; i < 100000; ++i) text += ", " + kSphere + "]}";
  try {
    parse_csg(tree(text), "deep.json");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(json_limit), std::string::npos) << e.what();
    EXPECT_EQ(e.json_path().rfind("root.children[0].children[0]", 0), 0u);
  }
}

std::string flat_union(int children) {
  std::string text = R"({"op": "union", "children": [)";
  for (int i = 0; i < children; ++i) text += (i ? ", " : "") + kSphere;
  return tree(text + "]}");
}

TEST(CsgLimits, AtMost4096Nodes) {
  // The union and its 4095 children are 4096 nodes.
  const CsgFile ok = parse_csg(flat_union(kCsgMaxNodes - 1), "tree.json");
  EXPECT_EQ(ok.tree.leaves().size(), static_cast<std::size_t>(kCsgMaxNodes - 1));
  try {
    parse_csg(flat_union(kCsgMaxNodes), "tree.json");
    FAIL() << "accepted 4097 nodes";
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()),
              "tree.json: root.children[4095]: more than 4096 nodes (a csg file allows at most 4096)");
  }
}

TEST(CsgLimits, ATreeTooDeepForAFileIsNotWritten) {
  CsgTree t;
  int node = t.sphere(1);
  for (int i = 0; i < kCsgMaxDepth; ++i) node = t.transform(space::Affine::translate({0.01, 0, 0}), node);
  EXPECT_THROW(to_json(t), std::invalid_argument);
}

TEST(CsgFile, MissingFileNamesIt) {
  try {
    read_csg("/no/such/tree.json");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("/no/such/tree.json: cannot open", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace gllab::io
