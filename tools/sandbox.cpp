// tools/sandbox.cpp — the bwrap command line, the limits and how a run ended (sandbox.h).
#include "sandbox.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace gllab {

namespace {

// How deep hand_over() goes into a writable folder: what lies deeper was
// written by the sandbox's user, who owns it already.
constexpr int kMaxHandOverDepth = 64;
// How long sandbox_unavailable_reason() waits for `true` in the sandbox.
constexpr double kProbeSeconds = 30;

// The executable file `name` in a folder of the host's PATH, else "".
std::string find_program(const std::string& name) {
  const char* path = std::getenv("PATH");
  const std::string dirs = path && *path ? path : "/usr/local/bin:/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::string dir = dirs.substr(start, end - start);
    start = end + 1;
    if (dir.empty() || dir[0] != '/') continue;  // a relative PATH entry is not trusted
    const std::string file = dir + "/" + name;
    struct stat st {};
    if (stat(file.c_str(), &st) == 0 && S_ISREG(st.st_mode) && access(file.c_str(), X_OK) == 0)
      return file;
  }
  return "";
}

// prlimit runs inside, so it must be in a folder the sandbox shows.
std::string find_prlimit() {
  for (const char* file : {"/usr/bin/prlimit", "/bin/prlimit"})
    if (access(file, X_OK) == 0) return file;
  return "";
}

// Does this bwrap know the option? (--disable-userns is 0.8.0, --size 0.5.0.)
bool bwrap_knows(const std::string& bwrap, const std::string& option) {
  static const std::string help =
      run_process({bwrap, "--help"}, {}, ProcessLimits{kProbeSeconds, 1 << 20}).out;
  return help.find(option + " ") != std::string::npos;
}

std::string format_bytes(std::uint64_t bytes) {
  const std::pair<std::uint64_t, const char*> units[] = {
      {std::uint64_t{1} << 30, "GiB"}, {std::uint64_t{1} << 20, "MiB"}, {std::uint64_t{1} << 10, "KiB"}};
  for (const auto& [size, name] : units)
    if (bytes >= size && bytes % size == 0) return std::to_string(bytes / size) + " " + name;
  return std::to_string(bytes) + " bytes";
}

std::string format_seconds(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", seconds);
  return text;
}

// RLIMIT_CPU takes whole seconds: the limit is cpu_seconds rounded up.
std::uint64_t cpu_limit(double seconds) {
  return seconds > 0 ? static_cast<std::uint64_t>(std::ceil(std::min(seconds, 1e12))) : 0;
}

std::string mode_text(const struct stat& st) {
  char text[64];
  std::snprintf(text, sizeof text, "mode %03o, owner uid %u", unsigned(st.st_mode & 07777),
                unsigned(st.st_uid));
  return text;
}

// May the sandbox's user (uid and gid 65534, no other groups) do `want`
// (a mask of r=4, w=2, x=1) to the file?
bool sandbox_user_may(const struct stat& st, unsigned want) {
  const unsigned bits = st.st_uid == kSandboxUid   ? (st.st_mode >> 6) & 7
                        : st.st_gid == kSandboxGid ? (st.st_mode >> 3) & 7
                                                   : st.st_mode & 7;
  return (bits & want) == want;
}

// "" when the sandbox's user can reach `path` (and read it, if `read`), else why not.
std::string unreachable_for_sandbox_user(const fs::path& path, bool read) {
  std::error_code ec;
  const fs::path real = fs::canonical(path, ec);
  if (ec) return "no folder " + path.string() + " to bind (" + ec.message() + ")";
  fs::path at = "/";
  for (const fs::path& part : real.relative_path()) {
    struct stat st {};
    if (stat(at.c_str(), &st) != 0 || !sandbox_user_may(st, 1))
      return "the sandbox runs as uid 65534, which cannot reach " + path.string() + ": " + at.string() +
             " is " + mode_text(st);
    at /= part;
  }
  struct stat st {};
  if (read && stat(real.c_str(), &st) == 0 && !sandbox_user_may(st, S_ISDIR(st.st_mode) ? 5 : 4))
    return "the sandbox runs as uid 65534, which cannot read " + path.string() + " (" + mode_text(st) + ")";
  return "";
}

// Hands the folder open as dir_fd and everything in it to the sandbox's user.
// Every entry is reached from its folder's descriptor and never through a
// link, so a link planted by an earlier run cannot point the chown elsewhere.
void hand_over(int dir_fd, int depth) {
  struct stat st {};
  if (fstat(dir_fd, &st) == 0 && (st.st_uid != kSandboxUid || st.st_gid != kSandboxGid))
    (void)!fchown(dir_fd, kSandboxUid, kSandboxGid);
  if (depth >= kMaxHandOverDepth) return;
  const int list_fd = dup(dir_fd);
  if (list_fd < 0) return;
  DIR* dir = fdopendir(list_fd);
  if (!dir) {
    close(list_fd);
    return;
  }
  while (const dirent* entry = readdir(dir)) {
    const char* name = entry->d_name;
    if (std::strcmp(name, ".") == 0 || std::strcmp(name, "..") == 0) continue;
    if (fstatat(dir_fd, name, &st, AT_SYMLINK_NOFOLLOW) != 0) continue;
    if (S_ISDIR(st.st_mode)) {
      const int sub = openat(dir_fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
      if (sub < 0) continue;
      hand_over(sub, depth + 1);
      close(sub);
    } else if (st.st_uid != kSandboxUid || st.st_gid != kSandboxGid) {
      (void)!fchownat(dir_fd, name, kSandboxUid, kSandboxGid, AT_SYMLINK_NOFOLLOW);
    }
  }
  closedir(dir);
}

void hand_over(const fs::path& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd >= 0) {
    hand_over(fd, 0);
    close(fd);
  } else {
    (void)!fchownat(AT_FDCWD, path.c_str(), kSandboxUid, kSandboxGid, AT_SYMLINK_NOFOLLOW);
  }
}

// An absolute path without "." and ".." parts or a trailing slash.
fs::path inside_path(const fs::path& p, const char* what) {
  if (!p.is_absolute())
    throw std::invalid_argument(std::string("sandbox: ") + what + " " + p.string() + " is not absolute");
  fs::path n = p.lexically_normal();
  if (n.has_filename() == false && n != n.root_path()) n = n.parent_path();
  if (n == n.root_path())
    throw std::invalid_argument(std::string("sandbox: ") + what + " is / (the whole host)");
  return n;
}

std::vector<SandboxMount> all_mounts(const Sandbox& box) {
  std::vector<SandboxMount> mounts;
  // A folder shown at its own path may be given relative to the working folder.
  for (const fs::path& p : box.read_only) mounts.push_back({p, fs::absolute(p), false});
  for (const fs::path& p : box.writable) mounts.push_back({p, fs::absolute(p), true});
  mounts.insert(mounts.end(), box.mounts.begin(), box.mounts.end());
  for (SandboxMount& m : mounts) {
    m.inside = inside_path(m.inside, "mount point");
    m.host = fs::absolute(m.host).lexically_normal();
  }
  // A folder before the folders mounted inside it.
  std::stable_sort(mounts.begin(), mounts.end(), [](const SandboxMount& a, const SandboxMount& b) {
    return std::distance(a.inside.begin(), a.inside.end()) < std::distance(b.inside.begin(), b.inside.end());
  });
  return mounts;
}

// The host path shown at `inside`: through the deepest mount that holds it,
// else the same path (the system folders are bound at their own paths).
fs::path host_of(const fs::path& inside, const std::vector<SandboxMount>& mounts) {
  for (auto m = mounts.rbegin(); m != mounts.rend(); ++m) {
    const fs::path rest = inside.lexically_relative(m->inside);
    if (!rest.empty() && *rest.begin() != "..") return rest == "." ? m->host : m->host / rest;
  }
  return inside;
}

struct Command {
  std::vector<std::string> argv;
  std::string error;                 // why the sandbox cannot start, else ""
  std::vector<SandboxMount> mounts;  // in the order bound
  bool hand_over = false;            // root: give the writable folders to the sandbox's user
};

Command sandbox_command(const std::vector<std::string>& argv, const Sandbox& box) {
  if (argv.empty()) throw std::invalid_argument("sandbox: no program to run (argv is empty)");
  for (const std::string& e : box.env)
    if (e.find('=') == std::string::npos || e.find('=') == 0)
      throw std::invalid_argument("sandbox: environment entry '" + e + "' is not NAME=VALUE");
  const std::vector<SandboxMount> mounts = all_mounts(box);
  std::vector<fs::path> hidden;
  for (const fs::path& h : box.hidden) hidden.push_back(inside_path(h, "hidden path"));
  fs::path chdir = "/tmp";
  const auto first_mount = std::find_if(box.mounts.begin(), box.mounts.end(),
                                        [](const SandboxMount& m) { return m.writable; });
  if (!box.chdir.empty()) chdir = inside_path(box.chdir, "working folder");
  else if (!box.writable.empty()) chdir = inside_path(fs::absolute(box.writable.front()), "writable folder");
  else if (first_mount != box.mounts.end()) chdir = inside_path(first_mount->inside, "mount point");

  Command c;
  const std::string bwrap = find_program("bwrap");
  const std::string prlimit = find_prlimit();
  const bool root = geteuid() == 0;
  const std::string setpriv = root ? find_program("setpriv") : "";
  if (bwrap.empty())
    c.error = "bwrap is not installed (no bwrap on PATH; Debian: apt-get install bubblewrap)";
  else if (prlimit.empty()) c.error = "prlimit (util-linux) is not in /usr/bin or /bin";
  else if (root && setpriv.empty())
    c.error = "setpriv (util-linux) is not on PATH: root needs it to run the sandbox as uid 65534";
  for (const SandboxMount& m : mounts) {
    if (!c.error.empty()) break;
    std::error_code ec;
    if (!fs::exists(m.host, ec)) c.error = "no folder " + m.host.string() + " to bind";
    else if (root) c.error = unreachable_for_sandbox_user(m.host, !m.writable);
  }
  if (!c.error.empty()) return c;

  std::vector<std::string>& a = c.argv;
  if (root) a = {setpriv, "--reuid=" + std::to_string(kSandboxUid), "--regid=" + std::to_string(kSandboxGid),
                 "--clear-groups", "--"};
  a.insert(a.end(), {bwrap, "--unshare-all", "--unshare-user"});
  if (bwrap_knows(bwrap, "--disable-userns")) a.push_back("--disable-userns");
  a.insert(a.end(), {"--die-with-parent", "--new-session", "--cap-drop", "ALL", "--ro-bind", "/usr", "/usr"});
  for (const char* top : {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"}) {
    std::error_code ec;
    if (fs::is_symlink(top, ec)) a.insert(a.end(), {"--symlink", fs::read_symlink(top, ec).string(), top});
    else if (fs::is_directory(top, ec)) a.insert(a.end(), {"--ro-bind", top, top});
  }
  for (const char* etc : {"/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/alternatives"})
    a.insert(a.end(), {"--ro-bind-try", etc, etc});
  const bool sizes = bwrap_knows(bwrap, "--size");
  a.insert(a.end(), {"--proc", "/proc", "--dev", "/dev"});
  if (sizes) a.insert(a.end(), {"--size", std::to_string(kSandboxShmBytes)});
  a.insert(a.end(), {"--tmpfs", "/dev/shm", "--remount-ro", "/dev"});
  if (sizes) a.insert(a.end(), {"--size", std::to_string(kSandboxTmpBytes)});
  a.insert(a.end(), {"--tmpfs", "/tmp"});
  for (const SandboxMount& m : mounts)
    a.insert(a.end(), {m.writable ? "--bind" : "--ro-bind", m.host.string(), m.inside.string()});
  for (const fs::path& h : hidden) {
    std::error_code ec;
    const fs::path host = host_of(h, mounts);
    if (fs::is_directory(fs::symlink_status(host, ec)))
      a.insert(a.end(), {"--tmpfs", h.string(), "--remount-ro", h.string()});
    else if (fs::exists(fs::symlink_status(host, ec)))
      a.insert(a.end(), {"--ro-bind", "/dev/null", h.string()});
  }
  a.insert(a.end(), {"--remount-ro", "/", "--clearenv", "--setenv", "PATH", "/usr/local/bin:/usr/bin:/bin",
                     "--setenv", "HOME", "/tmp", "--setenv", "LANG", "C.UTF-8"});
  for (const std::string& e : box.env) {
    const std::size_t eq = e.find('=');
    a.insert(a.end(), {"--setenv", e.substr(0, eq), e.substr(eq + 1)});
  }
  a.insert(a.end(), {"--chdir", chdir.string(), "--", prlimit, "--core=0"});
  const SandboxLimits& l = box.limits;
  if (const std::uint64_t cpu = cpu_limit(l.cpu_seconds))
    a.push_back("--cpu=" + std::to_string(cpu) + ":" + std::to_string(cpu + 1));
  if (l.memory_bytes > 0) {
    a.push_back("--data=" + std::to_string(l.memory_bytes));
    if (l.memory_bytes <= UINT64_MAX / kAddressSpacePerMemory)
      a.push_back("--as=" + std::to_string(l.memory_bytes * kAddressSpacePerMemory));
  }
  if (l.file_bytes > 0) a.push_back("--fsize=" + std::to_string(l.file_bytes));
  if (l.processes > 0) a.push_back("--nproc=" + std::to_string(l.processes));
  a.push_back("--");
  a.insert(a.end(), argv.begin(), argv.end());
  c.hand_over = root;
  c.mounts = mounts;
  return c;
}

bool contains(const std::string& text, const char* what) {
  const std::size_t n = std::strlen(what);
  const auto same = [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
  };
  return std::search(text.begin(), text.end(), what, what + n, same) != text.end();
}

// The limit a failed run reached (sandbox.h), or "".
std::string limit_hit(const ProcessResult& r, const SandboxLimits& l) {
  if (!r.started) return "";
  const std::string cpu =
      "CPU time limit of " + format_seconds(double(cpu_limit(l.cpu_seconds))) + " reached";
  const std::string file =
      "file size limit of " + format_bytes(l.file_bytes) + " reached (a file grew past it)";
  if (l.cpu_seconds > 0 && r.exit_status == 128 + SIGXCPU) return cpu;
  if (l.file_bytes > 0 && r.exit_status == 128 + SIGXFSZ) return file;
  if (r.output_exceeded)
    return "output limit of " + format_bytes(l.max_output_bytes) + " reached (stdout or stderr)";
  if (r.exit_status == 0 && !r.timed_out) return "";
  const auto said = [&](std::initializer_list<const char*> words) {
    return std::any_of(words.begin(), words.end(),
                       [&](const char* w) { return contains(r.err, w) || contains(r.out, w); });
  };
  std::string hit;
  if (l.cpu_seconds > 0 && said({"CPU time limit exceeded"})) hit = cpu;
  else if (l.file_bytes > 0 && said({"File size limit exceeded", "File too large"})) hit = file;
  else if (l.processes > 0 && said({"Resource temporarily unavailable", "Cannot fork"}))
    hit = "process limit of " + std::to_string(l.processes) + " reached";
  else if (l.memory_bytes > 0 &&
           said({"std::bad_alloc", "Cannot allocate memory", "out of memory", "memory exhausted"}))
    hit = "memory limit of " + format_bytes(l.memory_bytes) + " reached";
  const std::string wall = "wall-clock limit of " + format_seconds(l.wall_seconds) + " reached";
  if (r.timed_out) return hit.empty() ? wall : hit + ", then the " + wall;
  return hit;
}

std::string read_number(const char* file) {
  std::ifstream in(file);
  std::string value;
  in >> value;
  return value;
}

}  // namespace

SandboxLimits render_limits() { return SandboxLimits{}; }

SandboxLimits build_limits() {
  SandboxLimits l;
  l.cpu_seconds = 300;
  l.processes = 256;
  l.wall_seconds = 1800;
  return l;
}

SandboxResult run_sandboxed(const std::vector<std::string>& argv, const Sandbox& box) {
  SandboxResult result;
  const Command c = sandbox_command(argv, box);
  if (!c.error.empty()) {
    result.process.started = false;
    result.process.err = "sandbox: " + c.error;
    return result;
  }
  if (c.hand_over)
    for (const SandboxMount& m : c.mounts)
      if (m.writable) hand_over(m.host);
  result.process =
      run_process(c.argv, {}, ProcessLimits{box.limits.wall_seconds, box.limits.max_output_bytes});
  result.limit_hit = limit_hit(result.process, box.limits);
  return result;
}

std::string sandbox_unavailable_reason() {
  Sandbox probe;
  probe.limits.wall_seconds = kProbeSeconds;
  const SandboxResult r = run_sandboxed({"true"}, probe);
  if (!r.process.started) {
    const std::string why = first_line(r.process.err), prefix = "sandbox: ";
    return why.compare(0, prefix.size(), prefix) == 0 ? why.substr(prefix.size()) : why;
  }
  if (r.process.exit_status == 0) return "";
  const std::string said = r.process.timed_out ? "no answer in " + format_seconds(kProbeSeconds)
                                               : first_line(r.process.err);
  const std::string who = geteuid() == 0 ? " (as root it runs as uid 65534)" : "";
  const std::pair<const char*, const char*> switches[] = {
      {"/proc/sys/kernel/unprivileged_userns_clone", "0"},
      {"/proc/sys/kernel/apparmor_restrict_unprivileged_userns", "1"},
      {"/proc/sys/user/max_user_namespaces", "0"}};
  for (const auto& [file, off] : switches)
    if (read_number(file) == off)
      return std::string("user namespaces are off for unprivileged users") + who + ": " + file +
             " is " + off + " (bwrap: " + said + ")";
  return "bwrap cannot start a sandbox here" + who + ": " + said;
}

}  // namespace gllab
