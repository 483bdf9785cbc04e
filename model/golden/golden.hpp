// The golden half-space rasterizer: the truth for coverage. Every other engine is compared with
// it pixel for pixel. It applies docs/coverage-rule.md directly: integer edge functions evaluated
// at pixel centres, the top-left bias, the clipped bounding box.
//
// The golden comes in several traversals (docs/golden-performance.md). They differ only in which
// pixels they look at and how fast; every one decides coverage with the same exact integer test and
// emits the same spans: one span per covered row, rows in increasing y.
#pragma once
#include <memory>
#include <string>

#include "common/engine.hpp"

namespace trirast {

enum class Traversal {
  Simple,       // bounding box, every pixel tested with E evaluated from scratch (000 5.1 basic)
  Incremental,  // bounding box, incremental edge functions, leave a row at its end (000 5.1)
  Block,        // 8x8 blocks, trivial accept/reject by corner tests (000 5.2)
  Adaptive,     // block or incremental per triangle by the orientation metric 0.4..1.6 (000 5.3)
  Bisector,     // blocks walked outwards from the middle of the previous block row (000 5.5)
  SatBlock,     // block mask by separating-axis overlap, then traversal in overlapping blocks (004)
  Window,       // start each row's search at the previous row's span, early row exit (001 3.3)
  Scanline,     // exact per-row span bounds by quotient/remainder stepping: O(rows), no pixels
  Auto,         // the fastest of the above for each triangle (the default)
};

// Parses a --traversal value; throws std::invalid_argument
// "--traversal: unknown traversal 'x' (known: simple, incremental, ...)".
Traversal parse_traversal(const std::string& text);
const char* traversal_name(Traversal traversal);
// Every traversal, in the order --help lists them ("known: ...").
const Traversal* all_traversals(int* count);

// Block edge (pixels) of the block traversals.
constexpr int kGoldenBlock = 8;
// Traversal::Auto tests pixel by pixel (incremental) when the box has at most this many pixels,
// and uses scanline bounds otherwise.
constexpr int64_t kAutoPixelBoxLimit = 100;

// Rasterizes one set-up triangle with the given traversal, appending one span per covered row in
// increasing y. Every traversal appends exactly the same spans.
void golden_triangle(const TriangleSetup& t, const RasterConfig& cfg, Traversal traversal,
                     SpanList& out);
// The same with Traversal::Auto.
void golden_triangle(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out);

// The golden engine: Traversal::Auto on one thread.
std::unique_ptr<Engine> make_golden_engine();
// The golden engine with a traversal, on `threads` threads (>= 1; 0 = hardware concurrency).
// The output is the same span list, in the same order, for any thread count.
std::unique_ptr<Engine> make_golden_engine(Traversal traversal, int threads);

// The float scanline of 002_267f91d5740f3ec8.txt: float vertex math, top-left via ceil(x - 0.5).
// A non-exact baseline: its difference from the golden is reported as error.
std::unique_ptr<Engine> make_float_scanline_engine();

// ---- the traversals, one per file (model/golden/traversal_*.cpp) ------------------------------

void traverse_simple(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out);
void traverse_incremental(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out);
void traverse_block(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out);
void traverse_adaptive(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out);
void traverse_bisector(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out);
void traverse_sat_block(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out);
void traverse_window(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out);
void traverse_scanline(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out);
void traverse_auto(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out);

// The float scanline's spans of one triangle (see make_float_scanline_engine).
void float_scanline_triangle(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out);

}  // namespace trirast
