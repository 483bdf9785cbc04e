// Pictures of coverage: the viewport as a PNG, each triangle in its own colour, and the diff
// image of an engine against the golden (agreed grey, missing red, extra blue).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "common/span.hpp"
#include "common/span_diff.hpp"

namespace trirast {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row-major, 3 bytes a pixel
  RgbImage(int w, int h) : width(w), height(h), rgb(size_t(w) * h * 3, 0) {}
  void fill_span(const Span& s, uint8_t r, uint8_t g, uint8_t b);
};

// Distinct, bright colour for a triangle index (deterministic hash).
void triangle_colour(uint32_t tri, uint8_t rgb[3]);

RgbImage coverage_image(const SpanList& spans, int width, int height);
RgbImage diff_image(const SpanList& golden, const SpanDiff& diff, int width, int height);

// Writes an 8-bit RGB PNG atomically (see OutputFile); `option` names the option for errors.
void write_png(const RgbImage& image, const std::string& path, const std::string& option);

}  // namespace trirast
