// common/harness/lab.h — what a lab is, as both runners see it.
//
// A lab is data plus a few functions, like a Red Book program:
//   init()       once, after a GL context exists (shutdown(), if set, undoes it)
//   a view's draw(s)  the display() of that view: draws the whole frame from
//                the State s and nothing else (the runner has cleared the
//                colour, depth and stencil buffers with the lab's glClearColor)
//   keyboard()   changes the State (never GL state); the view's draw applies it
// Every knob a key turns is a named parameter in the State, so any picture a
// student sees in the window can be rendered again headless with --set.
#pragma once

#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "spline/types.h"
#include "spline/vec.h"

namespace gllab {

class State;

/// View flags (View::flags), combined with |.
/// kOrbit: a 3D view. In the window the right mouse button turns it, the wheel
///   zooms and [0] resets (State::camera, applied by gllab::apply_orbit); `p`
///   prints the camera as --camera, so the picture renders again headless.
/// kErrorView: it exists to show an error (say GLU's NURBS error for a
///   reversed trim loop). The window shows the error on screen; headless the
///   run exits 1 with the error line, as for any frame error, so the view has
///   no reference image. --list-views marks it ("name expect_error"); labrun
///   passes it when the render exits 1 with an error line, and fails it when
///   it renders. It cannot be a lab's first view (the window opens there).
inline constexpr unsigned kOrbit = 1u << 0;
inline constexpr unsigned kErrorView = 1u << 1;

/// One picture a lab can show, declared with the function that draws it:
///   {"slivers", "GLU's slivers along a coarse polyline", draw_slivers, gllab::kOrbit}
/// Graders compare each against reference_images/<lab>__<view>.png.
struct View {
  std::string name;  // lower_snake, used on the command line and in file names
  std::string what;  // one line for the help overlay and --list-views
  std::function<void(const State&)> draw;  // this view's display()
  unsigned flags = 0;                      // kOrbit, kErrorView
  /// Another view of the lab whose picture this one equals on purpose (lab
  /// 05's four submission paths). Every other pair of views must differ: a
  /// test renders them all (--list-views prints "name same_as=other").
  std::string same_as = {};

  bool expect_error() const { return (flags & kErrorView) != 0; }
  bool orbit() const { return (flags & kOrbit) != 0; }
};

/// A lab parameter: a number with a range. A parameter with the range [0, 1]
/// and the default 0 or 1 is a switch: only 0 and 1 may be set. A count, an
/// index or a choice is read with State::integer, which refuses a fractional
/// value (--set ticks=3.5 fails with one line instead of being rounded).
struct Param {
  std::string name;
  double value = 0;  // the default
  double lo = 0, hi = 1;
  std::string what;
};

/// Points the mouse drags in the window: control points, data points, tangent
/// handles, in the lab's coordinates. They live in the State like the
/// parameters, so a view draws them from there, `p` prints a dragged point
/// as `--set P[3]=1.5,2`, and the same picture renders again headless.
struct PointList {
  std::string name;                  // "P": --set P[3]=x,y[,z]
  std::vector<spline::Vec3> points;  // the defaults
  std::string what;
  /// 2: dragged in its plane z = const (z is kept); 3: dragged parallel to the screen.
  int dimension = 2;
};

/// A curve or surface a lab edits; the alternatives of io::SplineFile, so
/// it is written and read as a spline-core file.
using Model = std::variant<spline::BsplineCurve, spline::BezierCurve, spline::BsplineSurface>;

/// Dragged points snap to a grid of 1 / kGridPerUnit lab units: k / 1000 is
/// the double nearest the decimal k/1000, which is what reading the printed
/// `--set P[3]=1.234,0.5` gives back, so the window's picture renders again
/// exactly. (k * 0.001 would not be: it can be one unit in the last place off.)
inline constexpr double kGridPerUnit = 1000;
inline double snap_to_grid(double v) { return std::round(v * kGridPerUnit) / kGridPerUnit; }

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

/// The orbit camera of the kOrbit views: turns and a zoom on top of the
/// lab's own camera. The default {0, 0, 1} is the lab's camera as the
/// reference images show it. apply_orbit (gl/scene.h) turns the eye space
/// about the centre of the view: pitch degrees about the screen's x axis
/// (right-drag up and down), then yaw degrees about its y axis (left and
/// right); zoom scales the projection in x and y.
struct Camera {
  double yaw = 0, pitch = 0, zoom = 1;
  bool operator==(const Camera& o) const { return yaw == o.yaw && pitch == o.pitch && zoom == o.zoom; }
  bool operator!=(const Camera& o) const { return !(*this == o); }
};
inline constexpr double kMinZoom = 0.1, kMaxZoom = 20;

/// Everything a view's draw function may read. The runners own it;
/// keyboard() and the mouse change it.
class State {
 public:
  State(std::vector<View> views, std::vector<Param> params, std::vector<PointList> points = {});

  int width = 512, height = 512;  // framebuffer size in pixels
  double time = 0;                // seconds; fixed in headless runs (--time)
  bool help = false;              // help overlay on
  // True in the window runner only. A lab may show live measurements (frame
  // times, throughput) when it is set; a headless render never contains them,
  // so reference images stay reproducible.
  bool interactive = false;
  Camera camera;                  // kOrbit views: --camera yaw,pitch,zoom

  std::size_t view_index() const { return view_; }
  const std::string& view() const { return views_[view_].name; }
  const std::vector<View>& views() const { return views_; }
  const View& current_view() const { return views_[view_]; }
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
  /// Parses "key=value" or "P[3]=x,y[,z]" as given to --set; errors as
  /// set() and move_point().
  void set_from_text(const std::string& assignment);

  const std::vector<PointList>& point_lists() const { return points_; }
  /// The points of a list. Throws std::invalid_argument for an unknown name.
  const std::vector<spline::Vec3>& points(const std::string& list) const;
  /// Throws std::invalid_argument naming the list, the index and its range,
  /// or the coordinate that is not finite.
  void move_point(const std::string& list, std::size_t index, spline::Vec3 p);
  /// Replaces every point of a list; the count must stay the same.
  void set_points(const std::string& list, const std::vector<spline::Vec3>& points);
  /// Keyboard helpers: clamp to the range, wrap toggles.
  void toggle(const std::string& name);
  void step(const std::string& name, double delta);

  /// "yaw,pitch,zoom" as --camera takes it; throws std::invalid_argument
  /// naming the text for anything else (zoom within [kMinZoom, kMaxZoom]).
  void set_camera_from_text(const std::string& text);

  /// The arguments that reproduce this state: --view, then --camera when it
  /// is not the default, --set for non-default params and moved points.
  std::string as_arguments() const;

 private:
  const Param& find(const std::string& name) const;
  std::size_t list_index(const std::string& name) const;
  const PointList& find_list(const std::string& name) const;
  std::vector<View> views_;
  std::vector<Param> params_;
  std::vector<double> defaults_;
  std::vector<PointList> points_, default_points_;
  std::size_t view_ = 0;
};

struct Lab {
  std::string id;     // folder name, e.g. "01_immediate_mode"
  std::string title;  // the header's first line, e.g. "lab 01 · immediate mode"
  std::vector<View> views;
  std::vector<Param> params;
  std::vector<Key> keys;
  std::function<void()> init = nullptr;
  /// Keys that do more than turn one parameter. Returns true when the key
  /// was the lab's. May be empty when every key names its parameter.
  std::function<bool(State&, unsigned char)> keyboard = nullptr;
  /// True when a view's draw reads State::time: the window runner then advances
  /// time continuously; headless runs keep the fixed --time (default 0).
  bool animated = false;
  /// Optional: runs once, with the GL context still current, before the
  /// runner destroys it: release what init() made (buffers, lists, textures).
  std::function<void()> shutdown = nullptr;
  /// Points the mouse can drag (a view draws them with
  /// gllab::draw_control_points, which makes them pickable).
  std::vector<PointList> points = {};
  /// Optional, for labs that edit one curve or surface: that object, built
  /// from the State. Its control points are the first point list. [Ctrl+S]
  /// in the window writes it in the spline core's file format
  /// (common/io/README.md); --load FILE puts a file's points back
  /// (harness/model_file.h).
  std::function<Model(const State&)> model = nullptr;
};

/// Each lab's .cpp defines this; both runners call it.
Lab define_lab();

/// Keys the runners keep for themselves; a lab may not use them.
/// \x13 is Ctrl+S (save the model as JSON); 0 resets the orbit camera.
inline constexpr char kReservedKeys[] = "hvVp0\x1b\x13";

/// Checks a lab definition (views present, unique and each with its draw
/// function, same_as naming another view, defaults in range, no reserved or
/// duplicate keys, every key's parameter exists). Throws std::logic_error
/// naming the problem.
void validate_lab(const Lab& lab);

/// A key press in the window: a key that names a parameter steps or toggles
/// it, any other goes to lab.keyboard. Returns true when the state changed.
bool apply_key(const Lab& lab, State& state, unsigned char key);

/// An exception out of a view's draw (the spline core rejecting dragged data,
/// say) is a frame error like a GL error: shown in the window, exit 1
/// headless; the matrices and attributes it left pushed are popped.
/// Errors found while drawing (GL errors, GLU NURBS errors). The headless
/// runner exits non-zero when any is pending after a frame; the window runner
/// shows them on screen.
void report_frame_error(const std::string& message);
std::vector<std::string> take_frame_errors();

}  // namespace gllab
