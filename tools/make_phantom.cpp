// tools/make_phantom.cpp — writes the 3-D Shepp–Logan head phantom
// (field/phantom.h) as a uint8 NRRD volume: how examples/ct_phantom.nrrd is
// made (`make_phantom 48 examples/ct_phantom.nrrd`; tests/io check that the
// shipped file is what this program writes).
//
//   make_phantom N OUT.nrrd
//
// N points per axis over [-1, 1]^3; the density d (0..1) is stored as
// round(255 d): air and the ventricles 0, brain 51, tumours 77, skull 255.
// Errors: one line on stderr; exit 2 for bad arguments, 1 when the file
// cannot be written.
#include <iostream>
#include <stdexcept>
#include <string>

#include "cli.h"
#include "field/phantom.h"
#include "io/spline_json.h"
#include "io/volume_nrrd.h"

namespace {

const char* const kUsage =
    "usage: make_phantom N OUT.nrrd\n"
    "\n"
    "Writes the modified 3-D Shepp-Logan head phantom sampled at N^3 points over\n"
    "[-1, 1]^3 (2 <= N <= 1024; each value the mean of 2 x 2 x 2 sub-samples) as a\n"
    "raw uint8 NRRD, the density d (0..1) stored as round(255 d). The shipped\n"
    "examples/ct_phantom.nrrd is make_phantom 48.\n";

int fail(const std::string& message, int status) {
  std::cerr << "make_phantom: " << message << "\n";
  return status;
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
  if (argc != 3) return fail("need N and OUT.nrrd (make_phantom --help)", 2);
  const std::string text = argv[1];
  int n = 0;
  try {
    n = gllab::cli::parse_count(text, "N", 2, 1024);
  } catch (const gllab::cli::UsageError& e) {
    return fail(e.what(), gllab::cli::kBadInput);
  }
  try {
    const gllab::field::Grid3 g = gllab::field::shepp_logan_phantom(n);
    gllab::io::write_nrrd_uint8(g, argv[2], 0, 1,
                                "modified 3-D Shepp-Logan phantom, " + text +
                                    "^3 over [-1,1]^3, "
                                    "density d as round(255 d)");
  } catch (const gllab::io::FileError& e) {
    return fail(e.what(), 1);
  } catch (const std::exception& e) {
    return fail(e.what(), 1);
  }
  return 0;
}
