#include "cli/option_checks.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "cli/args.hpp"
#include "common/rtl_coverage.hpp"
#include "io/output_file.hpp"
#include "units.hpp"

namespace trirast {

void check_trace_engine(const EngineInfo& engine, const std::string& cmd) {
  if (!engine.timed)
    throw UsageError("trirast " + cmd + ": --trace: engine '" + engine.name +
                     "' is not timed (it has no cycles to trace); use a timed engine");
}

void check_trace_path(const std::string& path, const std::string& cmd) {
  auto ends_with = [&](const char* ext) {
    const size_t n = std::char_traits<char>::length(ext);
    return path.size() > n && path.compare(path.size() - n, n, ext) == 0;
  };
  if (!ends_with(".vcd") && !ends_with(".fst"))
    throw UsageError("trirast " + cmd + ": --trace " + path +
                     ": writes VCD or FST by the name's extension; name the file .vcd or .fst");
  check_output_path(path, "--trace");
}

void check_engine_options(const Args& a, const std::vector<std::string>& engines) {
  const std::string who = "trirast " + a.command() + ": ";
  // compare runs the golden besides its --engines, as the reference.
  const bool golden_runs = a.command() == "compare";
  for (const std::string& option : engine_options()) {
    if (!a.has(option)) continue;
    bool read = golden_runs && engine_reads("golden", option);
    std::vector<std::string> ignoring;  // the engines of `engines` that do not read it
    for (const std::string& engine : engines) {
      if (engine_reads(engine, option)) read = true;
      else if (std::find(ignoring.begin(), ignoring.end(), engine) == ignoring.end())
        ignoring.push_back(engine);
    }
    std::string names;
    for (const std::string& engine : ignoring)
      names += (names.empty() ? "'" : ", '") + engine + "'";
    const std::string applies = " (it applies to: " + engines_reading(option) + ")";
    if (!read && !golden_runs)
      throw UsageError(who + option + ": does not apply to engine " + names + applies);
    if (!read) throw UsageError(who + option + ": applies to none of the engines run" + applies);
    if (!ignoring.empty())
      std::fprintf(stderr, "%snote: %s: ignored by %s%s\n", who.c_str(), option.c_str(),
                   names.c_str(), applies.c_str());
  }
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

bool is_rtl_engine(const std::string& engine) {
  const EngineDescriptor* d = find_engine_descriptor(engine);
  return d && d->rtl_builds;
}

void check_coverage_option(const std::string& path, const std::vector<std::string>& engines,
                           const std::string& cmd) {
  std::string rtl;  // every RTL engine, for the message
  for (const EngineDescriptor& d : engine_descriptors())
    if (d.rtl_builds) rtl += (rtl.empty() ? "" : ", ") + d.info.name;
  if (std::none_of(engines.begin(), engines.end(), is_rtl_engine)) {
    std::string names;
    for (const std::string& e : engines) names += (names.empty() ? "'" : ", '") + e + "'";
    throw UsageError("trirast " + cmd + ": --coverage: engine " + names +
                     " has no cover points (it applies to the RTL engines: " + rtl + ")");
  }
  if (!rtl::rtl_coverage_built())
    throw UsageError("trirast " + cmd + ": --coverage: this build's Verilated models have no cover "
                     "points (configured with -DTRIRAST_RTL_COVERAGE=OFF)");
  check_output_path(path, "--coverage");
  rtl::reset_rtl_coverage();
}

std::string write_coverage_report(const std::string& path, const std::vector<std::string>& engines,
                                  const std::string& title) {
  std::vector<std::string> rtl_engines;
  for (const std::string& e : engines)
    if (is_rtl_engine(e)) rtl_engines.push_back(e);
  uint64_t hit = 0, total = 0;
  const std::string report = rtl::rtl_coverage_report(rtl_engines, title, hit, total);
  OutputFile out(path, "--coverage");
  out.write(report);
  out.commit();
  return "coverage: " + std::to_string(hit) + " of " + std::to_string(total) + " cover points hit";
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
