// tests/grading/sandbox_test.cpp — tools/sandbox.h: hostile student programs
// (hostile_program.cpp) run in the sandbox. Each must fail, for its reason
// (the errno it prints, or the limit_hit the sandbox names), leave the host
// as it was (the files of the class folder outside the build folder hash the
// same, nothing appears in the host's /tmp or /usr, no process is left) and
// end in seconds. A normal program, a lab render and a CMake build work.
//
// The limits here are small so that the whole test takes seconds: 1 s of
// CPU, 256 MiB of memory, 64 MiB per file, 32 processes, 3 s of wall clock,
// 1 MiB of output. The messages are the ones sandbox.h documents.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "sandbox.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using gllab::Sandbox;
using gllab::SandboxResult;
using gllab::run_sandboxed;
using gllab::testing::kBinDir;
using gllab::testing::ScratchDir;
using Clock = std::chrono::steady_clock;

const fs::path kHostileProgram = GLLAB_HOSTILE_PROGRAM;
const fs::path kLab = kBinDir / "01_immediate_mode";

constexpr double kCpuSeconds = 1;
constexpr std::uint64_t kMemoryBytes = std::uint64_t{256} << 20;
constexpr std::uint64_t kFileBytes = std::uint64_t{64} << 20;
constexpr int kProcesses = 32;
constexpr double kWallSeconds = 3;
constexpr std::size_t kOutputBytes = std::size_t{1} << 20;
// A case that runs into a limit ends within this: the wall clock of 3 s,
// bwrap's start (about 10 ms) and run_process's drain of at most 1 s.
constexpr double kCaseSeconds = 10;
// How long the kernel may take to remove a killed sandbox's processes.
constexpr double kTeardownSeconds = 2;

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_file(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Processes on the host whose program is `exe` (every pid namespace's
// processes are in the host's /proc).
int processes_of(const fs::path& exe) {
  int count = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator("/proc", ec)) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    if (fs::read_symlink(e.path() / "exe", ec) == exe) ++count;
  }
  return count;
}

// A class on disk, in a fresh folder: alice's tree (shown read-only, with her
// program in it) and build folder (writable), bob's tree and the
// instructor's answers (neither shown).
class SandboxTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string why = gllab::sandbox_unavailable_reason();
    if (!why.empty()) GTEST_SKIP() << "no sandbox here: " << why;
    write_file(tree_ / "lab.cpp", "alice's solution\n");
    write_file(other_ / "lab.cpp", "bob's solution\n");
    write_file(dir_ / "instructor" / "answers.txt", "the instructor's answers\n");
    fs::create_directories(build_);
    // Her program: a copy of hostile_program, so that its processes are
    // this test's alone (processes_of()).
    fs::copy_file(kHostileProgram, program_);
    box_.read_only = {tree_};
    box_.writable = {build_};
    box_.limits = {kCpuSeconds, kMemoryBytes, kFileBytes, kProcesses, kWallSeconds, kOutputBytes};
    remember_host_files();
    ready_ = true;
  }

  // What TearDown() compares the class folder with; a test that writes
  // files of its own outside the build folder calls it again.
  void remember_host_files() { before_ = host_files(); }

  void TearDown() override {
    if (!ready_) return;
    EXPECT_EQ(host_files(), before_) << "a file outside the build folder changed";
    const auto start = Clock::now();
    while (processes_of(program_) > 0 && seconds_since(start) < kTeardownSeconds)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_EQ(processes_of(program_), 0) << "a process of the sandbox outlived it";
  }

  // Every file of the class folder but the build folder: path -> hash of its bytes.
  std::map<std::string, std::size_t> host_files() const {
    std::map<std::string, std::size_t> files;
    const fs::recursive_directory_iterator end;
    for (auto e = fs::recursive_directory_iterator(dir_.path()); e != end; ++e) {
      if (e->path() == build_) {
        e.disable_recursion_pending();
        continue;
      }
      if (e->is_regular_file()) files[e->path().string()] = std::hash<std::string>{}(file_text(e->path()));
    }
    return files;
  }

  // Runs her program with args; `program` is its path inside, if not its own.
  SandboxResult hostile(const std::vector<std::string>& args, const fs::path& program = {}) {
    std::vector<std::string> argv = {program.empty() ? program_.string() : program.string()};
    argv.insert(argv.end(), args.begin(), args.end());
    const auto start = Clock::now();
    SandboxResult r = run_sandboxed(argv, box_);
    seconds_ = seconds_since(start);
    EXPECT_TRUE(r.process.started) << r.process.err;
    return r;
  }

  ScratchDir dir_{"sandbox"};
  const fs::path tree_ = dir_ / "alice/src";
  const fs::path build_ = dir_ / "alice/build";
  const fs::path other_ = dir_ / "bob/src";
  const fs::path program_ = tree_ / "hostile_program";
  // A name for files a program must not leave on the host.
  const std::string stray_ = "gllab-sandbox-stray-" + std::to_string(getpid());
  Sandbox box_;
  double seconds_ = 0;

 private:
  std::map<std::string, std::size_t> before_;
  bool ready_ = false;
};

// ---- what it can read --------------------------------------------------------

TEST_F(SandboxTest, AnotherSubmissionIsNotVisible) {
  const SandboxResult r = hostile({"read", (other_ / "lab.cpp").string()});
  EXPECT_EQ(r.process.exit_status, 1);
  EXPECT_NE(r.process.err.find("No such file or directory"), std::string::npos) << r.process.err;
  EXPECT_EQ(r.process.out.find("bob's solution"), std::string::npos);
  EXPECT_EQ(r.limit_hit, "");
}

TEST_F(SandboxTest, InstructorFilesAndHostFoldersAreNotVisible) {
  for (const fs::path& p : {dir_ / "instructor" / "answers.txt", fs::path("/root"), fs::path("/home"),
                            fs::path("/work"), fs::path("/etc/passwd"), fs::path("/etc/shadow")}) {
    const SandboxResult r = hostile({"exists", p.string()});
    EXPECT_EQ(r.process.exit_status, 1) << p;
    EXPECT_NE(r.process.err.find("No such file or directory"), std::string::npos)
        << p << ": " << r.process.err;
  }
}

TEST_F(SandboxTest, ItsOwnTreeIsReadable) {
  const SandboxResult r = hostile({"read", (tree_ / "lab.cpp").string()});
  EXPECT_EQ(r.process.exit_status, 0) << r.process.err;
  EXPECT_EQ(r.process.out, "alice's solution\n");
}

// ---- what it can write -------------------------------------------------------

TEST_F(SandboxTest, WritesIntoTheReadOnlyTreeFail) {
  for (const fs::path& p : {tree_ / "lab.cpp", tree_ / "new.txt"}) {
    const SandboxResult r = hostile({"write", p.string()});
    EXPECT_EQ(r.process.exit_status, 1) << p;
    EXPECT_NE(r.process.err.find("Read-only file system"), std::string::npos) << p << ": " << r.process.err;
  }
  EXPECT_FALSE(fs::exists(tree_ / "new.txt"));
}

TEST_F(SandboxTest, WritesIntoUsrAndTheRootFail) {
  for (const fs::path& p : {fs::path("/usr") / stray_, fs::path("/") / stray_}) {
    const SandboxResult r = hostile({"write", p.string()});
    EXPECT_EQ(r.process.exit_status, 1) << p;
    EXPECT_NE(r.process.err.find("Read-only file system"), std::string::npos) << p << ": " << r.process.err;
    EXPECT_FALSE(fs::exists(p)) << p;
  }
}

// /tmp inside is the sandbox's own: the write succeeds and the host never sees it.
TEST_F(SandboxTest, WritesIntoTmpStayInTheSandbox) {
  const fs::path p = fs::path("/tmp") / stray_;
  const SandboxResult r = hostile({"write", p.string()});
  EXPECT_EQ(r.process.exit_status, 0) << r.process.err;
  EXPECT_FALSE(fs::exists(p));
}

TEST_F(SandboxTest, WritesIntoTheBuildFolderReachTheHost) {
  const SandboxResult r = hostile({"write", (build_ / "out.txt").string()});
  EXPECT_EQ(r.process.exit_status, 0) << r.process.err;
  EXPECT_EQ(file_text(build_ / "out.txt"), "written by a hostile program\n");
}

// As root the sandbox hands the build folder to uid 65534 before each run
// (sandbox.h). Links an earlier run left there, to a file and to a folder of
// the instructor's, must not hand those over.
TEST_F(SandboxTest, LinksLeftInTheBuildFolderAreNotFollowed) {
  const fs::path answers = dir_ / "instructor" / "answers.txt";
  fs::create_symlink(answers, build_ / "to_file");
  fs::create_symlink(answers.parent_path(), build_ / "to_folder");
  struct stat before {};
  ASSERT_EQ(stat(answers.c_str(), &before), 0);
  const SandboxResult r = hostile({"exists", (build_ / "to_file").string()});
  EXPECT_EQ(r.process.exit_status, 1);  // the link's target is not in the sandbox
  struct stat after {};
  ASSERT_EQ(stat(answers.c_str(), &after), 0);
  EXPECT_EQ(after.st_uid, before.st_uid);
  ASSERT_EQ(stat(answers.parent_path().c_str(), &after), 0);
  EXPECT_EQ(after.st_uid, geteuid());
}

// ---- the network ---------------------------------------------------------------

// A server of the host's on 127.0.0.1: the sandbox's loopback is another one.
TEST_F(SandboxTest, ConnectToTheHostsLoopbackFails) {
  const int server = socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(server, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t size = sizeof address;
  ASSERT_EQ(bind(server, reinterpret_cast<sockaddr*>(&address), size), 0);
  ASSERT_EQ(listen(server, 4), 0);
  ASSERT_EQ(getsockname(server, reinterpret_cast<sockaddr*>(&address), &size), 0);
  const std::string port = std::to_string(ntohs(address.sin_port));
  const SandboxResult r = hostile({"connect", "127.0.0.1", port});
  EXPECT_EQ(r.process.exit_status, 1);
  EXPECT_NE(r.process.err.find("Connection refused"), std::string::npos) << r.process.err;
  pollfd waiting{server, POLLIN, 0};
  EXPECT_EQ(poll(&waiting, 1, 0), 0) << "the host's server got a connection";
  close(server);
}

TEST_F(SandboxTest, ConnectToAnInternetAddressFails) {
  const SandboxResult r = hostile({"connect", "1.1.1.1", "80"});
  EXPECT_EQ(r.process.exit_status, 1);
  EXPECT_NE(r.process.err.find("Network is unreachable"), std::string::npos) << r.process.err;
}

// ---- the limits ------------------------------------------------------------------

// Every process forks without end: at 32 processes forks fail, the bomb
// spins until the wall clock, and the host can still start a process.
TEST_F(SandboxTest, ForkBombStopsAtTheProcessLimit) {
  const SandboxResult r = hostile({"fork-bomb"});
  EXPECT_EQ(r.limit_hit, "process limit of 32 reached, then the wall-clock limit of 3 s reached");
  EXPECT_NE(r.process.err.find("fork: Resource temporarily unavailable"), std::string::npos) << r.process.err;
  EXPECT_LT(seconds_, kCaseSeconds);
  EXPECT_EQ(gllab::run_process({"/bin/true"}).exit_status, 0);
}

TEST_F(SandboxTest, EndlessFileStopsAtTheFileSizeLimit) {
  const SandboxResult r = hostile({"fill", (build_ / "disk.bin").string()});
  EXPECT_EQ(r.process.exit_status, 128 + SIGXFSZ);
  EXPECT_EQ(r.limit_hit, "file size limit of 64 MiB reached (a file grew past it)");
  EXPECT_EQ(fs::file_size(build_ / "disk.bin"), kFileBytes);
  EXPECT_LT(seconds_, kCaseSeconds);
}

// The program sleeps and so does its child: both die with the sandbox.
TEST_F(SandboxTest, EndlessSleepIsKilledAtTheWallClock) {
  const SandboxResult r = hostile({"sleep"});
  EXPECT_TRUE(r.process.timed_out);
  EXPECT_EQ(r.limit_hit, "wall-clock limit of 3 s reached");
  EXPECT_GE(seconds_, kWallSeconds);
  EXPECT_LT(seconds_, kCaseSeconds);
}

// SIGXCPU after 1 s of CPU, well before the wall clock's 3 s.
TEST_F(SandboxTest, BurningCpuStopsAtTheCpuLimit) {
  const SandboxResult r = hostile({"spin"});
  EXPECT_EQ(r.process.exit_status, 128 + SIGXCPU);
  EXPECT_FALSE(r.process.timed_out);
  EXPECT_EQ(r.limit_hit, "CPU time limit of 1 s reached");
}

// new throws std::bad_alloc at 256 MiB of data; uncaught, it aborts. Touching
// those 256 MiB took more than 1 s of CPU time (page faults) with other tests
// running beside it (SIGXCPU, 1 run in 12 here), so its CPU limit is the wall
// clock's: only the memory limit may stop it.
TEST_F(SandboxTest, EndlessAllocationStopsAtTheMemoryLimit) {
  box_.limits.cpu_seconds = kWallSeconds;
  const SandboxResult r = hostile({"allocate"});
  EXPECT_EQ(r.process.exit_status, 128 + SIGABRT);
  EXPECT_EQ(r.limit_hit, "memory limit of 256 MiB reached");
  EXPECT_LT(seconds_, kCaseSeconds);
}

TEST_F(SandboxTest, EndlessOutputStopsAtTheOutputLimit) {
  const SandboxResult r = hostile({"flood"});
  EXPECT_TRUE(r.process.output_exceeded);
  EXPECT_EQ(r.process.out.size(), kOutputBytes);
  EXPECT_EQ(r.limit_hit, "output limit of 1 MiB reached (stdout or stderr)");
}

// ---- what works --------------------------------------------------------------------

TEST_F(SandboxTest, AFailingProgramHitsNoLimit) {
  const SandboxResult r = hostile({"no-such-mode"});
  EXPECT_EQ(r.process.exit_status, 2);
  EXPECT_EQ(r.limit_hit, "");
}

TEST_F(SandboxTest, TheEnvironmentIsPathHomeLangAndTheCallers) {
  box_.env = {"GLLAB_STUDENT=alice"};
  const SandboxResult r = hostile({"env"});
  ASSERT_EQ(r.process.exit_status, 0) << r.process.err;
  std::set<std::string> env;
  std::istringstream in(r.process.out);
  for (std::string line; std::getline(in, line);) env.insert(line);
  EXPECT_EQ(env, (std::set<std::string>{"PATH=/usr/local/bin:/usr/bin:/bin", "HOME=/tmp", "LANG=C.UTF-8",
                                        "PWD=" + build_.string(), "GLLAB_STUDENT=alice"}));
}

// The class build's layout: folders at other paths, a hidden folder, a working folder.
TEST_F(SandboxTest, MountsAtOtherPathsAndHiddenFolders) {
  write_file(tree_ / "reference_images" / "01.png", "the reference\n");
  box_.read_only.clear();
  box_.writable.clear();
  box_.mounts = {{tree_, "/submission/src", false}, {build_, "/submission/build", true}};
  box_.hidden = {"/submission/src/reference_images"};
  box_.chdir = "/submission/build";
  remember_host_files();
  const fs::path inside = "/submission/src/hostile_program";
  SandboxResult r = hostile({"read", "/submission/src/lab.cpp"}, inside);
  EXPECT_EQ(r.process.out, "alice's solution\n") << r.process.err;
  r = hostile({"read", "/submission/src/reference_images/01.png"}, inside);
  EXPECT_EQ(r.process.exit_status, 1);
  EXPECT_NE(r.process.err.find("No such file or directory"), std::string::npos) << r.process.err;
  r = hostile({"write", "relative.txt"}, inside);
  EXPECT_EQ(r.process.exit_status, 0) << r.process.err;
  EXPECT_TRUE(fs::exists(build_ / "relative.txt"));
}

// A real lab program renders inside the same bytes as on the host (Mesa's
// llvmpipe through EGL surfaceless), with the limits of a render.
TEST_F(SandboxTest, ALabRendersInsideAsOnTheHost) {
  const std::string host_png = (dir_ / "host.png").string();
  ASSERT_EQ(gllab::run_process({kLab.string(), "--headless", "--out", host_png}).exit_status, 0);
  remember_host_files();
  box_.read_only = {kLab};
  box_.limits = gllab::render_limits();
  const std::string png = (build_ / "x.png").string();
  const SandboxResult r = run_sandboxed({kLab.string(), "--headless", "--out", png}, box_);
  ASSERT_EQ(r.process.exit_status, 0) << r.process.err;
  EXPECT_EQ(r.limit_hit, "");
  EXPECT_EQ(file_text(build_ / "x.png"), file_text(dir_ / "host.png"));
}

// A student's build: cmake configures and builds a tiny project with the
// host's compiler, the program runs.
TEST_F(SandboxTest, ACMakeProjectBuildsInside) {
  write_file(tree_ / "CMakeLists.txt",
             "cmake_minimum_required(VERSION 3.16)\nproject(tiny CXX)\nadd_executable(tiny main.cpp)\n");
  write_file(tree_ / "main.cpp", "#include <iostream>\nint main() { std::cout << \"tiny runs\\n\"; }\n");
  remember_host_files();
  box_.limits = gllab::build_limits();
  const std::string bin = (build_ / "b").string();
  SandboxResult r = run_sandboxed({"cmake", "-S", tree_.string(), "-B", bin}, box_);
  ASSERT_EQ(r.process.exit_status, 0) << r.process.out << r.process.err;
  r = run_sandboxed({"cmake", "--build", bin}, box_);
  ASSERT_EQ(r.process.exit_status, 0) << r.process.out << r.process.err;
  r = run_sandboxed({bin + "/tiny"}, box_);
  EXPECT_EQ(r.process.out, "tiny runs\n") << r.process.err;
}

TEST_F(SandboxTest, AMissingFolderDoesNotStart) {
  box_.read_only.push_back(dir_ / "no-such-folder");
  const SandboxResult r = run_sandboxed({program_.string(), "env"}, box_);
  EXPECT_FALSE(r.process.started);
  EXPECT_EQ(r.process.err, "sandbox: no folder " + (dir_ / "no-such-folder").string() + " to bind");
}

// ---- bad arguments and availability --------------------------------------------

TEST(SandboxArguments, BadArgumentsThrowNamingThem) {
  Sandbox box;
  EXPECT_THROW(run_sandboxed({}, box), std::invalid_argument);
  box.env = {"NO_EQUALS_SIGN"};
  EXPECT_THROW(run_sandboxed({"true"}, box), std::invalid_argument);
  box.env.clear();
  box.mounts = {{"/tmp", "relative/path", false}};
  EXPECT_THROW(run_sandboxed({"true"}, box), std::invalid_argument);
  box.mounts = {{"/tmp", "/", false}};
  EXPECT_THROW(run_sandboxed({"true"}, box), std::invalid_argument);
}

// bubblewrap is a requirement of class grading. Where it is installed but the
// kernel refuses it a user namespace (in a chroot, measured on a fresh Debian 12
// root; in some containers), the sandbox tests skip with the reason, and so
// does this one, unless GLLAB_REQUIRE_SANDBOX=1: .ci/run sets it, so that CI
// cannot skip them silently.
TEST(SandboxAvailability, ReasonIsEmptyWhereBwrapIsInstalled) {
  if (!fs::exists("/usr/bin/bwrap")) GTEST_SKIP() << "bubblewrap is not installed";
  const std::string why = gllab::sandbox_unavailable_reason();
  const char* require = std::getenv("GLLAB_REQUIRE_SANDBOX");
  if (!why.empty() && !(require && std::string(require) == "1"))
    GTEST_SKIP() << "no sandbox here: " << why << " (GLLAB_REQUIRE_SANDBOX=1 makes this a failure)";
  EXPECT_EQ(why, "");
}

TEST(SandboxAvailability, MissingBwrapIsNamed) {
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  setenv("PATH", "/nonexistent", 1);
  const std::string why = gllab::sandbox_unavailable_reason();
  setenv("PATH", path.c_str(), 1);
  EXPECT_EQ(why, "bwrap is not installed (no bwrap on PATH; Debian: apt-get install bubblewrap)");
}

}  // namespace
