// common/harness/lab.cpp — the State every lab draws from.
#include "harness/lab.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace gllab {

namespace {

std::string format_number(double v) {
  std::ostringstream out;
  out << v;  // shortest of %g: 0, 1, 0.25, 30
  return out.str();
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

State::State(std::vector<View> views, std::vector<Param> params)
    : views_(std::move(views)), params_(std::move(params)) {
  for (const Param& p : params_) defaults_.push_back(p.value);
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
  return static_cast<int>(std::lround(get(name)));
}

void State::set(const std::string& name, double value) {
  find(name);  // throws for an unknown name
  Param& p = *std::find_if(params_.begin(), params_.end(),
                           [&](const Param& q) { return q.name == name; });
  if (!(value >= p.lo && value <= p.hi))  // also rejects NaN
    throw std::invalid_argument("parameter " + name + "=" + format_number(value) +
                                " is out of range [" + format_number(p.lo) + ", " +
                                format_number(p.hi) + "]");
  p.value = value;
}

void State::set_from_text(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw std::invalid_argument("malformed --set '" + assignment + "' (expected key=value)");
  const std::string name = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  find(name);  // unknown keys are reported before malformed values
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value))
    throw std::invalid_argument("malformed --set '" + assignment + "': '" + text +
                                "' is not a number");
  set(name, value);
}

void State::toggle(const std::string& name) { set(name, flag(name) ? 0 : 1); }

void State::step(const std::string& name, double delta) {
  const Param& p = find(name);
  set(name, std::clamp(p.value + delta, p.lo, p.hi));
}

std::string State::as_arguments() const {
  std::string args = "--view " + view();
  for (std::size_t i = 0; i < params_.size(); ++i)
    if (params_[i].value != defaults_[i])
      args += " --set " + params_[i].name + "=" + format_number(params_[i].value);
  return args;
}

void validate_lab(const Lab& lab) {
  auto fail = [&](const std::string& why) {
    throw std::logic_error("lab " + lab.id + ": " + why);
  };
  if (lab.views.empty()) fail("has no views");
  if (!lab.display) fail("has no display()");
  for (std::size_t i = 0; i < lab.views.size(); ++i)
    for (std::size_t j = i + 1; j < lab.views.size(); ++j)
      if (lab.views[i].name == lab.views[j].name) fail("view '" + lab.views[i].name + "' twice");
  for (const Param& p : lab.params)
    if (!(p.lo <= p.value && p.value <= p.hi))
      fail("parameter " + p.name + " default " + format_number(p.value) + " outside its range");
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
