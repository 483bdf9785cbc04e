// Built-in scene internals: parameter parsing and the 2D building blocks (see builtin.hpp).
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "scene/builtin.hpp"

namespace trirast {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

// ---- parameters ----

BuiltinParams::BuiltinParams(const std::string& name, const std::vector<KeySpec>& keys,
                             const std::vector<std::pair<std::string, std::string>>& given)
    : name_(name), keys_(keys), given_(given) {
  for (size_t i = 0; i < given_.size(); ++i) {
    const std::string& key = given_[i].first;
    const bool known = std::any_of(keys_.begin(), keys_.end(),
                                   [&](const KeySpec& k) { return key == k.key; });
    if (!known) throw SceneError("builtin:" + name_ + ": unknown key '" + key + "'");
    for (size_t j = 0; j < i; ++j)
      if (given_[j].first == key)
        throw SceneError("builtin:" + name_ + ": key '" + key + "' given twice");
  }
}

std::string BuiltinParams::text(const char* key) const {
  for (const auto& kv : given_)
    if (kv.first == key) return kv.second;
  for (const KeySpec& k : keys_)
    if (std::strcmp(k.key, key) == 0) return k.default_value;
  // A generator asking for a key missing from its own KeySpec list is a programming error.
  throw std::logic_error("builtin:" + name_ + ": key '" + key + "' is not declared");
}

void BuiltinParams::bad_value(const char* key, const std::string& expected) const {
  throw SceneError("builtin:" + name_ + ": bad value for '" + key + "': '" + text(key) +
                   "' (expected " + expected + ")");
}

int64_t BuiltinParams::integer(const char* key, int64_t lo, int64_t hi) const {
  const std::string s = text(key);
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || errno == ERANGE || v < lo || v > hi)
    bad_value(key, "an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
  return v;
}

double BuiltinParams::real(const char* key, double lo, double hi) const {
  const std::string s = text(key);
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !(v >= lo && v <= hi))  // also refuses NaN
    bad_value(key, "a number in " + std::to_string(lo) + ".." + std::to_string(hi));
  return v;
}

std::string BuiltinParams::choice(const char* key) const {
  const std::string s = text(key);
  for (const KeySpec& k : keys_) {
    if (std::strcmp(k.key, key) != 0) continue;
    const std::string choices = k.choices;
    // Look for s as a whole '|'-separated word of the choice list.
    size_t start = 0;
    while (start <= choices.size()) {
      size_t bar = choices.find('|', start);
      if (bar == std::string::npos) bar = choices.size();
      if (choices.compare(start, bar - start, s) == 0 && !s.empty()) return s;
      start = bar + 1;
    }
    bad_value(key, "one of " + choices);
  }
  throw std::logic_error("builtin:" + name_ + ": key '" + key + "' is not declared");
}

// ---- triangles and layout ----

InputTriangle make_tri(double x0, double y0, double x1, double y1, double x2, double y2) {
  InputTriangle t;
  t.x[0] = x0, t.y[0] = y0, t.x[1] = x1, t.y[1] = y1, t.x[2] = x2, t.y[2] = y2;
  return t;
}

InputTriangle vertex_order(const InputTriangle& tri, int rotation, bool reversed) {
  InputTriangle out = tri;
  for (int i = 0; i < 3; ++i) {
    out.x[i] = tri.x[(i + rotation) % 3];
    out.y[i] = tri.y[(i + rotation) % 3];
  }
  if (reversed) {
    std::swap(out.x[1], out.x[2]);
    std::swap(out.y[1], out.y[2]);
  }
  return out;
}

InputTriangle translated(const InputTriangle& tri, double dx, double dy) {
  InputTriangle out = tri;
  for (int i = 0; i < 3; ++i) {
    out.x[i] += dx;
    out.y[i] += dy;
  }
  return out;
}

void add_all_orders(TriList& out, const InputTriangle& tri) {
  for (int reversed = 0; reversed < 2; ++reversed)
    for (int rotation = 0; rotation < 3; ++rotation)
      out.push_back(vertex_order(tri, rotation, reversed != 0));
}

CellLayout::CellLayout(const RasterConfig& cfg, int cell_w, int cell_h)
    : cols_(std::max(1, cfg.width / cell_w)),
      rows_(std::max(1, cfg.height / cell_h)),
      cell_w_(cell_w),
      cell_h_(cell_h) {}

std::pair<double, double> CellLayout::next() {
  const int slot = used_++ % (cols_ * rows_);
  return {double((slot % cols_) * cell_w_), double((slot / cols_) * cell_h_)};
}

void add_config_all_orders(TriList& out, const TriList& config, CellLayout& cells) {
  for (int reversed = 0; reversed < 2; ++reversed)
    for (int rotation = 0; rotation < 3; ++rotation) {
      const auto [ox, oy] = cells.next();
      for (const InputTriangle& tri : config)
        out.push_back(translated(vertex_order(tri, rotation, reversed != 0), ox, oy));
    }
}

// ---- closed 2D configurations ----

TriList make_fan(double cx, double cy, int n, double radius, double rotation_deg) {
  std::vector<std::pair<double, double>> rim;
  for (int i = 0; i < n; ++i) {
    const double a = (rotation_deg + 360.0 * i / n) * kPi / 180.0;
    rim.emplace_back(cx + radius * std::cos(a), cy + radius * std::sin(a));
  }
  TriList fan;
  for (int i = 0; i < n; ++i) {
    const auto& a = rim[size_t(i)];
    const auto& b = rim[size_t((i + 1) % n)];
    fan.push_back(make_tri(cx, cy, a.first, a.second, b.first, b.second));
  }
  return fan;
}

TriList make_quad_grid(double cx, double cy, int cols, int rows, double cell, double angle_deg,
                       const std::string& diag) {
  const double c = std::cos(angle_deg * kPi / 180.0), s = std::sin(angle_deg * kPi / 180.0);
  // Every grid node is computed once, so neighbouring quads share bit-identical corners.
  std::vector<std::pair<double, double>> node;
  for (int i = 0; i <= rows; ++i)
    for (int j = 0; j <= cols; ++j) {
      const double u = (j - cols * 0.5) * cell, v = (i - rows * 0.5) * cell;
      node.emplace_back(cx + c * u - s * v, cy + s * u + c * v);
    }
  auto at = [&](int i, int j) { return node[size_t(i * (cols + 1) + j)]; };
  TriList grid;
  auto add = [&](std::pair<double, double> p, std::pair<double, double> q,
                 std::pair<double, double> r) {
    grid.push_back(make_tri(p.first, p.second, q.first, q.second, r.first, r.second));
  };
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const auto a = at(i, j), b = at(i, j + 1), cc = at(i + 1, j + 1), d = at(i + 1, j);
      const bool main = diag == "main" || (diag == "alternate" && (i + j) % 2 == 0);
      if (main) {  // split along a-cc
        add(a, b, cc);
        add(a, cc, d);
      } else {  // split along b-d
        add(a, b, d);
        add(b, cc, d);
      }
    }
  return grid;
}

TriList make_strip(double x0, double x1, double cy, int n, double width, double amplitude,
                   double waves) {
  // Strip vertices alternate between the upper and the lower border of the band.
  std::vector<std::pair<double, double>> sv;
  for (int k = 0; k < n + 2; ++k) {
    const double t = double(k) / (n + 1);
    const double centre_y = cy + amplitude * std::sin(2.0 * kPi * waves * t);
    sv.emplace_back(x0 + (x1 - x0) * t, centre_y + (k % 2 ? 0.5 : -0.5) * width);
  }
  TriList strip;
  for (int i = 0; i < n; ++i) {
    // As in a GL strip, every other triangle swaps two vertices to keep one winding.
    const auto& a = sv[size_t(i)];
    const auto& b = sv[size_t(i + (i % 2 ? 2 : 1))];
    const auto& c = sv[size_t(i + (i % 2 ? 1 : 2))];
    strip.push_back(make_tri(a.first, a.second, b.first, b.second, c.first, c.second));
  }
  return strip;
}

}  // namespace trirast
