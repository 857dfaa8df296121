// tools/make_faces.cpp — draws the two cartoon faces of the morphing lab
// (deform/faces.h) as PNG pictures: how examples/face_a.png and face_b.png
// are made (`make_faces 256 examples/face_a.png examples/face_b.png`;
// tests/deform/faces_test.cpp checks that the shipped files are what
// face_picture draws).
//
//   make_faces SIZE OUT_A.png OUT_B.png
//   make_faces --features
//
// --features prints the feature points of both faces, to copy into a lab.
// Errors: one line on stderr; exit 2 for bad arguments, 1 when a file
// cannot be written (write_png is atomic: no half-written file is left).
#include <charconv>
#include <cstddef>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.h"
#include "deform/faces.h"
#include "image/image.h"

namespace {

using gllab::deform::Face;

const char* const kUsage =
    "usage: make_faces SIZE OUT_A.png OUT_B.png\n"
    "       make_faces --features\n"
    "\n"
    "Draws the two cartoon faces of the morphing lab (common/deform/faces.h) as\n"
    "SIZE x SIZE RGBA PNGs (16 <= SIZE <= 4096): face A round, its eyes high and\n"
    "close together; face B a long oval, its eyes lower and further apart, a\n"
    "longer nose and a wider mouth lower down. The shipped examples/face_a.png\n"
    "and examples/face_b.png are make_faces 256.\n"
    "\n"
    "--features prints the feature points of both faces: name, then x and y of\n"
    "face A and of face B in the unit square (x right, y up; pixel (px, py) of\n"
    "an N x N picture, py from the top, has its centre at ((px + 0.5) / N,\n"
    "1 - (py + 0.5) / N)).\n";

int fail(const std::string& message, int status) {
  std::cerr << "make_faces: " << message << "\n";
  return status;
}

/// The shortest text that reads back as v (the points are multiples of
/// 1/512, so this is their exact decimal value).
std::string number(double v) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

/// text and spaces up to `width`, and at least one.
std::string padded(std::string text, std::size_t width) {
  text.append(text.size() < width ? width - text.size() : 1, ' ');
  return text;
}

void print_features() {
  const std::vector<gllab::deform::Feature>& a = gllab::deform::face_features(Face::kA);
  const std::vector<gllab::deform::Feature>& b = gllab::deform::face_features(Face::kB);
  std::cout << "# feature points of the faces (common/deform/faces.h), unit square, y up\n"
            << "# name          A.x          A.y          B.x          B.y\n";
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
    std::cout << padded(a[i].name, 16) << padded(number(a[i].at.x), 13)
              << padded(number(a[i].at.y), 13) << padded(number(b[i].at.x), 13)
              << number(b[i].at.y) << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << kUsage;
      return 0;
    }
  }
  if (argc >= 2 && std::string(argv[1]) == "--features") {
    if (argc != 2) return fail("--features takes no other argument (make_faces --help)", 2);
    print_features();
    return 0;
  }
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] == '-' && argv[i][1] == '-')
      return fail("unknown option '" + std::string(argv[i]) + "' (make_faces --help)", 2);
  if (argc != 4) return fail("need SIZE, OUT_A.png and OUT_B.png (make_faces --help)", 2);
  int size = 0;
  try {
    size = gllab::cli::parse_count(argv[1], "SIZE", 16, 4096);
  } catch (const gllab::cli::UsageError& e) {
    return fail(e.what(), gllab::cli::kBadInput);
  }
  try {
    const gllab::Image a = gllab::deform::face_picture(Face::kA, size);
    const gllab::Image b = gllab::deform::face_picture(Face::kB, size);
    gllab::write_png(argv[2], a);
    gllab::write_png(argv[3], b);
  } catch (const std::exception& e) {
    return fail(e.what(), gllab::cli::kFailed);
  }
  return gllab::cli::kOk;
}
