// tests/io/obj_test.cpp — Wavefront OBJ output (common/io/obj.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>

#include "io/obj.h"
#include "io/spline_json.h"
#include "io_test_support.h"

namespace gllab::io {
namespace {

using spline::Mesh;
using spline::Vec3;
using testing::ScratchDir;

/// Two triangles making the unit square in z = 0, normals +z (counter-clockwise
/// seen from +z, as tessellate.h promises).
Mesh unit_square() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  m.uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

TEST(ObjText, MeshHasVertexNormalAndOneBasedFaceLines) {
  // The OBJ spec (Wavefront, "Object Files (.obj)"): indices start at 1, and
  // "f v//vn" names a vertex and its normal without a texture coordinate.
  EXPECT_EQ(obj_text(unit_square(), "unit square"),
            "# unit square\n"
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
            "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
            "f 1//1 2//2 3//3\nf 1//1 3//3 4//4\n");
}

TEST(ObjText, PolylineIsOneLineElement) {
  EXPECT_EQ(obj_text(std::vector<Vec3>{{0, 0, 0}, {1, 2, 0}, {3, 3, 0.5}}),
            "v 0 0 0\nv 1 2 0\nv 3 3 0.5\nl 1 2 3\n");
}

TEST(ObjText, MultiLineCommentStaysComment) {
  const std::string text = obj_text(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}}, "first\nsecond");
  EXPECT_EQ(text.rfind("# first\n# second\nv ", 0), 0u) << text;
}

TEST(ObjText, NumbersReadBackBitIdentical) {
  Mesh m = unit_square();
  m.positions[2] = {0.1, 1.0 / 3, -std::numeric_limits<double>::denorm_min()};
  std::istringstream in(obj_text(m));
  for (std::string tag; in >> tag;) {
    if (tag != "v") {
      std::getline(in, tag);
      continue;
    }
    double x, y, z;
    std::string sx, sy, sz;
    in >> sx >> sy >> sz;
    x = std::strtod(sx.c_str(), nullptr);
    y = std::strtod(sy.c_str(), nullptr);
    z = std::strtod(sz.c_str(), nullptr);
    if (x == 0.1) {
      EXPECT_EQ(y, 1.0 / 3);
      EXPECT_EQ(z, -std::numeric_limits<double>::denorm_min());
      return;
    }
  }
  FAIL() << "vertex 0.1 not found";
}

TEST(ObjText, BadMeshesAreRefused) {
  Mesh m = unit_square();
  m.normals.pop_back();
  EXPECT_THROW(obj_text(m), std::invalid_argument);  // one normal per vertex
  m = unit_square();
  m.triangles[1][2] = 4;
  EXPECT_THROW(obj_text(m), std::invalid_argument);  // index out of range
  m = unit_square();
  m.positions[0].x = std::nan("");
  EXPECT_THROW(obj_text(m), std::invalid_argument);  // OBJ readers choke on nan
}

TEST(WriteObj, WritesAtomicallyAndNamesAnUnwritableFile) {
  ScratchDir dir("obj");
  write_obj(dir / "square.obj", unit_square());
  EXPECT_EQ(testing::read_file(dir / "square.obj"), obj_text(unit_square()));
  int entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 1);  // no temporary file left behind
  try {
    write_obj("/nonexistent-dir/square.obj", unit_square());
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/square.obj"), std::string::npos);
  }
}

// ---- IndexedMesh (an iso-surface from field::marching_cubes) --------------------

/// The unit square as an IndexedMesh: floats, each vertex once.
IndexedMesh indexed_square() {
  IndexedMesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0.1f, 1, 0};
  m.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

TEST(ObjTextIndexed, VertexNormalAndFaceLinesWithShortestFloats) {
  // 0.1f prints as 0.1 (the shortest text that reads back to the same float).
  EXPECT_EQ(obj_text(indexed_square(), "square"),
            "# square\n"
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.1 1 0\n"
            "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
            "f 1//1 2//2 3//3\nf 1//1 3//3 4//4\n");
  IndexedMesh bare = indexed_square();
  bare.normals.clear();
  EXPECT_EQ(obj_text(bare), "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.1 1 0\nf 1 2 3\nf 1 3 4\n");
}

TEST(ObjTextIndexed, BadMeshesAreRefused) {
  IndexedMesh m = indexed_square();
  m.normals.pop_back();
  EXPECT_THROW(obj_text(m), std::invalid_argument);  // one normal per vertex
  m = indexed_square();
  m.indices[5] = 4;
  EXPECT_THROW(obj_text(m), std::invalid_argument);  // index out of range
  m = indexed_square();
  m.indices.pop_back();
  EXPECT_THROW(obj_text(m), std::invalid_argument);  // not whole triangles
  m = indexed_square();
  m.positions[4] = std::nanf("");
  EXPECT_THROW(obj_text(m), std::invalid_argument);
}

TEST(WriteObjIndexed, WritesAtomically) {
  ScratchDir dir("obj");
  write_obj(dir / "square.obj", indexed_square(), "c");
  EXPECT_EQ(testing::read_file(dir / "square.obj"), obj_text(indexed_square(), "c"));
  int entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 1);
  EXPECT_THROW(write_obj("/nonexistent-dir/square.obj", indexed_square()), FileError);
}

}  // namespace
}  // namespace gllab::io
