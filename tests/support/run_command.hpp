// Runs a shell command for CLI tests and captures its exit status, stdout and stderr.
#pragma once
#include <string>

namespace trirast::test {

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

}  // namespace trirast::test
