// common/harness/model_file.cpp — save and load a lab's model (model_file.h).
#include "harness/model_file.h"

#include <stdexcept>
#include <type_traits>
#include <vector>

#include "io/spline_json.h"

namespace gllab {

static_assert(std::is_same_v<Model, io::SplineFile>, "a lab's Model is written as an io::SplineFile");

namespace {

const char* kind(const Model& m) {
  static const char* const kKinds[] = {"bspline_curve", "bezier_curve", "bspline_surface"};
  return kKinds[m.index()];
}

const std::vector<spline::Vec3>& control_points(const Model& m) {
  return std::visit([](const auto& object) -> const std::vector<spline::Vec3>& { return object.P; }, m);
}

struct Mismatch : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

void same_number(const char* what, double in_file, double in_lab) {
  if (in_file != in_lab)
    throw Mismatch(std::string(what) + " is " + io::shortest_text(in_file) + " in the file, " +
                   io::shortest_text(in_lab) + " in the lab");
}

void same_values(const char* what, const std::vector<double>& in_file, const std::vector<double>& in_lab) {
  if (in_file.size() != in_lab.size())
    throw Mismatch(std::string("the file has ") + std::to_string(in_file.size()) + " " + what + ", the lab " +
                   std::to_string(in_lab.size()));
  for (std::size_t i = 0; i < in_file.size(); ++i)
    if (in_file[i] != in_lab[i])
      throw Mismatch(std::string(what) + "[" + std::to_string(i) + "] is " + io::shortest_text(in_file[i]) +
                     " in the file, " + io::shortest_text(in_lab[i]) + " in the lab");
}

// The first difference a student can act on (a parameter given differently),
// then everything else through the canonical text.
void same_model(const Model& file, const Model& lab) {
  if (const auto* f = std::get_if<spline::BsplineCurve>(&file)) {
    const auto& l = std::get<spline::BsplineCurve>(lab);
    same_number("degree", f->p, l.p);
    same_values("knots", f->U, l.U);
    same_values("weights", f->w, l.w);
  } else if (const auto* f = std::get_if<spline::BezierCurve>(&file)) {
    const auto& l = std::get<spline::BezierCurve>(lab);
    same_number("interval start", f->a, l.a);
    same_number("interval end", f->b, l.b);
  } else {
    const auto& fs = std::get<spline::BsplineSurface>(file);
    const auto& ls = std::get<spline::BsplineSurface>(lab);
    same_number("degree_u", fs.p, ls.p);
    same_number("degree_v", fs.q, ls.q);
    same_number("rows of points", fs.nu, ls.nu);
    same_values("knots_u", fs.U, ls.U);
    same_values("knots_v", fs.V, ls.V);
    same_values("weights", fs.w, ls.w);
    if (fs.trims.size() != ls.trims.size())
      throw Mismatch("the file has " + std::to_string(fs.trims.size()) + " trim loops, the lab " +
                     std::to_string(ls.trims.size()));
  }
  if (control_points(file) != control_points(lab))
    throw Mismatch("the lab does not draw the file's control points (its model ignores its first point list)");
  if (io::to_text(file) != io::to_text(lab)) throw Mismatch("the file differs from the lab's model (trims or dimension)");
}

const Lab& with_model(const Lab& lab) {
  if (!lab.model) throw std::invalid_argument("lab " + lab.id + " has no curve or surface to save or load");
  return lab;
}

}  // namespace

std::string model_noun(const Lab& lab) {
  if (!lab.model) return "";
  return lab.model(State(lab.views, lab.params, lab.points)).index() == 2 ? "surface" : "curve";
}

std::string model_file_name(const Lab& lab, const State& state) { return lab.id + "__" + state.view() + ".json"; }

void save_model(const Lab& lab, const State& state, const std::string& path) {
  io::write_file(path, with_model(lab).model(state));
}

void load_model(const Lab& lab, State& state, const std::string& path) {
  with_model(lab);
  const io::SplineFile file = io::read_any(path);
  const Model before = lab.model(state);
  if (file.index() != before.index())
    throw std::invalid_argument(path + ": a " + kind(file) + ", but lab " + lab.id + " edits a " + kind(before));
  try {
    state.set_points(lab.points.front().name, control_points(file));
    same_model(file, lab.model(state));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(path + ": " + e.what() + " (give --load the --set values it was saved with)");
  }
}

}  // namespace gllab
