// tools/cli.h — what splinetool, isotool and csgtool share on the command line: their
// exit statuses, their kinds of error and the one line that reports them, and option
// values read as numbers with a one-line error naming the option and the text.
#pragma once

#include <algorithm>
#include <cerrno>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <map>
#include <string>
#include <vector>

#include "files/files.h"      // finish_stdout
#include "io/spline_json.h"  // FileError

namespace gllab::cli {

constexpr int kOk = 0;
constexpr int kFailed = 1;    // an output could not be written (or an internal error)
constexpr int kBadInput = 2;  // bad arguments or a bad input file

/// Bad arguments: exit 2 with one line.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// An output that cannot be written: exit 1 with one line.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The whole of `text` as a finite number; `what` names the option.
inline double parse_number(const std::string& text, const std::string& what) {
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() ||
      std::isspace(static_cast<unsigned char>(text[0])))
    throw UsageError(what + ": '" + text + "' is not a number");
  if (!std::isfinite(x)) throw UsageError(what + ": '" + text + "' is not finite");
  return x;
}

/// The whole of `text` as a whole number in lo..hi.
inline int parse_count(const std::string& text, const std::string& what, int lo, int hi) {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || end != text.c_str() + text.size() ||
      std::isspace(static_cast<unsigned char>(text[0])))
    throw UsageError(what + ": '" + text + "' is not a whole number");
  if (errno == ERANGE || v < lo || v > hi)
    throw UsageError(what + ": " + text + " (must be " + std::to_string(lo) + ".." +
                     std::to_string(hi) + ")");
  return static_cast<int>(v);
}

/// A subcommand's arguments (argv[first] on): positional ones, and --key VALUE or --key=VALUE
/// for the keys in `known`. `help` is set at --help or -h, and the rest is not read. Throws
/// UsageError for an unknown option (naming "<tool> <command> --help"), a repeated one, or one
/// without its value.
struct SubcommandArgs {
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;
  bool help = false;
};
inline SubcommandArgs parse_subcommand(int argc, char** argv, int first,
                                       const std::vector<std::string>& known,
                                       const std::string& tool, const std::string& command) {
  SubcommandArgs out;
  for (int i = first; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      out.help = true;
      return out;
    }
    if (arg.rfind("--", 0) != 0 || arg.size() == 2) {
      out.positional.push_back(arg);
      continue;
    }
    const std::size_t eq = arg.find('=');
    const std::string key = arg.substr(2, eq == std::string::npos ? std::string::npos : eq - 2);
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw UsageError("unknown option '--" + key + "' for " + command + " (" + tool + " " +
                       command + " --help)");
    if (out.options.count(key)) throw UsageError("--" + key + " given twice");
    if (eq != std::string::npos) {
      out.options[key] = arg.substr(eq + 1);
    } else {
      if (i + 1 >= argc) throw UsageError("--" + key + " needs a value");
      out.options[key] = argv[++i];
    }
    // An empty value is never meant (eval --at '' would evaluate nothing and succeed).
    if (out.options[key].empty()) throw UsageError("--" + key + " '' is empty (--" + key + " needs a value)");
  }
  return out;
}

/// A tool's main: runs `run(argc, argv)` and turns each kind of error into one line on
/// stderr after `prefix` (newlines in the message become spaces) and its exit status.
/// After a run that succeeded, standard output is flushed and checked: a write that
/// failed (a full disk, a closed pipe) is exit 1 with one line, never a silent 0.
template <class Run>
int main_reporting(const std::string& prefix, Run run, int argc, char** argv) {
  const auto report = [&prefix](std::string message, int status) {
    std::replace(message.begin(), message.end(), '\n', ' ');
    std::cerr << prefix << message << "\n";
    return status;
  };
  try {
    const int status = run(argc, argv);
    // What was printed must have reached stdout (a full disk, a closed pipe):
    // checked at the end, the last flush included, before exit 0.
    std::cout.flush();
    files::finish_stdout();
    return status;
  } catch (const files::FileError& e) {
    return report(e.what(), kFailed);
  } catch (const UsageError& e) {
    return report(e.what(), kBadInput);
  } catch (const OutputError& e) {
    return report(e.what(), kFailed);
  } catch (const io::FileError& e) {
    return report(e.what(), kBadInput);
  } catch (const std::invalid_argument& e) {
    // The core's checks: the input does not suit the operation.
    return report(e.what(), kBadInput);
  } catch (const std::exception& e) {
    return report(std::string("internal error: ") + e.what(), kFailed);
  }
}

}  // namespace gllab::cli
