// common/io/obj.cpp — see obj.h.
#include "io/obj.h"

#include <cmath>
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

void write_obj(const std::filesystem::path& file, const spline::Mesh& mesh, const std::string& comment) {
  write_text_atomically(file, obj_text(mesh, comment));
}

void write_obj(const std::filesystem::path& file, const std::vector<spline::Vec3>& polyline,
               const std::string& comment) {
  write_text_atomically(file, obj_text(polyline, comment));
}

}  // namespace gllab::io
