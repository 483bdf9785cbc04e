// An independent, deliberately plain reading of docs/timing.md for tests: it steps the unit one
// cycle at a time (setup FSM, walk stage, FIFO, sink), each cycle deciding from the values at its
// start and committing at its end, exactly as the document words it. The SystemC model must give
// the same per-triangle cycles. Slow and obvious on purpose (no look-ahead, no closed forms).
#pragma once
#include <algorithm>
#include <cstdint>
#include <deque>
#include <vector>

#include "common/engine.hpp"
#include "common/sink_pattern.hpp"
#include "common/span_downstream.hpp"

namespace trirast::test {

// What the timing of one triangle depends on.
struct RefTriangle {
  uint32_t tri = 0;
  bool retire_in_setup = false;      // empty box (improved) / collinear (trad): retires in a + 1
  uint64_t setup_cycles = 0;         // cycles from accept to the first StHold cycle (3 + L, trad 3)
  std::vector<uint64_t> row_cost;    // cycles of each row (improved: 1)
  std::vector<uint64_t> row_pixels;  // pixels of each row's span, 0 = no span
  // Passed through to the stage breakdown (the unit model's counts, not timing).
  uint64_t divider_iterations = 0, boundary_steps = 0, box_width = 0, box_height = 0;
};

// One row per triangle before any timing: its index and the counts passed through to the stage
// breakdown (RefTriangle here, Ref2Triangle in improved2_cycle_reference.hpp).
template <class Tri>
std::vector<TriangleCycles> passed_through_rows(const std::vector<Tri>& tris) {
  std::vector<TriangleCycles> out(tris.size());
  for (size_t i = 0; i < tris.size(); ++i) {
    out[i] = TriangleCycles{tris[i].tri, 0, 0, 0, 0, 0, 0};
    out[i].divider_iterations = tris[i].divider_iterations;
    out[i].boundary_steps = tris[i].boundary_steps;
    out[i].box_width = tris[i].box_width;
    out[i].box_height = tris[i].box_height;
  }
  return out;
}

// rows_per_group: N for the improved unit (each group costs one cycle, row_cost all 1); 1 for the
// traditional unit (a row costs row_cost cycles, its span pushed in its last cycle). The FIFO room
// test is made at the start of every group (improved: count <= DEPTH - N) or row (trad:
// count <= DEPTH - 1).
//
// The sink is a SpanDownstream (common/span_downstream.hpp) driven by its contract: asked in the
// cycles a span is on offer, handed each popped span in its pop cycle. The reference knows a
// span's triangle and pixels, not its coordinates: it hands over the stand-in span
// reference_span() (the triangle's scene index, the row's position in its walk, x from 0).
inline Span reference_span(uint32_t tri, size_t row, uint64_t pixels) {
  return Span{tri, int32_t(row), 0, int32_t(pixels)};
}

inline std::vector<TriangleCycles> reference_cycles(const std::vector<RefTriangle>& tris,
                                                    uint64_t rows_per_group, uint64_t depth,
                                                    SpanDownstream& sink) {
  std::vector<TriangleCycles> out = passed_through_rows(tris);
  struct Entry {
    size_t tri;
    size_t row;  // its position in the triangle's walk
  };
  std::deque<Entry> fifo;
  // Setup stage.
  size_t next = 0;  // next triangle on the port
  enum { Idle, Busy, Hold } st = Idle;
  size_t st_tri = 0;
  uint64_t st_until = 0;  // Busy: first Hold cycle; empty box: cycle it turns Idle
  bool st_empty = false;
  // Walk stage.
  bool walking = false;
  size_t w_tri = 0, w_row = 0;
  uint64_t w_left = 0;  // cycles left of the current row (trad)
  bool w_spans = false;
  size_t done_count = 0;
  for (uint64_t c = 0; done_count < tris.size() || !fifo.empty(); ++c) {
    if (c > 100000000) break;          // safety
    const size_t count = fifo.size();  // at the start of the cycle
    const bool walk_idle = !walking;   // at the start of the cycle
    // --- sink: pops the oldest span when ready ---
    bool pop = count > 0 && sink.ready(c);
    // --- walk stage ---
    std::vector<Entry> pushes;
    if (walking) {
      const RefTriangle& t = tris[w_tri];
      {
        if (w_left == 0) {
          // Start of a group (improved) or row (trad): FIFO room test.
          const uint64_t need = rows_per_group;
          if (count + need > depth) {
            ++out[w_tri].stall_cycles;
          } else if (rows_per_group > 1 || t.row_cost[w_row] == 1) {
            // One cycle does the whole group / row.
            for (uint64_t n = 0; n < rows_per_group && w_row < t.row_cost.size(); ++n, ++w_row)
              if (t.row_pixels[w_row]) pushes.push_back(Entry{w_tri, w_row});
          } else {
            w_left = t.row_cost[w_row] - 1;  // this cycle is the row's first
          }
        } else if (--w_left == 0) {
          if (t.row_pixels[w_row]) pushes.push_back(Entry{w_tri, w_row});
          ++w_row;
        }
        if (w_left == 0 && w_row == t.row_cost.size()) {
          walking = false;  // idle from c + 1
          out[w_tri].walk_end_cycle = c;
          if (!w_spans && pushes.empty()) {
            out[w_tri].first_span_cycle = out[w_tri].done_cycle = c;
            ++done_count;
          }
        }
        if (!pushes.empty()) w_spans = true;
      }
    }
    // --- setup stage ---
    bool load = false;
    size_t load_tri = 0;
    if (st == Idle) {
      if (next < tris.size()) {
        st_tri = next++;
        out[st_tri].accept_cycle = c;
        out[st_tri].setup_start_cycle = c + 1;
        st_empty = tris[st_tri].retire_in_setup;
        st = Busy;
        st_until = st_empty ? c + 2 : c + tris[st_tri].setup_cycles;
        out[st_tri].setup_done_cycle = st_empty ? c + 1 : st_until;
        if (st_empty) {
          TriangleCycles& o = out[st_tri];
          o.handoff_cycle = o.walk_start_cycle = o.walk_end_cycle = c + 1;
          out[st_tri].first_span_cycle = out[st_tri].done_cycle = c + 1;
          ++done_count;
        }
      }
    } else if (st == Busy) {
      if (c + 1 == st_until && st_empty)
        st = Idle;  // Idle from st_until
      else if (!st_empty && c + 1 == st_until)
        st = Hold;
    } else if (st == Hold) {
      if (walk_idle) {
        load = true;
        load_tri = st_tri;
        st = Idle;  // from c + 1
      }
    }
    // --- commit ---
    if (pop) {
      const size_t t = fifo.front().tri;
      sink.take(reference_span(tris[t].tri, fifo.front().row,
                               tris[t].row_pixels[fifo.front().row]),
                c);
      fifo.pop_front();
      TriangleCycles& o = out[t];
      if (o.spans == 0) o.first_span_cycle = c;
      o.done_cycle = c;
      ++o.spans;
      if (o.spans == uint64_t(std::count_if(tris[t].row_pixels.begin(), tris[t].row_pixels.end(),
                                            [](uint64_t p) { return p > 0; })))
        ++done_count;
    }
    for (const Entry& e : pushes) fifo.push_back(e);
    if (load) {
      out[load_tri].handoff_cycle = c;
      out[load_tri].walk_start_cycle = c + 1;
      walking = true;
      w_tri = load_tri;
      w_row = 0;
      w_left = 0;
      w_spans = false;
    }
  }
  for (size_t i = 0; i < tris.size(); ++i) {
    uint64_t px = 0;
    for (uint64_t p : tris[i].row_pixels) px += p;
    out[i].pixels = px;
  }
  return out;
}

// The same with a sink whose ready is a function of the cycle alone (a --sink-stall pattern).
inline std::vector<TriangleCycles> reference_cycles(const std::vector<RefTriangle>& tris,
                                                    uint64_t rows_per_group, uint64_t depth,
                                                    const SinkPattern& sink) {
  PatternDownstream ds(sink);
  return reference_cycles(tris, rows_per_group, depth, ds);
}

}  // namespace trirast::test
