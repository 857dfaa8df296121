// common/io/obj.h — meshes and polylines as Wavefront OBJ, the plain-text
// format Blender and MeshLab open directly.
//
//   # comment
//   v x y z          one line per vertex
//   vn x y z         one unit normal per vertex (same order)
//   f a//a b//b c//c one line per triangle: 1-based vertex//normal indices,
//                    counter-clockwise seen from where the normals point
//   l 1 2 ... n      a polyline (vertices only)
//
// Numbers are printed in their shortest form that reads back bit-identical.
// Files are replaced atomically (temporary file + rename), like the JSON files.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "mesh/indexed_mesh.h"
#include "spline/tessellate.h"
#include "spline/vec.h"

namespace gllab::io {

/// The OBJ text of a triangle mesh (spline::Mesh from tessellate.h): v, vn and
/// f a//a lines, after one "# comment" line per line of comment (if any).
/// Throws std::invalid_argument when the normals do not match the positions,
/// a triangle index is out of range, or a number is not finite.
std::string obj_text(const spline::Mesh& mesh, const std::string& comment = "");

/// The OBJ text of an open polyline: v lines and one l line.
std::string obj_text(const std::vector<spline::Vec3>& polyline, const std::string& comment = "");

/// The OBJ text of an IndexedMesh (mesh/indexed_mesh.h; an iso-surface from
/// field::marching_cubes): v lines, vn lines (one normal per vertex) and f
/// a//a b//b c//c faces; a mesh without normals gets f a b c. Colours are
/// not written. Throws std::invalid_argument when positions or normals are
/// not 3 floats per vertex, an index is out of range or the number of
/// indices is no multiple of 3, or a number is not finite.
std::string obj_text(const IndexedMesh& mesh, const std::string& comment = "");

/// obj_text written to file atomically. Throws FileError (spline_json.h)
/// naming the file when it cannot be written.
void write_obj(const std::filesystem::path& file, const spline::Mesh& mesh, const std::string& comment = "");
void write_obj(const std::filesystem::path& file, const std::vector<spline::Vec3>& polyline,
               const std::string& comment = "");
void write_obj(const std::filesystem::path& file, const IndexedMesh& mesh, const std::string& comment = "");

}  // namespace gllab::io
