#include "cli/source_files.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <climits>
#include <vector>

namespace trirast {

namespace {
bool exists(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

std::string executable_dir() {
  char buf[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return "";
  const std::string exe(buf, size_t(n));
  return exe.substr(0, exe.find_last_of('/'));
}
}  // namespace

std::string source_file(const std::string& relative) {
  std::vector<std::string> candidates;
#ifdef TRIRAST_SOURCE_DIR
  candidates.push_back(std::string(TRIRAST_SOURCE_DIR) + "/" + relative);
#endif
  const std::string exe_dir = executable_dir();
  if (!exe_dir.empty()) candidates.push_back(exe_dir + "/../" + relative);
  candidates.push_back(relative);
  for (const std::string& c : candidates)
    if (exists(c)) return c;
  return candidates.front();
}

}  // namespace trirast
