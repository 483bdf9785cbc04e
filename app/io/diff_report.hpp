// Where an engine differs from the golden, for people: the triangles and pixels that differ, listed
// in the compare report (bounded), and the file name of each engine's diff image.
#pragma once
#include <string>

#include "common/span_diff.hpp"
#include "io/json.hpp"

namespace trirast {

constexpr int kDiffListLimit = 64;  // triangles and pixels listed per engine

// Sets differing_pixel_count, differing_triangle_count, differing_triangles (the first 64 scene
// indices) and differing_pixels (the first 64: tri, x, y, kind missing | extra) in `row`.
void add_diff_listing(Json& row, const SpanDiff& diff);

// FILE.png -> FILE.ENGINE.png: the diff image of one more engine beside the first.
std::string diff_image_path(const std::string& path, const std::string& engine);

}  // namespace trirast
