// What the tests of the trirast program share: running a shell command and capturing its exit
// status, stdout and stderr; the program's path (kBin); a temporary directory; reading an output
// back; the exact engines of this build.
#pragma once
#include <string>
#include <vector>

#include "common/engine.hpp"

namespace trirast::test {

#ifdef TRIRAST_BIN
// The trirast program of this build (tests/CMakeLists.txt defines TRIRAST_BIN for tests/test_*).
inline const std::string kBin = TRIRAST_BIN;
#endif

struct CommandResult {
  int status = -1;  // exit status; 128 + signal number when killed by a signal
  std::string out, err;
};

CommandResult run_command(const std::string& command);

// A fresh empty directory under /tmp for one test's files; removed by the destructor.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }
  // Names of the entries in the directory (to check that nothing was left behind).
  int entry_count() const;

 private:
  std::string path_;
};

void write_file(const std::string& path, const std::string& content);
bool file_exists(const std::string& path);
// The whole file, bytes as they are; empty when it cannot be read.
std::string slurp(const std::string& path);
int count_lines(const std::string& s);
// Every exact engine this build holds (the golden included), each name once, in list order.
std::vector<const EngineInfo*> exact_engines();

}  // namespace trirast::test
