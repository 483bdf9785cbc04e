#include "io/json.hpp"

#include <cmath>
#include <cstdio>

namespace trirast {

std::string json_escape(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += char(c);
        }
    }
  }
  return out + "\"";
}

Json Json::number(double v) {
  Json j(Kind::Scalar);
  if (!std::isfinite(v)) {
    j.scalar_ = "null";
  } else {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    j.scalar_ = buf;
  }
  return j;
}
Json Json::integer(int64_t v) {
  Json j(Kind::Scalar);
  j.scalar_ = std::to_string(v);
  return j;
}
Json Json::string(const std::string& v) {
  Json j(Kind::Scalar);
  j.scalar_ = json_escape(v);
  return j;
}
Json Json::boolean(bool v) {
  Json j(Kind::Scalar);
  j.scalar_ = v ? "true" : "false";
  return j;
}

Json& Json::set(const std::string& key, Json value) {
  for (auto& m : members_)
    if (m.first == key) {
      m.second = std::move(value);
      return *this;
    }
  members_.emplace_back(key, std::move(value));
  return *this;
}

Json& Json::push(Json value) {
  items_.push_back(std::move(value));
  return *this;
}

void Json::dump_to(std::string& out, int indent, int depth) const {
  const std::string pad(size_t(indent) * (depth + 1), ' '), end_pad(size_t(indent) * depth, ' ');
  if (kind_ == Kind::Scalar) {
    out += scalar_;
  } else if (kind_ == Kind::Object) {
    if (members_.empty()) { out += "{}"; return; }
    out += "{\n";
    for (size_t i = 0; i < members_.size(); ++i) {
      out += pad + json_escape(members_[i].first) + ": ";
      members_[i].second.dump_to(out, indent, depth + 1);
      out += i + 1 < members_.size() ? ",\n" : "\n";
    }
    out += end_pad + "}";
  } else {
    if (items_.empty()) { out += "[]"; return; }
    out += "[\n";
    for (size_t i = 0; i < items_.size(); ++i) {
      out += pad;
      items_[i].dump_to(out, indent, depth + 1);
      out += i + 1 < items_.size() ? ",\n" : "\n";
    }
    out += end_pad + "]";
  }
}

void Json::leaf_names(std::vector<std::string>& out, const std::string& prefix) const {
  if (kind_ == Kind::Object) {
    for (const auto& m : members_)
      m.second.leaf_names(out, prefix.empty() ? m.first : prefix + "." + m.first);
    return;
  }
  bool nested = kind_ == Kind::Array && !items_.empty();
  for (const Json& item : items_) nested = nested && item.kind_ != Kind::Scalar;
  if (nested) {
    for (const Json& item : items_) item.leaf_names(out, prefix + "[]");
    return;
  }
  for (const std::string& name : out)
    if (name == prefix) return;
  out.push_back(prefix);
}

std::string Json::dump(int indent) const {
  std::string out;
  dump_to(out, indent, 0);
  return out + "\n";
}

}  // namespace trirast
