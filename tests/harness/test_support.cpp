// tests/harness/test_support.cpp
#include "test_support.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>

namespace gllab::testing {

ScratchDir::ScratchDir(const std::string& tag) {
  static std::atomic<int> counter{0};
  path_ = std::filesystem::temp_directory_path() /
          ("gllab-" + tag + "-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

int line_count(const std::string& text) {
  if (text.empty()) return 0;
  const auto n = std::count(text.begin(), text.end(), '\n');
  return static_cast<int>(text.back() == '\n' ? n : n + 1);
}

std::vector<std::string> xvfb_run(const ScratchDir& dir) {
  return {"/usr/bin/xvfb-run", "-a", "-f", (dir / "xvfb-run.Xauthority").string(), "-s",
          "-screen 0 1024x768x24"};
}

gllab::ProcessResult chromium_dom(const std::filesystem::path& page) {
  const ScratchDir profile("chromium");
  return run_process({"/usr/bin/chromium", "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                      "--no-first-run", "--disable-background-networking", "--disable-component-update",
                      "--disable-sync", "--user-data-dir=" + profile.path().string(), "--virtual-time-budget=10000",
                      "--dump-dom", "file://" + page.string()},
                     {}, 120);
}

}  // namespace gllab::testing
