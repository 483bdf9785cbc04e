// The GTKWave save file of an RTL trace (core/gtkw_save.hpp writes it): the signals as the FST
// recording declares them (read back with GTKWave's FST reader, vendored in Verilator), one
// group per module instance (the top's ports open, the others closed), the setup and walk
// states by name through translate filters, the zoom on the traced window.
#pragma once
#include <cstdint>
#include <regex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtkwave/fstapi.h>

#include "common/gtkw_save.hpp"

namespace trirast::rtl {

// A state encoding (value, the RTL's enum name).
using StateNames = std::vector<std::pair<uint64_t, std::string>>;
// The state encodings of a unit's setup and walk stages (each harness's kStates).
struct UnitStates {
  StateNames setup, walk;
};
// The walk stage of the Bresenham units (rtl/improved/trirast_improved_walk_stage.sv, trirast_trad_walk_stage.sv).
inline const StateNames kWalkStageStates = {{0, "StWalkIdle"}, {1, "StWalk"}};

// Writes gtkw_path for the FST recording `fst_path` (the trace will be `trace_path`), whose
// window runs from dump time `start` to `end`. The recording's time unit is 100 ps (10 per cycle).
// The setup and walk stages' state registers (state_q, state_d in a scope named for the stage,
// the unit's setup_state_o, walk_state_o or walk_state) show the names of `states`.
inline void write_rtl_gtkw(const std::string& fst_path, const std::string& trace_path,
                           uint64_t start, uint64_t end, const UnitStates& states) {
  void* rd = fstReaderOpen(fst_path.c_str());
  if (!rd) throw std::runtime_error("--trace " + trace_path + ": cannot read the recording back");
  GtkwSave save;
  save.dump_path = trace_path;
  save.window_start = start;
  save.window_end = end;
  save.time_factor = 100;  // timescale 100ps: GTKWave counts in ps
  // (A unit without a setup state register, the second generation's pipelined setup, has none.)
  if (!states.setup.empty()) save.filters.push_back(GtkwSave::Filter{"setup_state", states.setup});
  save.filters.push_back(GtkwSave::Filter{"walk_state", states.walk});
  // The edge lane's phase (rtl/improved/trirast_improved_edge_lane.sv, localparams).
  save.filters.push_back(GtkwSave::Filter{
      "lane_phase", {{0, "PhSlope"}, {1, "PhTrav"}, {2, "PhEntry"}, {3, "PhDone"}}});
  std::vector<std::string> scope;
  std::vector<int> group_of;  // per scope depth: the group index of that scope (-1: none yet)
  int view_group = -1;        // the triangle port's per-vertex views (-1: none yet)
  auto path = [&]() {
    std::string p;
    for (const std::string& s : scope) p += (p.empty() ? "" : ".") + s;
    return p;
  };
  while (fstHier* h = fstReaderIterateHier(rd)) {
    if (h->htyp == FST_HT_SCOPE) {
      scope.emplace_back(h->u.scope.name, h->u.scope.name_length);
      group_of.push_back(-1);
    } else if (h->htyp == FST_HT_UPSCOPE) {
      if (!scope.empty()) {
        scope.pop_back();
        group_of.pop_back();
      }
    } else if (h->htyp == FST_HT_VAR && !scope.empty() && h->u.var.typ != FST_VT_VCD_PARAMETER &&
               scope.back().compare(0, 10, "unnamedblk") != 0) {
      // (Parameters are constants, and an unnamed block's variables loop counters: left out.)
      if (group_of.back() < 0) {
        group_of.back() = int(save.groups.size());
        // Scopes: the model's ports (1), the harness's top TOP_sim (2: the configuration
        // register and probes, scripts/gen_sim_top.py), the unit u_dut (3) and its instances.
        // The ports open; each module instance a closed group named by its path below the unit
        // ("u_setup.g_edge[0].u_lane"), the unit's own signals "top".
        constexpr size_t kUnitDepth = 3;
        std::string gname = scope.size() == 1               ? "ports"
                            : scope.size() == kUnitDepth - 1 ? "harness (configuration register)"
                            : scope.size() == kUnitDepth     ? "top"
                                                             : "";
        for (size_t i = kUnitDepth; i < scope.size(); ++i)
          gname += (i > kUnitDepth ? "." : "") + scope[i];
        save.groups.push_back(GtkwSave::Group{gname, scope.size() > 1, {}});
        if (scope.size() <= kUnitDepth) save.tree_open.push_back(path() + ".");
      }
      // FST names a bus "name [msb:lsb]"; GTKWave lists it as "name[msb:lsb]".
      std::string name(h->u.var.name, h->u.var.name_length);
      std::string shown;
      for (char ch : name)
        if (ch != ' ') shown += ch;
      // A one-bit bus "name[k:k]" GTKWave lists as "name[k]".
      const size_t colon = shown.rfind(':');
      const size_t open = shown.rfind('[');
      if (h->u.var.length == 1 && colon != std::string::npos && open != std::string::npos &&
          colon > open && shown.substr(open + 1, colon - open - 1) ==
                              shown.substr(colon + 1, shown.size() - colon - 2))
        shown = shown.substr(0, colon) + "]";
      const std::string base = shown.substr(0, shown.find('['));
      const std::string& leaf = scope.back();
      std::string filter;
      const bool setup_scope = leaf.find("setup") != std::string::npos;
      const bool walk_scope = leaf.find("walk") != std::string::npos;
      const bool state_reg = base == "state_q" || base == "state_d" || base == "state_o";
      if (base == "setup_state_o" || base == "setup_state" || (setup_scope && state_reg))
        filter = "setup_state";
      else if (base == "walk_state_o" || base == "walk_state" || (walk_scope && state_reg))
        filter = "walk_state";
      else if (leaf == "u_lane" && (base == "phase_q" || base == "phase_d"))
        filter = "lane_phase";
      // The harness top's trace views of the triangle port (scripts/gen_sim_top.py: tri_v0_x ..
      // tri_e2_c, one per vertex and edge): a group of their own, open, in signed decimal.
      static const std::regex kView("tri_(v[0-2]_[xy]|e[0-2]_[abc])");
      if (scope.size() == 2 && std::regex_match(base, kView)) {
        if (view_group < 0) {
          view_group = int(save.groups.size());
          save.groups.push_back(GtkwSave::Group{"triangle port, per vertex and edge (signed)", false, {}});
        }
        save.groups[size_t(view_group)].traces.push_back(
            GtkwSave::Trace{path() + "." + shown, int(h->u.var.length), "", true});
        continue;
      }
      save.groups[size_t(group_of.back())].traces.push_back(
          GtkwSave::Trace{path() + "." + shown, int(h->u.var.length), filter});
    }
  }
  fstReaderClose(rd);
  write_gtkw(gtkw_path_of(trace_path), save);
}

}  // namespace trirast::rtl
