// sc_platform: a SystemC virtual platform of its own around trirast's units (docs/embedding.md).
//
//   producer --TLM-2.0--> improved2 unit  --spans--> fragment stage
//            --TLM-2.0--> half-space unit --spans--> fragment stage
//
// One sc_clock drives the platform; the producer reads a mesh (or a .tri file, or a built-in
// scene), sets its triangles up and sends each one to every unit through a loosely-timed
// initiator socket. Each unit feeds a fragment stage of this program: a queue of pixels that
// consumes at most K pixels per cycle and stops accepting spans while it holds Q pixels or more.
// At the end it prints each unit's triangles per cycle and the cycles its fragment stage stalled
// it.
//   sc_platform SCENE [--rate K] [--capacity Q] [--instances N] [--cycles-out DIR]
//               [--spans-out DIR] [--always-ready]
//     --instances N    N copies of each unit side by side (default 1)
//     --always-ready   fragment stages that accept every span at once (no backpressure)
//     --cycles-out DIR per unit and instance, DIR/UNIT.I.csv: the per-triangle cycles, the
//                      columns of `trirast raster --cycles`
//     --spans-out DIR  per unit and instance, DIR/UNIT.I.spans: "tri y x_begin x_end" per line,
//                      in output order; DIR/golden.spans: the golden's, in its order
// Exit status 0; 2 on bad input.
#include <tlm_utils/simple_initiator_socket.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include <trirast/common/config.hpp>
#include <trirast/common/sc_engine.hpp>
#include <trirast/common/sc_raster_unit.hpp>
#include <trirast/common/setup.hpp>
#include <trirast/golden/golden.hpp>
#include <trirast/halfspace/halfspace_sc.hpp>
#include <trirast/improved2/improved2_sc.hpp>
#include <trirast/scene/scene.hpp>

namespace {

using trirast::sc::RasterUnitSc;

// The fragment stage downstream of a unit: a pixel queue that consumes `rate` pixels per cycle
// and takes a span while it holds fewer than `capacity` pixels at the start of the cycle. The
// unit asks it ahead of SystemC time (temporal decoupling), so it keeps its queue as a function
// of the cycle: what it held at the last cycle asked, less what it consumed since.
class FragmentStage : public sc_core::sc_module, public trirast::sc::SpanOutIf {
 public:
  FragmentStage(sc_core::sc_module_name name, uint64_t rate, uint64_t capacity)
      : sc_core::sc_module(name), rate_(rate), capacity_(capacity) {}

  bool ready(uint64_t c) override {
    drain_to(c);
    return queued_ < capacity_;
  }
  void take(const trirast::Span& s, uint64_t c) override {
    drain_to(c);
    queued_ += uint64_t(s.pixels());
    pixels_ += uint64_t(s.pixels());
    spans.push_back(s);
  }
  uint64_t pixels() const { return pixels_; }
  std::vector<trirast::Span> spans;

 private:
  void drain_to(uint64_t c) {
    if (c <= at_) return;
    const uint64_t consumed = rate_ == 0 ? queued_ : (c - at_) * rate_;
    queued_ = consumed >= queued_ ? 0 : queued_ - consumed;
    at_ = c;
  }
  uint64_t rate_, capacity_, queued_ = 0, at_ = 0, pixels_ = 0;
};

// The producer: every set-up triangle to every unit, in order, through one initiator socket per
// unit; its local time runs ahead of SystemC time up to the global quantum.
class Producer : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(Producer);
  Producer(sc_core::sc_module_name name, const std::vector<trirast::TriangleSetup>& tris,
           std::vector<RasterUnitSc*> units)
      : sc_core::sc_module(name), tris_(tris), units_(std::move(units)) {
    for (size_t i = 0; i < units_.size(); ++i) {
      sockets_.push_back(std::make_unique<tlm_utils::simple_initiator_socket<Producer>>(
          ("out" + std::to_string(i)).c_str()));
      sockets_.back()->bind(units_[i]->triangles);
    }
    SC_THREAD(run);
  }
  bool done = false;

 private:
  // One stream per unit, each with its own local time: the units do not wait for each other.
  void run() {
    std::vector<sc_core::sc_time> local(units_.size(), sc_core::SC_ZERO_TIME);
    tlm::tlm_generic_payload p;
    for (const trirast::TriangleSetup& t : tris_) {
      for (size_t i = 0; i < units_.size(); ++i) {
        p.set_command(tlm::TLM_WRITE_COMMAND);
        p.set_data_ptr(reinterpret_cast<unsigned char*>(const_cast<trirast::TriangleSetup*>(&t)));
        p.set_data_length(sizeof t);
        p.set_streaming_width(sizeof t);
        p.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        (*sockets_[i])->b_transport(p, local[i]);
        if (p.is_response_error()) {
          std::fprintf(stderr, "sc_platform: %s refused triangle %u: %s\n", units_[i]->name(),
                       t.index, p.get_response_string().c_str());
          std::exit(1);
        }
      }
      // Synchronize once every stream is a quantum ahead of SystemC time.
      const sc_core::sc_time quantum = tlm::tlm_global_quantum::instance().get();
      sc_core::sc_time ahead = local[0];
      for (const sc_core::sc_time& l : local) ahead = std::min(ahead, l);
      if (ahead >= quantum) {
        sc_core::wait(ahead);
        for (sc_core::sc_time& l : local) l -= ahead;
      }
    }
    // Wait until every unit is idle (its last span handed over).
    sc_core::sc_time end = sc_core::sc_time_stamp();
    for (RasterUnitSc* u : units_) end = std::max(end, u->time_of(u->idle_cycle()));
    sc_core::wait(end - sc_core::sc_time_stamp());
    done = true;
    sc_core::sc_stop();
  }

  const std::vector<trirast::TriangleSetup>& tris_;
  std::vector<RasterUnitSc*> units_;
  std::vector<std::unique_ptr<tlm_utils::simple_initiator_socket<Producer>>> sockets_;
};

void write_spans(const std::string& path, const std::vector<trirast::Span>& spans) {
  std::ofstream f(path);
  for (const trirast::Span& s : spans) f << s.tri << ' ' << s.y << ' ' << s.x_begin << ' ' << s.x_end << '\n';
  if (!f) throw std::runtime_error(path + ": cannot write");
}

void write_cycles(const std::string& path, const std::vector<trirast::TriangleCycles>& records) {
  std::ofstream f(path);
  f << "tri,accept_cycle,first_span_cycle,done_cycle,spans,pixels,stall_cycles,setup_start_cycle,"
       "setup_done_cycle,handoff_cycle,walk_start_cycle,walk_end_cycle,divider_iterations,"
       "boundary_steps,box_width,box_height\n";
  for (const trirast::TriangleCycles& c : records)
    f << c.tri << ',' << c.accept_cycle << ',' << c.first_span_cycle << ',' << c.done_cycle << ','
      << c.spans << ',' << c.pixels << ',' << c.stall_cycles << ',' << c.setup_start_cycle << ','
      << c.setup_done_cycle << ',' << c.handoff_cycle << ',' << c.walk_start_cycle << ','
      << c.walk_end_cycle << ',' << c.divider_iterations << ',' << c.boundary_steps << ','
      << c.box_width << ',' << c.box_height << '\n';
  if (!f) throw std::runtime_error(path + ": cannot write");
}

uint64_t number(const char* option, const char* text) {
  char* end = nullptr;
  const unsigned long long v = std::strtoull(text, &end, 10);
  if (!*text || *end || v == 0 || v > 1000000000ull)
    throw std::invalid_argument(std::string(option) + ": '" + text + "' is not a whole number 1..10^9");
  return v;
}

}  // namespace

int sc_main(int argc, char** argv) {
  std::string scene_arg, cycles_dir, spans_dir;
  uint64_t rate = 4, capacity = 64, instances = 1;
  bool always_ready = false;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto value = [&]() -> const char* {
        if (i + 1 >= argc) throw std::invalid_argument(a + ": needs a value");
        return argv[++i];
      };
      if (a == "--rate") rate = number("--rate", value());
      else if (a == "--capacity") capacity = number("--capacity", value());
      else if (a == "--instances") instances = number("--instances", value());
      else if (a == "--cycles-out") cycles_dir = value();
      else if (a == "--spans-out") spans_dir = value();
      else if (a == "--always-ready") always_ready = true;
      else if (a.rfind("--", 0) == 0) throw std::invalid_argument(a + ": unknown option");
      else if (scene_arg.empty()) scene_arg = a;
      else throw std::invalid_argument(a + ": one scene only");
    }
    if (scene_arg.empty()) throw std::invalid_argument("usage: sc_platform SCENE [options]");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sc_platform: %s\n", e.what());
    return 2;
  }

  trirast::RasterConfig cfg;  // 1024x768, 8 subpixel bits, N = 1, FIFO 8: trirast's defaults
  trirast::SetupResult setup;
  try {
    setup = trirast::setup_scene(trirast::load_scene(scene_arg, cfg, {}).tris, cfg);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sc_platform: %s\n", e.what());
    return 2;
  }

  // The platform: one clock (2 ns), the units side by side, each with its fragment stage.
  sc_core::sc_clock clk("clk", 2, sc_core::SC_NS);
  tlm::tlm_global_quantum::instance().set(sc_core::sc_time(10, sc_core::SC_US));
  const uint64_t ready_capacity = always_ready ? ~uint64_t(0) : capacity;
  const uint64_t ready_rate = always_ready ? 0 : rate;
  struct Lane {
    std::string unit;
    std::unique_ptr<RasterUnitSc> model;
    std::unique_ptr<FragmentStage> fragments;
  };
  std::vector<Lane> lanes;
  std::vector<RasterUnitSc*> units;
  for (const char* unit : {"improved2", "halfspace"})
    for (uint64_t i = 0; i < instances; ++i) {
      Lane l;
      l.unit = unit;
      const std::string name = std::string(unit) + "_" + std::to_string(i);
      if (l.unit == "improved2")
        l.model = std::make_unique<trirast::sc::Improved2UnitSc>(name.c_str(), cfg, clk.period());
      else
        l.model = std::make_unique<trirast::sc::HalfspaceUnitSc>(name.c_str(), cfg, clk.period());
      l.fragments = std::make_unique<FragmentStage>((name + "_fragments").c_str(), ready_rate,
                                                    ready_capacity);
      l.model->spans.bind(*l.fragments);
      units.push_back(l.model.get());
      lanes.push_back(std::move(l));
    }
  Producer producer("producer", setup.tris, units);

  // The producer ends the simulation (the clock would run on): no "stopped by user" notice.
  sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO,
                                          sc_core::SC_DO_NOTHING);
  sc_core::sc_start();
  if (!producer.done) {
    std::fprintf(stderr, "sc_platform: the simulation ended before the producer\n");
    return 1;
  }

  std::printf("%zu triangles set up from %s; fragment stages: %s\n", setup.tris.size(),
              scene_arg.c_str(),
              always_ready ? "always ready"
                           : (std::to_string(rate) + " pixels per cycle, queue of " +
                              std::to_string(capacity) + " pixels").c_str());
  std::printf("%-12s %10s %10s %14s %14s %12s\n", "unit", "cycles", "pixels", "triangles/cycle",
              "stall cycles", "time (us)");
  for (Lane& l : lanes) {
    const uint64_t cycles = l.model->idle_cycle();
    const auto stats = l.model->statistics();
    const auto stall = stats.find("stall_cycles.span_sink");
    std::printf("%-12s %10llu %10llu %14.5f %14llu %12.3f\n", l.model->name(),
                static_cast<unsigned long long>(cycles),
                static_cast<unsigned long long>(l.fragments->pixels()),
                cycles ? double(setup.tris.size()) / double(cycles) : 0.0,
                static_cast<unsigned long long>(stall == stats.end() ? 0 : stall->second),
                l.model->time_of(cycles).to_seconds() * 1e6);
  }
  try {
    for (Lane& l : lanes) {
      const std::string base = l.model->name();
      if (!cycles_dir.empty()) write_cycles(cycles_dir + "/" + base + ".csv", l.model->records());
      if (!spans_dir.empty()) write_spans(spans_dir + "/" + base + ".spans", l.fragments->spans);
    }
    if (!spans_dir.empty()) {
      trirast::EngineResult golden;
      trirast::make_golden_engine()->run(setup, cfg, golden);
      write_spans(spans_dir + "/golden.spans", golden.spans);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sc_platform: %s\n", e.what());
    return 2;
  }
  return 0;
}
