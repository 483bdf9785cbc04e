// The one face every engine shows: set-up triangles and a configuration in, spans and work
// statistics out. A new engine is one factory function and one line in app/engines.cpp.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/config.hpp"
#include "common/setup.hpp"
#include "common/span.hpp"

namespace trirast {

// Per-triangle timing of a cycle-level engine (model, rtl, trad with cycles).
struct TriangleCycles {
  uint32_t tri;
  uint64_t accept_cycle;
  uint64_t first_span_cycle;
  uint64_t done_cycle;
  uint64_t spans;
  uint64_t pixels;
  uint64_t stall_cycles;
  // The stage breakdown (docs/timing.md, "Outputs": the columns after stall_cycles).
  uint64_t setup_start_cycle = 0;   // first cycle the setup stage works on it (accept + 1)
  uint64_t setup_done_cycle = 0;    // first StHold cycle (retired in setup: its retire cycle)
  uint64_t handoff_cycle = 0;       // the walk stage loads it (retired in setup: retire cycle)
  uint64_t walk_start_cycle = 0;    // first StWalk cycle (handoff + 1; retired: retire cycle)
  uint64_t walk_end_cycle = 0;      // the cycle of its last group or row (retired: retire cycle)
  uint64_t divider_iterations = 0;  // the three lanes' divider cycles in set-up (trad: 0)
  uint64_t boundary_steps = 0;      // the three lanes' column steps in set-up (trad: 0)
  uint64_t box_width = 0;           // the box the unit walks, in pixels (0 when retired in setup)
  uint64_t box_height = 0;
};

struct EngineResult {
  SpanList spans;                      // in any order; callers sort with sort_spans()
  std::map<std::string, uint64_t> work;  // stage work counters, e.g. "divider_iterations"
  std::vector<TriangleCycles> cycles;  // empty for untimed engines
  uint64_t total_cycles = 0;           // 0 for untimed engines
};

class Engine {
 public:
  virtual ~Engine() = default;
  // Rasterizes every set-up triangle. Throws std::runtime_error (WidthError, ...) for a triangle
  // the engine's configuration cannot hold; never emits wrong spans silently.
  virtual void run(const SetupResult& setup, const RasterConfig& cfg, EngineResult& out) = 0;
};

// The untimed engine of a datapath model whose triangles are independent: a fresh Unit for the
// run's configuration takes every set-up triangle in order, appending its spans, and add_work
// adds what Unit::run_triangle returned into the work counters (the improved, trad and halfspace
// units; improved2 counts its triangles by kind and keeps its own engine).
template <class Unit, class AddWork>
class DatapathEngine : public Engine {
 public:
  explicit DatapathEngine(AddWork add_work) : add_work_(add_work) {}
  void run(const SetupResult& setup, const RasterConfig& cfg, EngineResult& out) override {
    Unit unit(cfg);
    for (const TriangleSetup& t : setup.tris) {
      add_work_(unit.run_triangle(t, out.spans), out.work);
      ++out.work["triangles"];
    }
  }

 private:
  AddWork add_work_;
};

template <class Unit, class AddWork>
std::unique_ptr<Engine> make_datapath_engine(AddWork add_work) {
  return std::make_unique<DatapathEngine<Unit, AddWork>>(add_work);
}

struct EngineInfo {
  std::string name;         // the --engine value
  std::string description;  // one line for --help
  bool exact;               // claims pixel-exact agreement with the golden rule
  std::function<std::unique_ptr<Engine>()> make;
  bool timed = false;       // reports per-triangle cycles (and can write a trace)
};

}  // namespace trirast
