// tools/process.cpp — posix_spawn with both output pipes read via poll().
#include "process.h"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <limits>

extern char** environ;

namespace gllab {

namespace {

using Clock = std::chrono::steady_clock;

// After a kill, how long to keep reading what the program wrote before it
// died; then its pipes are closed, whoever still holds them.
constexpr double kDrainSeconds = 1;

Clock::time_point after(double seconds) {
  return Clock::now() +
         std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

// Milliseconds until t for poll(): at least 1, at most an int's range.
int poll_ms(Clock::time_point t) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(t - Clock::now()).count();
  return static_cast<int>(std::clamp<long long>(left + 1, 1, std::numeric_limits<int>::max()));
}

}  // namespace

ProcessResult run_process(const std::vector<std::string>& argv,
                          const std::vector<std::string>& extra_env) {
  return run_process(argv, extra_env, ProcessLimits{});
}

ProcessResult run_process(const std::vector<std::string>& argv, const std::vector<std::string>& extra_env,
                          double timeout_seconds) {
  return run_process(argv, extra_env, ProcessLimits{timeout_seconds, 0});
}

ProcessResult run_process(const std::vector<std::string>& argv,
                          const std::vector<std::string>& extra_env, const ProcessLimits& limits) {
  ProcessResult result;
  int out_pipe[2], err_pipe[2];
  if (pipe2(out_pipe, O_CLOEXEC) != 0) {
    result.started = false;
    result.err = std::string("pipe: ") + std::strerror(errno);
    return result;
  }
  if (pipe2(err_pipe, O_CLOEXEC) != 0) {
    close(out_pipe[0]);
    close(out_pipe[1]);
    result.started = false;
    result.err = std::string("pipe: ") + std::strerror(errno);
    return result;
  }

  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<std::string> env_storage;
  for (char** e = environ; *e; ++e) env_storage.emplace_back(*e);
  for (const std::string& e : extra_env) {
    const std::string name = e.substr(0, e.find('=') + 1);
    for (std::string& existing : env_storage)
      if (existing.compare(0, name.size(), name) == 0) existing.clear();
    env_storage.push_back(e);
  }
  std::vector<char*> env;
  for (std::string& e : env_storage)
    if (!e.empty()) env.push_back(e.data());
  env.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out_pipe[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err_pipe[1], STDERR_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  pid_t pid = 0;
  const int spawn_error = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), env.data());
  posix_spawn_file_actions_destroy(&actions);
  close(out_pipe[1]);
  close(err_pipe[1]);
  if (spawn_error != 0) {
    close(out_pipe[0]);
    close(err_pipe[0]);
    result.started = false;
    result.err = "cannot run '" + argv[0] + "': " + std::strerror(spawn_error);
    return result;
  }

  pollfd fds[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
  std::string* sinks[2] = {&result.out, &result.err};
  int open_count = 2;
  char buffer[65536];
  // NaN, 0 or less: no deadline; more than the cap: the cap (no overflow).
  const bool has_deadline = limits.timeout_seconds > 0;
  const auto deadline =
      after(has_deadline ? std::min(limits.timeout_seconds, kMaxProcessTimeoutSeconds) : 0);
  bool killed = false;
  Clock::time_point drain_until{};
  const auto kill_it = [&] {
    kill(pid, SIGKILL);  // its pipes close when it dies; read what is left for a moment
    killed = true;
    drain_until = after(kDrainSeconds);
  };
  while (open_count > 0) {
    int wait_ms = -1;
    if (killed) {
      if (Clock::now() >= drain_until) break;  // a child it left holds the pipes: stop
      wait_ms = poll_ms(drain_until);
    } else if (has_deadline) {
      if (Clock::now() >= deadline) {
        result.timed_out = true;
        kill_it();
        continue;
      }
      wait_ms = poll_ms(deadline);
    }
    const int ready = poll(fds, 2, wait_ms);
    if (ready < 0) {
      if (errno == EINTR) continue;
      if (!killed) kill(pid, SIGKILL);  // cannot watch it any more: do not wait for it forever
      break;
    }
    if (ready == 0) continue;  // a deadline passed: handled at the top of the loop
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t n = read(fds[i].fd, buffer, sizeof buffer);
      if (n > 0) {
        std::size_t keep = static_cast<std::size_t>(n);
        if (limits.max_output_bytes > 0) {
          const std::size_t room =
              limits.max_output_bytes - std::min(limits.max_output_bytes, sinks[i]->size());
          if (keep > room) {
            keep = room;
            if (!killed) {
              result.output_exceeded = true;
              kill_it();
            }
          }
        }
        sinks[i]->append(buffer, keep);
      } else if (n == 0 || errno != EINTR) {
        close(fds[i].fd);
        fds[i].fd = -1;
        --open_count;
      }
    }
  }
  for (pollfd& f : fds)
    if (f.fd >= 0) close(f.fd);

  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) result.exit_status = WEXITSTATUS(status);
  else if (WIFSIGNALED(status)) result.exit_status = 128 + WTERMSIG(status);
  return result;
}

std::string first_line(const std::string& text) {
  const auto end = text.find('\n');
  return end == std::string::npos ? text : text.substr(0, end);
}

}  // namespace gllab
