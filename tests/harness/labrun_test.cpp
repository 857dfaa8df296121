// tests/harness/labrun_test.cpp — the comparison behind `make run` reports
// a missing, corrupt or wrong-sized reference as a failing row with its
// reason (one line) and exits 1; bad input exits 2 with one line; an error
// view passes only when its render exits 1.
#include <gtest/gtest.h>

#include <fstream>

#include "image/image.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using gllab::run_process;
using gllab::testing::kBinDir;
using gllab::testing::kSourceDir;
using gllab::testing::line_count;
using gllab::testing::ScratchDir;

constexpr int kSomeFailed = 1;  // labrun --help: "1 some failed"
constexpr int kUsage = 2;       // labrun --help: "2 usage or input error"

const std::string kLab = "01_immediate_mode";

std::string labrun() { return (kBinDir / "labrun").string(); }

// The output line of one view, e.g. "01_immediate_mode  default  FAIL ...",
// followed by its reason line.
std::string row_of(const std::string& out, const std::string& view) {
  const auto at = out.find(kLab + "      " + view);
  if (at == std::string::npos) return "";
  const auto end = out.find('\n', out.find('\n', at) + 1);
  return out.substr(at, end - at);
}

TEST(Labrun, BrokenReferencesFailTheirRowsWithTheReason) {
  ScratchDir refs("refs"), out("out");
  fs::copy_file(kSourceDir / "reference_images" / "MANIFEST", refs / "MANIFEST");
  // default: not a PNG; wireframe: a valid PNG of the wrong size;
  // vertex_order: missing; invalid_polygons: the real reference.
  std::ofstream(refs / (kLab + "__default.png")) << "this is not a PNG\n";
  gllab::write_png((refs / (kLab + "__wireframe.png")).string(), gllab::Image(16, 16));
  fs::copy_file(kSourceDir / "reference_images" / (kLab + "__invalid_polygons.png"),
                refs / (kLab + "__invalid_polygons.png"));

  const gllab::ProcessResult r = run_process(
      {labrun(), "--labs", "01", "--refs", refs.path().string(), "--out", out.path().string()});
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out << r.err;
  EXPECT_NE(row_of(r.out, "default").find("not a PNG"), std::string::npos) << r.out;
  EXPECT_NE(row_of(r.out, "wireframe").find("size mismatch: reference 16x16, test 512x512"),
            std::string::npos) << r.out;
  EXPECT_NE(row_of(r.out, "vertex_order").find("no reference image"), std::string::npos) << r.out;
  EXPECT_NE(row_of(r.out, "invalid_polygons").find("pass"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("4 views: 1 passed, 3 failed"), std::string::npos) << r.out;
  // The renders are kept for a look, and the heat map of the passing view.
  EXPECT_TRUE(fs::exists(out / (kLab + "__vertex_order.png")));
  EXPECT_TRUE(fs::exists(out / (kLab + "__invalid_polygons.diff.png")));
}

TEST(Labrun, MissingManifestIsAUsageErrorOfOneLine) {
  ScratchDir refs("refs"), out("out");
  const gllab::ProcessResult r = run_process(
      {labrun(), "--labs", "01", "--refs", refs.path().string(), "--out", out.path().string()});
  EXPECT_EQ(r.exit_status, kUsage);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("MANIFEST"), std::string::npos) << r.err;
}

TEST(Labrun, UnknownLabIsAUsageErrorNamingIt) {
  const gllab::ProcessResult r = run_process({labrun(), "--labs", "99"});
  EXPECT_EQ(r.exit_status, kUsage);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("'99'"), std::string::npos) << r.err;
}

// A stand-in renderer: lists one view, then runs `action` for the render.
void write_fake_renderer(const fs::path& path, const std::string& action) {
  std::ofstream(path) << "#!/bin/sh\ncase \"$1\" in --list-views) echo default ;; *) " << action
                      << " ;; esac\n";
  fs::permissions(path, fs::perms::owner_all);
}

TEST(Labrun, GlErrorInARenderIsAFailingRowWithTheError) {
  ScratchDir bin("bin"), out("out");
  write_fake_renderer(bin / (kLab + "_headless"),
                      "exec " + gllab::testing::kFixtureLab.string() + " --set gl_error=1 \"$@\"");
  const gllab::ProcessResult r = run_process(
      {labrun(), "--labs", "01", "--bin", bin.path().string(), "--out", out.path().string()});
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out << r.err;
  EXPECT_NE(row_of(r.out, "default").find("GL_INVALID_ENUM"), std::string::npos) << r.out;
}

TEST(Labrun, CrashingRendererIsAFailingRowNotASkip) {
  ScratchDir bin("bin"), out("out");
  write_fake_renderer(bin / (kLab + "_headless"), "kill -SEGV $$");
  const gllab::ProcessResult r = run_process(
      {labrun(), "--labs", "01", "--bin", bin.path().string(), "--out", out.path().string()});
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out << r.err;
  // 128 + SIGSEGV (11): how the shell reports a process killed by a signal.
  EXPECT_NE(row_of(r.out, "default").find("exited with status 139"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1 views: 0 passed, 1 failed"), std::string::npos) << r.out;
}

// An error view (harness/lab.h View::expect_error), listed as
// "name expect_error": a stand-in renderer with only that view, which
// exits with `status` after printing one error line.
void write_fake_error_view(const fs::path& path, int status) {
  std::ofstream(path) << "#!/bin/sh\ncase \"$1\" in --list-views) echo 'broken expect_error' ;; "
                      << "*) echo \"x: view 'broken': GLU NURBS error 28\" >&2; exit " << status << " ;; esac\n";
  fs::permissions(path, fs::perms::owner_all);
}

std::string error_view_row(const std::string& out) {
  const auto at = out.find(kLab + "      broken");
  return at == std::string::npos ? "" : out.substr(at, out.find('\n', out.find('\n', at) + 1) - at);
}

TEST(Labrun, ErrorViewThatExitsOnePassesAndShowsTheError) {
  ScratchDir bin("bin"), out("out");
  write_fake_error_view(bin / (kLab + "_headless"), 1);
  const gllab::ProcessResult r = run_process(
      {labrun(), "--labs", "01", "--bin", bin.path().string(), "--out", out.path().string()});
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  EXPECT_NE(error_view_row(r.out).find("pass"), std::string::npos) << r.out;
  EXPECT_NE(error_view_row(r.out).find("exits 1 as expected: x: view 'broken': GLU NURBS error 28"),
            std::string::npos) << r.out;
}

TEST(Labrun, ErrorViewThatRendersOrCrashesFails) {
  for (int status : {0, 2}) {
    ScratchDir bin("bin"), out("out");
    write_fake_error_view(bin / (kLab + "_headless"), status);
    const gllab::ProcessResult r = run_process(
        {labrun(), "--labs", "01", "--bin", bin.path().string(), "--out", out.path().string()});
    EXPECT_EQ(r.exit_status, kSomeFailed) << r.out << r.err;
    EXPECT_NE(error_view_row(r.out).find(status == 0 ? "rendered without an error" : "exit status 2 (expected 1)"),
              std::string::npos) << r.out;
  }
}

TEST(Labrun, ErrorViewNeedsNoReferenceAndMayNotHaveOne) {
  ScratchDir bin("bin"), refs("refs");
  write_fake_error_view(bin / (kLab + "_headless"), 1);
  const std::vector<std::string> check = {labrun(), "--check-references", "--labs", "01", "--bin",
                                          bin.path().string(), "--refs", refs.path().string()};
  EXPECT_EQ(run_process(check).exit_status, 0);
  gllab::write_png((refs / (kLab + "__broken.png")).string(), gllab::Image(16, 16));
  const gllab::ProcessResult r = run_process(check);
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out;
  EXPECT_NE(r.out.find("reference for an error view"), std::string::npos) << r.out;
}

TEST(Labrun, MissingRendererIsAUsageErrorNamingIt) {
  ScratchDir bin("bin");
  const gllab::ProcessResult r = run_process({labrun(), "--labs", "01", "--bin", bin.path().string()});
  EXPECT_EQ(r.exit_status, kUsage) << r.out;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("cannot list views"), std::string::npos) << r.err;
}

}  // namespace
