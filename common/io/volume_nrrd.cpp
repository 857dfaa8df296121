// common/io/volume_nrrd.cpp — see volume_nrrd.h. Teem does the parsing and
// the encodings; this file checks that what it read is a volume Grid3 can
// hold, and turns biff's error stack into one line.
#include "io/volume_nrrd.h"

#include "files/files.h"

#include <teem/nrrd.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/spline_json.h"

namespace gllab::io {

namespace {

struct NrrdDeleter {
  void operator()(Nrrd* n) const { nrrdNuke(n); }
};
using NrrdPtr = std::unique_ptr<Nrrd, NrrdDeleter>;

/// nrrdNix leaves the data alone (write_nrrd wraps memory it does not own).
struct NrrdNixer {
  void operator()(Nrrd* n) const { nrrdNix(n); }
};
struct IoDeleter {
  void operator()(NrrdIoState* s) const { nrrdIoStateNix(s); }
};

/// Teem's error stack ("[nrrd] nrrdLoad: trouble reading ...\n[nrrd]
/// nrrdRead: trouble\n...\n[nrrd] _nrrdEncodingRaw_read: fread got only 2
/// 4-sized things, not 8") as one line: its innermost (last) message, which
/// says what is wrong, without the "[nrrd] function: " prefix.
std::string teem_error() {
  char* raw = biffGetDone(NRRD);
  std::string all = raw ? raw : "";
  std::free(raw);
  std::string last;
  std::size_t start = 0;
  while (start < all.size()) {
    std::size_t end = all.find('\n', start);
    if (end == std::string::npos) end = all.size();
    std::string line = all.substr(start, end - start);
    if (line.compare(0, 7, "[nrrd] ") == 0) line.erase(0, 7);
    // "function: message" or a bare "function:" (a line that only says where).
    const std::size_t colon = line.find(':');
    if (colon != std::string::npos &&
        line.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") ==
            colon)
      line.erase(0, line.find_first_not_of(' ', colon + 1) == std::string::npos
                        ? line.size()
                        : line.find_first_not_of(' ', colon + 1));
    if (!line.empty()) last = line;
    start = end + 1;
  }
  return last.empty() ? "Teem's nrrd library failed (no message)" : last;
}

std::string number_text(double x) { return shortest_text(x); }

std::string vector_text(const double* v) {
  return "(" + number_text(v[0]) + ", " + number_text(v[1]) + ", " + number_text(v[2]) + ")";
}

void check_grid(const field::Grid3& g, const std::string& path) {
  if (g.nx < 2 || g.ny < 2 || g.nz < 2)
    throw std::invalid_argument(path + ": grid " + std::to_string(g.nx) + " x " +
                                std::to_string(g.ny) + " x " + std::to_string(g.nz) +
                                " (need at least 2 points per axis)");
  const std::size_t count = std::size_t(g.nx) * g.ny * g.nz;
  if (g.values.size() != count)
    throw std::invalid_argument(path + ": " + std::to_string(g.values.size()) +
                                " values for a grid of " + std::to_string(count));
  for (double h : {g.spacing.x, g.spacing.y, g.spacing.z})
    if (!(h > 0) || !std::isfinite(h))
      throw std::invalid_argument(path + ": spacing " + number_text(h) +
                                  " (must be positive and finite)");
  for (double o : {g.origin.x, g.origin.y, g.origin.z})
    if (!std::isfinite(o))
      throw std::invalid_argument(path + ": origin " + number_text(o) + " (must be finite)");
}

/// Writes the wrapped nrrd to path: a temporary file beside it, then
/// rename() (write_text_atomically's rules: through a symlink the target is
/// replaced; a path that is no regular file is written in place).
void save(const Nrrd* nrrd, const std::string& path) {
  std::unique_ptr<NrrdIoState, IoDeleter> nio(nrrdIoStateNew());
  nio->encoding = nrrdEncodingRaw;
  nio->format = nrrdFormatNRRD;
  nio->detachedHeader = AIR_FALSE;

  std::error_code status;
  std::filesystem::path file = path;
  if (std::filesystem::exists(file, status)) file = std::filesystem::canonical(path, status);
  if (status) file = path;
  const bool in_place = std::filesystem::exists(file, status) &&
                        !std::filesystem::is_regular_file(file, status) &&
                        !std::filesystem::is_directory(file, status);
  const std::filesystem::path target =
      in_place ? file
               : file.parent_path() /
                     ("." + file.filename().string() + ".tmp-" + std::to_string(getpid()));
  auto remove_target = [&] {
    if (in_place) return;
    std::error_code ignored;
    std::filesystem::remove(target, ignored);
  };
  std::FILE* out = std::fopen(target.c_str(), "wb");
  if (!out) throw FileError(path, "", std::string("cannot write (") + std::strerror(errno) + ")");
  if (nrrdWrite(out, nrrd, nio.get())) {
    const std::string problem = teem_error();
    std::fclose(out);
    remove_target();
    throw FileError(path, "", "cannot write: " + problem);
  }
  const bool flushed = std::fflush(out) == 0 && !std::ferror(out);
  const int error = errno;
  if (std::fclose(out) != 0 || !flushed) {
    remove_target();
    throw FileError(path, "",
                    std::string("cannot write (") + std::strerror(flushed ? errno : error) + ")");
  }
  if (in_place) return;
  std::error_code ec;
  std::filesystem::rename(target, file, ec);
  if (ec) {
    remove_target();
    throw FileError(path, "", "cannot replace (" + ec.message() + ")");
  }
}

/// Wraps data (not copied, not owned) as a 3-D nrrd with the grid's geometry.
void write_wrapped(const field::Grid3& g, const std::string& path, void* data, int type,
                   const std::string& content, double old_min, double old_max) {
  std::unique_ptr<Nrrd, NrrdNixer> nrrd(nrrdNew());
  if (nrrdWrap_va(nrrd.get(), data, type, 3u, std::size_t(g.nx), std::size_t(g.ny),
                  std::size_t(g.nz)) ||
      nrrdSpaceDimensionSet(nrrd.get(), 3)) {
    throw FileError(path, "", "cannot write: " + teem_error());
  }
  const double origin[3] = {g.origin.x, g.origin.y, g.origin.z};
  nrrdSpaceOriginSet(nrrd.get(), origin);
  const double dx[3] = {g.spacing.x, 0, 0}, dy[3] = {0, g.spacing.y, 0},
               dz[3] = {0, 0, g.spacing.z};
  nrrdAxisInfoSet_va(nrrd.get(), nrrdAxisInfoSpaceDirection, dx, dy, dz);
  // The values are samples at the points (node-centred), as in Grid3.
  nrrdAxisInfoSet_va(nrrd.get(), nrrdAxisInfoCenter, nrrdCenterNode, nrrdCenterNode,
                     nrrdCenterNode);
  if (!content.empty()) nrrd->content = airStrdup(content.c_str());  // nrrdNix frees it
  if (std::isfinite(old_min)) nrrd->oldMin = old_min;
  if (std::isfinite(old_max)) nrrd->oldMax = old_max;
  save(nrrd.get(), path);
}

}  // namespace

field::Grid3 read_nrrd(const std::string& path) {
  {
    // A regular file only (a FIFO would block Teem's reader, /dev/zero never
    // ends); opened without blocking to find out (files/files.h).
    const std::string reason = files::not_regular_reason(path);
    if (!reason.empty()) throw FileError(path, "", reason);
    std::ifstream probe(path, std::ios::binary);
    if (!probe)
      throw FileError(path, "", std::string("cannot open (") + std::strerror(errno) + ")");
  }
  nrrdStateVerboseIO = 0;  // Teem's warnings would go to stderr

  // The header first (no data): a header that claims a huge volume is
  // refused before anything is allocated.
  NrrdPtr nrrd(nrrdNew());
  {
    std::unique_ptr<NrrdIoState, IoDeleter> nio(nrrdIoStateNew());
    nio->skipData = AIR_TRUE;
    if (nrrdLoad(nrrd.get(), path.c_str(), nio.get())) throw FileError(path, "", teem_error());
  }
  if (nrrd->dim != 3)
    throw FileError(path, "",
                    std::to_string(nrrd->dim) + (nrrd->dim == 1 ? " dimension" : " dimensions") +
                        ", need 3 (a volume x, y, z)");
  if (nrrd->type == nrrdTypeBlock)
    throw FileError(path, "", "type block (need a scalar type: uchar ... double)");
  const char* axis_names[3] = {"x", "y", "z"};
  std::size_t count = 1;
  for (unsigned a = 0; a < 3; ++a) {
    const std::size_t size = nrrd->axis[a].size;
    if (size < 2)
      throw FileError(path, "",
                      "axis " + std::to_string(a) + " (" + axis_names[a] + ") has " +
                          std::to_string(size) + " sample" + (size == 1 ? "" : "s") +
                          ", need at least 2");
    if (size > 4096)
      throw FileError(path, "",
                      "axis " + std::to_string(a) + " (" + axis_names[a] + ") has " +
                          std::to_string(size) + " samples (at most 4096)");
    count *= size;
  }
  constexpr std::size_t kMaxValues = std::size_t(1) << 30;  // 4 GB of floats
  if (count > kMaxValues)
    throw FileError(
        path, "", std::to_string(count) + " samples (at most " + std::to_string(kMaxValues) + ")");

  field::Grid3 g;
  g.nx = static_cast<int>(nrrd->axis[0].size);
  g.ny = static_cast<int>(nrrd->axis[1].size);
  g.nz = static_cast<int>(nrrd->axis[2].size);
  double spacing[3] = {1, 1, 1}, origin[3] = {0, 0, 0};
  if (nrrd->spaceDim > 0) {
    if (nrrd->spaceDim != 3)
      throw FileError(path, "", "space dimension " + std::to_string(nrrd->spaceDim) + " (need 3)");
    for (unsigned a = 0; a < 3; ++a) {
      const double* d = nrrd->axis[a].spaceDirection;
      for (unsigned c = 0; c < 3; ++c) {
        const bool ok = c == a ? (std::isfinite(d[c]) && d[c] > 0) : d[c] == 0;
        if (!ok)
          throw FileError(path, "",
                          "axis " + std::to_string(a) + ": space direction " + vector_text(d) +
                              " is not along +" + axis_names[a] +
                              " (only axis-aligned, positive directions are supported)");
      }
      spacing[a] = d[a];
      if (std::isfinite(nrrd->spaceOrigin[a])) origin[a] = nrrd->spaceOrigin[a];
    }
  } else {
    for (unsigned a = 0; a < 3; ++a) {
      const double h = nrrd->axis[a].spacing;
      if (std::isnan(h)) continue;  // "spacings: nan" or none: 1
      if (!(h > 0) || !std::isfinite(h))
        throw FileError(
            path, "",
            "axis " + std::to_string(a) + ": spacing " + number_text(h) + " (must be positive)");
      spacing[a] = h;
    }
  }
  g.spacing = {spacing[0], spacing[1], spacing[2]};
  g.origin = {origin[0], origin[1], origin[2]};

  // Now the data.
  nrrd.reset(nrrdNew());
  if (nrrdLoad(nrrd.get(), path.c_str(), nullptr)) throw FileError(path, "", teem_error());
  if (nrrd->dim != 3 || nrrdElementNumber(nrrd.get()) != count)
    throw FileError(path, "", "changed while being read");
  g.values.resize(count);
  double (*lookup)(const void*, size_t) = nrrdDLookup[nrrd->type];
  for (std::size_t i = 0; i < count; ++i) {
    const double v = lookup(nrrd->data, i);
    const float f = static_cast<float>(v);
    if (!std::isfinite(f)) {
      const std::size_t x = i % g.nx, y = (i / g.nx) % g.ny, z = i / (std::size_t(g.nx) * g.ny);
      throw FileError(path, "",
                      "value at (" + std::to_string(x) + ", " + std::to_string(y) + ", " +
                          std::to_string(z) + ") is " + number_text(v) +
                          (std::isfinite(v) ? " (beyond the float range)" : "") +
                          " (values must be finite)");
    }
    g.values[i] = f;
  }
  return g;
}

void write_nrrd(const field::Grid3& grid, const std::string& path, const std::string& content) {
  check_grid(grid, path);
  for (std::size_t i = 0; i < grid.values.size(); ++i)
    if (!std::isfinite(grid.values[i]))
      throw std::invalid_argument(path + ": value " + std::to_string(i) + " is " +
                                  number_text(grid.values[i]) + " (values must be finite)");
  // nrrdWrap_va takes a non-const pointer; writing only reads it.
  write_wrapped(grid, path, const_cast<float*>(grid.values.data()), nrrdTypeFloat, content,
                std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
}

void write_nrrd_uint8(const field::Grid3& grid, const std::string& path, double lo, double hi,
                      const std::string& content) {
  check_grid(grid, path);
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    throw std::invalid_argument(path + ": quantisation range [" + number_text(lo) + ", " +
                                number_text(hi) + "] (need finite lo < hi)");
  std::vector<unsigned char> bytes(grid.values.size());
  const double scale = 255 / (hi - lo);
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const double v = grid.values[i];
    if (!std::isfinite(v))
      throw std::invalid_argument(path + ": value " + std::to_string(i) + " is " + number_text(v) +
                                  " (values must be finite)");
    const double q = std::round((v - lo) * scale);
    bytes[i] = static_cast<unsigned char>(q < 0 ? 0 : q > 255 ? 255 : q);
  }
  write_wrapped(grid, path, bytes.data(), nrrdTypeUChar, content, lo, hi);
}

}  // namespace gllab::io
