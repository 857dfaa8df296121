// tests/grading/labgrade_test.cpp — labgrade's promises (tools/labgrade.cpp
// --help and README "Grading"): every view the references define is graded;
// a missing render, a crash, a GL error or a hang is a failing row with its
// reason, never a skip; exit 0 all pass, 1 some fail, 2 usage or input error;
// the report, results.json, results.csv and the class CSV say the same.
#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <iterator>
#include <sstream>

#include <nlohmann/json.hpp>

#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using gllab::run_process;
using gllab::testing::kBinDir;
using gllab::testing::kSourceDir;
using gllab::testing::line_count;
using gllab::testing::ScratchDir;

constexpr int kSomeFailed = 1;  // labgrade --help: "1 some failed"
constexpr int kUsage = 2;       // labgrade --help: "2 usage or input error"

const std::string kLab = "01_immediate_mode";
const std::vector<std::string> kViews = {"default", "invalid_polygons", "vertex_order", "wireframe"};
const fs::path kRefs = kSourceDir / "reference_images";

std::string labgrade() { return (kBinDir / "labgrade").string(); }

gllab::ProcessResult grade(std::vector<std::string> args) {
  args.insert(args.begin(), labgrade());
  return run_process(args);
}

// The table row of a view and the reason line under it.
std::string row_of(const std::string& out, const std::string& view) {
  const auto at = out.find(kLab + "__" + view + " ");
  if (at == std::string::npos) return "";
  const auto end = out.find('\n', out.find('\n', at) + 1);
  return out.substr(at, end - at);
}

// A references folder with lab 01's MANIFEST and the given references.
void copy_references(const fs::path& to, const std::vector<std::string>& views) {
  fs::copy_file(kRefs / "MANIFEST", to / "MANIFEST");
  for (const std::string& v : views) fs::copy_file(kRefs / (kLab + "__" + v + ".png"), to / (kLab + "__" + v + ".png"));
}

// A stand-in headless program: runs `action` (a shell command) for a render.
void write_fake_renderer(const fs::path& path, const std::string& action) {
  std::ofstream(path) << "#!/bin/sh\n" << action << "\n";
  fs::permissions(path, fs::perms::owner_all);
}

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// A submitted image of lab 01's view `view` as `as`, with its text (the
// headless --print-text lines), as a student's folder holds them.
void submit_view(const fs::path& folder, const std::string& view, const std::string& as) {
  fs::copy_file(kRefs / (kLab + "__" + view + ".png"), folder / (kLab + "__" + as + ".png"),
                fs::copy_options::overwrite_existing);
  fs::copy_file(kRefs / (kLab + "__" + view + ".txt"), folder / (kLab + "__" + as + ".txt"),
                fs::copy_options::overwrite_existing);
}

TEST(Labgrade, EveryViewOfThisBuildPassesItsReference) {
  const gllab::ProcessResult r = grade({"--build", kBinDir.string(), "--labs", "01", "--quiet"});
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("4 views: 4 passed, 0 failed; score 100.0%"), std::string::npos) << r.out;
}

// A broken reference is the instructor's error, refused before grading
// (labgrade_limits_test.cpp); here the references are sound and define the views.
TEST(Labgrade, TheReferencesDefineTheViewsThatAreGraded) {
  ScratchDir refs("refs");
  copy_references(refs.path(), {"default", "invalid_polygons", "wireframe"});
  const gllab::ProcessResult r =
      grade({"--build", kBinDir.string(), "--refs", refs.path().string()});
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  // vertex_order has no reference, so it is not graded.
  EXPECT_EQ(row_of(r.out, "vertex_order"), "") << r.out;
  EXPECT_NE(row_of(r.out, "wireframe").find("pass"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("3 views: 3 passed, 0 failed"), std::string::npos) << r.out;
}

TEST(Labgrade, MissingManifestIsAUsageErrorOfOneLine) {
  ScratchDir refs("refs");
  const gllab::ProcessResult r = grade({"--build", kBinDir.string(), "--refs", refs.path().string()});
  EXPECT_EQ(r.exit_status, kUsage);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("MANIFEST"), std::string::npos) << r.err;
}

TEST(Labgrade, BadArgumentsAreUsageErrorsOfOneLineNamingThem) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--build", kBinDir.string(), "--labs", "99"}, "unknown lab '99'"},
      {{"--build", kBinDir.string(), "--views", "nope"}, "unknown view 'nope'"},
      {{"--build", kBinDir.string(), "--jobs", "0"}, "--jobs '0'"},
      {{"--build", kBinDir.string(), "--timeout", "-1"}, "--timeout '-1'"},
      {{"--build", "/no/such/dir"}, "no build folder /no/such/dir"},
      {{"--images", kBinDir.string(), "--build", kBinDir.string()}, "give one of --build, --images, --class"},
      {{"--labs", "01"}, "nothing to grade"},
      {{"--build", kBinDir.string(), "--frobnicate"}, "unknown option '--frobnicate'"},
  };
  for (const auto& [args, message] : cases) {
    const gllab::ProcessResult r = grade(args);
    EXPECT_EQ(r.exit_status, kUsage) << message;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  }
}

TEST(Labgrade, GlErrorCrashHangAndMissingRendererAreFailingRowsWithTheReason) {
  ScratchDir build("build");
  // Four "labs" of one build, each broken in its own way, graded against
  // references of that name (copies of lab 01's default view).
  ScratchDir refs("refs");
  fs::copy_file(kRefs / "MANIFEST", refs / "MANIFEST");
  for (const char* lab : {"91_gl_error", "92_crash", "93_hang", "94_missing"})
    fs::copy_file(kRefs / (kLab + "__default.png"), refs / (std::string(lab) + "__default.png"));
  write_fake_renderer(build / "91_gl_error",
                      "exec " + gllab::testing::kFixtureLab.string() + " --set gl_error=1 \"$@\"");
  write_fake_renderer(build / "92_crash", "kill -SEGV $$");
  write_fake_renderer(build / "93_hang", "exec sleep 30");
  const gllab::ProcessResult r = grade(
      {"--build", build.path().string(), "--refs", refs.path().string(), "--timeout", "1", "--out", (build / "out").string()});
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out << r.err;
  EXPECT_NE(r.out.find("GL_INVALID_ENUM"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("crashed (signal 11)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the render took longer than 1 s (killed)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("no program 94_missing in " + build.path().string()), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("4 views: 0 passed, 4 failed; score 0.0%"), std::string::npos) << r.out;
}

// A build renders a lab's views in one run (--views a,b,c --out -). A view
// that fails from that run is rendered again on its own and graded from that
// render, so the verdict is the one a run per view (as the references were
// made) gives: here the batch answers every view with the default view's
// picture, and the single runs are right, so every view passes.
TEST(Labgrade, AViewThatFailsInABatchIsGradedFromItsOwnRender) {
  ScratchDir build("build");
  const std::string real = (kBinDir / kLab).string();
  write_fake_renderer(build / kLab,
                      "if [ \"$2\" = --views ]; then exec " + real + " --views default,default,default,default --out -; fi\n"
                      "exec " + real + " \"$@\"");
  const gllab::ProcessResult r = grade({"--build", build.path().string(), "--labs", "01", "--quiet"});
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("4 views: 4 passed"), std::string::npos) << r.out;
}

// A batch run that stops after its first frame: the views it did not render
// are rendered one by one, each graded on its own.
TEST(Labgrade, ABatchThatStopsEarlyGradesTheRestOneByOne) {
  ScratchDir build("build");
  const std::string real = (kBinDir / kLab).string();
  write_fake_renderer(build / kLab,
                      "if [ \"$2\" = --views ]; then " + real + " --view default --out -; exit 3; fi\n"
                      "exec " + real + " \"$@\"");
  const gllab::ProcessResult r = grade({"--build", build.path().string(), "--labs", "01", "--quiet"});
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("4 views: 4 passed"), std::string::npos) << r.out;
}

TEST(Labgrade, ImageFolderIsGradedAndAWrongImageFails) {
  ScratchDir images("images");
  for (const std::string v : {"default", "invalid_polygons", "vertex_order"}) submit_view(images.path(), v, v);
  // vertex_order replaced by another view's picture: it must fail; wireframe is missing.
  fs::copy_file(kRefs / (kLab + "__default.png"), images / (kLab + "__vertex_order.png"),
                fs::copy_options::overwrite_existing);
  const gllab::ProcessResult r = grade({"--images", images.path().string(), "--labs", "01", "--out", (images / "out").string()});
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out << r.err;
  EXPECT_NE(row_of(r.out, "default").find("pass"), std::string::npos) << r.out;
  EXPECT_NE(row_of(r.out, "vertex_order").find("differs beyond tolerance"), std::string::npos) << r.out;
  EXPECT_NE(row_of(r.out, "wireframe").find("no render " + (images / (kLab + "__wireframe.png")).string()),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("4 views: 2 passed, 2 failed; score 50.0% (incomplete: 01_immediate_mode 2/4)"),
            std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(images / "out" / (kLab + "__vertex_order.diff.png")));
}

TEST(Labgrade, ProgressNamesEveryViewAsItFinishes) {
  const gllab::ProcessResult r = grade({"--build", kBinDir.string(), "--labs", "01", "--jobs", "2"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  // stderr is not a terminal here: one line per finished view.
  EXPECT_EQ(line_count(r.err), 4) << r.err;
  for (int done = 1; done <= 4; ++done)
    EXPECT_NE(r.err.find("[" + std::to_string(done) + "/4] pass " + kLab + "__"), std::string::npos) << r.err;
  for (const std::string& v : kViews) EXPECT_NE(r.err.find(kLab + "__" + v + "\n"), std::string::npos) << r.err;
}

TEST(Labgrade, ReportHasEveryViewFailuresFirstAndAgreesWithJsonAndCsv) {
  ScratchDir images("images"), report("report");
  for (const std::string& v : kViews) submit_view(images.path(), v, v);
  fs::copy_file(kRefs / (kLab + "__default.png"), images / (kLab + "__wireframe.png"), fs::copy_options::overwrite_existing);
  const gllab::ProcessResult r = grade({"--images", images.path().string(), "--labs", "01", "--report",
                                        report.path().string(), "--quiet"});
  ASSERT_EQ(r.exit_status, kSomeFailed) << r.err;

  const nlohmann::json json = nlohmann::json::parse(file_text(report / "results.json"));
  EXPECT_EQ(json["views"], 4);
  EXPECT_EQ(json["passed"], 3);
  ASSERT_EQ(json["results"].size(), 4u);
  EXPECT_EQ(json["results"][0]["view"], "wireframe");  // the failure first
  EXPECT_EQ(json["results"][0]["result"], "fail");
  EXPECT_EQ(json["profile"], "images");
  EXPECT_GT(json["results"][0]["score"].get<double>(), 1.0);  // in units of the limit
  for (int i = 1; i < 4; ++i) EXPECT_EQ(json["results"][i]["score"], 0.0);

  const std::string csv = file_text(report / "results.csv");
  EXPECT_EQ(line_count(csv), 5) << csv;
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "lab,view,result,score,differing_share,unexcused_pixels,shifted_pixels,max_delta,reason");
  EXPECT_NE(csv.find("\n" + kLab + ",wireframe,fail,"), std::string::npos) << csv;

  const std::string html = file_text(report / "index.html");
  EXPECT_LT(html.find(kLab + "__wireframe"), html.find(kLab + "__default")) << "failures come first";
  for (const std::string& v : kViews)
    for (const char* folder : {"reference", "submission", "heat_map"})
      EXPECT_TRUE(fs::exists(report / folder / (kLab + "__" + v + ".png"))) << folder << " " << v;
}

// The report in a real browser: it loads, and every image on it resolves
// (the page's own script counts loaded images into its title; Debian's
// chromium, installed by ./lab).
TEST(Labgrade, ReportLoadsInHeadlessChromiumWithEveryImage) {
  ScratchDir report("report");
  ASSERT_EQ(grade({"--build", kBinDir.string(), "--labs", "01", "--report", report.path().string(), "--quiet"}).exit_status, 0);
  ASSERT_TRUE(fs::exists("/usr/bin/chromium")) << "chromium is missing: ./lab installs it";
  const gllab::ProcessResult r = gllab::testing::chromium_dom(report / "index.html");
  ASSERT_EQ(r.exit_status, 0) << r.err;
  // 4 views x (reference, submission, heat map).
  EXPECT_NE(r.out.find("<title>gllab grade: images 12/12 loaded</title>"), std::string::npos)
      << r.out.substr(0, 400);
}

TEST(Labgrade, ClassCsvHasARowPerStudentAndAColumnPerLab) {
  ScratchDir klass("class");
  // anna: every image of lab 01; ben: one missing; carl: a build (a wrapper
  // around this build's renderer).
  fs::create_directories(klass / "anna");
  fs::create_directories(klass / "ben");
  fs::create_directories(klass / "carl");
  for (const std::string& v : kViews) {
    submit_view(klass / "anna", v, v);
    if (v != "wireframe") submit_view(klass / "ben", v, v);
  }
  write_fake_renderer(klass / "carl" / kLab, "exec " + (kBinDir / kLab).string() + " \"$@\"");
  const fs::path csv = klass / "grades.csv";
  // carl's wrapper runs this build's program, which a sandbox would not show
  // it: this test is about the CSV (class_test.cpp grades in the sandbox).
  ScratchDir work("work");
  const gllab::ProcessResult r =
      grade({"--class", klass.path().string(), "--labs", "01", "--csv", csv.string(), "--quiet", "--out",
             (klass / "out").string(), "--no-sandbox", "--work", work.path().string()});
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out << r.err;
  EXPECT_EQ(file_text(csv),
            "student,kind,views,passed,score,01_immediate_mode,hidden,hidden_passed,build,build_seconds,"
            "cache_hit_rate,reason\n"
            "anna,images,4,4,100.0,100.0,0,0,-,-,-,\n"
            "ben,images,4,3,75.0,75.0,0,0,-,-,-,\n"
            "carl,build,4,4,100.0,100.0,0,0,-,-,-,\n");
}

// ---- the text a view draws, error views, profiles ------------------------------

// One line of a submitted text file changed.
void edit_text(const fs::path& file, const std::string& from, const std::string& to) {
  std::string text = file_text(file);
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from << " not in " << file;
  text.replace(at, from.size(), to);
  std::ofstream(file, std::ios::binary) << text;
}

TEST(Labgrade, AWrongNumberInAViewsTextFailsItWithTheLine) {
  ScratchDir images("images");
  for (const std::string& v : kViews) submit_view(images.path(), v, v);
  const std::string line = file_text(kRefs / (kLab + "__vertex_order.txt")).substr(0, 200);
  // The picture is right; a number in its text is one off (the first digit run).
  const auto digit = line.find_first_of("0123456789");
  ASSERT_NE(digit, std::string::npos) << "lab 01's vertex_order draws no number: " << line;
  const std::string from = line.substr(digit, 1), to = from == "9" ? "8" : std::string(1, char(from[0] + 1));
  edit_text(images / (kLab + "__vertex_order.txt"), line.substr(0, digit + 1), line.substr(0, digit) + to);
  const gllab::ProcessResult r = grade({"--images", images.path().string(), "--labs", "01", "--out", (images / "out").string()});
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out << r.err;
  const std::string row = row_of(r.out, "vertex_order");
  EXPECT_NE(row.find("text differs: line "), std::string::npos) << row;
  EXPECT_NE(row.find("the reference \""), std::string::npos) << row;
  EXPECT_NE(r.out.find("4 views: 3 passed, 1 failed"), std::string::npos) << r.out;
}

TEST(Labgrade, MissingTextOrAChangedWordFailsAView) {
  ScratchDir images("images");
  for (const std::string& v : kViews) submit_view(images.path(), v, v);
  fs::remove(images / (kLab + "__default.txt"));
  // A word changed: the first letter of the wireframe text's first line upper-cased or lowered.
  std::string text = file_text(images / (kLab + "__wireframe.txt"));
  const auto letter = text.find_first_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ");
  ASSERT_NE(letter, std::string::npos);
  text[letter] = static_cast<char>(std::isupper(static_cast<unsigned char>(text[letter])) ? std::tolower(text[letter])
                                                                                           : std::toupper(text[letter]));
  std::ofstream(images / (kLab + "__wireframe.txt"), std::ios::binary) << text;
  const gllab::ProcessResult r = grade({"--images", images.path().string(), "--labs", "01", "--out", (images / "out").string()});
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out << r.err;
  EXPECT_NE(row_of(r.out, "default").find("text differs: no text from the render"), std::string::npos) << r.out;
  EXPECT_NE(row_of(r.out, "wireframe").find("text differs: line 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("4 views: 2 passed, 2 failed"), std::string::npos) << r.out;
}

TEST(Labgrade, NumbersAgreeWithinTheRelativeToleranceAndRoundingNoiseIsNoise) {
  ScratchDir refs("refs"), images("images");
  fs::copy_file(kRefs / "MANIFEST", refs / "MANIFEST");
  fs::copy_file(kRefs / (kLab + "__default.png"), refs / (kLab + "__default.png"));
  submit_view(images.path(), "default", "default");
  // MANIFEST: text_relative_tolerance 1e-06, text_absolute_tolerance 1e-09.
  std::ofstream(refs / (kLab + "__default.txt")) << "area 12.5 cm\nerror 3e-17\nn = 10\n";
  std::ofstream(images / (kLab + "__default.txt")) << "area 12.500001 cm\nerror -4.4e-16\nn = 10\n";
  const std::vector<std::string> args = {"--images", images.path().string(), "--refs", refs.path().string(), "--quiet"};
  gllab::ProcessResult r = grade(args);
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  std::ofstream(images / (kLab + "__default.txt")) << "area 12.5 cm\nerror 3e-17\nn = 11\n";
  r = grade(args);
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out;
  std::ofstream(images / (kLab + "__default.txt")) << "area 12.50002 cm\nerror 3e-17\nn = 10\n";
  r = grade(args);
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out;
}

TEST(Labgrade, AnErrorViewPassesABuildOnlyWhenItExitsOneWithItsLine) {
  const std::string lab = "22_trimmed_nurbs", view = "reversed_outer_loop";
  const std::string expected = file_text(kRefs / (lab + "__" + view + ".error"));
  ASSERT_FALSE(expected.empty());
  gllab::ProcessResult r = grade({"--build", kBinDir.string(), "--labs", "22", "--views", view});
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("1 views: 1 passed"), std::string::npos) << r.out;
  // A renderer that draws the default view instead, and one that refuses with another line.
  ScratchDir draws("draws"), other("other");
  const std::string real = (kBinDir / lab).string();
  write_fake_renderer(draws / lab, "exec " + real + " --view default --out -");
  write_fake_renderer(other / lab, "echo 'something else' >&2; exit 1");
  r = grade({"--build", draws.path().string(), "--labs", "22", "--views", view, "--out", (draws / "out").string()});
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out;
  EXPECT_NE(r.out.find("drew a picture; it must exit 1"), std::string::npos) << r.out;
  r = grade({"--build", other.path().string(), "--labs", "22", "--views", view, "--out", (other / "out").string()});
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out;
  EXPECT_NE(r.out.find("exit 1 with \"something else\", the reference"), std::string::npos) << r.out;
  // Images cannot show an exit: the error view is left out, and said so.
  ScratchDir images("images");
  for (const auto& entry : fs::directory_iterator(kRefs))
    if (entry.path().filename().string().rfind(lab + "__", 0) == 0 && entry.path().extension() != ".error")
      fs::copy_file(entry.path(), images / entry.path().filename());
  r = grade({"--images", images.path().string(), "--labs", "22"});
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("1 error view not graded: a folder of images cannot show an exit status"), std::string::npos)
      << r.out;
}

TEST(Labgrade, TheProfileFollowsTheSourceUnlessGiven) {
  ScratchDir report("report");
  ASSERT_EQ(grade({"--build", kBinDir.string(), "--labs", "01", "--views", "default", "--report", report.path().string(),
                   "--quiet"}).exit_status, 0);
  EXPECT_EQ(nlohmann::json::parse(file_text(report / "results.json"))["profile"], "build");
  ASSERT_EQ(grade({"--build", kBinDir.string(), "--labs", "01", "--views", "default", "--profile", "images",
                   "--report", report.path().string(), "--quiet"}).exit_status, 0);
  const nlohmann::json j = nlohmann::json::parse(file_text(report / "results.json"));
  EXPECT_EQ(j["profile"], "images");
  const std::string manifest = file_text(kRefs / "MANIFEST");
  const auto at = manifest.find("images_channel_threshold: ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_EQ(j["tolerance"]["channel_threshold"], std::stoi(manifest.substr(at + 26)));
  const gllab::ProcessResult r = grade({"--build", kBinDir.string(), "--profile", "strict"});
  EXPECT_EQ(r.exit_status, kUsage);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("unknown profile 'strict' (profiles: build, images)"), std::string::npos) << r.err;
}

// labrun --compare-builds (make backends, in CI: the EGL build against its OSMesa
// twins) passes only when every view is the same, byte for byte: a copy of the
// program passes, one that turns the shapes by 1 degree fails each view it changes,
// naming it, with exit status 1.
TEST(Labrun, CompareBuildsFailsOnAnyDifferingByte) {
  ScratchDir same("same"), turned("turned");
  const std::string real = (kBinDir / kLab).string();
  write_fake_renderer(same / kLab, "exec " + real + " \"$@\"");
  write_fake_renderer(turned / kLab, "exec " + real + " --set spin=1 \"$@\"");
  const std::string labrun = (kBinDir / "labrun").string();
  const gllab::ProcessResult ok =
      run_process({labrun, "--compare-builds", same.path().string(), "--labs", "01"});
  EXPECT_EQ(ok.exit_status, 0) << ok.out << ok.err;
  EXPECT_NE(ok.out.find("4 views of 1 lab: 4 byte-identical, 0 differ"), std::string::npos) << ok.out;
  const gllab::ProcessResult bad =
      run_process({labrun, "--compare-builds", turned.path().string(), "--labs", "01"});
  EXPECT_EQ(bad.exit_status, 1) << bad.out << bad.err;
  EXPECT_NE(bad.out.find("DIFFERS 01_immediate_mode default: "), std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find(" 0 byte-identical, 4 differ"), std::string::npos) << bad.out;
}

}  // namespace
