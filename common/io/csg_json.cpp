// common/io/csg_json.cpp — reads and writes CSG trees (csg_json.h,
// common/io/README.md "CSG trees"). Every key is checked here, so that a mistake
// is reported at its JSON path ("root.children[0].transform[2].scale[1]: ...")
// before space::CsgTree sees it.
#include "io/csg_json.h"
#include "io/json_checks.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace gllab::io {

using space::Affine;
using space::CsgNode;
using space::CsgTree;
using space::Op;
using space::Shape;
using spline::Vec3;

namespace {

using detail::describe;
using detail::index_path;
using detail::member_path;

constexpr const char* kStepKinds =
    R"(a step {"translate": [x, y, z]}, {"scale": [x, y, z]}, {"rotate": {"axis": [x, y, z], "degrees": d}} or {"matrix": [12 numbers]})";

bool finite(const Affine& a) {
  for (double x : a.m)
    if (!std::isfinite(x)) return false;
  return true;
}

class Checker : public detail::JsonChecker {
 public:
  using JsonChecker::JsonChecker;

  CsgFile file(const Json& root) {
    require_object(root, "", R"(a JSON object {"type": "csg", "root": ...})");
    const Json& type = member(root, "", "type", "csg file");
    if (string(type, "type") != "csg") fail("type", describe(type) + R"( (this file holds a "csg" tree))");
    only_keys(root, "", {"type", "root"}, "csg file");
    const int top = node(member(root, "", "root", "csg file"), "root", 1);
    tree_.set_root(top);
    CsgFile out;
    out.node_names.resize(tree_.nodes().size());
    for (std::size_t i = 0; i < tree_.nodes().size(); ++i) out.node_names[i] = tree_.nodes()[i].name;
    for (const auto& [index, name] : names_) out.node_names[static_cast<std::size_t>(index)] = name;
    out.tree = std::move(tree_);
    return out;
  }

 private:
  Vec3 vec3(const Json& v, const std::string& path) const { return triple(v, path, "", "number"); }

  /// Runs a CsgTree builder; its own checks (std::invalid_argument) fail at path.
  template <class Build>
  int built(const std::string& path, Build build) const {
    try {
      return build();
    } catch (const std::invalid_argument& e) {
      fail(path, e.what());
    }
  }

  int node(const Json& v, const std::string& path, int depth) {
    // Guards before anything recurses: a hostile file cannot exhaust the stack.
    if (depth > kCsgMaxDepth)
      fail(path, "nested more than " + std::to_string(kCsgMaxDepth) +
                     " levels deep (a csg file allows at most " + std::to_string(kCsgMaxDepth) + ")");
    if (++count_ > kCsgMaxNodes)
      fail(path, "more than " + std::to_string(kCsgMaxNodes) + " nodes (a csg file allows at most " +
                     std::to_string(kCsgMaxNodes) + ")");
    require_object(v, path,
                   R"(a node {"primitive": ...}, {"op": ..., "children": [...]} or {"transform": [...], "child": ...})");
    std::vector<std::string> kinds;
    for (const char* k : {"primitive", "op", "transform"})
      if (v.contains(k)) kinds.push_back(k);
    if (kinds.empty()) {
      std::string keys;
      for (const auto& item : v.items()) keys += (keys.empty() ? "" : ", ") + item.key();
      fail(path, R"(a node needs "primitive", "op" or "transform" (it has )" +
                     (keys.empty() ? std::string("no keys") : "only " + keys) + ")");
    }
    if (kinds.size() > 1)
      fail(member_path(path, kinds[1]), "a node is one of primitive, op, transform (this one also has \"" +
                                            kinds[0] + "\")");
    std::string name;
    if (const Json* n = optional_member(v, "name")) name = string(*n, member_path(path, "name"));
    if (kinds[0] == "primitive") return primitive(v, path, name);
    if (kinds[0] == "op") return op(v, path, depth, name);
    return transform(v, path, depth, name);
  }

  int primitive(const Json& v, const std::string& path, const std::string& name) {
    const Json& kind = *optional_member(v, "primitive");
    const std::string shape = string(kind, member_path(path, "primitive"));
    const std::string radius_path = member_path(path, "radius"), height_path = member_path(path, "height");
    if (shape == "sphere") {
      only_keys(v, path, {"primitive", "radius", "name"}, "sphere");
      const double r = positive(member(v, path, "radius", "sphere"), radius_path, "the sphere's radius");
      return built(path, [&] { return tree_.sphere(r, name); });
    }
    if (shape == "cylinder" || shape == "cone") {
      only_keys(v, path, {"primitive", "radius", "height", "name"}, shape);
      const double r = positive(member(v, path, "radius", shape), radius_path, "the " + shape + "'s radius");
      const double h = positive(member(v, path, "height", shape), height_path, "the " + shape + "'s height");
      return built(path, [&] { return shape == "cone" ? tree_.cone(r, h, name) : tree_.cylinder(r, h, name); });
    }
    if (shape == "box") {
      only_keys(v, path, {"primitive", "size", "name"}, "box");
      const std::string size_path = member_path(path, "size");
      const Vec3 size = vec3(member(v, path, "size", "box"), size_path);
      const double s[3] = {size.x, size.y, size.z};
      const char* axis[3] = {"x", "y", "z"};
      for (std::size_t c = 0; c < 3; ++c)
        if (!(s[c] > 0))
          fail(index_path(size_path, c),
               shortest_text(s[c]) + " (must be > 0: the box's edge along " + axis[c] + ")");
      return built(path, [&] { return tree_.box(size, name); });
    }
    fail(member_path(path, "primitive"), describe(kind) + " (known primitives: sphere, cylinder, cone, box)");
  }

  int op(const Json& v, const std::string& path, int depth, const std::string& name) {
    const Json& kind = *optional_member(v, "op");
    const std::string op_path = member_path(path, "op");
    const std::string o = string(kind, op_path);
    if (o != "union" && o != "intersection" && o != "difference")
      fail(op_path, describe(kind) + " (known operators: union, intersection, difference)");
    only_keys(v, path, {"op", "children", "name"}, o);
    const std::string children_path = member_path(path, "children");
    const Json& children = member(v, path, "children", o);
    if (!children.is_array()) fail(children_path, "expected an array of nodes, got " + describe(children));
    if (children.size() < 2)
      fail(children_path, std::to_string(children.size()) + (children.size() == 1 ? " child" : " children") +
                              " (" + (o == "intersection" ? "an " : "a ") + o + " needs at least 2)");
    // Folded from the left: a − b − c = (a − b) − c.
    int result = node(children[0], index_path(children_path, 0), depth + 1);
    for (std::size_t i = 1; i < children.size(); ++i) {
      const int child = node(children[i], index_path(children_path, i), depth + 1);
      result = built(path, [&] {
        if (o == "union") return tree_.unite(result, child);
        if (o == "intersection") return tree_.intersect(result, child);
        return tree_.subtract(result, child);
      });
    }
    if (!name.empty()) names_[result] = name;
    return result;
  }

  Affine step(const Json& v, const std::string& path) const {
    require_object(v, path, kStepKinds);
    if (v.empty()) fail(path, "empty (a step is one of translate, scale, rotate, matrix)");
    only_keys(v, path, {"translate", "scale", "rotate", "matrix"}, "transform step");
    if (v.size() > 1)
      fail(path, "has " + std::to_string(v.size()) +
                     " keys (a step has exactly one: translate, scale, rotate or matrix)");
    const auto first = v.begin();  // the one key (an object's iterator knows it)
    const std::string key = first.key();
    const Json& value = first.value();
    const std::string value_path = member_path(path, key);
    if (key == "translate") return Affine::translate(vec3(value, value_path));
    if (key == "scale") {
      const Vec3 s = vec3(value, value_path);
      const double c[3] = {s.x, s.y, s.z};
      for (std::size_t i = 0; i < 3; ++i)
        if (c[i] == 0)
          fail(index_path(value_path, i),
               shortest_text(c[i]) + " (a scale must not be zero: it flattens the solid)");
      return Affine::scale(s);
    }
    if (key == "rotate") {
      require_object(value, value_path, R"(a rotation {"axis": [x, y, z], "degrees": d})");
      only_keys(value, value_path, {"axis", "degrees"}, "rotation");
      const std::string axis_path = member_path(value_path, "axis");
      const Vec3 axis = vec3(member(value, value_path, "axis", "rotation"), axis_path);
      const double degrees = number(member(value, value_path, "degrees", "rotation"),
                                    member_path(value_path, "degrees"));
      if (!(spline::norm(axis) > 0))
        fail(axis_path, "[" + shortest_text(axis.x) + ", " + shortest_text(axis.y) + ", " + shortest_text(axis.z) +
                            "] (a rotation needs a non-zero axis)");
      try {
        return Affine::rotate(axis, degrees);
      } catch (const std::invalid_argument& e) {
        fail(axis_path, e.what());
      }
    }
    // "matrix": [L00, L01, L02, t0, L10, L11, L12, t1, L20, L21, L22, t2].
    if (!value.is_array())
      fail(value_path, "expected 12 numbers (a row-major 3 x 4 matrix [L | t]), got " + describe(value));
    if (value.size() != 12)
      fail(value_path, "has " + std::to_string(value.size()) + " number" + (value.size() == 1 ? "" : "s") +
                           " (expected 12: a row-major 3 x 4 matrix [L | t])");
    Affine a;
    for (std::size_t i = 0; i < 12; ++i) a.m[i] = number(value[i], index_path(value_path, i));
    const double det = a.determinant();
    if (!(det != 0 && std::isfinite(det)))
      fail(value_path, "singular (det = " + shortest_text(det == 0 ? 0.0 : det) + ": it flattens the solid)");
    return a;
  }

  int transform(const Json& v, const std::string& path, int depth, const std::string& name) {
    only_keys(v, path, {"transform", "child", "name"}, "transform");
    const std::string steps_path = member_path(path, "transform");
    const Json& steps = *optional_member(v, "transform");
    if (!steps.is_array()) fail(steps_path, "expected an array of steps, got " + describe(steps));
    if (steps.empty()) fail(steps_path, "empty (a transform needs at least one step)");
    // The first step acts first on the child: A = S_n ... S_2 S_1.
    Affine a = step(steps[0], index_path(steps_path, 0));
    for (std::size_t i = 1; i < steps.size(); ++i) a = step(steps[i], index_path(steps_path, i)) * a;
    const double det = a.determinant();
    if (!finite(a) || !std::isfinite(det))
      fail(steps_path, "the steps multiply to a matrix that is not finite (numbers too large)");
    if (det == 0)
      fail(steps_path, "the steps multiply to a singular matrix (det = 0: it flattens the solid)");
    const int child = node(member(v, path, "child", "transform"), member_path(path, "child"), depth + 1);
    const int result = built(path, [&] { return tree_.transform(a, child); });
    if (!name.empty()) names_[result] = name;
    return result;
  }

  CsgTree tree_;
  std::map<int, std::string> names_;  // operators and transforms (primitives keep theirs)
  int count_ = 0;
};

// --- writing ---------------------------------------------------------------------------

class Writer {
 public:
  Writer(const CsgTree& tree, const std::vector<std::string>* names) : tree_(tree), names_(names) {}

  Json node(int i, int depth) {
    const std::vector<CsgNode>& nodes = tree_.nodes();
    if (i < 0 || static_cast<std::size_t>(i) >= nodes.size())
      throw std::invalid_argument("csg: node " + std::to_string(i) + " does not exist (the tree has " +
                                  std::to_string(nodes.size()) + " nodes)");
    if (depth > kCsgMaxDepth)
      throw std::invalid_argument("csg: the tree is more than " + std::to_string(kCsgMaxDepth) +
                                  " levels deep as written (a csg file allows at most " +
                                  std::to_string(kCsgMaxDepth) + ")");
    if (++count_ > kCsgMaxNodes)
      throw std::invalid_argument("csg: the tree has more than " + std::to_string(kCsgMaxNodes) +
                                  " nodes as written (a csg file allows at most " +
                                  std::to_string(kCsgMaxNodes) + ")");
    const CsgNode& n = nodes[static_cast<std::size_t>(i)];
    Json out = Json::object();
    const std::string label = name(i);
    switch (n.op) {
      case Op::kPrimitive:
        out["primitive"] = space::shape_name(n.shape);
        if (!label.empty()) out["name"] = label;
        if (n.shape == Shape::kBox) {
          out["size"] = Json::array({n.size.x, n.size.y, n.size.z});
        } else {
          out["radius"] = n.radius;
          if (n.shape != Shape::kSphere) out["height"] = n.height;
        }
        return out;
      case Op::kTransform: {
        Json step = Json::object();
        step["matrix"] = n.transform.m;  // row-major 3 x 4: [L | t]
        out["transform"] = Json::array({std::move(step)});
        if (!label.empty()) out["name"] = label;
        out["child"] = node(n.left, depth + 1);
        return out;
      }
      default: {
        // A left chain of one operator, a − b − c = (a − b) − c, is one node with the
        // children a, b, c (the reader folds it back the same way). A named inner
        // node keeps its own level so that its name survives.
        std::vector<int> rights{n.right};
        int c = n.left;
        while (c >= 0 && static_cast<std::size_t>(c) < nodes.size() &&
               nodes[static_cast<std::size_t>(c)].op == n.op && name(c).empty()) {
          rights.push_back(nodes[static_cast<std::size_t>(c)].right);
          c = nodes[static_cast<std::size_t>(c)].left;
        }
        out["op"] = space::op_name(n.op);
        if (!label.empty()) out["name"] = label;
        Json children = Json::array();
        children.push_back(node(c, depth + 1));
        for (auto r = rights.rbegin(); r != rights.rend(); ++r) children.push_back(node(*r, depth + 1));
        out["children"] = std::move(children);
        return out;
      }
    }
  }

 private:
  std::string name(int i) const {
    const std::size_t k = static_cast<std::size_t>(i);
    if (names_ && k < names_->size() && !(*names_)[k].empty()) return (*names_)[k];
    return tree_.nodes()[k].name;
  }

  const CsgTree& tree_;
  const std::vector<std::string>* names_;
  int count_ = 0;
};

Json tree_json(const CsgTree& tree, const std::vector<std::string>* names) {
  if (tree.root() < 0) throw std::invalid_argument("csg: the tree is empty (no root)");
  Json out = Json::object();
  out["type"] = "csg";
  out["root"] = Writer(tree, names).node(tree.root(), 1);
  return out;
}

}  // namespace

CsgFile csg_from_json(const Json& value, const std::string& source) { return Checker(source).file(value); }

CsgFile parse_csg(const std::string& text, const std::string& source) {
  return csg_from_json(parse_json_text(text, source), source);
}

CsgFile read_csg(const std::filesystem::path& file) { return parse_csg(read_text_file(file), file.string()); }

Json to_json(const CsgTree& tree) { return tree_json(tree, nullptr); }
Json to_json(const CsgFile& file) { return tree_json(file.tree, &file.node_names); }

void write_csg(const std::filesystem::path& file, const CsgTree& tree) {
  write_text_atomically(file, to_text(to_json(tree)));
}
void write_csg(const std::filesystem::path& file, const CsgFile& csg) {
  write_text_atomically(file, to_text(to_json(csg)));
}

}  // namespace gllab::io
