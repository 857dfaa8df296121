// tests/io/volume_nrrd_test.cpp — NRRD volumes (common/io/volume_nrrd.cpp,
// Teem's nrrd library) and the shipped phantom examples/ct_phantom.nrrd
// (field/phantom.h, tools/make_phantom.cpp).
#include "io/volume_nrrd.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "field/phantom.h"
#include "io/spline_json.h"
#include "io_test_support.h"
#include "process.h"

namespace gllab::io {
namespace {

namespace fs = std::filesystem;
using field::Grid3;
using spline::Vec3;
using testing::kExamplesDir;
using testing::ScratchDir;

const std::string kPhantom = (kExamplesDir / "ct_phantom.nrrd").string();

/// A small grid with a different size, spacing and origin on every axis,
/// negative and fractional values (nothing a transposed axis could hide).
Grid3 test_grid() {
  Grid3 g;
  g.nx = 5;
  g.ny = 4;
  g.nz = 3;
  g.origin = {-1, 0.5, 1.0 / 3};
  g.spacing = {0.1, 0.25, 2.0 / 47};
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) g.values.push_back(float(i - 2 * j + 0.1 * k) / 3.0f);
  return g;
}

void write_bytes(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
}

/// Little-endian float bytes, as a raw NRRD with "endian: little" holds them.
std::string float_bytes(const std::vector<float>& v) {
  std::string out;
  for (float f : v) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    for (int b = 0; b < 4; ++b) out += char((u >> (8 * b)) & 0xff);
  }
  return out;
}

// ---- round trips ---------------------------------------------------------------

TEST(NrrdRoundTrip, FloatValuesSpacingAndOriginComeBackExactly) {
  ScratchDir dir("nrrd");
  const Grid3 g = test_grid();
  const std::string file = (dir / "grid.nrrd").string();
  write_nrrd(g, file, "test grid");
  const Grid3 r = read_nrrd(file);
  EXPECT_EQ(r.nx, 5);
  EXPECT_EQ(r.ny, 4);
  EXPECT_EQ(r.nz, 3);
  EXPECT_EQ(r.values, g.values);
  // Teem prints doubles with 17 significant digits: they read back bit-identical.
  EXPECT_EQ(r.spacing.x, 0.1);
  EXPECT_EQ(r.spacing.y, 0.25);
  EXPECT_EQ(r.spacing.z, 2.0 / 47);
  EXPECT_EQ(r.origin.x, -1.0);
  EXPECT_EQ(r.origin.y, 0.5);
  EXPECT_EQ(r.origin.z, 1.0 / 3);
  const std::string text = testing::read_file(file);
  EXPECT_EQ(text.rfind("NRRD", 0), 0u);
  EXPECT_NE(text.find("type: float\n"), std::string::npos);
  EXPECT_NE(text.find("encoding: raw\n"), std::string::npos);
  EXPECT_NE(text.find("content: test grid\n"), std::string::npos);
  // Header + the data: 60 floats, nothing more.
  EXPECT_EQ(text.size() - (text.find("\n\n") + 2), 60u * 4);
}

TEST(NrrdRoundTrip, Uint8IsQuantisedToLoHi) {
  ScratchDir dir("nrrd");
  Grid3 g = test_grid();
  g.values = std::vector<float>(60, 0.5f);
  g.values[0] = -3;   // below lo: 0
  g.values[1] = 0;    // lo: 0
  g.values[2] = 2;    // hi: 255
  g.values[3] = 7;    // above hi: 255
  g.values[4] = 0.5;  // 255 * 0.25 = 63.75: 64
  const std::string file = (dir / "grid8.nrrd").string();
  write_nrrd_uint8(g, file, 0, 2);
  const Grid3 r = read_nrrd(file);
  ASSERT_EQ(r.values.size(), 60u);
  EXPECT_EQ(r.values[0], 0);
  EXPECT_EQ(r.values[1], 0);
  EXPECT_EQ(r.values[2], 255);
  EXPECT_EQ(r.values[3], 255);
  EXPECT_EQ(r.values[4], 64);
  EXPECT_EQ(r.spacing.z, 2.0 / 47);
  EXPECT_EQ(r.origin.z, 1.0 / 3);
  const std::string text = testing::read_file(file);
  EXPECT_NE(text.find("type: unsigned char\n"), std::string::npos);
  EXPECT_NE(text.find("old max: 2\n"), std::string::npos);
  EXPECT_EQ(text.size() - (text.find("\n\n") + 2), 60u);
}

TEST(NrrdWrite, ReplacesAtomicallyAndNamesAnUnwritableFile) {
  ScratchDir dir("nrrd");
  const fs::path file = dir / "v.nrrd";
  write_bytes(file, "old");
  write_nrrd(test_grid(), file.string());
  EXPECT_EQ(read_nrrd(file.string()).values, test_grid().values);
  std::size_t entries = 0;
  for (const auto& e : fs::directory_iterator(dir.path())) entries += e.is_regular_file();
  EXPECT_EQ(entries, 1u) << "a temporary file was left behind";

  const std::string bad = (dir / "no_such_dir" / "v.nrrd").string();
  try {
    write_nrrd(test_grid(), bad);
    FAIL() << "wrote into a missing directory";
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(bad + ": cannot write", 0), 0u) << e.what();
  }
  // /dev/null is written in place (a rename would replace the device).
  EXPECT_NO_THROW(write_nrrd(test_grid(), "/dev/null"));
  Grid3 broken = test_grid();
  broken.values.pop_back();
  EXPECT_THROW(write_nrrd(broken, (dir / "b.nrrd").string()), std::invalid_argument);
  EXPECT_THROW(write_nrrd_uint8(test_grid(), (dir / "b.nrrd").string(), 1, 1),
               std::invalid_argument);
}

// ---- what Teem reads -------------------------------------------------------------------

TEST(NrrdRead, AsciiShortWithSpacingsField) {
  // No "space": the spacing comes from "spacings", the origin is 0.
  ScratchDir dir("nrrd");
  const fs::path file = dir / "short.nrrd";
  write_bytes(file,
              "NRRD0004\ntype: short\ndimension: 3\nsizes: 2 2 2\nspacings: 0.5 1 2\n"
              "encoding: ascii\n\n1 2 3 4 5 6 7 -8\n");
  const Grid3 r = read_nrrd(file.string());
  EXPECT_EQ(r.values, (std::vector<float>{1, 2, 3, 4, 5, 6, 7, -8}));
  EXPECT_EQ(r.spacing.x, 0.5);
  EXPECT_EQ(r.spacing.y, 1.0);
  EXPECT_EQ(r.spacing.z, 2.0);
  EXPECT_EQ(r.origin.x, 0.0);
  EXPECT_EQ(r.at(1, 1, 1), -8);
}

TEST(NrrdRead, GzipDoubleWithSpaceOrigin) {
  ScratchDir dir("nrrd");
  const fs::path file = dir / "gz.nrrd";
  write_bytes(file,
              "NRRD0004\ntype: double\ndimension: 3\nsizes: 3 2 2\nspace: right-anterior-superior\n"
              "space directions: (0.5,0,0) (0,0.25,0) (0,0,4)\nspace origin: (10,-20,30)\n"
              "endian: little\nencoding: gzip\n\n");
  std::vector<double> values(12);
  for (int i = 0; i < 12; ++i) values[i] = i * 0.5 - 1;
  gzFile gz = gzopen(file.c_str(), "ab");  // a gzip stream after the header
  ASSERT_NE(gz, nullptr);
  ASSERT_EQ(gzwrite(gz, values.data(), sizeof(double) * 12), int(sizeof(double) * 12));
  gzclose(gz);
  const Grid3 r = read_nrrd(file.string());
  ASSERT_EQ(r.values.size(), 12u);
  for (int i = 0; i < 12; ++i) EXPECT_EQ(r.values[i], float(values[i])) << i;
  EXPECT_EQ(r.spacing.x, 0.5);
  EXPECT_EQ(r.spacing.y, 0.25);
  EXPECT_EQ(r.spacing.z, 4.0);
  EXPECT_EQ(r.origin.x, 10.0);
  EXPECT_EQ(r.origin.y, -20.0);
  EXPECT_EQ(r.origin.z, 30.0);
}

// ---- bad files: one line naming the file ----------------------------------------------

struct BadNrrd {
  std::string name, bytes, expected;
};
void PrintTo(const BadNrrd& b, std::ostream* out) { *out << b.name; }

const std::string kHeader3 = "NRRD0004\ntype: float\ndimension: 3\nsizes: 2 2 2\nendian: little\n";

std::vector<BadNrrd> bad_nrrds() {
  std::vector<float> eight(8, 1.0f), with_nan = eight;
  with_nan[5] = std::nanf("");
  return {
      {"two_d.nrrd",
       "NRRD0004\ntype: float\ndimension: 2\nsizes: 2 2\nendian: little\nencoding: raw\n\n" +
           float_bytes({1, 2, 3, 4}),
       "2 dimensions, need 3"},
      {"four_d.nrrd",
       "NRRD0004\ntype: uchar\ndimension: 4\nsizes: 2 2 2 2\nencoding: raw\n\n" +
           std::string(16, 'a'),
       "4 dimensions, need 3"},
      {"truncated.nrrd", kHeader3 + "encoding: raw\n\n" + float_bytes({1, 2}),
       "fread got only 2 4-sized things, not 8"},
      {"not_nrrd.nrrd", "hello, I am not a volume\n", "couldn't parse"},
      {"empty.nrrd", "", "hit EOF"},
      {"axis_size_one.nrrd",
       "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 1 2\nencoding: raw\n\nabcd",
       "axis 1 (y) has 1 sample, need at least 2"},
      {"oblique.nrrd",
       "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\nspace dimension: 3\n"
       "space directions: (1,1,0) (0,1,0) (0,0,1)\nencoding: raw\n\nabcdefgh",
       "axis 0: space direction (1, 1, 0) is not along +x"},
      {"flipped.nrrd",
       "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\nspace: left-posterior-superior\n"
       "space directions: (-1,0,0) (0,-1,0) (0,0,1)\nencoding: raw\n\nabcdefgh",
       "axis 0: space direction (-1, 0, 0) is not along +x"},
      {"nan_value.nrrd", kHeader3 + "encoding: raw\n\n" + float_bytes(with_nan),
       "value at (1, 0, 1) is nan (values must be finite)"},
      {"bad_type.nrrd",
       "NRRD0004\ntype: complex\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\nabcdefgh", "type"},
  };
}

class BadNrrdFile : public ::testing::TestWithParam<BadNrrd> {};

TEST_P(BadNrrdFile, OneLineNamingTheFileAndTheProblem) {
  const BadNrrd& b = GetParam();
  ScratchDir dir("nrrd-bad");
  const std::string file = (dir / b.name).string();
  write_bytes(file, b.bytes);
  try {
    const Grid3 g = read_nrrd(file);
    FAIL() << b.name << " was read: " << g.nx << " x " << g.ny << " x " << g.nz;
  } catch (const FileError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(file + ": ", 0), 0u) << what;
    EXPECT_NE(what.find(b.expected), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(Teem, BadNrrdFile, ::testing::ValuesIn(bad_nrrds()),
                         [](const auto& info) { return testing::test_name(info.param.name); });

TEST(NrrdRead, MissingFileAndDirectory) {
  ScratchDir dir("nrrd");
  const std::string missing = (dir / "missing.nrrd").string();
  try {
    read_nrrd(missing);
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": cannot open (No such file or directory)");
  }
  try {
    read_nrrd(dir.path().string());
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()), dir.path().string() + ": is a directory, not a regular file");
  }
}

// ---- the shipped phantom ---------------------------------------------------------------------

/// The grid coordinate of index i at n = 48 over [-1, 1].
double coordinate(int i) { return -1 + 2.0 * i / 47; }

TEST(ShippedPhantom, SizeGeometryAndValueRange) {
  const Grid3 g = read_nrrd(kPhantom);
  EXPECT_EQ(g.nx, 48);
  EXPECT_EQ(g.ny, 48);
  EXPECT_EQ(g.nz, 48);
  EXPECT_DOUBLE_EQ(g.spacing.x, 2.0 / 47);
  EXPECT_DOUBLE_EQ(g.spacing.z, 2.0 / 47);
  EXPECT_EQ(g.origin.x, -1.0);
  EXPECT_EQ(g.origin.z, -1.0);
  const auto [lo, hi] = std::minmax_element(g.values.begin(), g.values.end());
  EXPECT_EQ(*lo, 0);    // air (and the ventricles: 1 - 0.8 - 0.2)
  EXPECT_EQ(*hi, 255);  // skull: density 1
  for (float v : g.values) ASSERT_EQ(v, std::round(v)) << "uint8 values are whole numbers";
  EXPECT_LE(fs::file_size(kPhantom), 112000u);  // 48^3 bytes and a header
}

TEST(ShippedPhantom, ValuesAreTheDensitySumsOfTheEllipsoids) {
  // The density at a grid point whose 2 x 2 x 2 sub-samples all lie in the
  // same ellipsoids is the sum of their densities (Toft's modified values,
  // from the table, not from the code), stored as 255 d to the nearest whole.
  const Grid3 g = read_nrrd(kPhantom);
  struct Probe {
    int i, j, k;
    double density;
    const char* where;
  };
  const Probe probes[] = {
      {24, 24, 24, 1.0 - 0.8, "the centre: skull + brain"},
      {0, 0, 0, 0.0, "a corner: air"},
      {24, 44, 24, 1.0, "the top of the skull"},
      {24, 32, 20, 1.0 - 0.8 + 0.1, "ellipsoid 5, above the ventricles"},
  };
  for (const Probe& p : probes) {
    const Vec3 x{coordinate(p.i), coordinate(p.j), coordinate(p.k)};
    // The probe is well inside its region: all eight sub-samples agree.
    const double h = 0.5 / 47;
    for (double dx : {-h, h})
      for (double dy : {-h, h})
        for (double dz : {-h, h})
          ASSERT_NEAR(field::shepp_logan_density({x.x + dx, x.y + dy, x.z + dz}), p.density, 1e-12)
              << p.where;
    EXPECT_NEAR(g.at(p.i, p.j, p.k), 255 * p.density, 0.5 + 1e-4) << p.where;
  }
  // The centre of the head, as the lab's trilinear interpolant sees it.
  EXPECT_NEAR(field::shepp_logan_density({0, 0, 0}), 0.2, 1e-15);
}

TEST(ShippedPhantom, IsWhatMakePhantomWrites) {
  ScratchDir dir("phantom");
  const std::string file = (dir / "ct_phantom.nrrd").string();
  const ProcessResult r = run_process({GLLAB_MAKE_PHANTOM, "48", file});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const Grid3 made = read_nrrd(file), shipped = read_nrrd(kPhantom);
  EXPECT_EQ(made.values, shipped.values)
      << "examples/ct_phantom.nrrd is stale: build/bin/make_phantom 48 examples/ct_phantom.nrrd";
  EXPECT_EQ(made.spacing.x, shipped.spacing.x);
  EXPECT_EQ(made.origin.y, shipped.origin.y);
  EXPECT_EQ(testing::read_file(file), testing::read_file(kPhantom)) << "byte-identical";
}

TEST(Phantom, IsSymmetricWhereTheTableIsAndRefusesBadSizes) {
  const Grid3 g = field::shepp_logan_phantom(16);
  EXPECT_EQ(g.values.size(), 16u * 16 * 16);
  EXPECT_EQ(g.origin.x, -1.0);
  EXPECT_DOUBLE_EQ(g.spacing.y, 2.0 / 15);
  EXPECT_EQ(g.at(0, 0, 0), 0.0f);
  EXPECT_EQ(field::shepp_logan_ellipsoids().size(), 10u);
  EXPECT_THROW(field::shepp_logan_phantom(1), std::invalid_argument);
  EXPECT_THROW(field::shepp_logan_phantom(2000), std::invalid_argument);
  // Two runs agree to the bit (deterministic sub-sampling).
  EXPECT_EQ(field::shepp_logan_phantom(16).values, g.values);
}

TEST(MakePhantom, BadArgumentsExitTwoWithOneLine) {
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{"1", "x.nrrd"}, {"abc", "x.nrrd"}, {"48"}, {}}) {
    std::vector<std::string> argv = {GLLAB_MAKE_PHANTOM};
    argv.insert(argv.end(), args.begin(), args.end());
    const ProcessResult r = run_process(argv);
    EXPECT_EQ(r.exit_status, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    if (args.size() == 2) {
      EXPECT_NE(r.err.find(args[0]), std::string::npos) << r.err;
    }
  }
}

}  // namespace
}  // namespace gllab::io
