#include "io/output_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace trirast {

namespace {
std::string dir_of(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}
}  // namespace

void check_output_path(const std::string& path, const std::string& option) {
  if (path.empty()) throw OutputError(option + ": empty file name");
  struct stat st;
  if (stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw OutputError(option + " " + path + ": is a directory");
  const std::string dir = dir_of(path);
  if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw OutputError(option + " " + path + ": directory " + dir + " does not exist");
  if (access(dir.c_str(), W_OK) != 0)
    throw OutputError(option + " " + path + ": directory " + dir + " is not writable");
}

OutputFile::OutputFile(const std::string& path, const std::string& option)
    : path_(path), option_(option) {
  check_output_path(path, option);
  temp_path_ = path + ".tmp" + std::to_string(getpid());
  temp_.reset(temp_path_);
  file_ = std::fopen(temp_path_.c_str(), "wb");
  if (!file_) throw OutputError(option + " " + path + ": cannot create: " + std::strerror(errno));
}

OutputFile::~OutputFile() {
  if (file_) std::fclose(file_);  // temp_ removes the file unless commit() released it
}

void OutputFile::write(const std::string& text) {
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size())
    throw OutputError(option_ + " " + path_ + ": write failed: " + std::strerror(errno));
}

void OutputFile::commit() {
  const bool ok = std::fflush(file_) == 0 && std::fclose(file_) == 0;
  file_ = nullptr;
  if (!ok) throw OutputError(option_ + " " + path_ + ": write failed: " + std::strerror(errno));
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0)
    throw OutputError(option_ + " " + path_ + ": cannot rename: " + std::strerror(errno));
  temp_.release();
}

}  // namespace trirast
