// A small ordered JSON object builder for reports (keys keep insertion order).
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace trirast {

class Json {
 public:
  static Json object() { return Json(Kind::Object); }
  static Json array() { return Json(Kind::Array); }
  static Json number(double v);
  static Json integer(int64_t v);
  static Json string(const std::string& v);
  static Json boolean(bool v);

  Json& set(const std::string& key, Json value);  // object member, in insertion order
  Json& set(const std::string& key, const std::string& v) { return set(key, string(v)); }
  Json& set(const std::string& key, const char* v) { return set(key, string(v)); }
  Json& set(const std::string& key, int64_t v) { return set(key, integer(v)); }
  Json& set(const std::string& key, uint64_t v) { return set(key, integer(int64_t(v))); }
  Json& set(const std::string& key, int v) { return set(key, integer(v)); }
  Json& set(const std::string& key, double v) { return set(key, number(v)); }
  Json& set(const std::string& key, bool v) { return set(key, boolean(v)); }
  Json& push(Json value);                          // array element

  std::string dump(int indent = 2) const;

  // The statistics of a report: the dotted names of its leaves ("triangles.read"); an array of
  // objects names its elements "[]" ("engines[].pixels"), an array of plain values is one leaf.
  void leaf_names(std::vector<std::string>& out, const std::string& prefix = "") const;

 private:
  enum class Kind { Object, Array, Scalar };
  explicit Json(Kind k) : kind_(k) {}
  void dump_to(std::string& out, int indent, int depth) const;
  Kind kind_;
  std::string scalar_;  // already-encoded text for scalars
  std::vector<std::pair<std::string, Json>> members_;
  std::vector<Json> items_;
};

std::string json_escape(const std::string& s);

}  // namespace trirast
