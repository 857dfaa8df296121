// common/files/files.cpp — checked input and output (files.h).
#include "files/files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace gllab::files {

namespace {

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string size_text(std::uintmax_t bytes) { return std::to_string(bytes) + " bytes"; }

// Reads fd to the end, at most max_bytes + 1 bytes (one more tells "too large").
std::string read_all(int fd, std::uintmax_t max_bytes, const std::string& name) {
  std::string out;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got < 0) {
      if (errno == EINTR) continue;
      throw FileError(name + ": cannot read (" + std::strerror(errno) + ")");
    }
    if (got == 0) return out;
    out.append(buffer, static_cast<std::size_t>(got));
    if (out.size() > max_bytes)
      throw FileError(name + ": larger than the limit of " + size_text(max_bytes));
  }
}

struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string not_regular_reason(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return "";
  return std::string("is ") + kind_of(st.st_mode) + ", not a regular file";
}

std::string read_input(const std::string& path, std::uintmax_t max_bytes, bool allow_stdin) {
  if (path == "-" && allow_stdin) return read_all(STDIN_FILENO, max_bytes, "standard input");
  if (path.empty()) throw FileError("an empty file name");
  Fd file;
  file.fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (file.fd < 0) throw FileError(path + ": cannot open (" + std::strerror(errno) + ")");
  struct stat st {};
  if (::fstat(file.fd, &st) != 0) throw FileError(path + ": cannot stat (" + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode)) throw FileError(path + ": is " + kind_of(st.st_mode) + ", not a regular file");
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes)
    throw FileError(path + ": " + size_text(static_cast<std::uintmax_t>(st.st_size)) +
                    ", larger than the limit of " + size_text(max_bytes));
  // A regular file never blocks; clear O_NONBLOCK all the same.
  ::fcntl(file.fd, F_SETFL, ::fcntl(file.fd, F_GETFL) & ~O_NONBLOCK);
  return read_all(file.fd, max_bytes, path);
}

void finish_stdout() {
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int err = errno;
  if (!flushed || std::ferror(stdout))
    throw FileError(std::string("standard output: write failed (") +
                    (err ? std::strerror(err) : "an earlier write failed") + ")");
}

}  // namespace gllab::files
