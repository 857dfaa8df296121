// tests/io/spline_json_test.cpp — the spline file format (common/io/spline_json.cpp):
// every bad file of tests/io/bad/ gives one line naming its JSON path, and
// every file of examples/ round-trips bit-exactly.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "io/field_json.h"
#include "io/spline_json.h"
#include "io_test_support.h"
#include "spline/bspline.h"

namespace gllab::io {
namespace {

namespace fs = std::filesystem;
using spline::BezierCurve;
using spline::BsplineCurve;
using spline::BsplineSurface;
using spline::Vec3;
using testing::BadFile;
using testing::bad_files;
using testing::kBadDir;
using testing::kExamplesDir;
using testing::ScratchDir;

// ---- (a) the corpus of bad files ---------------------------------------------

class BadSplineFile : public ::testing::TestWithParam<BadFile> {};

TEST_P(BadSplineFile, GivesOneLineNamingTheJsonPath) {
  const fs::path file = kBadDir / GetParam().file;
  try {
    read_any(file);
    FAIL() << file << " was accepted; expected an error containing: " << GetParam().expected;
  } catch (const FileError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << "starts with the file: " << message;
    EXPECT_NE(message.find(GetParam().expected), std::string::npos)
        << "expected: " << GetParam().expected << "\n got:     " << message;
    EXPECT_EQ(e.file(), file.string());
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadSplineFile, ::testing::ValuesIn(bad_files()),
                         [](const ::testing::TestParamInfo<BadFile>& info) {
                           return testing::test_name(info.param.file);
                         });

TEST(BadSplineFileCorpus, EveryFileIsListedInExpectedTxtAndViceVersa) {
  std::set<std::string> listed, present;
  for (const BadFile& b : bad_files()) listed.insert(b.file);
  for (const auto& entry : fs::directory_iterator(kBadDir))
    if (entry.path().extension() == ".json") present.insert(entry.path().filename().string());
  EXPECT_EQ(listed, present);
  // The task: at least 25 distinct mistakes.
  EXPECT_GE(listed.size(), 25u);
}

TEST(BadSplineFile, MissingFileNamesTheFileAndTheReason) {
  try {
    read_any(kBadDir / "no_such_file.json");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_file.json: cannot open (No such file or directory)"),
              std::string::npos)
        << e.what();
  }
}

TEST(BadSplineFile, DirectoryIsNotAFile) {
  EXPECT_THROW(read_any(kBadDir), FileError);
}

TEST(BadSplineFile, PathAndProblemAreSeparate) {
  try {
    parse_any(R"({"type": "bspline_curve", "degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 1]],
                  "weights": [1, -2]})",
              "text");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(e.file(), "text");
    EXPECT_EQ(e.json_path(), "weights[1]");
    EXPECT_EQ(e.problem(), "-2 (weights must be > 0)");
    EXPECT_STREQ(e.what(), "text: weights[1]: -2 (weights must be > 0)");
  }
}

TEST(BadSplineFile, DuplicateKeyInsideATrimPieceNamesItsPath) {
  const std::string text = R"({"type": "bspline_surface", "degree_u": 1, "degree_v": 1,
    "knots_u": [0, 0, 1, 1], "knots_v": [0, 0, 1, 1],
    "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]],
    "trims": [[{"type": "polyline", "points": [[0, 0], [1, 0]], "points": [[0, 0], [1, 1]]}]]})";
  try {
    parse_surface(text);
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(e.json_path(), "trims[0][0].points") << e.what();
  }
}

TEST(BadSplineFile, DeeplyNestedArraysAreRejectedQuickly) {
  // 100000 levels: the parser stops at the opening bracket of level
  // kMaxJsonDepth + 1, so nothing deep is built, copied or freed.
  const std::string depth = std::to_string(kMaxJsonDepth);
  const std::string text = std::string(100000, '[') + std::string(100000, ']');
  try {
    parse_any(text, "deep.json");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(e.problem(), "nested more than " + depth + " arrays or objects deep (the limit, kMaxJsonDepth)");
    std::string path;
    for (int i = 0; i < kMaxJsonDepth; ++i) path += "[0]";  // where level kMaxJsonDepth + 1 starts
    EXPECT_EQ(e.json_path(), path);
  }
  try {
    parse_any(std::string(100000, '[') + "1e999" + std::string(100000, ']'));
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(e.json_path().substr(0, 9), "[0][0][0]");
  }
}

// The crash class of issue 20: a deep value followed by another key made the
// ordered map copy the deep value recursively (a stack overflow from about
// 100k levels). Now the depth limit stops it before it is built.
TEST(BadSplineFile, DeepValueFollowedByAnotherKeyIsAnErrorNotACrash) {
  const std::string deep = std::string(200000, '[') + std::string(200000, ']');
  const std::string text = R"({"type": "bezier_curve", "extra": )" + deep + R"(, "points": [[0, 0], [1, 1]]})";
  try {
    parse_any(text, "deep.json");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("nested more than"), std::string::npos) << e.what();
    EXPECT_EQ(e.json_path().rfind("extra[0][0]", 0), 0u) << e.json_path();
  }
}

// Exactly kMaxJsonDepth levels parse (and are then judged as a spline file);
// one more is the depth error.
TEST(BadSplineFile, TheDepthLimitIsExact) {
  const auto nested = [](int levels) {
    return R"({"type": "bezier_curve", "points": [[0, 0], [1, 1]], "x": )" + std::string(levels - 1, '[') +
           std::string(levels - 1, ']') + "}";
  };
  const auto problem = [](const std::string& text) {
    try {
      parse_any(text);
    } catch (const FileError& e) {
      return e.problem();
    }
    return std::string("no error");
  };
  EXPECT_EQ(problem(nested(kMaxJsonDepth)).find("nested more than"), std::string::npos);
  EXPECT_NE(problem(nested(kMaxJsonDepth + 1)).find("nested more than"), std::string::npos);
}

// A text larger than kMaxJsonBytes is refused before it is parsed.
TEST(BadSplineFile, TooLargeTextIsRefusedBeforeParsing) {
  const std::string text(kMaxJsonBytes + 1, '[');
  try {
    parse_any(text, "big.json");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(e.problem(), std::to_string(kMaxJsonBytes + 1) + " bytes, larger than the limit of " +
                               std::to_string(kMaxJsonBytes) + " (kMaxJsonBytes)");
  }
}

TEST(BadSplineFile, InfinityBuiltInMemoryIsRejectedByFromJson) {
  Json value = Json::parse(R"({"type": "bezier_curve", "points": [[0, 0], [1, 1]]})");
  value["points"][1][0] = std::numeric_limits<double>::infinity();
  try {
    from_json(value, "memory");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(e.json_path(), "points[1][0]");
  }
}

TEST(BadSplineFile, SurfaceWhereACurveWasExpectedNamesTheType) {
  try {
    read_curve(kExamplesDir / "bicubic_surface.json");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(e.json_path(), "type") << e.what();
  }
  EXPECT_THROW(read_surface(kExamplesDir / "nurbs_circle.json"), FileError);
  EXPECT_THROW(read_bezier(kExamplesDir / "nurbs_circle.json"), FileError);
}

TEST(BadPointsFile, TangentOfTheWrongDimensionIsNamed) {
  try {
    parse_points(R"({"points": [[0, 0], [1, 1]], "end_tangent": [1, 0, 0]})");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(e.json_path(), "end_tangent") << e.what();
  }
  EXPECT_THROW(parse_points(R"({"points": [[0, 0]]})"), FileError);  // one point: nothing to interpolate
  EXPECT_THROW(parse_points(R"({"points": [[0, 0], [1, 1]], "type": "points"})"), FileError);
}

// ---- (b) round trips -------------------------------------------------------------

/// Bit patterns, so that -0.0 != 0.0 and every last bit counts.
std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

void expect_same_bits(const std::vector<double>& a, const std::vector<double>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(bits(a[i]), bits(b[i])) << what << "[" << i << "]";
}

void expect_same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(bits(a[i].x), bits(b[i].x)) << what << "[" << i << "].x";
    EXPECT_EQ(bits(a[i].y), bits(b[i].y)) << what << "[" << i << "].y";
    EXPECT_EQ(bits(a[i].z), bits(b[i].z)) << what << "[" << i << "].z";
  }
}

void expect_same(const BsplineCurve& a, const BsplineCurve& b) {
  EXPECT_EQ(a.p, b.p);
  EXPECT_EQ(a.dimension, b.dimension);
  expect_same_bits(a.U, b.U, "U");
  expect_same_bits(a.P, b.P, "P");
  expect_same_bits(a.w, b.w, "w");
}

void expect_same(const BezierCurve& a, const BezierCurve& b) {
  EXPECT_EQ(a.dimension, b.dimension);
  expect_same_bits(a.P, b.P, "P");
  expect_same_bits({a.a, a.b}, {b.a, b.b}, "interval");
}

void expect_same(const BsplineSurface& a, const BsplineSurface& b) {
  EXPECT_EQ(a.p, b.p);
  EXPECT_EQ(a.q, b.q);
  EXPECT_EQ(a.nu, b.nu);
  EXPECT_EQ(a.nv, b.nv);
  expect_same_bits(a.U, b.U, "U");
  expect_same_bits(a.V, b.V, "V");
  expect_same_bits(a.P, b.P, "P");
  expect_same_bits(a.w, b.w, "w");
  ASSERT_EQ(a.trims.size(), b.trims.size());
  for (std::size_t l = 0; l < a.trims.size(); ++l) {
    ASSERT_EQ(a.trims[l].pieces.size(), b.trims[l].pieces.size());
    for (std::size_t k = 0; k < a.trims[l].pieces.size(); ++k) {
      const spline::TrimPiece &pa = a.trims[l].pieces[k], &pb = b.trims[l].pieces[k];
      ASSERT_EQ(pa.curve.has_value(), pb.curve.has_value());
      if (pa.curve) expect_same(*pa.curve, *pb.curve);
      ASSERT_EQ(pa.polyline.size(), pb.polyline.size());
      for (std::size_t i = 0; i < pa.polyline.size(); ++i) {
        EXPECT_EQ(bits(pa.polyline[i].x), bits(pb.polyline[i].x));
        EXPECT_EQ(bits(pa.polyline[i].y), bits(pb.polyline[i].y));
      }
    }
  }
}

void expect_same(const SplineFile& a, const SplineFile& b) {
  ASSERT_EQ(a.index(), b.index());
  std::visit([&](const auto& x) { expect_same(x, std::get<std::decay_t<decltype(x)>>(b)); }, a);
}

/// The spline and points files in examples/ (blob scenes, "type": "blob_scene",
/// are field_json_test's).
std::vector<std::string> example_files() {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(kExamplesDir))
    if (entry.path().extension() == ".json" &&
        Json::parse(testing::read_file(entry.path())).value("type", "") != "blob_scene")
      files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

bool is_points_file(const fs::path& file) {
  return !Json::parse(testing::read_file(file)).contains("type");
}

class ExampleFile : public ::testing::TestWithParam<std::string> {};

TEST_P(ExampleFile, RoundTripsBitExactly) {
  const fs::path file = kExamplesDir / GetParam();
  if (is_points_file(file)) {
    const PointsFile a = read_points(file);
    const std::string text = to_text(to_json(a));
    const PointsFile b = parse_points(text);
    expect_same_bits(a.points, b.points, "points");
    EXPECT_EQ(a.dimension, b.dimension);
    EXPECT_EQ(to_text(to_json(b)), text);
    return;
  }
  const SplineFile a = read_any(file);
  const std::string text = to_text(a);
  const SplineFile b = parse_any(text, "written");
  expect_same(a, b);
  // Writing what was read back gives the same text: the layout is stable.
  EXPECT_EQ(to_text(b), text);
  // And through a real file, written atomically.
  ScratchDir dir("roundtrip");
  write_file(dir / GetParam(), a);
  expect_same(a, read_any(dir / GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleFile, ::testing::ValuesIn(example_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return testing::test_name(info.param);
                         });

TEST(Examples, TheTaskAsksForTheseFiles) {
  const std::vector<std::string> files = example_files();
  for (const char* name : {"cubic_bspline_curve.json", "nurbs_circle.json", "bezier_2d.json", "bicubic_surface.json",
                           "trimmed_nurbs_surface.json", "interpolation_points.json"})
    EXPECT_NE(std::find(files.begin(), files.end(), name), files.end()) << name;
}

TEST(Examples, NurbsCircleHasTheBooksWeightsAndKnots) {
  // The NURBS Book §7.5, Ex. 7.2: 9 points, degree 2, weights 1 and sqrt(2)/2.
  const BsplineCurve c = read_curve(kExamplesDir / "nurbs_circle.json");
  EXPECT_EQ(c.p, 2);
  EXPECT_EQ(c.dimension, 2);
  ASSERT_EQ(c.w.size(), 9u);
  for (std::size_t i = 0; i < 9; ++i) EXPECT_EQ(c.w[i], i % 2 ? std::sqrt(2.0) / 2 : 1.0) << i;
  EXPECT_EQ(c.U, (std::vector<double>{0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}));
}

TEST(Examples, TrimmedSurfaceHasAPolylineOuterLoopAndACircleHole) {
  const BsplineSurface s = read_surface(kExamplesDir / "trimmed_nurbs_surface.json");
  ASSERT_EQ(s.trims.size(), 2u);
  ASSERT_EQ(s.trims[0].pieces.size(), 1u);
  EXPECT_FALSE(s.trims[0].pieces[0].curve.has_value());
  ASSERT_TRUE(s.trims[1].pieces[0].curve.has_value());
  EXPECT_TRUE(s.trims[1].pieces[0].curve->rational());
  // Shoelace area: > 0 counter-clockwise (outer), < 0 clockwise (the hole's
  // control polygon turns the same way as the circle).
  auto signed_area = [](const std::vector<spline::Vec2>& loop) {
    double twice = 0;
    for (std::size_t i = 0; i + 1 < loop.size(); ++i) twice += spline::cross(loop[i], loop[i + 1]);
    return twice / 2;
  };
  EXPECT_GT(signed_area(s.trims[0].pieces[0].polyline), 0);
  std::vector<spline::Vec2> hole;
  for (const Vec3& p : s.trims[1].pieces[0].curve->P) hole.push_back({p.x, p.y});
  EXPECT_LT(signed_area(hole), 0);
}

TEST(Readme, EveryJsonExampleInTheFormatDocumentIsValid) {
  // common/io/README.md documents the format with examples: they must read.
  const std::string readme = testing::read_file(testing::kSourceDir / "common" / "io" / "README.md");
  int blocks = 0;
  for (std::size_t start = readme.find("```json\n"); start != std::string::npos;
       start = readme.find("```json\n", start + 1)) {
    const std::size_t begin = start + 8, end = readme.find("```", begin);
    const std::string block = readme.substr(begin, end - begin);
    SCOPED_TRACE(block);
    if (block.find("\"blob_scene\"") != std::string::npos)
      EXPECT_NO_THROW(parse_blob_scene(block, "README.md"));  // field_json.h
    else if (block.find("\"type\"") != std::string::npos && block.find("\"type\"") < block.find("\"points\""))
      EXPECT_NO_THROW(parse_any(block, "README.md"));
    else
      EXPECT_NO_THROW(parse_points(block, "README.md"));
    ++blocks;
  }
  EXPECT_GE(blocks, 4);
}

TEST(RoundTrip, AwkwardDoublesComeBackBitIdentical) {
  const double kAwkward[] = {0.1,
                             1.0 / 3,
                             -0.0,
                             3.141592653589793,
                             1e-300,
                             std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::lowest(),
                             123456789012345678.0,
                             std::nextafter(1.0, 2.0)};
  BezierCurve b;
  b.dimension = 3;
  for (double x : kAwkward) b.P.push_back({x, -x, x / 7});
  b.a = -1.0 / 3;
  b.b = std::nextafter(-1.0 / 3, 1.0);
  const BezierCurve back = parse_bezier(to_text(b));
  expect_same(b, back);
}

TEST(RoundTrip, TwoDimensionalStaysTwoDimensional) {
  const BsplineCurve c = read_curve(kExamplesDir / "nurbs_circle.json");
  const std::string text = to_text(c);
  EXPECT_NE(text.find("[1.0, 0.0]"), std::string::npos) << text;
  EXPECT_EQ(text.find("[1.0, 0.0, 0.0]"), std::string::npos) << text;
}

TEST(RoundTrip, BezierIsReadAsTheSameClampedBspline) {
  // A Bézier curve over [a, b] is the B-spline with knots a^(p+1) b^(p+1)
  // (The NURBS Book §2.2: the Bernstein polynomials are those B-splines).
  const std::string text = R"({"type": "bezier_curve", "points": [[0, 0], [2, 4.5], [8.5, 6.5], [11, 2]],
                               "interval": [1, 3]})";
  const BsplineCurve c = parse_curve(text);
  EXPECT_EQ(c.p, 3);
  EXPECT_EQ(c.U, (std::vector<double>{1, 1, 1, 1, 3, 3, 3, 3}));
  const BezierCurve b = parse_bezier(text);
  EXPECT_EQ(b.a, 1);
  EXPECT_EQ(b.b, 3);
  EXPECT_NE(to_text(b).find("\"interval\": [1.0, 3.0]"), std::string::npos);
}

TEST(RoundTrip, ParametersOfAnInterpolatedCurveAreAcceptedAndDropped) {
  const BsplineCurve c = parse_curve(R"({"type": "bspline_curve", "degree": 1, "knots": [0, 0, 1, 1],
                                         "points": [[0, 0], [1, 1]], "parameters": [0, 1]})");
  EXPECT_EQ(to_text(c).find("parameters"), std::string::npos);
}

TEST(Write, NonFiniteValuesAreRefused) {
  BsplineCurve c = read_curve(kExamplesDir / "cubic_bspline_curve.json");
  c.P[2].y = std::nan("");
  EXPECT_THROW(to_text(c), std::invalid_argument);
}

TEST(Write, TwoDimensionalCurveWithZIsRefused) {
  BsplineCurve c = read_curve(kExamplesDir / "nurbs_circle.json");
  c.P[1].z = 0.5;
  EXPECT_THROW(to_text(c), std::invalid_argument);
}

TEST(Write, ReplacesTheFileAndLeavesNoTemporaryFile) {
  ScratchDir dir("write");
  const SplineFile circle = read_any(kExamplesDir / "nurbs_circle.json");
  const SplineFile bezier = read_any(kExamplesDir / "bezier_2d.json");
  write_file(dir / "x.json", circle);
  write_file(dir / "x.json", bezier);
  expect_same(bezier, read_any(dir / "x.json"));
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 1);
}

// A FIFO (like /dev/null or /dev/stdout, not a regular file) is written into,
// never replaced: renaming a temporary file over it would replace the device.
TEST(Write, IntoAFifoWritesThroughItAndKeepsIt) {
  ScratchDir dir("fifo");
  const fs::path fifo = dir / "pipe.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  std::string received;
  std::thread reader([&] {
    std::ifstream in(fifo, std::ios::binary);
    received.assign(std::istreambuf_iterator<char>(in), {});
  });
  gllab::io::write_text_atomically(fifo, "{\"kind\": 1}\n");
  reader.join();
  EXPECT_TRUE(fs::is_fifo(fifo)) << "replaced the FIFO with a file";
  EXPECT_EQ(received, "{\"kind\": 1}\n");
}

TEST(Write, ThroughASymlinkReplacesTheFileItNames) {
  ScratchDir dir("link");
  gllab::io::write_text_atomically(dir / "real.txt", "one\n");
  fs::create_symlink(dir / "real.txt", dir / "link.txt");
  gllab::io::write_text_atomically(dir / "link.txt", "two\n");
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  std::ifstream in(dir / "real.txt");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "two\n");
}

TEST(Write, UnwritableDirectoryNamesTheFile) {
  const SplineFile circle = read_any(kExamplesDir / "nurbs_circle.json");
  try {
    write_file("/nonexistent-dir/x.json", circle);
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.json: cannot write"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gllab::io
