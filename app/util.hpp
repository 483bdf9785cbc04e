// Small helpers the application's commands share: splitting an option's list and timing a step.
#pragma once
#include <chrono>
#include <string>
#include <vector>

namespace trirast {

// The items of `s` between the separators, empty ones kept ("a,,b" -> a, "", b; "a," -> a, ""),
// so a caller can refuse them or skip them; an empty `s` has no items.
inline std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  if (s.empty()) return out;
  size_t start = 0;
  for (;;) {
    const size_t at = s.find(sep, start);
    out.push_back(s.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) return out;
    start = at + 1;
  }
}

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace trirast
