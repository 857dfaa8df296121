// common/io/json_checks.h — internal to common/io: what the readers of
// spline files (spline_json.cpp) and blob scenes (field_json.cpp) check in
// every JSON value, each failure one FileError at the value's JSON path.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "io/spline_json.h"

namespace gllab::io::detail {

inline std::string member_path(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}
inline std::string index_path(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

/// How a value appears in a message: scalars as written, containers by kind.
inline std::string describe(const Json& v) {
  if (v.is_array()) return v.empty() ? "an empty array" : "an array";
  if (v.is_object()) return v.empty() ? "an empty object" : "an object";
  std::string text = v.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return text;
}

/// Checks one parsed file. Every failure throws FileError(source, path, problem).
class JsonChecker {
 public:
  explicit JsonChecker(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw FileError(source_, path, problem);
  }

  void require_object(const Json& v, const std::string& path, const std::string& what) const {
    if (!v.is_object()) fail(path, "expected " + what + ", got " + describe(v));
  }

  /// Rejects keys the format does not know (a typo such as "weight" would
  /// otherwise silently turn a NURBS curve into a polynomial one).
  void only_keys(const Json& object, const std::string& path, const std::vector<std::string>& known,
                 const std::string& kind) const {
    for (const auto& item : object.items()) {
      if (std::find(known.begin(), known.end(), item.key()) != known.end()) continue;
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      fail(member_path(path, item.key()), "unknown key in a " + kind + " (known keys: " + list + ")");
    }
  }

  const Json& member(const Json& object, const std::string& path, const std::string& key,
                     const std::string& kind) const {
    const auto it = object.find(key);
    if (it == object.end()) fail(member_path(path, key), "missing (a " + kind + " needs it)");
    return *it;
  }

  const Json* optional_member(const Json& object, const std::string& key) const {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  double number(const Json& v, const std::string& path) const {
    if (!v.is_number()) fail(path, "expected a number, got " + describe(v));
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(path, shortest_text(x) + " (numbers must be finite)");
    return x;
  }

  /// [x, y, z] of finite numbers. `kind` names it in "expected <kind>[x, y, z], got ..." ("a
  /// point " or ""), `entry` names its entries in "has 2 <entry>s" ("coordinate", "number").
  spline::Vec3 triple(const Json& v, const std::string& path, const std::string& kind,
                      const std::string& entry) const {
    if (!v.is_array()) fail(path, "expected " + kind + "[x, y, z], got " + describe(v));
    if (v.size() != 3)
      fail(path, "has " + std::to_string(v.size()) + " " + entry + (v.size() == 1 ? "" : "s") +
                     " (expected [x, y, z])");
    return {number(v[0], index_path(path, 0)), number(v[1], index_path(path, 1)),
            number(v[2], index_path(path, 2))};
  }

  /// A number > 0; `meaning` says what it is: "... (must be > 0: the radius of the blob)".
  double positive(const Json& v, const std::string& path, const std::string& meaning) const {
    const double x = number(v, path);
    if (!(x > 0)) fail(path, shortest_text(x) + " (must be > 0: " + meaning + ")");
    return x;
  }

  std::string string(const Json& v, const std::string& path) const {
    if (!v.is_string()) fail(path, "expected a string, got " + describe(v));
    return v.get<std::string>();
  }

 private:
  std::string source_;
};

}  // namespace gllab::io::detail
