// common/deform/teapot.cpp — Newell's teapot: the table (teapot.h names its
// source), the oriented patches and the welded triangle mesh.
#include "deform/teapot.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace gllab::deform {

namespace {

// Newell's table (Newell 1975, as published in Crow 1987; the 306-point,
// 32-patch version with a bottom, z up): the data only, numbers and order
// unchanged. Transcribed from the "teaset" files as Steve Baker's teaset.tgz
// passes them on (e.g. markkilgard/opengl4_examples, tessellation/teapot.cpp)
// and checked entry by entry against a second copy (K-3D, k3dsdk/teapot.cpp,
// whose indices count from 1). Each line starts with the index of its first
// point.
const std::vector<Vec3> kPoints = {
    /*   0 */ {1.4, 0, 2.4}, {1.4, -0.784, 2.4}, {0.784, -1.4, 2.4},
    /*   3 */ {0, -1.4, 2.4}, {1.3375, 0, 2.53125}, {1.3375, -0.749, 2.53125},
    /*   6 */ {0.749, -1.3375, 2.53125}, {0, -1.3375, 2.53125}, {1.4375, 0, 2.53125},
    /*   9 */ {1.4375, -0.805, 2.53125}, {0.805, -1.4375, 2.53125}, {0, -1.4375, 2.53125},
    /*  12 */ {1.5, 0, 2.4}, {1.5, -0.84, 2.4}, {0.84, -1.5, 2.4},
    /*  15 */ {0, -1.5, 2.4}, {-0.784, -1.4, 2.4}, {-1.4, -0.784, 2.4},
    /*  18 */ {-1.4, 0, 2.4}, {-0.749, -1.3375, 2.53125}, {-1.3375, -0.749, 2.53125},
    /*  21 */ {-1.3375, 0, 2.53125}, {-0.805, -1.4375, 2.53125}, {-1.4375, -0.805, 2.53125},
    /*  24 */ {-1.4375, 0, 2.53125}, {-0.84, -1.5, 2.4}, {-1.5, -0.84, 2.4},
    /*  27 */ {-1.5, 0, 2.4}, {-1.4, 0.784, 2.4}, {-0.784, 1.4, 2.4},
    /*  30 */ {0, 1.4, 2.4}, {-1.3375, 0.749, 2.53125}, {-0.749, 1.3375, 2.53125},
    /*  33 */ {0, 1.3375, 2.53125}, {-1.4375, 0.805, 2.53125}, {-0.805, 1.4375, 2.53125},
    /*  36 */ {0, 1.4375, 2.53125}, {-1.5, 0.84, 2.4}, {-0.84, 1.5, 2.4},
    /*  39 */ {0, 1.5, 2.4}, {0.784, 1.4, 2.4}, {1.4, 0.784, 2.4},
    /*  42 */ {0.749, 1.3375, 2.53125}, {1.3375, 0.749, 2.53125}, {0.805, 1.4375, 2.53125},
    /*  45 */ {1.4375, 0.805, 2.53125}, {0.84, 1.5, 2.4}, {1.5, 0.84, 2.4},
    /*  48 */ {1.75, 0, 1.875}, {1.75, -0.98, 1.875}, {0.98, -1.75, 1.875},
    /*  51 */ {0, -1.75, 1.875}, {2, 0, 1.35}, {2, -1.12, 1.35},
    /*  54 */ {1.12, -2, 1.35}, {0, -2, 1.35}, {2, 0, 0.9},
    /*  57 */ {2, -1.12, 0.9}, {1.12, -2, 0.9}, {0, -2, 0.9},
    /*  60 */ {-0.98, -1.75, 1.875}, {-1.75, -0.98, 1.875}, {-1.75, 0, 1.875},
    /*  63 */ {-1.12, -2, 1.35}, {-2, -1.12, 1.35}, {-2, 0, 1.35},
    /*  66 */ {-1.12, -2, 0.9}, {-2, -1.12, 0.9}, {-2, 0, 0.9},
    /*  69 */ {-1.75, 0.98, 1.875}, {-0.98, 1.75, 1.875}, {0, 1.75, 1.875},
    /*  72 */ {-2, 1.12, 1.35}, {-1.12, 2, 1.35}, {0, 2, 1.35},
    /*  75 */ {-2, 1.12, 0.9}, {-1.12, 2, 0.9}, {0, 2, 0.9},
    /*  78 */ {0.98, 1.75, 1.875}, {1.75, 0.98, 1.875}, {1.12, 2, 1.35},
    /*  81 */ {2, 1.12, 1.35}, {1.12, 2, 0.9}, {2, 1.12, 0.9},
    /*  84 */ {2, 0, 0.45}, {2, -1.12, 0.45}, {1.12, -2, 0.45},
    /*  87 */ {0, -2, 0.45}, {1.5, 0, 0.225}, {1.5, -0.84, 0.225},
    /*  90 */ {0.84, -1.5, 0.225}, {0, -1.5, 0.225}, {1.5, 0, 0.15},
    /*  93 */ {1.5, -0.84, 0.15}, {0.84, -1.5, 0.15}, {0, -1.5, 0.15},
    /*  96 */ {-1.12, -2, 0.45}, {-2, -1.12, 0.45}, {-2, 0, 0.45},
    /*  99 */ {-0.84, -1.5, 0.225}, {-1.5, -0.84, 0.225}, {-1.5, 0, 0.225},
    /* 102 */ {-0.84, -1.5, 0.15}, {-1.5, -0.84, 0.15}, {-1.5, 0, 0.15},
    /* 105 */ {-2, 1.12, 0.45}, {-1.12, 2, 0.45}, {0, 2, 0.45},
    /* 108 */ {-1.5, 0.84, 0.225}, {-0.84, 1.5, 0.225}, {0, 1.5, 0.225},
    /* 111 */ {-1.5, 0.84, 0.15}, {-0.84, 1.5, 0.15}, {0, 1.5, 0.15},
    /* 114 */ {1.12, 2, 0.45}, {2, 1.12, 0.45}, {0.84, 1.5, 0.225},
    /* 117 */ {1.5, 0.84, 0.225}, {0.84, 1.5, 0.15}, {1.5, 0.84, 0.15},
    /* 120 */ {-1.6, 0, 2.025}, {-1.6, -0.3, 2.025}, {-1.5, -0.3, 2.25},
    /* 123 */ {-1.5, 0, 2.25}, {-2.3, 0, 2.025}, {-2.3, -0.3, 2.025},
    /* 126 */ {-2.5, -0.3, 2.25}, {-2.5, 0, 2.25}, {-2.7, 0, 2.025},
    /* 129 */ {-2.7, -0.3, 2.025}, {-3, -0.3, 2.25}, {-3, 0, 2.25},
    /* 132 */ {-2.7, 0, 1.8}, {-2.7, -0.3, 1.8}, {-3, -0.3, 1.8},
    /* 135 */ {-3, 0, 1.8}, {-1.5, 0.3, 2.25}, {-1.6, 0.3, 2.025},
    /* 138 */ {-2.5, 0.3, 2.25}, {-2.3, 0.3, 2.025}, {-3, 0.3, 2.25},
    /* 141 */ {-2.7, 0.3, 2.025}, {-3, 0.3, 1.8}, {-2.7, 0.3, 1.8},
    /* 144 */ {-2.7, 0, 1.575}, {-2.7, -0.3, 1.575}, {-3, -0.3, 1.35},
    /* 147 */ {-3, 0, 1.35}, {-2.5, 0, 1.125}, {-2.5, -0.3, 1.125},
    /* 150 */ {-2.65, -0.3, 0.9375}, {-2.65, 0, 0.9375}, {-2, -0.3, 0.9},
    /* 153 */ {-1.9, -0.3, 0.6}, {-1.9, 0, 0.6}, {-3, 0.3, 1.35},
    /* 156 */ {-2.7, 0.3, 1.575}, {-2.65, 0.3, 0.9375}, {-2.5, 0.3, 1.125},
    /* 159 */ {-1.9, 0.3, 0.6}, {-2, 0.3, 0.9}, {1.7, 0, 1.425},
    /* 162 */ {1.7, -0.66, 1.425}, {1.7, -0.66, 0.6}, {1.7, 0, 0.6},
    /* 165 */ {2.6, 0, 1.425}, {2.6, -0.66, 1.425}, {3.1, -0.66, 0.825},
    /* 168 */ {3.1, 0, 0.825}, {2.3, 0, 2.1}, {2.3, -0.25, 2.1},
    /* 171 */ {2.4, -0.25, 2.025}, {2.4, 0, 2.025}, {2.7, 0, 2.4},
    /* 174 */ {2.7, -0.25, 2.4}, {3.3, -0.25, 2.4}, {3.3, 0, 2.4},
    /* 177 */ {1.7, 0.66, 0.6}, {1.7, 0.66, 1.425}, {3.1, 0.66, 0.825},
    /* 180 */ {2.6, 0.66, 1.425}, {2.4, 0.25, 2.025}, {2.3, 0.25, 2.1},
    /* 183 */ {3.3, 0.25, 2.4}, {2.7, 0.25, 2.4}, {2.8, 0, 2.475},
    /* 186 */ {2.8, -0.25, 2.475}, {3.525, -0.25, 2.49375}, {3.525, 0, 2.49375},
    /* 189 */ {2.9, 0, 2.475}, {2.9, -0.15, 2.475}, {3.45, -0.15, 2.5125},
    /* 192 */ {3.45, 0, 2.5125}, {2.8, 0, 2.4}, {2.8, -0.15, 2.4},
    /* 195 */ {3.2, -0.15, 2.4}, {3.2, 0, 2.4}, {3.525, 0.25, 2.49375},
    /* 198 */ {2.8, 0.25, 2.475}, {3.45, 0.15, 2.5125}, {2.9, 0.15, 2.475},
    /* 201 */ {3.2, 0.15, 2.4}, {2.8, 0.15, 2.4}, {0, 0, 3.15},
    /* 204 */ {0, -0.002, 3.15}, {0.002, 0, 3.15}, {0.8, 0, 3.15},
    /* 207 */ {0.8, -0.45, 3.15}, {0.45, -0.8, 3.15}, {0, -0.8, 3.15},
    /* 210 */ {0, 0, 2.85}, {0.2, 0, 2.7}, {0.2, -0.112, 2.7},
    /* 213 */ {0.112, -0.2, 2.7}, {0, -0.2, 2.7}, {-0.002, 0, 3.15},
    /* 216 */ {-0.45, -0.8, 3.15}, {-0.8, -0.45, 3.15}, {-0.8, 0, 3.15},
    /* 219 */ {-0.112, -0.2, 2.7}, {-0.2, -0.112, 2.7}, {-0.2, 0, 2.7},
    /* 222 */ {0, 0.002, 3.15}, {-0.8, 0.45, 3.15}, {-0.45, 0.8, 3.15},
    /* 225 */ {0, 0.8, 3.15}, {-0.2, 0.112, 2.7}, {-0.112, 0.2, 2.7},
    /* 228 */ {0, 0.2, 2.7}, {0.45, 0.8, 3.15}, {0.8, 0.45, 3.15},
    /* 231 */ {0.112, 0.2, 2.7}, {0.2, 0.112, 2.7}, {0.4, 0, 2.55},
    /* 234 */ {0.4, -0.224, 2.55}, {0.224, -0.4, 2.55}, {0, -0.4, 2.55},
    /* 237 */ {1.3, 0, 2.55}, {1.3, -0.728, 2.55}, {0.728, -1.3, 2.55},
    /* 240 */ {0, -1.3, 2.55}, {1.3, 0, 2.4}, {1.3, -0.728, 2.4},
    /* 243 */ {0.728, -1.3, 2.4}, {0, -1.3, 2.4}, {-0.224, -0.4, 2.55},
    /* 246 */ {-0.4, -0.224, 2.55}, {-0.4, 0, 2.55}, {-0.728, -1.3, 2.55},
    /* 249 */ {-1.3, -0.728, 2.55}, {-1.3, 0, 2.55}, {-0.728, -1.3, 2.4},
    /* 252 */ {-1.3, -0.728, 2.4}, {-1.3, 0, 2.4}, {-0.4, 0.224, 2.55},
    /* 255 */ {-0.224, 0.4, 2.55}, {0, 0.4, 2.55}, {-1.3, 0.728, 2.55},
    /* 258 */ {-0.728, 1.3, 2.55}, {0, 1.3, 2.55}, {-1.3, 0.728, 2.4},
    /* 261 */ {-0.728, 1.3, 2.4}, {0, 1.3, 2.4}, {0.224, 0.4, 2.55},
    /* 264 */ {0.4, 0.224, 2.55}, {0.728, 1.3, 2.55}, {1.3, 0.728, 2.55},
    /* 267 */ {0.728, 1.3, 2.4}, {1.3, 0.728, 2.4}, {0, 0, 0},
    /* 270 */ {1.5, 0, 0.15}, {1.5, 0.84, 0.15}, {0.84, 1.5, 0.15},
    /* 273 */ {0, 1.5, 0.15}, {1.5, 0, 0.075}, {1.5, 0.84, 0.075},
    /* 276 */ {0.84, 1.5, 0.075}, {0, 1.5, 0.075}, {1.425, 0, 0},
    /* 279 */ {1.425, 0.798, 0}, {0.798, 1.425, 0}, {0, 1.425, 0},
    /* 282 */ {-0.84, 1.5, 0.15}, {-1.5, 0.84, 0.15}, {-1.5, 0, 0.15},
    /* 285 */ {-0.84, 1.5, 0.075}, {-1.5, 0.84, 0.075}, {-1.5, 0, 0.075},
    /* 288 */ {-0.798, 1.425, 0}, {-1.425, 0.798, 0}, {-1.425, 0, 0},
    /* 291 */ {-1.5, -0.84, 0.15}, {-0.84, -1.5, 0.15}, {0, -1.5, 0.15},
    /* 294 */ {-1.5, -0.84, 0.075}, {-0.84, -1.5, 0.075}, {0, -1.5, 0.075},
    /* 297 */ {-1.425, -0.798, 0}, {-0.798, -1.425, 0}, {0, -1.425, 0},
    /* 300 */ {0.84, -1.5, 0.15}, {1.5, -0.84, 0.15}, {0.84, -1.5, 0.075},
    /* 303 */ {1.5, -0.84, 0.075}, {0.798, -1.425, 0}, {1.425, -0.798, 0},
};

// The patches, 16 indices each (4 rows of 4), 0-based, as published.
const std::vector<std::array<int, 16>> kPatches = {
    // rim
    {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},
    {3, 16, 17, 18, 7, 19, 20, 21, 11, 22, 23, 24, 15, 25, 26, 27},
    {18, 28, 29, 30, 21, 31, 32, 33, 24, 34, 35, 36, 27, 37, 38, 39},
    {30, 40, 41, 0, 33, 42, 43, 4, 36, 44, 45, 8, 39, 46, 47, 12},
    // body: the upper ring of 4, then the lower
    {12, 13, 14, 15, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59},
    {15, 25, 26, 27, 51, 60, 61, 62, 55, 63, 64, 65, 59, 66, 67, 68},
    {27, 37, 38, 39, 62, 69, 70, 71, 65, 72, 73, 74, 68, 75, 76, 77},
    {39, 46, 47, 12, 71, 78, 79, 48, 74, 80, 81, 52, 77, 82, 83, 56},
    {56, 57, 58, 59, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95},
    {59, 66, 67, 68, 87, 96, 97, 98, 91, 99, 100, 101, 95, 102, 103, 104},
    {68, 75, 76, 77, 98, 105, 106, 107, 101, 108, 109, 110, 104, 111, 112, 113},
    {77, 82, 83, 56, 107, 114, 115, 84, 110, 116, 117, 88, 113, 118, 119, 92},
    // handle: the arc from the body's top (y <= 0, y >= 0), then down to the body
    {120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135},
    {123, 136, 137, 120, 127, 138, 139, 124, 131, 140, 141, 128, 135, 142, 143, 132},
    {132, 133, 134, 135, 144, 145, 146, 147, 148, 149, 150, 151, 68, 152, 153, 154},
    {135, 142, 143, 132, 147, 155, 156, 144, 151, 157, 158, 148, 154, 159, 160, 68},
    // spout: from the body (y <= 0, y >= 0), then the tip
    {161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176},
    {164, 177, 178, 161, 168, 179, 180, 165, 172, 181, 182, 169, 176, 183, 184, 173},
    {173, 174, 175, 176, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196},
    {176, 183, 184, 173, 188, 197, 198, 185, 192, 199, 200, 189, 196, 201, 202, 193},
    // lid: the knob (its first row is the pole), then the lid
    {203, 203, 203, 203, 206, 207, 208, 209, 210, 210, 210, 210, 211, 212, 213, 214},
    {203, 203, 203, 203, 209, 216, 217, 218, 210, 210, 210, 210, 214, 219, 220, 221},
    {203, 203, 203, 203, 218, 223, 224, 225, 210, 210, 210, 210, 221, 226, 227, 228},
    {203, 203, 203, 203, 225, 229, 230, 206, 210, 210, 210, 210, 228, 231, 232, 211},
    {211, 212, 213, 214, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244},
    {214, 219, 220, 221, 236, 245, 246, 247, 240, 248, 249, 250, 244, 251, 252, 253},
    {221, 226, 227, 228, 247, 254, 255, 256, 250, 257, 258, 259, 253, 260, 261, 262},
    {228, 231, 232, 211, 256, 263, 264, 233, 259, 265, 266, 237, 262, 267, 268, 241},
    // bottom (its first row is the pole)
    {269, 269, 269, 269, 278, 279, 280, 281, 274, 275, 276, 277, 270, 271, 272, 273},
    {269, 269, 269, 269, 281, 288, 289, 290, 277, 285, 286, 287, 273, 282, 283, 284},
    {269, 269, 269, 269, 290, 297, 298, 299, 287, 294, 295, 296, 284, 291, 292, 293},
    {269, 269, 269, 269, 299, 304, 305, 278, 296, 302, 303, 274, 293, 300, 301, 270},
};

const std::array<TeapotPart, 6> kParts = {{{"rim", 0, 4},
                                           {"body", 4, 8},
                                           {"handle", 12, 4},
                                           {"spout", 16, 4},
                                           {"lid", 20, 8},
                                           {"bottom", 28, 4}}};

std::vector<spline::BezierSurface> make_patches() {
  std::vector<spline::BezierSurface> out;
  out.reserve(kPatches.size());
  for (const std::array<int, 16>& index : kPatches) {
    spline::BezierSurface s;  // n = m = 3 on [0, 1]^2
    s.P.resize(16);
    // Each row of the table reversed: as published, Su x Sv points inward on
    // every patch (teapot.h); reversing v turns it over.
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) s.point(i, j) = kPoints[index[i * 4 + 3 - j]];
    out.push_back(std::move(s));
  }
  return out;
}

// Welding (teapot.h): samples within kTeapotWeldTolerance in every coordinate
// are one point. They are found through a grid of cells kCell wide: two such
// samples lie in the same cell or in neighbouring ones.
constexpr double kCell = 1e-6;
static_assert(kCell > kTeapotWeldTolerance, "a cell must be wider than the tolerance");

struct Cell {
  std::int64_t x, y, z;
  bool operator==(const Cell& o) const { return x == o.x && y == o.y && z == o.z; }
};

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    const std::uint64_t h = static_cast<std::uint64_t>(c.x) * 0x9E3779B97F4A7C15ull ^
                            static_cast<std::uint64_t>(c.y) * 0xC2B2AE3D27D4EB4Full ^
                            static_cast<std::uint64_t>(c.z) * 0x165667B19E3779F9ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

Cell cell_of(Vec3 p) {
  return {static_cast<std::int64_t>(std::floor(p.x / kCell)),
          static_cast<std::int64_t>(std::floor(p.y / kCell)),
          static_cast<std::int64_t>(std::floor(p.z / kCell))};
}

bool same_point(Vec3 a, Vec3 b) {
  return std::fabs(a.x - b.x) <= kTeapotWeldTolerance &&
         std::fabs(a.y - b.y) <= kTeapotWeldTolerance &&
         std::fabs(a.z - b.z) <= kTeapotWeldTolerance;
}

// The mesh's vertices as samples arrive: each vertex keeps its first sample's
// position and normal (what later samples are compared with) and the sum of
// its samples' normals.
class Welder {
 public:
  explicit Welder(std::size_t samples)
      : smooth_cos_(std::cos(kTeapotCreaseDegrees * 3.14159265358979323846 / 180)) {
    cells_.reserve(samples);
    for (std::vector<Vec3>* v : {&position, &first_normal, &normal_sum}) v->reserve(samples);
    next_in_cell_.reserve(samples);
  }

  // The vertex of the sample p with unit normal n: one within the tolerance
  // whose first normal is within the crease angle of n, else a new one. The
  // cells next to p's are looked at only along an axis where p lies within
  // the tolerance of its cell's side.
  std::uint32_t add(Vec3 p, Vec3 n) {
    const Cell c = cell_of(p);
    const auto reach = [](double x, std::int64_t i, int range[2]) {
      range[0] = x - static_cast<double>(i) * kCell <= kTeapotWeldTolerance ? -1 : 0;
      range[1] = static_cast<double>(i + 1) * kCell - x <= kTeapotWeldTolerance ? 1 : 0;
    };
    int rx[2], ry[2], rz[2];
    reach(p.x, c.x, rx);
    reach(p.y, c.y, ry);
    reach(p.z, c.z, rz);
    for (int dx = rx[0]; dx <= rx[1]; ++dx)
      for (int dy = ry[0]; dy <= ry[1]; ++dy)
        for (int dz = rz[0]; dz <= rz[1]; ++dz) {
          const auto it = cells_.find({c.x + dx, c.y + dy, c.z + dz});
          if (it == cells_.end()) continue;
          for (std::uint32_t w = it->second; w != kNone; w = next_in_cell_[w])
            if (same_point(position[w], p) && dot(first_normal[w], n) >= smooth_cos_) {
              normal_sum[w] += n;
              return w;
            }
        }
    const auto w = static_cast<std::uint32_t>(position.size());
    position.push_back(p);
    first_normal.push_back(n);
    normal_sum.push_back(n);
    const auto [it, added] = cells_.try_emplace(c, w);
    next_in_cell_.push_back(added ? kNone : it->second);
    it->second = w;
    return w;
  }

  std::vector<Vec3> position, first_normal, normal_sum;

 private:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  double smooth_cos_;
  // The last vertex made in each cell; next_in_cell_[w] the one made there before w.
  std::unordered_map<Cell, std::uint32_t, CellHash> cells_;
  std::vector<std::uint32_t> next_in_cell_;
};

}  // namespace

const std::vector<Vec3>& teapot_control_points() { return kPoints; }

const std::vector<std::array<int, 16>>& teapot_patch_indices() { return kPatches; }

const std::array<TeapotPart, 6>& teapot_parts() { return kParts; }

const std::vector<spline::BezierSurface>& teapot_patches() {
  static const std::vector<spline::BezierSurface> patches = make_patches();
  return patches;
}

IndexedMesh teapot_mesh(int per_patch) {
  if (per_patch < 1 || per_patch > kMaxTeapotPerPatch)
    throw std::invalid_argument("teapot_mesh: per_patch = " + std::to_string(per_patch) +
                                " (must be 1.." + std::to_string(kMaxTeapotPerPatch) + ")");
  const int k = per_patch;
  const std::size_t side = static_cast<std::size_t>(k) + 1;
  Welder weld(kTeapotPatchCount * side * side);
  std::vector<std::uint32_t> vertex(side * side);  // of the grid point (a, b): vertex[a * side + b]
  IndexedMesh mesh;
  std::vector<double> params(side);  // u = a / k and v = b / k
  for (std::size_t a = 0; a < side; ++a) params[a] = static_cast<double>(a) / k;
  std::vector<Vec3> points, normals;
  // A triangle; next to a pole one of a cell's two has two equal corners: left out.
  const auto triangle = [&mesh](std::uint32_t p, std::uint32_t q, std::uint32_t r) {
    if (p == q || q == r || r == p) return;
    mesh.indices.insert(mesh.indices.end(), {p, q, r});
  };
  for (const spline::BezierSurface& patch : teapot_patches()) {
    // The points and unit normals of the whole grid at once: what
    // surface_point and surface_normal give (fast/surface_batch.h).
    spline::surface_grid(spline::to_bspline(patch), params, params, points, &normals);
    for (std::size_t g = 0; g < side * side; ++g) vertex[g] = weld.add(points[g], normals[g]);
    // Two triangles per cell, counter-clockwise in (u, v) and so, Su x Sv
    // pointing outward, seen from outside.
    for (std::size_t a = 0; a < side - 1; ++a)
      for (std::size_t b = 0; b < side - 1; ++b) {
        const std::uint32_t p00 = vertex[a * side + b], p10 = vertex[(a + 1) * side + b];
        const std::uint32_t p11 = vertex[(a + 1) * side + b + 1], p01 = vertex[a * side + b + 1];
        triangle(p00, p10, p11);
        triangle(p00, p11, p01);
      }
  }
  const auto append = [](std::vector<float>& out, Vec3 x) {
    out.insert(out.end(),
               {static_cast<float>(x.x), static_cast<float>(x.y), static_cast<float>(x.z)});
  };
  mesh.positions.reserve(3 * weld.position.size());
  mesh.normals.reserve(3 * weld.position.size());
  for (std::size_t w = 0; w < weld.position.size(); ++w) {
    const Vec3 p = weld.position[w], n = spline::normalized(weld.normal_sum[w]);
    append(mesh.positions, p);
    append(mesh.normals, n);
  }
  return mesh;
}

}  // namespace gllab::deform
