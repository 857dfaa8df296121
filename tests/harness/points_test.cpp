// tests/harness/points_test.cpp — point lists in the State (lab.h) and the
// lab's curve saved and loaded as a spline file (model_file.h). Expected
// values follow from the documented contracts there: --set P[i]=x,y moves one
// point, as_arguments() prints what moved so that parsing it gives the same
// State, and --load accepts only a file the lab can reproduce.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include "harness/lab.h"
#include "harness/model_file.h"
#include "harness/options.h"
#include "io/spline_json.h"
#include "spline/bspline.h"

namespace {

using gllab::spline::Vec3;

// What(): the message of the std::invalid_argument that f throws ("" if none).
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// A lab editing a clamped B-spline curve of degree `degree` through the 2D
// points P (lab data: four points and a 3D list H for other tests).
gllab::Lab curve_lab() {
  gllab::Lab lab;
  lab.id = "99_test_curve";
  lab.title = "test";
  lab.views = {{"default", "", [](const gllab::State&) {}}, {"other", "", [](const gllab::State&) {}}};
  lab.params = {{"degree", 2, 1, 3, ""}, {"weight", 1, 0.5, 4, ""}};
  lab.points = {{"P", {{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}}, "control points"},
                {"H", {{0, 0, 1}}, "a 3D handle", 3}};
  lab.model = [](const gllab::State& s) -> gllab::Model {
    gllab::spline::BsplineCurve c = gllab::spline::clamped_curve(s.points("P"), s.integer("degree"), 2);
    if (s.get("weight") != 1) c.w = {1, s.get("weight"), 1, 1};
    return c;
  };
  return lab;
}

gllab::State state_of(const gllab::Lab& lab) { return gllab::State(lab.views, lab.params, lab.points); }

TEST(PointList, SetMovesOnePointAndKeepsZOfA2dList) {
  const gllab::Lab lab = curve_lab();
  gllab::State s = state_of(lab);
  s.set_from_text("P[2]=2.5,-1");
  EXPECT_EQ(s.points("P")[2], (Vec3{2.5, -1, 0}));
  s.set_from_text("H[0]=1,2,3");
  EXPECT_EQ(s.points("H")[0], (Vec3{1, 2, 3}));
  s.set_from_text("H[0]=4,5");  // two coordinates: z stays
  EXPECT_EQ(s.points("H")[0], (Vec3{4, 5, 3}));
}

TEST(PointList, BadAssignmentsNameTheValue) {
  const gllab::Lab lab = curve_lab();
  gllab::State s = state_of(lab);
  EXPECT_EQ(error_of([&] { s.set_from_text("P[4]=1,2"); }), "point P[4] does not exist (P has points 0..3)");
  EXPECT_EQ(error_of([&] { s.set_from_text("Q[0]=1,2"); }), "unknown point list 'Q' (point lists: P, H)");
  EXPECT_EQ(error_of([&] { s.set_from_text("P[1]=1,x"); }), "malformed --set 'P[1]=1,x': 'x' is not a number");
  EXPECT_EQ(error_of([&] { s.set_from_text("P[1]=1"); }),
            "malformed --set 'P[1]=1': 1 coordinates (expected x,y or x,y,z)");
  EXPECT_EQ(error_of([&] { s.set_from_text("P[1]=1,2,3,4"); }),
            "malformed --set 'P[1]=1,2,3,4': 4 coordinates (expected x,y or x,y,z)");
  EXPECT_EQ(error_of([&] { s.set_from_text("P[-1]=1,2"); }), "malformed --set 'P[-1]=1,2' (expected P[i]=x,y)");
  EXPECT_EQ(error_of([&] { s.set_from_text("P[1=1,2"); }), "malformed --set 'P[1=1,2' (expected P[i]=x,y)");
  EXPECT_EQ(error_of([&] { s.set_from_text("P[1]=1,inf"); }), "malformed --set 'P[1]=1,inf': 'inf' is not a number");
  // Nothing moved.
  EXPECT_EQ(s.points("P"), curve_lab().points[0].points);
}

// Property: any point the window can produce (snap_to_grid) prints as a
// --set line that parses back to the same double, bit for bit.
TEST(PointList, ArgumentsReproduceDraggedPointsExactly) {
  const gllab::Lab lab = curve_lab();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> where(-2000, 2000);  // lab units, as a mouse drag gives them
  for (int trial = 0; trial < 200; ++trial) {
    gllab::State s = state_of(lab);
    const Vec3 p{gllab::snap_to_grid(where(random)), gllab::snap_to_grid(where(random)), 0};
    const Vec3 h{gllab::snap_to_grid(where(random)), gllab::snap_to_grid(where(random)),
                 gllab::snap_to_grid(where(random))};
    s.move_point("P", 1, p);
    s.move_point("H", 0, h);
    s.select_view("other");
    // "--view other --set P[1]=x,y --set H[0]=x,y,z": split and parse again.
    std::vector<std::string> args;
    std::string word, text = s.as_arguments();
    for (char c : text + ' ')
      if (c == ' ') args.push_back(word), word.clear();
      else word += c;
    ASSERT_EQ(args.size(), 6u) << text;
    const gllab::State again = gllab::make_state(lab, gllab::parse_options(args, gllab::Runner::kWindow));
    EXPECT_EQ(again.points("P")[1], p) << text;
    EXPECT_EQ(again.points("H")[0], h) << text;
    EXPECT_EQ(again.view(), "other");
  }
}

TEST(PointList, UnmovedPointsAreNotPrinted) {
  const gllab::Lab lab = curve_lab();
  gllab::State s = state_of(lab);
  EXPECT_EQ(s.as_arguments(), "--view default");
  s.move_point("P", 3, {4.5, 0, 0});
  EXPECT_EQ(s.as_arguments(), "--view default --set P[3]=4.5,0");
  s.move_point("P", 3, {4, 0, 0});  // back where it was
  EXPECT_EQ(s.as_arguments(), "--view default");
}

TEST(ValidateLab, PointListsNeedUniqueNamesAndPoints) {
  gllab::Lab lab = curve_lab();
  EXPECT_NO_THROW(gllab::validate_lab(lab));
  lab.points[1].name = "P";
  EXPECT_THROW(gllab::validate_lab(lab), std::logic_error);
  lab = curve_lab();
  lab.points[1].name = "degree";  // a parameter's name
  EXPECT_THROW(gllab::validate_lab(lab), std::logic_error);
  lab = curve_lab();
  lab.points[1].points.clear();
  EXPECT_THROW(gllab::validate_lab(lab), std::logic_error);
  lab = curve_lab();
  lab.points[0].name = "P[0]";
  EXPECT_THROW(gllab::validate_lab(lab), std::logic_error);
}

// ---- model files ---------------------------------------------------------------

class ModelFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("gllab_model_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

TEST_F(ModelFile, SavedCurveIsTheLabsCurveInTheCoreFormat) {
  const gllab::Lab lab = curve_lab();
  gllab::State s = state_of(lab);
  s.set_from_text("degree=3");
  s.move_point("P", 1, {1.25, 2.5, 0});
  EXPECT_EQ(gllab::model_file_name(lab, s), "99_test_curve__default.json");
  gllab::save_model(lab, s, path("c.json"));
  // Read back with the core's reader: the clamped cubic on 4 points is one
  // Bézier segment, knots 0 0 0 0 1 1 1 1 (clamped_uniform_knots).
  const gllab::spline::BsplineCurve c = gllab::io::read_curve(path("c.json"));
  EXPECT_EQ(c.p, 3);
  EXPECT_EQ(c.U, (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(c.P[1], (Vec3{1.25, 2.5, 0}));
  EXPECT_EQ(c.dimension, 2);
}

TEST_F(ModelFile, LoadPutsTheFilesPointsBack) {
  const gllab::Lab lab = curve_lab();
  gllab::State saved = state_of(lab);
  saved.set_from_text("weight=2");
  saved.move_point("P", 2, {3.5, 2.75, 0});
  gllab::save_model(lab, saved, path("c.json"));

  gllab::Options options = gllab::parse_options({"--set", "weight=2", "--load", path("c.json")},
                                                gllab::Runner::kWindow);
  const gllab::State loaded = gllab::make_state(lab, options);
  EXPECT_EQ(loaded.points("P"), saved.points("P"));
  EXPECT_EQ(loaded.as_arguments(), saved.as_arguments());
}

TEST_F(ModelFile, LoadRejectsWhatTheLabCannotReproduce) {
  const gllab::Lab lab = curve_lab();
  gllab::State saved = state_of(lab);
  saved.set_from_text("weight=2");
  gllab::save_model(lab, saved, path("c.json"));
  auto load_with = [&](std::vector<std::string> args) {
    args.push_back("--load");
    args.push_back(path("c.json"));
    return error_of([&] { gllab::make_state(lab, gllab::parse_options(args, gllab::Runner::kWindow)); });
  };
  // Saved with weight=2, loaded without: the weights differ (w[1] = 2 vs none).
  EXPECT_EQ(load_with({}), path("c.json") +
                               ": the file has 4 weights, the lab 0 (give --load the --set values it was saved with)");
  EXPECT_EQ(load_with({"--set", "weight=3"}),
            path("c.json") + ": weights[1] is 2 in the file, 3 in the lab (give --load the --set values it was saved with)");
  EXPECT_EQ(load_with({"--set", "weight=2", "--set", "degree=3"}),
            path("c.json") + ": degree is 2 in the file, 3 in the lab (give --load the --set values it was saved with)");

  // Another number of points, another kind of object, a broken file.
  gllab::spline::BsplineCurve five = gllab::spline::clamped_curve({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}, {4, 0, 0}}, 2, 2);
  gllab::io::write_file(path("five.json"), five);
  EXPECT_EQ(error_of([&] {
              gllab::make_state(lab, gllab::parse_options({"--load", path("five.json")}, gllab::Runner::kWindow));
            }),
            path("five.json") + ": 5 points for P, which has 4 (give --load the --set values it was saved with)");
  gllab::spline::BezierCurve bezier;
  bezier.P = {{0, 0, 0}, {1, 1, 0}};
  gllab::io::write_file(path("bezier.json"), bezier);
  EXPECT_EQ(error_of([&] {
              gllab::make_state(lab, gllab::parse_options({"--load", path("bezier.json")}, gllab::Runner::kWindow));
            }),
            path("bezier.json") + ": a bezier_curve, but lab 99_test_curve edits a bspline_curve");
  std::FILE* f = std::fopen(path("broken.json").c_str(), "w");
  std::fputs("{\"type\": \"bspline_curve\", \"degree\": 2,", f);
  std::fclose(f);
  EXPECT_THROW(gllab::make_state(lab, gllab::parse_options({"--load", path("broken.json")}, gllab::Runner::kWindow)),
               gllab::UsageError);
}

TEST(ModelFileLab, LabWithoutAModelSaysSo) {
  gllab::Lab lab = curve_lab();
  lab.model = nullptr;
  EXPECT_EQ(error_of([&] { gllab::save_model(lab, state_of(lab), "x.json"); }),
            "lab 99_test_curve has no curve or surface to save or load");
  EXPECT_EQ(gllab::model_noun(lab), "");
  EXPECT_EQ(gllab::model_noun(curve_lab()), "curve");
}

}  // namespace

namespace {

// A key's step prints as the decimal a student expects and reads back as
// the same double (lab.h: as_arguments reproduces the state exactly).
TEST(State, SteppedParametersPrintShortAndReadBackExactly) {
  gllab::Lab lab = curve_lab();
  lab.params = {{"t", 0.6, 0, 1, ""}};
  gllab::State s(lab.views, lab.params, lab.points);
  for (int k = 0; k < 7; ++k) s.step("t", -0.05);  // 0.6 - 7 x 0.05 = 0.25
  EXPECT_EQ(s.as_arguments(), "--view default --set t=0.25");
  s.step("t", +0.05 / 3);                           // 0.26666666666666666...
  const std::string args = s.as_arguments();
  EXPECT_EQ(args, "--view default --set t=0.266666666667");
  const gllab::State again =
      gllab::make_state(lab, gllab::parse_options({"--set", args.substr(args.rfind(' ') + 1)}, gllab::Runner::kWindow));
  EXPECT_EQ(again.get("t"), s.get("t"));  // bit for bit
}

}  // namespace
