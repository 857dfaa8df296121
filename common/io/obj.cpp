// common/io/obj.cpp — see obj.h.
#include "io/obj.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "io/spline_json.h"
#include "spline/errors.h"

namespace gllab::io {

namespace {

void append_number(std::string& out, double x) {
  if (!std::isfinite(x))
    spline::fail(spline::ErrorCode::kNotFinite, "OBJ: " + shortest_text(x) + " is not finite", {{"x", x}});
  out += shortest_text(x);
}

void append_line(std::string& out, const char* tag, spline::Vec3 p) {
  out += tag;
  out += ' ';
  append_number(out, p.x);
  out += ' ';
  append_number(out, p.y);
  out += ' ';
  append_number(out, p.z);
  out += '\n';
}

void append_comment(std::string& out, const std::string& comment) {
  if (comment.empty()) return;
  out += "# ";
  for (char c : comment) out += c == '\n' ? std::string("\n# ") : std::string(1, c);
  out += '\n';
}

/// A float in its shortest form that reads back to the same float (0.1f is
/// "0.1", not the double 0.10000000149011612).
void append_float_line(std::string& out, const char* tag, const float* v) {
  out += tag;
  for (int c = 0; c < 3; ++c) {
    if (!std::isfinite(v[c]))
      spline::fail(spline::ErrorCode::kNotFinite, "OBJ: " + shortest_text(v[c]) + " is not finite", {{"x", v[c]}});
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v[c]);
    out += ' ';
    out.append(buffer, result.ptr);
  }
  out += '\n';
}

}  // namespace

std::string obj_text(const spline::Mesh& mesh, const std::string& comment) {
  if (mesh.normals.size() != mesh.positions.size())
    spline::fail(spline::ErrorCode::kSizeMismatch,
                 "OBJ: " + std::to_string(mesh.normals.size()) + " normals for " +
                     std::to_string(mesh.positions.size()) + " positions (need one per vertex)",
                 {{"normals", mesh.normals.size()}, {"positions", mesh.positions.size()}});
  const int count = static_cast<int>(mesh.positions.size());
  std::string out;
  append_comment(out, comment);
  for (const spline::Vec3& p : mesh.positions) append_line(out, "v", p);
  for (const spline::Vec3& n : mesh.normals) append_line(out, "vn", n);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    out += 'f';
    for (int index : mesh.triangles[t]) {
      if (index < 0 || index >= count)
        spline::fail(spline::ErrorCode::kIndexOutOfRange,
                     "OBJ: triangle " + std::to_string(t) + " uses vertex " + std::to_string(index) + " of " +
                         std::to_string(count),
                     {{"triangle", t}, {"vertex", index}, {"vertices", count}});
      const std::string one_based = std::to_string(index + 1);
      out += ' ' + one_based + "//" + one_based;
    }
    out += '\n';
  }
  return out;
}

std::string obj_text(const std::vector<spline::Vec3>& polyline, const std::string& comment) {
  std::string out;
  append_comment(out, comment);
  for (const spline::Vec3& p : polyline) append_line(out, "v", p);
  if (polyline.size() >= 2) {
    out += 'l';
    for (std::size_t i = 1; i <= polyline.size(); ++i) out += ' ' + std::to_string(i);
    out += '\n';
  }
  return out;
}

std::string obj_text(const IndexedMesh& mesh, const std::string& comment) {
  const std::size_t count = mesh.positions.size() / 3;
  if (mesh.positions.size() % 3 != 0)
    spline::fail(spline::ErrorCode::kSizeMismatch,
                 "OBJ: " + std::to_string(mesh.positions.size()) + " position floats (need 3 per vertex)",
                 {{"positions", mesh.positions.size()}});
  const bool normals = !mesh.normals.empty();
  if (normals && mesh.normals.size() != mesh.positions.size())
    spline::fail(spline::ErrorCode::kSizeMismatch,
                 "OBJ: " + std::to_string(mesh.normals.size()) + " normal floats for " +
                     std::to_string(mesh.positions.size()) + " position floats (need one normal per vertex)",
                 {{"normals", mesh.normals.size()}, {"positions", mesh.positions.size()}});
  if (mesh.indices.size() % 3 != 0)
    spline::fail(spline::ErrorCode::kSizeMismatch,
                 "OBJ: " + std::to_string(mesh.indices.size()) + " indices (need 3 per triangle)",
                 {{"indices", mesh.indices.size()}});
  std::string out;
  append_comment(out, comment);
  for (std::size_t v = 0; v < count; ++v) append_float_line(out, "v", &mesh.positions[3 * v]);
  if (normals)
    for (std::size_t v = 0; v < count; ++v) append_float_line(out, "vn", &mesh.normals[3 * v]);
  for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
    out += 'f';
    for (std::size_t c = 0; c < 3; ++c) {
      const std::uint32_t index = mesh.indices[i + c];
      if (index >= count)
        spline::fail(spline::ErrorCode::kIndexOutOfRange,
                     "OBJ: triangle " + std::to_string(i / 3) + " uses vertex " + std::to_string(index) + " of " +
                         std::to_string(count),
                     {{"triangle", i / 3}, {"vertex", index}, {"vertices", count}});
      const std::string one_based = std::to_string(index + 1);
      out += ' ' + one_based;
      if (normals) out += "//" + one_based;
    }
    out += '\n';
  }
  return out;
}

void write_obj(const std::filesystem::path& file, const IndexedMesh& mesh, const std::string& comment) {
  write_text_atomically(file, obj_text(mesh, comment));
}

void write_obj(const std::filesystem::path& file, const spline::Mesh& mesh, const std::string& comment) {
  write_text_atomically(file, obj_text(mesh, comment));
}

void write_obj(const std::filesystem::path& file, const std::vector<spline::Vec3>& polyline,
               const std::string& comment) {
  write_text_atomically(file, obj_text(polyline, comment));
}

}  // namespace gllab::io
