// tests/grading/hidden_inputs_test.cpp — labgrade's hidden inputs
// (tools/hidden_inputs.h): the draws follow the rules of its header, are the
// same for the same seed on any standard library, and a real lab renders them.
#include "hidden_inputs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "grading.h"
#include "image/image.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using gllab::run_process;
using gllab::grading::hidden_sets;
using gllab::grading::LabInputs;
using gllab::grading::parse_lab_inputs;
using gllab::testing::kBinDir;
using gllab::testing::ScratchDir;

// What a lab prints for --list-params (harness/options.h): a switch, a count,
// a continuous parameter, a 2D list of three points and a 3D list of one.
const std::string kListing =
    "param lighting 1 0 1\n"
    "param slices 16 3 64\n"
    "param t 0.6 0 1\n"
    "points P 0 2 0 0 0\n"
    "points P 1 2 2 4.5 0.25\n"
    "points P 2 2 4 1 0\n"
    "points S 0 3 0.3 -0.2 1\n";
const std::string kLab = "12_bezier_curves";
constexpr int kManyDraws = 2000;  // enough to reach both ends of every small range

// "name=value" or "P[2]=x,y[,z]" split into the name and its numbers.
struct Assignment {
  std::string name;
  std::vector<std::string> texts;
  std::vector<double> values;
};
Assignment split(const std::string& set) {
  Assignment a;
  const auto eq = set.find('=');
  a.name = set.substr(0, eq);
  std::stringstream in(set.substr(eq + 1));
  for (std::string part; std::getline(in, part, ',');) {
    char* end = nullptr;
    a.values.push_back(std::strtod(part.c_str(), &end));
    EXPECT_EQ(*end, '\0') << set;
    a.texts.push_back(part);
  }
  return a;
}

// On the 1/1000 grid, as snap_to_grid (harness/lab.h) leaves a value, and
// printed with at most 3 decimals.
bool on_grid(double v, const std::string& text) {
  const auto dot = text.find('.');
  return std::round(v * 1000) / 1000 == v && (dot == std::string::npos || text.size() - dot - 1 <= 3);
}

std::string message_of(const std::string& text) {
  try {
    parse_lab_inputs(text, "lab");
  } catch (const gllab::grading::UsageError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ParseLabInputs, ReadsParamsAndPointsInOrder) {
  const LabInputs in = parse_lab_inputs(kListing, kLab);
  ASSERT_EQ(in.params.size(), 3u);
  EXPECT_EQ(in.params[1].name, "slices");
  EXPECT_EQ(in.params[1].value, 16);
  EXPECT_EQ(in.params[1].lo, 3);
  EXPECT_EQ(in.params[1].hi, 64);
  EXPECT_TRUE(in.params[0].is_switch());
  EXPECT_TRUE(in.params[1].is_integer());
  EXPECT_FALSE(in.params[1].is_switch());
  EXPECT_FALSE(in.params[2].is_integer());
  ASSERT_EQ(in.points.size(), 4u);
  EXPECT_EQ(in.points[1].list, "P");
  EXPECT_EQ(in.points[1].index, 1u);
  EXPECT_EQ(in.points[1].dimension, 2);
  EXPECT_EQ(in.points[1].y, 4.5);
  EXPECT_EQ(in.points[1].z, 0.25);
  EXPECT_EQ(in.points[3].dimension, 3);
  EXPECT_TRUE(parse_lab_inputs("", kLab).params.empty());  // a lab with nothing to vary
}

// Every malformed line is refused with one message naming the lab, the line
// number, the line and what was expected.
TEST(ParseLabInputs, MalformedLinesAreRejectedNamingTheLine) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"param t 0.6 0\n", "lab --list-params, line 1 'param t 0.6 0': expected param NAME DEFAULT LO HI"},
      {"param t 0.6 0 1\nparm u 1 0 2\n",
       "line 2 'parm u 1 0 2': expected param NAME DEFAULT LO HI or points"},
      {"param t x 0 1\n", "line 1 'param t x 0 1': 'x' is not a decimal number"},
      {"param t nan 0 1\n", "'nan' is not a decimal number"},
      {"param t 1e300 0 1e301\n", "'1e300' is not a decimal number of magnitude at most 1e12"},
      {"param t 0.5 1 0\n", "line 1 'param t 0.5 1 0': lo 1 is above hi 0"},
      {"param t 2 0 1\n", "the default 2 is outside [lo, hi]"},
      {"param t=1 0 0 1\n", "'t=1' is not a parameter name"},
      {"param t 0 0 1\nparam t 1 0 1\n", "line 2 'param t 1 0 1': parameter 't' is listed twice"},
      {"points P 0 2 0 0\n", "expected points LIST INDEX DIMENSION X Y Z"},
      {"points P[0] 0 2 0 0 0\n", "'P[0]' is not a point list name"},
      {"points P 1 2 0 0 0\n", "line 1 'points P 1 2 0 0 0': expected point P[0], not [1]"},
      {"points P 0 2 0 0 0\npoints P 2 2 0 0 0\n",
       "line 2 'points P 2 2 0 0 0': expected point P[1], not [2]"},
      {"points P 0 4 0 0 0\n", "dimension '4' is neither 2 nor 3"},
      {"points P 0 2 0 0 0\npoints P 1 3 0 0 0\n", "dimension 3 differs from the list's 2"},
      {"points P 0 2 0 0 0\npoints Q 0 2 0 0 0\npoints P 1 2 0 0 0\n",
       "line 3 'points P 1 2 0 0 0': the points of list 'P' are not together"},
      {"points P -1 2 0 0 0\n", "'-1' is not a point index"},
  };
  for (const auto& [text, expected] : cases)
    EXPECT_NE(message_of(text).find(expected), std::string::npos) << text << "\ngot: " << message_of(text);
  EXPECT_NE(message_of("param " + std::string(200, 'a') + "\n").find("aaa...': expected"), std::string::npos)
      << "a long line is shortened in the message";
}

// The numbers behind the draws are fixed by standards, not by a library:
// mt19937_64's 10000th output of a default-constructed engine is
// 9981545732273789042 (C++17 [rand.predef] p6); FNV-1a 64 of "" and "a" are
// the offset basis and 0xaf63dc4c8601ec8c (the FNV reference test vectors).
TEST(HiddenSets, TheirNumbersAreFixedByStandards) {
  std::mt19937_64 engine;
  engine.discard(9999);
  EXPECT_EQ(engine(), 9981545732273789042ull);
  EXPECT_EQ(gllab::grading::lab_seed("", 0), 0xcbf29ce484222325ull);
  EXPECT_EQ(gllab::grading::lab_seed("a", 0), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(gllab::grading::lab_seed("a", 0xff), 0xaf63dc4c8601ec8cull ^ 0xff);
  EXPECT_EQ(gllab::grading::unit_interval(0), 0.0);
  EXPECT_EQ(gllab::grading::unit_interval(std::uint64_t{1} << 63), 0.5);
  EXPECT_EQ(gllab::grading::unit_interval(~std::uint64_t{0}), 1 - 0x1.0p-53);  // never 1
}

// The draws of kListing with seed 1, as this implementation printed them
// (GCC 12, libstdc++): they follow from the standard's generator and FNV-1a
// alone, so every compiler and standard library must print the same.
TEST(HiddenSets, SeedOneGivesTheseDrawsEverywhere) {
  const std::vector<std::vector<std::string>> expected = {
      {"lighting=1", "slices=45", "t=0.964", "P[0]=0.167,0.055", "P[1]=1.976,4.526", "P[2]=3.998,1.206",
       "S[0]=0.307,-0.192,0.973"},
      {"lighting=1", "slices=5", "t=0.422", "P[0]=-0.209,0.223", "P[1]=2.176,4.656", "P[2]=4.159,1.154",
       "S[0]=0.285,-0.173,0.971"},
  };
  EXPECT_EQ(hidden_sets(parse_lab_inputs(kListing, kLab), kLab, 2, 1), expected);
}

TEST(HiddenSets, SameSeedGivesSameDrawsAndAnotherSeedOthers) {
  const LabInputs in = parse_lab_inputs(kListing, kLab);
  const auto draws = hidden_sets(in, kLab, 5, 42);
  ASSERT_EQ(draws.size(), 5u);
  EXPECT_EQ(hidden_sets(in, kLab, 5, 42), draws);
  EXPECT_NE(hidden_sets(in, kLab, 5, 43), draws);
  EXPECT_NE(hidden_sets(in, kLab, 5, 0), draws);
  // Fewer draws are the first of more: the nth draw does not depend on n.
  const auto three = hidden_sets(in, kLab, 3, 42);
  EXPECT_EQ(three, decltype(three)(draws.begin(), draws.begin() + 3));
  // The draws of one seed differ from one another.
  EXPECT_EQ(std::set<std::vector<std::string>>(draws.begin(), draws.end()).size(), draws.size());
  EXPECT_TRUE(hidden_sets(in, kLab, 0, 42).empty());
  EXPECT_THROW(hidden_sets(in, kLab, -1, 42), gllab::grading::UsageError);
}

// A lab's generator is seeded from the seed and its own name: its draws are
// the same whether it is graded alone or with others, and two labs with the
// same inputs get different draws.
TEST(HiddenSets, ALabsDrawsDoNotChangeWhenAnotherLabIsAdded) {
  const LabInputs in = parse_lab_inputs(kListing, kLab);
  const LabInputs other = parse_lab_inputs("param n 3 1 9\npoints Q 0 3 1 2 3\n", "13_cubic_splines");
  const auto alone = hidden_sets(in, kLab, 4, 7);
  // Graded in a class of two, the other lab drawn first.
  std::map<std::string, std::vector<std::vector<std::string>>> graded;
  graded["13_cubic_splines"] = hidden_sets(other, "13_cubic_splines", 4, 7);
  graded[kLab] = hidden_sets(in, kLab, 4, 7);
  EXPECT_EQ(graded[kLab], alone);
  EXPECT_NE(hidden_sets(in, "13_cubic_splines", 4, 7), alone);
}

// Every value is one the lab accepts: inside its range, a switch 0 or 1, a
// whole-number param whole, any other on the 1/1000 grid; every point moved
// by at most 5% of its list's extent (and the half grid step of the snap) in
// the coordinates it is dragged in. Each draw varies everything.
TEST(HiddenSets, ValuesStayInTheirRangesAndOnTheGrid) {
  const LabInputs in = parse_lab_inputs(kListing, kLab);
  // Extents: P's box in x, y is 4 wide and 4.5 high; S has one point: kMinExtent.
  const std::map<std::string, double> reach = {{"P", 0.05 * 4.5}, {"S", 0.05 * 1}};
  constexpr double kHalfGridStep = 0.0005;
  std::map<std::string, std::set<double>> seen;
  for (const auto& draw : hidden_sets(in, kLab, kManyDraws, 2024)) {
    ASSERT_EQ(draw.size(), in.params.size() + in.points.size());
    for (std::size_t i = 0; i < in.params.size(); ++i) {
      const auto& p = in.params[i];
      const Assignment a = split(draw[i]);
      ASSERT_EQ(a.name, p.name);
      ASSERT_EQ(a.values.size(), 1u) << draw[i];
      const double v = a.values[0];
      EXPECT_GE(v, p.lo) << draw[i];
      EXPECT_LE(v, p.hi) << draw[i];
      if (p.is_switch())
        EXPECT_TRUE(a.texts[0] == "0" || a.texts[0] == "1") << draw[i];
      else if (p.is_integer())
        EXPECT_EQ(a.texts[0].find_first_not_of("-0123456789"), std::string::npos) << draw[i];
      else
        EXPECT_TRUE(on_grid(v, a.texts[0])) << draw[i];
      seen[p.name].insert(v);
    }
    for (std::size_t i = 0; i < in.points.size(); ++i) {
      const auto& p = in.points[i];
      const Assignment a = split(draw[in.params.size() + i]);
      ASSERT_EQ(a.name, p.list + "[" + std::to_string(p.index) + "]");
      ASSERT_EQ(a.values.size(), static_cast<std::size_t>(p.dimension)) << "x,y for 2D, x,y,z for 3D";
      const double defaults[] = {p.x, p.y, p.z};
      for (std::size_t c = 0; c < a.values.size(); ++c) {
        EXPECT_TRUE(on_grid(a.values[c], a.texts[c])) << draw[in.params.size() + i];
        EXPECT_LE(std::abs(a.values[c] - defaults[c]), reach.at(p.list) + kHalfGridStep) << a.name;
        seen[a.name + std::to_string(c)].insert(a.values[c]);
      }
    }
  }
  EXPECT_EQ(seen["lighting"], (std::set<double>{0, 1}));
  EXPECT_EQ(seen["slices"].size(), 62u) << "every whole number in [3, 64]";
  EXPECT_EQ(*seen["slices"].begin(), 3);
  EXPECT_EQ(*seen["slices"].rbegin(), 64);
  // t: 2000 uniform draws over the 1001 multiples of 0.001 in [0, 1] reach
  // about 1001 * (1 - e^-2) = 866 of them.
  EXPECT_GT(seen["t"].size(), 700u) << "t takes many values";
  for (const auto& [name, values] : seen) EXPECT_GT(values.size(), 1u) << name << " never varies";
}

// A range with no multiple of 0.001 keeps its default; a range narrower
// than the grid but holding one multiple gets it, never a value outside.
TEST(HiddenSets, RangesOffTheGridStayInside) {
  const LabInputs in =
      parse_lab_inputs("param a 0.00015 0.0001 0.0002\nparam b 0.001 0.0005 0.0015\n", "lab");
  for (const auto& draw : hidden_sets(in, "lab", 50, 3)) {
    EXPECT_EQ(draw[0], "a=0.00015");
    EXPECT_EQ(draw[1], "b=0.001");
  }
}

// --- a real lab ---------------------------------------------------------------

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Lab 12 has params (a switch, counts, t) and a 2D point list: its
// --list-params gives inputs, three draws of seed 1 render its first view
// (exit 0), and each picture differs from the default one.
TEST(HiddenSets, ARealLabRendersThreeDrawsThatDifferFromTheDefault) {
  const std::string program = (kBinDir / kLab).string();
  const gllab::ProcessResult list = run_process({program, "--list-params"});
  ASSERT_EQ(list.exit_status, 0) << list.err;
  const LabInputs in = parse_lab_inputs(list.out, kLab);
  ASSERT_FALSE(in.params.empty());
  ASSERT_FALSE(in.points.empty());
  const gllab::ProcessResult views = run_process({program, "--list-views"});
  ASSERT_EQ(views.exit_status, 0) << views.err;
  const std::string view = lines_of(views.out).at(0);

  ScratchDir dir("hidden");
  const auto render = [&](const std::vector<std::string>& sets, const std::string& name) {
    std::vector<std::string> argv = {program, "--headless", "--view", view, "--out", (dir / name).string()};
    for (const std::string& set : sets) argv.insert(argv.end(), {"--set", set});
    const gllab::ProcessResult r = run_process(argv);
    EXPECT_EQ(r.exit_status, 0) << name << ": " << r.err;
    return gllab::read_png((dir / name).string());
  };
  const gllab::Image plain = render({}, "default.png");
  const auto draws = hidden_sets(in, kLab, 3, 1);
  ASSERT_EQ(draws.size(), 3u);
  for (std::size_t i = 0; i < draws.size(); ++i) {
    const gllab::Image drawn = render(draws[i], "hidden" + std::to_string(i) + ".png");
    EXPECT_EQ(drawn.width, plain.width);
    EXPECT_TRUE(drawn.rgba != plain.rgba) << "draw " << i << " renders the default picture";
  }
}

}  // namespace
