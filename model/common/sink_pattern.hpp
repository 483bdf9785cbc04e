// The span sink's ready signal as a function of the cycle number alone (docs/timing.md, "Sink
// patterns"), so the SystemC model and the RTL testbench drive the same sequence.
#pragma once
#include <cstdint>
#include <string>

namespace trirast {

// splitmix64 finaliser of seed * 0x9E3779B97F4A7C15 + cycle (docs/timing.md).
uint64_t sink_mix(uint64_t seed, uint64_t cycle);

class SinkPattern {
 public:
  enum class Kind { Always, Periodic, Random };

  // "none" | "periodic:R:S" | "random:SEED:P"; throws std::invalid_argument naming --sink-stall.
  static SinkPattern parse(const std::string& text);

  bool ready(uint64_t cycle) const {
    switch (kind_) {
      case Kind::Periodic: return cycle % (ready_ + stall_) < ready_;
      case Kind::Random: return sink_mix(seed_, cycle) % 100 >= percent_;
      default: return true;
    }
  }
  // First cycle >= c in which the sink is ready.
  uint64_t next_ready(uint64_t c) const;

  Kind kind() const { return kind_; }
  uint64_t ready_cycles() const { return ready_; }
  uint64_t stall_cycles() const { return stall_; }
  uint64_t seed() const { return seed_; }
  uint64_t percent() const { return percent_; }
  std::string text() const;

 private:
  Kind kind_ = Kind::Always;
  uint64_t ready_ = 1, stall_ = 0, seed_ = 0, percent_ = 0;
};

}  // namespace trirast
