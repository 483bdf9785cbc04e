// The golden's traversal list, its dispatch and the per-triangle choice of Traversal::Auto.
// The traversals live in traversal_*.cpp, the engines in golden_parallel.cpp.
#include "golden/golden.hpp"

#include <stdexcept>

namespace trirast {

namespace {

constexpr Traversal kAll[] = {Traversal::Simple,   Traversal::Incremental, Traversal::Block,
                              Traversal::Adaptive, Traversal::Bisector,    Traversal::SatBlock,
                              Traversal::Window,   Traversal::Scanline,    Traversal::Auto};

}  // namespace

const Traversal* all_traversals(int* count) {
  *count = int(sizeof(kAll) / sizeof(kAll[0]));
  return kAll;
}

const char* traversal_name(Traversal traversal) {
  switch (traversal) {
    case Traversal::Simple: return "simple";
    case Traversal::Incremental: return "incremental";
    case Traversal::Block: return "block";
    case Traversal::Adaptive: return "adaptive";
    case Traversal::Bisector: return "bisector";
    case Traversal::SatBlock: return "sat-block";
    case Traversal::Window: return "window";
    case Traversal::Scanline: return "scanline";
    case Traversal::Auto: return "auto";
  }
  return "?";
}

Traversal parse_traversal(const std::string& text) {
  std::string known;
  for (Traversal t : kAll) {
    if (text == traversal_name(t)) return t;
    known += (known.empty() ? "" : ", ") + std::string(traversal_name(t));
  }
  throw std::invalid_argument("--traversal: unknown traversal '" + text + "' (known: " + known +
                              ")");
}

// Traversal::Auto: a box of a few pixels is cheapest to test pixel by pixel (no divisions);
// anything larger is cheapest by scanline bounds, which cost per row, not per pixel
// (docs/golden-performance.md has the measurements behind the threshold).
void traverse_auto(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out) {
  if (t.box.empty()) return;
  if (t.box.width() * t.box.height() <= kAutoPixelBoxLimit) traverse_incremental(t, cfg, out);
  else traverse_scanline(t, cfg, out);
}

void golden_triangle(const TriangleSetup& t, const RasterConfig& cfg, Traversal traversal,
                     SpanList& out) {
  switch (traversal) {
    case Traversal::Simple: return traverse_simple(t, cfg, out);
    case Traversal::Incremental: return traverse_incremental(t, cfg, out);
    case Traversal::Block: return traverse_block(t, cfg, out);
    case Traversal::Adaptive: return traverse_adaptive(t, cfg, out);
    case Traversal::Bisector: return traverse_bisector(t, cfg, out);
    case Traversal::SatBlock: return traverse_sat_block(t, cfg, out);
    case Traversal::Window: return traverse_window(t, cfg, out);
    case Traversal::Scanline: return traverse_scanline(t, cfg, out);
    case Traversal::Auto: return traverse_auto(t, cfg, out);
  }
}

void golden_triangle(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out) {
  traverse_auto(t, cfg, out);
}

}  // namespace trirast
