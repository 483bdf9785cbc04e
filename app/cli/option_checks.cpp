#include "cli/option_checks.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "cli/args.hpp"
#include "io/output_file.hpp"

namespace trirast {

void check_trace_engine(const EngineInfo& engine, const std::string& cmd) {
  if (!engine.timed)
    throw UsageError("trirast " + cmd + ": --trace: engine '" + engine.name +
                     "' is not timed (it has no cycles to trace); use a timed engine");
}

void check_png_path(const std::string& path, const std::string& cmd, const std::string& option) {
  std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".png")
    throw UsageError("trirast " + cmd + ": " + option + " " + path +
                     ": writes PNG only; name the file .png");
  check_output_path(path, option);
}

void check_trace_window(int64_t first, int64_t last, uint64_t triangles, const std::string& cmd) {
  (void)last;
  if (uint64_t(first) >= triangles)
    throw UsageError("trirast " + cmd + ": --trace-tris: " + std::to_string(first) + ":" +
                     std::to_string(last) + " holds no triangle: the scene has " +
                     std::to_string(triangles) + " (indices 0.." +
                     (triangles ? std::to_string(triangles - 1) : std::string("none")) + ")");
}

OutputStamps::Stamp OutputStamps::stamp(const std::string& path) {
  Stamp s;
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) return s;
  s.exists = true;
  s.dev = st.st_dev;
  s.ino = st.st_ino;
  s.mtime_ns = int64_t(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec;
  s.size = int64_t(st.st_size);
  return s;
}

void OutputStamps::note(const std::string& path) { before_[path] = stamp(path); }

bool OutputStamps::written(const std::string& path) const {
  const Stamp now = stamp(path);
  if (!now.exists) return false;
  auto it = before_.find(path);
  return it == before_.end() || !(it->second == now);
}

}  // namespace trirast
