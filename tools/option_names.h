// tools/option_names.h — the NAME,NAME,... lists of labgrade's and labrun's
// --labs and --views, read the same way by both.
#pragma once

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace gllab {

/// The names of `text` ("a,b"). An empty name ("", "a,,b", "a,") throws Error
/// (the tool's usage error): an empty --labs must not mean "every lab", which
/// for labrun would rewrite every reference.
template <class Error>
std::vector<std::string> option_names(const std::string& option, const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ',');) parts.push_back(part);
  if (text.empty() || text.back() == ',' ||
      std::any_of(parts.begin(), parts.end(), [](const std::string& p) { return p.empty(); }))
    throw Error(option + " '" + text + "' has an empty name (expected NAME,NAME,...)");
  return parts;
}

}  // namespace gllab
