#include "common/sc_engine.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include <vector>

#include "common/sc_stage_skeleton.hpp"

namespace trirast {
namespace sc {
namespace {

// SystemC prints a banner to stdout when its kernel starts; the CLI's stdout is for reports.
bool quiet_systemc() {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  return true;
}

std::vector<ScUnit>& registered_units() {
  static std::vector<ScUnit> units;
  return units;
}

// Every registered unit, elaborated together on first use (SystemC elaborates once per process).
struct World {
  bool quiet = quiet_systemc();
  std::vector<std::unique_ptr<UnitScIf>> units;

  World() {
    for (const ScUnit& u : registered_units()) units.push_back(u.elaborate());
  }
  static World& get() {
    static World w;
    return w;
  }
  UnitScIf& unit(int u) { return *units.at(size_t(u)); }
};

// One run through the unit, from the current SystemC time. Returns the wall-clock seconds.
double simulate(int unit, const SetupResult& setup, const RasterConfig& cfg, EngineResult& out,
                VcdRecorder* trace) {
  World& w = World::get();
  RunState r;
  r.cfg = cfg;
  r.sink = SinkPattern::parse(cfg.sink_stall);
  r.base = now_cycles();
  r.setup = &setup;
  r.out = &out;
  r.trace = trace;
  out.cycles.assign(setup.tris.size(), TriangleCycles{0, 0, 0, 0, 0, 0, 0});
  const auto t0 = std::chrono::steady_clock::now();
  w.unit(unit).run(r);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (r.error) std::rethrow_exception(r.error);
  if (!r.finished) throw std::runtime_error("SystemC model: the run stopped before its end");
  uint64_t total = 0;
  for (const TriangleCycles& c : out.cycles) total = std::max(total, c.done_cycle + 1);
  out.total_cycles = total;
  return secs;
}

// The trace: a second run that records the cycles from the first windowed triangle's accept to
// the last one's done (the first run found them), plus the sink's ready in that window.
void write_trace(int unit, const SetupResult& setup, const RasterConfig& cfg,
                 const EngineResult& first) {
  uint64_t lo = ~uint64_t(0), hi = 0;
  for (const TriangleCycles& c : first.cycles) {
    if (int64_t(c.tri) < cfg.trace_first) continue;
    if (cfg.trace_last >= 0 && int64_t(c.tri) > cfg.trace_last) continue;
    lo = std::min(lo, c.accept_cycle);
    hi = std::max(hi, c.done_cycle);
  }
  if (lo > hi) lo = hi = 0;  // no triangle in the window: an empty trace at cycle 0
  VcdRecorder rec;
  rec.set_window(lo, hi);
  EngineResult again;
  simulate(unit, setup, cfg, again, &rec);
  // span.ready is a function of the cycle alone (signal 1 of scope span, declared by the unit).
  const SinkPattern sink = SinkPattern::parse(cfg.sink_stall);
  if (sink.kind() != SinkPattern::Kind::Always) {
    const int ready = rec.find("span", "ready");
    bool prev = true;
    for (uint64_t c = lo; c <= hi; ++c) {
      const bool r = sink.ready(c);
      if (c == lo || r != prev) rec.value(ready, c, r ? 1 : 0);
      prev = r;
    }
  }
  rec.write(cfg.trace_path, registered_units().at(size_t(unit)).name);
}

class ScEngine : public Engine {
 public:
  explicit ScEngine(int unit) : unit_(unit) {}

  void run(const SetupResult& setup, const RasterConfig& cfg, EngineResult& out) override {
    cfg.validate();
    const ScUnit& unit = registered_units().at(size_t(unit_));
    if (unit.check_widths) unit.check_widths(cfg);  // the datapath's width limits
    const double secs = simulate(unit_, setup, cfg, out, nullptr);
    World::get().unit(unit_).add_counters(out.work);
    out.work["triangles"] += setup.tris.size();
    out.work["total_cycles"] = out.total_cycles;
    out.work["sim_wall_microseconds"] = uint64_t(secs * 1e6);
    out.work["sim_cycles_per_second"] = secs > 0 ? uint64_t(double(out.total_cycles) / secs) : 0;
    if (!cfg.trace_path.empty()) write_trace(unit_, setup, cfg, out);
  }

 private:
  int unit_;
};

}  // namespace

int register_sc_unit(ScUnit unit) {
  registered_units().push_back(std::move(unit));
  return int(registered_units().size()) - 1;
}

std::unique_ptr<Engine> make_sc_engine(int unit) {
  // Keeps the sc_main stub below in every program that can run a model.
  static volatile auto keep = &sc_main;
  (void)keep;
  return std::make_unique<ScEngine>(unit);
}

}  // namespace sc

}  // namespace trirast

// libsystemc.so's main() refers to sc_main. Programs with their own main() (the trirast CLI, the
// GoogleTest programs) never call it, but must link: this weak stub satisfies the reference, and a
// program's own sc_main (tests/sc/sc_test_main.cpp) replaces it.
extern "C" __attribute__((weak)) int sc_main(int, char**) {
  std::fprintf(stderr, "trirast: this program has no sc_main of its own\n");
  return 2;
}
