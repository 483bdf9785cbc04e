// ctest sc_platform_*: the units as components of a platform of the user's own (docs/embedding.md,
// "SystemC components"), one process per path that failed before the units were components:
//
//   from_thread  the user's clocked SC_THREAD sends the triangles, one per clock edge at the
//                earliest, and waits for each accept (was: E529, insert module failed: simulation
//                running, when the model elaborated itself from inside the user's thread)
//   built_first  the units are built before the user's own clock, modules and channels (was:
//                E113, insert primitive channel failed, after the model had run once)
//   after_clock  the user's free-running clock exists first, and the user's sc_start(duration),
//                called several times, runs the platform; the stream spans the calls (was: E554,
//                sc_start called unexpectedly, from the model's own sc_start)
//
// In each, the improved2 and half-space units (two instances of improved2) are instantiated in
// this sc_main beside the user's modules and run by the user's sc_start: their spans must equal
// the golden's and each unit's per-triangle cycles those of `trirast raster --cycles` with its
// SystemC engine (the same stream, downstream always ready; from_thread's triangles come at the
// clock edge after each accept, and the port is never ready before it).
//   platform_sc_main PATH SCENE
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <systemc>
#include <tlm_utils/simple_initiator_socket.h>
#include <vector>

#include "common/sc_raster_unit.hpp"
#include "common/setup.hpp"
#include "golden/golden.hpp"
#include "io/cycles_file.hpp"
#include "halfspace/halfspace_sc.hpp"
#include "improved2/improved2_sc.hpp"
#include "scene/scene.hpp"
#include "support/run_command.hpp"

namespace {

using trirast::sc::RasterUnitSc;
using trirast::sc::SpanDownstreamChannel;

int failures = 0;
void check(bool ok, const std::string& what) {
  if (!ok) {
    std::fprintf(stderr, "FAIL: %s\n", what.c_str());
    ++failures;
  }
}

// The per-triangle cycles as `trirast raster --cycles` writes them.
std::string cycles_csv(const std::vector<trirast::TriangleCycles>& records) {
  trirast::test::TempDir d;
  trirast::write_cycles_file(records, d.file("cycles.csv"), "records");
  return trirast::test::slurp(d.file("cycles.csv"));
}

// The CLI's per-triangle cycles of engine UNIT-sc on the scene (another process: this one's
// SystemC belongs to the platform).
std::string cli_cycles(const std::string& unit, const std::string& scene) {
  trirast::test::TempDir d;
  const std::string csv = d.file("cycles.csv");
  const trirast::test::CommandResult r = trirast::test::run_command(
      trirast::test::kBin + " raster --engine " + unit + "-sc --scene '" + scene + "' --cycles " +
      csv + " >/dev/null");
  check(r.status == 0, "trirast raster --engine " + unit + "-sc: " + r.err);
  return trirast::test::slurp(csv);
}

trirast::SpanList sorted(trirast::SpanList s) {
  trirast::sort_spans(s);
  return s;
}

// A unit, the downstream channel its span port binds (always ready) and the spans it received.
struct UnitUnderTest {
  std::string unit;
  trirast::SpanList spans;
  std::unique_ptr<RasterUnitSc> model;
  std::unique_ptr<SpanDownstreamChannel> downstream;
};

std::vector<std::unique_ptr<UnitUnderTest>> build_units(const trirast::RasterConfig& cfg,
                                                        const sc_core::sc_time& period) {
  std::vector<std::unique_ptr<UnitUnderTest>> units;
  for (const char* unit : {"improved2", "improved2", "halfspace"}) {
    auto u = std::make_unique<UnitUnderTest>();
    u->unit = unit;
    const std::string name = u->unit + std::to_string(units.size());
    if (u->unit == "improved2")
      u->model = std::make_unique<trirast::sc::Improved2UnitSc>(name.c_str(), cfg, period);
    else
      u->model = std::make_unique<trirast::sc::HalfspaceUnitSc>(name.c_str(), cfg, period);
    u->downstream = std::make_unique<SpanDownstreamChannel>(
        (name + "_downstream").c_str(), trirast::make_span_downstream("none"), &u->spans);
    u->model->spans.bind(*u->downstream);
    units.push_back(std::move(u));
  }
  return units;
}

// The user's producer: one initiator socket per unit. With a clock, an SC_THREAD sensitive to its
// rising edge offers each unit its next triangle at the first edge after the unit accepted the
// last one; without, it sends the stream back to back with local time (loosely timed).
class UserProducer : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(UserProducer);
  UserProducer(sc_core::sc_module_name name, const std::vector<trirast::TriangleSetup>& tris,
               std::vector<RasterUnitSc*> units, const sc_core::sc_clock* clk)
      : sc_core::sc_module(name), tris_(tris), units_(std::move(units)), clk_(clk) {
    for (size_t i = 0; i < units_.size(); ++i) {
      sockets_.push_back(std::make_unique<tlm_utils::simple_initiator_socket<UserProducer>>(
          ("out" + std::to_string(i)).c_str()));
      sockets_.back()->bind(units_[i]->triangles);
    }
    SC_THREAD(run);
    if (clk_) sensitive << clk_->posedge_event();
  }
  std::vector<std::vector<sc_core::sc_time>> offered;  // per unit: each triangle's offer time
  bool done = false;

 private:
  void send(size_t i, const trirast::TriangleSetup& t, sc_core::sc_time& delay) {
    tlm::tlm_generic_payload p;
    p.set_command(tlm::TLM_WRITE_COMMAND);
    p.set_data_ptr(reinterpret_cast<unsigned char*>(const_cast<trirast::TriangleSetup*>(&t)));
    p.set_data_length(sizeof t);
    p.set_streaming_width(sizeof t);
    (*sockets_[i])->b_transport(p, delay);
    check(p.is_response_ok(), std::string(units_[i]->name()) + " refused a triangle");
  }
  void run() {
    offered.assign(units_.size(), {});
    if (clk_) {
      // At each rising edge, every unit whose last triangle was accepted before the edge gets
      // its next one (offered in that cycle; the call returns the cycle it was accepted in).
      std::vector<size_t> next(units_.size(), 0);
      std::vector<sc_core::sc_time> free(units_.size(), sc_core::SC_ZERO_TIME);
      for (bool more = true; more;) {
        sc_core::wait();  // the next rising edge
        const sc_core::sc_time now = sc_core::sc_time_stamp();
        more = false;
        for (size_t i = 0; i < units_.size(); ++i) {
          if (next[i] < tris_.size() && now >= free[i]) {
            offered[i].push_back(now);
            sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
            send(i, tris_[next[i]++], delay);
            free[i] = now + delay + clk_->period();
          }
          more = more || next[i] < tris_.size();
        }
      }
    } else {
      std::vector<sc_core::sc_time> local(units_.size(), sc_core::SC_ZERO_TIME);
      for (const trirast::TriangleSetup& t : tris_)
        for (size_t i = 0; i < units_.size(); ++i) send(i, t, local[i]);
    }
    sc_core::sc_time end = sc_core::sc_time_stamp();
    for (RasterUnitSc* u : units_) end = std::max(end, u->time_of(u->idle_cycle()));
    sc_core::wait(end - sc_core::sc_time_stamp());
    done = true;
  }

  const std::vector<trirast::TriangleSetup>& tris_;
  std::vector<RasterUnitSc*> units_;
  const sc_core::sc_clock* clk_;
  std::vector<std::unique_ptr<tlm_utils::simple_initiator_socket<UserProducer>>> sockets_;
};

// A module of the user's own on the clock: counts rising edges through a signal it drives.
class EdgeCounter : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(EdgeCounter);
  EdgeCounter(sc_core::sc_module_name name, const sc_core::sc_clock& clk)
      : sc_core::sc_module(name), count("count") {
    SC_METHOD(tick);
    sensitive << clk.posedge_event();
    dont_initialize();
  }
  sc_core::sc_signal<unsigned> count;

 private:
  void tick() { count.write(count.read() + 1); }
};

}  // namespace

int sc_main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: platform_sc_main from_thread|built_first|after_clock SCENE\n");
    return 2;
  }
  const std::string path = argv[1], scene = argv[2];
  if (path != "from_thread" && path != "built_first" && path != "after_clock") {
    std::fprintf(stderr, "platform_sc_main: unknown path '%s'\n", path.c_str());
    return 2;
  }
  trirast::RasterConfig cfg;
  const trirast::SetupResult setup =
      trirast::setup_scene(trirast::load_scene(scene, cfg, {}).tris, cfg);
  trirast::EngineResult golden;
  trirast::make_golden_engine()->run(setup, cfg, golden);
  const trirast::SpanList golden_sorted = sorted(golden.spans);

  const sc_core::sc_time period(4, sc_core::SC_NS);
  std::vector<std::unique_ptr<UnitUnderTest>> units;
  if (path == "built_first") units = build_units(cfg, period);  // before anything of the user's
  sc_core::sc_clock clk("clk", period);
  EdgeCounter counter("counter", clk);
  sc_core::sc_signal<bool> user_channel("user_channel");  // a primitive channel of the user's
  if (path != "built_first") units = build_units(cfg, period);
  std::vector<RasterUnitSc*> models;
  for (auto& u : units) models.push_back(u->model.get());
  UserProducer producer("producer", setup.tris, models, path == "from_thread" ? &clk : nullptr);

  if (path == "after_clock") {
    // The user's sc_start in steps, the stream still under way after the first ones.
    const sc_core::sc_time step(20, sc_core::SC_US);
    for (int i = 0; i < 100000 && !producer.done; ++i) sc_core::sc_start(step);
  } else {
    // The clock runs for ever: the user stops once the producer is done.
    while (!producer.done) sc_core::sc_start(sc_core::sc_time(1, sc_core::SC_MS));
  }
  check(producer.done, "the producer did not finish");
  check(counter.count.read() > 0, "the user's clocked module never ran");
  std::printf("%s on %s: %zu triangles, %u clock edges of the user's module, %s\n", path.c_str(),
              scene.c_str(), setup.tris.size(), counter.count.read(),
              sc_core::sc_time_stamp().to_string().c_str());

  const std::string expected[2] = {cli_cycles("improved2", scene),
                                   cli_cycles("halfspace", scene)};
  for (size_t i = 0; i < units.size(); ++i) {
    UnitUnderTest& u = *units[i];
    const std::string who = std::string(u.model->name()) + " on " + scene;
    check(sorted(u.spans) == golden_sorted, who + ": spans differ from the golden's");
    check(u.model->records().size() == setup.tris.size(), who + ": not every triangle recorded");
    check(!u.model->error(), who + ": an error");
    check(cycles_csv(u.model->records()) == expected[u.unit == "improved2" ? 0 : 1],
          who + ": per-triangle cycles differ from trirast raster --cycles");
    if (path == "from_thread") {
      // Each triangle was offered at a rising edge of the user's clock (a whole cycle of the
      // unit), the edge after the last accept, and accepted then or when the port was ready.
      const auto& recs = u.model->records();
      check(producer.offered[i].size() == recs.size(), who + ": offers and records differ");
      for (size_t k = 0; k < recs.size() && k < producer.offered[i].size(); ++k) {
        const uint64_t edge = u.model->cycle_at(producer.offered[i][k]);
        check(u.model->time_of(edge) == producer.offered[i][k], who + ": an edge off the clock");
        check(edge == (k ? recs[k - 1].accept_cycle + 1 : 0), who + ": an offer at another edge");
        check(recs[k].accept_cycle >= edge, who + ": a triangle accepted before it was offered");
      }
    }
    std::printf("  %-12s %zu spans, idle from cycle %llu\n", u.model->name(), u.spans.size(),
                static_cast<unsigned long long>(u.model->idle_cycle()));
  }
  // Two instances of a unit give the same records.
  check(cycles_csv(units[0]->model->records()) == cycles_csv(units[1]->model->records()),
        "the two improved2 instances differ");
  if (failures) std::fprintf(stderr, "platform_sc_main %s: %d failure(s)\n", path.c_str(), failures);
  else std::printf("platform_sc_main %s: passed\n", path.c_str());
  return failures ? 1 : 0;
}
