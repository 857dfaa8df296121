// tools/class_build.cpp — configure and build a student's tree (class_build.h).
#include "class_build.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "process.h"

namespace fs = std::filesystem;

namespace gllab::grading {

namespace {

const char kSource[] = "/submission/src";
const char kBuild[] = "/submission/build";
const char kOwnCache[] = "/ccache/own";
const char kBaseCache[] = "/ccache/base";

// The last `count` lines of text.
std::string last_lines(const std::string& text, int count) {
  std::size_t at = text.size();
  while (at > 0 && text[at - 1] == '\n') --at;
  for (int k = 0; k < count && at > 0; ++k) {
    const std::size_t nl = text.rfind('\n', at - 1);
    if (nl == std::string::npos) return text.substr(0, text.find_last_not_of('\n') + 1);
    at = nl;
    if (k + 1 == count) return text.substr(at + 1, text.find_last_not_of('\n') - at);
  }
  return text.substr(0, text.find_last_not_of('\n') + 1);
}

// The first line that reads like a compiler's or CMake's error, else "".
// CMake says what went wrong on the next line that is not empty.
std::string first_error(const std::string& log) {
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("CMake Error", 0) == 0)
      for (std::string next; std::getline(in, next);)
        if (next.find_first_not_of(' ') != std::string::npos) {
          line += " " + next.substr(next.find_first_not_of(' '));
          break;
        }
    if (line.find("error:") != std::string::npos || line.rfind("CMake Error", 0) == 0 ||
        line.find("undefined reference") != std::string::npos)
      return line.size() > 240 ? line.substr(0, 240) + "..." : line;
  }
  return "";
}

struct Step {
  ProcessResult process;
  std::string limit_hit;
};

}  // namespace

bool looks_like_source(const fs::path& dir) {
  std::error_code ec;
  const fs::path lists = dir / "CMakeLists.txt";
  if (!fs::is_regular_file(lists, ec) || fs::file_size(lists, ec) > (1u << 20)) return false;
  std::ifstream in(lists);
  std::stringstream text;
  text << in.rdbuf();
  // "project(gllab", spaces allowed around the parenthesis.
  const std::string t = text.str();
  for (std::size_t at = t.find("project"); at != std::string::npos; at = t.find("project", at + 1)) {
    std::size_t k = t.find_first_not_of(" \t", at + 7);
    if (k == std::string::npos || t[k] != '(') continue;
    k = t.find_first_not_of(" \t\n", k + 1);
    if (k != std::string::npos && t.compare(k, 5, "gllab") == 0 &&
        (k + 5 == t.size() || !(std::isalnum(static_cast<unsigned char>(t[k + 5])) || t[k + 5] == '_')))
      return true;
  }
  return false;
}

double CacheStats::hit_rate() const {
  return hits + misses > 0 ? double(hits) / double(hits + misses) : 0;
}

fs::path program_dir(const TreeBuild& b) { return b.build_dir / "bin"; }

TreeBuild build_tree(const fs::path& tree, const fs::path& build_dir, const fs::path& own_cache,
                     const fs::path& base_cache, const TreeBuildSettings& settings, bool writable_base) {
  const auto start = std::chrono::steady_clock::now();
  TreeBuild b;
  b.build_dir = build_dir;
  std::error_code ec;
  fs::remove_all(build_dir, ec);
  fs::create_directories(build_dir, ec);
  if (ec) throw std::runtime_error("cannot make the build folder " + build_dir.string() + " (" + ec.message() + ")");
  if (settings.use_cache) {
    fs::create_directories(own_cache, ec);
    if (!base_cache.empty()) fs::create_directories(base_cache, ec);
    if (ec) throw std::runtime_error("cannot make the cache folder " + own_cache.string() + " (" + ec.message() + ")");
  }

  // Paths as the build sees them: fixed inside the sandbox, the host's without it.
  const bool box = settings.sandboxed;
  const std::string src = box ? kSource : fs::absolute(tree).string();
  const std::string bld = box ? kBuild : fs::absolute(build_dir).string();
  const std::string own = box ? kOwnCache : fs::absolute(own_cache).string();
  const std::string base = box ? kBaseCache : fs::absolute(base_cache).string();

  std::vector<std::string> env;
  if (settings.use_cache) {
    env = {"CCACHE_DIR=" + own, "CCACHE_TEMPDIR=" + own + "/tmp", "CCACHE_NOHASHDIR=1"};
    if (!base_cache.empty())
      env.push_back("CCACHE_REMOTE_STORAGE=file://" + base + (writable_base ? "" : "|read-only"));
  }
  Sandbox sandbox;
  sandbox.mounts = {{fs::absolute(tree), kSource, false}, {fs::absolute(build_dir), kBuild, true}};
  sandbox.hidden = {std::string(kSource) + "/reference_images"};
  if (settings.use_cache) {
    sandbox.mounts.push_back({fs::absolute(own_cache), kOwnCache, true});
    if (!base_cache.empty()) sandbox.mounts.push_back({fs::absolute(base_cache), kBaseCache, writable_base});
  }
  sandbox.limits = settings.limits;
  sandbox.env = env;
  sandbox.chdir = kBuild;

  std::string log;
  const auto run = [&](const std::vector<std::string>& argv, bool logged = true) {
    if (logged) {
      log += "$";
      for (const std::string& a : argv) log += " " + a;
      log += "\n";
    }
    Step s;
    if (box) {
      SandboxResult r = run_sandboxed(argv, sandbox);
      s.process = std::move(r.process);
      s.limit_hit = r.limit_hit;
    } else {
      s.process = run_process(argv, env,
                              ProcessLimits{settings.limits.wall_seconds, settings.limits.max_output_bytes});
      if (s.process.timed_out) s.limit_hit = "wall-clock limit reached";
    }
    if (logged) log += s.process.out + s.process.err;
    return s;
  };
  const auto fail = [&](const std::string& step, const Step& s) {
    b.ok = false;
    std::string why = !s.limit_hit.empty() ? s.limit_hit
                      : !s.process.started ? first_line(s.process.err)
                                           : first_error(s.process.out + "\n" + s.process.err);
    if (why.empty()) why = "exit status " + std::to_string(s.process.exit_status);
    b.reason = step + " failed: " + why;
  };

  if (settings.use_cache) run({"ccache", "--zero-stats"}, false);
  std::vector<std::string> configure = {"cmake", "-S", src, "-B", bld, "-DCMAKE_BUILD_TYPE=Release",
                                        "-DGLLAB_TESTS=OFF", "-DGLLAB_GRADING_FIXTURES=OFF"};
  // Ninja when it is installed: a build whose every object is a cache hit
  // then takes 3.9 s instead of make's 18.5 s (36 lab programs, 2 jobs),
  // which spends it checking the dependencies of every target it is given.
  std::error_code ninja_ec;
  if (fs::exists("/usr/bin/ninja", ninja_ec)) configure.insert(configure.begin() + 1, {"-G", "Ninja"});
  if (settings.use_cache)
    configure.insert(configure.end(),
                     {"-DCMAKE_C_COMPILER_LAUNCHER=ccache", "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"});
  const Step c = run(configure);
  if (c.process.exit_status != 0 || !c.limit_hit.empty()) {
    fail("configure", c);
  } else {
    std::vector<std::string> build = {"cmake", "--build", bld, "-j", std::to_string(std::max(1, settings.jobs)),
                                      "--target"};
    build.insert(build.end(), settings.labs.begin(), settings.labs.end());
    const Step m = run(build);
    if (m.process.exit_status != 0 || !m.limit_hit.empty()) fail("build", m);
    else b.ok = true;
  }
  if (settings.use_cache) {
    const Step stats = run({"ccache", "--print-stats"}, false);
    std::istringstream in(stats.process.out);
    for (std::string key, value; in >> key >> value;) {
      const long long n = std::atoll(value.c_str());
      if (key == "direct_cache_hit" || key == "preprocessed_cache_hit") b.cache.hits += n;
      else if (key == "remote_storage_hit") b.cache.base_hits += n;
      else if (key == "cache_miss") b.cache.misses += n;
      else if (key == "could_not_use_precompiled_header" || key == "unsupported_code_directive" ||
               key == "called_for_link" || key == "no_input_file")
        b.cache.uncacheable += n;
    }
  }
  b.log_tail = last_lines(log, 20);
  b.log = std::move(log);
  b.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return b;
}

}  // namespace gllab::grading
