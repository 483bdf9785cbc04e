// Pixel-level golden traversals: simple (000 5.1, E from scratch at every pixel of the box),
// incremental (000 5.1, one add per step, leave a row at its end) and window search (001 3.3:
// start each row at the previous row's span and walk only as far as the span reaches).
#include "golden/golden.hpp"
#include "golden/traversal_common.hpp"
#include "common/fixed_point.hpp"

namespace trirast {

using golden_detail::EdgeValues;
using golden_detail::inside;

// Every pixel of the bounding box, each edge function evaluated from scratch: A*cx + B*cy + C.
void traverse_simple(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out) {
  if (t.box.empty()) return;
  for (int32_t y = t.box.y0; y <= t.box.y1; ++y) {
    const int64_t cy = pixel_centre(y, cfg);
    int32_t first = -1, last = -1;
    for (int32_t x = t.box.x0; x <= t.box.x1; ++x) {
      const int64_t cx = pixel_centre(x, cfg);
      int64_t e[3];
      for (int i = 0; i < 3; ++i) e[i] = t.edge[i].eval(cx, cy) + t.edge[i].bias;
      if (inside(e)) {
        if (first < 0) first = x;
        last = x;
      }
    }
    if (first >= 0) out.push_back(Span{t.index, y, first, last + 1});
  }
}

// Incremental edge functions over the box: the row start is stepped by B*u, each pixel by A*u.
void traverse_incremental(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out) {
  if (t.box.empty()) return;
  const EdgeValues ev(t, cfg);
  int64_t row[3] = {ev.origin[0], ev.origin[1], ev.origin[2]};
  for (int32_t y = t.box.y0; y <= t.box.y1; ++y) {
    int64_t e[3] = {row[0], row[1], row[2]};
    int32_t begin = -1;
    int32_t x = t.box.x0;
    for (; x <= t.box.x1; ++x) {
      const bool in = inside(e);
      if (in && begin < 0) begin = x;
      if (!in && begin >= 0) break;  // a row of a triangle is one run: leave at its end
      for (int i = 0; i < 3; ++i) e[i] += ev.dx[i];
    }
    if (begin >= 0) out.push_back(Span{t.index, y, begin, x});
    for (int i = 0; i < 3; ++i) row[i] += ev.dy[i];
  }
}

// Window search: each row starts at a guess (the previous row's first pixel). Inside: widen both
// ways to the span's ends. Outside: the failing edges say on which side the span lies (an edge with
// A > 0 admits a half-line to the right, A < 0 to the left, A == 0 all or nothing), so walk that
// way until inside; failing edges on both sides mean the row is empty. Only the span's pixels and
// the ones between the guess and the span are tested.
void traverse_window(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out) {
  if (t.box.empty()) return;
  const EdgeValues ev(t, cfg);
  const int32_t x0 = t.box.x0, x1 = t.box.x1;
  // First guess: the column of the topmost vertex, clamped to the box.
  int top = 0;
  for (int i = 1; i < 3; ++i)
    if (t.v[i].y < t.v[top].y) top = i;
  int32_t guess = int32_t(std::clamp<int64_t>(floor_div(t.v[top].x, cfg.unit()), x0, x1));
  // Which way the span lies from a pixel that failing edges reject: +1 right, -1 left, 0 nowhere.
  auto direction = [&](const int64_t e[3]) {
    int dir = 0;
    for (int i = 0; i < 3; ++i) {
      if (e[i] >= 0) continue;
      const int want = t.edge[i].A > 0 ? 1 : t.edge[i].A < 0 ? -1 : 2;
      if (want == 2 || (dir != 0 && dir != want)) return 0;
      dir = want;
    }
    return dir;
  };
  for (int32_t y = t.box.y0; y <= t.box.y1; ++y) {
    int64_t e[3];
    for (int i = 0; i < 3; ++i) e[i] = ev.at(i, guess, y);
    int32_t x = guess;
    if (!inside(e)) {
      const int dir = direction(e);
      if (dir == 0) continue;
      do {  // walk towards the span; stop at the box edge or when the row proves empty
        x += dir;
        if (x < x0 || x > x1) break;
        for (int i = 0; i < 3; ++i) e[i] += dir * ev.dx[i];
      } while (!inside(e) && direction(e) == dir);
      if (x < x0 || x > x1 || !inside(e)) continue;
    }
    // x is inside: widen to both ends of the run (scalars: the hot loops of this traversal).
    const int64_t d0 = ev.dx[0], d1 = ev.dx[1], d2 = ev.dx[2];
    int64_t l0 = e[0], l1 = e[1], l2 = e[2];
    int32_t begin = x;
    while (begin > x0) {
      l0 -= d0, l1 -= d1, l2 -= d2;
      if ((l0 | l1 | l2) < 0) break;
      --begin;
    }
    int64_t r0 = e[0], r1 = e[1], r2 = e[2];
    int32_t end = x + 1;
    while (end <= x1) {
      r0 += d0, r1 += d1, r2 += d2;
      if ((r0 | r1 | r2) < 0) break;
      ++end;
    }
    out.push_back(Span{t.index, y, begin, end});
    guess = begin;
  }
}

}  // namespace trirast
