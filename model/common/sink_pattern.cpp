#include "common/sink_pattern.hpp"

#include <cerrno>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace trirast {

uint64_t sink_mix(uint64_t seed, uint64_t cycle) {
  uint64_t z = seed * 0x9E3779B97F4A7C15ull + cycle;
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

namespace {
// `what` names the field in the error, e.g. "PERCENT (0..99)".
uint64_t parse_u64(const std::string& s, const std::string& whole, const char* what) {
  errno = 0;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || errno != 0 || s[0] == '-' || s[0] == '+' || s[0] == ' ')
    throw std::invalid_argument("--sink-stall: '" + whole + "': " + what + " '" + s +
                                "' is not a whole number");
  return v;
}
}  // namespace

SinkPattern SinkPattern::parse(const std::string& text) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t i = 0; i <= text.size(); ++i)
    if (i == text.size() || text[i] == ':') {
      parts.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  SinkPattern p;
  if (parts.size() == 1 && (parts[0] == "none" || parts[0].empty())) return p;
  if (parts.size() == 3 && parts[0] == "periodic") {
    p.kind_ = Kind::Periodic;
    p.ready_ = parse_u64(parts[1], text, "READY");
    p.stall_ = parse_u64(parts[2], text, "STALL");
    if (p.ready_ == 0)
      throw std::invalid_argument("--sink-stall: '" + text + "': the sink must be ready sometimes");
    return p;
  }
  if (parts.size() == 3 && parts[0] == "random") {
    p.kind_ = Kind::Random;
    p.seed_ = parse_u64(parts[1], text, "SEED");
    p.percent_ = parse_u64(parts[2], text, "PERCENT (the stall probability in percent, 0..99)");
    if (p.percent_ > 99)
      throw std::invalid_argument("--sink-stall: '" + text + "': stall percent must be 0..99");
    return p;
  }
  throw std::invalid_argument("--sink-stall: '" + text +
                              "': expected none, periodic:READY:STALL, random:SEED:PERCENT or queue:RATE:CAPACITY");
}

uint64_t SinkPattern::next_ready(uint64_t c) const {
  switch (kind_) {
    case Kind::Periodic: {
      const uint64_t period = ready_ + stall_;
      return c % period < ready_ ? c : c - c % period + period;
    }
    case Kind::Random:
      while (!ready(c)) ++c;
      return c;
    default: return c;
  }
}

std::string SinkPattern::text() const {
  switch (kind_) {
    case Kind::Periodic: return "periodic:" + std::to_string(ready_) + ":" + std::to_string(stall_);
    case Kind::Random: return "random:" + std::to_string(seed_) + ":" + std::to_string(percent_);
    default: return "none";
  }
}

}  // namespace trirast
