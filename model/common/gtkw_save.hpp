// The GTKWave save file (.gtkw) of a trace, one writer for every timed engine (the SystemC
// models' VCD, model/common/sc_vcd_trace.cpp; the Verilated RTL's FST, tb/common/cycle_loop.hpp):
//   * the dump named RELATIVE to the save file (with a [savefile] line, GTKWave resolves it from
//     the save file's folder), so the pair opens from any working directory and after a move;
//   * the zoom set to the traced window;
//   * signals in groups (one per module), buses in decimal (signed where a trace says so), bits as bits;
//   * state registers shown by name through GTKWave translate filter files, written beside the
//     save file (FILE.NAME.filter) and referenced from it by their relative names.
// Every file goes to a temporary name first and is renamed when complete (temporary_files.hpp).
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace trirast {

struct GtkwSave {
  struct Filter {
    std::string name;  // file FILE.<name>.filter
    std::vector<std::pair<uint64_t, std::string>> values;  // value -> label
  };
  struct Trace {
    std::string name;    // full name as GTKWave lists it, e.g. "improved.setup.state[2:0]"
    int width = 1;       // 1: shown as a bit; more: a bus in decimal
    std::string filter;  // a Filter's name, or empty
    bool is_signed = false;  // a bus shown in signed decimal
  };
  struct Group {
    std::string name;
    bool closed = false;  // collapsed when the file opens
    std::vector<Trace> traces;
  };

  std::string dump_path;  // the trace as the engine wrote it (any working directory)
  // The traced window in the dump's time units (its timescale); the view opens on it.
  uint64_t window_start = 0, window_end = 0;
  // The dump's time unit in GTKWave's internal time: GTKWave counts in the timescale's unit
  // (1 for "1ns" or "1ps"), in multiples for "10ps"/"100ps" (their factor: 10, 100).
  uint64_t time_factor = 1;
  std::vector<std::string> tree_open;  // scopes expanded in the hierarchy pane, e.g. "improved."
  std::vector<Filter> filters;
  std::vector<Group> groups;
};

// The .gtkw path of a trace: FILE.vcd / FILE.fst -> FILE.gtkw (other names: NAME.gtkw).
std::string gtkw_path_of(const std::string& trace_path);

// The path of `target` relative to the folder of `from_file` (both as given: relative to the
// working directory, or absolute).
std::string relative_to_file(const std::string& target, const std::string& from_file);

// Writes the save file and its filter files. Throws std::runtime_error naming the file on failure.
void write_gtkw(const std::string& gtkw_path, const GtkwSave& save);

}  // namespace trirast
