// The stage downstream of a unit's span output (model/common/span_downstream.hpp) and the RTL
// engines that drive it (tb/common/cycle_loop.hpp):
//   - SpanDownstream: the queue downstream (queue:RATE:CAPACITY) and the patterns on small cases
//     worked by hand from docs/timing.md "Sink patterns", next_ready against asking cycle by cycle
//     on random states, the --sink-stall texts;
//   - RtlDownstream: every RTL engine with a queue downstream gives the spans of its reference
//     (the golden, the traditional unit's C++ model) and is back-pressured by it; a program's own
//     downstream (RasterConfig::downstream) is driven as the contract says: asked every cycle,
//     cycles never decreasing, one take per handshake in the cycle of the handshake, the spans
//     taken being the run's spans in output order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/config.hpp"
#include "common/cycle_columns.hpp"
#include "common/setup.hpp"
#include "common/span_downstream.hpp"
#include "engines.hpp"
#include "golden/golden.hpp"
#include "support/rtl_helpers.hpp"
#include "trad/trad_bresenham.hpp"

namespace trirast {
namespace {

Span px_span(int64_t pixels, uint32_t tri = 0) { return Span{tri, 0, 0, int32_t(pixels)}; }

// ---- SpanDownstream: hand-computed cases -----------------------------------------------------

// queue:2:4, a 6-pixel span taken in cycle 0 (docs/timing.md's example): q(1) = 4 (not ready),
// q(2) = 2 (ready).
TEST(SpanDownstream, QueueWorkedExample) {
  PixelQueueDownstream q(2, 4);
  EXPECT_TRUE(q.ready(0));
  q.take(px_span(6), 0);
  EXPECT_FALSE(q.ready(1));
  EXPECT_EQ(q.queued(), 4u);
  EXPECT_EQ(q.next_ready(1), 2u);
  EXPECT_TRUE(q.ready(2));
  EXPECT_EQ(q.queued(), 2u);
}

// queue:1:4: ready while fewer than 4 pixels are queued at the start of the cycle; a span taken in
// c adds its pixels in c, then one pixel leaves at the end of c.
TEST(SpanDownstream, QueueFillsAndDrainsCycleByCycle) {
  PixelQueueDownstream q(1, 4);
  ASSERT_TRUE(q.ready(0));  // q(0) = 0
  q.take(px_span(3), 0);    // q(1) = 0 + 3 - 1 = 2
  ASSERT_TRUE(q.ready(1));
  EXPECT_EQ(q.queued(), 2u);
  q.take(px_span(3), 1);    // q(2) = 2 + 3 - 1 = 4: full
  EXPECT_FALSE(q.ready(2));
  EXPECT_EQ(q.queued(), 4u);
  EXPECT_TRUE(q.ready(3));  // q(3) = 3
  EXPECT_EQ(q.queued(), 3u);
  // Not taking: it drains one pixel a cycle down to 0 and stays there.
  EXPECT_TRUE(q.ready(5));  // q(5) = 1
  EXPECT_EQ(q.queued(), 1u);
  EXPECT_TRUE(q.ready(9));
  EXPECT_EQ(q.queued(), 0u);
}

// A span larger than the capacity is taken whole; the queue is then not ready until it drained
// below the capacity: queue:3:10 taking 100 pixels in cycle 5 has q(5 + k) = 100 - 3k.
TEST(SpanDownstream, QueueTakesASpanLargerThanItsCapacity) {
  PixelQueueDownstream q(3, 10);
  ASSERT_TRUE(q.ready(5));
  q.take(px_span(100), 5);
  EXPECT_EQ(q.next_ready(6), 36u);  // q(35) = 10, q(36) = 7
  PixelQueueDownstream a = q, b = q;
  EXPECT_FALSE(a.ready(35));
  EXPECT_EQ(a.queued(), 10u);
  EXPECT_TRUE(b.ready(36));
  EXPECT_EQ(b.queued(), 7u);
}

// Capacity 1: ready only with an empty queue. Two spans in one cycle are not allowed, so a span
// taken each ready cycle shows the pace: pixels / RATE cycles per span.
TEST(SpanDownstream, QueueCapacityOneWaitsForAnEmptyQueue) {
  PixelQueueDownstream q(2, 1);
  std::vector<uint64_t> taken;
  for (uint64_t c = 0; c < 20; ++c)
    if (q.ready(c)) {
      q.take(px_span(4), c);  // 4 pixels at 2 per cycle: empty again 2 cycles later
      taken.push_back(c);
    }
  EXPECT_EQ(taken, (std::vector<uint64_t>{0, 2, 4, 6, 8, 10, 12, 14, 16, 18}));
  PixelQueueDownstream r(1, 1);
  taken.clear();
  for (uint64_t c = 0; c < 20; ++c)
    if (r.ready(c)) {
      r.take(px_span(5), c);
      taken.push_back(c);
    }
  EXPECT_EQ(taken, (std::vector<uint64_t>{0, 5, 10, 15}));
}

// A pattern's ready is its SinkPattern's, whatever it took; periodic:2:3 is ready in 0, 1, 5, 6.
TEST(SpanDownstream, PatternIsItsSinkPatternAndIgnoresTakes) {
  PatternDownstream p(SinkPattern::parse("periodic:2:3"));
  std::vector<uint64_t> ready;
  for (uint64_t c = 0; c < 12; ++c)
    if (p.ready(c)) {
      p.take(px_span(1000), c);
      ready.push_back(c);
    }
  EXPECT_EQ(ready, (std::vector<uint64_t>{0, 1, 5, 6, 10, 11}));
  EXPECT_EQ(p.next_ready(2), 5u);
  EXPECT_EQ(p.next_ready(5), 5u);
  PatternDownstream none(SinkPattern::parse("none"));
  PatternDownstream random(SinkPattern::parse("random:7:30"));
  const SinkPattern r = SinkPattern::parse("random:7:30");
  for (uint64_t c = 0; c < 500; ++c) {
    EXPECT_TRUE(none.ready(c));
    EXPECT_EQ(random.ready(c), r.ready(c)) << c;
    random.take(px_span(50), c);
  }
}

// ---- SpanDownstream: random states ----------------------------------------------------------

// The queue of docs/timing.md written out: q(c + 1) = max(0, q(c) + p(c) - RATE).
struct QueueFormula {
  uint64_t rate, cap, q = 0;
};

// next_ready(c) is the first c' >= c with ready(c'), and ready(c) does not depend on which cycles
// were asked: random queues driven by random takes, asked every cycle (a) or only now and then
// (b), against the formula; then next_ready from random cycles against asking cycle by cycle.
TEST(SpanDownstream, QueueNextReadyIsTheFirstReadyCycleOnRandomStates) {
  std::mt19937_64 rng(0x5eed);
  int checked = 0, not_ready = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const uint64_t rate = 1 + rng() % 8, cap = 1 + rng() % 64;
    PixelQueueDownstream a(rate, cap), b(rate, cap);
    QueueFormula f{rate, cap};
    const uint64_t cycles = 1 + rng() % 200;
    for (uint64_t c = 0; c < cycles; ++c) {
      const bool ready = f.q < cap;
      ASSERT_EQ(a.ready(c), ready) << "trial " << trial << " cycle " << c;
      const bool ask_b = rng() % 3 == 0;
      if (ask_b) {
        ASSERT_EQ(b.ready(c), ready) << "trial " << trial << " cycle " << c;
      }
      uint64_t p = 0;
      if (ready && rng() % 2) {  // the unit offers a span
        p = 1 + rng() % 40;
        if (!ask_b) {
          ASSERT_TRUE(b.ready(c));  // a take follows a ready(c) that answered true
        }
        a.take(px_span(int64_t(p)), c);
        b.take(px_span(int64_t(p)), c);
      }
      f.q = f.q + p > rate ? f.q + p - rate : 0;
    }
    // From the state reached, next_ready from a random cycle at or after the last one asked.
    const uint64_t from = cycles + rng() % 20;
    PixelQueueDownstream scan = a;
    uint64_t first = from;
    while (!scan.ready(first)) ++first;
    EXPECT_EQ(a.next_ready(from), first) << "trial " << trial << " rate " << rate << " cap " << cap;
    not_ready += first > from;
    ++checked;
  }
  EXPECT_EQ(checked, 400);
  EXPECT_GT(not_ready, 20);  // the states include full queues, not only ready ones
}

TEST(SpanDownstream, PatternNextReadyIsTheFirstReadyCycleOnRandomStates) {
  std::mt19937_64 rng(0xbead);
  for (int trial = 0; trial < 300; ++trial) {
    const std::string text =
        trial % 2 ? "periodic:" + std::to_string(1 + rng() % 5) + ":" + std::to_string(rng() % 9)
                  : "random:" + std::to_string(rng() % 1000) + ":" + std::to_string(rng() % 96);
    PatternDownstream p(SinkPattern::parse(text));
    for (int k = 0; k < 10; ++k) {
      const uint64_t c = rng() % 100000;
      uint64_t first = c;
      while (!p.ready(first)) ++first;
      EXPECT_EQ(p.next_ready(c), first) << text << " from " << c;
    }
  }
}

// ---- the --sink-stall texts and a program's factory ------------------------------------------

std::string error_of(const std::string& text) {
  try {
    make_span_downstream(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(SpanDownstream, TextsMakeTheirDownstreams) {
  EXPECT_NE(dynamic_cast<PixelQueueDownstream*>(make_span_downstream("queue:2:16").get()), nullptr);
  for (const char* p : {"none", "periodic:2:3", "random:7:30"})
    EXPECT_NE(dynamic_cast<PatternDownstream*>(make_span_downstream(p).get()), nullptr) << p;
  for (const char* bad : {"queue:0:4", "queue:2:0", "queue:2", "queue:2:x", "queue::4", "queue"}) {
    const std::string msg = error_of(bad);
    EXPECT_NE(msg.find("--sink-stall"), std::string::npos) << bad << ": " << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
  RasterConfig cfg;
  cfg.sink_stall = "queue:3:5";
  ASSERT_NO_THROW(cfg.validate());
  EXPECT_NE(dynamic_cast<PixelQueueDownstream*>(make_span_downstream(cfg).get()), nullptr);
  int made = 0;
  cfg.downstream = [&made]() -> std::unique_ptr<SpanDownstream> {
    ++made;
    return std::make_unique<PatternDownstream>(SinkPattern::parse("periodic:1:1"));
  };
  EXPECT_NE(dynamic_cast<PatternDownstream*>(make_span_downstream(cfg).get()), nullptr);
  EXPECT_EQ(made, 1);
}

// ---- the RTL engines with a queue downstream -------------------------------------------------

const char* const kRtlEngines[] = {"improved-rtl", "improved2-rtl", "trad-rtl", "halfspace-rtl"};

// Medium triangles: spans of about ten pixels, which fill a queue of a few pixels per cycle.
SetupResult downstream_scene(const RasterConfig& cfg) {
  return test::scene("builtin:random:count=300,size=medium,seed=23", cfg);
}

EngineResult run_engine(const std::string& name, const SetupResult& setup, const RasterConfig& cfg) {
  const EngineInfo* e = find_engine(name);
  if (!e) throw std::logic_error("no engine " + name);
  EngineResult r;
  e->make()->run(setup, cfg, r);
  return r;
}

// The engine's spans: the golden's for the exact units, the C++ model's for the traditional one.
SpanList reference_spans(const std::string& name, const SetupResult& setup, const RasterConfig& cfg) {
  EngineResult r;
  (find_engine(name)->exact ? make_golden_engine() : make_trad_datapath_engine())->run(setup, cfg, r);
  sort_spans(r.spans);
  return r.spans;
}

// queue:2:16 and queue:1:4: the spans of the reference, the sink stalled (the queue back-pressured
// the unit), so the run is longer than with an always-ready sink.
TEST(RtlDownstream, QueueGivesTheReferenceSpansAndBackPressures) {
  for (const char* engine : kRtlEngines) {
    RasterConfig base;
    base.validate();
    const SetupResult setup = downstream_scene(base);
    const SpanList want = reference_spans(engine, setup, base);
    ASSERT_GT(want.size(), 100u);
    const EngineResult free_run = run_engine(engine, setup, base);
    EXPECT_EQ(free_run.work.at("stall_cycles.span_sink"), 0u) << engine;
    for (const char* queue : {"queue:2:16", "queue:1:4"}) {
      RasterConfig cfg = base;
      cfg.sink_stall = queue;
      cfg.validate();
      const std::string what = std::string(engine) + " " + queue;
      EngineResult r;
      ASSERT_NO_THROW(r = run_engine(engine, setup, cfg)) << what;
      sort_spans(r.spans);
      EXPECT_EQ(test::first_span_difference(r.spans, engine, want, "reference"), "") << what;
      EXPECT_EQ(r.cycles.size(), setup.tris.size()) << what;
      EXPECT_GT(r.work.at("stall_cycles.span_sink"), 0u) << what;
      EXPECT_GT(r.total_cycles, free_run.total_cycles) << what;
    }
  }
}

// ---- a program's own downstream --------------------------------------------------------------

// A downstream that records every question and every take and answers as the one it wraps.
struct Event {
  bool take;
  uint64_t cycle;
  bool ready;  // a question's answer
  Span span;   // a take's span
};

class RecordingDownstream : public SpanDownstream {
 public:
  RecordingDownstream(std::unique_ptr<SpanDownstream> inner, std::vector<Event>& log)
      : inner_(std::move(inner)), log_(log) {}
  bool ready(uint64_t c) override {
    const bool r = inner_->ready(c);
    log_.push_back(Event{false, c, r, Span{}});
    return r;
  }
  void take(const Span& s, uint64_t c) override {
    log_.push_back(Event{true, c, false, s});
    inner_->take(s, c);
  }

 private:
  std::unique_ptr<SpanDownstream> inner_;
  std::vector<Event>& log_;
};

// The log of one run against the contract and the run's outputs; returns "" or the first problem.
std::string check_log(const std::vector<Event>& log, const EngineResult& r) {
  std::vector<Span> taken;
  uint64_t next_question = 0;  // the RTL harness asks every cycle, from 0
  for (size_t i = 0; i < log.size(); ++i) {
    const Event& e = log[i];
    const std::string at = "event " + std::to_string(i) + " (cycle " + std::to_string(e.cycle) + ")";
    if (i > 0 && e.cycle < log[i - 1].cycle) return at + ": a cycle before the previous event's";
    if (!e.take) {
      if (e.cycle != next_question)
        return at + ": asked cycle " + std::to_string(e.cycle) + ", expected " +
               std::to_string(next_question) + " (every cycle, once)";
      ++next_question;
      continue;
    }
    // A take follows the question of its cycle, answered true, with no take in between.
    if (i == 0 || log[i - 1].take || log[i - 1].cycle != e.cycle || !log[i - 1].ready)
      return at + ": a take not right after a ready(c) that answered true";
    taken.push_back(e.span);
  }
  if (taken.size() != r.spans.size())
    return std::to_string(taken.size()) + " takes for " + std::to_string(r.spans.size()) + " spans";
  for (size_t k = 0; k < taken.size(); ++k)
    if (taken[k] != r.spans[k]) return "take " + std::to_string(k) + " is not the run's span " + std::to_string(k);
  // One take per handshake: as many as the sink's pops, each triangle's first and last in its
  // first_span_cycle and done_cycle.
  if (r.work.at("busy_cycles.span_sink") != taken.size())
    return std::to_string(taken.size()) + " takes for " +
           std::to_string(r.work.at("busy_cycles.span_sink")) + " handshakes";
  std::vector<uint64_t> first(r.cycles.size(), UINT64_MAX), last(r.cycles.size(), 0);
  for (size_t i = 0; i < log.size(); ++i) {
    if (!log[i].take) continue;
    for (size_t p = 0; p < r.cycles.size(); ++p)
      if (r.cycles[p].tri == log[i].span.tri) {
        first[p] = std::min(first[p], log[i].cycle);
        last[p] = std::max(last[p], log[i].cycle);
      }
  }
  for (size_t p = 0; p < r.cycles.size(); ++p) {
    if (r.cycles[p].spans == 0) continue;
    if (first[p] != r.cycles[p].first_span_cycle || last[p] != r.cycles[p].done_cycle)
      return "triangle " + std::to_string(r.cycles[p].tri) + ": takes in " +
             std::to_string(first[p]) + ".." + std::to_string(last[p]) + ", spans popped in " +
             std::to_string(r.cycles[p].first_span_cycle) + ".." +
             std::to_string(r.cycles[p].done_cycle);
  }
  return "";
}

// Every RTL engine with a program's downstream wrapping a queue and a pattern: the contract holds,
// the factory makes one downstream per run, and the run is the one --sink-stall names (a
// program's downstream takes the place of cfg.sink_stall's).
TEST(RtlDownstream, ProgramDownstreamSeesTheContract) {
  for (const char* engine : kRtlEngines)
    for (const char* inner : {"queue:1:4", "periodic:2:3"}) {
      const std::string what = std::string(engine) + " " + inner;
      RasterConfig cfg;
      cfg.validate();
      const SetupResult setup = test::scene("builtin:random:count=60,size=medium,seed=5", cfg);
      std::vector<Event> log;
      int made = 0;
      cfg.downstream = [&]() -> std::unique_ptr<SpanDownstream> {
        ++made;
        return std::make_unique<RecordingDownstream>(make_span_downstream(inner), log);
      };
      const EngineResult r = run_engine(engine, setup, cfg);
      EXPECT_EQ(made, 1) << what;
      ASSERT_GT(r.spans.size(), 20u) << what;
      EXPECT_EQ(check_log(log, r), "") << what;
      // The questions answered false: at least the sink's stall cycles (those with a span on offer).
      const uint64_t refused = uint64_t(
          std::count_if(log.begin(), log.end(), [](const Event& e) { return !e.take && !e.ready; }));
      EXPECT_GE(refused, r.work.at("stall_cycles.span_sink")) << what;
      EXPECT_GT(r.work.at("stall_cycles.span_sink"), 0u) << what;
      // The same run as --sink-stall INNER.
      RasterConfig by_text = cfg;
      by_text.downstream = nullptr;
      by_text.sink_stall = inner;
      const EngineResult t = run_engine(engine, setup, by_text);
      EXPECT_EQ(r.spans, t.spans) << what;
      std::string rows;
      EXPECT_EQ(test::cycle_rows_mismatch(r.cycles, "factory", t.cycles, "text", what, rows), 0u)
          << rows;
      int stats = 0;
      EXPECT_EQ(test::statistics_mismatch(t.work, r.work, {}, stats), "") << what;
      EXPECT_GE(stats, 10) << what;
    }
}

}  // namespace
}  // namespace trirast
