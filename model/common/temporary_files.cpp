#include "common/temporary_files.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstring>

namespace trirast {

namespace {

// A fixed table the signal handler can walk without allocating: state 0 free, 1 being filled or
// emptied, 2 live.
constexpr int kSlots = 256;
constexpr size_t kPathMax = 4096;
struct Slot {
  std::atomic<int> state{0};
  bool folder = false;
  char path[kPathMax];
};
Slot g_slots[kSlots];
pid_t g_main_pid = 0;  // the process that installed the handler; forked workers stay silent

void remove_path(const Slot& s) {
  if (s.folder) rmdir(s.path);
  else unlink(s.path);
}

extern "C" void on_interrupt(int sig) {
  for (Slot& s : g_slots)
    if (s.state.load() == 2) remove_path(s);
  static const char msg[] = "trirast: interrupted\n";
  if (getpid() == g_main_pid) {
    ssize_t ignored = write(2, msg, sizeof msg - 1);
    (void)ignored;
  }
  _exit(128 + sig);
}

}  // namespace

void install_interrupt_cleanup() {
  g_main_pid = getpid();
  struct sigaction sa;
  std::memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  sigaddset(&sa.sa_mask, SIGINT);
  sigaddset(&sa.sa_mask, SIGTERM);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

void TemporaryPath::reset(const std::string& path, bool folder) {
  remove();
  if (path.size() >= kPathMax) return;  // too long to track: the guard cannot remove it either
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (!g_slots[i].state.compare_exchange_strong(expected, 1)) continue;
    std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
    g_slots[i].folder = folder;
    g_slots[i].state.store(2);
    slot_ = i;
    return;
  }
}

void TemporaryPath::remove() {
  if (slot_ < 0) return;
  Slot& s = g_slots[slot_];
  remove_path(s);
  s.state.store(0);
  slot_ = -1;
}

void TemporaryPath::release() {
  if (slot_ < 0) return;
  g_slots[slot_].state.store(0);
  slot_ = -1;
}

}  // namespace trirast
