// common/harness/model_file.h — a lab's curve or surface as a spline-core file.
//
// A lab that edits one curve or surface sets Lab::model. In the window,
// [Ctrl+S] writes that object as <lab>__<view>.json in the core's format
// (common/io/README.md: splinetool and the tests read it too), and prints
// the headless command that renders the same picture from it:
//   ./lab render 13 --view knot_insertion --load 15_bspline_curves__knot_insertion.json --out x.png
// --load (both runners) puts the file's control points into the lab's first
// point list and then checks that the lab, with the other --set values of
// the command line, builds exactly the file's object: same type, degrees,
// knots and weights. A file that the lab cannot reproduce is an error naming
// the first difference, never a silently different picture.
#pragma once

#include <string>

#include "harness/lab.h"

namespace gllab {

/// "curve" or "surface": what the lab's model is (for help texts); "" without one.
std::string model_noun(const Lab& lab);

/// The file name [Ctrl+S] writes: "<lab>__<view>.json".
std::string model_file_name(const Lab& lab, const State& state);

/// Writes lab.model(state) to path atomically. Throws std::invalid_argument
/// when the lab has no model, io::FileError when the file cannot be written.
void save_model(const Lab& lab, const State& state, const std::string& path);

/// Reads path into the state as described above. Throws io::FileError for a
/// bad file and std::invalid_argument naming the difference (wrong type,
/// point count, degree, knot, weight) or when the lab has no model.
void load_model(const Lab& lab, State& state, const std::string& path);

}  // namespace gllab
