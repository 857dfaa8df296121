// tests/fuzz/fuzz_grading.cpp — what labgrade reads (tools/grading.h): reference PNGs,
// the PAM frames a renderer writes to it, and reference_images/MANIFEST.
//
// The input's first bytes pick the reader, so one corpus holds all three and a
// mutation can move between them:
//   "\x89PNG"  decode_png (read_png's decoder), then the image as a reference: PAM
//              encode and decode give it back, compare_images of it with itself finds
//              no difference (images of up to 2^12 pixels; larger ones are only decoded);
//   "P7"       decode_pam, and decode_pam_at over the bytes as a stream of frames
//              (a renderer's --views ... --out -), at most 16 frames;
//   otherwise  MANIFEST: written to a temporary folder and read with read_manifest;
//              what it accepts is judged with: both profiles' tolerances compare an
//              8 x 8 image with a copy that differs in 3 pixels.
// A refusal must be the documented exception (ImageError, grading::UsageError; the
// comparison's std::invalid_argument) with a one-line message; nothing may crash.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <typeinfo>

#include "fuzz_common.h"
#include "grading.h"
#include "image/compare.h"
#include "image/image.h"
#include "image/pam.h"

namespace {

using namespace gllab;
using gllab::fuzz::check;
using gllab::fuzz::fail;

constexpr long long kMaxComparedPixels = 1 << 12;
constexpr int kMaxFrames = 16;

bool same(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.rgba == b.rgba;
}

void use_image(const Image& img, const char* what) {
  check(img.width > 0 && img.height > 0 &&
            img.rgba.size() == static_cast<std::size_t>(img.width) * img.height * 4,
        std::string(what) + ": malformed image");
  if (static_cast<long long>(img.width) * img.height > kMaxComparedPixels) return;
  try {
    check(same(decode_pam(encode_pam(img), "round_trip"), img), std::string(what) + ": PAM round trip differs");
    const Comparison c = compare_images(img, img, 0, 1, 1);
    check(c.differing_pixels == 0 && c.mismatched_pixels == 0, std::string(what) + ": image differs from itself");
  } catch (const std::exception& e) {
    fail(std::string(what) + ": a decoded image is refused: " + typeid(e).name() + ": " + e.what());
  }
}

void png(const std::uint8_t* data, std::size_t size) {
  try {
    use_image(decode_png(data, size, "fuzz.png"), "decode_png");
  } catch (const ImageError& e) {
    gllab::fuzz::check_one_line(e, "decode_png");
  } catch (const std::exception& e) {
    fail(std::string("decode_png threw ") + typeid(e).name() + " (not ImageError): " + e.what());
  }
}

void pam(const std::string& bytes) {
  try {
    use_image(decode_pam(bytes, "fuzz.pam"), "decode_pam");
  } catch (const ImageError& e) {
    gllab::fuzz::check_one_line(e, "decode_pam");
  } catch (const std::exception& e) {
    fail(std::string("decode_pam threw ") + typeid(e).name() + " (not ImageError): " + e.what());
  }
  std::size_t at = 0;
  try {
    for (int frame = 0; frame < kMaxFrames && at < bytes.size(); ++frame) {
      const std::size_t before = at;
      use_image(decode_pam_at(bytes, at, "fuzz.pam"), "decode_pam_at");
      check(at > before && at <= bytes.size(), "decode_pam_at: position did not advance within the bytes");
    }
  } catch (const ImageError& e) {
    gllab::fuzz::check_one_line(e, "decode_pam_at");
  } catch (const std::exception& e) {
    fail(std::string("decode_pam_at threw ") + typeid(e).name() + " (not ImageError): " + e.what());
  }
}

/// A folder of its own for the MANIFEST, one per process.
const std::filesystem::path& refs() {
  static const std::filesystem::path dir = [] {
    char name[] = "/tmp/gllab_fuzz_grading_XXXXXX";
    check(mkdtemp(name) != nullptr, "cannot make a temporary folder");
    return std::filesystem::path(name);
  }();
  static const struct Remove {
    ~Remove() {
      std::error_code ignored;
      std::filesystem::remove_all(dir, ignored);
    }
  } remove_at_exit;
  return dir;
}

void judge_with(const Tolerance& t) {
  Image a(8, 8);
  for (std::size_t i = 0; i < a.rgba.size(); ++i) a.rgba[i] = static_cast<std::uint8_t>(i * 37);
  Image b = a;
  b.rgba[0] ^= 0x80;
  b.rgba[4 * 9 + 1] ^= 0x10;
  b.rgba[4 * 63 + 2] ^= 0x01;
  try {
    const Comparison c = compare_images(a, b, t);
    (void)c.score(t);
    (void)c.passes(t);
  } catch (const std::invalid_argument& e) {
    gllab::fuzz::check_one_line(e, "compare_images with the MANIFEST's tolerance");
  } catch (const std::exception& e) {
    fail(std::string("compare_images threw ") + typeid(e).name() + ": " + e.what());
  }
}

void manifest(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = refs() / "MANIFEST";
  std::FILE* f = std::fopen(file.c_str(), "wb");
  check(f != nullptr, "cannot write " + file.string());
  check(std::fwrite(data, 1, size, f) == size, "cannot write " + file.string());
  std::fclose(f);
  try {
    const grading::Manifest m = grading::read_manifest(refs());
    for (grading::Profile p : {grading::Profile::kBuild, grading::Profile::kImages})
      judge_with(grading::judgement(m, p).tolerance);
  } catch (const grading::UsageError& e) {
    gllab::fuzz::check_one_line(e, "read_manifest");
  } catch (const std::exception& e) {
    fail(std::string("read_manifest threw ") + typeid(e).name() + " (not UsageError): " + e.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  if (bytes.compare(0, 4, "\x89PNG") == 0) png(data, size);
  else if (bytes.compare(0, 2, "P7") == 0) pam(bytes);
  else manifest(data, size);
  return 0;
}
