// common/harness/options.cpp — parsing with one-line errors that name the value.
#include "harness/options.h"

#include "harness/model_file.h"
#include "io/spline_json.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <utility>

namespace gllab {

namespace {

int parse_dimension(const std::string& part, const std::string& whole) {
  if (part.empty() || part.size() > 5 || part.find_first_not_of("0123456789") != std::string::npos)
    throw UsageError("malformed --size '" + whole + "' (expected WxH, e.g. 512x512)");
  const int v = std::atoi(part.c_str());
  if (v < 1 || v > kMaxSize)
    throw UsageError("--size '" + whole + "': " + part + " is outside 1.." +
                     std::to_string(kMaxSize));
  return v;
}

}  // namespace

void parse_size(const std::string& text, int& width, int& height) {
  const auto x = text.find('x');
  if (x == std::string::npos)
    throw UsageError("malformed --size '" + text + "' (expected WxH, e.g. 512x512)");
  width = parse_dimension(text.substr(0, x), text);
  height = parse_dimension(text.substr(x + 1), text);
}

namespace {

// The options of the two runners. Those that take a value list it here too.
const std::vector<std::string> kHeadlessOnly = {"--headless", "--out",        "--views",
                                                "--info",     "--print-text", "--text-out"};
const std::vector<std::string> kWindowOnly = {"--capture", "--capture-views", "--capture-at-exit",
                                              "--frames"};
const std::vector<std::string> kTakesValue = {
    "--view",    "--views",         "--size",            "--out",    "--set",    "--load",
    "--capture", "--capture-views", "--capture-at-exit", "--frames", "--camera", "--time",
    "--text-out"};

bool one_of(const std::string& a, const std::vector<std::string>& list) {
  return std::find(list.begin(), list.end(), a) != list.end();
}

}  // namespace

Runner runner_for(const std::vector<std::string>& args) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (one_of(args[i], kHeadlessOnly)) return Runner::kHeadless;
    if (one_of(args[i], kTakesValue)) ++i;  // its value is not an option
  }
  return Runner::kWindow;
}

Options parse_options(const std::vector<std::string>& args, Runner runner) {
  Options o;
  const bool headless = runner == Runner::kHeadless;
  const std::string out_flag = headless ? "--out" : "--capture";
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
      // An empty value is never meant: --view '' would draw the default view.
      if (args[i + 1].empty()) throw UsageError(a + " '' is empty (" + a + " needs a value)");
      return args[++i];
    };
    // An option of the other runner: say which way it runs.
    if (headless && one_of(a, kWindowOnly))
      throw UsageError(a + " is a window option; it does not go with --headless or --out");
    if (!headless && one_of(a, kHeadlessOnly))
      throw UsageError(a + " renders headless; it does not go with window options");
    if (a == "--view") o.view = value();
    else if (a == "--headless") continue;  // runner_for chose the runner
    else if (a == "--views") {
      std::stringstream list(value());
      for (std::string v; std::getline(list, v, ',');)
        if (!v.empty()) o.views.push_back(v);
      if (o.views.empty()) throw UsageError("--views needs view names, e.g. --views default,wireframe");
    }
    else if (a == "--size") parse_size(value(), o.width, o.height);
    else if (a == out_flag) o.out = value();
    else if (a == "--set") o.sets.push_back(value());
    else if (a == "--load") o.load = value();
    else if (a == "--capture-views") o.capture_views = value();
    else if (a == "--capture-at-exit") o.capture_at_exit = value();
    else if (a == "--frames") {
      const std::string& n = value();
      char* end = nullptr;
      const long frames = std::strtol(n.c_str(), &end, 10);
      if (n.empty() || *end != '\0' || !std::isdigit(static_cast<unsigned char>(n[0])) ||
          frames < 1 || frames > kMaxFrames)
        throw UsageError("--frames '" + n + "' (expected a whole number 1.." +
                         std::to_string(kMaxFrames) + ")");
      o.frames = static_cast<int>(frames);
    }
    else if (a == "--camera") o.camera = value();
    else if (a == "--time") {
      const std::string& t = value();
      char* end = nullptr;
      o.time = std::strtod(t.c_str(), &end);
      if (t.empty() || *end != '\0' || !std::isfinite(o.time) || o.time < 0)
        throw UsageError("malformed --time '" + t + "' (expected seconds >= 0)");
    } else if (a == "--overlay") o.overlay = true;
    else if (a == "--list-views") o.list_views = true;
    else if (a == "--list-params") o.list_params = true;
    else if (a == "--info") o.info = true;
    else if (a == "--print-text") o.print_text = true;
    else if (a == "--text-out") o.text_out = value();
    else if (a == "--help" || a == "-h") o.help = true;
    else throw UsageError("unknown option '" + a + "' (try --help)");
  }
  const bool listing = o.list_views || o.list_params;
  if (o.out.empty() && runner == Runner::kHeadless && !o.help && !listing && !o.info)
    throw UsageError("missing --out FILE (the PNG to write)");
  if (!o.views.empty() && o.out != "-") throw UsageError("--views goes with --out - (one raw frame per view on stdout)");
  if (!o.views.empty() && !o.view.empty()) throw UsageError("give --view or --views, not both");
  if (!o.out.empty() && o.out.back() == '/')
    throw UsageError(out_flag + " '" + o.out + "' is a directory, not a PNG file name");
  return o;
}

State make_state(const Lab& lab, const Options& options) {
  State s(lab.views, lab.params, lab.points);
  s.width = options.width;
  s.height = options.height;
  s.time = options.time;
  s.help = options.overlay;
  try {
    if (!options.view.empty()) s.select_view(options.view);
    if (!options.camera.empty()) s.set_camera_from_text(options.camera);
    for (const std::string& v : options.views) s.select_view(v);  // each must exist; the first is drawn first
    if (!options.views.empty()) s.select_view(options.views.front());
    for (const std::string& set : options.sets) s.set_from_text(set);
    if (!options.load.empty()) load_model(lab, s, options.load);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  } catch (const io::FileError& e) {
    throw UsageError(e.what());
  }
  return s;
}

namespace {

// "  name    what": the whats line up, at least two spaces after the longest name.
std::string columns(const std::vector<std::pair<std::string, std::string>>& rows, std::size_t min_width) {
  std::size_t width = min_width;
  for (const auto& row : rows) width = std::max(width, row.first.size() + 2);
  std::ostringstream out;
  for (const auto& [name, what] : rows) out << "  " << name << std::string(width - name.size(), ' ') << what << '\n';
  return out.str();
}

}  // namespace

std::string views_text(const Lab& lab) {
  std::vector<std::pair<std::string, std::string>> rows;
  for (const View& v : lab.views)
    rows.emplace_back(v.name, v.expect_error() ? v.what + " (error view: headless exits 1)" : v.what);
  return columns(rows, 20);
}

std::string list_views_text(const Lab& lab) {
  std::string text;
  for (const View& v : lab.views) {
    text += v.name;
    if (v.expect_error()) text += " expect_error";
    if (!v.same_as.empty()) text += " same_as=" + v.same_as;
    text += "\n";
  }
  return text;
}

std::string list_params_text(const Lab& lab) {
  // io::shortest_text reads back as the same double: --set t=0.6 is the default.
  const auto number = [](double v) { return io::shortest_text(v); };
  std::string text;
  for (const Param& p : lab.params)
    text += "param " + p.name + " " + number(p.value) + " " + number(p.lo) + " " + number(p.hi) + "\n";
  for (const PointList& l : lab.points)
    for (std::size_t i = 0; i < l.points.size(); ++i) {
      const spline::Vec3& q = l.points[i];
      text += "points " + l.name + " " + std::to_string(i) + " " + std::to_string(l.dimension) + " " +
              number(q.x) + " " + number(q.y) + " " + number(q.z) + "\n";
    }
  return text;
}

std::string listing_text(const Lab& lab, const Options& options) {
  return (options.list_views ? list_views_text(lab) : "") +
         (options.list_params ? list_params_text(lab) : "");
}

std::string usage_text(const Lab& lab, const std::string& program) {
  std::ostringstream out;
  out << lab.title << "\n\n"
      << "usage: " << program << " [--view NAME] [--size WxH] [--set key=value]... [--capture FILE.png]\n"
      << "       " << program
      << " --headless --out FILE.png [--view NAME] [--size WxH] [--set key=value]...\n"
      << "       " << program << " --list-views | --list-params | --info | --help\n\n"
      << "Without --headless it opens the lab in a window (freeglut). --capture draws the\n"
      << "first frame, writes it as PNG and exits (window smoke test); --capture-views DIR\n"
      << "does so for every view, as DIR/<lab>__<view>.png (graders compare window and\n"
      << "headless renders); --capture-at-exit FILE writes the last frame shown when the\n"
      << "window closes (scripted tests); --frames N draws the view N more times after the\n"
      << "first, prints the time per frame and exits (the figures of the labs' READMEs).\n\n"
      << "--headless renders one view without a display and writes a PNG; --out, --views,\n"
      << "--info, --print-text and --text-out imply it. --out - writes the raw frame to\n"
      << "stdout as PAM, for graders; --views a,b,c with --out - renders several views in\n"
      << "one run, one PAM each. --info prints the backend (EGL or OSMesa), the renderer\n"
      << "and the versions.\n"
      << "Exit status: 0 written, 1 GL/GLU error or unwritable file, 2 bad arguments.\n"
      << "--print-text also prints every text the frame drew (labels, numbers), one per line.\n"
      << "--text-out FILE writes it to FILE instead, for every view: a line \"== VIEW N\", then\n"
      << "its N lines (graders compare it with reference_images/<lab>__<view>.txt).\n"
      << "--list-views prints the views, one per line; --list-params prints every parameter\n"
      << "as \"param NAME DEFAULT LO HI\" and every point as \"points LIST INDEX DIMENSION X Y Z\"\n"
      << "(graders draw hidden inputs from these ranges). Neither needs a display.\n\n";
  out << "options:\n"
      << "  --view NAME       view to show (default: " << lab.views.front().name << ")\n"
      << "  --size WxH        framebuffer size in pixels (default 512x512)\n"
      << "  --set key=value   lab parameter (repeatable; see below)\n";
  if (std::any_of(lab.views.begin(), lab.views.end(), [](const View& v) { return v.orbit(); }))
    out << "  --camera Y,P,Z    3D views: yaw and pitch in degrees, zoom (default 0,0,1; `p` prints it)\n";
  if (!lab.points.empty())
    out << "  --set P[i]=x,y    move point i of a point list (x,y,z for 3D lists)\n";
  if (lab.model)
    out << "  --load FILE.json  the lab's " << model_noun(lab)
        << " from a spline file (after the --set values; [Ctrl+S] in the window writes one)\n";
  out << "  --time SECONDS    animation time (default 0)\n"
      << "  --overlay         draw the help overlay\n\n"
      << "views:\n" << views_text(lab) << "\nparameters:\n";
  if (lab.params.empty()) out << "  (none)\n";
  std::vector<std::pair<std::string, std::string>> params;
  for (const Param& p : lab.params) {
    std::ostringstream range;
    range << p.name << '=' << p.value << " [" << p.lo << ".." << p.hi << "]";
    params.emplace_back(range.str(), p.what);
  }
  out << columns(params, 26);
  if (!lab.points.empty()) {
    out << "\npoint lists:\n";
    std::vector<std::pair<std::string, std::string>> lists;
    for (const PointList& l : lab.points)
      lists.emplace_back(l.name + "[0.." + std::to_string(l.points.size() - 1) + "] " + std::to_string(l.dimension) + "D",
                         l.what);
    out << columns(lists, 26);
  }
  // The window's keys and mouse.
  out << "\nkeys:\n  v / V   next / previous view\n  h       help overlay\n"
      << "  p       print the command that renders this state headless\n";
  if (lab.model) out << "  Ctrl+S  save the " << model_noun(lab)
                     << " as <lab>__<view>.json and print the command that renders it\n";
  out << "  Esc     quit\n";
  for (const Key& k : lab.keys) out << "  " << k.key << "       " << k.what << '\n';
  const bool orbit = std::any_of(lab.views.begin(), lab.views.end(), [](const View& v) { return v.orbit(); });
  if (orbit) out << "  0       reset the camera of a 3D view\n";
  if (!lab.points.empty() || orbit) out << "\nmouse:\n";
  if (!lab.points.empty()) out << "  drag a point with the left button (its coordinates show while it moves)\n";
  if (orbit) out << "  3D views: drag with the right button to turn, the wheel zooms\n";
  return out.str();
}

std::string program_name(const char* argv0) {
  std::string name = argv0 ? argv0 : "lab";
  const auto slash = name.rfind('/');
  if (slash != std::string::npos) name = name.substr(slash + 1);
  return name;
}

}  // namespace gllab
