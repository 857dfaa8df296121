// tests/robustness/bad_input_test.cpp — the bad-input suite: each class of
// failure a hostile or careless user found (issue 20), with cases of our own,
// run against the built programs. For every case: the exit status, exactly
// one line on stderr that names the offending value, and nothing on stdout.
//
//   crash            a deep JSON value followed by another key (the ordered map
//                    copied it recursively and overflowed the stack)
//   no bound         a Bézier degree of 20,000; /dev/zero, a FIFO, a file over
//                    the size limit as input; 10^6 + 1 parameters in one call
//   silent success   a write to a full stdout; P[huge index]; 3.5 for a count;
//                    0.5 for a switch; --view ''; eval --at ''
// The grading tools' classes (labgrade's references, MANIFEST, --jobs,
// --timeout, temporary files) are in tests/grading.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "process.h"

namespace {

namespace fs = std::filesystem;
using gllab::ProcessResult;
using gllab::run_process;

const std::string kSplinetool = GLLAB_SPLINETOOL;
const std::string kLab = GLLAB_LAB_HEADLESS;    // 12_bezier_curves: a lab with --load and --set
const std::string kLab36 = GLLAB_LAB36_HEADLESS;  // a lab with a count and a choice
const fs::path kExamples = fs::path(GLLAB_SOURCE_DIR) / "examples";

/// A scratch folder, removed at the end.
struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("gllab_bad_input_" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name, std::ios::binary) << text;
    return (dir / name).string();
  }
};

struct Case {
  std::vector<std::string> argv;
  int status;
  std::string expected;  // a part of the one stderr line
};

void expect_one_line_failure(const Case& c) {
  std::string line;
  for (const std::string& a : c.argv) line += (a.size() > 80 ? a.substr(0, 77) + "..." : a) + " ";
  const ProcessResult r = run_process(c.argv, {}, 60.0);
  EXPECT_FALSE(r.timed_out) << line;
  EXPECT_EQ(r.exit_status, c.status) << line << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << line << "\n" << r.err;
  EXPECT_NE(r.err.find(c.expected), std::string::npos) << line << "\nstderr: " << r.err;
  EXPECT_EQ(r.out, "") << line;
}

// ---- crash ------------------------------------------------------------------------------

TEST(BadInputCrash, DeepValueFollowedByAKeyIsOneLineNotASegfault) {
  Scratch s;
  const std::string deep = std::string(300000, '[') + std::string(300000, ']');
  const std::string file =
      s.write("deep.json", R"({"type": "bezier_curve", "x": )" + deep + R"(, "points": [[0, 0], [1, 1]]})");
  for (const Case& c : {Case{{kSplinetool, "eval", file, "--at", "0.5"}, 2, "nested more than 256"},
                        Case{{kLab, "--load", file, "--out", (s.dir / "x.png").string()}, 2,
                             "nested more than 256"}})
    expect_one_line_failure(c);
  EXPECT_FALSE(fs::exists(s.dir / "x.png"));
}

// ---- no bound ---------------------------------------------------------------------------

TEST(BadInputBounds, HugeBezierDegreeIsRefusedAtOnce) {
  Scratch s;
  std::string points;
  for (int i = 0; i < 20000; ++i) points += (i ? ", [" : "[") + std::to_string(i) + ", 0]";
  const std::string file = s.write("degree.json", R"({"type": "bezier_curve", "points": [)" + points + "]}");
  expect_one_line_failure({{kSplinetool, "eval", file, "--at", "0.5"}, 2, "degree n=19999 is above the limit of 64"});
}

TEST(BadInputBounds, InputsMustBeRegularFiles) {
  Scratch s;
  const std::string fifo = (s.dir / "pipe.json").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const Case& c : {Case{{kSplinetool, "eval", "/dev/zero", "--at", "0.5"}, 2, "is a character device"},
                        Case{{kSplinetool, "eval", fifo, "--at", "0.5"}, 2, "is a FIFO, not a regular file"},
                        Case{{kSplinetool, "eval", s.dir.string(), "--at", "0.5"}, 2, "is a directory"},
                        Case{{kLab, "--load", fifo, "--out", (s.dir / "x.png").string()}, 2, "is a FIFO"},
                        Case{{kLab, "--load", "/dev/zero", "--out", (s.dir / "x.png").string()}, 2,
                             "is a character device"}})
    expect_one_line_failure(c);
}

TEST(BadInputBounds, InputsHaveASizeLimit) {
  Scratch s;
  const std::string file = s.write("big.json", std::string((8u << 20) + 1, ' '));
  expect_one_line_failure({{kSplinetool, "eval", file, "--at", "0.5"}, 2, "larger than the limit of 8388608 bytes"});
}

// --samples beyond the per-call limit (a list for --at cannot get there: the
// system's limit on one argument, 128 KiB, stops it at about 65,000 values).
TEST(BadInputBounds, ParametersPerCallHaveALimit) {
  const std::string curve = (kExamples / "bezier_2d.json").string();
  expect_one_line_failure({{kSplinetool, "eval", curve, "--samples", "1000001"}, 2, "1000001 (must be 2..1000000)"});
}

// ---- silent success ---------------------------------------------------------------------

// A write to a full disk: exit 1 with one line, for JSON, the help text, --list-views
// and --print-text alike.
TEST(BadInputSilentSuccess, AFailedWriteToStdoutIsAnError) {
  const std::string curve = (kExamples / "bezier_2d.json").string();
  const std::vector<std::vector<std::string>> runs = {
      {kSplinetool, "eval", curve, "--at", "0.5"},
      {kSplinetool, "--help"},
      {kLab, "--list-views"},
      {kLab, "--print-text", "--out", "/dev/null"}};
  for (const auto& argv : runs) {
    std::string command = "exec";
    for (std::size_t k = 0; k < argv.size(); ++k) command += " \"$" + std::to_string(k) + "\"";
    std::vector<std::string> sh = {"/bin/sh", "-c", command + " > /dev/full"};
    sh.insert(sh.end(), argv.begin(), argv.end());
    const ProcessResult r = run_process(sh, {}, 60.0);
    EXPECT_EQ(r.exit_status, 1) << argv[1] << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << argv[1] << "\n" << r.err;
    EXPECT_NE(r.err.find("standard output: write failed"), std::string::npos) << r.err;
  }
}

TEST(BadInputSilentSuccess, StrictNumbersAndNames) {
  Scratch s;
  const std::string png = (s.dir / "x.png").string();
  for (const Case& c : {
           Case{{kLab, "--set", "P[18446744073709551616]=0,0", "--out", png}, 2,
                "point P[18446744073709551616] does not exist"},
           Case{{kLab, "--set", "P[4294967296]=0,0", "--out", png}, 2, "point P[4294967296] does not exist"},
           Case{{kLab, "--view", "", "--out", png}, 2, "--view '' is empty"},
           Case{{kLab, "--set", "labels=0.5", "--out", png}, 2, "labels=0.5 is a switch: 0 or 1"},
           Case{{kLab36, "--set", "ticks=3.5", "--out", png}, 1, "ticks=3.5 is not a whole number"},
           Case{{kSplinetool, "eval", (kExamples / "bezier_2d.json").string(), "--at", ""}, 2,
                "--at '' is empty"},
       })
    expect_one_line_failure(c);
  EXPECT_FALSE(fs::exists(png));
}

}  // namespace
