// tests/image/png_test.cpp · tests for common/image/image.cpp
// Round trips, expansion of every PNG colour type to RGBA8, and errors that must
// be loud, one line, and leave nothing behind. Scratch files live in a fresh
// directory under the system temp dir, removed after each test.
#include "image/image.h"
#include "test_images.h"

#include <gtest/gtest.h>
#include <png.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

namespace fs = std::filesystem;
using gllab::Image;
using gllab::ImageError;

namespace {

using gllab::testing::random_image;
using gllab::testing::rgba_at;

using Bytes = std::vector<std::uint8_t>;

// --- Helpers -------------------------------------------------------------------

Bytes read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_bytes(const std::string& path, const Bytes& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!out) throw std::runtime_error("test helper: cannot write '" + path + "'");
}

// The names in a directory, sorted: shows leftover temporary files.
std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

// CRC-32 as the PNG specification defines it (ISO/IEC 15948, annex D):
// polynomial 0xEDB88320 (reflected), initial value and final xor 0xFFFFFFFF.
std::uint32_t png_crc(const std::uint8_t* data, std::size_t size) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

// Where one chunk sits in a PNG file: a chunk is length(4) type(4) data crc(4).
struct Chunk {
  std::size_t start = 0;   // offset of the length field
  std::uint32_t length = 0;
  std::string type;
  std::size_t data() const { return start + 8; }
  std::size_t crc() const { return start + 8 + length; }
};

std::vector<Chunk> chunks_of(const Bytes& png) {
  std::vector<Chunk> chunks;
  std::size_t at = 8;  // after the signature
  while (at + 12 <= png.size()) {
    Chunk c;
    c.start = at;
    c.length = std::uint32_t(png[at]) << 24 | std::uint32_t(png[at + 1]) << 16 |
               std::uint32_t(png[at + 2]) << 8 | std::uint32_t(png[at + 3]);
    c.type.assign(png.begin() + long(at) + 4, png.begin() + long(at) + 8);
    chunks.push_back(c);
    at = c.crc() + 4;
  }
  return chunks;
}

// Rewrites a chunk's CRC so the damage inside it reaches the decoder.
void fix_crc(Bytes& png, const Chunk& c) {
  const std::uint32_t crc = png_crc(&png[c.start + 4], c.length + 4);  // type + data
  for (int i = 0; i < 4; ++i) png[c.crc() + i] = std::uint8_t(crc >> (24 - 8 * i));
}

// A PNG exactly as it is stored, for files our writer never produces
// (grey, palette, 16-bit, tRNS, interlaced). Rows hold packed samples;
// 16-bit samples are big-endian, as the PNG spec stores them.
struct RawPng {
  int width = 0, height = 0;
  int bit_depth = 8;
  int color_type = PNG_COLOR_TYPE_RGB_ALPHA;
  bool interlaced = false;
  std::vector<Bytes> rows;
  std::vector<png_color> palette;  // PLTE
  Bytes palette_alpha;             // tRNS for a palette image
  bool has_key = false;            // tRNS for grey/RGB: this colour is transparent
  png_color_16 key = {};
};

// libpng's default error handler longjmps to png_jmpbuf after printing the message.
// Only plain data lives in this frame (see common/image/image.cpp for why).
bool encode_raw(png_structp png, png_infop info, std::FILE* file, const RawPng* raw) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_set_IHDR(png, info, png_uint_32(raw->width), png_uint_32(raw->height), raw->bit_depth,
               raw->color_type, raw->interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (!raw->palette.empty())
    png_set_PLTE(png, info, raw->palette.data(), int(raw->palette.size()));
  if (!raw->palette_alpha.empty())
    png_set_tRNS(png, info, raw->palette_alpha.data(), int(raw->palette_alpha.size()), nullptr);
  if (raw->has_key) png_set_tRNS(png, info, nullptr, 0, &raw->key);
  png_write_info(png, info);
  // For an interlaced file libpng picks each pass's pixels out of the full rows.
  const int passes = png_set_interlace_handling(png);
  for (int pass = 0; pass < passes; ++pass)
    for (const Bytes& row : raw->rows) png_write_row(png, row.data());
  png_write_end(png, info);
  return true;
}

void write_raw_png(const std::string& path, const RawPng& raw) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) throw std::runtime_error("test helper: cannot create '" + path + "'");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
  const bool ok = info != nullptr && encode_raw(png, info, file, &raw);
  png_destroy_write_struct(&png, &info);
  std::fclose(file);
  if (!ok) throw std::runtime_error("test helper: libpng could not write '" + path + "'");
}

// The RGBA of pixel (x,y) as a vector, so gtest prints it on failure.
// --- Fixture: a fresh scratch directory per test --------------------------------

class PngFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    dir_ = fs::temp_directory_path() /
           ("gllab_image_test_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ignored);
    fs::remove_all(dir_, ignored);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Checks an error message: one line, naming the file.
  static void expect_one_line_naming(const std::string& message, const std::string& file) {
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find("'" + file + "'"), std::string::npos) << message;
  }

  fs::path dir_;
};

// --- Image and image_from_bottom_up -------------------------------------------------

TEST(ImageType, ConstructorZeroFillsAndIndexesRowMajor) {
  Image img(3, 2);
  ASSERT_EQ(img.rgba.size(), 3u * 2u * 4u);  // width*height*4 (image.h)
  EXPECT_TRUE(std::all_of(img.rgba.begin(), img.rgba.end(), [](std::uint8_t b) { return b == 0; }));
  // image.h: pixel(x,y) == &rgba[(y*width+x)*4]; (2,1) -> (1*3+2)*4 = 20.
  EXPECT_EQ(img.pixel(2, 1), &img.rgba[20]);
}

TEST(ImageType, NonPositiveSizeThrowsNamingTheValues) {
  for (auto [w, h] : {std::pair{0, 5}, std::pair{4, -2}}) {
    try {
      Image img(w, h);
      ADD_FAILURE() << "no exception for " << w << "x" << h;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(std::to_string(w) + "x" + std::to_string(h)),
                std::string::npos) << e.what();
    }
  }
}

TEST(ImageFromBottomUp, FirstInputRowBecomesLastImageRow) {
  // 2x3 buffer as glReadPixels returns it: row 0 is the bottom of the screen.
  // Every byte of row r is 10*r + byte index, so each row is recognisable.
  constexpr int kWidth = 2, kHeight = 3;
  Bytes gl(kWidth * kHeight * 4);
  for (int r = 0; r < kHeight; ++r)
    for (int i = 0; i < kWidth * 4; ++i) gl[r * kWidth * 4 + i] = std::uint8_t(10 * r + i);

  const Image img = gllab::image_from_bottom_up(gl.data(), kWidth, kHeight);
  ASSERT_EQ(img.width, kWidth);
  ASSERT_EQ(img.height, kHeight);
  // Property of the flip: image row y is input row height-1-y.
  for (int y = 0; y < kHeight; ++y)
    for (int i = 0; i < kWidth * 4; ++i)
      EXPECT_EQ(img.rgba[y * kWidth * 4 + i], gl[(kHeight - 1 - y) * kWidth * 4 + i]) << y << "," << i;
  // Input row 0 (bottom) is the image's last row: its first pixel is 0,1,2,3.
  EXPECT_EQ(rgba_at(img, 0, kHeight - 1), (Bytes{0, 1, 2, 3}));
}

TEST(ImageFromBottomUp, NullBufferThrows) {
  EXPECT_THROW(gllab::image_from_bottom_up(nullptr, 2, 2), std::invalid_argument);
}

// --- Round trips ------------------------------------------------------------------

struct Size {
  int width, height;
};
// So gtest (and ctest's test names) show a size as "3x7".
std::ostream& operator<<(std::ostream& out, const Size& s) {
  return out << s.width << "x" << s.height;
}

class PngRoundTrip : public PngFiles,
                     public ::testing::WithParamInterface<std::tuple<int, Size>> {};

TEST_P(PngRoundTrip, RandomRgbaIsByteExact) {
  const auto [level, size] = GetParam();
  const Image original = random_image(size.width, size.height, unsigned(level * 1000 + size.width));
  const std::string file = path("round_trip.png");
  gllab::write_png(file, original, level);

  // PNG is lossless at every zlib level: the same bytes must come back.
  const Image back = gllab::read_png(file);
  EXPECT_EQ(back.width, original.width);
  EXPECT_EQ(back.height, original.height);
  EXPECT_TRUE(back.rgba == original.rgba);
  // The atomic write leaves only the finished file, no "*.tmp.<pid>".
  EXPECT_EQ(listing(dir_), std::vector<std::string>{"round_trip.png"});
}

// Test names like "Level6_3x7".
std::string round_trip_name(const ::testing::TestParamInfo<PngRoundTrip::ParamType>& info) {
  const auto [level, size] = info.param;
  return "Level" + std::to_string(level) + "_" + std::to_string(size.width) + "x" +
         std::to_string(size.height);
}

INSTANTIATE_TEST_SUITE_P(LevelsAndOddSizes, PngRoundTrip,
                         ::testing::Combine(::testing::Values(0, 1, 6, 9),
                                            ::testing::Values(Size{1, 1}, Size{3, 7}, Size{64, 33})),
                         round_trip_name);

TEST_F(PngFiles, HigherZlibLevelGivesSmallerFileForSmoothImage) {
  // A gradient compresses well; level 0 only stores (zlib "stored" blocks), so it
  // must be larger than level 9 (a property of deflate, not an exact size).
  Image gradient(128, 64);
  for (int y = 0; y < gradient.height; ++y)
    for (int x = 0; x < gradient.width; ++x) {
      std::uint8_t* p = gradient.pixel(x, y);
      p[0] = std::uint8_t(2 * x), p[1] = std::uint8_t(4 * y), p[2] = 128, p[3] = 255;
    }
  gllab::write_png(path("level0.png"), gradient, 0);
  gllab::write_png(path("level9.png"), gradient, 9);
  EXPECT_GT(fs::file_size(path("level0.png")), fs::file_size(path("level9.png")));
  EXPECT_TRUE(gllab::read_png(path("level0.png")).rgba == gradient.rgba);
  EXPECT_TRUE(gllab::read_png(path("level9.png")).rgba == gradient.rgba);
}

TEST_F(PngFiles, WriteReplacesAnExistingFile) {
  const Image first = random_image(4, 4, 1), second = random_image(5, 3, 2);
  gllab::write_png(path("out.png"), first);
  gllab::write_png(path("out.png"), second);
  EXPECT_TRUE(gllab::read_png(path("out.png")).rgba == second.rgba);
  EXPECT_EQ(listing(dir_), std::vector<std::string>{"out.png"});
}

// --- Expansion of other PNG formats to RGBA8 -------------------------------------
// Expected values follow the PNG specification (ISO/IEC 15948): grey expands to
// R=G=B (§10.1), low bit depths scale by (2^8-1)/(2^n-1), i.e. *17 for 4 bits
// (§12.5); no alpha means opaque; tRNS gives palette alpha, and entries past its
// end are opaque; a grey/RGB tRNS key colour is fully transparent (§11.3.2.1).

TEST_F(PngFiles, Gray4BitExpandsToOpaqueGrey) {
  RawPng raw;
  raw.width = 4, raw.height = 1, raw.bit_depth = 4, raw.color_type = PNG_COLOR_TYPE_GRAY;
  raw.rows = {{0x05, 0xAF}};  // samples 0, 5, 10, 15 packed two per byte
  write_raw_png(path("gray4.png"), raw);

  const Image img = gllab::read_png(path("gray4.png"));
  ASSERT_EQ(img.width, 4);
  ASSERT_EQ(img.height, 1);
  EXPECT_EQ(rgba_at(img, 0, 0), (Bytes{0, 0, 0, 255}));        // 0*17
  EXPECT_EQ(rgba_at(img, 1, 0), (Bytes{85, 85, 85, 255}));     // 5*17
  EXPECT_EQ(rgba_at(img, 2, 0), (Bytes{170, 170, 170, 255}));  // 10*17
  EXPECT_EQ(rgba_at(img, 3, 0), (Bytes{255, 255, 255, 255}));  // 15*17
}

TEST_F(PngFiles, GrayAlpha8BitKeepsAlpha) {
  RawPng raw;
  raw.width = 2, raw.height = 1, raw.color_type = PNG_COLOR_TYPE_GRAY_ALPHA;
  raw.rows = {{100, 50, 200, 255}};  // (grey, alpha) pairs
  write_raw_png(path("gray_alpha.png"), raw);

  const Image img = gllab::read_png(path("gray_alpha.png"));
  EXPECT_EQ(rgba_at(img, 0, 0), (Bytes{100, 100, 100, 50}));
  EXPECT_EQ(rgba_at(img, 1, 0), (Bytes{200, 200, 200, 255}));
}

TEST_F(PngFiles, Palette2BitWithTransparencyExpandsToColours) {
  RawPng raw;
  raw.width = 3, raw.height = 1, raw.bit_depth = 2, raw.color_type = PNG_COLOR_TYPE_PALETTE;
  raw.palette = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
  raw.palette_alpha = {255, 128};  // tRNS covers entries 0 and 1 only
  raw.rows = {{0x18}};             // indices 0, 1, 2 (binary 00 01 10, padded with 00)
  write_raw_png(path("palette.png"), raw);

  const Image img = gllab::read_png(path("palette.png"));
  ASSERT_EQ(img.width, 3);
  EXPECT_EQ(rgba_at(img, 0, 0), (Bytes{255, 0, 0, 255}));  // entry 0, tRNS 255
  EXPECT_EQ(rgba_at(img, 1, 0), (Bytes{0, 255, 0, 128}));  // entry 1, tRNS 128
  EXPECT_EQ(rgba_at(img, 2, 0), (Bytes{0, 0, 255, 255}));  // entry 2, past tRNS: opaque
}

TEST_F(PngFiles, Rgba16BitRoundsTo8Bit) {
  // image.h: 16 -> 8 bits is round(v*255/65535) = round(v/257).
  //   0xFFFF -> 255, 0x0000 -> 0, 0x8080 = 128*257 -> 128 exactly,
  //   0x12FF = 4863 -> 18.92 -> 19 (keeping the high byte would give 0x12 = 18),
  //   0x1280 = 4736 -> 18.43 -> 18, 0x4000 = 16384 -> 63.75 -> 64.
  RawPng raw;
  raw.width = 2, raw.height = 1, raw.bit_depth = 16, raw.color_type = PNG_COLOR_TYPE_RGB_ALPHA;
  raw.rows = {{0xFF, 0xFF, 0x00, 0x00, 0x80, 0x80, 0xFF, 0xFF,    // pixel 0
               0x12, 0xFF, 0x12, 0x80, 0x00, 0x00, 0x40, 0x00}};  // pixel 1
  write_raw_png(path("rgba16.png"), raw);

  const Image img = gllab::read_png(path("rgba16.png"));
  EXPECT_EQ(rgba_at(img, 0, 0), (Bytes{255, 0, 128, 255}));
  EXPECT_EQ(rgba_at(img, 1, 0), (Bytes{19, 18, 0, 64}));
}

TEST_F(PngFiles, Gray16BitExpandsToOpaqueGrey) {
  // 0x8080 = 128*257 -> 128; 0xFFFF -> 255 (same rule as above).
  RawPng raw;
  raw.width = 2, raw.height = 1, raw.bit_depth = 16, raw.color_type = PNG_COLOR_TYPE_GRAY;
  raw.rows = {{0x80, 0x80, 0xFF, 0xFF}};
  write_raw_png(path("gray16.png"), raw);

  const Image img = gllab::read_png(path("gray16.png"));
  EXPECT_EQ(rgba_at(img, 0, 0), (Bytes{128, 128, 128, 255}));
  EXPECT_EQ(rgba_at(img, 1, 0), (Bytes{255, 255, 255, 255}));
}

TEST_F(PngFiles, RgbColourKeyBecomesTransparent) {
  RawPng raw;
  raw.width = 2, raw.height = 1, raw.color_type = PNG_COLOR_TYPE_RGB;
  raw.rows = {{10, 20, 30, 40, 50, 60}};
  raw.has_key = true;
  raw.key.red = 40, raw.key.green = 50, raw.key.blue = 60;  // pixel 1's colour
  write_raw_png(path("rgb_key.png"), raw);

  const Image img = gllab::read_png(path("rgb_key.png"));
  EXPECT_EQ(rgba_at(img, 0, 0), (Bytes{10, 20, 30, 255}));
  EXPECT_EQ(rgba_at(img, 1, 0), (Bytes{40, 50, 60, 0}));
}

TEST_F(PngFiles, InterlacedRgbaReadsLikeNonInterlaced) {
  // Adam7 reorders pixels into 7 passes in the file; decoded, they are the same pixels.
  const Image original = random_image(9, 7, 42);
  RawPng raw;
  raw.width = original.width, raw.height = original.height, raw.interlaced = true;
  for (int y = 0; y < original.height; ++y)
    raw.rows.emplace_back(original.pixel(0, y), original.pixel(0, y) + original.width * 4);
  write_raw_png(path("adam7.png"), raw);

  EXPECT_TRUE(gllab::read_png(path("adam7.png")).rgba == original.rgba);
}

// --- read_png errors ---------------------------------------------------------------

// The exact text of a read_png error, so the test states what the user sees.
std::string read_error(const std::string& file) {
  try {
    gllab::read_png(file);
  } catch (const ImageError& e) {
    return e.what();
  }
  return "(no exception)";
}

TEST_F(PngFiles, MissingFileSaysNoSuchFile) {
  const std::string file = path("missing.png");
  EXPECT_EQ(read_error(file), "read_png: '" + file + "': no such file");  // image.h
}

TEST_F(PngFiles, TextFileNamedPngIsNotAPng) {
  const std::string file = path("notes.png");
  write_bytes(file, Bytes{'h', 'e', 'l', 'l', 'o', ',', ' ', 'w', 'o', 'r', 'l', 'd', '\n'});
  EXPECT_EQ(read_error(file), "read_png: '" + file + "': not a PNG file");  // image.h
}

TEST_F(PngFiles, EmptyFileIsNotAPng) {
  const std::string file = path("empty.png");
  write_bytes(file, Bytes{});
  EXPECT_EQ(read_error(file), "read_png: '" + file + "': not a PNG file");
}

TEST_F(PngFiles, DirectoryCannotBeRead) {
  const std::string message = read_error(dir_.string());
  EXPECT_EQ(message.rfind("read_png: '" + dir_.string() + "': ", 0), 0u) << message;
  expect_one_line_naming(message, dir_.string());
}

TEST_F(PngFiles, TruncatedPngIsCorrupt) {
  const std::string good = path("good.png"), half = path("half.png");
  gllab::write_png(good, random_image(16, 16, 7));
  const Bytes bytes = read_bytes(good);
  write_bytes(half, Bytes(bytes.begin(), bytes.begin() + long(bytes.size() / 2)));

  const std::string message = read_error(half);
  // image.h: "read_png: '<path>': corrupt PNG (libpng: <msg>)"
  EXPECT_EQ(message.rfind("read_png: '" + half + "': corrupt PNG (libpng: ", 0), 0u) << message;
  EXPECT_EQ(message.back(), ')') << message;
  expect_one_line_naming(message, half);
}

TEST_F(PngFiles, CorruptedIdatByteFailsTheCrc) {
  const std::string file = path("bad_idat.png");
  gllab::write_png(file, random_image(16, 16, 8));
  Bytes bytes = read_bytes(file);
  const auto chunks = chunks_of(bytes);
  const auto idat = std::find_if(chunks.begin(), chunks.end(),
                                 [](const Chunk& c) { return c.type == "IDAT"; });
  ASSERT_NE(idat, chunks.end());
  bytes[idat->data() + idat->length / 2] ^= 0xFF;
  write_bytes(file, bytes);

  const std::string message = read_error(file);
  EXPECT_EQ(message.rfind("read_png: '" + file + "': corrupt PNG (libpng: ", 0), 0u) << message;
  // libpng inflates IDAT while reading it, so whichever check trips first names
  // the chunk: zlib's Adler-32 ("IDAT: incorrect data check"), an invalid deflate
  // code, or the chunk CRC at its end ("IDAT: CRC error").
  EXPECT_NE(message.find("(libpng: IDAT: "), std::string::npos) << message;
  expect_one_line_naming(message, file);
}

// Property: whatever the damage, read_png returns an image or throws a one-line
// ImageError naming the file. Under AddressSanitizer this also shows that no
// error path leaks or touches freed memory.
TEST_F(PngFiles, EveryTruncationAndByteFlipFailsCleanly) {
  const std::string good = path("good.png"), bad = path("bad.png");
  gllab::write_png(good, random_image(5, 4, 9));
  const Bytes bytes = read_bytes(good);
  int errors = 0, images = 0;

  auto try_read = [&](const Bytes& damaged, const std::string& what) {
    write_bytes(bad, damaged);
    try {
      const Image img = gllab::read_png(bad);
      EXPECT_EQ(img.rgba.size(), std::size_t(img.width) * std::size_t(img.height) * 4) << what;
      ++images;
    } catch (const ImageError& e) {
      ++errors;
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << what << ": " << message;
      EXPECT_NE(message.find("'" + bad + "'"), std::string::npos) << what << ": " << message;
    }  // any other exception type fails the test
  };

  // Every proper prefix of the file is truncated somewhere.
  for (std::size_t n = 0; n < bytes.size(); ++n)
    try_read(Bytes(bytes.begin(), bytes.begin() + long(n)), "first " + std::to_string(n) + " bytes");
  // Flip each byte: the chunk CRCs catch it; with the CRC rewritten, the damage
  // reaches the IHDR checks and the zlib decoder instead.
  const auto chunks = chunks_of(bytes);
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    Bytes damaged = bytes;
    damaged[i] ^= 0xFF;
    try_read(damaged, "byte " + std::to_string(i) + " flipped");
    for (const Chunk& c : chunks)
      if (i >= c.data() && i < c.crc()) {
        fix_crc(damaged, c);
        try_read(damaged, "byte " + std::to_string(i) + " flipped, CRC fixed");
      }
  }
  EXPECT_GE(errors, int(bytes.size()));  // at least every truncation fails
  std::cout << "[          ] " << errors << " damaged files rejected, " << images
            << " decoded to some image\n";
}

// --- write_png errors ----------------------------------------------------------------

std::string write_error(const std::string& file, const Image& img) {
  try {
    gllab::write_png(file, img);
  } catch (const ImageError& e) {
    return e.what();
  }
  return "(no exception)";
}

TEST_F(PngFiles, WriteIntoMissingDirectoryThrowsAndLeavesNothing) {
  const std::string file = path("no_such_dir/out.png");
  const std::string message = write_error(file, random_image(2, 2, 3));
  // image.h: "write_png: '<path>': cannot open for writing: <strerror(ENOENT)>"
  EXPECT_EQ(message, "write_png: '" + file + "': cannot open for writing: " + std::strerror(ENOENT));
  EXPECT_TRUE(listing(dir_).empty());
}

TEST_F(PngFiles, WriteBelowARegularFileThrowsAndLeavesNothing) {
  // Fails for root too: a regular file can't hold directory entries (ENOTDIR).
  write_bytes(path("plain_file"), Bytes{'x'});
  const std::string file = path("plain_file/out.png");
  const std::string message = write_error(file, random_image(2, 2, 3));
  EXPECT_EQ(message, "write_png: '" + file + "': cannot open for writing: " + std::strerror(ENOTDIR));
  EXPECT_EQ(listing(dir_), std::vector<std::string>{"plain_file"});
}

TEST_F(PngFiles, WriteIntoSysfsThrowsAndLeavesNothing) {
  // sysfs never lets anyone create a file in its root, root included (EACCES, or
  // EROFS where it is mounted read-only), so this is a read-only target for CI.
  const std::string file = "/sys/gllab_image_test.png";
  if (!fs::is_directory("/sys")) GTEST_SKIP() << "no /sys on this system";
  const std::string message = write_error(file, random_image(2, 2, 3));
  EXPECT_EQ(message.rfind("write_png: '" + file + "': cannot open for writing: ", 0), 0u) << message;
  expect_one_line_naming(message, file);
  EXPECT_FALSE(fs::exists(file));
  EXPECT_FALSE(fs::exists(file + ".tmp." + std::to_string(::getpid())));
}

TEST_F(PngFiles, WriteIntoReadOnlyDirectoryThrowsForNonRoot) {
  if (::geteuid() == 0) GTEST_SKIP() << "root may write into a 0555 directory";
  const fs::path locked = dir_ / "locked";
  fs::create_directory(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  const std::string file = (locked / "out.png").string();
  const std::string message = write_error(file, random_image(2, 2, 3));
  fs::permissions(locked, fs::perms::owner_all);
  EXPECT_EQ(message, "write_png: '" + file + "': cannot open for writing: " + std::strerror(EACCES));
  EXPECT_TRUE(fs::is_empty(locked));
}

TEST_F(PngFiles, WriteOntoADirectoryRemovesTheTemporaryFile) {
  // The temporary file is written completely; only rename() fails (EISDIR).
  // This is the path where write_png must clean up a file it created.
  fs::create_directory(dir_ / "target");
  const std::string file = path("target");
  const std::string message = write_error(file, random_image(2, 2, 3));
  EXPECT_NE(message.find("cannot rename"), std::string::npos) << message;
  expect_one_line_naming(message, file);
  EXPECT_EQ(listing(dir_), std::vector<std::string>{"target"});
  EXPECT_TRUE(fs::is_empty(dir_ / "target"));
}

TEST_F(PngFiles, BadArgumentsThrowInvalidArgumentAndWriteNothing) {
  const Image ok = random_image(2, 2, 4);
  EXPECT_THROW(gllab::write_png(path("a.png"), ok, -1), std::invalid_argument);
  EXPECT_THROW(gllab::write_png(path("a.png"), ok, 10), std::invalid_argument);
  EXPECT_THROW(gllab::write_png(path("a.png"), Image{}), std::invalid_argument);  // 0x0
  Image short_rgba = ok;
  short_rgba.rgba.pop_back();  // 15 bytes for a 2x2 image
  EXPECT_THROW(gllab::write_png(path("a.png"), short_rgba), std::invalid_argument);
  EXPECT_TRUE(listing(dir_).empty());
}

// A FIFO (like /dev/null or /dev/stdout, not a regular file) is written into,
// never replaced: renaming a temporary file over it would replace the device.
TEST_F(PngFiles, WriteIntoAFifoWritesThroughItAndKeepsIt) {
  const std::string fifo = path("pipe.png");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  std::string received;
  std::thread reader([&] {
    std::ifstream in(fifo, std::ios::binary);
    received.assign(std::istreambuf_iterator<char>(in), {});
  });
  const gllab::Image img = random_image(3, 2, 7);
  gllab::write_png(fifo, img);
  reader.join();
  EXPECT_TRUE(fs::is_fifo(fifo)) << "write_png replaced the FIFO with a file";
  EXPECT_EQ(listing(dir_), std::vector<std::string>{"pipe.png"});
  ASSERT_GT(received.size(), 8u);
  EXPECT_EQ(received.substr(1, 3), "PNG");
}

TEST_F(PngFiles, WriteThroughASymlinkReplacesTheFileItNames) {
  const gllab::Image first = random_image(2, 2, 1), second = random_image(2, 2, 2);
  gllab::write_png(path("real.png"), first);
  fs::create_symlink(path("real.png"), path("link.png"));
  gllab::write_png(path("link.png"), second);
  EXPECT_TRUE(fs::is_symlink(path("link.png")));
  EXPECT_EQ(gllab::read_png(path("real.png")).rgba, second.rgba);
}

}  // namespace
