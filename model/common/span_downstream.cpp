#include "common/span_downstream.hpp"

#include <stdexcept>

#include "common/config.hpp"

namespace trirast {

namespace {
bool starts_with(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

uint64_t queue_field(const std::string& s, const std::string& whole, const char* what) {
  if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos ||
      std::stoull(s) == 0)
    throw std::invalid_argument("--sink-stall: '" + whole + "': " + what + " '" + s +
                                "' is not a whole number from 1 to 999999999");
  return std::stoull(s);
}
}  // namespace

bool is_cycle_pattern(const std::string& text) { return !starts_with(text, "queue:"); }

std::unique_ptr<SpanDownstream> make_span_downstream(const std::string& text) {
  if (!is_cycle_pattern(text)) {
    const std::string rest = text.substr(6);
    const size_t colon = rest.find(':');
    if (colon == std::string::npos)
      throw std::invalid_argument("--sink-stall: '" + text + "': expected queue:RATE:CAPACITY");
    const uint64_t rate = queue_field(rest.substr(0, colon), text, "RATE (pixels per cycle)");
    const uint64_t cap = queue_field(rest.substr(colon + 1), text, "CAPACITY (pixels)");
    return std::make_unique<PixelQueueDownstream>(rate, cap);
  }
  return std::make_unique<PatternDownstream>(SinkPattern::parse(text));
}

std::unique_ptr<SpanDownstream> make_span_downstream(const RasterConfig& cfg) {
  return cfg.downstream ? cfg.downstream() : make_span_downstream(cfg.sink_stall);
}

}  // namespace trirast
