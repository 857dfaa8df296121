// tests/harness/test_support.h — paths and helpers for tests that run the
// built programs. The build passes the locations in as definitions.
#pragma once

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "process.h"

namespace gllab::testing {

inline const std::filesystem::path kBinDir = GLLAB_BIN_DIR;          // build/bin
inline const std::filesystem::path kSourceDir = GLLAB_SOURCE_DIR;    // the repository
inline const std::filesystem::path kFixtureLab = GLLAB_FIXTURE_LAB;  // tests' own lab

inline std::vector<std::string> lab_ids() {
  std::vector<std::string> labs;
  std::stringstream in(GLLAB_LABS);
  for (std::string lab; std::getline(in, lab, ';');) labs.push_back(lab);
  return labs;
}

// An OSMesa build (cmake -DGLLAB_HEADLESS=osmesa) has no window: the tests that
// open one skip there, saying so. CMake defines it for the programs that run labs.
#ifndef GLLAB_HAVE_WINDOW
#define GLLAB_HAVE_WINDOW 1
#endif
#define GLLAB_SKIP_WITHOUT_WINDOW() \
  if (!GLLAB_HAVE_WINDOW) GTEST_SKIP() << "this build has no window (headless backend OSMesa)"

/// The lab's one program; --out (or --headless) makes it render headless.
inline std::string headless(const std::string& lab) { return (kBinDir / lab).string(); }

/// A fresh directory under the system temp dir, removed by the destructor.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& tag);
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// The start of a command that runs a program on a virtual X display of its
/// own: `xvfb-run -a` (a free display number), a 1024x768x24 screen, and the X
/// authority file in `dir` (-f). With -f, xvfb-run makes no temporary folder:
/// removing its own folder at exit failed now and then with window tests
/// running side by side (exit 5, "problem while cleaning up temporary
/// directory", the program's own exit status lost; seen in CI, and here in 2 of
/// about 650 runs of two window tests at once beside the class-grading test).
std::vector<std::string> xvfb_run(const ScratchDir& dir);

/// Number of lines in text (a trailing newline does not start a new line).
int line_count(const std::string& text);

/// The page after Debian's chromium (installed by ./lab) loaded it headless,
/// its scripts run: `chromium --headless --dump-dom file://PAGE`, with a
/// fresh profile and no network services. exit_status and err tell whether it ran.
gllab::ProcessResult chromium_dom(const std::filesystem::path& page);

}  // namespace gllab::testing
