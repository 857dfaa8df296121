// tools/hidden_inputs.h — labgrade's hidden inputs: parameters and points drawn
// from the ranges a lab declares, so a build is graded on pictures that no
// reference image shows (labgrade --hidden N --seed S).
//
// A lab declares its inputs with `<lab> --list-params` (harness/options.h,
// list_params_text), one per line:
//   param NAME DEFAULT LO HI              a Param (harness/lab.h)
//   points LIST INDEX DIMENSION X Y Z     one default point of a PointList
// and every draw is a list of --set values that the student's build and the
// instructor's build both render. The declared ranges, and how a draw uses them:
//   - a switch (range [0, 1], default 0 or 1: Param in harness/lab.h) gets 0 or 1;
//   - a param whose default, lo and hi are whole numbers gets a whole number
//     in [lo, hi], each equally likely (counts, indices and choices are read
//     with State::integer, which refuses a fraction; a whole number is valid
//     for any param);
//   - any other param gets a number uniform in [lo, hi], rounded to 3
//     decimals and kept in the range (the nearest multiple of 0.001 in
//     [lo, hi]; the default when the range holds no such multiple);
//   - every point of a list moves in the coordinates it is dragged in (x and
//     y for dimension 2, its z kept; x, y and z for dimension 3), each
//     coordinate by an amount uniform within ±5% (kMoveShare) of the list's
//     extent, and snaps to the 1/1000 grid (snap_to_grid, harness/lab.h), as
//     a point dragged in the window does. The extent is the largest side of
//     the bounding box of the list's defaults in those coordinates, and at
//     least 1 lab unit (kMinExtent): a list of one point (lab 30's cross-hair,
//     32's probe, 33's sphere centre) has no box, and those scenes are 2 to 4
//     units across (space_camera half-widths 1.1 to 1.9), so it moves by up to
//     0.05 units, a few pixels up to a dozen in a 512x512 frame. 5% moves
//     every curve and surface visibly and keeps the shape the lab teaches
//     (a control polygon, a lattice; close points may pass one another).
//   Each draw varies everything at once: every param and every point.
// A draw may hold a value that the lab shows an error for on purpose (lab
// 07's negative slices: GLU_INVALID_VALUE; lab 25's finer=-3: GLU's trim
// loops cross); the instructor's build then fails on it as well.
//
// Deterministic on every compiler and standard library: the numbers come from
// std::mt19937_64, whose sequence the standard fixes ([rand.predef]), mapped
// to [0, 1) here (unit_interval); no std::uniform_*_distribution, whose
// algorithm is the library's choice. The generator of a lab is seeded with
// lab_seed(lab, S) = FNV-1a(lab) xor S, so a lab's draws depend on S and its
// name only, not on which other labs are graded. Numbers are printed so that
// the lab reads back exactly the value drawn ("37", "1.234", "-0.5").
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gllab::grading {

/// A point moves by up to this share of its list's extent, each coordinate.
inline constexpr double kMoveShare = 0.05;
/// The extent of a list is at least this many lab units (a list of one point).
inline constexpr double kMinExtent = 1;
/// Numbers in --list-params are at most this large in magnitude (lab
/// coordinates are a few units): draws on the 1/1000 grid stay exact integers
/// times 0.001 (1e12 * 1000 < 2^53).
inline constexpr double kMaxMagnitude = 1e12;

/// "param NAME DEFAULT LO HI"
struct ParamRange {
  std::string name;
  double value = 0;  // the default
  double lo = 0, hi = 1;
  /// Range [0, 1] and default 0 or 1 (Param, harness/lab.h).
  bool is_switch() const;
  /// Default, lo and hi are whole numbers.
  bool is_integer() const;
};

/// "points LIST INDEX DIMENSION X Y Z": the default of point LIST[INDEX].
struct PointRange {
  std::string list;
  std::size_t index = 0;
  int dimension = 2;  // 2: x, y move (z kept); 3: x, y, z move
  double x = 0, y = 0, z = 0;
};

/// A lab's inputs, in the order of its --list-params.
struct LabInputs {
  std::vector<ParamRange> params;
  std::vector<PointRange> points;  // each list's points together, indices 0, 1, ...
};

/// Parses `<lab> --list-params` output. Throws UsageError (grading.h) naming
/// the lab, the line number and the line, and what was expected: a line that
/// is neither form, a name that --set cannot take, a number that is not finite
/// or beyond kMaxMagnitude, lo > hi or a default outside [lo, hi], a name
/// given twice, a point out of order (indices 0, 1, ... per list, the list's
/// points together) or a dimension other than 2 or 3 or not the list's.
LabInputs parse_lab_inputs(const std::string& text, const std::string& lab);

/// n draws (0 <= n; UsageError otherwise), each the --set values of every
/// param ("slices=37") and then every point ("P[2]=1.234,0.5", or
/// "P[2]=1.234,0.5,2" for dimension 3), by the rules above.
std::vector<std::vector<std::string>> hidden_sets(const LabInputs& inputs, const std::string& lab, int n,
                                                  std::uint64_t seed);

/// The seed of a lab's generator: FNV-1a (64 bit) of the lab's name xor seed.
std::uint64_t lab_seed(const std::string& lab, std::uint64_t seed);
/// A 64-bit output of the generator as a double in [0, 1): its top 53 bits
/// times 2^-53, so every value is exact and 1 is never reached.
double unit_interval(std::uint64_t bits);

}  // namespace gllab::grading
