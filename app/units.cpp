// The registration list: the reference engines and the four units. Adding a unit: include its
// engines' factory headers and add one descriptor below.
#include "units.hpp"

#include <algorithm>

#include "golden/golden.hpp"
#include "halfspace/halfspace_sc.hpp"
#include "improved/improved_sc.hpp"
#include "improved2/improved2_sc.hpp"
#include "trad/trad_sc.hpp"
#include "halfspace/halfspace_unit.hpp"
#include "improved2/improved2_unit.hpp"
#include "improved/improved_unit.hpp"
#include "improved/improved_rtl_engine.hpp"
#include "halfspace/halfspace_rtl_engine.hpp"
#include "improved2/improved2_rtl_engine.hpp"
#include "trad/trad_rtl_engine.hpp"

namespace trirast {

namespace {

// The timed units' shared options: the span FIFO and the sink (docs/timing.md, "Parameters").
const std::vector<std::string> kFifoAndSink = {"--fifo-depth", "--sink-stall"};

std::vector<std::string> plus(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The setup stage / walk stage wording of the units built as the first generation was
// (improved, trad, halfspace): a setup stage that ends in StHold, a walk stage after it.
CycleWords setup_and_walk_words(std::string stall) {
  CycleWords w;
  w.port_stage = "setup stage";
  w.setup_span = "set-up";
  w.ready_wait = "in StHold";
  w.setup_title = "set-up cycles per triangle (accept to hold)";
  w.retire = "retired in the setup stage";
  w.stall = std::move(stall);
  return w;
}

UnitDescriptor improved_unit() {
  UnitDescriptor u;
  u.name = "improved";
  u.title = "improved-Bresenham unit";
  u.views = {
      {"datapath", "improved-Bresenham unit, bit-accurate datapath model, untimed (docs/unit.md)",
       make_improved_datapath_engine},
      {"sc",
       "improved-Bresenham unit, SystemC model: the datapath's spans plus cycles (docs/timing.md)",
       make_improved_sc_engine, true},
      {"rtl", "improved-Bresenham unit, Verilated RTL (rtl/improved/trirast_improved.f)", make_improved_rtl_engine,
       true, rtl::improved_builds},
  };
  u.options = {"--box-bits", "--boundary", "--divider"};
  u.timed_options = plus({"--endpoints"}, kFifoAndSink);
  u.timed_pair = {"improved-sc", "improved-rtl"};
  u.stages = {
      {"setup stage", {"StIdle", "StBox", "StEdge", "StLanes", "StHold"}},
      {"walk stage", {"StWalkIdle", "StWalk"}},
      {"span FIFO", {}},
  };
  u.words = setup_and_walk_words("in its walk: FIFO full");
  return u;
}

UnitDescriptor improved2_unit() {
  UnitDescriptor u;
  u.name = "improved2";
  u.title = "second-generation improved unit";
  u.views = {
      {"datapath",
       "second-generation improved unit, bit-accurate datapath, untimed (docs/improved2.md)",
       make_improved2_datapath_engine},
      {"sc",
       "second-generation improved unit, SystemC model: its spans plus cycles, N = 1, 2, 4 "
       "(docs/improved2.md)",
       make_improved2_sc_engine, true},
      {"rtl",
       "second-generation improved unit, Verilated RTL (rtl/improved2/trirast_improved2.f): improved2-sc's "
       "spans and cycles",
       make_improved2_rtl_engine, true, rtl::improved2_builds},
  };
  // Step boundary and the adaptive divider are built in; the corner form changes only cycles.
  u.options = {"--box-bits"};
  u.timed_options = plus({"--corner-form", "--endpoints"}, kFifoAndSink);
  u.timed_pair = {"improved2-sc", "improved2-rtl"};
  // The stages and the values their trace signals show (improved2_sc.hpp; the RTL has the same
  // registers and no state enumerations).
  u.stages = {
      {"box stage (B)", {}},
      {"corner stage (C), its corner unit", {"Idle", "RunL", "RunR", "Products"}},
      {"job stage (L), each lane", {"Idle", "Slope", "Entry", "Traverse"}},
      {"walk stage (W)", {"StWalkIdle", "StWalkLanes", "StWalkTiny"}},
      {"span FIFO", {}},
  };
  // setup_done_cycle is the first cycle its job could be handed off: from accept + 1 to there it
  // is in B, C and L, and waits there for C or L to be free are part of those cycles.
  CycleWords& w = u.words;
  w.port_stage = "box stage (B)";
  w.setup_span = "box, corner and job stages (B, C, L)";
  w.setup_span_note = "waits for a free corner or job stage included";
  w.ready_wait = "in the job stage (L) with its job ready";
  w.setup_title = "cycles per triangle from accept to ready for the walk stage";
  w.retire = "retired in the box stage (B)";
  w.stall = "in its walk: FIFO full";
  w.job_stage = true;
  return u;
}

UnitDescriptor trad_unit() {
  UnitDescriptor u;
  u.name = "trad";
  u.title = "traditional Bresenham unit";
  u.exact = false;
  u.views = {
      {"sc",
       "traditional Bresenham unit (GR3-style edge walking), SystemC model with cycles; its own "
       "coverage, not the rule",
       make_trad_sc_engine, true},
      {"rtl",
       "traditional Bresenham unit, Verilated RTL (rtl/trad/trirast_trad.f): trad-sc's spans and cycles",
       make_trad_rtl_engine, true, rtl::trad_builds},
  };
  // No box bits, no divider, no N: one row per cycle at most.
  u.options = {};
  u.timed_options = kFifoAndSink;
  u.timed_pair = {"trad-sc", "trad-rtl"};
  u.stages = {
      {"setup stage", {"StIdle", "StSort", "StLine", "StHold"}},
      {"walk stage", {"StWalkIdle", "StWalk"}},
      {"span FIFO", {}},
  };
  u.words = setup_and_walk_words("in its walk: FIFO full");
  return u;
}

UnitDescriptor halfspace_unit() {
  UnitDescriptor u;
  u.name = "halfspace";
  u.title = "half-space tile unit";
  u.views = {
      {"datapath",
       "half-space (edge-function) tile unit, bit-accurate datapath, untimed (docs/unit.md)",
       make_halfspace_datapath_engine},
      {"sc",
       "half-space tile unit, SystemC model: the datapath's spans plus cycles (docs/timing.md)",
       make_halfspace_sc_engine, true},
      {"rtl",
       "half-space tile unit, Verilated RTL (rtl/halfspace/trirast_halfspace.f): halfspace-sc's spans and "
       "cycles",
       make_halfspace_rtl_engine, true, rtl::halfspace_builds},
  };
  // One span per cycle from its span emitter: --endpoints does not apply.
  u.options = {"--box-bits", "--stamp", "--tile", "--hs-walk"};
  // The corner form changes only the set-up's cycles.
  u.timed_options = plus({"--hs-corner-form"}, kFifoAndSink);
  u.timed_pair = {"halfspace-sc", "halfspace-rtl"};
  u.stages = {
      {"setup stage", {"StIdle", "StBox", "StEdge", "StHold"}},
      {"walk stage: tile walker", {"WIdle", "WUnit", "WStamp", "WWait", "WDrain"}},
      {"walk stage: span emitter", {}},
      {"span FIFO", {}},
  };
  // A triangle's stall cycles are its span emitter's pushes that found the FIFO full.
  u.words = setup_and_walk_words("of its span emitter: FIFO full");
  return u;
}

EngineDescriptor reference(std::string name, std::string description, bool exact,
                           std::function<std::unique_ptr<Engine>()> make,
                           std::vector<std::string> options) {
  EngineDescriptor d;
  d.info = {std::move(name), std::move(description), exact, std::move(make)};
  d.options = std::move(options);
  return d;
}

}  // namespace

const std::vector<UnitDescriptor>& units() {
  static const std::vector<UnitDescriptor> list = {improved_unit(), improved2_unit(), trad_unit(),
                                                   halfspace_unit()};
  return list;
}

const std::vector<EngineDescriptor>& engine_descriptors() {
  static const std::vector<EngineDescriptor> list = [] {
    std::vector<EngineDescriptor> out;
    // The golden traverses by --traversal on --threads; whatever it picks, its spans are the rule.
    out.push_back(reference(
        "golden", "half-space rasterizer, the coverage rule of docs/coverage-rule.md (the truth)",
        true, [] { return make_golden_engine(); }, {"--traversal", "--threads"}));
    for (const UnitDescriptor& u : units())
      for (const UnitView& v : u.views) {
        EngineDescriptor d;
        d.info = {u.name + "-" + v.view, v.description, u.exact, v.make, v.timed};
        d.unit = &u;
        d.options = v.timed ? plus(u.options, u.timed_options) : u.options;
        d.rtl_builds = v.rtl_builds;
        if (v.rtl_builds) d.options.push_back("--rtl-checked");
        out.push_back(d);
      }
    out.push_back(reference(
        "float-scanline",
        "float scanline with the top-left rule as ceil(x - 0.5): a CPU baseline, not exact", false,
        make_float_scanline_engine, {}));
    return out;
  }();
  return list;
}

const EngineDescriptor* find_engine_descriptor(const std::string& name) {
  for (const EngineDescriptor& d : engine_descriptors())
    if (d.info.name == name) return &d;
  return nullptr;
}

const UnitDescriptor* unit_of(const std::string& engine) {
  const EngineDescriptor* d = find_engine_descriptor(engine);
  return d ? d->unit : nullptr;
}

const std::vector<std::string>& engine_options() {
  static const std::vector<std::string> list = {
      "--box-bits",    "--boundary",  "--divider",    "--stamp",      "--tile",      "--hs-walk",
      "--corner-form", "--hs-corner-form", "--endpoints", "--fifo-depth", "--sink-stall", "--traversal", "--threads",
      "--rtl-checked"};
  return list;
}

bool engine_reads(const std::string& engine, const std::string& option) {
  const EngineDescriptor* d = find_engine_descriptor(engine);
  return d && std::find(d->options.begin(), d->options.end(), option) != d->options.end();
}

const CycleWords& cycle_words(const std::string& engine) {
  static const CycleWords kSetupAndWalk = setup_and_walk_words("in its walk: FIFO full");
  const UnitDescriptor* unit = unit_of(engine);
  return unit ? unit->words : kSetupAndWalk;
}

std::string engines_reading(const std::string& option) {
  std::string list;
  for (const EngineDescriptor& d : engine_descriptors())
    if (engine_reads(d.info.name, option)) list += (list.empty() ? "" : ", ") + d.info.name;
  return list;
}

}  // namespace trirast
