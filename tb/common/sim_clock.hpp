// Wall and process CPU time of an engine run, reported as the simulator's speed (the work counters
// sim_wall_microseconds, sim_cpu_microseconds, sim_cycles_per_second, sim_cycles_per_cpu_second).
#pragma once
#include <time.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <memory>

#include "common/engine.hpp"

namespace trirast {

class SimClock {
 public:
  SimClock() : wall0_(std::chrono::steady_clock::now()), cpu0_(cpu_seconds()) {}
  static double cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
  }
  // Adds the speed of the run so far (out.total_cycles simulated) to out.work.
  void report(EngineResult& out) const {
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0_).count();
    const double cpu = cpu_seconds() - cpu0_;
    const double cycles = double(out.total_cycles);
    out.work["sim_wall_microseconds"] = uint64_t(wall * 1e6);
    out.work["sim_cpu_microseconds"] = uint64_t(cpu * 1e6);
    out.work["sim_cycles_per_second"] = wall > 0 ? uint64_t(cycles / wall) : 0;
    out.work["sim_cycles_per_cpu_second"] = cpu > 0 ? uint64_t(cycles / cpu) : 0;
  }

 private:
  std::chrono::steady_clock::time_point wall0_;
  double cpu0_;
};

// An RTL engine's run (rtl_engine.cpp, rtl_trad_engine.cpp, rtl_hs_engine.cpp,
// rtl_improved2_engine.cpp): the X seed from TRIRAST_RTL_SEED (default 1; reported as work
// "rtl_x_seed"), the run, and its speed.
template <class Run>
void run_rtl_timed(EngineResult& out, Run&& run) {
  uint32_t seed = 1;
  if (const char* s = std::getenv("TRIRAST_RTL_SEED")) seed = uint32_t(std::strtoul(s, nullptr, 0));
  const SimClock clock;
  run(seed);
  clock.report(out);
}

// The Engine of an RTL unit: run(setup, cfg, seed, out) through run_rtl_timed.
template <class Run>
std::unique_ptr<Engine> make_timed_rtl_engine(Run run) {
  class TimedRtlEngine : public Engine {
   public:
    explicit TimedRtlEngine(Run r) : run_(r) {}
    void run(const SetupResult& setup, const RasterConfig& cfg, EngineResult& out) override {
      run_rtl_timed(out, [&](uint32_t seed) { run_(setup, cfg, seed, out); });
    }

   private:
    Run run_;
  };
  return std::make_unique<TimedRtlEngine>(run);
}

}  // namespace trirast
