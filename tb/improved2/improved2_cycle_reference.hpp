// An independent, deliberately plain reading of docs/timing.md "The second-generation improved
// unit" for tests: it steps the unit one cycle at a time, every stage register (B, C, L, W), the
// span FIFO and the sink deciding from the values at the start of the cycle and committing at its
// end, as the document words it. The SystemC model improved2-sc must give the same per-triangle
// cycles. Slow and obvious on purpose: no stage computes another stage's cycle in advance.
#pragma once
#include <cstdint>
#include <deque>
#include <vector>

#include "common/engine.hpp"
#include "common/sink_pattern.hpp"
#include "common/span_downstream.hpp"
#include "common/cycle_reference.hpp"

namespace trirast::test {

// What the timing of one triangle depends on (the datapath's results, model/improved2_unit).
struct Ref2Triangle {
  uint32_t tri = 0;
  bool empty = false;                 // empty box: retires in B
  bool tiny = false;                  // the 2x2 direct test's job (no lanes)
  uint64_t digits_l = 0, digits_r = 0;  // the radix-16 corner unit's runs (E_L; E_R for lane jobs)
  uint64_t lane_cycles = 0;           // L: max over the three lanes (lane jobs)
  std::vector<uint64_t> row_pixels;   // the rows the walk stage goes through, in order: the
                                      // pixels of each row's span, 0 = no span
  // Passed through to the stage breakdown (the datapath's counts, not timing).
  uint64_t divider_iterations = 0, boundary_steps = 0, box_width = 0, box_height = 0;
};

// corner_radix16: the digit-serial corner unit (else products: values one cycle after entering C).
// The sink is a SpanDownstream driven by its contract (asked in the cycles a span is on offer,
// handed each popped span in its pop cycle), the spans as reference_span() (cycle_reference.hpp):
// triangle, the row's position in the walk, its pixels.
inline std::vector<TriangleCycles> reference2_cycles(const std::vector<Ref2Triangle>& tris,
                                                     bool corner_radix16, uint64_t n,
                                                     uint64_t depth, SpanDownstream& sink) {
  const size_t none = tris.size();
  std::vector<TriangleCycles> out = passed_through_rows(tris);
  // A stage register: the triangle it holds (none: empty) and, for C and L, the first cycle its
  // work is done (counted down cycle by cycle below).
  struct Stage {
    size_t tri;
    uint64_t left = 0;  // cycles of work left at the start of the cycle (0: ready)
  };
  Stage b{none}, c{none}, l{none};
  // W: the job, its next row, the spans of the group that went last cycle (pushed this cycle).
  size_t w = none, w_row = 0;
  bool w_spans = false;
  struct SpanRef {
    size_t tri;
    uint64_t pixels;
    size_t row;  // its position in the triangle's walk
  };
  std::vector<SpanRef> push_q;  // spans registered for the push
  std::deque<SpanRef> fifo;     // spans in the FIFO
  size_t next = 0;
  std::vector<bool> ready_seen(tris.size(), false);
  for (uint64_t t = 0; next < tris.size() || b.tri != none || c.tri != none || l.tri != none ||
                       w != none || !push_q.empty() || !fifo.empty();
       ++t) {
    if (t > 400000000) break;  // safety
    // ---- decisions from the values at the start of cycle t ----
    const bool pop = !fifo.empty() && sink.ready(t);
    // W: a group goes when the FIFO's count plus the registered push leaves room for N.
    bool w_go = false, w_last = false;
    std::vector<SpanRef> group;
    if (w != none) {
      if (fifo.size() + push_q.size() + n <= depth) {
        w_go = true;
        const std::vector<uint64_t>& rows = tris[w].row_pixels;
        for (uint64_t r = 0; r < n && w_row + r < rows.size(); ++r)
          if (rows[w_row + r]) group.push_back(SpanRef{w, rows[w_row + r], w_row + r});
        w_last = w_row + n >= rows.size();
      } else {
        ++out[w].stall_cycles;
      }
    }
    const bool w_free = w == none;  // the hand-off needs W idle at the start of the cycle
    // L: hands off when its job is ready and W is free.
    const bool l_ready = l.tri != none && l.left == 0;
    if (l_ready && !ready_seen[l.tri]) {
      out[l.tri].setup_done_cycle = t;
      ready_seen[l.tri] = true;
    }
    const bool handoff = l_ready && w_free;
    // C: moves to L when its values are ready and L is empty or handing off.
    const bool c_move = c.tri != none && c.left == 0 && (l.tri == none || handoff);
    // B: an empty box retires; otherwise it moves to C when C is empty or moving.
    const bool b_retire = b.tri != none && tris[b.tri].empty;
    const bool b_move = b.tri != none && !b_retire && (c.tri == none || c_move);
    // The port: accepts when B is empty, retiring or moving.
    const bool accept = next < tris.size() && (b.tri == none || b_retire || b_move);

    // ---- outputs of cycle t ----
    // A span's cycle is its pop: the first one of a triangle is its first span, the last its done.
    if (pop) {
      TriangleCycles& o = out[fifo.front().tri];
      if (o.spans == 0) o.first_span_cycle = t;
      o.done_cycle = t;
      ++o.spans;
      o.pixels += fifo.front().pixels;
      sink.take(reference_span(tris[fifo.front().tri].tri, fifo.front().row, fifo.front().pixels),
                t);
      fifo.pop_front();
    }
    if (b_retire) {  // an empty box: every column its retire cycle
      TriangleCycles& o = out[b.tri];
      o.first_span_cycle = o.done_cycle = o.setup_done_cycle = o.handoff_cycle = t;
      o.walk_start_cycle = o.walk_end_cycle = t;
    }
    if (w_go && w_last) {
      out[w].walk_end_cycle = t;
      if (!w_spans && group.empty())  // a job without spans is done in its last walk cycle
        out[w].first_span_cycle = out[w].done_cycle = t;
    }
    if (handoff) out[l.tri].handoff_cycle = t;
    if (accept) out[next].accept_cycle = t;

    // ---- the end of cycle t: every register takes its next value ----
    for (const SpanRef& s : push_q) fifo.push_back(s);  // the registered push enters the FIFO
    push_q.clear();
    if (w_go) {
      push_q = group;
      if (!group.empty()) w_spans = true;
      w_row += n;
      if (w_last) w = none;
    }
    if (handoff) {
      w = l.tri;
      w_row = 0;
      w_spans = false;
      out[w].walk_start_cycle = t + 1;
    }
    if (l.tri != none && l.left > 0) --l.left;
    if (handoff) l.tri = none;
    if (c_move) {
      const Ref2Triangle& x = tris[c.tri];
      l = Stage{c.tri, x.tiny ? 0 : x.lane_cycles};
    }
    if (c.tri != none && c.left > 0) --c.left;
    if (c_move) c.tri = none;
    if (b_move) {
      const Ref2Triangle& x = tris[b.tri];
      // Products: values one cycle after entering C. Radix 16: the first run (d_L digits) starts
      // as the triangle enters C, its result one cycle after its last digit; a lane job then runs
      // again for E_R (d_R digits) from the cycle after that result.
      uint64_t work = 0;
      if (corner_radix16) work = x.tiny ? x.digits_l : x.digits_l + 2 + x.digits_r;
      c = Stage{b.tri, work};
    }
    if (b_retire || b_move) b.tri = none;
    if (accept) {
      b.tri = next;
      out[next].setup_start_cycle = t + 1;
      ++next;
    }
  }
  return out;
}

// The same with a sink whose ready is a function of the cycle alone (a --sink-stall pattern).
inline std::vector<TriangleCycles> reference2_cycles(const std::vector<Ref2Triangle>& tris,
                                                     bool corner_radix16, uint64_t n,
                                                     uint64_t depth, const SinkPattern& sink) {
  PatternDownstream ds(sink);
  return reference2_cycles(tris, corner_radix16, n, depth, ds);
}

}  // namespace trirast::test
