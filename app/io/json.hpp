// The JSON documents trirast writes (the --report of raster, compare and fit, sweep.json): an
// ordered JSON object (keys keep insertion order) built by chained set() / push() calls, over
// nlohmann::ordered_json.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace trirast {

class Json {
 public:
  static Json object() { return Json(nlohmann::ordered_json::object()); }
  static Json array() { return Json(nlohmann::ordered_json::array()); }
  // A double with an integral value is written as an integer ("3", not "3.0"), any other one
  // with the digits that read back to the same double; NaN and infinities as null.
  static Json number(double v);
  static Json integer(int64_t v) { return Json(nlohmann::ordered_json(v)); }
  static Json unsigned_integer(uint64_t v) { return Json(nlohmann::ordered_json(v)); }
  static Json string(const std::string& v) { return Json(nlohmann::ordered_json(v)); }
  static Json boolean(bool v) { return Json(nlohmann::ordered_json(v)); }

  // Object member: a new key goes last, an existing key keeps its place and takes the value.
  Json& set(const std::string& key, Json value);
  Json& set(const std::string& key, const std::string& v) { return set(key, string(v)); }
  Json& set(const std::string& key, const char* v) { return set(key, string(v)); }
  Json& set(const std::string& key, int64_t v) { return set(key, integer(v)); }
  Json& set(const std::string& key, uint64_t v) { return set(key, unsigned_integer(v)); }
  Json& set(const std::string& key, int v) { return set(key, integer(v)); }
  Json& set(const std::string& key, double v) { return set(key, number(v)); }
  Json& set(const std::string& key, bool v) { return set(key, boolean(v)); }
  Json& push(Json value);  // array element

  // Indented by `indent` spaces per level, with a final newline. Bytes of a string that are not
  // UTF-8 are written as U+FFFD.
  std::string dump(int indent = 2) const;

  // The statistics of a report: the dotted names of its leaves ("triangles.read"); an array of
  // objects names its elements "[]" ("engines[].pixels"), an array of plain values is one leaf.
  void leaf_names(std::vector<std::string>& out, const std::string& prefix = "") const;

  const nlohmann::ordered_json& value() const { return value_; }

 private:
  explicit Json(nlohmann::ordered_json v) : value_(std::move(v)) {}
  nlohmann::ordered_json value_;
};

// `s` as a JSON string literal, quotes included.
std::string json_escape(const std::string& s);

}  // namespace trirast
