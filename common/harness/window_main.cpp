// common/harness/window_main.cpp — <lab>: the lab in a freeglut window.
//
// Keys of the runner: [v]/[V] view, [h] help overlay, [p] print the headless
// command for what is on screen, [Esc] quit. Everything else goes to the lab.
#include <X11/Xlib.h>
#include <GL/freeglut.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "gl/check.h"
#include "gl/gl.h"
#include "harness/frame.h"
#include "harness/lab.h"
#include "harness/options.h"
#include "image/image.h"

namespace {

// GLUT callbacks take no user pointer, so the runner keeps its state here.
struct WindowState {
  gllab::Lab lab;
  std::optional<gllab::State> state;
  std::string program;
  std::string capture;                  // --capture FILE: write the first frame, exit
  std::vector<std::string> errors;      // shown on screen until the next key
  int exit_status = 0;
  double start_time = 0;                // --time: where an animated lab's clock starts
  bool shut_down = false;               // lab.shutdown() has run
};
WindowState* g_window = nullptr;

void update_title() {
  const std::string title = g_window->lab.title + "  -  view: " + g_window->state->view() +
                            "   ([v] next view, [h] help)";
  glutSetWindowTitle(title.c_str());
}

// Leave glutMainLoop and return from main(), so freeglut destroys the window
// and its GL context (std::exit would leave them to the leak checker).
void quit(int status) {
  g_window->exit_status = status;
  glutLeaveMainLoop();
}

void display() {
  WindowState& w = *g_window;
  gllab::draw_frame(w.lab, *w.state);
  for (std::string& e : gllab::take_frame_errors()) {
    if (std::find(w.errors.begin(), w.errors.end(), e) != w.errors.end()) continue;  // shown already
    std::fprintf(stderr, "%s: %s\n", w.program.c_str(), e.c_str());
    w.errors.push_back(std::move(e));
  }
  if (!w.errors.empty()) gllab::draw_error_lines(w.errors);
  if (!w.capture.empty()) {
    // Read the back buffer: exactly what the lab drew, before the swap.
    glFinish();
    std::vector<std::uint8_t> rows(static_cast<std::size_t>(w.state->width) * w.state->height * 4);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w.state->width, w.state->height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    int status = w.errors.empty() ? 0 : 1;
    try {
      gllab::write_png(w.capture, gllab::image_from_bottom_up(rows.data(), w.state->width, w.state->height));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", w.program.c_str(), e.what());
      status = 1;
    }
    quit(status);
    return;
  }
  glutSwapBuffers();
}

void reshape(int width, int height) {
  g_window->state->width = width;
  g_window->state->height = height;
}

void keyboard(unsigned char key, int, int) {
  WindowState& w = *g_window;
  gllab::State& s = *w.state;
  w.errors.clear();
  switch (key) {
    case 27: quit(0); return;
    case 'h': s.help = !s.help; break;
    case 'v': s.next_view(+1); break;
    case 'V': s.next_view(-1); break;
    case 'p': {
      // An animated lab's picture also depends on the clock: print it too.
      char time[48] = "";
      if (w.lab.animated) std::snprintf(time, sizeof time, " --time %.3f", s.time);
      std::printf("./lab render %s %s%s --out %s.png\n", w.lab.id.c_str(), s.as_arguments().c_str(), time,
                  s.view().c_str());
      std::fflush(stdout);
      return;
    }
    default:
      if (!gllab::apply_key(w.lab, s, key)) return;
  }
  update_title();
  glutPostRedisplay();
}

// lab.shutdown() needs the window's context current: freeglut runs the close
// callback so when the user closes the window; after glutLeaveMainLoop the
// window still exists and main() calls this itself.
void shut_down_lab() {
  WindowState& w = *g_window;
  if (w.shut_down || !w.lab.shutdown) return;
  w.shut_down = true;
  w.lab.shutdown();
  gllab::check_gl_errors("in shutdown()");
  for (const std::string& e : gllab::take_frame_errors()) {
    std::fprintf(stderr, "%s: %s\n", w.program.c_str(), e.c_str());
    w.exit_status = 1;
  }
}

// Animated labs: the clock runs from --time on, about 60 frames a second.
// A --capture run keeps the first frame's time, like a headless run.
void tick(int) {
  WindowState& w = *g_window;
  w.state->time = w.start_time + glutGet(GLUT_ELAPSED_TIME) / 1000.0;
  glutPostRedisplay();
  glutTimerFunc(16, tick, 0);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string program = gllab::program_name(argv[0]);
  auto fail = [&](int status, const std::string& message) {
    std::fprintf(stderr, "%s: %s\n", program.c_str(), message.c_str());
    return status;
  };
  static WindowState window;
  g_window = &window;
  window.program = program;
  try {
    window.lab = gllab::define_lab();
    gllab::validate_lab(window.lab);
    const gllab::Options options = gllab::parse_options(
        std::vector<std::string>(argv + 1, argv + argc), gllab::Runner::kWindow);
    if (options.help) {
      std::fputs(gllab::usage_text(window.lab, program, gllab::Runner::kWindow).c_str(), stdout);
      return 0;
    }
    if (options.list_views) {
      for (const gllab::View& v : window.lab.views) std::printf("%s\n", v.name.c_str());
      return 0;
    }
    window.state = gllab::make_state(window.lab, options);
    window.state->interactive = true;
    window.start_time = options.time;
    window.capture = options.out;
  } catch (const gllab::UsageError& e) {
    return fail(2, e.what());
  } catch (const std::exception& e) {
    return fail(1, e.what());
  }

  // freeglut exits 1 with "failed to open display ''" when there is none;
  // say what to do instead.
  // Keep this connection open until the window exists: an X server with no
  // clients left resets, and a connection made during the reset fails.
  Display* x_display = XOpenDisplay(nullptr);
  if (!x_display) {
    return fail(2, "cannot open a window: no X display (DISPLAY='" +
                       std::string(std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "") +
                       "'); render headless instead: build/bin/" + window.lab.id +
                       "_headless --view " + window.state->view() + " --out " +
                       window.state->view() + ".png (or run under xvfb-run -a)");
  }

  int glut_argc = 1;  // our options are parsed already; GLUT sees none of them
  glutInit(&glut_argc, argv);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA | GLUT_DEPTH);
  glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
  glutInitWindowSize(window.state->width, window.state->height);
  glutCreateWindow(window.lab.title.c_str());
  XCloseDisplay(x_display);
  if (glGetString(GL_RENDERER) == nullptr) return fail(1, "GL_RENDERER is null: no usable GL context");
  update_title();
  if (window.lab.init) window.lab.init();
  gllab::check_gl_errors("in init()");
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutKeyboardFunc(keyboard);
  glutCloseFunc(shut_down_lab);
  if (window.lab.animated && window.capture.empty()) glutTimerFunc(16, tick, 0);
  glutMainLoop();
  if (glutGetWindow() != 0) shut_down_lab();
  return window.exit_status;
}
