// Output files are written whole or not at all: content goes to a temporary file beside the
// target, renamed over it only on commit(). A run that fails leaves no partial output behind.
#pragma once
#include <cstdio>
#include <stdexcept>
#include <string>

#include "common/temporary_files.hpp"

namespace trirast {

class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class OutputFile {
 public:
  // `option` names the command-line option the path came from, for error messages.
  OutputFile(const std::string& path, const std::string& option);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  FILE* stream() { return file_; }
  void write(const std::string& text);
  // Flushes, closes and renames the temporary file to the target path.
  void commit();

 private:
  std::string path_, option_, temp_path_;
  FILE* file_ = nullptr;
  TemporaryPath temp_;  // removed on failure and on SIGINT / SIGTERM
};

// Checks that `path` can be created (its directory exists and is writable) before a long run.
void check_output_path(const std::string& path, const std::string& option);

}  // namespace trirast
