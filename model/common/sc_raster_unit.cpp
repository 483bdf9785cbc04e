#include "common/sc_raster_unit.hpp"

#include <algorithm>
#include <stdexcept>

namespace trirast::sc {

RasterUnitSc::RasterUnitSc(sc_core::sc_module_name name, const RasterConfig& cfg,
                           const sc_core::sc_time& period)
    : sc_core::sc_module(name), triangles("triangles"), spans("spans"), period_(period) {
  if (period_ == sc_core::SC_ZERO_TIME)
    throw std::invalid_argument(std::string(this->name()) + ": the clock period is zero");
  cfg.validate();
  state_.cfg = cfg;
  triangles.register_b_transport(this, &RasterUnitSc::b_transport);
}

void RasterUnitSc::restart(const RasterConfig& cfg, VcdRecorder* trace) {
  const sc_core::sc_time now = sc_core::sc_time_stamp();
  if (!state_.records.empty() && now < time_of(idle_cycle()))
    throw std::logic_error(std::string(name()) + ": restart() while a triangle is inside the unit");
  cfg.validate();
  SpanDownstream* out = state_.downstream;
  state_ = RunState{};
  state_.cfg = cfg;
  state_.downstream = out;
  state_.trace = trace;
  start_ = now;
  port_ready_ = 0;
  done_end_ = 0;
  begin_stream();
}

sc_core::sc_time RasterUnitSc::time_of(uint64_t n) const {
  return sc_core::sc_time::from_value(start_.value() + n * period_.value());
}

uint64_t RasterUnitSc::cycle_at(const sc_core::sc_time& t) const {
  if (t <= start_) return 0;
  const uint64_t d = (t - start_).value(), p = period_.value();
  return (d + p - 1) / p;
}

std::map<std::string, uint64_t> RasterUnitSc::statistics() const {
  std::map<std::string, uint64_t> w = state_.work;
  add_counters(w);
  return w;
}

uint64_t RasterUnitSc::idle_cycle() const { return std::max(port_ready_, unit_idle_from()); }

void RasterUnitSc::before_end_of_elaboration() {
  // The unit's own port must be bound: a span port left open is a platform's mistake.
  if (spans.size() == 0)
    throw std::logic_error(std::string(name()) + ": the span port 'spans' is not bound");
}

uint64_t RasterUnitSc::offer(const TriangleSetup& t, uint64_t offered) {
  if (!state_.downstream) state_.downstream = spans.operator->();
  const uint64_t a = std::max(offered, port_ready_);
  port_ready_ = accept(t, state_.records.size(), a);
  // The triangle's record is complete (accept() ran it through the whole unit).
  done_end_ = std::max(done_end_, state_.records.back().done_cycle + 1);
  return a;
}

void RasterUnitSc::b_transport(tlm::tlm_generic_payload& p, sc_core::sc_time& delay) {
  if (p.get_command() != tlm::TLM_WRITE_COMMAND) {
    p.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return;
  }
  if (p.get_data_length() != sizeof(TriangleSetup) || p.get_data_ptr() == nullptr) {
    p.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
    return;
  }
  const sc_core::sc_time now = sc_core::sc_time_stamp();
  try {
    const uint64_t a =
        offer(*reinterpret_cast<const TriangleSetup*>(p.get_data_ptr()), cycle_at(now + delay));
    delay = time_of(a) - now;
    p.set_response_status(tlm::TLM_OK_RESPONSE);
  } catch (...) {
    if (!state_.error) state_.error = std::current_exception();
    p.set_response_status(tlm::TLM_GENERIC_ERROR_RESPONSE);
  }
}

}  // namespace trirast::sc
