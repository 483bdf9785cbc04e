// Simulated time of the SystemC model in clock cycles (docs/sc-model.md). One cycle is 1 ns of
// SystemC time; nothing ticks: the setup stage's process stamps work with its cycle and lets SystemC
// time catch up through its quantum keeper (stage_skeleton.hpp).
#pragma once
#include <cstdint>
#include <systemc>

namespace trirast::sc {

constexpr uint64_t kPsPerCycle = 1000;  // 1 cycle = 1 ns at SystemC's default 1 ps resolution

// SystemC time of n cycles.
inline sc_core::sc_time cycles_time(uint64_t n) {
  return sc_core::sc_time::from_value(n * kPsPerCycle);
}
// The current SystemC time in whole cycles (absolute: runs follow each other in one process).
inline uint64_t now_cycles() { return sc_core::sc_time_stamp().value() / kPsPerCycle; }

}  // namespace trirast::sc
