#include "io/heatmap.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace trirast {

uint64_t heatmap_value(const TriangleCycles& c, const std::string& metric) {
  if (metric == "stalls") return c.stall_cycles;
  if (metric == "setup") return c.setup_done_cycle - c.accept_cycle;
  return c.done_cycle - c.accept_cycle;
}

namespace {

// Viridis-like ramp (dark purple - blue - green - yellow), t in [0, 1].
void ramp(double t, uint8_t rgb[3]) {
  static const double stops[][3] = {{68, 1, 84},    {59, 82, 139},  {33, 145, 140},
                                    {94, 201, 98},  {253, 231, 37}};
  t = std::clamp(t, 0.0, 1.0) * 4.0;
  const int i = std::min(3, int(t));
  const double f = t - i;
  for (int k = 0; k < 3; ++k)
    rgb[k] = uint8_t(std::lround(stops[i][k] + (stops[i + 1][k] - stops[i][k]) * f));
}

// A 3x5 pixel font: five rows of three columns per glyph, '#' set.
const char* glyph(char ch) {
  static const struct { char c; const char* rows; } font[] = {
      {'0', "###"
            "# #"
            "# #"
            "# #"
            "###"},
      {'1', " # "
            "## "
            " # "
            " # "
            "###"},
      {'2', "###"
            "  #"
            "###"
            "#  "
            "###"},
      {'3', "###"
            "  #"
            " ##"
            "  #"
            "###"},
      {'4', "# #"
            "# #"
            "###"
            "  #"
            "  #"},
      {'5', "###"
            "#  "
            "###"
            "  #"
            "###"},
      {'6', "###"
            "#  "
            "###"
            "# #"
            "###"},
      {'7', "###"
            "  #"
            "  #"
            " # "
            " # "},
      {'8', "###"
            "# #"
            "###"
            "# #"
            "###"},
      {'9', "###"
            "# #"
            "###"
            "  #"
            "###"},
      {'a', " # "
            "# #"
            "###"
            "# #"
            "# #"},
      {'b', "## "
            "# #"
            "## "
            "# #"
            "## "},
      {'c', " ##"
            "#  "
            "#  "
            "#  "
            " ##"},
      {'d', "## "
            "# #"
            "# #"
            "# #"
            "## "},
      {'e', "###"
            "#  "
            "## "
            "#  "
            "###"},
      {'f', "###"
            "#  "
            "## "
            "#  "
            "#  "},
      {'g', " ##"
            "#  "
            "# #"
            "# #"
            " ##"},
      {'h', "# #"
            "# #"
            "###"
            "# #"
            "# #"},
      {'i', "###"
            " # "
            " # "
            " # "
            "###"},
      {'k', "# #"
            "## "
            "#  "
            "## "
            "# #"},
      {'l', "#  "
            "#  "
            "#  "
            "#  "
            "###"},
      {'m', "# #"
            "###"
            "###"
            "# #"
            "# #"},
      {'n', "## "
            "# #"
            "# #"
            "# #"
            "# #"},
      {'o', " # "
            "# #"
            "# #"
            "# #"
            " # "},
      {'p', "## "
            "# #"
            "## "
            "#  "
            "#  "},
      {'r', "## "
            "# #"
            "## "
            "# #"
            "# #"},
      {'s', " ##"
            "#  "
            " # "
            "  #"
            "## "},
      {'t', "###"
            " # "
            " # "
            " # "
            " # "},
      {'u', "# #"
            "# #"
            "# #"
            "# #"
            "###"},
      {'v', "# #"
            "# #"
            "# #"
            "# #"
            " # "},
      {'w', "# #"
            "# #"
            "###"
            "###"
            "# #"},
      {'x', "# #"
            "# #"
            " # "
            "# #"
            "# #"},
      {'y', "# #"
            "# #"
            " # "
            " # "
            " # "},
      {'z', "###"
            "  #"
            " # "
            "#  "
            "###"},
      {'(', " # "
            "#  "
            "#  "
            "#  "
            " # "},
      {')', " # "
            "  #"
            "  #"
            "  #"
            " # "},
      {':', "   "
            " # "
            "   "
            " # "
            "   "},
      {'-', "   "
            "   "
            "###"
            "   "
            "   "},
      {',', "   "
            "   "
            "   "
            " # "
            "#  "},
      {'.', "   "
            "   "
            "   "
            "   "
            " # "},
  };
  for (const auto& g : font)
    if (g.c == ch) return g.rows;
  return nullptr;  // blank
}

constexpr int kScale = 2;                  // font pixels per glyph pixel
constexpr int kAdvance = 4 * kScale;       // glyph width plus one column of space
constexpr int kGlyphHeight = 5 * kScale;

void put(RgbImage& img, int x, int y, const uint8_t rgb[3]) {
  if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
  uint8_t* p = &img.rgb[(size_t(y) * img.width + x) * 3];
  p[0] = rgb[0], p[1] = rgb[1], p[2] = rgb[2];
}

// Draws text (lower case, digits, a few signs) with its top-left corner at (x, y).
void text(RgbImage& img, int x, int y, const std::string& s) {
  static const uint8_t ink[3] = {0, 0, 0};
  for (char ch : s) {
    const char c = char(std::tolower(static_cast<unsigned char>(ch)));
    if (const char* rows = glyph(c))
      for (int gy = 0; gy < 5; ++gy)
        for (int gx = 0; gx < 3; ++gx)
          if (rows[gy * 3 + gx] == '#')
            for (int dy = 0; dy < kScale; ++dy)
              for (int dx = 0; dx < kScale; ++dx) put(img, x + gx * kScale + dx, y + gy * kScale + dy, ink);
    x += kAdvance;
  }
}

int text_width(const std::string& s) { return int(s.size()) * kAdvance - kScale; }

}  // namespace

RgbImage heatmap_image(const SpanList& spans, const std::vector<TriangleCycles>& cycles,
                       const std::string& metric, const std::string& engine,
                       const std::string& setup_title, int width, int height) {
  // The scale: log(1 + v) from the smallest to the largest value of a triangle with pixels.
  std::unordered_map<uint32_t, uint64_t> value;
  value.reserve(cycles.size());
  for (const TriangleCycles& c : cycles) value[c.tri] = heatmap_value(c, metric);
  uint64_t vmax = 0, vmin = ~uint64_t(0);
  for (const TriangleCycles& c : cycles)
    if (c.pixels > 0) {
      vmax = std::max(vmax, value[c.tri]);
      vmin = std::min(vmin, value[c.tri]);
    }
  if (vmin > vmax) vmin = vmax = 0;
  const double lmin = std::log1p(double(vmin)), lmax = std::log1p(double(vmax));
  auto t_of = [&](uint64_t v) {
    return lmax > lmin ? (std::log1p(double(v)) - lmin) / (lmax - lmin) : 0.0;
  };

  const std::string title = metric == "stalls"  ? "stall cycles per triangle"
                            : metric == "setup" ? setup_title
                                                : "cycles per triangle (accept to done)";
  const std::string caption = title + ", " + engine + ", log scale";
  const int legend_w = std::max(360, text_width(caption) + 16);
  const int canvas_w = std::max(width, legend_w);
  const int legend_h = 16 + kGlyphHeight + 6 + 14 + 4 + kGlyphHeight + 10;
  RgbImage img(canvas_w, height + legend_h);
  std::fill(img.rgb.begin(), img.rgb.end(), uint8_t(255));
  // The viewport's frame, so its extent shows where no triangle covers it.
  static const uint8_t frame[3] = {190, 190, 190};
  for (int x = 0; x < width; ++x) put(img, x, height - 1, frame);
  for (int y = 0; y < height; ++y) put(img, width - 1, y, frame);
  for (const Span& s : spans) {
    auto it = value.find(s.tri);
    if (it == value.end()) continue;
    uint8_t c[3];
    ramp(t_of(it->second), c);
    img.fill_span(s, c[0], c[1], c[2]);
  }
  // The legend: caption, colour bar, ticks with their values.
  const int x0 = 8, y_caption = height + 8, y_bar = y_caption + kGlyphHeight + 6;
  const int bar_w = legend_w - 16, bar_h = 14;
  text(img, x0, y_caption, caption);
  for (int x = 0; x < bar_w; ++x) {
    uint8_t c[3];
    ramp(double(x) / double(bar_w - 1), c);
    for (int y = 0; y < bar_h; ++y) put(img, x0 + x, y_bar + y, c);
  }
  static const uint8_t ink[3] = {0, 0, 0};
  for (int i = 0; i <= 4; ++i) {
    const double t = i / 4.0;
    const uint64_t v = uint64_t(std::llround(std::expm1(lmin + t * (lmax - lmin))));
    const int x = x0 + int(std::lround(t * (bar_w - 1)));
    for (int y = y_bar + bar_h; y < y_bar + bar_h + 4; ++y) put(img, x, y, ink);
    const std::string label = std::to_string(v);
    const int lw = text_width(label);
    const int lx = std::clamp(x - lw / 2, x0, x0 + bar_w - lw);
    text(img, lx, y_bar + bar_h + 5, label);
  }
  return img;
}

}  // namespace trirast
