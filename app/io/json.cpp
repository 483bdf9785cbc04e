#include "io/json.hpp"

#include <algorithm>
#include <cmath>

namespace trirast {

namespace {

using nlohmann::ordered_json;

void collect_leaves(const ordered_json& j, std::vector<std::string>& out,
                    const std::string& prefix) {
  if (j.is_object()) {
    for (const auto& m : j.items())
      collect_leaves(m.value(), out, prefix.empty() ? m.key() : prefix + "." + m.key());
    return;
  }
  const bool nested = j.is_array() && !j.empty() &&
                      std::all_of(j.begin(), j.end(),
                                  [](const ordered_json& item) { return item.is_structured(); });
  if (nested) {
    for (const ordered_json& item : j) collect_leaves(item, out, prefix + "[]");
    return;
  }
  if (std::find(out.begin(), out.end(), prefix) == out.end()) out.push_back(prefix);
}

}  // namespace

Json Json::number(double v) {
  if (!std::isfinite(v)) return Json(ordered_json(nullptr));
  // Below 2^53 every integral double is an exact int64_t.
  if (v == std::trunc(v) && std::fabs(v) < 9007199254740992.0) return integer(int64_t(v));
  return Json(ordered_json(v));
}

Json& Json::set(const std::string& key, Json value) {
  value_[key] = std::move(value.value_);
  return *this;
}

Json& Json::push(Json value) {
  value_.push_back(std::move(value.value_));
  return *this;
}

std::string Json::dump(int indent) const {
  return value_.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

void Json::leaf_names(std::vector<std::string>& out, const std::string& prefix) const {
  collect_leaves(value_, out, prefix);
}

std::string json_escape(const std::string& s) {
  return ordered_json(s).dump(-1, ' ', false, ordered_json::error_handler_t::replace);
}

}  // namespace trirast
