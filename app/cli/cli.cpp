#include "cli/cli.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "core/engine.hpp"
#include "engines.hpp"
#include "core/fixed_point.hpp"
#include "core/span_diff.hpp"
#include "golden/golden.hpp"
#include "io/image.hpp"
#include "io/json.hpp"
#include "io/output_file.hpp"
#include "io/cycles_file.hpp"
#include "io/spans_file.hpp"
#include "scene/scene.hpp"

namespace trirast {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

bool file_exists(const std::string& path) { return std::ifstream(path).good(); }

// The GTKWave save file a trace writer leaves beside FILE.vcd / FILE.fst.
std::string gtkw_path(const std::string& trace) {
  const size_t dot = trace.find_last_of('.');
  const size_t slash = trace.find_last_of('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_ext ? trace.substr(0, dot) : trace) + ".gtkw";
}

// Options every scene-consuming subcommand shares.
std::vector<OptionSpec> scene_options() {
  return {
      {"--scene", "SCENE", "builtin:NAME[:k=v,...], a .tri file, or a mesh file (OBJ, PLY, STL, OFF, glTF, ...)", ""},
      {"--width", "W", "viewport width in pixels, 1..16384", "1024"},
      {"--height", "H", "viewport height in pixels, 1..16384", "768"},
      {"--subpixel-bits", "S", "vertex snapping: 1/2^S pixel, 0..8", "8"},
      {"--coord-bits", "N", "signed integer bits of a coordinate: range [-2^(N-1), 2^(N-1)) px", "16"},
      {"--cull", "MODE", "none | back | front (front faces run counter-clockwise as seen on screen)", "none"},
      {"--yaw", "DEG", "mesh camera: rotation about the up axis", "30"},
      {"--pitch", "DEG", "mesh camera: elevation", "20"},
      {"--distance", "R", "mesh camera: eye distance in bounding radii; 0 fits the viewport", "0"},
      {"--fov", "DEG", "mesh camera: vertical field of view", "45"},
      {"--traversal", "NAME", "golden traversal: simple | incremental | block | adaptive | bisector | sat-block | window | scanline | auto", "auto"},
      {"--threads", "N", "golden threads (0 = all cores)", "1"},
      {"--box-bits", "N", "unit: bits of a box-relative coordinate, 1..14", "14"},
      {"--boundary", "MODE", "unit: boundary traversal, step (the paper) | divide", "step"},
      {"--divider", "MODE", "unit: divider iterations, adaptive (bits the box needs) | fixed (box-bits + 1)", "adaptive"},
      {"--stamp", "S", "half-space unit: stamp of S x S pixels tested per cycle, 1 | 2 | 4", "2"},
      {"--tile", "T", "half-space unit: tile of T x T pixels rejected/accepted from its corners, 8 | 16 | none", "8"},
      {"--hs-walk", "ORDER", "half-space unit: tile order, row (every tile) | zigzag (alternate bands, end a band after its last non-rejected tile)", "zigzag"},
      {"--endpoints", "N", "timed units: rows (endpoints per edge) walked per cycle, 1 | 2 | 4", "1"},
      {"--fifo-depth", "D", "timed units: span FIFO entries (>= --endpoints)", "8"},
      {"--sink-stall", "PATTERN", "timed units: sink ready pattern: none | periodic:READY:STALL (cycles) | random:SEED:PERCENT (stall percent 0..99)", "none"},
  };
}

RasterConfig config_from(const Args& a) {
  RasterConfig cfg;
  cfg.width = int(a.get_int("--width", 1, kMaxViewport));
  cfg.height = int(a.get_int("--height", 1, kMaxViewport));
  cfg.subpixel_bits = int(a.get_int("--subpixel-bits", 0, 8));
  cfg.coord_int_bits = int(a.get_int("--coord-bits", 2, 24));
  cfg.box_bits = int(a.get_int("--box-bits", 1, 14));
  cfg.endpoints = int(a.get_int("--endpoints", 1, 4));
  cfg.fifo_depth = int(a.get_int("--fifo-depth", 1, 1024));
  cfg.sink_stall = a.get("--sink-stall");
  cfg.hs_stamp = int(a.get_int("--stamp", 1, 4));
  try {
    const std::string tile = a.get("--tile");
    if (tile == "none") {
      cfg.hs_tile = 0;
    } else {
      cfg.hs_tile = int(a.get_int("--tile", 8, 16));
    }
    cfg.hs_walk = parse_hs_walk(a.get("--hs-walk"));
    cfg.cull = parse_cull_mode(a.get("--cull"));
    cfg.boundary = parse_boundary_mode(a.get("--boundary"));
    cfg.divider = parse_divider_mode(a.get("--divider"));
    cfg.validate();
  } catch (const std::invalid_argument& e) {
    throw UsageError("trirast " + a.command() + ": " + e.what());
  }
  return cfg;
}

CameraOptions camera_from(const Args& a) {
  CameraOptions cam;
  cam.yaw_deg = a.get_double("--yaw");
  cam.pitch_deg = a.get_double("--pitch");
  cam.distance = a.get_double("--distance");
  cam.fov_deg = a.get_double("--fov");
  if (cam.fov_deg <= 0 || cam.fov_deg >= 180)
    throw UsageError("trirast " + a.command() + ": --fov: must be between 0 and 180 degrees");
  if (cam.distance < 0)
    throw UsageError("trirast " + a.command() + ": --distance: must not be negative");
  return cam;
}

struct LoadedScene {
  Scene scene;
  SetupResult setup;
  double load_seconds = 0, setup_seconds = 0;
};

LoadedScene load_and_setup(const Args& a, const RasterConfig& cfg) {
  if (!a.has("--scene")) throw UsageError("trirast " + a.command() + ": --scene is required");
  LoadedScene ls;
  auto t0 = Clock::now();
  ls.scene = load_scene(a.get("--scene"), cfg, camera_from(a));
  ls.load_seconds = seconds_since(t0);
  t0 = Clock::now();
  try {
    ls.setup = setup_scene(ls.scene.tris, cfg);
  } catch (const SetupError& e) {
    // Name the file (and line) the bad triangle came from.
    const std::string scene = a.get("--scene");
    throw SceneError(e.line > 0 ? scene + ":" + std::to_string(e.line) + ": " + e.what()
                                : scene + ": " + e.what());
  }
  ls.setup_seconds = seconds_since(t0);
  return ls;
}

Json triangle_counts(const LoadedScene& ls) {
  const SetupCounts& c = ls.setup.counts;
  return Json::object()
      .set("read", c.read)
      .set("accepted", c.accepted)
      .set("culled", c.culled)
      .set("degenerate", c.degenerate)
      .set("offscreen", c.offscreen)
      .set("near_clipped", ls.scene.near_clipped)
      .set("near_dropped", ls.scene.near_dropped)
      .set("range_dropped", ls.scene.range_dropped);
}

Json config_json(const RasterConfig& cfg) {
  return Json::object()
      .set("width", cfg.width)
      .set("height", cfg.height)
      .set("subpixel_bits", cfg.subpixel_bits)
      .set("coord_bits", cfg.coord_int_bits)
      .set("cull", cull_mode_name(cfg.cull))
      .set("box_bits", cfg.box_bits)
      .set("boundary", boundary_mode_name(cfg.boundary))
      .set("divider", divider_mode_name(cfg.divider))
      .set("endpoints", cfg.endpoints)
      .set("fifo_depth", cfg.fifo_depth)
      .set("sink_stall", cfg.sink_stall);
}

// `option` is the option the name came from ("--engine", "--engines"), for the message.
const EngineInfo& engine_or_throw(const std::string& name, const std::string& cmd,
                                  const std::string& option) {
  const EngineInfo* info = find_engine(name);
  if (!info) {
    std::string known;
    for (const EngineInfo& e : engine_registry()) known += (known.empty() ? "" : ", ") + e.name;
    throw UsageError("trirast " + cmd + ": " + option + ": unknown engine '" + name +
                     "' (known: " + known + ")");
  }
  return *info;
}

struct EngineRun {
  const EngineInfo* info;
  EngineResult result;
  double seconds = 0;
};

// Golden options (--traversal, --threads) of a command; other engines ignore them.
struct GoldenOptions {
  Traversal traversal = Traversal::Auto;
  int threads = 1;
};

GoldenOptions golden_options_from(const Args& a) {
  GoldenOptions g;
  try {
    g.traversal = parse_traversal(a.get("--traversal"));
  } catch (const std::invalid_argument& e) {
    throw UsageError("trirast " + a.command() + ": " + e.what());
  }
  g.threads = int(a.get_int("--threads", 0, 256));
  return g;
}

EngineRun run_engine(const EngineInfo& info, const LoadedScene& ls, const RasterConfig& cfg,
                     const GoldenOptions& golden_options) {
  EngineRun run{&info, {}, 0};
  auto engine = info.name == "golden"
                    ? make_golden_engine(golden_options.traversal, golden_options.threads)
                    : info.make();
  auto t0 = Clock::now();
  engine->run(ls.setup, cfg, run.result);
  run.seconds = seconds_since(t0);
  sort_spans(run.result.spans);
  return run;
}

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// Work counters the text output of raster and compare leaves to --report: the per-module busy
// and stall cycles ("busy_cycles.setup", ...), and the total cycles and simulator speed, which
// have a line (raster) or a column (compare) of their own.
bool module_counter(const std::string& key) {
  return starts_with(key, "busy_cycles.") || starts_with(key, "stall_cycles.");
}
bool timing_counter(const std::string& key) {
  return key == "total_cycles" || starts_with(key, "sim_");
}

// Datapath work counters (the per-module busy/stall cycles are reported apart).
Json work_json(const EngineResult& r) {
  Json w = Json::object();
  for (const auto& kv : r.work)
    if (!module_counter(kv.first)) w.set(kv.first, kv.second);
  return w;
}

// Per-module busy and stall cycles of a timed engine: {module: {busy, stall}}.
std::map<std::string, std::pair<uint64_t, uint64_t>> module_cycles(const EngineResult& r) {
  std::map<std::string, std::pair<uint64_t, uint64_t>> modules;
  for (const auto& kv : r.work) {
    if (starts_with(kv.first, "busy_cycles.")) modules[kv.first.substr(12)].first = kv.second;
    if (starts_with(kv.first, "stall_cycles.")) modules[kv.first.substr(13)].second = kv.second;
  }
  return modules;
}

// Throughput of a timed engine, for the JSON report.
Json timing_json(const EngineResult& r, uint64_t triangles, uint64_t spans, int64_t pixels) {
  const double cycles = double(r.total_cycles);
  Json t = Json::object();
  t.set("total_cycles", r.total_cycles)
      .set("triangles_per_cycle", cycles > 0 ? triangles / cycles : 0.0)
      .set("spans_per_cycle", cycles > 0 ? spans / cycles : 0.0)
      .set("pixels_per_cycle", cycles > 0 ? pixels / cycles : 0.0);
  auto it = r.work.find("sim_cycles_per_second");
  if (it != r.work.end()) t.set("sim_cycles_per_second", it->second);
  Json modules = Json::object();
  for (const auto& [name, bs] : module_cycles(r))
    modules.set(name, Json::object().set("busy", bs.first).set("stall", bs.second));
  t.set("modules", modules);
  return t;
}

std::string engine_list_help() {
  std::string s;
  for (const EngineInfo& e : engine_registry()) s += (s.empty() ? "" : " | ") + e.name;
  return s;
}

// ---------------------------------------------------------------------------------------------
int cmd_raster(int argc, char** argv) {
  auto specs = scene_options();
  specs.insert(specs.begin(), {"--engine", "NAME", "engine: " + engine_list_help(), "golden"});
  specs.push_back({"--spans", "FILE", "write spans: 'tri y x_begin x_end' per line, sorted", ""});
  specs.push_back({"--image", "FILE.png", "write the viewport as PNG, a colour per triangle", ""});
  specs.push_back({"--report", "FILE.json", "write the JSON report", ""});
  specs.push_back({"--cycles", "FILE.csv", "timed engines: per-triangle cycles (docs/timing.md)", ""});
  specs.push_back({"--trace", "FILE", "timed engines: waveform trace (.vcd; the rtl engine also .fst)", ""});
  specs.push_back({"--trace-tris", "A:B", "record only triangles A..B (scene indices) in the trace", ""});
  Args a("raster", "--scene SCENE [--engine NAME] [options]", specs);
  a.parse(argc, argv, 2);
  if (a.help_requested()) {
    std::cout << "Rasterize a scene with one engine and report spans, pixels and work.\n\n"
              << a.help_text();
    return 0;
  }
  RasterConfig cfg = config_from(a);
  const EngineInfo& info = engine_or_throw(a.get("--engine"), "raster", "--engine");
  if (a.has("--trace")) {
    check_output_path(a.get("--trace"), "--trace");
    cfg.trace_path = a.get("--trace");
  }
  if (a.has("--trace-tris")) {
    const std::string w = a.get("--trace-tris");
    long long first = -1, last = -1;
    char extra = 0;
    if (std::sscanf(w.c_str(), "%lld:%lld%c", &first, &last, &extra) != 2 || first < 0 ||
        last < first)
      throw UsageError("trirast raster: --trace-tris: expected A:B with 0 <= A <= B, got '" + w + "'");
    cfg.trace_first = first;
    cfg.trace_last = last;
  }
  if (a.has("--cycles")) check_output_path(a.get("--cycles"), "--cycles");
  // Refuse unwritable outputs before the run, so a long run cannot fail at the end.
  if (a.has("--spans")) check_output_path(a.get("--spans"), "--spans");
  if (a.has("--image")) check_output_path(a.get("--image"), "--image");
  if (a.has("--report")) check_output_path(a.get("--report"), "--report");

  auto t0 = Clock::now();
  LoadedScene ls = load_and_setup(a, cfg);
  EngineRun run = run_engine(info, ls, cfg, golden_options_from(a));
  const int64_t pixels = count_pixels(run.result.spans);

  Json report = Json::object();
  report.set("engine", info.name)
      .set("scene", a.get("--scene"))
      .set("config", config_json(cfg))
      .set("triangles", triangle_counts(ls))
      .set("spans", uint64_t(run.result.spans.size()))
      .set("pixels", pixels)
      .set("work", work_json(run.result));
  if (!run.result.cycles.empty())
    report.set("timing", timing_json(run.result, ls.setup.counts.accepted,
                                     run.result.spans.size(), pixels));

  if (a.has("--cycles")) {
    if (run.result.cycles.empty() && !ls.setup.tris.empty())
      throw UsageError("trirast raster: --cycles: engine '" + info.name + "' is not timed");
    write_cycles_file(run.result.cycles, a.get("--cycles"), "--cycles");
  }
  if (a.has("--spans")) write_spans_file(run.result.spans, a.get("--spans"), "--spans");
  if (a.has("--image"))
    write_png(coverage_image(run.result.spans, cfg.width, cfg.height), a.get("--image"), "--image");
  report.set("wall_seconds", Json::object()
                                 .set("load", ls.load_seconds)
                                 .set("setup", ls.setup_seconds)
                                 .set("engine", run.seconds)
                                 .set("total", seconds_since(t0)));
  if (a.has("--report")) {
    OutputFile out(a.get("--report"), "--report");
    out.write(report.dump());
    out.commit();
  }

  const SetupCounts& c = ls.setup.counts;
  std::printf("trirast raster: engine %s, scene %s, viewport %dx%d, S=%d\n", info.name.c_str(),
              a.get("--scene").c_str(), cfg.width, cfg.height, cfg.subpixel_bits);
  std::printf("  triangles  %llu read, %llu accepted, %llu degenerate, %llu culled, %llu offscreen",
              (unsigned long long)c.read, (unsigned long long)c.accepted,
              (unsigned long long)c.degenerate, (unsigned long long)c.culled,
              (unsigned long long)c.offscreen);
  if (ls.scene.near_clipped || ls.scene.near_dropped || ls.scene.range_dropped)
    std::printf(", %llu near-clipped, %llu near-dropped, %llu out of range",
                (unsigned long long)ls.scene.near_clipped, (unsigned long long)ls.scene.near_dropped,
                (unsigned long long)ls.scene.range_dropped);
  std::printf("\n  coverage   %zu spans, %lld pixels\n", run.result.spans.size(), (long long)pixels);
  for (const auto& kv : run.result.work)
    if (!module_counter(kv.first) && !timing_counter(kv.first))
      std::printf("  work       %-28s %llu\n", kv.first.c_str(), (unsigned long long)kv.second);
  if (!run.result.cycles.empty()) {
    const double c = double(std::max<uint64_t>(run.result.total_cycles, 1));
    std::printf("  cycles     %llu total: %.4f triangles, %.4f spans, %.3f pixels per cycle\n",
                (unsigned long long)run.result.total_cycles, ls.setup.counts.accepted / c,
                run.result.spans.size() / c, pixels / c);
    auto sim = run.result.work.find("sim_cycles_per_second");
    if (sim != run.result.work.end())
      std::printf("  simulated  %.1f M cycles per wall-clock second\n", sim->second / 1e6);
    std::printf("  %-26s %12s %12s\n", "module", "busy", "stall");
    for (const auto& [name, bs] : module_cycles(run.result))
      std::printf("  %-26s %12llu %12llu\n", name.c_str(), (unsigned long long)bs.first,
                  (unsigned long long)bs.second);
  }
  std::printf("  time       %.3f s (load %.3f, setup %.3f, engine %.3f)\n", seconds_since(t0),
              ls.load_seconds, ls.setup_seconds, run.seconds);
  for (const char* opt : {"--spans", "--image", "--report", "--cycles", "--trace"})
    if (a.has(opt)) std::printf("  wrote      %s (%s)\n", a.get(opt).c_str(), opt + 2);
  if (a.has("--trace") && file_exists(gtkw_path(a.get("--trace"))))
    std::printf("  wrote      %s (GTKWave save file)\n", gtkw_path(a.get("--trace")).c_str());
  return 0;
}

// ---------------------------------------------------------------------------------------------
// "a,,b" and "a," hold an empty item: kept, so the caller can refuse it.
std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  if (s.empty()) return out;
  size_t start = 0;
  for (;;) {
    const size_t comma = s.find(',', start);
    out.push_back(s.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

int cmd_compare(int argc, char** argv) {
  auto specs = scene_options();
  specs.insert(specs.begin(), {"--engines", "A,B,...", "engines to run against the golden: " +
                                                           engine_list_help() +
                                                           ", or file:SPANS for recorded spans", "golden"});
  specs.push_back({"--diff-image", "FILE.png",
                   "PNG of the first engine that differs from golden (else the first non-golden one): grey agreed, red missing, blue extra", ""});
  specs.push_back({"--report", "FILE.json", "write the comparison as JSON", ""});
  Args a("compare", "--scene SCENE --engines A,B,... [options]", specs);
  a.parse(argc, argv, 2);
  if (a.help_requested()) {
    std::cout << "Run engines on one scene and compare each with the golden pixel for pixel.\n"
                 "Exit status 0 only if every exact engine (all but trad) agrees with the golden.\n\n"
              << a.help_text();
    return 0;
  }
  const RasterConfig cfg = config_from(a);
  // "file:PATH" stands for spans recorded by another implementation (interchange format); it
  // claims exactness, so any difference from the golden fails the comparison.
  std::vector<EngineInfo> file_engines;
  std::vector<std::string> names = split_list(a.get("--engines"));
  for (const std::string& name : names) {
    if (name.empty())
      throw UsageError("trirast compare: --engines: empty engine name in '" + a.get("--engines") +
                       "'");
    if (name.rfind("file:", 0) == 0) file_engines.push_back({name, "recorded spans", true, nullptr});
  }
  std::vector<const EngineInfo*> engines;
  size_t next_file = 0;
  for (const std::string& name : names)
    engines.push_back(name.rfind("file:", 0) == 0 ? &file_engines[next_file++]
                                                   : &engine_or_throw(name, "compare", "--engines"));
  if (engines.empty()) throw UsageError("trirast compare: --engines: empty list");
  if (a.has("--diff-image")) check_output_path(a.get("--diff-image"), "--diff-image");
  if (a.has("--report")) check_output_path(a.get("--report"), "--report");

  // Every input is read and checked before anything is printed: the scene, then the recorded
  // spans files, so a bad one is a one-line error with nothing on stdout.
  LoadedScene ls = load_and_setup(a, cfg);
  std::vector<SpanList> recorded(file_engines.size());
  for (size_t i = 0; i < file_engines.size(); ++i) {
    recorded[i] = read_spans_file(file_engines[i].name.substr(5));
    sort_spans(recorded[i]);
  }
  const GoldenOptions golden_options = golden_options_from(a);
  EngineRun golden = run_engine(*find_engine("golden"), ls, cfg, golden_options);
  const int64_t golden_pixels = count_pixels(golden.result.spans);

  std::printf("trirast compare: scene %s, viewport %dx%d, S=%d, %llu triangles (%llu accepted)\n",
              a.get("--scene").c_str(), cfg.width, cfg.height, cfg.subpixel_bits,
              (unsigned long long)ls.setup.counts.read, (unsigned long long)ls.setup.counts.accepted);
  std::printf("  %-14s %6s %10s %12s %10s %10s %9s %10s  %s\n", "engine", "exact", "spans",
              "pixels", "missing", "extra", "seconds", "cycles", "work");
  bool any_module_counters = false;
  bool all_exact_agree = true;
  std::string diff_engine;  // the engine shown in --diff-image
  bool diff_agrees = true;
  SpanDiff diff_for_image;
  Json rows = Json::array();
  for (const EngineInfo* info : engines) {
    EngineRun run{info, {}, 0};
    if (info->name == "golden") {
      run = golden;
    } else if (!info->make) {
      run.result.spans = std::move(recorded[size_t(info - file_engines.data())]);
    } else {
      run = run_engine(*info, ls, cfg, golden_options);
    }
    const SpanDiff diff = diff_spans(golden.result.spans, run.result.spans);
    const bool agrees = diff.exact();
    if (info->exact && !agrees) all_exact_agree = false;
    // The work column: the engine's own counters, not those already in a column (spans,
    // pixels, triangles) nor those left to --report, or the line would run to a screen and more.
    std::string work;
    for (const auto& kv : run.result.work) {
      const std::string& k = kv.first;
      any_module_counters = any_module_counters || module_counter(k);
      if (module_counter(k) || timing_counter(k) || k == "spans" || k == "pixels" ||
          k == "triangles")
        continue;
      work += (work.empty() ? "" : " ") + k + "=" + std::to_string(kv.second);
    }
    const bool timed = run.result.total_cycles > 0 || run.result.work.count("total_cycles") > 0;
    const std::string cycles = timed ? std::to_string(run.result.total_cycles) : "-";
    std::printf("  %-14s %6s %10zu %12lld %10lld %10lld %9.3f %10s  %s%s\n", info->name.c_str(),
                info->exact ? "yes" : "no", run.result.spans.size(),
                (long long)count_pixels(run.result.spans), (long long)diff.missing_pixels,
                (long long)diff.extra_pixels, run.seconds, cycles.c_str(), work.c_str(),
                info->exact && !agrees ? "  <-- DISAGREES WITH GOLDEN" : "");
    rows.push(Json::object()
                  .set("engine", info->name)
                  .set("claims_exact", info->exact)
                  .set("spans", uint64_t(run.result.spans.size()))
                  .set("pixels", count_pixels(run.result.spans))
                  .set("missing_pixels", diff.missing_pixels)
                  .set("extra_pixels", diff.extra_pixels)
                  .set("agrees", agrees)
                  .set("seconds", run.seconds)
                  .set("work", work_json(run.result)));
    // The diff image shows the first engine that differs from the golden, or else the first
    // engine other than the golden.
    if (info->name != "golden" && (diff_engine.empty() || (!agrees && diff_agrees))) {
      diff_engine = info->name;
      diff_agrees = agrees;
      diff_for_image = diff;
    }
  }
  if (any_module_counters)
    std::printf("  (cycles: total of the timed engines; per-module busy and stall cycles and the "
                "simulation speed: %s)\n",
                a.has("--report") ? ("in " + a.get("--report")).c_str() : "--report FILE.json");
  if (a.has("--diff-image")) {
    write_png(diff_image(golden.result.spans, diff_for_image, cfg.width, cfg.height),
              a.get("--diff-image"), "--diff-image");
    std::printf("  wrote %s (%s against golden: grey agreed, red missing, blue extra)\n",
                a.get("--diff-image").c_str(), diff_engine.empty() ? "golden" : diff_engine.c_str());
  }
  if (a.has("--report")) {
    OutputFile out(a.get("--report"), "--report");
    out.write(Json::object()
                  .set("scene", a.get("--scene"))
                  .set("config", config_json(cfg))
                  .set("triangles", triangle_counts(ls))
                  .set("golden_pixels", golden_pixels)
                  .set("engines", rows)
                  .set("all_exact_agree", all_exact_agree)
                  .dump());
    out.commit();
    std::printf("  wrote %s (report)\n", a.get("--report").c_str());
  }
  std::printf("  result: %s\n", all_exact_agree ? "every exact engine agrees with the golden"
                                                 : "MISMATCH: an exact engine disagrees with the golden");
  return all_exact_agree ? 0 : 1;
}

// ---------------------------------------------------------------------------------------------
int cmd_scenes(int argc, char** argv) {
  Args a("scenes", "", {});
  a.parse(argc, argv, 2);
  if (a.help_requested()) {
    std::cout << "List the built-in scenes (use as --scene builtin:NAME[:key=value,...]).\n\n"
              << a.help_text();
    return 0;
  }
  for (const BuiltinInfo& b : builtin_scenes())
    std::printf("%-22s %s\n", b.name.c_str(), b.description.c_str());
  return 0;
}

int cmd_engines(int argc, char** argv) {
  Args a("engines", "", {});
  a.parse(argc, argv, 2);
  if (a.help_requested()) {
    std::cout << "List the engines compiled into this build.\n\n" << a.help_text();
    return 0;
  }
  for (const EngineInfo& e : engine_registry())
    std::printf("%-15s %-8s %s\n", e.name.c_str(), e.exact ? "exact" : "inexact",
                e.description.c_str());
  return 0;
}

void print_usage() {
  std::cout <<
      "trirast: a cycle-level model of the improved-Bresenham triangle rasterization unit\n"
      "\n"
      "usage: trirast COMMAND [options]     (trirast COMMAND --help for its options)\n"
      "\n"
      "commands:\n"
      "  raster    rasterize a scene with one engine; write spans, a PNG and a JSON report\n"
      "  compare   run engines on a scene and compare them with the golden pixel for pixel\n"
      "  scenes    list the built-in scenes\n"
      "  engines   list the engines\n"
      "  fuzz      random scenes through several engines; a disagreement becomes a .tri reproducer\n"
      "  sweep     engines x configurations x scenes: cycles, area and time against error\n"
      "  fit       the smallest configuration that is exact (or within an error budget) on a scene\n"
      "\n"
      "exit status: 0 success, 1 an exact engine disagrees with the golden, 2 bad input or usage\n";
}

}  // namespace

int run_cli(int argc, char** argv) {
  try {
    if (argc < 2) {
      print_usage();
      return 2;
    }
    const std::string cmd = argv[1];
    if (cmd == "--help" || cmd == "-h" || cmd == "help") {
      print_usage();
      return 0;
    }
    if (cmd == "raster") return cmd_raster(argc, argv);
    if (cmd == "compare") return cmd_compare(argc, argv);
    if (cmd == "scenes") return cmd_scenes(argc, argv);
    if (cmd == "engines") return cmd_engines(argc, argv);
    if (cmd == "fuzz") return cmd_fuzz(argc, argv);
    if (cmd == "sweep") return cmd_sweep(argc, argv);
    if (cmd == "fit") return cmd_fit(argc, argv);
    throw UsageError("trirast: unknown command '" + cmd + "' (see trirast --help)");
  } catch (const UsageError& e) {
    std::fprintf(stderr, "%s\n", e.what());
  } catch (const SceneError& e) {
    std::fprintf(stderr, "trirast: %s\n", e.what());
  } catch (const SetupError& e) {
    std::fprintf(stderr, "trirast: %s\n", e.what());
  } catch (const WidthError& e) {
    std::fprintf(stderr, "trirast: %s\n", e.what());
  } catch (const OutputError& e) {
    std::fprintf(stderr, "trirast: %s\n", e.what());
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "trirast: out of memory\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "trirast: %s\n", e.what());
  }
  return 2;
}

}  // namespace trirast
