// The transaction-level waveform of a SystemC run (docs/sc-model.md, "Traces"): the modules report
// signal changes stamped with the cycle they take effect in (the model runs ahead of SystemC time
// inside a triangle, so changes arrive out of order); the recorder keeps those inside a cycle
// window, sorts them and writes a VCD plus a GTKWave save file (.gtkw) that groups the signals by
// module.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace trirast::sc {

class VcdRecorder {
 public:
  static constexpr uint64_t kX = ~uint64_t(0);  // value "unknown / none" (x in the VCD)

  // Declares a signal of `width` bits in module `scope` (e.g. "setup"). A counter signal is
  // driven by deltas (+1/-1) instead of values. Returns its handle.
  int add(const std::string& scope, const std::string& name, int width, uint64_t initial,
          bool counter = false);
  // Shows signal `sig` by name in GTKWave: a translate filter (value -> label) named `filter`,
  // written beside the .gtkw (core/gtkw_save.hpp). Filters of one name are declared once.
  void name_values(int sig, const std::string& filter,
                   const std::vector<std::pair<uint64_t, std::string>>& labels);

  // Only changes taking effect in cycles first..last are written; earlier ones make the values the
  // trace starts with.
  void set_window(uint64_t first, uint64_t last);
  uint64_t window_first() const { return first_; }
  uint64_t window_last() const { return last_; }

  // The signal takes value v from cycle `cycle` on. Several changes in one cycle: the last reported
  // wins.
  void value(int sig, uint64_t cycle, uint64_t v) {
    if (cycle > last_) return;
    if (cycle < first_) {
      Signal& s = signals_[sig];
      if (cycle >= s.initial_cycle) {
        s.initial = v;
        s.initial_cycle = cycle;
      }
      return;
    }
    changes_.push_back(Change{cycle, seq_++, sig, int64_t(v)});
  }
  // A counter signal changes by d from cycle `cycle` on.
  void delta(int sig, uint64_t cycle, int64_t d) {
    if (cycle > last_) return;
    if (cycle < first_) {
      signals_[sig].initial += uint64_t(d);
      return;
    }
    changes_.push_back(Change{cycle, seq_++, sig, d});
  }

  size_t changes() const { return changes_.size(); }
  // The handle of a declared signal; -1 when there is none.
  int find(const std::string& scope, const std::string& name) const {
    for (size_t i = 0; i < signals_.size(); ++i)
      if (signals_[i].scope == scope && signals_[i].name == name) return int(i);
    return -1;
  }

  // Writes the VCD (timescale: one cycle = 1 ns, time = the run's cycle number) under `top`, and
  // the .gtkw beside it (path with .vcd replaced by .gtkw; core/gtkw_save.hpp: the dump named
  // relative to it, the zoom on the window, one group per scope, states by name). A .fst path gets the VCD converted
  // by gtkwave's vcd2fst (and FILE.gtkw beside it). Each file goes to a temporary name
  // first and is renamed when complete. Throws std::runtime_error naming the file on failure.
  void write(const std::string& vcd_path, const std::string& top) const;

  // The .gtkw path written beside a VCD (or FST) path: FILE.vcd / FILE.fst -> FILE.gtkw.
  static std::string gtkw_path(const std::string& vcd_path);

 private:
  struct Signal {
    std::string scope, name;
    int width;
    bool counter;
    uint64_t initial;
    uint64_t initial_cycle;
    std::string filter;  // translate filter name, or empty
  };
  struct Change {
    uint64_t cycle;
    uint64_t seq;
    int sig;
    int64_t v;  // value, or delta for a counter
  };
  std::vector<Signal> signals_;
  std::vector<Change> changes_;
  std::vector<std::pair<std::string, std::vector<std::pair<uint64_t, std::string>>>> filters_;
  uint64_t first_ = 0, last_ = ~uint64_t(0);
  uint64_t seq_ = 0;
};

}  // namespace trirast::sc
