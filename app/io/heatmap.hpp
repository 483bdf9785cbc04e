// A heat map of per-triangle timing (trirast raster/compare --heatmap): each triangle's pixels
// painted with the colour of its cycles (accept to done), stall cycles or set-up cycles (accept to
// its first StHold cycle), on a logarithmic colour scale whose legend is drawn below the viewport.
#pragma once
#include <string>
#include <vector>

#include "common/engine.hpp"
#include "common/span.hpp"
#include "io/image.hpp"

namespace trirast {

// metric: "cycles", "stalls" or "setup". Uncovered pixels are white.
RgbImage heatmap_image(const SpanList& spans, const std::vector<TriangleCycles>& cycles,
                       const std::string& metric, const std::string& engine, int width, int height);

// The metric's value for one triangle.
uint64_t heatmap_value(const TriangleCycles& c, const std::string& metric);

}  // namespace trirast
