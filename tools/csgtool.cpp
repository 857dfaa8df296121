// tools/csgtool.cpp — constructive solid geometry from the command line (lecture
// notes ch. 1, "Solid Representation", "Constructive Solid Geometry";
// common/space/csg.h).
//
//   csgtool classify TREE.json X,Y,Z [X,Y,Z ...] [--tolerance T]   inside / outside / on
//   csgtool volume TREE.json [--samples N] [--seed S] [--rays N]     Monte Carlo and rays
//   csgtool render TREE.json --out IMAGE.png [--size WxH] [--azimuth DEG] [--elevation DEG]
//   csgtool info TREE.json                                           the tree as an outline
//
// TREE.json is a "csg" file (common/io/README.md "CSG trees"). Errors: one line on
// stderr, exit 2 for bad input or usage, 1 when an output (the PNG, stdout) cannot be
// written, 0 otherwise (splinetool's conventions). `csgtool COMMAND --help` explains each.
#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.h"
#include "image/image.h"
#include "io/csg_json.h"
#include "io/spline_json.h"
#include "space/csg.h"

namespace {

using gllab::cli::kBadInput, gllab::cli::kFailed, gllab::cli::kOk;
using gllab::cli::OutputError, gllab::cli::UsageError;
using gllab::cli::parse_count, gllab::cli::parse_number;
using gllab::io::CsgFile;
using gllab::io::FileError;
using gllab::io::shortest_text;
using gllab::spline::Vec3;
namespace space = gllab::space;

using Options = std::map<std::string, std::string>;

struct Command {
  const char* name;
  const char* summary;
  const char* help;                   // printed by `csgtool NAME --help`
  std::vector<std::string> options;   // each takes a value: --name VALUE or --name=VALUE
  int min_positional, max_positional; // TREE.json and, for classify, the points
  std::function<int(const std::vector<std::string>& positional, const Options& options)> run;
};

std::optional<std::string> option(const Options& options, const std::string& name) {
  const auto it = options.find(name);
  if (it == options.end()) return std::nullopt;
  return it->second;
}

std::vector<std::string> split_list(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.push_back("");
  return parts;
}

std::string number(double x, int digits = 9) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return buffer;
}

std::string point_text(const Vec3& p) {
  return "[" + shortest_text(p.x) + ", " + shortest_text(p.y) + ", " + shortest_text(p.z) + "]";
}

std::string bounds_text(const space::Box3& b) { return point_text(b.lo) + " " + point_text(b.hi); }

// --- classify ----------------------------------------------------------------------------

Vec3 parse_point(const std::string& text) {
  const std::vector<std::string> parts = split_list(text, ',');
  if (parts.size() != 3)
    throw UsageError("point '" + text + "': " + std::to_string(parts.size()) +
                     " coordinate" + (parts.size() == 1 ? "" : "s") + " (expected X,Y,Z)");
  const std::string what = "point '" + text + "'";
  return {parse_number(parts[0], what), parse_number(parts[1], what), parse_number(parts[2], what)};
}

int classify(const std::vector<std::string>& positional, const Options& options) {
  double tolerance = 1e-9;
  if (const auto t = option(options, "tolerance")) {
    tolerance = parse_number(*t, "--tolerance");
    if (!(tolerance >= 0)) throw UsageError("--tolerance: " + *t + " (must be >= 0)");
  }
  std::vector<Vec3> points;
  for (std::size_t i = 1; i < positional.size(); ++i) points.push_back(parse_point(positional[i]));
  const CsgFile file = gllab::io::read_csg(positional[0]);
  for (const Vec3& p : points)
    std::cout << shortest_text(p.x) << " " << shortest_text(p.y) << " " << shortest_text(p.z) << " "
              << space::where_name(space::classify(file.tree, p, tolerance)) << "\n";
  return kOk;
}

// --- volume --------------------------------------------------------------------------------

std::uint64_t parse_seed(const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if (text.empty() || !std::isdigit(static_cast<unsigned char>(text[0])) || end != text.c_str() + text.size())
    throw UsageError("--seed: '" + text + "' is not a whole number >= 0");
  if (errno == ERANGE) throw UsageError("--seed: " + text + " (must be below 2^64)");
  return static_cast<std::uint64_t>(v);
}

int volume(const std::vector<std::string>& positional, const Options& options) {
  const auto samples_text = option(options, "samples");
  const int samples = samples_text ? parse_count(*samples_text, "--samples", 1, 100000000) : 100000;
  const std::uint64_t seed = option(options, "seed") ? parse_seed(*option(options, "seed")) : 1;
  const auto rays_text = option(options, "rays");
  const int rays = rays_text ? parse_count(*rays_text, "--rays", 2, 4096) : 256;
  if (rays % 2 != 0)
    throw UsageError("--rays: " + *rays_text + " (must be even: the error compares with the n/2 grid)");
  const CsgFile file = gllab::io::read_csg(positional[0]);
  const space::VolumeEstimate mc =
      space::volume_monte_carlo(file.tree, static_cast<std::size_t>(samples), seed);
  const space::VolumeEstimate by_rays = space::volume_by_rays(file.tree, rays);
  std::cout << "monte_carlo " << number(mc.value) << " ± " << number(mc.error) << " (" << mc.samples
            << " samples, seed " << seed << ", 3 standard errors)\n"
            << "rays " << number(by_rays.value) << " ± " << number(by_rays.error) << " (" << rays << " x "
            << rays << " rays along z, error = change from the " << rays / 2 << " x " << rays / 2
            << " grid)\n"
            << "bounds " << bounds_text(file.tree.bounds()) << "\n";
  return kOk;
}

// --- render ----------------------------------------------------------------------------------

using Matrix = std::array<double, 16>;  // column-major, as glGetDoublev returns it

/// glOrtho's matrix.
Matrix ortho(double l, double r, double b, double t, double n, double f) {
  Matrix m{};
  m[0] = 2 / (r - l);
  m[5] = 2 / (t - b);
  m[10] = -2 / (f - n);
  m[12] = -(r + l) / (r - l);
  m[13] = -(t + b) / (t - b);
  m[14] = -(f + n) / (f - n);
  m[15] = 1;
  return m;
}

/// gluLookAt's matrix: rows s, u, -f (f from the eye to the centre), then -eye.
Matrix look_at(Vec3 eye, Vec3 centre, Vec3 up) {
  using gllab::spline::cross, gllab::spline::dot, gllab::spline::normalized;
  const Vec3 f = normalized(centre - eye);
  const Vec3 s = normalized(cross(f, up));
  const Vec3 u = cross(s, f);
  Matrix m{};
  m[0] = s.x, m[4] = s.y, m[8] = s.z, m[12] = -dot(s, eye);
  m[1] = u.x, m[5] = u.y, m[9] = u.z, m[13] = -dot(u, eye);
  m[2] = -f.x, m[6] = -f.y, m[10] = -f.z, m[14] = dot(f, eye);
  m[15] = 1;
  return m;
}

/// Okabe and Ito's colour-blind-safe palette (black replaced by light grey),
/// indexed by primitive id modulo 8.
constexpr std::uint8_t kPalette[8][3] = {{230, 159, 0},  {86, 180, 233}, {0, 158, 115},  {240, 228, 66},
                                         {0, 114, 178},  {213, 94, 0},   {204, 121, 167}, {220, 220, 220}};
constexpr std::uint8_t kBackground = 40;  // dark grey

int render(const std::vector<std::string>& positional, const Options& options) {
  const auto out = option(options, "out");
  if (!out) throw UsageError("render needs --out IMAGE.png");
  if (out->empty()) throw UsageError("--out: empty file name");
  int width = 512, height = 512;
  if (const auto size = option(options, "size")) {
    const std::size_t x = size->find('x');
    if (x == std::string::npos) throw UsageError("--size: '" + *size + "' is not WxH (e.g. 640x480)");
    width = parse_count(size->substr(0, x), "--size (width)", 1, 8192);
    height = parse_count(size->substr(x + 1), "--size (height)", 1, 8192);
  }
  const double azimuth = option(options, "azimuth") ? parse_number(*option(options, "azimuth"), "--azimuth") : 30;
  const double elevation =
      option(options, "elevation") ? parse_number(*option(options, "elevation"), "--elevation") : 25;
  if (!(elevation >= -90 && elevation <= 90))
    throw UsageError("--elevation: " + shortest_text(elevation) + " (must be -90..90)");
  const CsgFile file = gllab::io::read_csg(positional[0]);

  // The labs' camera (gl/space_view.h): z up, azimuth about z, elevation above the
  // x-y plane; at azimuth 0, elevation 0 the viewer stands on the -y side.
  const double pi = std::acos(-1.0), a = azimuth * pi / 180, e = elevation * pi / 180;
  const Vec3 back{-std::cos(e) * std::sin(a), -std::cos(e) * std::cos(a), std::sin(e)};  // to the viewer
  const Vec3 up{std::sin(e) * std::sin(a), std::sin(e) * std::cos(a), std::cos(e)};
  const space::Box3 bounds = file.tree.bounds();
  Vec3 centre = bounds.centre();
  double radius = 0.5 * gllab::spline::norm(bounds.size());
  const Vec3 size = bounds.size();
  if (!(radius > 0 && std::isfinite(radius) && size.x >= 0 && size.y >= 0 && size.z >= 0)) {
    centre = {0, 0, 0};  // an empty solid: show the background around the origin
    radius = 1;
  }
  const double distance = 3 * radius, half = 1.05 * radius;
  const double aspect = static_cast<double>(width) / height;
  const double hw = aspect >= 1 ? half * aspect : half, hh = aspect >= 1 ? half : half / aspect;
  const Matrix projection = ortho(-hw, hw, -hh, hh, distance - 1.5 * radius, distance + 1.5 * radius);
  const Matrix modelview = look_at(centre + distance * back, centre, up);
  space::PixelCamera camera;
  camera.inverse_mvp = space::inverse_mvp(projection, modelview);
  camera.width = width;
  camera.height = height;
  const std::vector<space::CastPixel> pixels = space::cast_image(file.tree, camera);

  gllab::Image image(width, height);
  std::size_t hits = 0;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const space::CastPixel& p = pixels[static_cast<std::size_t>(j) * width + i];
      std::uint8_t* rgba = image.pixel(i, height - 1 - j);  // cast_image is bottom-up
      rgba[3] = 255;
      if (p.primitive < 0) {
        rgba[0] = rgba[1] = rgba[2] = kBackground;
        continue;
      }
      ++hits;
      // Lambert with a headlight: the light comes from the viewer.
      const double shade = 0.25 + 0.75 * std::min(1.0, std::fabs(gllab::spline::dot(
                                                           gllab::spline::normalized(p.normal), back)));
      const std::uint8_t* colour = kPalette[p.primitive % 8];
      for (int c = 0; c < 3; ++c) rgba[c] = static_cast<std::uint8_t>(std::lround(colour[c] * shade));
    }
  try {
    gllab::write_png(*out, image);
  } catch (const gllab::ImageError& e) {
    throw OutputError(e.what());
  }
  std::cout << "wrote " << *out << ": " << width << " x " << height << ", " << hits
            << " pixels on the solid (azimuth " << shortest_text(azimuth) << ", elevation "
            << shortest_text(elevation) << ")\n";
  return kOk;
}

// --- info --------------------------------------------------------------------------------------

/// Display: 6 digits, round-off such as cos 90° = 6.1e-17 shown as 0.
std::string tidy(double x) { return number(std::fabs(x) < 1e-12 ? 0.0 : x, 6); }

class Outline {
 public:
  explicit Outline(const CsgFile& file) : file_(file), nodes_(file.tree.nodes()) {
    for (std::size_t i = 0; i < file.tree.leaves().size(); ++i) primitive_id_[file.tree.leaves()[i].node] = int(i);
  }

  std::string name(int i) const {
    const std::size_t k = static_cast<std::size_t>(i);
    if (k < file_.node_names.size() && !file_.node_names[k].empty()) return file_.node_names[k];
    return nodes_[k].name;
  }

  void print(int i, int depth, std::ostream& out) const {
    const space::CsgNode& n = nodes_[static_cast<std::size_t>(i)];
    const std::string pad(static_cast<std::size_t>(2 * depth), ' ');
    const std::string label = name(i).empty() ? "" : "  \"" + name(i) + "\"";
    switch (n.op) {
      case space::Op::kPrimitive: {
        out << pad << space::shape_name(n.shape);
        if (n.shape == space::Shape::kBox)
          out << " size " << tidy(n.size.x) << " x " << tidy(n.size.y) << " x " << tidy(n.size.z);
        else
          out << " radius " << tidy(n.radius);
        if (n.shape == space::Shape::kCylinder || n.shape == space::Shape::kCone) out << " height " << tidy(n.height);
        const auto id = primitive_id_.find(i);
        if (id != primitive_id_.end()) out << "  #" << id->second;
        out << label << "\n";
        return;
      }
      case space::Op::kTransform: {
        const auto& m = n.transform.m;
        out << pad << "transform [";
        for (int r = 0; r < 3; ++r)
          out << (r ? "; " : "") << tidy(m[4 * r]) << " " << tidy(m[4 * r + 1]) << " " << tidy(m[4 * r + 2]) << " | "
              << tidy(m[4 * r + 3]);
        out << "]" << label << "\n";
        print(n.left, depth + 1, out);
        return;
      }
      default: {
        // A left chain of one operator is shown as one node with several children,
        // as the file writes it.
        std::vector<int> rights{n.right};
        int c = n.left;
        while (nodes_[static_cast<std::size_t>(c)].op == n.op && name(c).empty()) {
          rights.push_back(nodes_[static_cast<std::size_t>(c)].right);
          c = nodes_[static_cast<std::size_t>(c)].left;
        }
        out << pad << space::op_name(n.op) << " " << space::op_symbol(n.op) << label << "\n";
        print(c, depth + 1, out);
        for (auto r = rights.rbegin(); r != rights.rend(); ++r) print(*r, depth + 1, out);
      }
    }
  }

  /// An upper bound of the number of products (before empty ones are dropped) of the
  /// node and of its complement, by the normalization rules of space::sum_of_products:
  /// (A ∪ B) has P_A + P_B, (A ∩ B) P_A P_B, (A − B) P_A Q_B; complements swap the roles.
  std::pair<double, double> product_bound(int i) const {
    const space::CsgNode& n = nodes_[static_cast<std::size_t>(i)];
    switch (n.op) {
      case space::Op::kPrimitive:
        return {1, 1};
      case space::Op::kTransform:
        return product_bound(n.left);
      default: {
        const auto [pa, qa] = product_bound(n.left);
        const auto [pb, qb] = product_bound(n.right);
        if (n.op == space::Op::kUnion) return {pa + pb, qa * qb};
        if (n.op == space::Op::kIntersection) return {pa * pb, qa + qb};
        return {pa * qb, qa + pb};
      }
    }
  }

 private:
  const CsgFile& file_;
  const std::vector<space::CsgNode>& nodes_;
  std::map<int, int> primitive_id_;
};

constexpr double kMaxProducts = 100000;  // beyond this, info does not expand the tree
constexpr std::size_t kProductsShown = 32;

int info(const std::vector<std::string>& positional, const Options&) {
  const CsgFile file = gllab::io::read_csg(positional[0]);
  const space::CsgTree& tree = file.tree;
  const Outline outline(file);
  std::cout << "tree\n";
  outline.print(tree.root(), 1, std::cout);
  const std::size_t primitives = tree.leaves().size();
  std::cout << "primitives " << primitives << "\n";
  std::cout << "nodes " << tree.nodes().size() << " (binary)\n";
  const double bound = outline.product_bound(tree.root()).first;
  if (bound > kMaxProducts) {
    std::cout << "products more than " << number(kMaxProducts) << " possible (not expanded)\n";
  } else {
    const std::vector<space::Product> products = space::sum_of_products(tree);
    std::cout << "products " << products.size() << "\n";
    auto label = [&](int id) {
      const space::CsgLeaf& leaf = tree.leaves()[static_cast<std::size_t>(id)];
      return "#" + std::to_string(id) + " " + (leaf.name.empty() ? space::shape_name(leaf.shape) : leaf.name);
    };
    for (std::size_t k = 0; k < products.size() && k < kProductsShown; ++k) {
      // Positive literals intersected, complemented ones subtracted: a ∩ b ∩ ¬c = a ∩ b − c.
      std::string text;
      for (const space::Literal& l : products[k])
        if (!l.complement) text += (text.empty() ? "" : " ∩ ") + label(l.primitive);
      for (const space::Literal& l : products[k])
        if (l.complement) text += " − " + label(l.primitive);
      std::cout << "  " << text << "\n";
    }
    if (products.size() > kProductsShown)
      std::cout << "  ... and " << products.size() - kProductsShown << " more\n";
  }
  std::cout << "bounds " << bounds_text(tree.bounds()) << "\n";
  return kOk;
}

// --- the command table ---------------------------------------------------------------

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"classify", "is each point inside, outside or on the solid",
       "usage: csgtool classify TREE.json X,Y,Z [X,Y,Z ...] [--tolerance T]\n"
       "\n"
       "Prints one line per point, \"x y z inside|outside|on\" (point-membership\n"
       "classification, space::classify): a point within T of a primitive's surface is on\n"
       "it, and the tree combines the primitives with the regularized rules.\n"
       "\n"
       "  X,Y,Z          a point: three numbers separated by commas, no spaces (-1,0,0.5)\n"
       "  --tolerance T  T >= 0, in object units (default 1e-9)\n",
       {"tolerance"}, 2, 1000000, classify},
      {"volume", "the volume by Monte Carlo and by rays",
       "usage: csgtool volume TREE.json [--samples N] [--seed S] [--rays N]\n"
       "\n"
       "Prints three lines:\n"
       "  monte_carlo V ± E (...)  uniform points in the bounds; E = 3 standard errors\n"
       "  rays V ± E (...)         rays along z through an N x N grid, each ray's inside\n"
       "                           length exact; E = |V(N) - V(N/2)|, an estimate\n"
       "  bounds [x0, y0, z0] [x1, y1, z1]   the box the estimates cover\n"
       "\n"
       "  --samples N   Monte Carlo points, 1..100000000 (default 100000)\n"
       "  --seed S      the generator's seed (std::mt19937_64), 0..2^64-1 (default 1)\n"
       "  --rays N      rays per axis, even, 2..4096 (default 256)\n",
       {"samples", "seed", "rays"}, 1, 1, volume},
      {"render", "ray-cast the solid into a PNG",
       "usage: csgtool render TREE.json --out IMAGE.png [--size WxH] [--azimuth DEG]\n"
       "                      [--elevation DEG]\n"
       "\n"
       "Casts a ray through every pixel centre (space::cast_image) of an orthographic\n"
       "camera looking at the centre of the tree's bounds (z up; the whole bounding box\n"
       "fits). Each pixel is its primitive's colour (8 colours, by primitive id) times\n"
       "0.25 + 0.75 |n . v| (a headlight), the background dark grey. The PNG is written\n"
       "atomically; exit 1 when it cannot be written.\n"
       "\n"
       "  --out FILE       the PNG to write (required)\n"
       "  --size WxH       pixels, each 1..8192 (default 512x512)\n"
       "  --azimuth DEG    the camera's turn about z (default 30; at 0 it looks along +y)\n"
       "  --elevation DEG  the camera's height above the x-y plane, -90..90 (default 25)\n",
       {"out", "size", "azimuth", "elevation"}, 1, 1, render},
      {"info", "the tree as an outline, its primitives and products",
       "usage: csgtool info TREE.json\n"
       "\n"
       "Prints the tree as an indented outline (operators, transforms as [L | t] rows,\n"
       "shapes with their sizes, primitive ids #k and names), then\n"
       "  primitives N\n"
       "  nodes N (binary)           the nodes of space::CsgTree\n"
       "  products N                 the sum of products (space::sum_of_products), each\n"
       "                             as \"a ∩ b − c\" (at most 32 shown)\n"
       "  bounds [x0, y0, z0] [x1, y1, z1]\n",
       {}, 1, 1, info},
  };
  return table;
}

void print_overview(std::ostream& out) {
  out << "usage: csgtool COMMAND TREE.json [arguments] [options]   (csgtool COMMAND --help for details)\n\n";
  for (const Command& c : commands())
    out << "  " << c.name << std::string(10 - std::string(c.name).size(), ' ') << c.summary << "\n";
  out << "\n"
         "  csgtool classify TREE.json X,Y,Z [X,Y,Z ...] [--tolerance T]\n"
         "  csgtool volume TREE.json [--samples N] [--seed S] [--rays N]\n"
         "  csgtool render TREE.json --out IMAGE.png [--size WxH] [--azimuth DEG] [--elevation DEG]\n"
         "  csgtool info TREE.json\n"
         "\nTREE.json: a \"csg\" file (common/io/README.md, examples/csg/). Errors: one line on\n"
         "stderr; exit 2 for bad input or usage, 1 when an output cannot be written, 0 otherwise.\n";
}

/// stdout may be a full disk or a closed pipe: say so (exit 1) instead of exiting 0.
int flushed(int status) {
  std::cout.flush();
  if (!std::cout) throw OutputError("stdout: cannot write (" + std::string(std::strerror(errno)) + ")");
  return status;
}

int run(int argc, char** argv) {
  if (argc < 2) throw UsageError("no command (csgtool --help lists them)");
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    print_overview(std::cout);
    return flushed(kOk);
  }
  const Command* command = nullptr;
  for (const Command& c : commands())
    if (name == c.name) command = &c;
  if (!command) throw UsageError("unknown command '" + name + "' (csgtool --help lists them)");

  const gllab::cli::SubcommandArgs args =
      gllab::cli::parse_subcommand(argc, argv, 2, command->options, "csgtool", name);
  if (args.help) {
    std::cout << command->help;
    return flushed(kOk);
  }
  const std::vector<std::string>& positional = args.positional;
  if (positional.empty()) throw UsageError(name + " needs a TREE.json (csgtool " + name + " --help)");
  if (static_cast<int>(positional.size()) < command->min_positional)
    throw UsageError(name + " needs at least one point X,Y,Z (csgtool " + name + " --help)");
  if (static_cast<int>(positional.size()) > command->max_positional)
    throw UsageError("unexpected argument '" + positional[static_cast<std::size_t>(command->max_positional)] + "'");
  return flushed(command->run(positional, args.options));
}

}  // namespace

int main(int argc, char** argv) {
  const std::string prefix = argc >= 2 ? std::string("csgtool ") + argv[1] + ": " : "csgtool: ";
  return gllab::cli::main_reporting(prefix, run, argc, argv);
}
