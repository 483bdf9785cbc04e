// Files (and folders) a run creates under temporary names: removed when the run fails (the guard's
// destructor), when it ends by SIGINT or SIGTERM (the handler), and kept only by release() once
// the file is complete under its own name. One list for every writer (output files, traces, the
// sweep's folder), so an interrupted run leaves nothing half-written behind.
#pragma once
#include <string>

namespace trirast {

// Installs the SIGINT / SIGTERM handler: it removes every registered path, prints
// "trirast: interrupted" (one line) on stderr and exits with 128 + the signal (130, 143).
void install_interrupt_cleanup();

// Registers `path` for removal; a folder is removed only when empty (rmdir). Thread-safe and
// usable from any library; without install_interrupt_cleanup() only the guard's removal applies.
class TemporaryPath {
 public:
  TemporaryPath() = default;
  explicit TemporaryPath(const std::string& path, bool folder = false) { reset(path, folder); }
  ~TemporaryPath() { remove(); }
  TemporaryPath(const TemporaryPath&) = delete;
  TemporaryPath& operator=(const TemporaryPath&) = delete;

  void reset(const std::string& path, bool folder = false);  // removes the previous one
  void remove();   // removes the path now (if still registered) and forgets it
  void release();  // the path is final: forget it without removing it

 private:
  int slot_ = -1;
};

}  // namespace trirast
