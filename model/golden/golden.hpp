// The golden half-space rasterizer: the truth for coverage. Every other engine is compared with
// it pixel for pixel. It applies raster-rules.md directly: integer edge functions evaluated at pixel
// centres, the top-left bias, the clipped bounding box.
#pragma once
#include <memory>

#include "core/engine.hpp"

namespace trirast {

// Rasterizes one set-up triangle by incremental edge functions over its bounding box, appending
// one span per covered row.
void golden_triangle(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out);

std::unique_ptr<Engine> make_golden_engine();

}  // namespace trirast
