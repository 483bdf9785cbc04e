#include "common/config.hpp"

#include <stdexcept>
#include <utility>

#include "common/span_downstream.hpp"

namespace trirast {

CullMode parse_cull_mode(const std::string& text) {
  if (text == "none") return CullMode::None;
  if (text == "back") return CullMode::Back;
  if (text == "front") return CullMode::Front;
  throw std::invalid_argument("--cull: expected none, back or front, got '" + text + "'");
}

const char* cull_mode_name(CullMode mode) {
  switch (mode) {
    case CullMode::Back: return "back";
    case CullMode::Front: return "front";
    default: return "none";
  }
}

BoundaryMode parse_boundary_mode(const std::string& text) {
  if (text == "step") return BoundaryMode::Step;
  if (text == "divide") return BoundaryMode::Divide;
  throw std::invalid_argument("--boundary: expected step or divide, got '" + text + "'");
}

const char* boundary_mode_name(BoundaryMode mode) {
  return mode == BoundaryMode::Divide ? "divide" : "step";
}

DividerMode parse_divider_mode(const std::string& text) {
  if (text == "fixed") return DividerMode::Fixed;
  if (text == "adaptive") return DividerMode::Adaptive;
  throw std::invalid_argument("--divider: expected fixed or adaptive, got '" + text + "'");
}

const char* divider_mode_name(DividerMode mode) {
  return mode == DividerMode::Fixed ? "fixed" : "adaptive";
}

HalfspaceWalk parse_halfspace_walk(const std::string& text) {
  if (text == "row") return HalfspaceWalk::Row;
  if (text == "zigzag") return HalfspaceWalk::Zigzag;
  if (text == "forward") return HalfspaceWalk::Forward;
  throw std::invalid_argument("--hs-walk: expected row, zigzag or forward, got '" + text + "'");
}

const char* halfspace_walk_name(HalfspaceWalk walk) {
  switch (walk) {
    case HalfspaceWalk::Row: return "row";
    case HalfspaceWalk::Zigzag: return "zigzag";
    case HalfspaceWalk::Forward: return "forward";
  }
  return "?";
}

int parse_corner_form(const std::string& text, const std::string& option) {
  if (text == "dsp") return 0;
  if (text == "radix16") return 1;
  throw std::invalid_argument(option + ": expected dsp or radix16, got '" + text + "'");
}

const char* corner_form_name(int form) { return form == 0 ? "dsp" : "radix16"; }

void RasterConfig::validate() const {
  if (width < 1 || width > kMaxViewport)
    throw std::invalid_argument("--width: " + std::to_string(width) + " is outside 1.." +
                                std::to_string(kMaxViewport));
  if (height < 1 || height > kMaxViewport)
    throw std::invalid_argument("--height: " + std::to_string(height) + " is outside 1.." +
                                std::to_string(kMaxViewport));
  if (subpixel_bits < 0 || subpixel_bits > 8)
    throw std::invalid_argument("--subpixel-bits: " + std::to_string(subpixel_bits) +
                                " is outside 0..8");
  // The viewport must lie inside the coordinate range, and edge values (2p+2 bits) must fit int64.
  if (coord_int_bits < 2 || coord_int_bits > 24)
    throw std::invalid_argument("--coord-bits: " + std::to_string(coord_int_bits) +
                                " is outside 2..24");
  // Edge values need 2p + 2 bits with p = coord_int_bits + frac_bits (docs/coverage-rule.md); they
  // are computed in int64, so p may not exceed 30.
  if (coord_int_bits + frac_bits() > 30)
    throw std::invalid_argument("--coord-bits: " + std::to_string(coord_int_bits) + " with " +
                                std::to_string(subpixel_bits) +
                                " subpixel bits needs edge values wider than 63 bits (at most " +
                                std::to_string(30 - frac_bits()) + ")");
  if (coord_limit_px() < width || coord_limit_px() < height)
    throw std::invalid_argument("--coord-bits: " + std::to_string(coord_int_bits) +
                                " bits cannot hold a " + std::to_string(width) + "x" +
                                std::to_string(height) + " viewport");
  if (endpoints != 1 && endpoints != 2 && endpoints != 4)
    throw std::invalid_argument("--endpoints: " + std::to_string(endpoints) + " is not 1, 2 or 4");
  if (fifo_depth < endpoints || fifo_depth > 1024)
    throw std::invalid_argument("--fifo-depth: " + std::to_string(fifo_depth) + " is outside " +
                                std::to_string(endpoints) + "..1024 (at least --endpoints)");
  make_span_downstream(sink_stall);  // throws with a message naming --sink-stall
  const std::pair<const char*, int> forms[] = {{"--corner-form", improved2.corner_form},
                                                {"--hs-corner-form", halfspace.corner_form}};
  for (const auto& [option, form] : forms)
    if (form != 0 && form != 1)
      throw std::invalid_argument(std::string(option) + ": " + std::to_string(form) +
                                  " is not 0 (dsp) or 1 (radix16)");
  if (halfspace.stamp != 1 && halfspace.stamp != 2 && halfspace.stamp != 4)
    throw std::invalid_argument("--stamp: " + std::to_string(halfspace.stamp) + " is not 1, 2 or 4");
  if (halfspace.tile != 0 && halfspace.tile != 8 && halfspace.tile != 16)
    throw std::invalid_argument("--tile: " + std::to_string(halfspace.tile) + " is not none, 8 or 16");
  if (box_bits < 1 || box_bits > 14)
    throw std::invalid_argument("--box-bits: " + std::to_string(box_bits) + " is outside 1..14");
}

}  // namespace trirast
