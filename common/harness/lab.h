// common/harness/lab.h — what a lab is, as both runners see it.
//
// A lab is data plus four functions, like a Red Book program:
//   init()      once, after a GL context exists (shutdown(), if set, undoes it)
//   display(s)  draws the whole frame from the State s and nothing else
//   keyboard()  changes the State (never GL state), display() applies it
// Every knob a key turns is a named parameter in the State, so any picture a
// student sees in the window can be rendered again headless with --set.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace gllab {

/// One picture a lab can show; graders compare each against
/// reference_images/<lab>__<view>.png.
struct View {
  std::string name;  // lower_snake, used on the command line and in file names
  std::string what;  // one line for the help overlay and --list-views
};

/// A lab parameter: a number with a range. Toggles are 0/1.
struct Param {
  std::string name;
  double value = 0;  // the default
  double lo = 0, hi = 1;
  std::string what;
};

/// A key the lab handles, listed in the help overlay. Most keys only turn
/// one parameter; they name it and need no code:
///   {'s', "slices +2", "slices", +2}   adds 2, clamped to the range
///   {'l', "lighting on/off", "lighting"} toggles (step 0)
/// A key without a parameter goes to Lab::keyboard.
struct Key {
  unsigned char key;
  std::string what;
  std::string param = {};
  double step = 0;
};

/// Everything display() may read. The runners own it; keyboard() changes it.
class State {
 public:
  State(std::vector<View> views, std::vector<Param> params);

  int width = 512, height = 512;  // framebuffer size in pixels
  double time = 0;                // seconds; fixed in headless runs (--time)
  bool help = false;              // help overlay on
  // True in the window runner only. A lab may show live measurements (frame
  // times, throughput) when it is set; a headless render never contains them,
  // so reference images stay reproducible.
  bool interactive = false;

  std::size_t view_index() const { return view_; }
  const std::string& view() const { return views_[view_].name; }
  const std::vector<View>& views() const { return views_; }
  /// Throws std::invalid_argument naming the view and listing the valid ones.
  void select_view(const std::string& name);
  void next_view(int step);

  const std::vector<Param>& params() const { return params_; }
  double get(const std::string& name) const;
  bool flag(const std::string& name) const { return get(name) != 0; }
  int integer(const std::string& name) const;
  /// Throws std::invalid_argument when the name is unknown or the value is
  /// out of range, naming both.
  void set(const std::string& name, double value);
  /// Parses "key=value" as given to --set; errors as set().
  void set_from_text(const std::string& assignment);
  /// Keyboard helpers: clamp to the range, wrap toggles.
  void toggle(const std::string& name);
  void step(const std::string& name, double delta);

  /// The --set arguments that reproduce this state (non-default params only).
  std::string as_arguments() const;

 private:
  const Param& find(const std::string& name) const;
  std::vector<View> views_;
  std::vector<Param> params_;
  std::vector<double> defaults_;
  std::size_t view_ = 0;
};

struct Lab {
  std::string id;     // folder name, e.g. "01_immediate_mode"
  std::string title;  // the header's first line, e.g. "lab 01 · immediate mode"
  std::vector<View> views;
  std::vector<Param> params;
  std::vector<Key> keys;
  std::function<void()> init;
  std::function<void(const State&)> display;
  /// Keys that do more than turn one parameter. Returns true when the key
  /// was the lab's. May be empty when every key names its parameter.
  std::function<bool(State&, unsigned char)> keyboard = nullptr;
  /// True when display() reads State::time: the window runner then advances
  /// time continuously; headless runs keep the fixed --time (default 0).
  bool animated = false;
  /// Optional: runs once, with the GL context still current, before the
  /// runner destroys it: release what init() made (buffers, lists, textures).
  std::function<void()> shutdown = nullptr;
};

/// Each lab's .cpp defines this; both runners call it.
Lab define_lab();

/// Keys the runners keep for themselves; a lab may not use them.
inline constexpr char kReservedKeys[] = "hvVp\x1b";

/// Checks a lab definition (views present and unique, defaults in range, no
/// reserved or duplicate keys, every key's parameter exists). Throws
/// std::logic_error naming the problem.
void validate_lab(const Lab& lab);

/// A key press in the window: a key that names a parameter steps or toggles
/// it, any other goes to lab.keyboard. Returns true when the state changed.
bool apply_key(const Lab& lab, State& state, unsigned char key);

/// Errors found while drawing (GL errors, GLU NURBS errors). The headless
/// runner exits non-zero when any is pending after a frame; the window runner
/// shows them on screen.
void report_frame_error(const std::string& message);
std::vector<std::string> take_frame_errors();

}  // namespace gllab
