// common/harness/window_main.cpp — <lab> without --headless: the lab in a freeglut window.
//
// Keys of the runner: [v]/[V] view, [h] help overlay, [p] print the headless
// command for what is on screen, [Ctrl+S] save the lab's curve or surface
// (model_file.h), [0] reset the camera of a 3D view, [Esc] quit. Everything
// else goes to the lab. The left mouse button drags the points of the lab's
// point lists (gl/pick.h); in a 3D view (kOrbit) the right button turns the
// camera and the wheel zooms (State::camera).
#include <X11/Xlib.h>
#include <GL/freeglut.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "files/files.h"
#include "gl/check.h"
#include "gl/gl.h"
#include "gl/glut_shapes.h"
#include "gl/pick.h"
#include "gl/text.h"
#include "harness/frame.h"
#include "harness/lab.h"
#include "harness/model_file.h"
#include "harness/options.h"
#include "harness/runners.h"
#include "image/image.h"

namespace {

// GLUT callbacks take no user pointer, so the runner keeps its state here.
struct WindowState {
  gllab::Lab lab;
  std::optional<gllab::State> state;
  std::string program;
  std::string capture;                  // --capture FILE: write the first frame, exit
  std::string capture_views;            // --capture-views DIR: every view's first frame, then exit
  std::vector<std::string> errors;      // shown on screen until the next key
  int exit_status = 0;
  double start_time = 0;                // --time: where an animated lab's clock starts
  bool shut_down = false;               // lab.shutdown() has run
  std::optional<gllab::Pickable> drag;  // the point the left button holds
  std::string notice;                   // one line for the user (a file saved), until the next key
  std::string capture_at_exit;          // --capture-at-exit FILE: the last frame, written at the end
  std::vector<std::uint8_t> last_frame; // its pixels, bottom-up RGBA (only with --capture-at-exit)
  int frames = 0;                       // --frames N: frames to time after the first
  int frames_drawn = 0;
  std::chrono::steady_clock::time_point frames_start;
  // A right-button drag of the camera: where it started, in GLUT pixels.
  struct Turn {
    int x = 0, y = 0;
    gllab::Camera from;
  };
  std::optional<Turn> turn;
};

// How near (pixels) the mouse must be to a point to grab it.
constexpr double kPickPixels = 12;
// The orbit camera: degrees per pixel of a right-button drag, and the zoom
// factor of one wheel step. Angles snap to 1/2 degree and the zoom to 1/100,
// decimals that the printed --camera reads back exactly (like snap_to_grid).
constexpr double kDegreesPerPixel = 0.5;
constexpr double kZoomPerStep = 1.25;
double snap_angle(double degrees) { return std::round(degrees * 2) / 2; }
double snap_zoom(double zoom) { return std::clamp(std::round(zoom * 100) / 100, gllab::kMinZoom, gllab::kMaxZoom); }
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

// "P[3] = (1.234, 0.5)" for the point being dragged.
std::string drag_text(const WindowState& w) {
  const gllab::Pickable& d = *w.drag;
  const gllab::spline::Vec3 p = w.state->points(d.list)[d.index];
  char text[160];
  if (d.dimension == 3) std::snprintf(text, sizeof text, "%s[%zu] = (%.3f, %.3f, %.3f)", d.list.c_str(), d.index, p.x, p.y, p.z);
  else std::snprintf(text, sizeof text, "%s[%zu] = (%.3f, %.3f)", d.list.c_str(), d.index, p.x, p.y);
  return text;
}

// "camera yaw=30 pitch=-15 zoom=1.25" while the right button turns it.
std::string camera_text(const gllab::State& s) {
  char text[128];
  std::snprintf(text, sizeof text, "camera yaw=%g pitch=%g zoom=%g", s.camera.yaw, s.camera.pitch, s.camera.zoom);
  return text;
}

void display() {
  WindowState& w = *g_window;
  gllab::clear_pickables();
  gllab::draw_frame(w.lab, *w.state);
  for (std::string& e : gllab::take_frame_errors()) {
    if (std::find(w.errors.begin(), w.errors.end(), e) != w.errors.end()) continue;  // shown already
    std::fprintf(stderr, "%s: %s\n", w.program.c_str(), e.c_str());
    w.errors.push_back(std::move(e));
  }
  if (!w.errors.empty()) gllab::draw_error_lines(w.errors);
  if (w.drag) gllab::draw_text_panel(8, w.state->height - 32, {drag_text(w)}, {1.f, 1.f, 0.6f});
  else if (w.turn) gllab::draw_text_panel(8, w.state->height - 32, {camera_text(*w.state)}, {1.f, 1.f, 0.6f});
  else if (!w.notice.empty()) gllab::draw_text_panel(8, w.state->height - 32, {w.notice}, {0.7f, 1.f, 0.7f});
  if (!w.capture_at_exit.empty()) {
    glFinish();
    w.last_frame.resize(static_cast<std::size_t>(w.state->width) * w.state->height * 4);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w.state->width, w.state->height, GL_RGBA, GL_UNSIGNED_BYTE, w.last_frame.data());
  }
  if (!w.capture.empty() || !w.capture_views.empty()) {
    // Read the back buffer: exactly what the lab drew, before the swap.
    glFinish();
    std::vector<std::uint8_t> rows(static_cast<std::size_t>(w.state->width) * w.state->height * 4);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w.state->width, w.state->height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    int status = w.errors.empty() ? 0 : 1;
    const std::string file = !w.capture.empty() ? w.capture
                                                : w.capture_views + "/" + w.lab.id + "__" + w.state->view() + ".png";
    try {
      gllab::write_png(file, gllab::image_from_bottom_up(rows.data(), w.state->width, w.state->height));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", w.program.c_str(), e.what());
      status = 1;
    }
    w.exit_status = std::max(w.exit_status, status);
    // --capture-views: the next view, until every one is written (error
    // views exist to fail, headless too: they have no picture to compare).
    std::size_t next = w.state->view_index() + 1;
    while (!w.capture_views.empty() && next < w.state->views().size() && w.state->views()[next].expect_error())
      ++next;
    if (!w.capture_views.empty() && next < w.state->views().size()) {
      w.errors.clear();
      w.state->select_view(w.state->views()[next].name);
      glutPostRedisplay();
      return;
    }
    quit(w.exit_status);
    return;
  }
  glutSwapBuffers();
  if (w.frames > 0) {
    // --frames N: the first frame warms up (caches, meshes made once); the N after it are timed,
    // each to the end of its drawing (glFinish), swap included.
    glFinish();
    const auto now = std::chrono::steady_clock::now();
    if (w.frames_drawn++ == 0) w.frames_start = now;
    if (w.frames_drawn > w.frames) {
      const double s = std::chrono::duration<double>(now - w.frames_start).count();
      std::printf("%d frames of view %s in %.3f s: %.1f ms per frame, %.1f frames/s\n", w.frames,
                  w.state->view().c_str(), s, 1000 * s / w.frames, w.frames / s);
      std::fflush(stdout);
      quit(w.exit_status);
      return;
    }
    glutPostRedisplay();
  }
}

void reshape(int width, int height) {
  g_window->state->width = width;
  g_window->state->height = height;
}

void keyboard(unsigned char key, int, int) {
  WindowState& w = *g_window;
  gllab::State& s = *w.state;
  w.errors.clear();
  w.notice.clear();
  switch (key) {
    case 27: quit(0); return;
    case 19: {  // Ctrl+S: the lab's curve or surface as a spline file
      if (!w.lab.model) return;
      const std::string file = gllab::model_file_name(w.lab, s);
      try {
        gllab::save_model(w.lab, s, file);
      } catch (const std::exception& e) {
        w.errors.push_back(e.what());
        std::fprintf(stderr, "%s: %s\n", w.program.c_str(), e.what());
        glutPostRedisplay();
        return;
      }
      // The --set values stay: --load checks the file against them.
      std::printf("./lab render %s %s --load %s --out %s.png\n", w.lab.id.c_str(), s.as_arguments().c_str(),
                  file.c_str(), s.view().c_str());
      std::fflush(stdout);
      w.notice = "saved " + file + " (the command is on stdout)";
      break;
    }
    case 'h': s.help = !s.help; break;
    case '0':
      if (!s.current_view().orbit()) return;
      s.camera = gllab::Camera{};
      break;
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

// GLUT gives window pixels with y down; GL's window coordinates have y up.
double gl_y(int y) { return g_window->state->height - 1 - y; }

// The wheel arrives as buttons 3 (up: closer) and 4 (down) when no wheel
// callback is set (freeglut); the right button turns the camera.
void orbit_mouse(int button, int button_state, int x, int y) {
  WindowState& w = *g_window;
  gllab::State& s = *w.state;
  if (!s.current_view().orbit()) return;
  if ((button == 3 || button == 4) && button_state == GLUT_DOWN) {
    s.camera.zoom = snap_zoom(button == 3 ? s.camera.zoom * kZoomPerStep : s.camera.zoom / kZoomPerStep);
  } else if (button == GLUT_RIGHT_BUTTON && button_state == GLUT_DOWN) {
    w.turn = WindowState::Turn{x, y, s.camera};
  } else if (button == GLUT_RIGHT_BUTTON && w.turn) {
    std::printf("%s\n", camera_text(s).c_str());  // where it was let go
    std::fflush(stdout);
    w.turn.reset();
  } else {
    return;
  }
  w.errors.clear();
  glutPostRedisplay();
}

void mouse(int button, int button_state, int x, int y) {
  WindowState& w = *g_window;
  if (button != GLUT_LEFT_BUTTON) return orbit_mouse(button, button_state, x, y);
  if (button_state == GLUT_DOWN) {
    w.drag = gllab::nearest_pickable(x, gl_y(y), kPickPixels);
  } else if (w.drag) {
    std::printf("%s\n", drag_text(w).c_str());  // where it was let go
    std::fflush(stdout);
    w.drag.reset();
  }
  glutPostRedisplay();
}

// Moves the held point under the mouse, snapped to the grid (lab.h) so that
// the printed --set line reproduces it exactly.
void motion(int x, int y) {
  WindowState& w = *g_window;
  if (w.turn) {
    gllab::Camera& c = w.state->camera;
    c.yaw = snap_angle(w.turn->from.yaw + kDegreesPerPixel * (x - w.turn->x));
    c.pitch = snap_angle(w.turn->from.pitch + kDegreesPerPixel * (y - w.turn->y));
    glutPostRedisplay();
    return;
  }
  if (!w.drag) return;
  const std::optional<gllab::spline::Vec3> to = gllab::drag_to(*w.drag, x, gl_y(y));
  if (!to) return;
  using gllab::snap_to_grid;
  const gllab::spline::Vec3 p = {snap_to_grid(to->x), snap_to_grid(to->y),
                                 w.drag->dimension == 3 ? snap_to_grid(to->z) : w.drag->point.z};
  w.errors.clear();
  w.state->move_point(w.drag->list, w.drag->index, p);
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

int gllab::run_window(int argc, char** argv) {
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
      std::fputs(gllab::usage_text(window.lab, program).c_str(), stdout);
      gllab::files::finish_stdout();  // a full disk or a closed pipe: exit 1, one line
      return 0;
    }
    if (options.list_views || options.list_params) {
      std::fputs(gllab::listing_text(window.lab, options).c_str(), stdout);
      gllab::files::finish_stdout();
      return 0;
    }
    window.state = gllab::make_state(window.lab, options);
    // A capture is a test of what headless draws: no live numbers in it.
    window.state->interactive = options.out.empty() && options.capture_views.empty();
    window.start_time = options.time;
    window.capture = options.out;
    window.capture_views = options.capture_views;
    window.capture_at_exit = options.capture_at_exit;
    window.frames = options.frames;
    if (!window.capture_views.empty()) window.state->select_view(window.lab.views.front().name);
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
                       " --headless --view " + window.state->view() + " --out " +
                       window.state->view() + ".png (or run under xvfb-run -a)");
  }

  int glut_argc = 1;  // our options are parsed already; GLUT sees none of them
  glutInit(&glut_argc, argv);
  gllab::use_freeglut_shapes();  // freeglut is initialised: its own glutSolid* from now on
  // A stencil buffer too: lab 33's CSG counts surfaces in it (8 bits on llvmpipe).
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA | GLUT_DEPTH | GLUT_STENCIL);
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
  glutMouseFunc(mouse);
  glutMotionFunc(motion);
  gllab::enable_picking(true);
  glutCloseFunc(shut_down_lab);
  if (window.lab.animated && window.capture.empty() && window.capture_views.empty()) glutTimerFunc(16, tick, 0);
  glutMainLoop();
  if (glutGetWindow() != 0) shut_down_lab();
  if (!window.capture_at_exit.empty()) {
    try {
      if (window.last_frame.empty()) throw std::runtime_error("no frame was shown");
      gllab::write_png(window.capture_at_exit, gllab::image_from_bottom_up(window.last_frame.data(),
                                                                           window.state->width, window.state->height));
    } catch (const std::exception& e) {
      return fail(1, "--capture-at-exit " + window.capture_at_exit + ": " + e.what());
    }
  }
  return window.exit_status;
}
