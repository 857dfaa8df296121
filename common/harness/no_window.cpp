// common/harness/no_window.cpp — run_window in a build whose headless backend is
// OSMesa (cmake -DGLLAB_HEADLESS=osmesa). libOSMesa exports every gl* function
// itself, so a program that links it must not link libGL as well (docs/platform.md,
// "The OSMesa backend: headless only"): that build renders headless and has no window.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "files/files.h"
#include "harness/lab.h"
#include "harness/options.h"
#include "harness/runners.h"

int gllab::run_window(int argc, char** argv) {
  const std::string program = program_name(argv[0]);
  try {
    const Lab lab = define_lab();
    validate_lab(lab);
    const Options options = parse_options(std::vector<std::string>(argv + 1, argv + argc), Runner::kWindow);
    // --help, --list-views and --list-params need no window.
    if (options.help || options.list_views || options.list_params) {
      const std::string text = options.help ? usage_text(lab, program) : listing_text(lab, options);
      std::fputs(text.c_str(), stdout);
      files::finish_stdout();
      return 0;
    }
    const State state = make_state(lab, options);
    std::fprintf(stderr,
                 "%s: this build has no window (its headless backend is OSMesa, which cannot share a "
                 "program with libGL); render headless: %s --headless --view %s --out %s.png, or "
                 "build with EGL (cmake -DGLLAB_HEADLESS=egl)\n",
                 program.c_str(), program.c_str(), state.view().c_str(), state.view().c_str());
    return 2;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "%s: %s\n", program.c_str(), e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", program.c_str(), e.what());
    return 1;
  }
}
