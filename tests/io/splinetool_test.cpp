// tests/io/splinetool_test.cpp — runs the built splinetool (tools/splinetool.cpp)
// as a process: exit codes, one-line errors, and values checked against
// references that do not come from the tool (the lecture, The NURBS Book, and
// properties such as "knot insertion does not change the curve").
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "io/spline_json.h"
#include "io_test_support.h"
#include "process.h"
#include "spline/vec.h"

namespace gllab::io {
namespace {

namespace fs = std::filesystem;
using spline::BsplineCurve;
using spline::BsplineSurface;
using spline::Vec3;
using testing::BadFile;
using testing::kBadDir;
using testing::kExamplesDir;
using testing::ScratchDir;

constexpr int kBadInput = 2;  // documented in splinetool --help
constexpr int kFailed = 1;    // an output file could not be written

/// Exact algorithms (knot insertion, degree elevation, splitting, printing
/// with 17 significant digits) agree to round-off.
constexpr double kRoundOff = 1e-12;
/// Interpolants hit their points up to the error of the linear solves.
constexpr double kInterpolation = 1e-9;
/// The lecture prints the de Casteljau levels rounded to two decimals.
constexpr double kLectureRounding = 0.01;
constexpr double kPi = 3.141592653589793;

const std::string kTool = GLLAB_SPLINETOOL;
const std::string kCircle = (kExamplesDir / "nurbs_circle.json").string();
const std::string kCubic = (kExamplesDir / "cubic_bspline_curve.json").string();
const std::string kBezier = (kExamplesDir / "bezier_2d.json").string();
const std::string kSurface = (kExamplesDir / "bicubic_surface.json").string();
const std::string kTrimmed = (kExamplesDir / "trimmed_nurbs_surface.json").string();
const std::string kPoints = (kExamplesDir / "interpolation_points.json").string();
const std::string kClampedPoints = (kExamplesDir / "interpolation_clamped.json").string();

ProcessResult splinetool(std::vector<std::string> args) {
  args.insert(args.begin(), kTool);
  return run_process(args);
}

/// Runs splinetool, expects success, returns its JSON.
Json run_ok(const std::vector<std::string>& args) {
  const ProcessResult r = splinetool(args);
  std::string line;
  for (const std::string& a : args) line += a + " ";
  EXPECT_EQ(r.exit_status, 0) << line << "\n" << r.err;
  EXPECT_EQ(r.err, "") << line;
  try {
    return Json::parse(r.out);
  } catch (const std::exception& e) {
    ADD_FAILURE() << line << ": stdout is not JSON: " << e.what() << "\n" << r.out;
    return Json::object();
  }
}

/// Runs splinetool and saves its output as a file for the next command.
std::string run_to_file(const std::vector<std::string>& args, const ScratchDir& dir, const std::string& name) {
  const ProcessResult r = splinetool(args);
  EXPECT_EQ(r.exit_status, 0) << r.err;
  const fs::path file = dir / name;
  std::ofstream(file) << r.out;
  return file.string();
}

Vec3 vec(const Json& p) { return {p[0].get<double>(), p[1].get<double>(), p.size() > 2 ? p[2].get<double>() : 0.0}; }

std::string joined(const std::vector<double>& t) {
  std::string out;
  char buffer[40];
  for (double x : t) {
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    out += (out.empty() ? "" : ",") + std::string(buffer);
  }
  return out;
}

void expect_near(Vec3 a, Vec3 b, double tolerance, const std::string& what) {
  EXPECT_LE(spline::norm(a - b), tolerance) << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x
                                            << ", " << b.y << ", " << b.z << ")";
}

void expect_same_points(const Json& a, const Json& b, double tolerance) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) expect_near(vec(a[i]), vec(b[i]), tolerance, "point " + std::to_string(i));
}

// ---- help and usage ------------------------------------------------------------------

const char* const kCommands[] = {"eval", "insert-knot", "elevate", "split", "to-bezier", "interpolate", "tessellate"};

TEST(Help, OverviewListsEveryCommand) {
  const ProcessResult r = splinetool({"--help"});
  EXPECT_EQ(r.exit_status, 0);
  for (const char* command : kCommands) EXPECT_NE(r.out.find(command), std::string::npos) << command;
}

TEST(Help, EveryCommandExplainsItsOptions) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> options = {
      {"eval", {"--at", "--samples", "--derivatives"}},
      {"insert-knot", {"--knot", "--times"}},
      {"elevate", {"--times"}},
      {"split", {"--at"}},
      {"to-bezier", {}},
      {"interpolate", {"--method", "--param", "natural", "clamped", "periodic", "lagrange", "newton", "bezier",
                       "uniform", "chordal", "centripetal", "foley"}},
      {"tessellate", {"--tolerance", "--obj"}}};
  for (const auto& [command, words] : options) {
    const ProcessResult r = splinetool({command, "--help"});
    EXPECT_EQ(r.exit_status, 0) << command;
    EXPECT_NE(r.out.find("usage: splinetool " + command), std::string::npos) << r.out;
    for (const std::string& w : words) EXPECT_NE(r.out.find(w), std::string::npos) << command << " " << w;
  }
}

struct BadUsage {
  std::vector<std::string> args;
  std::string named;  // what the one line must contain
};
void PrintTo(const BadUsage& b, std::ostream* out) {
  *out << "splinetool";
  for (const std::string& a : b.args) *out << " " << fs::path(a).filename().string();
}

class SplinetoolBadInput : public ::testing::TestWithParam<BadUsage> {};

TEST_P(SplinetoolBadInput, PrintsOneLineAndExitsTwo) {
  const ProcessResult r = splinetool(GetParam().args);
  EXPECT_EQ(r.exit_status, kBadInput) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(GetParam().named), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SplinetoolBadInput,
    ::testing::Values(
        BadUsage{{}, "no command"},
        BadUsage{{"frobnicate"}, "unknown command 'frobnicate'"},
        BadUsage{{"eval"}, "eval needs a FILE"},
        BadUsage{{"eval", kCircle}, "--at"},
        BadUsage{{"eval", kCircle, "--at", "abc"}, "'abc' is not a number"},
        BadUsage{{"eval", kCircle, "--at", "0,1.5"}, "1.5 is outside the domain [0, 1]"},
        BadUsage{{"eval", kCircle, "--at", "nan"}, "'nan' is not finite"},
        BadUsage{{"eval", kCircle, "--at", "0,,1"}, "'' is not a number"},
        BadUsage{{"eval", kCircle, "--samples", "1"}, "--samples: 1"},
        BadUsage{{"eval", kCircle, "--at", "0", "--samples", "3"}, "not both"},
        BadUsage{{"eval", kCircle, "--at", "0", "--derivatives", "-1"}, "--derivatives: -1"},
        BadUsage{{"eval", kCircle, "--frob", "1"}, "unknown option '--frob'"},
        BadUsage{{"eval", kCircle, "--at"}, "--at needs a value"},
        BadUsage{{"eval", kCircle, "--at", "0", "extra"}, "unexpected argument 'extra'"},
        BadUsage{{"eval", "/nonexistent/x.json", "--at", "0"}, "/nonexistent/x.json: cannot open"},
        BadUsage{{"eval", kSurface, "--at", "0.5"}, "'0.5' is not u:v"},
        BadUsage{{"eval", kSurface, "--at", "0.5:2"}, "2 is outside the domain [0, 1]"},
        BadUsage{{"eval", kSurface, "--at", "0.5:0.5", "--derivatives", "1"}, "--derivatives is for curves"},
        BadUsage{{"insert-knot", kCircle}, "--knot"},
        BadUsage{{"insert-knot", kCircle, "--knot", "2"}, "2 is outside the domain"},
        // The NURBS Book A5.1 needs s + r <= p: 0.25 already has multiplicity 2 = p.
        BadUsage{{"insert-knot", kCircle, "--knot", "0.25"}, "0.25"},
        BadUsage{{"insert-knot", kSurface, "--knot", "0.5"}, "\"bspline_surface\""},
        BadUsage{{"elevate", kCircle, "--times", "x"}, "'x' is not a whole number"},
        BadUsage{{"elevate", kCircle, "--times", "40"}, "--times: 40"},
        BadUsage{{"split", kCircle, "--at", "0"}, "0 is not inside the domain"},
        BadUsage{{"split", kBezier, "--at", "1"}, "1 is not inside the interval"},
        BadUsage{{"to-bezier", kSurface}, "\"bspline_surface\""},
        BadUsage{{"interpolate", kPoints}, "--method"},
        BadUsage{{"interpolate", kPoints, "--method", "cubic"}, "--method: 'cubic'"},
        BadUsage{{"interpolate", kPoints, "--method", "natural", "--param", "arc"}, "--param: 'arc'"},
        BadUsage{{"interpolate", kPoints, "--method", "clamped"}, "start_tangent: missing"},
        BadUsage{{"interpolate", kCircle, "--method", "natural"}, "type: unknown key in a points file"},
        BadUsage{{"tessellate", kCircle}, "--tolerance"},
        BadUsage{{"tessellate", kCircle, "--tolerance", "0"}, "--tolerance: 0"},
        BadUsage{{"tessellate", kCircle, "--tolerance", "-1"}, "--tolerance: -1"}));

/// Every file of the bad corpus gives the same one line through the tool.
class SplinetoolBadFile : public ::testing::TestWithParam<BadFile> {};

TEST_P(SplinetoolBadFile, PrintsTheReadersOneLineAndExitsTwo) {
  const std::string file = (kBadDir / GetParam().file).string();
  const ProcessResult r = splinetool({"eval", file, "--at", "0"});
  EXPECT_EQ(r.exit_status, kBadInput) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(file + ": "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(GetParam().expected), std::string::npos) << "expected: " << GetParam().expected << "\n"
                                                                 << r.err;
  EXPECT_EQ(r.out, "");
}

INSTANTIATE_TEST_SUITE_P(Corpus, SplinetoolBadFile, ::testing::ValuesIn(testing::bad_files()),
                         [](const ::testing::TestParamInfo<BadFile>& info) {
                           return testing::test_name(info.param.file);
                         });

TEST(SplinetoolBadInput, CoincidentPointsNameBothIndices) {
  ScratchDir dir("coincident");
  std::ofstream(dir / "points.json") << R"({"points": [[0, 0], [1, 1], [1, 1], [2, 0]]})";
  const ProcessResult r =
      splinetool({"interpolate", (dir / "points.json").string(), "--method", "natural", "--param", "chordal"});
  EXPECT_EQ(r.exit_status, kBadInput);
  EXPECT_NE(r.err.find("P[1]"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("P[2]"), std::string::npos) << r.err;
}

// ---- eval ---------------------------------------------------------------------------

TEST(Eval, NurbsCircleHasRadiusOneAndTangentsPerpendicular) {
  // The NURBS Book §7.5, Ex. 7.2: the 9-point circle is exact, |C(u)| = 1,
  // and a circle's tangent is perpendicular to its radius.
  const Json out = run_ok({"eval", kCircle, "--samples", "101", "--derivatives", "1"});
  ASSERT_EQ(out["points"].size(), 101u);
  ASSERT_EQ(out["derivatives"].size(), 1u);
  for (std::size_t i = 0; i < 101; ++i) {
    const Vec3 C = vec(out["points"][i]), D = vec(out["derivatives"][0][i]);
    EXPECT_EQ(out["points"][i].size(), 2u);  // a 2D file gives 2D points
    EXPECT_NEAR(spline::norm(C), 1.0, kRoundOff) << i;
    EXPECT_NEAR(spline::dot(C, D) / spline::norm(D), 0.0, kRoundOff) << i;
  }
  EXPECT_EQ(out["parameters"].front().get<double>(), 0.0);
  EXPECT_EQ(out["parameters"].back().get<double>(), 1.0);
}

TEST(Eval, NurbsCirclePassesTheAxisPointsAtQuarterParameters) {
  // The knots 1/4, 1/2, 3/4 sit at the control points on the axes (Ex. 7.2).
  const Json out = run_ok({"eval", kCircle, "--at", "0,0.25,0.5,0.75,1"});
  const Vec3 expected[] = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {1, 0, 0}};
  for (std::size_t i = 0; i < 5; ++i) expect_near(vec(out["points"][i]), expected[i], kRoundOff, "axis point");
}

TEST(Eval, LectureDeCasteljauExampleAtPointSix) {
  // Ch. 1 §1.6, "Example (de Casteljau algorithm)": b = (0,0), (2,4.5),
  // (8.5,6.5), (11,2) gives X(0.6) = (6.63, 4.54) with levels rounded to two
  // decimals. The Bernstein form without rounding: (6.624, 4.536).
  const Json out = run_ok({"eval", kBezier, "--at", "0.6", "--derivatives", "1"});
  const Vec3 X = vec(out["points"][0]);
  EXPECT_NEAR(X.x, 6.63, kLectureRounding);
  EXPECT_NEAR(X.y, 4.54, kLectureRounding);
  expect_near(X, {6.624, 4.536, 0}, kRoundOff, "Bernstein form");
  // X'(t) = 3 [(1-t)^2 (b1 - b0) + 2 (1-t) t (b2 - b1) + t^2 (b3 - b2)].
  const double t = 0.6;
  const Vec3 b[] = {{0, 0, 0}, {2, 4.5, 0}, {8.5, 6.5, 0}, {11, 2, 0}};
  const Vec3 d = 3 * ((1 - t) * (1 - t) * (b[1] - b[0]) + 2 * (1 - t) * t * (b[2] - b[1]) + t * t * (b[3] - b[2]));
  expect_near(vec(out["derivatives"][0][0]), d, kRoundOff, "derivative");
}

TEST(Eval, DerivativesHaveOneListPerOrderInThePointsDimension) {
  const Json out = run_ok({"eval", kCubic, "--at", "0,0.3,1", "--derivatives", "4"});
  ASSERT_EQ(out["derivatives"].size(), 4u);
  for (const Json& order : out["derivatives"]) {
    ASSERT_EQ(order.size(), 3u);
    for (const Json& p : order) EXPECT_EQ(p.size(), 3u);
  }
  // A cubic's fourth derivative is zero.
  for (const Json& p : out["derivatives"][3]) expect_near(vec(p), {}, kRoundOff, "4th derivative");
}

TEST(Eval, SurfaceNormalIsTheUnitCrossProductOfThePartials) {
  const Json out = run_ok({"eval", kSurface, "--samples", "9"});
  ASSERT_EQ(out["points"].size(), 81u);
  for (std::size_t i = 0; i < 81; ++i) {
    const Vec3 du = vec(out["du"][i]), dv = vec(out["dv"][i]), n = vec(out["normals"][i]);
    expect_near(n, spline::normalized(spline::cross(du, dv)), kRoundOff, "normal " + std::to_string(i));
    EXPECT_NEAR(spline::norm(n), 1.0, kRoundOff);
  }
  // A clamped surface interpolates its corner control points.
  expect_near(vec(out["points"][0]), {0, 0, 0}, kRoundOff, "corner (0, 0)");
  expect_near(vec(out["points"][80]), {4, 4, 0}, kRoundOff, "corner (1, 1)");
}

TEST(Eval, RationalBezierPatchMatchesTheBernsteinSum) {
  // The trimmed example is one bicubic rational Bézier patch (knots 0^4 1^4):
  // S(u, v) = sum B_i(u) B_j(v) w_ij P_ij / sum B_i(u) B_j(v) w_ij (The NURBS
  // Book eq. 4.15), summed here from the file, not by the tool.
  const BsplineSurface s = read_surface(kTrimmed);
  auto bernstein = [](double t) {
    return std::vector<double>{(1 - t) * (1 - t) * (1 - t), 3 * (1 - t) * (1 - t) * t, 3 * (1 - t) * t * t, t * t * t};
  };
  const double u = 0.3, v = 0.8;
  Vec3 numerator;
  double denominator = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double c = bernstein(u)[i] * bernstein(v)[j] * s.weight(i, j);
      numerator += c * s.point(i, j);
      denominator += c;
    }
  const Json out = run_ok({"eval", kTrimmed, "--at", "0.3:0.8"});
  expect_near(vec(out["points"][0]), numerator / denominator, kRoundOff, "S(0.3, 0.8)");
  // The partials against central differences of the tool's own points.
  const double h = 1e-6;
  const Json near = run_ok({"eval", kTrimmed, "--at", "0.299999:0.8,0.300001:0.8,0.3:0.799999,0.3:0.800001"});
  const Vec3 du = (vec(near["points"][1]) - vec(near["points"][0])) / (2 * h);
  const Vec3 dv = (vec(near["points"][3]) - vec(near["points"][2])) / (2 * h);
  expect_near(vec(out["du"][0]), du, 1e-6, "du");
  expect_near(vec(out["dv"][0]), dv, 1e-6, "dv");
}

// ---- refinement: the curve must not change ----------------------------------------

/// Evaluates two files at the same 101 parameters of a's domain.
void expect_same_curve(const std::string& a, const std::string& b) {
  const Json ea = run_ok({"eval", a, "--samples", "101"});
  std::vector<double> t;
  for (const Json& x : ea["parameters"]) t.push_back(x.get<double>());
  const Json eb = run_ok({"eval", b, "--at", joined(t)});
  expect_same_points(ea["points"], eb["points"], kRoundOff);
}

TEST(InsertKnot, LeavesTheCurveUnchanged) {
  ScratchDir dir("insert");
  for (const std::string& file : {kCubic, kCircle, kBezier}) {
    const std::string refined =
        run_to_file({"insert-knot", file, "--knot", "0.3", "--times", "2"}, dir, "refined.json");
    const BsplineCurve before = read_curve(file), after = read_curve(refined);
    EXPECT_EQ(after.U.size(), before.U.size() + 2) << file;
    EXPECT_EQ(after.P.size(), before.P.size() + 2) << file;
    EXPECT_EQ(std::count(after.U.begin(), after.U.end(), 0.3), 2) << file;
    EXPECT_EQ(after.dimension, before.dimension) << file;
    expect_same_curve(file, refined);
  }
}

TEST(Elevate, LeavesTheCurveUnchanged) {
  ScratchDir dir("elevate");
  for (const std::string& file : {kCubic, kCircle, kBezier}) {
    const std::string elevated = run_to_file({"elevate", file, "--times", "2"}, dir, "elevated.json");
    EXPECT_EQ(read_curve(elevated).p, read_curve(file).p + 2) << file;
    expect_same_curve(file, elevated);
  }
  // A Bézier file stays a Bézier file.
  EXPECT_EQ(run_ok({"elevate", kBezier})["type"], "bezier_curve");
}

TEST(Split, TheTwoPiecesAreTheCurvesHalves) {
  for (const std::string& file : {kCubic, kCircle, kBezier}) {
    const Json out = run_ok({"split", file, "--at", "0.6"});
    ASSERT_EQ(out["curves"].size(), 2u);
    const SplineFile first = from_json(out["curves"][0]), second = from_json(out["curves"][1]);
    ScratchDir dir("split");
    write_file(dir / "first.json", first);
    write_file(dir / "second.json", second);
    // Each half keeps the original parameters: [0, 0.6] and [0.6, 1].
    const Json a = run_ok({"eval", (dir / "first.json").string(), "--samples", "31"});
    const Json b = run_ok({"eval", (dir / "second.json").string(), "--samples", "31"});
    EXPECT_EQ(a["parameters"].back().get<double>(), 0.6);
    EXPECT_EQ(b["parameters"].front().get<double>(), 0.6);
    std::vector<double> ta, tb;
    for (const Json& x : a["parameters"]) ta.push_back(x.get<double>());
    for (const Json& x : b["parameters"]) tb.push_back(x.get<double>());
    expect_same_points(a["points"], run_ok({"eval", file, "--at", joined(ta)})["points"], kRoundOff);
    expect_same_points(b["points"], run_ok({"eval", file, "--at", joined(tb)})["points"], kRoundOff);
  }
}

TEST(ToBezier, OnePiecePerKnotSpanMatchingTheCurve) {
  // The cubic example has interior knots 1/4, 1/2, 3/4: four spans; the circle
  // has four quarter arcs (rational: one-span bspline_curves with weights).
  for (const std::string& file : {kCubic, kCircle}) {
    const Json out = run_ok({"to-bezier", file});
    ASSERT_EQ(out["curves"].size(), 4u) << file;
    for (const Json& piece : out["curves"]) {
      ScratchDir dir("piece");
      write_file(dir / "piece.json", from_json(piece));
      const Json e = run_ok({"eval", (dir / "piece.json").string(), "--samples", "11"});
      std::vector<double> t;
      for (const Json& x : e["parameters"]) t.push_back(x.get<double>());
      expect_same_points(e["points"], run_ok({"eval", file, "--at", joined(t)})["points"], kRoundOff);
    }
  }
  EXPECT_EQ(run_ok({"to-bezier", kCubic})["curves"][0]["type"], "bezier_curve");
  EXPECT_EQ(run_ok({"to-bezier", kCircle})["curves"][0]["type"], "bspline_curve");
}

// ---- interpolate --------------------------------------------------------------------

struct Interpolated {
  Json curve;
  std::string file;
  std::vector<double> t;
};

Interpolated interpolate(const std::string& points, const std::string& method, const std::string& param,
                         const ScratchDir& dir) {
  Interpolated r;
  r.file = run_to_file({"interpolate", points, "--method", method, "--param", param}, dir, method + ".json");
  r.curve = Json::parse(testing::read_file(r.file));
  for (const Json& x : r.curve["parameters"]) r.t.push_back(x.get<double>());
  return r;
}

TEST(Interpolate, EveryMethodPassesThroughThePointsAtTheirParameters) {
  const PointsFile input = read_points(kClampedPoints);
  for (const std::string method : {"natural", "clamped", "periodic", "lagrange", "newton", "bezier"})
    for (const std::string param : {"uniform", "chordal", "centripetal", "foley", "nielson"}) {
      SCOPED_TRACE(method + " " + param);
      ScratchDir dir("interpolate");
      const Interpolated r = interpolate(kClampedPoints, method, param, dir);
      const std::size_t n = input.points.size();
      ASSERT_EQ(r.t.size(), method == "periodic" ? n + 1 : n);
      const Json e = run_ok({"eval", r.file, "--at", joined(r.t)});
      for (std::size_t i = 0; i < r.t.size(); ++i)
        expect_near(vec(e["points"][i]), input.points[i % n], kInterpolation, "point " + std::to_string(i));
      EXPECT_EQ(e["points"][0].size(), 2u);  // 2D in, 2D out
    }
}

TEST(Interpolate, UniformAndChordalParametersAreTheLecturesDefinitions) {
  // Ch. 1 §1.6: uniform t_i = i; chordal t_{i+1} - t_i = |P_{i+1} - P_i|.
  ScratchDir dir("params");
  const PointsFile input = read_points(kPoints);
  const Interpolated uniform = interpolate(kPoints, "natural", "uniform", dir);
  for (std::size_t i = 0; i < uniform.t.size(); ++i) EXPECT_EQ(uniform.t[i], static_cast<double>(i));
  const Interpolated chordal = interpolate(kPoints, "natural", "chordal", dir);
  double length = 0;
  for (std::size_t i = 0; i < chordal.t.size(); ++i) {
    if (i > 0) length += spline::norm(input.points[i] - input.points[i - 1]);
    EXPECT_NEAR(chordal.t[i], length, kRoundOff) << i;
  }
}

TEST(Interpolate, CubicSplinesAreC2CubicBsplinesWithTheEndConditions) {
  ScratchDir dir("ends");
  const PointsFile input = read_points(kClampedPoints);
  for (const std::string method : {"natural", "clamped", "periodic"}) {
    SCOPED_TRACE(method);
    const Interpolated r = interpolate(kClampedPoints, method, "chordal", dir);
    EXPECT_EQ(r.curve["type"], "bspline_curve");
    EXPECT_EQ(r.curve["degree"], 3);
    // Simple interior knots: C2 everywhere (The NURBS Book §2.5: C^{p-k} at a knot of multiplicity k).
    const std::vector<double> U = r.curve["knots"].get<std::vector<double>>();
    for (std::size_t i = 4; i + 4 < U.size(); ++i) EXPECT_LT(U[i - 1], U[i + 1]);
    const double t0 = r.t.front(), tn = r.t.back();
    const Json e = run_ok({"eval", r.file, "--at", joined({t0, tn}), "--derivatives", "2"});
    const Vec3 d1_start = vec(e["derivatives"][0][0]), d1_end = vec(e["derivatives"][0][1]);
    const Vec3 d2_start = vec(e["derivatives"][1][0]), d2_end = vec(e["derivatives"][1][1]);
    if (method == "natural") {
      expect_near(d2_start, {}, kInterpolation, "S''(t0)");
      expect_near(d2_end, {}, kInterpolation, "S''(tn)");
    } else if (method == "clamped") {
      expect_near(d1_start, *input.start_tangent, kInterpolation, "S'(t0)");
      expect_near(d1_end, *input.end_tangent, kInterpolation, "S'(tn)");
    } else {
      expect_near(vec(e["points"][0]), vec(e["points"][1]), kInterpolation, "closed");
      expect_near(d1_start, d1_end, kInterpolation, "S' closes");
      expect_near(d2_start, d2_end, kInterpolation, "S'' closes");
    }
  }
}

TEST(Interpolate, LagrangeNewtonAndBezierGiveTheSamePolynomial) {
  // The interpolating polynomial of degree n is unique (ch. 1 §1.6, Theorem 1).
  ScratchDir dir("polynomial");
  const Interpolated lagrange = interpolate(kPoints, "lagrange", "centripetal", dir);
  const Interpolated newton = interpolate(kPoints, "newton", "centripetal", dir);
  const Interpolated bezier = interpolate(kPoints, "bezier", "centripetal", dir);
  for (const Interpolated* r : {&lagrange, &newton, &bezier}) {
    EXPECT_EQ(r->curve["type"], "bezier_curve");
    EXPECT_EQ(r->curve["points"].size(), 5u);  // degree 4 through 5 points
    EXPECT_EQ(r->curve["interval"][0].get<double>(), r->t.front());
    EXPECT_EQ(r->curve["interval"][1].get<double>(), r->t.back());
  }
  expect_same_points(lagrange.curve["points"], bezier.curve["points"], kInterpolation);
  expect_same_points(newton.curve["points"], bezier.curve["points"], kInterpolation);
}

TEST(Interpolate, ThreeDimensionalPointsGiveAThreeDimensionalCurve) {
  ScratchDir dir("3d");
  std::ofstream(dir / "points.json") << R"({"points": [[0, 0, 0], [1, 2, 1], [3, 3, -1], [4, 1, 0]]})";
  const Interpolated r = interpolate((dir / "points.json").string(), "natural", "chordal", dir);
  for (const Json& p : r.curve["points"]) EXPECT_EQ(p.size(), 3u);
}

// ---- tessellate ----------------------------------------------------------------------

/// What an OBJ file holds (v, vn, f a//a, l).
struct Obj {
  std::vector<Vec3> v, vn;
  std::vector<std::array<int, 3>> f;  // 0-based
  std::vector<int> l;                 // 0-based
};

Obj read_obj(const fs::path& file) {
  Obj obj;
  std::istringstream in(testing::read_file(file));
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v" || tag == "vn") {
      Vec3 p;
      words >> p.x >> p.y >> p.z;
      (tag == "v" ? obj.v : obj.vn).push_back(p);
    } else if (tag == "f") {
      std::array<int, 3> face{};
      for (int& index : face) {
        std::string ref;
        words >> ref;
        const std::size_t slashes = ref.find("//");
        EXPECT_NE(slashes, std::string::npos) << line;
        EXPECT_EQ(ref.substr(0, slashes), ref.substr(slashes + 2)) << "vertex and normal index agree: " << line;
        index = std::stoi(ref) - 1;
      }
      obj.f.push_back(face);
    } else if (tag == "l") {
      for (int i; words >> i;) obj.l.push_back(i - 1);
    }
  }
  return obj;
}

TEST(Tessellate, CircleBecomesAPolylineWithinTheTolerance) {
  const double tolerance = 1e-3;
  ScratchDir dir("circle");
  const std::string obj_file = (dir / "circle.obj").string();
  const Json summary = run_ok({"tessellate", kCircle, "--tolerance", "0.001", "--obj", obj_file});
  EXPECT_EQ(summary["type"], "polyline");
  const Obj obj = read_obj(obj_file);
  ASSERT_EQ(obj.v.size(), summary["vertices"].get<std::size_t>());
  EXPECT_EQ(obj.l.size(), obj.v.size());
  // The vertices lie on the unit circle; each chord's midpoint is within the
  // tolerance of it (the chordal error of a circle peaks at the midpoint).
  for (std::size_t i = 0; i < obj.v.size(); ++i) {
    EXPECT_NEAR(spline::norm(obj.v[i]), 1.0, kRoundOff) << i;
    if (i > 0) {
      EXPECT_LE(1 - spline::norm((obj.v[i] + obj.v[i - 1]) / 2), tolerance) << i;
    }
  }
  // An inscribed polygon is shorter than the circle, but with sagitta <= tol
  // each chord keeps at least 1 - tol/3 of its arc (sin x / x >= 1 - x^2/6).
  const double length = summary["length"].get<double>();
  EXPECT_LE(length, 2 * kPi);
  EXPECT_GE(length, 2 * kPi * (1 - tolerance / 3));
}

TEST(Tessellate, SurfaceMeshHasUnitNormalsOnTheSideOfItsWinding) {
  ScratchDir dir("surface");
  const std::string obj_file = (dir / "surface.obj").string();
  const Json summary = run_ok({"tessellate", kSurface, "--tolerance", "0.01", "--obj", obj_file});
  EXPECT_EQ(summary["type"], "mesh");
  const Obj obj = read_obj(obj_file);
  ASSERT_EQ(obj.v.size(), summary["vertices"].get<std::size_t>());
  ASSERT_EQ(obj.vn.size(), obj.v.size());
  ASSERT_EQ(obj.f.size(), summary["triangles"].get<std::size_t>());
  for (const Vec3& n : obj.vn) EXPECT_NEAR(spline::norm(n), 1.0, kRoundOff);
  for (const auto& [a, b, c] : obj.f) {
    ASSERT_TRUE(a >= 0 && b >= 0 && c >= 0 && a < int(obj.v.size()) && b < int(obj.v.size()) && c < int(obj.v.size()));
    const Vec3 face = spline::cross(obj.v[b] - obj.v[a], obj.v[c] - obj.v[a]);
    EXPECT_GT(spline::dot(face, obj.vn[a] + obj.vn[b] + obj.vn[c]), 0) << "counter-clockwise seen from the normals";
  }
  // The example's control net spans [0, 4] x [0, 4]: so does the mesh.
  double max_x = 0, max_y = 0;
  for (const Vec3& p : obj.v) {
    max_x = std::max(max_x, p.x);
    max_y = std::max(max_y, p.y);
  }
  EXPECT_NEAR(max_x, 4, kRoundOff);
  EXPECT_NEAR(max_y, 4, kRoundOff);
}

TEST(Tessellate, TrimmedSurfaceLosesItsHole) {
  // The hole is the NURBS circle of radius 0.2 around (u, v) = (0.5, 0.5).
  // Its image on the surface, sampled by eval (not by the tessellator), is at
  // least `rim` from S(0.5, 0.5); no vertex may come closer than that (less a
  // margin for the sampling of the rim and the tolerance).
  std::string at = "0.5:0.5";
  for (int k = 0; k < 64; ++k)
    at += "," + joined({0.5 + 0.2 * std::cos(k * kPi / 32)}) + ":" + joined({0.5 + 0.2 * std::sin(k * kPi / 32)});
  const Json e = run_ok({"eval", kTrimmed, "--at", at});
  const Vec3 centre = vec(e["points"][0]);
  double rim = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < e["points"].size(); ++k) rim = std::min(rim, spline::norm(vec(e["points"][k]) - centre));

  ScratchDir dir("trimmed");
  const Json trimmed = run_ok({"tessellate", kTrimmed, "--tolerance", "0.001", "--obj", (dir / "t.obj").string()});
  const Obj obj = read_obj(dir / "t.obj");
  double closest = std::numeric_limits<double>::infinity();
  for (const Vec3& p : obj.v) closest = std::min(closest, spline::norm(p - centre));
  EXPECT_GE(closest, 0.95 * rim - 0.001);

  // Without its trims the same surface covers more area.
  BsplineSurface untrimmed = read_surface(kTrimmed);
  untrimmed.trims.clear();
  write_file(dir / "untrimmed.json", untrimmed);
  const Json full = run_ok({"tessellate", (dir / "untrimmed.json").string(), "--tolerance", "0.001"});
  EXPECT_LT(trimmed["area"].get<double>(), full["area"].get<double>());
  EXPECT_GT(trimmed["boundary_edges"].get<int>(), full["boundary_edges"].get<int>());  // the hole's rim
}

TEST(Tessellate, UnwritableObjExitsOneWithOneLine) {
  const ProcessResult r = splinetool({"tessellate", kCircle, "--tolerance", "0.01", "--obj", "/nonexistent-dir/c.obj"});
  EXPECT_EQ(r.exit_status, kFailed);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("/nonexistent-dir/c.obj"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace gllab::io
