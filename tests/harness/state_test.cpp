// tests/harness/state_test.cpp — the lab State and the shared command line.
// Expected values follow from the documented contracts in lab.h/options.h.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "harness/lab.h"
#include "harness/options.h"

namespace {

const auto kNoDraw = [](const gllab::State&) {};

gllab::State sample_state() {
  return gllab::State({{"default", "", kNoDraw}, {"wireframe", "", kNoDraw}, {"vertex_order", "", kNoDraw}},
                      {{"spin", 0, -180, 180, ""}, {"lighting", 1, 0, 1, ""}});
}

TEST(State, StartsOnTheFirstViewWithDefaults) {
  const gllab::State s = sample_state();
  EXPECT_EQ(s.view(), "default");
  EXPECT_EQ(s.get("spin"), 0);
  EXPECT_TRUE(s.flag("lighting"));
}

TEST(State, NextViewWrapsBothWays) {
  gllab::State s = sample_state();
  s.next_view(-1);
  EXPECT_EQ(s.view(), "vertex_order");
  s.next_view(+2);
  EXPECT_EQ(s.view(), "wireframe");
}

TEST(State, UnknownViewNamesItAndListsTheValidOnes) {
  gllab::State s = sample_state();
  try {
    s.select_view("wirefram");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "unknown view 'wirefram' (views: default, wireframe, vertex_order)");
  }
}

TEST(State, SetFromTextRejectsUnknownKeyMalformedAndOutOfRangeValues) {
  gllab::State s = sample_state();
  s.set_from_text("spin=-45.5");
  EXPECT_EQ(s.get("spin"), -45.5);
  EXPECT_THROW(s.set_from_text("spn=1"), std::invalid_argument);
  EXPECT_THROW(s.set_from_text("spin="), std::invalid_argument);
  EXPECT_THROW(s.set_from_text("spin=1x"), std::invalid_argument);
  EXPECT_THROW(s.set_from_text("spin=nan"), std::invalid_argument);
  EXPECT_THROW(s.set_from_text("=1"), std::invalid_argument);
  EXPECT_THROW(s.set_from_text("spin=180.5"), std::invalid_argument);
  EXPECT_EQ(s.get("spin"), -45.5) << "a rejected value leaves the old one";
}

TEST(State, StepClampsToTheRangeAndToggleFlips) {
  gllab::State s = sample_state();
  s.step("spin", 170);
  s.step("spin", 170);
  EXPECT_EQ(s.get("spin"), 180);
  s.toggle("lighting");
  EXPECT_FALSE(s.flag("lighting"));
}

TEST(State, ArgumentsReproduceTheState) {
  gllab::State s = sample_state();
  s.select_view("wireframe");
  s.set("spin", 30);
  EXPECT_EQ(s.as_arguments(), "--view wireframe --set spin=30");
}

TEST(Options, SizeParsesWxHWithinLimits) {
  int w = 0, h = 0;
  gllab::parse_size("640x480", w, h);
  EXPECT_EQ(w, 640);
  EXPECT_EQ(h, 480);
  for (const char* bad : {"", "x", "640", "640x", "x480", "-1x5", "0x5", "8193x1", "6 40x480", "1e3x5"})
    EXPECT_THROW(gllab::parse_size(bad, w, h), gllab::UsageError) << bad;
  gllab::parse_size("8192x1", w, h);  // kMaxSize is allowed
  EXPECT_EQ(w, gllab::kMaxSize);
}

TEST(Options, HeadlessNeedsOutUnlessListingOrHelping) {
  using gllab::Runner;
  EXPECT_THROW(gllab::parse_options({"--view", "default"}, Runner::kHeadless), gllab::UsageError);
  EXPECT_NO_THROW(gllab::parse_options({"--list-views"}, Runner::kHeadless));
  EXPECT_NO_THROW(gllab::parse_options({"--list-params"}, Runner::kHeadless));
  EXPECT_NO_THROW(gllab::parse_options({"--list-params"}, Runner::kWindow));
  EXPECT_NO_THROW(gllab::parse_options({"--view", "default"}, Runner::kWindow));
  EXPECT_THROW(gllab::parse_options({"--out", "x.png"}, Runner::kWindow), gllab::UsageError);
  EXPECT_THROW(gllab::parse_options({"--out", "dir/"}, Runner::kHeadless), gllab::UsageError);
}

// One program per lab: --headless, or an option only headless takes, picks the
// headless runner; the value of an option never does (--set out=... is a value).
TEST(Options, RunnerForPicksHeadlessByItsOptionsNotByValues) {
  using gllab::Runner;
  using gllab::runner_for;
  EXPECT_EQ(runner_for({}), Runner::kWindow);
  EXPECT_EQ(runner_for({"--view", "wireframe", "--set", "n=3"}), Runner::kWindow);
  EXPECT_EQ(runner_for({"--list-views"}), Runner::kWindow);
  EXPECT_EQ(runner_for({"--list-params"}), Runner::kWindow);  // both runners take it
  EXPECT_EQ(runner_for({"--list-params", "--headless"}), Runner::kHeadless);
  EXPECT_EQ(runner_for({"--help"}), Runner::kWindow);
  for (const char* headless : {"--headless", "--out", "--views", "--info", "--print-text", "--text-out"})
    EXPECT_EQ(runner_for({"--view", "default", headless}), Runner::kHeadless) << headless;
  EXPECT_EQ(runner_for({"--set", "--out"}), Runner::kWindow);
  EXPECT_EQ(runner_for({"--capture", "--headless"}), Runner::kWindow);  // a file named --headless
  EXPECT_EQ(runner_for({"--load", "--info", "--out", "x.png"}), Runner::kHeadless);
}

TEST(Options, AnOptionOfTheOtherRunnerIsNamedAsSuch) {
  using gllab::Runner;
  const auto message = [](const std::vector<std::string>& args, Runner runner) {
    try {
      gllab::parse_options(args, runner);
    } catch (const gllab::UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({"--headless", "--capture", "x.png"}, Runner::kHeadless),
            "--capture is a window option; it does not go with --headless or --out");
  EXPECT_EQ(message({"--frames", "5", "--out", "x.png"}, Runner::kHeadless),
            "--frames is a window option; it does not go with --headless or --out");
  EXPECT_EQ(message({"--out", "x.png"}, Runner::kWindow), "--out renders headless; it does not go with window options");
  EXPECT_TRUE(gllab::parse_options({"--headless", "--out", "x.png"}, Runner::kHeadless).out == "x.png");
}

TEST(ValidateLab, ReservedAndDuplicateKeysAreRejected) {
  gllab::Lab lab;
  lab.id = "test";
  lab.views = {{"default", "", kNoDraw}};
  lab.keyboard = [](gllab::State&, unsigned char) { return false; };
  lab.keys = {{'h', "mine"}};
  EXPECT_THROW(gllab::validate_lab(lab), std::logic_error);
  lab.keys = {{'a', "one"}, {'a', "two"}};
  EXPECT_THROW(gllab::validate_lab(lab), std::logic_error);
  lab.keys = {{'a', "one"}};
  EXPECT_NO_THROW(gllab::validate_lab(lab));
}

}  // namespace

// Keys that name a parameter: the runner steps or toggles it, clamped to the
// range as State::step promises; other keys reach the lab's keyboard().
TEST(ApplyKey, NamedParameterIsSteppedClampedOrToggled) {
  gllab::Lab lab;
  lab.id = "test";
  lab.views = {{"default", "", kNoDraw}};
  lab.params = {{"count", 4, 2, 6, ""}, {"labels", 1, 0, 1, ""}};
  int other = 0;
  lab.keyboard = [&](gllab::State&, unsigned char key) { return key == 'x' && ++other; };
  lab.keys = {{'+', "count +3", "count", +3}, {'n', "labels on/off", "labels"}, {'x', "other"}};
  ASSERT_NO_THROW(gllab::validate_lab(lab));
  gllab::State s(lab.views, lab.params);
  EXPECT_TRUE(gllab::apply_key(lab, s, '+'));
  EXPECT_EQ(s.get("count"), 6);  // 4 + 3 clamped to the range's top
  EXPECT_TRUE(gllab::apply_key(lab, s, 'n'));
  EXPECT_EQ(s.get("labels"), 0);
  EXPECT_TRUE(gllab::apply_key(lab, s, 'n'));
  EXPECT_EQ(s.get("labels"), 1);
  EXPECT_TRUE(gllab::apply_key(lab, s, 'x'));
  EXPECT_EQ(other, 1);
  EXPECT_FALSE(gllab::apply_key(lab, s, 'q'));  // nobody's key: no change
  EXPECT_EQ(s.as_arguments(), "--view default --set count=6");
}

TEST(ValidateLab, KeyWithUnknownParameterOrNoHandlerIsRejected) {
  gllab::Lab lab;
  lab.id = "test";
  lab.views = {{"default", "", kNoDraw}};
  lab.params = {{"count", 4, 2, 6, ""}};
  lab.keys = {{'+', "more", "cuont", +1}};
  EXPECT_THROW(gllab::validate_lab(lab), std::logic_error);
  lab.keys = {{'x', "does something"}};  // no parameter and no keyboard()
  EXPECT_THROW(gllab::validate_lab(lab), std::logic_error);
  lab.keys = {{'+', "more", "count", +1}};
  EXPECT_NO_THROW(gllab::validate_lab(lab));
}

// An error view (lab.h kErrorView) is marked in --list-views and
// --help, and may not be the first view: the window opens there.
TEST(ValidateLab, ErrorViewIsListedAsSuchAndCannotComeFirst) {
  gllab::Lab lab;
  lab.id = "test";
  lab.title = "test";
  lab.views = {{"default", "a picture", kNoDraw}, {"broken", "shows an error", kNoDraw, gllab::kErrorView}};
  ASSERT_NO_THROW(gllab::validate_lab(lab));
  EXPECT_EQ(gllab::list_views_text(lab), "default\nbroken expect_error\n");
  EXPECT_NE(gllab::views_text(lab).find("shows an error (error view: headless exits 1)"), std::string::npos);
  std::swap(lab.views[0], lab.views[1]);
  EXPECT_THROW(gllab::validate_lab(lab), std::logic_error);
}

// Views are declared with the function that draws them: a view without one,
// a misspelt same_as and a name that is not lower_snake_case are refused when
// the lab starts, naming the view.
TEST(ValidateLab, EveryViewNeedsItsDrawFunction) {
  gllab::Lab lab;
  lab.id = "test";
  lab.views = {{"default", "", kNoDraw}, {"outline", "", nullptr}};
  try {
    gllab::validate_lab(lab);
    FAIL() << "a view without a draw function passed";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "lab test: view 'outline' has no draw function");
  }
  lab.views[1].draw = kNoDraw;
  EXPECT_NO_THROW(gllab::validate_lab(lab));
  lab.views[1].same_as = "defualt";
  try {
    gllab::validate_lab(lab);
    FAIL() << "same_as naming no view passed";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "lab test: view 'outline' is the same as 'defualt', which is not another view");
  }
  lab.views[1].same_as = "outline";  // itself
  EXPECT_THROW(gllab::validate_lab(lab), std::logic_error);
  lab.views[1].same_as = "default";
  EXPECT_NO_THROW(gllab::validate_lab(lab));
  EXPECT_EQ(gllab::list_views_text(lab), "default\noutline same_as=default\n");
  lab.views[1].name = "Outline";
  EXPECT_THROW(gllab::validate_lab(lab), std::logic_error);
}

// --list-params (options.h): "param NAME DEFAULT LO HI" per Param, then
// "points LIST INDEX DIMENSION X Y Z" per point, in the lab's order.
TEST(ListParams, PrintsEveryParamThenEveryPointInOrder) {
  gllab::Lab lab;
  lab.views = {{"default", "", kNoDraw}};
  lab.params = {{"slices", 16, 3, 64, ""}, {"lighting", 1, 0, 1, ""}, {"t", 0.6, 0, 1, ""}};
  lab.points = {{"P", {{0, 0, 0}, {2, 4.5, 0}}, "", 2}, {"Q", {{-1, 0.25, 3}}, "", 3}};
  EXPECT_EQ(gllab::list_params_text(lab),
            "param slices 16 3 64\n"
            "param lighting 1 0 1\n"
            "param t 0.6 0 1\n"
            "points P 0 2 0 0 0\n"
            "points P 1 2 2 4.5 0\n"
            "points Q 0 3 -1 0.25 3\n");
  lab.params.clear();
  lab.points.clear();
  EXPECT_EQ(gllab::list_params_text(lab), "");  // a lab with nothing to vary
}

// Every printed number reads back as the same double, bit for bit, so that
// --set NAME=DEFAULT renders the default (values with no short decimal).
TEST(ListParams, NumbersReadBackExactly) {
  const std::vector<double> values = {1.0 / 3, 0.1 + 0.2, -2.0 / 7, 1e-5, 123456.789, 5e-324, -0.0};
  gllab::Lab lab;
  lab.views = {{"default", "", kNoDraw}};
  for (std::size_t i = 0; i < values.size(); ++i)
    lab.params.push_back({"p" + std::to_string(i), values[i], -1e6, 1e6, ""});
  lab.points = {{"P", {{values[0], values[1], values[2]}}, "", 3}};
  std::istringstream text(gllab::list_params_text(lab));
  std::vector<double> read;
  for (std::string line; std::getline(text, line);) {
    std::istringstream fields(line);
    std::string kind, name, field;
    fields >> kind >> name;
    if (kind == "points") fields >> field >> field;  // INDEX DIMENSION
    while (fields >> field) read.push_back(std::strtod(field.c_str(), nullptr));
  }
  std::vector<double> expected;
  for (double v : values) expected.insert(expected.end(), {v, -1e6, 1e6});
  expected.insert(expected.end(), {values[0], values[1], values[2]});
  ASSERT_EQ(read.size(), expected.size());
  for (std::size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(read[i], expected[i]) << i;
    EXPECT_EQ(std::signbit(read[i]), std::signbit(expected[i])) << i;
  }
}

// Both listings in one run print the views, then the params.
TEST(ListParams, WithListViewsPrintsBothInOrder) {
  gllab::Lab lab;
  lab.views = {{"default", "", kNoDraw}};
  lab.params = {{"n", 2, 1, 5, ""}};
  const auto listing = [&](const std::vector<std::string>& args) {
    return gllab::listing_text(lab, gllab::parse_options(args, gllab::Runner::kWindow));
  };
  EXPECT_EQ(listing({"--list-params"}), "param n 2 1 5\n");
  EXPECT_EQ(listing({"--list-views"}), "default\n");
  EXPECT_EQ(listing({"--list-params", "--list-views"}), "default\nparam n 2 1 5\n");
}

// The orbit camera: --camera yaw,pitch,zoom sets it, and the arguments that
// reproduce a state carry it only when it is not the default (so the printed
// command of an untouched view is what it was before there was a camera).
TEST(Camera, TextIsParsedCheckedAndPrintedBack) {
  gllab::State s = sample_state();
  EXPECT_EQ(s.as_arguments(), "--view default");
  s.set_camera_from_text("20,-7.5,1.25");
  EXPECT_EQ(s.camera.yaw, 20);
  EXPECT_EQ(s.camera.pitch, -7.5);
  EXPECT_EQ(s.camera.zoom, 1.25);
  EXPECT_EQ(s.as_arguments(), "--view default --camera 20,-7.5,1.25");
  const auto message = [&](const std::string& text) {
    try {
      s.set_camera_from_text(text);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("20,10"), "malformed --camera '20,10': 2 numbers (expected yaw,pitch,zoom, e.g. 30,-15,1.5)");
  EXPECT_EQ(message("20,x,1"), "malformed --camera '20,x,1': 'x' is not a number (expected yaw,pitch,zoom, e.g. 30,-15,1.5)");
  EXPECT_EQ(message("0,0,50"), "--camera '0,0,50': zoom 50 is out of range [0.1, 20]");
  EXPECT_EQ(message("nan,0,1"), "malformed --camera 'nan,0,1': 'nan' is not a number (expected yaw,pitch,zoom, e.g. 30,-15,1.5)");
  EXPECT_EQ(s.as_arguments(), "--view default --camera 20,-7.5,1.25");  // a refused text changes nothing
}

// --print-text is the headless runner's: the window has no stdout to read.
TEST(Options, PrintTextIsHeadlessOnly) {
  using gllab::Runner;
  EXPECT_TRUE(gllab::parse_options({"--print-text", "--out", "x.png"}, Runner::kHeadless).print_text);
  EXPECT_THROW(gllab::parse_options({"--print-text"}, Runner::kWindow), gllab::UsageError);
}

// --frames N times the window (the labs' README figures): a whole number in
// 1..kMaxFrames, the window runner's only.
TEST(Options, FramesIsAWholeNumberForTheWindowOnly) {
  using gllab::Runner;
  EXPECT_EQ(gllab::parse_options({"--frames", "20"}, Runner::kWindow).frames, 20);
  EXPECT_EQ(gllab::parse_options({"--frames", "100000"}, Runner::kWindow).frames, gllab::kMaxFrames);
  for (const char* bad : {"0", "-3", "2.5", "", "x", "100001", " 5", "5 ", "+5", "1e3"}) {
    try {
      gllab::parse_options({"--frames", bad}, Runner::kWindow);
      ADD_FAILURE() << "accepted --frames '" << bad << "'";
    } catch (const gllab::UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("--frames '" + std::string(bad) + "'"), std::string::npos)
          << e.what();
    }
  }
  EXPECT_THROW(gllab::parse_options({"--frames", "5", "--out", "x.png"}, Runner::kHeadless),
               gllab::UsageError);
}
