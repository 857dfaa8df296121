// tools/sandbox.h — run a student's program (a build, a lab render) in a
// bubblewrap sandbox, with limits on its time, memory, files and processes.
//
// An instructor grades a class by building and running every student's code.
// Without a sandbox that code runs with the instructor's rights: it can read
// the other submissions and the instructor's files, write anywhere, open the
// network and never end. run_sandboxed() runs it under bwrap (the Debian
// package bubblewrap; measured with 0.8.0 on Debian 12, kernel 6.18).
//
// What the program sees:
// - /usr read-only, and /bin, /sbin, /lib, /lib64 as the host has them
//   (symbolic links into /usr on a merged-/usr system, else read-only binds).
// - Of /etc only what the compiler, cmake and the dynamic linker read:
//   ld.so.cache, ld.so.conf, ld.so.conf.d and alternatives (c++ and cc are
//   links through /etc/alternatives). No passwd or group: the host's account
//   names stay on the host, and getpwuid() finds no entry. A lab render needs
//   nothing of /etc: Mesa's EGL vendor file and llvmpipe are in /usr.
// - A new /proc and a minimal /dev (null, zero, random, tty, ...), /dev read-only.
// - Its own /tmp (a tmpfs of kSandboxTmpBytes) and /dev/shm (kSandboxShmBytes):
//   the host's /tmp is not visible and nothing written there reaches it.
// - The folders the caller binds: `read_only` and `writable` at their own
//   paths, `mounts` at the path given, `hidden` covered by an empty folder.
//   Nothing else: not /root, /home, /work, nor another student's folder. The
//   rest of the root is an empty tmpfs, read-only.
// - Its own namespaces (--unshare-all): no network but its own loopback (a
//   connect to the host's 127.0.0.1 is refused, to 1.1.1.1 unreachable), its
//   own process ids (the host's processes are not visible, and killing
//   bwrap kills every process inside), IPC, host name and user namespace; no
//   capabilities; no further user namespaces (--disable-userns); setuid bits
//   do nothing (no_new_privs); a new session (no TIOCSTI into the terminal).
// - An environment of PATH=/usr/local/bin:/usr/bin:/bin, HOME=/tmp,
//   LANG=C.UTF-8, PWD (bwrap sets it) and the caller's `env`; the rest is cleared.
// - Its working directory: `chdir`, else the first writable folder, else /tmp.
//
// The limits are set by prlimit (util-linux) inside the sandbox, just before
// the program starts; it cannot raise them (soft = hard). RLIMIT_NPROC is the
// reason they are set inside and not on bwrap. The kernel counts processes
// per user and per user namespace, and a limit set inside counts only the
// sandbox's processes: with 26 other processes of the same user on the host,
// a limit of 40 set on bwrap let the sandbox fork 11 children, set inside 38.
// RLIMIT_NPROC does nothing for root (uid 0 in the host's namespace), also
// not inside bwrap's user namespace: as root, 40 of 40 forks succeeded under a
// limit of 20 with --uid 65534 and with --cap-drop ALL. So a root caller
// runs bwrap as uid 65534 (nobody): setpriv gives up root first, and
// the writable folders, with what is in them, are handed to uid 65534 (without
// following links). That user must be able to reach every folder bound: a
// folder under /root (drwx------) cannot be bound then. A non-root caller
// runs bwrap as itself and nothing changes owner.
//
// Why each limit has its value (render_limits(); build_limits() for a
// configure or build step of a source tree). A limit of 0 is no limit.
// - cpu_seconds, RLIMIT_CPU, per process: a render of all the views of the
//   slowest lab (33_csg_stencil) in one run takes 0.18 CPU s, so 60 s (labgrade's
//   default timeout per view) is a render gone wrong. The heaviest file of a
//   Release build (tests/io/splinetool_test.cpp) compiles in 12 CPU s: 300 s
//   for a build step. SIGXCPU at the limit, SIGKILL one second later.
// - memory_bytes, RLIMIT_DATA (heap and thread stacks), per process: 2 GiB.
//   The labs' renders need 64-120 MiB of data with the two llvmpipe threads
//   of this 2-core machine, 17 MiB more per thread; llvmpipe starts one per
//   core, at most 32 (LP_NUM_THREADS), and needs 576 MiB then. The heaviest
//   compile peaks at 486 MiB resident. RLIMIT_AS is kAddressSpacePerMemory
//   times memory_bytes, 8 GiB: glibc reserves a 64 MiB malloc arena per thread
//   (at most 8 per core), so a render reserves 560-660 MiB of address space
//   with 2 threads, 1,296 MiB with 8 and 1,664 MiB with 32 here (16 arenas);
//   with an arena per thread, as on a 32-core machine, about 4.2 GiB. An
//   address-space limit of 2 GiB would fail correct renders on big machines,
//   but it stops shared mappings, which RLIMIT_DATA does not count. Neither
//   stops data written to a memfd. A render under a limit too small does not
//   always fail: with 1 GiB of address space and 32 threads asked, a render
//   stopped at 13 of its 66 threads and waited forever (the wall clock ends it). An
//   AddressSanitizer build reserves terabytes: it needs memory_bytes 0.
// - file_bytes, RLIMIT_FSIZE, per file: 256 MiB. The largest file of a whole
//   Release build is 3.5 MB (bin/labs_test), a render's PNG 29,480 bytes for
//   lab 01. It limits each file, not their sum: the writable folders are on
//   the host's disk, with no quota.
// - processes, RLIMIT_NPROC, processes and threads in the sandbox, bwrap's own
//   init among them: 128 for a render, which runs 2 threads + 2 per llvmpipe
//   thread (6 here, 66 with 32 llvmpipe threads). A build with make and
//   ccache peaked at 15 processes with -j 2 and 21 with -j 4, 3 per job: 256
//   for a build step. A fork bomb stops there (31 of its processes and
//   bwrap's init under a limit of 32) and spins until the wall clock.
// - wall_seconds: 120 s for a render (labgrade passes its timeout), 1800 s for
//   a build step: a Release build of the whole tree with its tests costs
//   1,757 CPU s (docs/platform.md), about 15 min on 2 cores.
// - max_output_bytes: kMaxRendererOutputBytes (64 MiB) of stdout and of stderr.
//
// limit_hit names the limit a failed run reached. It is read from how the run
// ended: killed by SIGXCPU (exit status 152) or SIGXFSZ (153), by the wall
// clock or the output limit; or, when a process inside it died and the run
// failed, from what the tools print then: "CPU time limit exceeded", "File
// size limit exceeded", "File too large" (EFBIG), "Resource temporarily
// unavailable" or "Cannot fork" (a fork or a thread refused at the process
// limit), "std::bad_alloc", "Cannot allocate memory" or "out of memory". A
// program that ignores a failed fork or malloc silently leaves no trace: a
// fork bomb that prints nothing is reported at the wall clock.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "process.h"

namespace gllab {

/// The sandbox's own /tmp: 256 MiB of memory at most (a tmpfs). The largest
/// temporary file of a Release build is the 3.2 MB assembly of
/// tests/io/splinetool_test.cpp.
inline constexpr std::uint64_t kSandboxTmpBytes = std::uint64_t{256} << 20;
/// The sandbox's /dev/shm (POSIX shared memory): 64 MiB, a tmpfs. The labs use none.
inline constexpr std::uint64_t kSandboxShmBytes = std::uint64_t{64} << 20;
/// RLIMIT_AS is this many times memory_bytes (see the header comment).
inline constexpr std::uint64_t kAddressSpacePerMemory = 4;
/// The user a root caller runs the sandbox as: nobody.
inline constexpr unsigned kSandboxUid = 65534, kSandboxGid = 65534;

/// What one sandboxed run may take. 0 is no limit. The defaults are those of
/// one render (render_limits()); the header comment gives each one's reason.
struct SandboxLimits {
  double cpu_seconds = 60;                                // per process, rounded up to whole seconds
  std::uint64_t memory_bytes = std::uint64_t{2} << 30;    // data per process (RLIMIT_DATA)
  std::uint64_t file_bytes = std::uint64_t{256} << 20;    // per file written
  int processes = 128;                                    // processes and threads in the sandbox
  double wall_seconds = 120;                              // the whole run, then SIGKILL
  std::size_t max_output_bytes = kMaxRendererOutputBytes;  // of stdout, and of stderr
};

/// The limits of one lab render (several views in one run).
SandboxLimits render_limits();
/// The limits of one step of a source tree's build: cmake's configure, or
/// `cmake --build` (256 processes: room for about -j 80).
SandboxLimits build_limits();

/// A host folder (or file) shown at `inside`, read-only unless `writable`.
struct SandboxMount {
  std::filesystem::path host;
  std::filesystem::path inside;  // absolute
  bool writable = false;
};

struct Sandbox {
  std::vector<std::filesystem::path> read_only;  // bound read-only at the same path (the student's tree)
  std::vector<std::filesystem::path> writable;   // bound read-write at the same path (its build folder)
  std::vector<SandboxMount> mounts;              // bound at another path
  std::vector<std::filesystem::path> hidden;     // paths inside, covered by an empty folder (or file)
  SandboxLimits limits;
  std::vector<std::string> env;                  // NAME=VALUE set inside
  std::filesystem::path chdir;                   // "": the first writable folder, else /tmp
};

struct SandboxResult {
  ProcessResult process;  // bwrap's exit status is the program's (128 + signal when killed)
  std::string limit_hit;  // "" or one line naming the limit, e.g. "process limit of 64 reached"
};

/// Runs argv (argv[0] a path inside the sandbox, or a name on its PATH) in
/// the sandbox described above, waits, and returns how it ended. Never throws
/// for a failing program; a sandbox that cannot start (no bwrap, a folder that
/// does not exist or that the sandbox's user cannot reach) is started false
/// with the reason in process.err. Throws std::invalid_argument for an empty
/// argv, an env entry without NAME=, or a path inside that is relative or "/".
SandboxResult run_sandboxed(const std::vector<std::string>& argv, const Sandbox& box);

/// "" when bwrap can run the sandbox here, else one line saying why: not
/// installed, prlimit or setpriv missing, or user namespaces off (naming
/// /proc/sys/kernel/unprivileged_userns_clone,
/// /proc/sys/kernel/apparmor_restrict_unprivileged_userns or
/// /proc/sys/user/max_user_namespaces when one is set so), else bwrap's error.
std::string sandbox_unavailable_reason();

}  // namespace gllab
