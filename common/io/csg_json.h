// common/io/csg_json.h — constructive solid geometry trees (lecture notes ch. 1,
// "Solid Representation", "Constructive Solid Geometry"; common/space/csg.h) in
// JSON files, with the rules of the spline files (common/io/README.md "CSG trees"):
//   {"type": "csg", "root": NODE}
//   NODE: {"primitive": "sphere", "radius": R}
//         {"primitive": "cylinder" | "cone", "radius": R, "height": H}
//         {"primitive": "box", "size": [X, Y, Z]}
//         {"op": "union" | "intersection" | "difference", "children": [NODE, NODE, ...]}
//         {"transform": [STEP, ...], "child": NODE}
//   STEP: {"translate": [x, y, z]} | {"scale": [x, y, z]} |
//         {"rotate": {"axis": [x, y, z], "degrees": d}} | {"matrix": [12 numbers, row-major 3 x 4]}
//   any node may have "name": "text".
// An operator's children are folded from the left (a − b − c = (a − b) − c);
// a transform's steps act in the order given (the first acts first on the child).
// A bad file throws FileError with one line naming the file and the JSON path:
//   "tree.json: root.children[1].radius: -1 (must be > 0: the sphere's radius)"
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "io/spline_json.h"
#include "space/csg.h"

namespace gllab::io {

/// Limits of a file: deeper or larger trees are refused with the JSON path
/// (the reader and the tree's algorithms recurse once per level).
constexpr int kCsgMaxDepth = 64;      // levels of nested nodes, the root is level 1
constexpr int kCsgMaxNodes = 4096;    // nodes written in the file

struct CsgFile {
  space::CsgTree tree;
  /// The "name" of every node of `tree` (node_names[i] for tree.nodes()[i]; "" when none).
  /// CsgTree keeps only its primitives' names, so an operator's or a transform's name
  /// lives here. An operator with n children is n − 1 binary nodes: the name goes to
  /// the last (the one the others are folded into).
  std::vector<std::string> node_names;
};

CsgFile read_csg(const std::filesystem::path& file);
CsgFile parse_csg(const std::string& text, const std::string& source = "<string>");
/// Checks an already parsed value (same checks and messages as parse_csg).
CsgFile csg_from_json(const Json& value, const std::string& source = "<json>");

/// {"type": "csg", "root": NODE}: primitives with their sizes and names, operators with
/// their children (a chain of one operator folded from the left becomes one node with
/// several children again), each transform as one {"matrix": [...]} step. Throws
/// std::invalid_argument for an empty tree or one the reader would refuse (deeper than
/// kCsgMaxDepth or larger than kCsgMaxNodes as written).
Json to_json(const space::CsgTree& tree);
/// The same, with the names of operators and transforms from node_names.
Json to_json(const CsgFile& file);
/// to_text(to_json(...)) written atomically (temporary file + rename); throws FileError.
void write_csg(const std::filesystem::path& file, const space::CsgTree& tree);
void write_csg(const std::filesystem::path& file, const CsgFile& csg);

}  // namespace gllab::io
