// common/files/files.h — reading the files a user names and writing what a
// program prints, with the checks every tool needs:
//   - an input must be a regular file (or "-", standard input, where a tool
//     allows it): a FIFO would block forever and /dev/zero never ends;
//   - an input has a size limit, checked before it is read;
//   - standard output is flushed and checked at the end: a full disk or a
//     closed pipe is an error, not a silent success.
// Depends on the standard library and POSIX only: every other module may use it.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace gllab::files {

/// The largest input any tool reads: 64 MiB. The largest real input is far
/// below it (examples/ct_phantom.nrrd, 111 KB; the largest reference PNG 129 KB).
inline constexpr std::uintmax_t kMaxInputBytes = std::uintmax_t{64} << 20;

/// What a failed read or write throws: one line naming the file and the reason,
/// "examples/x.json: is a FIFO, not a regular file".
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The bytes of `path`, which must be a regular file of at most max_bytes, or
/// "-" for standard input when allow_stdin (then read up to max_bytes + 1 to
/// tell a too-long input). Opens without blocking (O_NONBLOCK), so a FIFO is
/// refused instead of waited on. Throws FileError: no such file, a directory,
/// a FIFO, a device, a socket, too large (its size and the limit), a read error.
std::string read_input(const std::string& path, std::uintmax_t max_bytes = kMaxInputBytes,
                       bool allow_stdin = false);

/// "is a directory", "is a FIFO", "is a character device", ... for a path that
/// exists and is not a regular file; "" for a regular file or no file at all.
std::string not_regular_reason(const std::string& path);

/// Flushes standard output and throws FileError("standard output: write failed
/// (No space left on device)") when any write to it failed. Call it before a
/// program exits 0 after printing.
void finish_stdout();

}  // namespace gllab::files
