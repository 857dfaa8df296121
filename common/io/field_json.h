// common/io/field_json.h — blob scenes (lecture notes ch. 1, §1.5 Blobby
// objects) in JSON files, with the rules of the spline files
// (common/io/README.md "blob_scene"):
//   {"type": "blob_scene", "density": "hermite", "iso": 0.5,
//    "blobs": [{"centre": [x, y, z], "a": 1, "b": 1}, ...],
//    "bounds": [[x0, y0, z0], [x1, y1, z1]]}          density, iso, a, b, bounds optional
// A bad file throws FileError with one line naming the file and the JSON path:
//   "scene.json: blobs[2].b: -1 (must be > 0: the radius of the blob)"
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "field/density.h"
#include "io/spline_json.h"

namespace gllab::io {

/// A box [lo, hi] (lo < hi on each axis).
struct Box {
  spline::Vec3 lo, hi;
};

struct BlobScene {
  field::BlobField field;     // the blobs (at least one) and their density
  double iso = 0.5;           // the surface {sum f_i = iso}, iso > 0
  std::optional<Box> bounds;  // as given in the file; bounds_of() fills in the default
};

/// The box the scene is sampled over: its "bounds", or else the union of
/// the blobs' boxes centre +- b grown by 5% of its size on every side.
Box bounds_of(const BlobScene& scene);

BlobScene read_blob_scene(const std::filesystem::path& file);
BlobScene parse_blob_scene(const std::string& text, const std::string& source = "<string>");
/// Checks an already parsed value (same checks and messages as parse_blob_scene).
BlobScene blob_scene_from_json(const Json& value, const std::string& source = "<json>");

/// "type" first, then density, iso, blobs (each with centre, a, b) and
/// bounds when the scene has them. to_text (spline_json.h) prints it.
Json to_json(const BlobScene& scene);
/// to_text(to_json(scene)) written atomically; throws FileError.
void write_blob_scene(const std::filesystem::path& file, const BlobScene& scene);

}  // namespace gllab::io
