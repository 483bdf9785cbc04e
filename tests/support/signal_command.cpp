#include "support/signal_command.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace trirast::test {

SignalledResult run_and_signal(const std::string& command, double delay_seconds, int sig) {
  char tmpl[] = "/tmp/trirast-sig-XXXXXX";
  const int err_fd = mkstemp(tmpl);
  if (err_fd < 0) throw std::runtime_error("mkstemp failed");
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    const int null_fd = open("/dev/null", O_RDWR);
    dup2(null_fd, 0);
    dup2(null_fd, 1);
    dup2(err_fd, 2);
    const std::string line = "exec " + command;
    execl("/bin/sh", "sh", "-c", line.c_str(), (char*)nullptr);
    _exit(127);
  }
  close(err_fd);
  SignalledResult r;
  int raw = 0;
  const auto until = std::chrono::steady_clock::now() +
                     std::chrono::microseconds(int64_t(delay_seconds * 1e6));
  bool done = false;
  while (std::chrono::steady_clock::now() < until) {
    if (waitpid(pid, &raw, WNOHANG) == pid) {
      done = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  r.exited_before_signal = done;
  if (!done) {
    kill(pid, sig);
    waitpid(pid, &raw, 0);
  }
  if (WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
  else if (WIFSIGNALED(raw)) r.status = 128 + WTERMSIG(raw);
  std::ifstream in(tmpl);
  std::stringstream ss;
  ss << in.rdbuf();
  r.err = ss.str();
  std::remove(tmpl);
  return r;
}

}  // namespace trirast::test
