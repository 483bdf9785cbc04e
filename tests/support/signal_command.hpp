// Runs a command in a child process, sends it a signal after a delay (to test what an interrupted
// run leaves behind) and waits for it.
#pragma once
#include <string>

namespace trirast::test {

struct SignalledResult {
  int status = -1;     // exit status; 128 + signal number when killed by a signal
  bool exited_before_signal = false;  // the command ended before the delay was over
  std::string err;     // its stderr
};

// Starts `/bin/sh -c "exec COMMAND"` with stdout discarded, waits `delay_seconds`, sends `sig`
// to it and waits for it to end.
SignalledResult run_and_signal(const std::string& command, double delay_seconds, int sig);

}  // namespace trirast::test
