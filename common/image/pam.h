// common/image · raw frames between programs (netpbm PAM, "P7")
// A grader compares many renders in memory: PNG's deflate costs a headless
// run more time than its drawing (docs/platform.md: ~13 ms per 512x512 frame at zlib
// level 6). So a headless program asked for `--out -` writes its frame to
// stdout as PAM, the simplest standard container for RGBA8 pixels (netpbm's
// P7: a text header, then the rows top-down), and the grader decodes it here.
//   P7\nWIDTH 512\nHEIGHT 512\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n<bytes>
#pragma once

#include <string>

#include "image/image.h"

namespace gllab {

/// The image as PAM bytes (RGB_ALPHA, 8 bits per sample).
std::string encode_pam(const Image& img);

/// Decodes what encode_pam wrote. Throws ImageError naming `source` and the
/// problem ("not a PAM", "truncated: 1048576 bytes expected, 1000 read", ...).
/// Only DEPTH 4, MAXVAL 255, TUPLTYPE RGB_ALPHA is accepted.
Image decode_pam(const std::string& bytes, const std::string& source);

/// One image of a stream of PAMs (a headless program's --views ... --out -),
/// starting at `at`, which moves past it. Throws ImageError as decode_pam,
/// "truncated" when the stream ends inside the image.
Image decode_pam_at(const std::string& bytes, std::size_t& at, const std::string& source);

}  // namespace gllab
