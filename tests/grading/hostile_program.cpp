// tests/grading/hostile_program.cpp — what a hostile student's program does,
// one mode per run, for sandbox_test.cpp. Each mode says on stdout or stderr
// what it did or why it could not, in one line, and exits 0 only when the
// hostile act succeeded.
//
//   hostile_program exists PATH        does PATH exist? (stat)
//   hostile_program read PATH          reads PATH, prints its bytes
//   hostile_program write PATH         creates or truncates PATH and writes a line
//   hostile_program connect IP PORT    opens a TCP connection
//   hostile_program fork-bomb          every process forks without end
//   hostile_program fill PATH          writes PATH without end
//   hostile_program spin               burns CPU without end
//   hostile_program sleep              sleeps without end, with a sleeping child
//   hostile_program allocate           allocates and touches memory without end
//   hostile_program flood              writes stdout without end
//   hostile_program env                prints its environment, one entry a line
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

extern char** environ;

namespace {

int fail(const std::string& what) {
  std::fprintf(stderr, "%s: %s\n", what.c_str(), std::strerror(errno));
  return 1;
}

int fork_bomb() {
  bool told = false;
  for (;;) {
    if (fork() < 0 && !told) {
      // Each process says once that a fork failed, then keeps trying.
      std::fprintf(stderr, "fork: %s\n", std::strerror(errno));
      told = true;
    }
  }
}

int fill(const char* path) {
  const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return fail(std::string("open ") + path);
  static char block[1 << 20];
  for (;;)
    if (write(fd, block, sizeof block) < 0) return fail(std::string("write ") + path);
}

int allocate() {
  std::vector<char*> blocks;
  for (;;) {
    // new throws std::bad_alloc at the limit: uncaught, it says so and aborts.
    char* block = new char[16 << 20];
    std::memset(block, 1, 16 << 20);
    blocks.push_back(block);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "exists" && argc == 3) {
    struct stat st {};
    if (stat(argv[2], &st) != 0) return fail(argv[2]);
    std::printf("%s exists\n", argv[2]);
    return 0;
  }
  if (mode == "read" && argc == 3) {
    FILE* f = std::fopen(argv[2], "rb");
    if (!f) return fail(std::string("open ") + argv[2]);
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;) std::fwrite(buffer, 1, n, stdout);
    std::fclose(f);
    return 0;
  }
  if (mode == "write" && argc == 3) {
    const int fd = open(argv[2], O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) return fail(std::string("open ") + argv[2]);
    const char line[] = "written by a hostile program\n";
    if (write(fd, line, sizeof line - 1) < 0) return fail(std::string("write ") + argv[2]);
    close(fd);
    std::printf("wrote %s\n", argv[2]);
    return 0;
  }
  if (mode == "connect" && argc == 4) {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) return fail("socket");
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(std::atoi(argv[3])));
    if (inet_pton(AF_INET, argv[2], &address.sin_addr) != 1) return fail(std::string("address ") + argv[2]);
    if (connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0)
      return fail(std::string("connect ") + argv[2] + ":" + argv[3]);
    std::printf("connected to %s:%s\n", argv[2], argv[3]);
    return 0;
  }
  if (mode == "fork-bomb") return fork_bomb();
  if (mode == "fill" && argc == 3) return fill(argv[2]);
  if (mode == "spin") {
    for (volatile unsigned long n = 0;; n = n + 1) {
    }
  }
  if (mode == "sleep") {
    if (fork() < 0) return fail("fork");
    for (;;) pause();
  }
  if (mode == "allocate") return allocate();
  if (mode == "flood") {
    static const std::string line(1023, 'x');
    for (;;) std::puts(line.c_str());
  }
  if (mode == "env") {
    for (char** e = environ; *e; ++e) std::puts(*e);
    return 0;
  }
  std::fprintf(stderr, "usage: hostile_program MODE [ARGS] (modes: see the file's header)\n");
  return 2;
}
