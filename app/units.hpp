// One descriptor per unit: its engines (views), the options its engines read, the engines whose
// per-triangle cycles must agree, its pipeline stages with their state names, and the words its
// per-triangle columns read in. Every command reads them (the engine list, the option checks of
// raster and compare, the JSON report, compare's cycle check, --explain, --slowest, --heatmap),
// so a unit is added in one place: app/units.cpp. The reference engines (golden, float-scanline)
// are not units; they have an entry of their own in the same list.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/engine.hpp"
#include "common/rtl_builds.hpp"

namespace trirast {

// One view of a unit: one engine, named "<unit>-<view>".
struct UnitView {
  std::string view;         // "datapath" (bit-accurate, untimed), "sc" (SystemC) or "rtl"
  std::string description;  // one line for `trirast engines`
  std::function<std::unique_ptr<Engine>()> make;
  bool timed = false;  // reports per-triangle cycles (and can write a trace)
  // An RTL view's Verilated builds (fuzz draws only widths they cover); nullptr otherwise.
  const std::vector<rtl::RtlBuild>& (*rtl_builds)() = nullptr;
};

// A pipeline stage of the unit, named as its SystemC model and RTL name it, with the states (or
// trace values) its waveform shows.
struct PipelineStage {
  std::string name;                 // "setup stage", "box stage (B)", ...
  std::vector<std::string> states;  // "StIdle", "StBox", ...; empty: a register without states
};

// How the unit's per-triangle columns (docs/timing.md, "Outputs") read in its own stages' words:
// the --explain and --slowest lines and the caption of --heatmap setup:FILE.
struct CycleWords {
  // The stage that holds a triangle until the port accepts the next one.
  std::string port_stage;
  // What setup_start_cycle .. setup_done_cycle - 1 spans ("set-up"), and a note inside its
  // parentheses (what else those cycles hold; empty: nothing).
  std::string setup_span;
  std::string setup_span_note;
  // Where a triangle whose set-up is done waits for the walk stage: "in StHold".
  std::string ready_wait;
  // The --heatmap legend's title of setup_done_cycle - accept_cycle (its 3x5 font has no j, q
  // or comma).
  std::string setup_title;
  // Where a triangle with nothing to walk (an empty box, collinear integer vertices) retires:
  // "retired in the setup stage".
  std::string retire;
  // What a per-triangle stall cycle is ("stall cycles in its walk").
  std::string stall;
  // A pipeline of box, corner and job stages (improved2): a triangle waits in the box stage
  // until the corner stage is free (the next accept is that cycle), and the job stage takes the
  // next job only once the walk stage took the previous one.
  bool job_stage = false;
};

struct UnitDescriptor {
  std::string name;   // "improved", "improved2", "trad", "halfspace": engines are <name>-<view>
  std::string title;  // "improved-Bresenham unit"
  bool exact = true;  // its spans follow the golden rule (docs/coverage-rule.md)
  std::vector<UnitView> views;
  // The raster / compare options every view reads, and those its timed views read as well.
  std::vector<std::string> options;
  std::vector<std::string> timed_options;
  // Engines that report the same per-triangle cycles, column for column (the SystemC model and
  // its RTL): compare checks them against each other.
  std::vector<std::string> timed_pair;
  std::vector<PipelineStage> stages;
  CycleWords words;
};

// Every engine, units' views and reference engines alike, in the order `trirast engines` lists.
struct EngineDescriptor {
  EngineInfo info;
  const UnitDescriptor* unit = nullptr;  // nullptr: a reference engine (golden, float-scanline)
  std::vector<std::string> options;      // the raster / compare options it reads (engine_options())
  const std::vector<rtl::RtlBuild>& (*rtl_builds)() = nullptr;
};

// The units, in the order `trirast engines` lists their views.
const std::vector<UnitDescriptor>& units();
const std::vector<EngineDescriptor>& engine_descriptors();
// nullptr when `name` is no engine.
const EngineDescriptor* find_engine_descriptor(const std::string& name);
// The unit of an engine; nullptr for a reference engine or an unknown name.
const UnitDescriptor* unit_of(const std::string& engine);

// The words of an engine's unit; an engine of no unit gets the setup stage / walk stage words.
const CycleWords& cycle_words(const std::string& engine);

// The options of raster and compare that only some engines read, in the order the JSON report
// records them. Every other scene or engine option (--width, --subpixel-bits, --coord-bits, ...)
// shapes every engine's run.
const std::vector<std::string>& engine_options();
// Whether `engine` reads `option` (one of engine_options()); false for an unknown engine.
bool engine_reads(const std::string& engine, const std::string& option);
// The engines that read `option`, as "a, b, c".
std::string engines_reading(const std::string& option);

}  // namespace trirast
