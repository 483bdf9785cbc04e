// The stage downstream of a unit's span output (docs/timing.md, "Sink patterns"; docs/embedding.md,
// "SystemC components"): it decides, cycle by cycle, whether it takes the span the unit offers. The SystemC models and the RTL
// harnesses drive the same object, so a downstream that reacts to what it received gives the same
// per-triangle cycles in both.
//
// The contract (what makes the two views agree):
//   - ready(c) is a function of c and of the spans taken in cycles before c, never of which cycles
//     were asked: the RTL harness asks every cycle, the SystemC model only the cycles in which a
//     span is on offer (and next_ready for the first ready cycle from a given one).
//   - The cycles asked never decrease; take(s, c) follows a ready(c) that answered true, at most
//     one span per cycle, in the unit's output order.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "common/sink_pattern.hpp"
#include "common/span.hpp"

namespace trirast {

struct RasterConfig;

class SpanDownstream {
 public:
  virtual ~SpanDownstream() = default;
  // Whether the downstream takes a span offered in cycle c.
  virtual bool ready(uint64_t cycle) = 0;
  // The first cycle >= c in which ready() would answer true (no span taken in between).
  virtual uint64_t next_ready(uint64_t c) {
    while (!ready(c)) ++c;
    return c;
  }
  // The span the unit's output handed over in cycle c (ready(c) was true).
  virtual void take(const Span& s, uint64_t cycle) = 0;
};

// A downstream whose ready is a function of the cycle alone: the --sink-stall patterns
// none | periodic:READY:STALL | random:SEED:PERCENT (sink_pattern.hpp).
class PatternDownstream : public SpanDownstream {
 public:
  explicit PatternDownstream(const SinkPattern& p) : pattern_(p) {}
  bool ready(uint64_t c) override { return pattern_.ready(c); }
  uint64_t next_ready(uint64_t c) override { return pattern_.next_ready(c); }
  void take(const Span&, uint64_t) override {}
  const SinkPattern& pattern() const { return pattern_; }

 private:
  SinkPattern pattern_;
};

// A downstream stage with a pixel queue (--sink-stall queue:RATE:CAPACITY): it consumes up to
// RATE pixels per cycle from its queue and is ready while the queue holds fewer than CAPACITY
// pixels at the start of the cycle; a span taken in cycle c adds its pixels in c, and the
// consumption of cycle c follows. Its ready depends on the spans it took: a reacting downstream.
class PixelQueueDownstream : public SpanDownstream {
 public:
  PixelQueueDownstream(uint64_t rate, uint64_t capacity) : rate_(rate), capacity_(capacity) {}
  bool ready(uint64_t c) override {
    advance(c);
    return queued_ < capacity_;
  }
  uint64_t next_ready(uint64_t c) override {
    advance(c);
    if (queued_ < capacity_) return c;
    const uint64_t over = queued_ - capacity_ + 1;  // pixels to consume before it is ready
    return c + (over + rate_ - 1) / rate_;
  }
  void take(const Span& s, uint64_t c) override {
    advance(c);
    queued_ += uint64_t(s.pixels());
  }
  uint64_t queued() const { return queued_; }  // pixels in the queue at the start of the last cycle asked

 private:
  void advance(uint64_t c) {
    if (c <= at_) return;
    const uint64_t cycles = c - at_;
    queued_ = cycles >= (queued_ + rate_ - 1) / rate_ ? 0 : queued_ - cycles * rate_;
    at_ = c;
  }
  uint64_t rate_, capacity_;
  uint64_t queued_ = 0, at_ = 0;
};

// Makes a fresh downstream (one per run: a downstream has state).
using SpanDownstreamFactory = std::function<std::unique_ptr<SpanDownstream>()>;

// The downstream a --sink-stall text names: none, periodic:READY:STALL, random:SEED:PERCENT,
// queue:RATE:CAPACITY; throws std::invalid_argument naming --sink-stall otherwise.
std::unique_ptr<SpanDownstream> make_span_downstream(const std::string& text);
// A run's downstream: cfg.downstream's when a program set one, else the one cfg.sink_stall names.
std::unique_ptr<SpanDownstream> make_span_downstream(const RasterConfig& cfg);
// Whether the text names a downstream whose ready is a function of the cycle alone.
bool is_cycle_pattern(const std::string& text);

}  // namespace trirast
