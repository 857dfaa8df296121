// common/image · an RGBA8 image and PNG files
// The headless runner reads the framebuffer with glReadPixels, turns it into an
// Image and writes it as PNG; the tests read reference PNGs back and compare them
// (see compare.h). Nothing here touches OpenGL.
//
// Errors are loud: every failure throws with a one-line message that names the
// file and the reason, e.g. "read_png: 'ref/01.png': not a PNG file".
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace gllab {

/// An 8-bit RGBA image. Pixel (0,0) is the top-left corner; rows run top-down,
/// the order PNG files and image viewers use.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width*height*4 bytes, rows top-down

  Image() = default;
  /// A zero-filled (transparent black) image. Throws std::invalid_argument
  /// naming the values when w <= 0 or h <= 0.
  Image(int w, int h);

  /// The 4 bytes R,G,B,A of pixel (x,y): &rgba[(y*width+x)*4]. Not range-checked
  /// in release builds (an assert catches mistakes in debug builds).
  std::uint8_t* pixel(int x, int y);
  const std::uint8_t* pixel(int x, int y) const;
};

/// A file could not be read or written, or two images can't be compared.
class ImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Rows of a glReadPixels buffer are bottom-up (OpenGL's origin is the lower-left
/// corner): this builds a top-down Image from one. `rgba` holds width*height*4 bytes
/// read with GL_RGBA, GL_UNSIGNED_BYTE and GL_PACK_ALIGNMENT 4 or less
/// (RGBA rows are always a multiple of 4 bytes, so no padding is possible).
Image image_from_bottom_up(const std::uint8_t* rgba, int width, int height);

/// Reads a PNG of any colour type and bit depth and expands it to RGBA8:
/// grey -> R=G=B, palette -> its colours, tRNS -> alpha, no alpha -> 0xff,
/// 16-bit -> 8-bit rounded (round(v*255/65535)), low bit depths scaled up
/// (a 4-bit 5 becomes 5*17 = 85). Samples are taken as stored: no gamma correction.
/// Errors throw ImageError:
///   "read_png: 'x.png': no such file"
///   "read_png: 'x.png': not a PNG file"
///   "read_png: 'x.png': corrupt PNG (libpng: <libpng's message>)"
///   "read_png: 'x.png': is a FIFO, not a regular file" (only regular files
///   of at most files::kMaxInputBytes are read: files/files.h)
Image read_png(const std::string& path);

/// The same for a PNG already in memory (`size` bytes at `data`: a picture
/// compiled into a program). Errors as read_png's, with `name` in place of
/// "read_png: 'x.png'".
Image decode_png(const std::uint8_t* data, std::size_t size, const std::string& name);

/// Writes an 8-bit RGBA PNG. The write is atomic: the data goes to
/// "<path>.tmp.<pid>", which is renamed to `path` only when complete, so a failed
/// write never leaves a half-written file at `path` (nor the temporary file).
/// zlib_level 0 (store) .. 9 (smallest); the pixels are identical at every level.
/// I/O errors throw ImageError, e.g.
///   "write_png: 'dir/x.png': cannot open for writing: Permission denied".
/// A malformed Image or a zlib_level outside 0..9 throws std::invalid_argument.
void write_png(const std::string& path, const Image& img, int zlib_level = 6);

}  // namespace gllab
