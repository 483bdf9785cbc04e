// A unit's SystemC model as a component of a user's platform (docs/embedding.md, "SystemC
// components"): instantiate it in your own sc_main, any number of times, on your own clock
// period; bind its target socket to your triangle producer and its span port to your downstream
// stage; run your simulation with your own sc_start. The unit never calls sc_start.
//
//   triangles  tlm_utils::simple_target_socket (TLM-2.0, blocking transport, loosely timed):
//              a write of one TriangleSetup (data pointer, data length sizeof(TriangleSetup)).
//              The call's delay is the producer's local time offset when it offers the triangle;
//              on return it is the offset of the cycle the unit accepted it (the port's
//              backpressure: never earlier than offered). The unit computes the triangle's whole
//              way through inside the call (its stages, its spans' handshakes with the
//              downstream), stamped with cycles ahead of SystemC time: temporal decoupling, as a
//              loosely-timed initiator expects. A triangle the unit cannot hold (a width error)
//              answers TLM_GENERIC_ERROR_RESPONSE; error() tells why.
//   spans      sc_port<SpanOutIf>: the downstream (span_downstream.hpp's contract), asked
//              ready(cycle) / next_ready(cycle) and handed take(span, cycle) in output order,
//              with cycles that never decrease. Bind a module of your own that implements
//              SpanOutIf, or a SpanDownstreamChannel around any SpanDownstream.
//
// Cycle n of the unit is SystemC time start + n * period (start: construction, or the last
// restart()). A stream has no length known up front; records(), statistics() and idle_cycle()
// can be read at any time and cover the triangles accepted so far.
#pragma once
#include <cstdint>
#include <exception>
#include <map>
#include <memory>
#include <string>
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>
#include <vector>

#include "common/config.hpp"
#include "common/engine.hpp"
#include "common/setup.hpp"
#include "common/span_downstream.hpp"
#include "common/sc_span_fifo.hpp"

namespace trirast::sc {

// The interface a unit's span port binds to (a SpanDownstream that is a SystemC interface).
class SpanOutIf : public virtual sc_core::sc_interface, public SpanDownstream {};

// A channel around a plain SpanDownstream (a --sink-stall pattern, a PixelQueueDownstream, a
// program's own): bind a unit's span port to it. It keeps every span it passed on when asked to.
class SpanDownstreamChannel : public sc_core::sc_object, public SpanOutIf {
 public:
  explicit SpanDownstreamChannel(const char* name, std::unique_ptr<SpanDownstream> d = nullptr,
                                 SpanList* keep = nullptr)
      : sc_core::sc_object(name), d_(std::move(d)), keep_(keep) {}
  // Replaces the downstream (between streams) and where its spans are kept (null: nowhere).
  void reset(std::unique_ptr<SpanDownstream> d, SpanList* keep) {
    d_ = std::move(d);
    keep_ = keep;
  }
  SpanDownstream& downstream() { return *d_; }
  bool ready(uint64_t c) override { return d_->ready(c); }
  uint64_t next_ready(uint64_t c) override { return d_->next_ready(c); }
  void take(const Span& s, uint64_t c) override {
    if (keep_) keep_->push_back(s);
    d_->take(s, c);
  }

 private:
  std::unique_ptr<SpanDownstream> d_;
  SpanList* keep_;
};

class RasterUnitSc : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<RasterUnitSc> triangles;
  sc_core::sc_port<SpanOutIf> spans;

  // The unit with configuration cfg (its widths, N, FIFO depth, ...; cfg.sink_stall and
  // cfg.downstream are not the unit's: the downstream is what `spans` binds) on a clock of
  // `period`. Throws std::invalid_argument / WidthError for a configuration it cannot build.
  RasterUnitSc(sc_core::sc_module_name name, const RasterConfig& cfg,
               const sc_core::sc_time& period);

  // Starts a new stream in the current SystemC time: cycle 0 is now, the records and statistics
  // are cleared, the unit takes cfg. The unit must be idle (its last stream over: now at or past
  // time_of(idle_cycle())); throws std::logic_error otherwise. `trace`, when not null, records
  // the stream's signals (sc_vcd_trace.hpp; the caller sets its window and writes it).
  void restart(const RasterConfig& cfg, VcdRecorder* trace = nullptr);

  const sc_core::sc_time& period() const { return period_; }
  // SystemC time of cycle n of the current stream, and the first cycle at or after time t.
  sc_core::sc_time time_of(uint64_t n) const;
  uint64_t cycle_at(const sc_core::sc_time& t) const;

  // Per accepted triangle, in acceptance order: its cycles (docs/timing.md, "Outputs"). A
  // triangle's record is complete when its transport call returned.
  const std::vector<TriangleCycles>& records() const { return state_.records; }
  // Moves the records out (a caller done with the stream's records; records() is empty after).
  std::vector<TriangleCycles> take_records() { return std::move(state_.records); }
  // One past the latest done cycle of the records so far (0 before the first): the stream's
  // total cycles.
  uint64_t done_end_cycle() const { return done_end_; }
  // Room for n records, for a caller that knows the stream's length (saves the regrowth).
  void reserve_records(size_t n) { state_.records.reserve(n); }
  // The stream's work counters so far: busy_cycles.* / stall_cycles.* per module, the datapath's
  // counters (docs/sc-model.md, "Statistics").
  std::map<std::string, uint64_t> statistics() const;
  // The first cycle from which the unit holds no triangle and its port is ready (the stream's
  // end when no more triangles come).
  uint64_t idle_cycle() const;
  // The cycle from which the triangle port is ready for the next triangle.
  uint64_t port_ready_cycle() const { return port_ready_; }
  // The first error of the stream (a triangle answered with TLM_GENERIC_ERROR_RESPONSE), or null.
  std::exception_ptr error() const { return state_.error; }

  // Accepts triangle t offered in cycle `offered` (>= every earlier offer); returns the cycle it
  // was accepted in. The socket's b_transport in one call, for a caller that counts in cycles.
  uint64_t offer(const TriangleSetup& t, uint64_t offered);

 protected:
  // The unit's own part, implemented by each unit:
  //   begin_stream: its modules for the stream's configuration (state_ is set; declares the
  //                 trace's signals when state_.trace is set);
  //   accept:       triangle t, accepted in cycle a, at position pos of the stream, through the
  //                 whole unit; returns the first cycle the port is ready again;
  //   unit_idle_from: the first cycle from which no accepted triangle is inside;
  //   add_counters: the modules' busy and stall counters into work.
  virtual void begin_stream() = 0;
  virtual uint64_t accept(const TriangleSetup& t, size_t pos, uint64_t a) = 0;
  virtual uint64_t unit_idle_from() const = 0;
  virtual void add_counters(std::map<std::string, uint64_t>& work) const = 0;

  // For the constructor of the unit's class (its modules are built by then): the first stream.
  void start(const RasterConfig& cfg) { restart(cfg); }

  RunState state_;

 private:
  void b_transport(tlm::tlm_generic_payload& p, sc_core::sc_time& delay);
  void before_end_of_elaboration() override;

  sc_core::sc_time period_;
  sc_core::sc_time start_;  // the SystemC time of the stream's cycle 0
  uint64_t port_ready_ = 0;
  uint64_t done_end_ = 0;  // done_end_cycle()
};

}  // namespace trirast::sc
