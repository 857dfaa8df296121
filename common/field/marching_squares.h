// common/field/marching_squares.h — iso-curves f(x, y) = c of a bilinear grid
// (lecture notes ch. 1, §1.7 Surface representations, "Iso-curves").
//
// Each cell is classified by its four corners (inside: f > c) into one of 16
// cases; the curve crosses an edge where the corners differ, at the point of
// linear interpolation. Cases 5 and 10 (diagonal corners inside) are saddles:
// two pairs of crossings, two ways to join them. The naive table always
// separates the inside corners; the asymptotic decider (Nielson and Hamann
// 1991) joins them as the bilinear interpolant does: the value at its saddle
// point, (f00 f11 - f10 f01) / (f00 + f11 - f10 - f01), compared with c, says
// whether the inside corners are connected through the cell.
#pragma once

#include <array>
#include <vector>

#include "field/grid.h"

namespace gllab::field {

enum class Saddle { kNaive, kDecider };

struct IsoCurves {
  std::vector<std::array<double, 2>> points;     // each grid-edge crossing once
  std::vector<std::array<int, 2>> segments;      // into points; inside on the left
  struct Cell { int i, j, mask; bool saddle; };  // mask bit 0 (i,j) 1 (i+1,j) 2 (i+1,j+1) 3 (i,j+1)
  std::vector<Cell> cells;                       // the cells the curve crosses
  /// The segments chained into polylines (indices into points); a closed one
  /// repeats its first index at the end.
  std::vector<std::vector<int>> polylines() const;
};

IsoCurves marching_squares(const Grid2& g, double c, Saddle rule = Saddle::kDecider);

}  // namespace gllab::field
