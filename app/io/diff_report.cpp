#include "io/diff_report.hpp"

#include <cctype>
#include <set>

namespace trirast {

void add_diff_listing(Json& row, const SpanDiff& diff) {
  std::set<uint32_t> tris;
  for (const SpanList* list : {&diff.missing, &diff.extra})
    for (const Span& s : *list) tris.insert(s.tri);
  Json tri_list = Json::array();
  int listed = 0;
  for (uint32_t t : tris) {
    if (listed++ == kDiffListLimit) break;
    tri_list.push(Json::integer(t));
  }
  // Pixels: missing ones first (the worse error), then extra ones, each in span order.
  Json pixels = Json::array();
  int n = 0;
  for (const auto& [list, kind] : {std::make_pair(&diff.missing, "missing"),
                                   std::make_pair(&diff.extra, "extra")})
    for (const Span& s : *list)
      for (int x = s.x_begin; x < s.x_end && n < kDiffListLimit; ++x, ++n)
        pixels.push(Json::object().set("tri", int64_t(s.tri)).set("x", x).set("y", s.y).set("kind", kind));
  row.set("differing_pixel_count", diff.missing_pixels + diff.extra_pixels)
      .set("differing_triangle_count", uint64_t(tris.size()))
      .set("differing_triangles", tri_list)
      .set("differing_pixels", pixels);
}

std::string diff_image_path(const std::string& path, const std::string& engine) {
  const size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  std::string label = engine;  // file:PATH engines: no slashes in a file name
  for (char& c : label)
    if (!(std::isalnum((unsigned char)c) || c == '-' || c == '_')) c = '_';
  return (has_ext ? path.substr(0, dot) : path) + "." + label + (has_ext ? path.substr(dot) : ".png");
}

}  // namespace trirast
