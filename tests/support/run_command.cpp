#include "support/run_command.hpp"

#include <dirent.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "engines.hpp"

namespace trirast::test {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

int count_lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

std::vector<const EngineInfo*> exact_engines() {
  std::vector<const EngineInfo*> out;
  std::set<std::string> seen;
  for (const EngineInfo& e : engine_registry())
    if (e.exact && seen.insert(e.name).second) out.push_back(&e);
  return out;
}

CommandResult run_command(const std::string& command) {
  char tmpl[] = "/tmp/trirast-cmd-XXXXXX";
  const char* dir = mkdtemp(tmpl);
  if (!dir) throw std::runtime_error("mkdtemp failed");
  const std::string out = std::string(dir) + "/out", err = std::string(dir) + "/err";
  const int raw = std::system((command + " >" + out + " 2>" + err + " </dev/null").c_str());
  CommandResult r;
  if (WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
  else if (WIFSIGNALED(raw)) r.status = 128 + WTERMSIG(raw);
  r.out = slurp(out);
  r.err = slurp(err);
  std::remove(out.c_str());
  std::remove(err.c_str());
  rmdir(dir);
  return r;
}

TempDir::TempDir() {
  char tmpl[] = "/tmp/trirast-test-XXXXXX";
  const char* dir = mkdtemp(tmpl);
  if (!dir) throw std::runtime_error("mkdtemp failed");
  path_ = dir;
}

TempDir::~TempDir() { std::system(("rm -rf '" + path_ + "'").c_str()); }

int TempDir::entry_count() const {
  int n = 0;
  if (DIR* d = opendir(path_.c_str())) {
    while (dirent* e = readdir(d))
      if (std::string(e->d_name) != "." && std::string(e->d_name) != "..") ++n;
    closedir(d);
  }
  return n;
}

void write_file(const std::string& path, const std::string& content) {
  std::ofstream f(path, std::ios::binary);
  f << content;
}

bool file_exists(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

}  // namespace trirast::test
