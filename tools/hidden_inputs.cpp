// tools/hidden_inputs.cpp — the draws of labgrade --hidden (hidden_inputs.h).
#include "hidden_inputs.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <sstream>

#include "grading.h"

namespace gllab::grading {

bool ParamRange::is_switch() const { return lo == 0 && hi == 1 && (value == 0 || value == 1); }

bool ParamRange::is_integer() const {
  return value == std::floor(value) && lo == std::floor(lo) && hi == std::floor(hi);
}

namespace {

// The 1/1000 grid of dragged points (harness/lab.h kGridPerUnit) and of drawn
// numbers: a value on it is k / 1000 for a whole k.
constexpr double kGrid = 1000;

// A name --set can take as NAME=... or NAME[i]=...: letters, digits, '_'.
bool is_name(const std::string& s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

std::vector<std::string> fields_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> fields;
  for (std::string f; in >> f;) fields.push_back(f);
  return fields;
}

// The shortest text that reads back as v (std::to_chars).
std::string shortest(double v) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

// k / 1000 as a decimal of at most 3 places ("1.234", "-0.5", "37"): reading
// it gives the double nearest k / 1000, which is k / kGrid computed in double
// (one correctly rounded division), the value drawn.
std::string grid_text(long long k) {
  const unsigned long long a =
      k < 0 ? 0ull - static_cast<unsigned long long>(k) : static_cast<unsigned long long>(k);
  std::string text = (k < 0 ? "-" : "") + std::to_string(a / 1000);
  if (const unsigned long long rest = a % 1000; rest != 0) {
    std::string digits = std::to_string(rest);
    digits.insert(0, 3 - digits.size(), '0');
    digits.erase(digits.find_last_not_of('0') + 1);
    text += "." + digits;
  }
  return text;
}

// The multiples k of 1/1000 with lo <= k / 1000 <= hi; nullopt when none.
std::optional<std::pair<long long, long long>> grid_range(double lo, double hi) {
  long long first = std::llround(lo * kGrid), last = std::llround(hi * kGrid);
  if (static_cast<double>(first) / kGrid < lo) ++first;
  if (static_cast<double>(last) / kGrid > hi) --last;
  if (first > last) return std::nullopt;
  return std::make_pair(first, last);
}

// The coordinates a point of the given dimension is dragged in.
std::vector<double> dragged(const PointRange& p) {
  return p.dimension == 3 ? std::vector<double>{p.x, p.y, p.z} : std::vector<double>{p.x, p.y};
}

}  // namespace

LabInputs parse_lab_inputs(const std::string& text, const std::string& lab) {
  LabInputs inputs;
  std::set<std::string> param_names, list_names;
  std::istringstream in(text);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    const auto bad = [&](const std::string& what) {
      const std::string shown = line.size() > 80 ? line.substr(0, 80) + "..." : line;
      return UsageError(lab + " --list-params, line " + std::to_string(number) + " '" + shown + "': " + what);
    };
    const auto value = [&](const std::string& field) {
      const std::optional<double> v = parse_number(field, -kMaxMagnitude, kMaxMagnitude);
      if (!v) throw bad("'" + field + "' is not a decimal number of magnitude at most 1e12");
      return *v;
    };
    const std::vector<std::string> f = fields_of(line);
    if (f.empty()) continue;
    if (f[0] == "param") {
      if (f.size() != 5) throw bad("expected param NAME DEFAULT LO HI");
      ParamRange p;
      p.name = f[1];
      if (!is_name(p.name)) throw bad("'" + p.name + "' is not a parameter name (letters, digits, _)");
      if (!param_names.insert(p.name).second) throw bad("parameter '" + p.name + "' is listed twice");
      p.value = value(f[2]);
      p.lo = value(f[3]);
      p.hi = value(f[4]);
      if (!(p.lo <= p.hi)) throw bad("lo " + f[3] + " is above hi " + f[4]);
      if (!(p.lo <= p.value && p.value <= p.hi)) throw bad("the default " + f[2] + " is outside [lo, hi]");
      inputs.params.push_back(p);
    } else if (f[0] == "points") {
      if (f.size() != 7) throw bad("expected points LIST INDEX DIMENSION X Y Z");
      PointRange p;
      p.list = f[1];
      if (!is_name(p.list)) throw bad("'" + p.list + "' is not a point list name (letters, digits, _)");
      const std::optional<long long> index = parse_integer(f[2], 0, 1'000'000);
      if (!index) throw bad("'" + f[2] + "' is not a point index (0 to 1000000)");
      p.index = static_cast<std::size_t>(*index);
      const std::optional<long long> dimension = parse_integer(f[3], 2, 3);
      if (!dimension) throw bad("dimension '" + f[3] + "' is neither 2 nor 3");
      p.dimension = static_cast<int>(*dimension);
      p.x = value(f[4]);
      p.y = value(f[5]);
      p.z = value(f[6]);
      // A list's points come together, in order: 0, 1, 2, ...
      const bool continues = !inputs.points.empty() && inputs.points.back().list == p.list;
      if (!continues && !list_names.insert(p.list).second)
        throw bad("the points of list '" + p.list + "' are not together");
      const std::size_t expected = continues ? inputs.points.back().index + 1 : 0;
      if (p.index != expected)
        throw bad("expected point " + p.list + "[" + std::to_string(expected) + "], not [" + f[2] + "]");
      if (continues && p.dimension != inputs.points.back().dimension)
        throw bad("dimension " + f[3] + " differs from the list's " +
                  std::to_string(inputs.points.back().dimension));
      inputs.points.push_back(p);
    } else {
      throw bad("expected param NAME DEFAULT LO HI or points LIST INDEX DIMENSION X Y Z");
    }
  }
  return inputs;
}

std::uint64_t lab_seed(const std::string& lab, std::uint64_t seed) {
  // FNV-1a, 64 bit (Fowler, Noll, Vo): offset basis and prime of the spec.
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const char c : lab) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ull;
  }
  return hash ^ seed;
}

double unit_interval(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

std::vector<std::vector<std::string>> hidden_sets(const LabInputs& inputs, const std::string& lab, int n,
                                                  std::uint64_t seed) {
  if (n < 0)
    throw UsageError("hidden inputs of " + lab + ": " + std::to_string(n) + " draws (expected 0 or more)");
  // Each list's extent: the largest side of its defaults' box in the
  // coordinates it is dragged in, at least kMinExtent.
  std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> box;  // low, high corner
  for (const PointRange& p : inputs.points) {
    const std::vector<double> c = dragged(p);
    const auto [at, first] = box.try_emplace(p.list, c, c);
    if (first) continue;
    auto& [low, high] = at->second;
    for (std::size_t i = 0; i < c.size() && i < low.size(); ++i) {
      low[i] = std::min(low[i], c[i]);
      high[i] = std::max(high[i], c[i]);
    }
  }
  std::map<std::string, double> extent;
  for (const auto& [list, corners] : box) {
    double side = kMinExtent;
    for (std::size_t i = 0; i < corners.first.size(); ++i)
      side = std::max(side, corners.second[i] - corners.first[i]);
    extent[list] = side;
  }

  std::mt19937_64 engine(lab_seed(lab, seed));
  const auto uniform = [&] { return unit_interval(engine()); };
  std::vector<std::vector<std::string>> draws;
  for (int d = 0; d < n; ++d) {
    std::vector<std::string> sets;
    // One generator output per param and per moved coordinate, in order,
    // whatever the rule: the layout of the stream is fixed by the inputs.
    for (const ParamRange& p : inputs.params) {
      const double u = uniform();
      std::string value;
      if (p.is_switch()) {
        value = u < 0.5 ? "0" : "1";
      } else if (p.is_integer()) {
        const double count = p.hi - p.lo + 1;
        const double k = std::min(p.lo + std::floor(u * count), p.hi);
        value = std::to_string(static_cast<long long>(k));
      } else if (const auto grid = grid_range(p.lo, p.hi)) {
        const long long k = std::llround((p.lo + u * (p.hi - p.lo)) * kGrid);
        value = grid_text(std::clamp(k, grid->first, grid->second));
      } else {
        value = shortest(p.value);  // no multiple of 0.001 in [lo, hi]
      }
      sets.push_back(p.name + "=" + value);
    }
    for (const PointRange& p : inputs.points) {
      const double reach = kMoveShare * extent.at(p.list);
      std::string text;
      for (const double c : dragged(p)) {
        const double moved = c + (2 * uniform() - 1) * reach;
        text += (text.empty() ? "" : ",") + grid_text(std::llround(moved * kGrid));
      }
      sets.push_back(p.list + "[" + std::to_string(p.index) + "]=" + text);
    }
    draws.push_back(std::move(sets));
  }
  return draws;
}

}  // namespace gllab::grading
