// A heat map of per-triangle timing (trirast raster/compare --heatmap): each triangle's pixels
// painted with the colour of its cycles (accept to done), stall cycles or set-up cycles (accept to
// setup_done_cycle: its first StHold cycle, or in a unit with a job stage its job ready), on a
// logarithmic colour scale whose legend is drawn below the viewport.
#pragma once
#include <string>
#include <vector>

#include "common/engine.hpp"
#include "common/span.hpp"
#include "io/image.hpp"

namespace trirast {

// metric: "cycles", "stalls" or "setup"; setup_title is the legend's title of "setup" in the
// words of the engine's unit (units.hpp, CycleWords::setup_title). Uncovered pixels are white.
RgbImage heatmap_image(const SpanList& spans, const std::vector<TriangleCycles>& cycles,
                       const std::string& metric, const std::string& engine,
                       const std::string& setup_title, int width, int height);

// The metric's value for one triangle.
uint64_t heatmap_value(const TriangleCycles& c, const std::string& metric);

}  // namespace trirast
