// Checks of command-line options that need more than their own text: the engine (--trace needs a
// timed one; an engine option must be one the engine reads), the scene (--trace-tris within its
// triangles), the file type (PNG only; a trace .vcd or .fst), and which output files a run
// actually wrote (for its "wrote" lines).
#pragma once
#include <sys/stat.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "cli/args.hpp"
#include "common/engine.hpp"

namespace trirast {

// Throws UsageError "trirast CMD: --trace: engine 'X' is not timed ..." for an untimed engine
// (one that reports no cycles: it has no waveform to trace).
void check_trace_engine(const EngineInfo& engine, const std::string& cmd);

// Throws UsageError "trirast CMD: --trace PATH: ..." unless `path` ends in .vcd or .fst (the
// format every timed engine then writes); then checks that the path can be written.
void check_trace_path(const std::string& path, const std::string& cmd);

// The engine options (units.hpp, engine_options()) given on the command line that an engine of
// the run does not read. raster (one engine): UsageError "trirast raster: --boundary: does not
// apply to engine 'improved2-sc' (it applies to: ...)". compare (`engines`, the golden always
// running besides them): UsageError when no engine of the run reads the option, else one note
// per option on stderr naming the engines of `engines` that ignore it.
void check_engine_options(const Args& a, const std::vector<std::string>& engines);

// Throws UsageError naming `option` unless `path` ends in .png (any case); then checks that the
// path can be written (check_output_path).
void check_png_path(const std::string& path, const std::string& cmd, const std::string& option);

// Throws UsageError naming --trace-tris and the scene's triangle count when the window A:B
// holds no triangle of a scene of `triangles` triangles.
void check_trace_window(int64_t first, int64_t last, uint64_t triangles, const std::string& cmd);

// Whether `engine` is a view with Verilated builds (an RTL engine, units.hpp).
bool is_rtl_engine(const std::string& engine);

// --coverage FILE (docs/coverage.md): the cover points of the RTL engines among `engines` (a view
// with Verilated builds, units.hpp). Refuses it when none of them is an RTL engine, or when the
// build has no cover points (TRIRAST_RTL_COVERAGE=OFF), and an unwritable FILE; clears the counts
// collected so far.
void check_coverage_option(const std::string& path, const std::vector<std::string>& engines,
                           const std::string& cmd);
// Writes the report of the RTL engines among `engines` to `path`; returns its summary line
// "coverage: H of T cover points hit".
std::string write_coverage_report(const std::string& path, const std::vector<std::string>& engines,
                                  const std::string& title);

// What was at each output path before a run: a path counts as written by the run when it exists
// afterwards and did not before, or is another file now (writers rename a new file over it).
class OutputStamps {
 public:
  void note(const std::string& path);
  bool written(const std::string& path) const;

 private:
  struct Stamp {
    bool exists = false;
    dev_t dev = 0;
    ino_t ino = 0;
    int64_t mtime_ns = 0;
    int64_t size = 0;
    bool operator==(const Stamp& o) const {
      return exists == o.exists && dev == o.dev && ino == o.ino && mtime_ns == o.mtime_ns &&
             size == o.size;
    }
  };
  static Stamp stamp(const std::string& path);
  std::map<std::string, Stamp> before_;
};

}  // namespace trirast
