#include "common/gtkw_save.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "common/temporary_files.hpp"

namespace trirast {

namespace fs = std::filesystem;

std::string gtkw_path_of(const std::string& trace_path) {
  for (const std::string ext : {".vcd", ".fst"})
    if (trace_path.size() > ext.size() &&
        trace_path.compare(trace_path.size() - ext.size(), ext.size(), ext) == 0)
      return trace_path.substr(0, trace_path.size() - ext.size()) + ".gtkw";
  return trace_path + ".gtkw";
}

std::string relative_to_file(const std::string& target, const std::string& from_file) {
  const fs::path t = fs::absolute(fs::path(target)).lexically_normal();
  const fs::path dir = fs::absolute(fs::path(from_file)).lexically_normal().parent_path();
  const fs::path rel = t.lexically_relative(dir);
  return rel.empty() ? t.string() : rel.string();
}

namespace {

// Writes text to path through a temporary name (removed on failure, SIGINT and SIGTERM).
void write_text(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  TemporaryPath guard(tmp);
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw std::runtime_error("--trace: cannot write '" + path + "'");
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !ok || std::rename(tmp.c_str(), path.c_str()) != 0)
    throw std::runtime_error("--trace: cannot write '" + path + "'");
  guard.release();
}

// The base of the save file's name (no folder, no .gtkw): the filter files are named after it.
std::string stem_of(const std::string& gtkw_path) {
  std::string base = fs::path(gtkw_path).filename().string();
  if (base.size() > 5 && base.compare(base.size() - 5, 5, ".gtkw") == 0)
    base.resize(base.size() - 5);
  return base;
}

// GTKWave's trace flags (its analyzer.h): what the @ lines hold.
constexpr unsigned kFlagDec = 0x4, kFlagBin = 0x8, kFlagRjustify = 0x20, kFlagBlank = 0x200,
                   kFlagSigned = 0x400,
                   kFlagFileTranslated = 0x2000, kFlagClosed = 0x400000,
                   kFlagGroupBegin = 0x800000, kFlagGroupEnd = 0x1000000;

std::string flags(unsigned f) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "@%x\n", f);
  return buf;
}

// The wave pane's width in pixels at the [size] below (the signal and hierarchy panes take the
// rest): the zoom puts the window into it.
constexpr int kWindowWidth = 1280, kWindowHeight = 800, kWavePixels = 700;

}  // namespace

void write_gtkw(const std::string& gtkw_path, const GtkwSave& save) {
  const std::string stem = stem_of(gtkw_path);
  const fs::path dir = fs::path(gtkw_path).parent_path();
  std::vector<std::string> filter_files;
  for (const GtkwSave::Filter& f : save.filters) {
    std::string text;
    for (const auto& [v, label] : f.values) text += std::to_string(v) + " " + label + "\n";
    const std::string name = stem + "." + f.name + ".filter";
    write_text((dir / name).string(), text);
    filter_files.push_back(name);
  }

  std::string g;
  g += "[*] trirast: " + std::string("the dump and the filter files are named relative to this file\n");
  g += "[dumpfile] \"" + relative_to_file(save.dump_path, gtkw_path) + "\"\n";
  // With [savefile] GTKWave resolves a relative [dumpfile] from the save file's own folder.
  g += "[savefile] \"" + fs::path(gtkw_path).filename().string() + "\"\n";
  const uint64_t start = save.window_start * save.time_factor;
  const uint64_t end = std::max(save.window_end, save.window_start + 1) * save.time_factor;
  g += "[timestart] " + std::to_string(start) + "\n";
  g += "[size] " + std::to_string(kWindowWidth) + " " + std::to_string(kWindowHeight) + "\n";
  g += "[pos] -1 -1\n";
  // Zoom: GTKWave's "zoom full" puts T time units into W pixels with zoom = -log2(T * 200 / W)
  // (its zoombuttons.c; zoombase 2). No marker (-1).
  char zoom[64];
  std::snprintf(zoom, sizeof zoom, "*%.6f -1",
                -std::log2(double(end - start + 1) * 200.0 / double(kWavePixels)));
  g += zoom;
  for (int i = 0; i < 26; ++i) g += " -1";  // named markers A..Z: none
  g += "\n";
  g += "[sst_width] 220\n[signals_width] 240\n[sst_expanded] 1\n[sst_vpaned_height] 200\n";
  for (const std::string& t : save.tree_open) g += "[treeopen] " + t + "\n";
  for (const GtkwSave::Group& grp : save.groups) {
    g += flags(kFlagGroupBegin | kFlagBlank | (grp.closed ? kFlagClosed : 0u)) + "-" + grp.name + "\n";
    for (const GtkwSave::Trace& t : grp.traces) {
      int filter = 0;
      for (size_t i = 0; i < save.filters.size(); ++i)
        if (save.filters[i].name == t.filter) filter = int(i) + 1;
      if (filter) {
        g += "^" + std::to_string(filter) + " " + filter_files[size_t(filter - 1)] + "\n";
        g += flags(kFlagFileTranslated | kFlagRjustify | kFlagDec);
      } else {
        g += flags(kFlagRjustify | (t.width == 1 ? kFlagBin : kFlagDec) |
                   (t.is_signed && t.width > 1 ? kFlagSigned : 0u));
      }
      g += t.name + "\n";
    }
    g += flags(kFlagGroupEnd | kFlagBlank | (grp.closed ? kFlagClosed : 0u)) + "-" + grp.name + "\n";
  }
  write_text(gtkw_path, g);
}

}  // namespace trirast
