#include "common/sc_engine.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include <vector>

#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "common/sc_raster_unit.hpp"
#include "common/span_downstream.hpp"

namespace trirast {
namespace sc {
namespace {

// SystemC prints a banner to stdout when its kernel starts; the CLI's stdout is for reports.
bool quiet_systemc() {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  return true;
}

// A downstream that notes every handshake's cycle for the trace (write_trace).
class TakeRecorder : public SpanDownstream {
 public:
  TakeRecorder(std::unique_ptr<SpanDownstream> d, std::vector<uint64_t>& takes)
      : d_(std::move(d)), takes_(takes) {}
  bool ready(uint64_t c) override { return d_->ready(c); }
  uint64_t next_ready(uint64_t c) override { return d_->next_ready(c); }
  void take(const Span& s, uint64_t c) override {
    takes_.push_back(c);
    d_->take(s, c);
  }

 private:
  std::unique_ptr<SpanDownstream> d_;
  std::vector<uint64_t>& takes_;
};

std::vector<ScUnit>& registered_units() {
  static std::vector<ScUnit> units;
  return units;
}

// The engine's producer of one unit: a loosely-timed TLM-2.0 initiator that sends a run's
// triangles back to back, keeps SystemC time through its quantum keeper and, after the last
// triangle, waits until the unit is idle.
class StreamProducer : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(StreamProducer);
  StreamProducer(sc_core::sc_module_name name, RasterUnitSc& unit)
      : sc_core::sc_module(name), out("out"), unit_(unit) {
    tlm_utils::tlm_quantumkeeper::set_global_quantum(unit.time_of(kQuantumCycles) -
                                                     unit.time_of(0));
    out.bind(unit.triangles);
    SC_THREAD(thread);
  }
  tlm_utils::simple_initiator_socket<StreamProducer> out;

  // Sends tris in the next sc_start().
  void begin(const std::vector<TriangleSetup>* tris) {
    tris_ = tris;
    finished_ = false;
    pending_ = true;
    start_ev_.notify(sc_core::SC_ZERO_TIME);
  }
  bool finished() const { return finished_; }

 private:
  // SystemC time catches up with the producer's local time at least once per this many cycles.
  static constexpr uint64_t kQuantumCycles = uint64_t(1) << 16;

  void thread() {
    tlm::tlm_generic_payload& p = payload_;
    for (;;) {
      while (!pending_) sc_core::wait(start_ev_);
      pending_ = false;
      quantum_.reset();
      for (const TriangleSetup& t : *tris_) {
        p.set_command(tlm::TLM_WRITE_COMMAND);
        p.set_address(0);
        p.set_data_ptr(reinterpret_cast<unsigned char*>(const_cast<TriangleSetup*>(&t)));
        p.set_data_length(sizeof(TriangleSetup));
        p.set_streaming_width(sizeof(TriangleSetup));
        p.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        sc_core::sc_time local = quantum_.get_local_time();
        out->b_transport(p, local);
        if (p.is_response_error()) break;  // the unit keeps the error (RasterUnitSc::error)
        quantum_.set_and_sync(local);
      }
      // The run ends in SystemC time when the unit is idle.
      const sc_core::sc_time end = unit_.time_of(unit_.idle_cycle());
      const sc_core::sc_time now = sc_core::sc_time_stamp();
      quantum_.set(end > now ? end - now : sc_core::SC_ZERO_TIME);
      quantum_.sync();
      finished_ = true;
    }
  }

  RasterUnitSc& unit_;
  const std::vector<TriangleSetup>* tris_ = nullptr;
  // A member, not a local of the thread: the thread never returns, and the payload's extension
  // array must be freed when the module is (LeakSanitizer).
  tlm::tlm_generic_payload payload_;
  tlm_utils::tlm_quantumkeeper quantum_;
  bool pending_ = false, finished_ = false;
  sc_core::sc_event start_ev_;
};

// Every registered unit with its producer and downstream channel, elaborated together on first
// use (SystemC elaborates once per process). One cycle is 1 ns.
struct World {
  bool quiet = quiet_systemc();
  struct Slot {
    std::unique_ptr<RasterUnitSc> unit;
    std::unique_ptr<SpanDownstreamChannel> downstream;
    std::unique_ptr<StreamProducer> producer;
  };
  std::vector<Slot> slots;

  World() {
    for (const ScUnit& u : registered_units()) {
      Slot s;
      s.unit = u.elaborate(u.name.c_str(), RasterConfig{}, sc_core::sc_time(1, sc_core::SC_NS));
      s.downstream = std::make_unique<SpanDownstreamChannel>((u.name + "_downstream").c_str());
      s.unit->spans.bind(*s.downstream);
      s.producer = std::make_unique<StreamProducer>((u.name + "_producer").c_str(), *s.unit);
      slots.push_back(std::move(s));
    }
  }
  static World& get() {
    static World w;
    return w;
  }
  Slot& slot(int u) { return slots.at(size_t(u)); }
};

// One run through the unit, from the current SystemC time. `takes`, when not null, gets every
// span's handshake cycle. Returns the wall-clock seconds.
double simulate(int unit, const SetupResult& setup, const RasterConfig& cfg, EngineResult& out,
                VcdRecorder* trace, std::vector<uint64_t>* takes = nullptr) {
  World::Slot& s = World::get().slot(unit);
  std::unique_ptr<SpanDownstream> d = make_span_downstream(cfg);
  if (takes) d = std::make_unique<TakeRecorder>(std::move(d), *takes);
  s.downstream->reset(std::move(d), &out.spans);
  s.unit->restart(cfg, trace);
  s.unit->reserve_records(setup.tris.size());
  s.producer->begin(&setup.tris);
  const auto t0 = std::chrono::steady_clock::now();
  sc_core::sc_start();
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (s.unit->error()) std::rethrow_exception(s.unit->error());
  if (!s.producer->finished() || s.unit->records().size() != setup.tris.size())
    throw std::runtime_error("SystemC model: the run stopped before its end");
  out.cycles = s.unit->take_records();
  out.total_cycles = s.unit->done_end_cycle();
  return secs;
}

// The trace: a second run that records the cycles from the one the first windowed triangle is on
// the port (offered: the cycle after its predecessor's accept, or cycle 0) to the last one's done
// (the first run found them), plus the downstream's ready in that window. The RTL's trace window
// starts on the same cycle (tb/common/cycle_loop.hpp), so the two line up in GTKWave.
void write_trace(int unit, const SetupResult& setup, const RasterConfig& cfg,
                 const EngineResult& first) {
  uint64_t lo = ~uint64_t(0), hi = 0;
  for (size_t i = 0; i < first.cycles.size(); ++i) {
    const TriangleCycles& c = first.cycles[i];  // setup order: offered back to back
    if (int64_t(c.tri) < cfg.trace_first) continue;
    if (cfg.trace_last >= 0 && int64_t(c.tri) > cfg.trace_last) continue;
    lo = std::min(lo, i == 0 ? uint64_t(0) : first.cycles[i - 1].accept_cycle + 1);
    hi = std::max(hi, c.done_cycle);
  }
  if (lo > hi) lo = hi = 0;  // no triangle in the window: an empty trace at cycle 0
  VcdRecorder rec;
  rec.set_window(lo, hi);
  EngineResult again;
  std::vector<uint64_t> takes;
  simulate(unit, setup, cfg, again, &rec, &takes);
  // span.ready (signal 1 of scope span, declared by the unit) as the downstream answers it every
  // cycle: a fresh one is asked each cycle up to the window's end and handed the run's spans in
  // their handshake cycles. A downstream always ready leaves the declared initial 1.
  std::unique_ptr<SpanDownstream> d = make_span_downstream(cfg);
  const auto* pattern = dynamic_cast<const PatternDownstream*>(d.get());
  if (!pattern || pattern->pattern().kind() != SinkPattern::Kind::Always) {
    const int ready = rec.find("span", "ready");
    bool prev = true;
    size_t next = 0;
    for (uint64_t c = 0; c <= hi; ++c) {
      const bool r = d->ready(c);
      if (c >= lo && (c == lo || r != prev)) rec.value(ready, c, r ? 1 : 0);
      prev = r;
      for (; next < takes.size() && takes[next] == c; ++next) d->take(again.spans[next], c);
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
    for (const auto& [key, v] : World::get().slot(unit_).unit->statistics()) out.work[key] += v;
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

std::unique_ptr<RasterUnitSc> make_raster_unit_sc(const std::string& unit, const char* name,
                                                  const RasterConfig& cfg,
                                                  const sc_core::sc_time& period) {
  for (const ScUnit& u : registered_units())
    if (u.name == unit) {
      quiet_systemc();
      return u.elaborate(name, cfg, period);
    }
  return nullptr;
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
