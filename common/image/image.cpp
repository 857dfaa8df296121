// common/image · an RGBA8 image and PNG files (see image.h)
//
// How libpng reports errors, and why this file is shaped the way it is:
// libpng calls an error function that must not return. The classic way out is a
// longjmp back to a setjmp placed before the libpng calls. A longjmp skips C++
// destructors, so the functions that call setjmp (decode_header, decode_rows,
// encode) hold only plain data and pointers. Every object with a destructor (the
// file bytes, the Image, the row table, the cleanup guards) lives in the frame of
// read_png or write_png, which the jump never crosses: it lands in the setjmp
// function, which returns false, and read_png/write_png throw a normal exception.
#include "image/image.h"

#include "files/files.h"

#include <png.h>
#include <unistd.h>  // getpid

#include <cassert>
#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

namespace gllab {
namespace {

constexpr std::size_t kMessageSize = 256;      // room for one libpng message
constexpr int kChannels = 4;                   // R, G, B, A
// Refuse more than 2^28 pixels (1 GiB of RGBA). A corrupt header may claim up to
// libpng's own limit of 1,000,000 x 1,000,000, and we would try to allocate 4 TB.
constexpr std::uint64_t kMaxPixels = std::uint64_t{1} << 28;

// 'path' for an error message. Control characters become '?' so that the
// message stays on one line whatever the file is called.
std::string quote(const std::string& path) {
  std::string out = "'";
  for (char c : path) {
    const bool control = static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
    out += control ? '?' : c;
  }
  return out + "'";
}

std::string size_text(long long w, long long h) {
  return std::to_string(w) + "x" + std::to_string(h);
}

// An Image built by hand may have an rgba vector that doesn't match its size.
void check_image(const Image& img, const std::string& where) {
  if (img.width <= 0 || img.height <= 0)
    throw std::invalid_argument(where + "image is " + size_text(img.width, img.height) +
                                " (width and height must be > 0)");
  const std::size_t expected = std::size_t(img.width) * std::size_t(img.height) * kChannels;
  if (img.rgba.size() != expected)
    throw std::invalid_argument(where + "image is " + size_text(img.width, img.height) +
                                " but rgba has " + std::to_string(img.rgba.size()) +
                                " bytes (expected " + std::to_string(expected) + ")");
}

// --- libpng callbacks shared by reading and writing ------------------------
// The error pointer given to libpng is a char[kMessageSize] that receives the
// message before we jump back to setjmp.
[[noreturn]] void on_png_error(png_structp png, png_const_charp msg) {
  char* message = static_cast<char*>(png_get_error_ptr(png));
  std::snprintf(message, kMessageSize, "%s", msg != nullptr ? msg : "unknown error");
  for (char* c = message; *c != '\0'; ++c)
    if (static_cast<unsigned char>(*c) < 0x20) *c = ' ';  // keep it one line
  png_longjmp(png, 1);
}

// Warnings (an odd ancillary chunk, an imperfect colour profile) don't change
// the pixels we return, so they are not printed.
void on_png_warning(png_structp, png_const_charp) {}

// --- Reading ---------------------------------------------------------------
// Plain data only: libpng may longjmp across code that uses it.
struct PngDecoder {
  png_structp png = nullptr;
  png_infop info = nullptr;
  const std::uint8_t* data = nullptr;  // the whole file, already in memory
  std::size_t size = 0;
  std::size_t offset = 0;              // next byte libpng will read
  char message[kMessageSize] = {};     // libpng's error text
};

// Frees libpng's structures on every way out of read_png.
struct DecoderCleanup {
  PngDecoder& d;
  ~DecoderCleanup() { png_destroy_read_struct(&d.png, &d.info, nullptr); }
};

// libpng asks for `count` bytes at a time; a truncated file runs out here.
void read_from_memory(png_structp png, png_bytep out, std::size_t count) {
  auto* d = static_cast<PngDecoder*>(png_get_io_ptr(png));
  if (count > d->size - d->offset) {
    char text[kMessageSize];
    std::snprintf(text, sizeof text, "file is truncated: it ends after %zu bytes", d->size);
    png_error(png, text);  // on_png_error copies the text before jumping
  }
  std::memcpy(out, d->data + d->offset, count);
  d->offset += count;
}

// Reads the chunks before the image data and sets up the expansion to RGBA8.
// Returns false (with d->message set) when libpng reports an error.
bool decode_header(PngDecoder* d) {
  if (setjmp(png_jmpbuf(d->png))) return false;  // libpng jumped here: an error
  png_read_info(d->png, d->info);

  // Whatever the file holds, ask libpng for 8-bit R,G,B,A:
  png_set_expand(d->png);      // palette -> RGB, grey of 1/2/4 bits -> 8 bits, tRNS -> alpha
  png_set_scale_16(d->png);    // 16 -> 8 bits as round(v*255/65535)
  png_set_gray_to_rgb(d->png);  // grey -> R = G = B
  png_set_add_alpha(d->png, 0xff, PNG_FILLER_AFTER);  // no alpha channel -> opaque
  png_set_interlace_handling(d->png);  // Adam7 files: png_read_image runs all 7 passes
  png_read_update_info(d->png, d->info);

  // Can this happen? Not with the settings above; checked so a surprise is loud.
  if (png_get_bit_depth(d->png, d->info) != 8 || png_get_channels(d->png, d->info) != kChannels)
    png_error(d->png, "cannot expand this PNG to RGBA8");
  return true;
}

// Decodes all rows into `rows` (one pointer per row, top-down) and checks the
// chunks after the image data up to IEND.
bool decode_rows(PngDecoder* d, png_bytepp rows) {
  if (setjmp(png_jmpbuf(d->png))) return false;
  png_read_image(d->png, rows);
  png_read_end(d->png, nullptr);
  return true;
}

// The whole file, so that libpng decodes from memory and a truncated file is
// simply one that runs out of bytes.
std::vector<std::uint8_t> read_file(const std::string& path, const std::string& where) {
  // A regular file of at most files::kMaxInputBytes (a FIFO would block, /dev/zero never ends).
  try {
    const std::string bytes = files::read_input(path);
    return std::vector<std::uint8_t>(bytes.begin(), bytes.end());
  } catch (const files::FileError& e) {
    const std::string what = e.what(), prefix = path + ": ";
    const std::string reason = what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
    if (reason == "cannot open (No such file or directory)") throw ImageError(where + "no such file");
    throw ImageError(where + reason);
  }
}

// --- Writing ---------------------------------------------------------------
// Plain data only, like PngDecoder.
struct PngEncoder {
  png_structp png = nullptr;
  png_infop info = nullptr;
  std::FILE* file = nullptr;
  int write_errno = 0;              // set when fwrite fails (e.g. ENOSPC)
  char message[kMessageSize] = {};  // libpng's error text
};

struct EncoderCleanup {
  PngEncoder& e;
  ~EncoderCleanup() { png_destroy_write_struct(&e.png, &e.info); }
};

// The temporary file: closed and removed on every way out except success.
struct TemporaryFile {
  std::string path;
  std::FILE* file = nullptr;
  bool created = false;
  bool keep = false;
  ~TemporaryFile() {
    if (file != nullptr) std::fclose(file);
    if (created && !keep) std::remove(path.c_str());
  }
};

void write_to_file(png_structp png, png_bytep data, std::size_t count) {
  auto* e = static_cast<PngEncoder*>(png_get_io_ptr(png));
  if (std::fwrite(data, 1, count, e->file) != count) {
    e->write_errno = errno != 0 ? errno : EIO;
    png_error(png, "write failed");
  }
}

void flush_file(png_structp png) {
  auto* e = static_cast<PngEncoder*>(png_get_io_ptr(png));
  std::fflush(e->file);  // a failure shows up in ferror/fclose, checked by write_png
}

// Row by row, straight from the Image: no row table needed.
void write_rows(png_structp png, const Image& img) {
  for (int y = 0; y < img.height; ++y) png_write_row(png, img.pixel(0, y));
}

// Writes the whole PNG stream. Returns false (with e->message set) on an error.
bool encode(PngEncoder* e, const Image* img, int zlib_level) {
  if (setjmp(png_jmpbuf(e->png))) return false;
  png_set_write_fn(e->png, e, write_to_file, flush_file);
  png_set_compression_level(e->png, zlib_level);
  png_set_IHDR(e->png, e->info, png_uint_32(img->width), png_uint_32(img->height),
               8, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(e->png, e->info);
  write_rows(e->png, *img);
  png_write_end(e->png, e->info);
  return true;
}

}  // namespace

// --- Image -------------------------------------------------------------------
Image::Image(int w, int h) : width(w), height(h) {
  if (w <= 0 || h <= 0)
    throw std::invalid_argument("Image: size " + size_text(w, h) +
                                " (width and height must be > 0)");
  rgba.assign(std::size_t(w) * std::size_t(h) * kChannels, 0);
}

std::uint8_t* Image::pixel(int x, int y) {
  assert(x >= 0 && x < width && y >= 0 && y < height);
  return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * kChannels];
}

const std::uint8_t* Image::pixel(int x, int y) const {
  assert(x >= 0 && x < width && y >= 0 && y < height);
  return &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * kChannels];
}

Image image_from_bottom_up(const std::uint8_t* rgba, int width, int height) {
  Image img(width, height);  // throws for a bad size
  if (rgba == nullptr)
    throw std::invalid_argument("image_from_bottom_up: rgba is null for a " +
                                size_text(width, height) + " image");
  const std::size_t row_bytes = std::size_t(width) * kChannels;
  for (int y = 0; y < height; ++y) {
    // OpenGL's row 0 is the bottom row, so it becomes the image's last row.
    const std::uint8_t* source_row = rgba + std::size_t(y) * row_bytes;
    std::memcpy(img.pixel(0, height - 1 - y), source_row, row_bytes);
  }
  return img;
}

// --- read_png, decode_png ---------------------------------------------------------
Image read_png(const std::string& path) {
  const std::vector<std::uint8_t> bytes = read_file(path, "read_png: " + quote(path) + ": ");
  return decode_png(bytes.data(), bytes.size(), "read_png: " + quote(path));
}

Image decode_png(const std::uint8_t* data, std::size_t size, const std::string& name) {
  const std::string where = name + ": ";
  // Every PNG starts with the same 8-byte signature (\x89PNG\r\n\x1a\n).
  constexpr std::size_t kSignatureSize = 8;
  if (data == nullptr || size < kSignatureSize || png_sig_cmp(data, 0, kSignatureSize) != 0)
    throw ImageError(where + "not a PNG file");

  PngDecoder d;
  d.data = data;
  d.size = size;
  d.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, d.message, on_png_error, on_png_warning);
  if (d.png == nullptr) throw ImageError(where + "libpng: cannot create a read struct");
  DecoderCleanup cleanup{d};
  d.info = png_create_info_struct(d.png);
  if (d.info == nullptr) throw ImageError(where + "libpng: cannot create an info struct");
  png_set_read_fn(d.png, &d, read_from_memory);

  const std::string corrupt = where + "corrupt PNG (libpng: ";
  if (!decode_header(&d)) throw ImageError(corrupt + d.message + ")");

  const png_uint_32 width = png_get_image_width(d.png, d.info);
  const png_uint_32 height = png_get_image_height(d.png, d.info);
  if (std::uint64_t(width) * height > kMaxPixels)
    throw ImageError(where + "image is too large: " + size_text(width, height) +
                     " (more than " + std::to_string(kMaxPixels) + " pixels)");

  // libpng fills the Image in place through one pointer per row.
  Image img(static_cast<int>(width), static_cast<int>(height));
  std::vector<png_bytep> rows(height);
  for (png_uint_32 y = 0; y < height; ++y) rows[y] = img.pixel(0, int(y));
  if (!decode_rows(&d, rows.data())) throw ImageError(corrupt + d.message + ")");
  return img;
}

// --- write_png -------------------------------------------------------------------
void write_png(const std::string& path, const Image& img, int zlib_level) {
  const std::string where = "write_png: " + quote(path) + ": ";
  if (zlib_level < 0 || zlib_level > 9)
    throw std::invalid_argument(where + "zlib_level " + std::to_string(zlib_level) +
                                " is outside 0..9");
  check_image(img, where);

  // Write next to the target (same directory, so rename() is atomic), then
  // rename; through a symlink, next to the file it names. A path that names
  // no regular file (/dev/null, a FIFO, /dev/stdout) is written in place:
  // a rename would replace the device itself.
  std::error_code ec;
  std::string target = path;
  if (std::filesystem::exists(path, ec)) target = std::filesystem::canonical(path, ec).string();
  if (ec) target = path;
  const bool in_place = std::filesystem::exists(target, ec) && !std::filesystem::is_regular_file(target, ec) &&
                        !std::filesystem::is_directory(target, ec);
  TemporaryFile tmp;
  tmp.path = in_place ? target : target + ".tmp." + std::to_string(::getpid());
  tmp.file = std::fopen(tmp.path.c_str(), "wb");
  if (tmp.file == nullptr) {
    const int err = errno;
    throw ImageError(where + "cannot open for writing: " + std::strerror(err));
  }
  tmp.created = !in_place;

  PngEncoder e;
  e.file = tmp.file;
  e.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, e.message, on_png_error, on_png_warning);
  if (e.png == nullptr) throw ImageError(where + "libpng: cannot create a write struct");
  EncoderCleanup cleanup{e};
  e.info = png_create_info_struct(e.png);
  if (e.info == nullptr) throw ImageError(where + "libpng: cannot create an info struct");

  if (!encode(&e, &img, zlib_level)) {
    if (e.write_errno != 0)
      throw ImageError(where + "write failed: " + std::strerror(e.write_errno));
    throw ImageError(where + "libpng: " + e.message);
  }

  // Buffered data can still fail to reach the disk (ENOSPC, EIO): check the
  // flush and the close before the file takes the real name.
  const bool flushed = std::fflush(tmp.file) == 0 && std::ferror(tmp.file) == 0;
  int err = errno;
  const bool closed = std::fclose(tmp.file) == 0;
  if (!closed) err = errno;
  tmp.file = nullptr;
  if (!flushed || !closed) throw ImageError(where + "write failed: " + std::strerror(err));

  if (in_place) return;
  if (std::rename(tmp.path.c_str(), target.c_str()) != 0) {
    err = errno;
    throw ImageError(where + "cannot rename " + quote(tmp.path) + " into place: " +
                     std::strerror(err));
  }
  tmp.keep = true;
}

}  // namespace gllab
