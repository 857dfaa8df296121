// common/harness/options.h — the command line both runners share.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "harness/lab.h"

namespace gllab {

/// Bad command-line input: the runner prints what() as one line and exits 2.
struct UsageError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// One program per lab runs in one of two ways: a freeglut window, or headless
/// (no display: one frame to PNG, harness/offscreen.h).
enum class Runner { kWindow, kHeadless };

struct Options {
  std::string view;                 // empty: the lab's first view
  std::vector<std::string> views;   // --views a,b,c (headless, with --out -): several in one run
  int width = 512, height = 512;    // --size WxH
  std::string out;                  // --out FILE (headless), --capture FILE (window)
  std::string capture_views;        // --capture-views DIR (window): every view to DIR/<lab>__<view>.png
  std::string capture_at_exit;      // --capture-at-exit FILE (window): the last frame shown, when it closes
  int frames = 0;                   // --frames N (window): draw N frames, print the frame rate, exit
  std::string camera;               // --camera yaw,pitch,zoom (State::camera)
  std::vector<std::string> sets;    // --set key=value, in order
  std::string load;                 // --load FILE: the lab's curve or surface (model_file.h)
  double time = 0;                  // --time SECONDS
  bool overlay = false;             // --overlay: draw the help overlay
  bool list_views = false;
  bool list_params = false;         // --list-params: the params and point lists, for graders
  bool print_text = false;          // --print-text: print the frame's text on stdout (headless)
  std::string text_out;             // --text-out FILE (headless): every view's text to FILE (graders)
  bool info = false;                // --info: print renderer and versions (headless)
  bool help = false;
};

inline constexpr int kMaxSize = 8192;
inline constexpr int kMaxFrames = 100000;

/// Which way these arguments (argv without argv[0]) ask the lab to run:
/// headless when one of them is --headless or an option only headless takes
/// (--out, --views, --info, --print-text, --text-out); the window otherwise.
/// The values of options are skipped (--set out=1 is not --out).
Runner runner_for(const std::vector<std::string>& args);
/// Parses argv (without argv[0]) for that runner. Throws UsageError naming the
/// bad argument; an option of the other runner is named as such.
Options parse_options(const std::vector<std::string>& args, Runner runner);
/// Parses "WxH" with 1 <= W, H <= kMaxSize. Throws UsageError.
void parse_size(const std::string& text, int& width, int& height);

/// The State for these options: view selected, --set applied, then --load.
/// Throws UsageError (a bad file too: it is input).
State make_state(const Lab& lab, const Options& options);

/// --help: both ways of running the lab, its options, views, parameters and keys.
std::string usage_text(const Lab& lab, const std::string& program);
std::string views_text(const Lab& lab);
/// What --list-views prints: one view name per line, an error view's name
/// followed by " expect_error" (kErrorView; labrun reads it), a view that
/// equals another on purpose by " same_as=OTHER" (View::same_as).
std::string list_views_text(const Lab& lab);
/// What --list-params prints: every Param, then every point of every point
/// list, one per line, in the lab's order:
///   param NAME DEFAULT LO HI
///   points NAME INDEX DIMENSION X Y Z
/// Numbers in the shortest text that reads back as the same double (0.6, 3,
/// 1e-05), so --set NAME=DEFAULT gives the default exactly. labgrade draws its
/// hidden inputs from these ranges (tools/hidden_inputs.h).
std::string list_params_text(const Lab& lab);
/// What a run with --list-views or --list-params prints (with both: the
/// views, then the params). Both runners print it and exit 0, without a display.
std::string listing_text(const Lab& lab, const Options& options);

/// "01_immediate_mode" from a path like "build/bin/01_immediate_mode".
std::string program_name(const char* argv0);

}  // namespace gllab
