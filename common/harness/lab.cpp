// common/harness/lab.cpp — the State every lab draws from.
#include "harness/lab.h"

#include <cstdio>

#include "io/spline_json.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace gllab {

namespace {

// The shortest text that reads back as the same double (0, 1, 0.25, 0.65):
// what `p` prints must render the same picture again, bit for bit.
std::string format_number(double v) { return io::shortest_text(v); }
std::string format_coordinate(double v) { return io::shortest_text(v); }

// A key's step lands on the nearest decimal of at most 12 significant
// digits: 0.6 + 0.05 is 0.65 (printed "0.65"), not 0.6499999999999999.
double decimal(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", v);
  return std::strtod(text, nullptr);
}

std::string format_point(const spline::Vec3& p, int dimension) {
  std::string text = format_coordinate(p.x) + "," + format_coordinate(p.y);
  if (dimension == 3 || p.z != 0) text += "," + format_coordinate(p.z);
  return text;
}

bool parse_number(const std::string& text, double& value) {
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && *end == '\0' && std::isfinite(value);
}

std::string view_list(const std::vector<View>& views) {
  std::string names;
  for (const View& v : views) names += (names.empty() ? "" : ", ") + v.name;
  return names;
}

std::vector<std::string>& pending_errors() {
  static std::vector<std::string> errors;
  return errors;
}

}  // namespace

State::State(std::vector<View> views, std::vector<Param> params, std::vector<PointList> points)
    : views_(std::move(views)), params_(std::move(params)), points_(std::move(points)) {
  for (const Param& p : params_) defaults_.push_back(p.value);
  default_points_ = points_;
}

void State::select_view(const std::string& name) {
  for (std::size_t i = 0; i < views_.size(); ++i) {
    if (views_[i].name == name) {
      view_ = i;
      return;
    }
  }
  throw std::invalid_argument("unknown view '" + name + "' (views: " + view_list(views_) + ")");
}

void State::next_view(int step) {
  const auto n = static_cast<long>(views_.size());
  view_ = static_cast<std::size_t>(((static_cast<long>(view_) + step) % n + n) % n);
}

const Param& State::find(const std::string& name) const {
  for (const Param& p : params_)
    if (p.name == name) return p;
  std::string names;
  for (const Param& p : params_) names += (names.empty() ? "" : ", ") + p.name;
  throw std::invalid_argument("unknown parameter '" + name + "' (parameters: " +
                              (names.empty() ? "none" : names) + ")");
}

double State::get(const std::string& name) const { return find(name).value; }

int State::integer(const std::string& name) const {
  const double v = get(name);
  // A whole-number parameter (a count, an index, a choice): a fractional value
  // from --set is refused here, where the lab reads it, not rounded.
  if (v != std::floor(v))
    throw std::invalid_argument("parameter " + name + "=" + format_number(v) + " is not a whole number");
  return static_cast<int>(v);
}

void State::set(const std::string& name, double value) {
  find(name);  // throws for an unknown name
  Param& p = *std::find_if(params_.begin(), params_.end(),
                           [&](const Param& q) { return q.name == name; });
  if (!(value >= p.lo && value <= p.hi))  // also rejects NaN
    throw std::invalid_argument("parameter " + name + "=" + format_number(value) +
                                " is out of range [" + format_number(p.lo) + ", " +
                                format_number(p.hi) + "]");
  // A switch (range [0, 1], default 0 or 1) is off or on: 0.5 is neither.
  const double preset = defaults_[static_cast<std::size_t>(&p - params_.data())];
  const bool is_switch = p.lo == 0 && p.hi == 1 && (preset == 0 || preset == 1);
  if (is_switch && value != 0 && value != 1)
    throw std::invalid_argument("parameter " + name + "=" + format_number(value) + " is a switch: 0 or 1");
  p.value = value;
}

void State::set_from_text(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw std::invalid_argument("malformed --set '" + assignment + "' (expected key=value or P[i]=x,y)");
  const std::string name = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  const auto bracket = name.find('[');
  if (bracket != std::string::npos) {
    // P[3]=x,y or P[3]=x,y,z: one point of a list.
    const std::string list = name.substr(0, bracket);
    const PointList& l = find_list(list);  // unknown lists before malformed indices
    const std::string index_text = name.substr(bracket + 1, name.size() - bracket - 2);
    if (name.back() != ']' || index_text.empty() || index_text.find_first_not_of("0123456789") != std::string::npos)
      throw std::invalid_argument("malformed --set '" + assignment + "' (expected " + list + "[i]=x,y)");
    // The whole index, exactly: an index too long for any list is one that does not exist.
    std::size_t index = l.points.size();
    const auto [end, ec] = std::from_chars(index_text.data(), index_text.data() + index_text.size(), index);
    if (ec != std::errc() || end != index_text.data() + index_text.size() || index >= l.points.size())
      throw std::invalid_argument("point " + list + "[" + index_text + "] does not exist (" + list +
                                  " has points 0.." + std::to_string(l.points.size() - 1) + ")");
    std::vector<double> xyz;
    std::size_t start = 0;
    while (true) {
      const auto comma = text.find(',', start);
      const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      double v = 0;
      if (!parse_number(part, v))
        throw std::invalid_argument("malformed --set '" + assignment + "': '" + part + "' is not a number");
      xyz.push_back(v);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (xyz.size() < 2 || xyz.size() > 3)
      throw std::invalid_argument("malformed --set '" + assignment + "': " + std::to_string(xyz.size()) +
                                  " coordinates (expected x,y or x,y,z)");
    const std::size_t i = index;
    const double z = xyz.size() == 3 ? xyz[2] : (i < l.points.size() ? l.points[i].z : 0.0);
    move_point(list, i, {xyz[0], xyz[1], z});
    return;
  }
  find(name);  // unknown keys are reported before malformed values
  double value = 0;
  if (!parse_number(text, value))
    throw std::invalid_argument("malformed --set '" + assignment + "': '" + text +
                                "' is not a number");
  set(name, value);
}

std::size_t State::list_index(const std::string& name) const {
  for (std::size_t i = 0; i < points_.size(); ++i)
    if (points_[i].name == name) return i;
  std::string names;
  for (const PointList& l : points_) names += (names.empty() ? "" : ", ") + l.name;
  throw std::invalid_argument("unknown point list '" + name + "' (point lists: " +
                              (names.empty() ? "none" : names) + ")");
}

const PointList& State::find_list(const std::string& name) const { return points_[list_index(name)]; }

const std::vector<spline::Vec3>& State::points(const std::string& list) const { return find_list(list).points; }

void State::move_point(const std::string& list, std::size_t index, spline::Vec3 p) {
  PointList& l = points_[list_index(list)];
  if (index >= l.points.size())
    throw std::invalid_argument("point " + list + "[" + std::to_string(index) + "] does not exist (" + list +
                                " has points 0.." + std::to_string(l.points.size() - 1) + ")");
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    throw std::invalid_argument("point " + list + "[" + std::to_string(index) + "]=" + format_point(p, 3) +
                                " is not finite");
  l.points[index] = p;
}

void State::set_points(const std::string& list, const std::vector<spline::Vec3>& points) {
  const PointList& l = find_list(list);
  if (points.size() != l.points.size())
    throw std::invalid_argument(std::to_string(points.size()) + " points for " + list + ", which has " +
                                std::to_string(l.points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) move_point(list, i, points[i]);
}

void State::toggle(const std::string& name) { set(name, flag(name) ? 0 : 1); }

void State::step(const std::string& name, double delta) {
  const Param& p = find(name);
  set(name, std::clamp(decimal(p.value + delta), p.lo, p.hi));
}

void State::set_camera_from_text(const std::string& text) {
  std::vector<double> v;
  std::size_t start = 0;
  while (true) {
    const auto comma = text.find(',', start);
    const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    double x = 0;
    if (!parse_number(part, x))
      throw std::invalid_argument("malformed --camera '" + text + "': '" + part +
                                  "' is not a number (expected yaw,pitch,zoom, e.g. 30,-15,1.5)");
    v.push_back(x);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (v.size() != 3)
    throw std::invalid_argument("malformed --camera '" + text + "': " + std::to_string(v.size()) +
                                " numbers (expected yaw,pitch,zoom, e.g. 30,-15,1.5)");
  if (!(v[2] >= kMinZoom && v[2] <= kMaxZoom))
    throw std::invalid_argument("--camera '" + text + "': zoom " + format_number(v[2]) + " is out of range [" +
                                format_number(kMinZoom) + ", " + format_number(kMaxZoom) + "]");
  camera = {v[0], v[1], v[2]};
}

std::string State::as_arguments() const {
  std::string args = "--view " + view();
  if (camera != Camera{})
    args += " --camera " + format_number(camera.yaw) + "," + format_number(camera.pitch) + "," +
            format_number(camera.zoom);
  for (std::size_t i = 0; i < params_.size(); ++i)
    if (params_[i].value != defaults_[i])
      args += " --set " + params_[i].name + "=" + format_number(params_[i].value);
  for (std::size_t l = 0; l < points_.size(); ++l)
    for (std::size_t i = 0; i < points_[l].points.size(); ++i)
      if (points_[l].points[i] != default_points_[l].points[i])
        args += " --set " + points_[l].name + "[" + std::to_string(i) + "]=" +
                format_point(points_[l].points[i], points_[l].dimension);
  return args;
}

void validate_lab(const Lab& lab) {
  auto fail = [&](const std::string& why) {
    throw std::logic_error("lab " + lab.id + ": " + why);
  };
  if (lab.views.empty()) fail("has no views");
  if (lab.views.front().expect_error())
    fail("first view '" + lab.views.front().name + "' is an error view (the window opens with the first view)");
  for (std::size_t i = 0; i < lab.views.size(); ++i) {
    const View& v = lab.views[i];
    if (v.name.empty() || v.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") != std::string::npos)
      fail("view name '" + v.name + "' (needs lower_snake_case: a-z, 0-9, _)");
    if (!v.draw) fail("view '" + v.name + "' has no draw function");
    if ((v.flags & ~(kOrbit | kErrorView)) != 0) fail("view '" + v.name + "' has unknown flags");
    for (std::size_t j = i + 1; j < lab.views.size(); ++j)
      if (v.name == lab.views[j].name) fail("view '" + v.name + "' twice");
    if (!v.same_as.empty()) {
      const bool known = std::any_of(lab.views.begin(), lab.views.end(),
                                     [&](const View& o) { return o.name == v.same_as && &o != &v; });
      if (!known) fail("view '" + v.name + "' is the same as '" + v.same_as + "', which is not another view");
    }
  }
  for (const Param& p : lab.params)
    if (!(p.lo <= p.value && p.value <= p.hi))
      fail("parameter " + p.name + " default " + format_number(p.value) + " outside its range");
  for (std::size_t i = 0; i < lab.points.size(); ++i) {
    const PointList& l = lab.points[i];
    if (l.name.empty() || l.name.find_first_of("[]=, ") != std::string::npos)
      fail("point list name '" + l.name + "' (needs a name without [ ] = , or spaces)");
    if (l.points.empty()) fail("point list " + l.name + " is empty");
    if (l.dimension != 2 && l.dimension != 3) fail("point list " + l.name + " has dimension " + std::to_string(l.dimension));
    for (const Param& p : lab.params)
      if (p.name == l.name) fail("'" + l.name + "' is a parameter and a point list");
    for (std::size_t j = i + 1; j < lab.points.size(); ++j)
      if (lab.points[j].name == l.name) fail("point list " + l.name + " twice");
  }
  if (lab.model && lab.points.empty()) fail("has a model but no point list for its control points");
  const std::string reserved = kReservedKeys;
  for (std::size_t i = 0; i < lab.keys.size(); ++i) {
    const unsigned char k = lab.keys[i].key;
    if (reserved.find(static_cast<char>(k)) != std::string::npos)
      fail(std::string("key '") + static_cast<char>(k) + "' is reserved by the runner");
    for (std::size_t j = i + 1; j < lab.keys.size(); ++j)
      if (lab.keys[j].key == k) fail(std::string("key '") + static_cast<char>(k) + "' twice");
    const std::string& param = lab.keys[i].param;
    const bool known = std::any_of(lab.params.begin(), lab.params.end(),
                                   [&](const Param& p) { return p.name == param; });
    if (!param.empty() && !known)
      fail(std::string("key '") + static_cast<char>(k) + "' turns unknown parameter '" + param + "'");
    if (param.empty() && !lab.keyboard)
      fail(std::string("key '") + static_cast<char>(k) + "' names no parameter and the lab has no keyboard()");
  }
}

bool apply_key(const Lab& lab, State& state, unsigned char key) {
  for (const Key& k : lab.keys) {
    if (k.key != key || k.param.empty()) continue;
    if (k.step == 0) state.toggle(k.param);
    else state.step(k.param, k.step);
    return true;
  }
  return lab.keyboard && lab.keyboard(state, key);
}

void report_frame_error(const std::string& message) { pending_errors().push_back(message); }

std::vector<std::string> take_frame_errors() {
  std::vector<std::string> out;
  out.swap(pending_errors());
  return out;
}

}  // namespace gllab
