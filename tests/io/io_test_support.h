// tests/io/io_test_support.h — where the tests find the example and bad files,
// the table of expected errors (tests/io/bad/EXPECTED.txt), a scratch directory.
#pragma once

#include <unistd.h>

#include <atomic>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace gllab::io::testing {

inline const std::filesystem::path kSourceDir = GLLAB_SOURCE_DIR;  // the repository
inline const std::filesystem::path kExamplesDir = kSourceDir / "examples";
inline const std::filesystem::path kBadDir = kSourceDir / "tests" / "io" / "bad";

inline std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// One line of EXPECTED.txt: a bad file and a substring its one-line error
/// must contain (the JSON path and the problem, or the line and column).
struct BadFile {
  std::string file, expected;
};
/// How GoogleTest shows a case (instead of its bytes).
inline void PrintTo(const BadFile& b, std::ostream* out) { *out << b.file; }

inline std::vector<BadFile> bad_files() {
  std::vector<BadFile> out;
  std::istringstream in(read_file(kBadDir / "EXPECTED.txt"));
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t tab = line.find('\t');
    if (tab == std::string::npos) throw std::runtime_error("EXPECTED.txt: no tab in: " + line);
    out.push_back({line.substr(0, tab), line.substr(tab + 1)});
  }
  return out;
}

/// A GoogleTest-safe name for a file: letters, digits and underscores.
inline std::string test_name(const std::string& file) {
  std::string name = file.substr(0, file.rfind('.'));
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

/// A fresh directory under the system temp dir, removed by the destructor.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& tag) {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("gllab-io-" + tag + "-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace gllab::io::testing
