// tests/grading/labgrade_limits_test.cpp — labgrade and labrun on bad or extreme
// input (issue 20): every case ends with its exit status and one line on
// stderr that names the value, the file or the MANIFEST field; nothing
// crashes, hangs, grows without bound, leaves a temporary file behind or
// exits 0 after a failed write. The limits are the named constants of
// tools/grading.h and tools/process.h (listed in tools/README.md); the
// messages are the ones those files document.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <tuple>

#include "image/image.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using gllab::ProcessResult;
using gllab::run_process;
using gllab::testing::kBinDir;
using gllab::testing::kSourceDir;
using gllab::testing::line_count;
using gllab::testing::ScratchDir;

constexpr int kSomeFailed = 1;  // labgrade --help: "1 some failed"
constexpr int kUsage = 2;       // labgrade --help: "2 usage or input error"
// No case may take longer than this: a FIFO read would block forever, a
// renderer that writes without end would run until memory is gone.
constexpr double kCaseTimeoutSeconds = 60;

const std::string kLab = "01_immediate_mode";
const fs::path kRefs = kSourceDir / "reference_images";

std::string labgrade() { return (kBinDir / "labgrade").string(); }

ProcessResult grade(std::vector<std::string> args) {
  args.insert(args.begin(), labgrade());
  return run_process(args, {}, kCaseTimeoutSeconds);
}

// Runs a shell command line (for redirections and ulimit).
ProcessResult shell(const std::string& command) {
  return run_process({"/bin/sh", "-c", command}, {}, kCaseTimeoutSeconds);
}

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void write_file(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

void write_fake_renderer(const fs::path& path, const std::string& action) {
  write_file(path, "#!/bin/sh\n" + action + "\n");
  fs::permissions(path, fs::perms::owner_all);
}

// A references folder with the real MANIFEST and lab 01's references of `views`.
void copy_references(const fs::path& to, const std::vector<std::string>& views) {
  fs::copy_file(kRefs / "MANIFEST", to / "MANIFEST");
  for (const std::string& v : views)
    for (const char* ext : {".png", ".txt"})
      fs::copy_file(kRefs / (kLab + "__" + v + ext), to / (kLab + "__" + v + ext));
}

// Exit 2 with exactly one line on stderr that contains `message`.
void expect_usage_error(const ProcessResult& r, const std::string& message) {
  EXPECT_FALSE(r.timed_out) << message;
  EXPECT_EQ(r.exit_status, kUsage) << message << "\n" << r.out << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos)
      << "expected: " << message << "\ngot: " << r.err;
}

// Every file under dir whose name has ".tmp" in it (a leftover of a write).
std::vector<std::string> leftovers(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.path().filename().string().find(".tmp") != std::string::npos)
      found.push_back(entry.path().string());
  return found;
}

// ---- 8: strict numbers; 1 and 2: the job and timeout limits -------------------------

TEST(LabgradeLimits, JobsOutsideOneTo256OrNotAWholeNumberIsAUsageErrorNamingIt) {
  // kMaxJobs = 256 (grading.h); "3.5" and "1e2" are not whole numbers (parse_integer).
  for (const std::string jobs :
       {"257", "100000", "99999999999999999999", "3.5", "1e2", " 2", "2 ", "+2", "", "0"})
    expect_usage_error(grade({"--build", kBinDir.string(), "--jobs", jobs}),
                       "--jobs '" + jobs + "' is not a whole number from 1 to 256");
}

TEST(LabgradeLimits, TimeoutOutsideItsRangeOrNotANumberIsAUsageErrorNamingIt) {
  // kMaxTimeoutSeconds = 3600 (grading.h): 1e18 once overflowed into "-2147483648 s".
  for (const std::string t :
       {"1e18", "3600.5", "1e309", "nan", "inf", "-1", "0", "1s", "0x10", " 5", ""})
    expect_usage_error(grade({"--build", kBinDir.string(), "--timeout", t}),
                       "--timeout '" + t + "' is not a number of seconds > 0 and <= 3600");
}

TEST(LabgradeLimits, TheLargestJobsAndTimeoutGradeNormally) {
  // At the limits: 256 jobs for one lab start one thread; a deadline an hour
  // away does not overflow the clock (every view passes, as with the defaults).
  const ProcessResult r = grade({"--build", kBinDir.string(), "--labs", "01", "--jobs", "256",
                                 "--timeout", "3600", "--quiet"});
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("4 views: 4 passed, 0 failed"), std::string::npos) << r.out;
}

TEST(LabgradeLimits, AFractionalTimeoutIsReportedAsGiven) {
  ScratchDir build("build"), refs("refs");
  fs::copy_file(kRefs / "MANIFEST", refs / "MANIFEST");
  fs::copy_file(kRefs / (kLab + "__default.png"), refs / "93_hang__default.png");
  write_fake_renderer(build / "93_hang", "exec sleep 30");
  const ProcessResult r = grade({"--build", build.path().string(), "--refs", refs.path().string(),
                                 "--timeout", "0.5", "--out", (build / "out").string()});
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out << r.err;
  EXPECT_NE(r.out.find("the render took longer than 0.5 s (killed)"), std::string::npos) << r.out;
}

// 1: a thread that cannot start. An address-space limit (ulimit -v) lets the
// first few threads have their 8 MiB stacks and refuses the rest; labgrade
// grades with those (before: std::terminate, exit 134). 30 labs of one 8x8
// view each, graded as images, keep the memory small. Not under ASan, which
// reserves terabytes of address space for its shadow memory.
TEST(LabgradeLimits, AThreadThatCannotStartLeavesTheWorkToTheThreadsThatDid) {
#if defined(GLLAB_ASAN)
  GTEST_SKIP() << "ulimit -v and AddressSanitizer do not mix";
#else
  constexpr int kLabs = 30;
  ScratchDir refs("refs"), images("images");
  std::string manifest = file_text(kRefs / "MANIFEST");
  manifest.replace(manifest.find("size: 512x512"), 13, "size: 8x8");
  write_file(refs / "MANIFEST", manifest);
  gllab::Image image(8, 8);
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    image.rgba[i] = static_cast<std::uint8_t>(i * 7);
  for (int lab = 0; lab < kLabs; ++lab) {
    const std::string name = std::to_string(50 + lab) + "_lab__default";
    gllab::write_png((refs / (name + ".png")).string(), image);
    gllab::write_png((images / (name + ".png")).string(), image);
  }
  const std::string command = "ulimit -s 8192 && ulimit -v 120000 && exec " + labgrade() +
                              " --images " + images.path().string() + " --refs " +
                              refs.path().string() + " --jobs 256 --quiet";
  const ProcessResult r = shell(command);
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("30 views: 30 passed, 0 failed"), std::string::npos) << r.out << r.err;
  EXPECT_EQ(r.err, "");
#endif
}

// A failure of the grading itself in a worker thread (here: no temporary
// folder for a renderer's text) stops every thread and is one line, exit 2
// (before: std::terminate from the thread).
TEST(LabgradeLimits, NoTemporaryFolderStopsTheGradingWithOneLine) {
  const ProcessResult r =
      run_process({labgrade(), "--build", kBinDir.string(), "--labs", "01", "--jobs", "2"},
                  {"TMPDIR=/nonexistent/gllab"}, kCaseTimeoutSeconds);
  expect_usage_error(r, "labgrade: no temporary folder for a renderer's text (");
}

// ---- 3: a renderer's output is capped ------------------------------------------------

TEST(LabgradeLimits, ARendererThatWritesWithoutEndIsKilledAndFailsItsView) {
  // kMaxRendererOutputBytes = 64 MiB (process.h), on stdout and on stderr. The
  // third leaves a child behind that holds the pipes for 30 s: labgrade must
  // not wait for it.
  ScratchDir build("build"), refs("refs");
  fs::copy_file(kRefs / "MANIFEST", refs / "MANIFEST");
  for (const char* lab : {"95_stdout", "96_stderr", "97_orphan"})
    fs::copy_file(kRefs / (kLab + "__default.png"), refs / (std::string(lab) + "__default.png"));
  write_fake_renderer(build / "95_stdout", "exec cat /dev/zero");
  write_fake_renderer(build / "96_stderr", "exec cat /dev/zero >&2");
  write_fake_renderer(build / "97_orphan", "sleep 30 &\nexec cat /dev/zero");
  const auto start = std::chrono::steady_clock::now();
  const ProcessResult r = grade({"--build", build.path().string(), "--refs", refs.path().string(),
                                 "--jobs", "1", "--out", (build / "out").string()});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out << r.err;
  const std::string reason = "the renderer wrote more than 64 MiB to stdout or stderr (killed)";
  for (const char* lab : {"95_stdout", "96_stderr", "97_orphan"}) {
    const auto row = r.out.find(std::string(lab) + "__default ");
    ASSERT_NE(row, std::string::npos) << r.out;
    EXPECT_NE(r.out.find(reason, row), std::string::npos) << lab << "\n" << r.out;
  }
  EXPECT_NE(r.out.find("3 views: 0 passed, 3 failed"), std::string::npos) << r.out;
  // The orphan's 30 s are not waited for (process.cpp drains a killed run for 1 s).
  EXPECT_LT(seconds, 20) << r.out;
}

// ---- 4: the instructor's files, checked before any grading ---------------------------

// A build whose renderer leaves a mark when it runs: a case that must be
// refused before grading leaves none.
struct MarkingBuild {
  ScratchDir dir{"build"};
  MarkingBuild() {
    write_fake_renderer(dir / kLab,
                        "touch " + (dir / "rendered").string() + "\nexec " +
                            (kBinDir / kLab).string() + " \"$@\"");
  }
  bool rendered() const { return fs::exists(dir / "rendered"); }
};

ProcessResult grade_with(const MarkingBuild& build, const fs::path& refs) {
  return grade({"--build", build.dir.path().string(), "--refs", refs.string(), "--out",
                (build.dir / "out").string()});
}

TEST(LabgradeLimits, ACorruptTruncatedOrWronglySizedReferenceStopsBeforeGrading) {
  const std::string real = file_text(kRefs / (kLab + "__default.png"));
  // The IHDR of a PNG of 100000 x 100000 pixels (its CRC is not checked: the size is refused
  // first).
  std::string huge = real;
  for (int k = 0; k < 2; ++k) {
    const unsigned v = 100000;
    for (int b = 0; b < 4; ++b)
      huge[16 + 4 * k + b] = static_cast<char>((v >> (24 - 8 * b)) & 0xff);
  }
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"this is not a PNG\n", "__default.png: not a PNG file"},
      {real.substr(0, real.size() / 2), "__default.png: corrupt PNG"},  // truncated
      {real.substr(0, 30), "__default.png: corrupt PNG"},
      {"", "__default.png: not a PNG file"},
      {huge,
       "__default.png: a PNG of 100000x100000 pixels, larger than the limit of 4096 per side"},
  };
  for (const auto& [bytes, message] : cases) {
    ScratchDir refs("refs");
    MarkingBuild build;
    copy_references(refs.path(), {"default", "wireframe"});
    write_file(refs / (kLab + "__default.png"), bytes);
    const ProcessResult r = grade_with(build, refs.path());
    expect_usage_error(r, "labgrade: reference " + (refs / (kLab + "__default.png")).string());
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "") << "no row is graded";
    EXPECT_FALSE(build.rendered()) << message;
  }
  // A valid PNG of the wrong size: the MANIFEST says 512x512.
  ScratchDir refs("refs");
  MarkingBuild build;
  copy_references(refs.path(), {"default", "wireframe"});
  gllab::write_png((refs / (kLab + "__wireframe.png")).string(), gllab::Image(16, 16));
  const ProcessResult r = grade_with(build, refs.path());
  expect_usage_error(r, "reference " + (refs / (kLab + "__wireframe.png")).string() +
                            " is 16x16, not 512x512 (the MANIFEST's size)");
  EXPECT_FALSE(build.rendered());
}

TEST(LabgradeLimits, WithoutASizeInTheManifestTheReferencesMustAgreeOnOne) {
  ScratchDir refs("refs");
  MarkingBuild build;
  copy_references(refs.path(), {"default", "invalid_polygons", "wireframe"});
  std::string manifest = file_text(refs / "MANIFEST");
  manifest.erase(manifest.find("size: 512x512\n"), 14);
  write_file(refs / "MANIFEST", manifest);
  gllab::write_png((refs / (kLab + "__invalid_polygons.png")).string(), gllab::Image(512, 256));
  expect_usage_error(grade_with(build, refs.path()),
                     "reference " + (refs / (kLab + "__invalid_polygons.png")).string() +
                         " is 512x256, not 512x512 (the size of 2 of the 3 references)");
  EXPECT_FALSE(build.rendered());
}

TEST(LabgradeLimits, AReferenceThatIsAFifoADeviceOrAnEmptyErrorLineIsRefusedAtOnce) {
  struct Case {
    std::string file;  // in the references folder
    std::string make;  // "fifo", "dir", "zero" (a symlink to /dev/zero) or the text to write
    std::string message;
  };
  const std::vector<Case> cases = {
      {kLab + "__default.png", "fifo", "__default.png: is a FIFO, not a regular file"},
      {kLab + "__default.png", "zero", "__default.png: is a character device, not a regular file"},
      {kLab + "__default.txt", "fifo", "__default.txt: is a FIFO, not a regular file"},
      {kLab + "__default.png", "dir", "__default.png: is a directory, not a regular file"},
      {kLab + "__broken.error", "",
       "__broken.error: no line (the one line the view must exit 1 with)"},
  };
  for (const Case& c : cases) {
    ScratchDir refs("refs");
    MarkingBuild build;
    copy_references(refs.path(), {"default"});
    const fs::path file = refs / c.file;
    fs::remove(file);
    if (c.make == "fifo")
      ASSERT_EQ(mkfifo(file.c_str(), 0600), 0);
    else if (c.make == "zero")
      fs::create_symlink("/dev/zero", file);
    else if (c.make == "dir")
      fs::create_directory(file);
    else
      write_file(file, c.make);
    const ProcessResult r = grade_with(build, refs.path());
    expect_usage_error(r, "labgrade: reference " + file.string());
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(build.rendered()) << c.message;
  }
}

TEST(LabgradeLimits, AManifestFieldOutOfRangeIsAUsageErrorNamingTheFieldAndValue) {
  // {the line as the real MANIFEST has it, the line instead, the message}.
  // Ranges: grading.h parse_manifest (thresholds and contrast 0..255, shift
  // radius 0..kMaxShiftRadius = 3, shares and text tolerances 0..1).
  const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
      {"build_channel_threshold: 2", "build_channel_threshold: nan",
       "build_channel_threshold 'nan' is not an integer from 0 to 255"},
      {"build_channel_threshold: 2", "build_channel_threshold: -1",
       "build_channel_threshold '-1' is not an integer from 0 to 255"},
      {"build_channel_threshold: 2", "build_channel_threshold: 256",
       "build_channel_threshold '256' is not an integer from 0 to 255"},
      {"build_channel_threshold: 2", "build_channel_threshold: 2.5",
       "build_channel_threshold '2.5' is not an integer from 0 to 255"},
      {"images_shift_radius: 1", "images_shift_radius: 4",
       "images_shift_radius '4' is not an integer from 0 to 3"},
      {"images_edge_contrast: 13", "images_edge_contrast: 99999999999999999999",
       "images_edge_contrast '99999999999999999999' is not an integer from 0 to 255"},
      {"build_max_unexcused_share: 0.0001", "build_max_unexcused_share: nan",
       "build_max_unexcused_share 'nan' is not a number from 0 to 1"},
      {"build_max_unexcused_share: 0.0001", "build_max_unexcused_share: -0.0001",
       "build_max_unexcused_share '-0.0001' is not a number from 0 to 1"},
      {"images_max_shifted_share: 0.1", "images_max_shifted_share: 1.5",
       "images_max_shifted_share '1.5' is not a number from 0 to 1"},
      {"images_max_shifted_share: 0.1", "images_max_shifted_share: inf",
       "images_max_shifted_share 'inf' is not a number from 0 to 1"},
      {"text_relative_tolerance: 1e-06", "text_relative_tolerance: -1e-06",
       "text_relative_tolerance '-1e-06' is not a number from 0 to 1"},
      {"text_absolute_tolerance: 1e-09", "text_absolute_tolerance: 1e-09 ",
       "text_absolute_tolerance '1e-09 ' is not a number from 0 to 1"},
      {"size: 512x512", "size: 512x", "size '512x' is not WIDTHxHEIGHT, each from 1 to 4096"},
      {"size: 512x512", "size: 0x512", "size '0x512' is not WIDTHxHEIGHT, each from 1 to 4096"},
      {"build_shift_radius: 1", "build_shift_radius: 1\nbuild_shift_radius: 1",
       "build_shift_radius is given twice"},
      {"build_shift_radius: 1", "build_shift_radius=1", "is not 'key: value' or a # comment"},
      {"build_shift_radius: 1", "", "MANIFEST: no build_shift_radius"},
  };
  for (const auto& [from, to, message] : cases) {
    ScratchDir refs("refs");
    MarkingBuild build;
    copy_references(refs.path(), {"default"});
    std::string manifest = file_text(refs / "MANIFEST");
    const auto at = manifest.find(from + "\n");
    ASSERT_NE(at, std::string::npos) << from << " is not in the MANIFEST";
    manifest.replace(at, from.size(), to);
    write_file(refs / "MANIFEST", manifest);
    const ProcessResult r = grade_with(build, refs.path());
    expect_usage_error(r, message);
    EXPECT_NE(r.err.find("labgrade: " + (refs / "MANIFEST").string() + ": "), std::string::npos)
        << r.err;
    EXPECT_FALSE(build.rendered()) << message;
  }
}

TEST(LabgradeLimits, AManifestThatIsAFifoOrADirectoryIsRefusedAtOnce) {
  for (const std::string kind : {"fifo", "dir"}) {
    ScratchDir refs("refs");
    copy_references(refs.path(), {"default"});
    fs::remove(refs / "MANIFEST");
    if (kind == "fifo")
      ASSERT_EQ(mkfifo((refs / "MANIFEST").c_str(), 0600), 0);
    else
      fs::create_directory(refs / "MANIFEST");
    expect_usage_error(grade({"--build", kBinDir.string(), "--refs", refs.path().string()}),
                       (refs / "MANIFEST").string() + ": is a " +
                           (kind == "fifo" ? "FIFO" : "directory") + ", not a regular file");
  }
}

// ---- 7: a student's files must be regular files too (a failing row, not a hang) -------

TEST(LabgradeLimits, ASubmittedImageOrTextThatIsAFifoOrADeviceFailsItsViewWithoutWaiting) {
  ScratchDir images("images");
  for (const char* v : {"default", "invalid_polygons", "vertex_order", "wireframe"})
    for (const char* ext : {".png", ".txt"})
      fs::copy_file(kRefs / (kLab + "__" + v + ext), images / (kLab + "__" + v + ext));
  const fs::path fifo_png = images / (kLab + "__default.png"),
                 zero_png = images / (kLab + "__wireframe.png");
  const fs::path fifo_txt = images / (kLab + "__vertex_order.txt");
  for (const fs::path& f : {fifo_png, zero_png, fifo_txt}) fs::remove(f);
  ASSERT_EQ(mkfifo(fifo_png.c_str(), 0600), 0);
  ASSERT_EQ(mkfifo(fifo_txt.c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", zero_png);
  const ProcessResult r = grade(
      {"--images", images.path().string(), "--labs", "01", "--out", (images / "out").string()});
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_status, kSomeFailed) << r.out << r.err;
  EXPECT_NE(r.out.find(fifo_png.string() + ": is a FIFO, not a regular file"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find(zero_png.string() + ": is a character device, not a regular file"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find(fifo_txt.string() + ": is a FIFO, not a regular file"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("4 views: 1 passed, 3 failed"), std::string::npos) << r.out;
}

// ---- 5: no temporary file is left behind -------------------------------------------

TEST(LabgradeLimits, ACsvTargetThatIsADirectoryIsRefusedBeforeGradingAndLeavesNothing) {
  ScratchDir klass("class");
  fs::create_directories(klass / "anna");
  fs::create_directories(klass / "grades.csv");
  for (const char* v : {"default", "invalid_polygons", "vertex_order", "wireframe"})
    for (const char* ext : {".png", ".txt"})
      fs::copy_file(kRefs / (kLab + "__" + v + ext), klass / "anna" / (kLab + "__" + v + ext));
  const ProcessResult r = grade({"--class", klass.path().string(), "--labs", "01", "--csv",
                                 (klass / "grades.csv").string(), "--quiet"});
  expect_usage_error(r, "--csv " + (klass / "grades.csv").string() + " is a directory");
  EXPECT_EQ(r.out, "") << "refused before grading";
  EXPECT_EQ(leftovers(klass.path()), std::vector<std::string>());
  // No folder for it: refused too.
  expect_usage_error(
      grade({"--class", klass.path().string(), "--labs", "01", "--csv",
             (klass / "no" / "grades.csv").string()}),
      "--csv " + (klass / "no" / "grades.csv").string() + ": no folder " + (klass / "no").string());
}

TEST(LabgradeLimits, AReportFileThatCannotBeWrittenIsOneLineAndLeavesNoTemporaryFile) {
  ScratchDir report("report");
  // index.html is a directory: written last but one; the write fails, nothing is left.
  fs::create_directories(report / "index.html");
  ProcessResult r = grade({"--build", kBinDir.string(), "--labs", "01", "--views", "default",
                           "--report", report.path().string(), "--quiet"});
  expect_usage_error(r, "cannot write " + (report / "index.html").string() + ": it is a directory");
  EXPECT_EQ(leftovers(report.path()), std::vector<std::string>());
  // A report "folder" that is a file: refused before grading.
  ScratchDir other("other");
  write_file(other / "report", "a file\n");
  r = grade({"--build", kBinDir.string(), "--labs", "01", "--report", (other / "report").string(),
             "--quiet"});
  expect_usage_error(r, "--report " + (other / "report").string() + " is not a folder");
  EXPECT_EQ(r.out, "");
  // A full disk: /dev/full is written in place (a rename would replace the
  // device) and the failed write is an error.
  ScratchDir klass("class");
  fs::create_directories(klass / "anna");
  for (const char* ext : {".png", ".txt"})
    fs::copy_file(kRefs / (kLab + "__default" + ext), klass / "anna" / (kLab + "__default" + ext));
  r = grade({"--class", klass.path().string(), "--labs", "01", "--views", "default", "--csv",
             "/dev/full", "--quiet"});
  expect_usage_error(r, "cannot write /dev/full (No space left on device)");
  EXPECT_EQ(leftovers(klass.path()), std::vector<std::string>());
}

// ---- 6: every write to stdout is checked ---------------------------------------------

TEST(LabgradeLimits, AFailedWriteToStdoutIsAnErrorForLabgradeAndLabrun) {
  const std::string message = "standard output: write failed (No space left on device)";
  const std::string labrun = (kBinDir / "labrun").string();
  for (const std::string& command :
       {labgrade() + " --help",
        labgrade() + " --build " + kBinDir.string() + " --labs 01 --views default --quiet",
        labrun + " --help", labrun + " --check-references --labs 01"}) {
    const ProcessResult r = shell("exec " + command + " > /dev/full");
    EXPECT_EQ(r.exit_status, kUsage) << command << "\n" << r.err;
    EXPECT_EQ(line_count(r.err), 1) << command << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << command << "\n" << r.err;
  }
}

// ---- labrun: empty names are not "all" ----------------------------------------------

TEST(LabgradeLimits, AnEmptyLabOrViewNameIsAUsageErrorNotEverything) {
  const std::string labrun = (kBinDir / "labrun").string();
  for (const std::string names : {"", "01,", "01,,02", ","}) {
    expect_usage_error(
        run_process({labrun, "--check-references", "--labs", names}, {}, kCaseTimeoutSeconds),
        "--labs '" + names + "' has an empty name");
    expect_usage_error(grade({"--build", kBinDir.string(), "--views", names}),
                       "--views '" + names + "' has an empty name");
  }
}

// ---- process.h: the limits of run_process ---------------------------------------------

TEST(LabgradeProcess, OutputBeyondTheLimitIsCutThereAndTheProgramKilled) {
  // yes prints without end; 1000 bytes are kept, the program is killed (SIGKILL: 137).
  const ProcessResult r =
      run_process({"/usr/bin/yes"}, {}, gllab::ProcessLimits{kCaseTimeoutSeconds, 1000});
  EXPECT_TRUE(r.output_exceeded);
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_status, 128 + 9);
  EXPECT_EQ(r.out.size(), 1000u);
  EXPECT_EQ(r.out.substr(0, 4), "y\ny\n");
  // Within the limit nothing changes.
  const ProcessResult ok =
      run_process({"/bin/echo", "hello"}, {}, gllab::ProcessLimits{kCaseTimeoutSeconds, 1000});
  EXPECT_FALSE(ok.output_exceeded);
  EXPECT_EQ(ok.exit_status, 0);
  EXPECT_EQ(ok.out, "hello\n");
}

TEST(LabgradeProcess, AHugeOrNanTimeoutIsNoDeadlineAndDoesNotOverflow) {
  // 1e18 s is capped at kMaxProcessTimeoutSeconds (1e9 s): the deadline is in
  // the future, so a quick program is not "timed out" (before: an overflowed
  // deadline in the past killed it at once).
  for (double t : {1e18, 1e300, std::numeric_limits<double>::infinity(), std::nan("")}) {
    const ProcessResult r = run_process({"/bin/echo", "done"}, {}, t);
    EXPECT_FALSE(r.timed_out) << t;
    EXPECT_EQ(r.exit_status, 0) << t;
    EXPECT_EQ(r.out, "done\n") << t;
  }
}

}  // namespace

// ---- --hidden, --seed, --reference-build: strict, and only where they apply ----------

TEST(LabgradeLimits, HiddenInputOptionsAreStrict) {
  const std::string build = kBinDir.string();
  for (const std::string n : {"3.5", "-1", "101", "x", ""})
    expect_usage_error(grade({"--build", build, "--hidden", n}),
                       "--hidden '" + n + "' is not a whole number from 0 to 100");
  for (const std::string s : {"-1", "1e3", "18446744073709551616", "0x10"})
    expect_usage_error(grade({"--build", build, "--hidden", "1", "--seed", s}),
                       "--seed '" + s + "' is not a whole number from 0 to 9999999999999999999");
  expect_usage_error(grade({"--build", build, "--seed", "5"}), "--seed goes with --hidden N");
  expect_usage_error(grade({"--images", build, "--hidden", "1"}),
                     "--hidden needs programs to render: a build or a class, not --images");
  ScratchDir empty("empty");
  expect_usage_error(grade({"--build", build, "--labs", "01", "--hidden", "1", "--reference-build",
                            empty.path().string()}),
                     "--reference-build " + empty.path().string() +
                         " holds no lab programs (give the instructor's build)");
}
