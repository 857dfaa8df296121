// common/io/field_json.cpp — reads and writes blob scenes (field_json.h,
// common/io/README.md). Every key is checked here, so that a mistake is
// reported at its JSON path ("blobs[2].centre[1]: ...").
#include "io/field_json.h"
#include "io/json_checks.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace gllab::io {

using spline::Vec3;

namespace {

using detail::describe;
using detail::index_path;
using detail::member_path;

constexpr const char* kDensities = R"("hermite", "wyvill" or "blinn")";

class Checker : public detail::JsonChecker {
 public:
  using JsonChecker::JsonChecker;

  Vec3 point(const Json& v, const std::string& path) const {
    return triple(v, path, "a point ", "coordinate");
  }

  field::Blob blob(const Json& v, const std::string& path) const {
    require_object(v, path, R"(a blob {"centre": [x, y, z], "a": 1, "b": 1})");
    only_keys(v, path, {"centre", "a", "b"}, "blob");
    field::Blob b;
    b.centre = point(member(v, path, "centre", "blob"), member_path(path, "centre"));
    if (const Json* a = optional_member(v, "a"))
      b.a = positive(*a, member_path(path, "a"), "the density at the centre");
    if (const Json* r = optional_member(v, "b"))
      b.b = positive(*r, member_path(path, "b"), "the radius of the blob");
    return b;
  }

  Box bounds(const Json& v) const {
    if (!v.is_array()) fail("bounds", "expected [[x0, y0, z0], [x1, y1, z1]], got " + describe(v));
    if (v.size() != 2)
      fail("bounds", "has " + std::to_string(v.size()) +
                         " entries (expected two corners [[x0, y0, z0], [x1, y1, z1]])");
    Box box{point(v[0], "bounds[0]"), point(v[1], "bounds[1]")};
    const double lo[3] = {box.lo.x, box.lo.y, box.lo.z}, hi[3] = {box.hi.x, box.hi.y, box.hi.z};
    for (std::size_t c = 0; c < 3; ++c)
      if (!(hi[c] > lo[c]))
        fail(index_path("bounds[1]", c), shortest_text(hi[c]) + " <= bounds[0][" +
                                             std::to_string(c) + "] = " + shortest_text(lo[c]) +
                                             " (the upper corner must be above the lower one)");
    return box;
  }

  BlobScene scene(const Json& root) const {
    require_object(root, "", R"(a JSON object {"type": "blob_scene", ...})");
    const Json& type = member(root, "", "type", "blob_scene");
    if (string(type, "type") != "blob_scene")
      fail("type", describe(type) + R"( (this file holds a "blob_scene"))");
    only_keys(root, "", {"type", "density", "iso", "blobs", "bounds"}, "blob_scene");
    BlobScene s;
    if (const Json* d = optional_member(root, "density")) {
      const std::string name = string(*d, "density");
      bool known = false;
      for (field::Density k :
           {field::Density::kHermite, field::Density::kWyvill, field::Density::kBlinn})
        if (name == field::density_name(k)) {
          s.field.density = k;
          known = true;
        }
      if (!known) fail("density", describe(*d) + " (one of " + kDensities + ")");
    }
    if (const Json* iso = optional_member(root, "iso")) {
      s.iso = number(*iso, "iso");
      if (!(s.iso > 0))
        fail("iso", shortest_text(s.iso) + " (must be > 0: the field is 0 far from the blobs)");
    }
    const Json& blobs = member(root, "", "blobs", "blob_scene");
    if (!blobs.is_array()) fail("blobs", "expected an array of blobs, got " + describe(blobs));
    if (blobs.empty()) fail("blobs", "empty (a blob_scene needs at least one blob)");
    for (std::size_t i = 0; i < blobs.size(); ++i)
      s.field.blobs.push_back(blob(blobs[i], index_path("blobs", i)));
    if (const Json* b = optional_member(root, "bounds")) s.bounds = bounds(*b);
    return s;
  }

};

Json point_json(const Vec3& p) { return Json::array({p.x, p.y, p.z}); }

}  // namespace

Box bounds_of(const BlobScene& scene) {
  if (scene.bounds) return *scene.bounds;
  Box box;
  bool first = true;
  for (const field::Blob& b : scene.field.blobs) {
    const Vec3 lo{b.centre.x - b.b, b.centre.y - b.b, b.centre.z - b.b};
    const Vec3 hi{b.centre.x + b.b, b.centre.y + b.b, b.centre.z + b.b};
    if (first) {
      box = {lo, hi};
      first = false;
      continue;
    }
    box.lo = {std::min(box.lo.x, lo.x), std::min(box.lo.y, lo.y), std::min(box.lo.z, lo.z)};
    box.hi = {std::max(box.hi.x, hi.x), std::max(box.hi.y, hi.y), std::max(box.hi.z, hi.z)};
  }
  if (first) return {{-1, -1, -1}, {1, 1, 1}};  // no blobs: the reader never returns such a scene
  const Vec3 grow{0.05 * (box.hi.x - box.lo.x), 0.05 * (box.hi.y - box.lo.y),
                  0.05 * (box.hi.z - box.lo.z)};
  return {{box.lo.x - grow.x, box.lo.y - grow.y, box.lo.z - grow.z},
          {box.hi.x + grow.x, box.hi.y + grow.y, box.hi.z + grow.z}};
}

BlobScene blob_scene_from_json(const Json& value, const std::string& source) {
  return Checker(source).scene(value);
}

BlobScene parse_blob_scene(const std::string& text, const std::string& source) {
  return blob_scene_from_json(parse_json_text(text, source), source);
}

BlobScene read_blob_scene(const std::filesystem::path& file) {
  return parse_blob_scene(read_text_file(file), file.string());
}

Json to_json(const BlobScene& scene) {
  Json out = Json::object();
  out["type"] = "blob_scene";
  out["density"] = field::density_name(scene.field.density);
  out["iso"] = scene.iso;
  Json blobs = Json::array();
  for (const field::Blob& b : scene.field.blobs) {
    Json blob = Json::object();
    blob["centre"] = point_json(b.centre);
    blob["a"] = b.a;
    blob["b"] = b.b;
    blobs.push_back(std::move(blob));
  }
  out["blobs"] = std::move(blobs);
  if (scene.bounds)
    out["bounds"] = Json::array({point_json(scene.bounds->lo), point_json(scene.bounds->hi)});
  return out;
}

void write_blob_scene(const std::filesystem::path& file, const BlobScene& scene) {
  write_text_atomically(file, to_text(to_json(scene)));
}

}  // namespace gllab::io
