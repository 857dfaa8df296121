// common/harness/headless_main.cpp — <lab>_headless: one view to PNG, no display.
//
// Exit status: 0 written; 1 GL or GLU error, context failure or unwritable
// file; 2 bad command line. Every failure is one line on stderr.
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "gl/check.h"
#include "gl/gl.h"
#include "gl/text.h"
#include "harness/frame.h"
#include "harness/lab.h"
#include "harness/offscreen.h"
#include "harness/options.h"
#include "image/image.h"

int main(int argc, char** argv) {
  const std::string program = gllab::program_name(argv[0]);
  auto fail = [&](int status, const std::string& message) {
    std::fprintf(stderr, "%s: %s\n", program.c_str(), message.c_str());
    return status;
  };
  try {
    const gllab::Lab lab = gllab::define_lab();
    gllab::validate_lab(lab);
    gllab::Options options;
    std::optional<gllab::State> parsed;
    try {
      options = gllab::parse_options(std::vector<std::string>(argv + 1, argv + argc),
                                     gllab::Runner::kHeadless);
      if (options.help) {
        std::fputs(gllab::usage_text(lab, program, gllab::Runner::kHeadless).c_str(), stdout);
        return 0;
      }
      if (options.list_views) {
        std::fputs(gllab::list_views_text(lab).c_str(), stdout);
        return 0;
      }
      parsed = gllab::make_state(lab, options);
    } catch (const gllab::UsageError& e) {
      return fail(2, e.what());
    }

    const gllab::State& state = *parsed;
    gllab::OffscreenContext context(state.width, state.height);
    if (options.info) {
      std::printf("renderer: %s\ngl_version: %s\nglu_version: %s\n", context.renderer().c_str(),
                  reinterpret_cast<const char*>(glGetString(GL_VERSION)),
                  reinterpret_cast<const char*>(gluGetString(GLU_VERSION)));
      return 0;
    }
    if (lab.init) lab.init();
    gllab::check_gl_errors("in init()");
    gllab::record_text(options.print_text);
    gllab::draw_frame(lab, state);
    gllab::record_text(false);
    glFinish();
    gllab::check_gl_errors("after the frame");
    const std::vector<std::string> errors = gllab::take_frame_errors();
    if (!errors.empty()) {
      std::string more = errors.size() > 1 ? " (+" + std::to_string(errors.size() - 1) + " more)" : "";
      return fail(1, "view '" + state.view() + "': " + errors.front() + more);
    }
    const gllab::Image image = context.read_pixels();
    if (lab.shutdown) {
      lab.shutdown();
      gllab::check_gl_errors("in shutdown()");
      const std::vector<std::string> late = gllab::take_frame_errors();
      if (!late.empty()) return fail(1, late.front());
    }
    gllab::write_png(options.out, image);
    for (const std::string& line : gllab::take_recorded_text()) std::printf("%s\n", line.c_str());
    return 0;
  } catch (const std::exception& e) {
    return fail(1, e.what());
  }
}
