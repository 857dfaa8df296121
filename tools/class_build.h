// tools/class_build.h — building a student's source tree for labgrade --class.
//
// A student hands in a gllab tree (a folder with the project's CMakeLists.txt).
// build_tree() configures and builds the lab programs labgrade grades, in the
// sandbox (sandbox.h) unless the instructor turned it off:
//
//   inside the sandbox          on the host
//   /submission/src   (ro)      the student's tree; its reference_images/ is hidden
//   /submission/build (rw)      WORK/builds/<student>/
//   /ccache/own       (rw)      WORK/ccache/<student>/: this student's compiler cache
//   /ccache/base      (ro)      WORK/ccache/base/: the instructor's tree, built once
//
// Every tree is built at the same paths, so the compiler sees the same
// command line for the same file, and ccache (a compiler cache, the Debian
// package ccache) can answer a student's unchanged files from the base cache.
// The base is read-only inside: a student's objects go to the student's own
// cache only, so one student's objects never feed another's. A second grading
// of the same class (a warm cache) also hits the student's own cache.
//
// The build runs `cmake -S /submission/src -B /submission/build` with
// CMAKE_BUILD_TYPE=Release (the reference build's type, so that unchanged code
// renders the same bytes), GLLAB_TESTS=OFF, GLLAB_GRADING_FIXTURES=OFF and
// ccache as the compiler launcher, then `cmake --build` of the lab programs
// being graded, nothing else.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sandbox.h"

namespace gllab::grading {

/// Is dir a source tree of this project: a CMakeLists.txt whose project()
/// is gllab? (A build holds lab programs; an image folder holds PNGs.)
bool looks_like_source(const std::filesystem::path& dir);

/// The compiler cache's counters for one build (ccache --print-stats).
struct CacheStats {
  long long hits = 0;         // answered from a cache: the student's own or the base
  long long base_hits = 0;    // of those, from the base (ccache's remote storage)
  long long misses = 0;       // compiled
  long long uncacheable = 0;  // compilations ccache does not cache (links, .incbin)
  /// hits / (hits + misses), 0 without any.
  double hit_rate() const;
};

/// Where a class's builds and caches live.
struct ClassWork {
  std::filesystem::path root;  // --work DIR
  std::filesystem::path builds() const { return root / "builds"; }
  std::filesystem::path base_cache() const { return root / "ccache" / "base"; }
  std::filesystem::path own_cache(const std::string& student) const { return root / "ccache" / student; }
};

struct TreeBuildSettings {
  std::vector<std::string> labs;  // the lab programs to build (targets)
  int jobs = 2;                   // cmake --build -j
  bool sandboxed = true;          // false: --no-sandbox, run with the grader's rights
  SandboxLimits limits;           // per build step (configure, build)
  bool use_cache = true;          // ccache
};

struct TreeBuild {
  bool ok = false;
  std::string reason;    // one line when it failed: the step, and the compiler's first error or the limit
  std::string log_tail;  // the log's last lines
  std::string log;       // all of it: the commands and what they printed
  std::filesystem::path build_dir;  // host path of the build (programs in bin/)
  CacheStats cache;
  double seconds = 0;
};

/// Configures and builds `tree` into build_dir (made empty first) as described
/// above. own_cache is this build's cache folder; base_cache is read from
/// (empty path: none). With writable_base the base is this build's cache
/// instead (the instructor's seed build). Never throws for a failing
/// student build; throws std::runtime_error when the grader cannot go on
/// (no cmake, a folder it cannot make).
TreeBuild build_tree(const std::filesystem::path& tree, const std::filesystem::path& build_dir,
                     const std::filesystem::path& own_cache, const std::filesystem::path& base_cache,
                     const TreeBuildSettings& settings, bool writable_base = false);

/// The lab programs a build made: DIR/bin/<lab>.
std::filesystem::path program_dir(const TreeBuild& b);

}  // namespace gllab::grading
