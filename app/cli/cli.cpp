#include "cli/cli.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "cli/scene_options.hpp"
#include "common/engine.hpp"
#include "common/fixed_point.hpp"
#include "common/temporary_files.hpp"
#include "common/span_diff.hpp"
#include "engines.hpp"
#include "units.hpp"
#include "golden/golden.hpp"
#include "io/cycles_file.hpp"
#include "io/image.hpp"
#include "io/json.hpp"
#include "io/report_descriptions.hpp"
#include "io/diff_report.hpp"
#include "io/output_file.hpp"
#include "io/cycles_file.hpp"
#include "io/heatmap.hpp"
#include "cli/slowest.hpp"
#include "cli/source_files.hpp"
#include "sweep/sweep_area.hpp"
#include "io/spans_file.hpp"
#include "io/kit_vectors.hpp"
#include "scene/scene.hpp"
#include "util.hpp"

namespace trirast {

namespace {


// The GTKWave save file a trace writer leaves beside FILE.vcd / FILE.fst.
std::string gtkw_path(const std::string& trace) {
  const size_t dot = trace.find_last_of('.');
  const size_t slash = trace.find_last_of('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_ext ? trace.substr(0, dot) : trace) + ".gtkw";
}

// The engines that read an engine option, for its --help line: "timed engines" when those are
// the ones; else a unit whose every view reads it as "unit-*" and other engines by name.
std::string option_scope(const std::string& option) {
  bool timed_only = true;
  for (const EngineDescriptor& d : engine_descriptors())
    timed_only = timed_only && engine_reads(d.info.name, option) == d.info.timed;
  if (timed_only) return "timed engines";
  std::string scope;
  auto add = [&](const std::string& name) { scope += (scope.empty() ? "" : ", ") + name; };
  for (const EngineDescriptor& d : engine_descriptors()) {
    if (!engine_reads(d.info.name, option)) continue;
    if (!d.unit) {
      add(d.info.name);
      continue;
    }
    bool all = true;
    for (const UnitView& v : d.unit->views)
      all = all && engine_reads(d.unit->name + "-" + v.view, option);
    if (!all)
      add(d.info.name);
    else if (d.info.name == d.unit->name + "-" + d.unit->views.front().view)
      add(d.unit->name + "-*");
  }
  return scope;
}

// Options every scene-consuming subcommand shares: the scene's (cli/scene_options.hpp, which
// fit shares too) and the engines' configuration. An engine option's help names the engines
// that read it (units.hpp); giving it to another engine is an error (check_engine_options).
std::vector<OptionSpec> scene_options() {
  std::vector<OptionSpec> specs = scene_input_options();
  std::vector<OptionSpec> engine_specs = {
      {"--coord-bits", "N", "signed integer bits of a coordinate: range [-2^(N-1), 2^(N-1)) px", "16"},
      {"--traversal", "NAME", "pixel traversal, simple | incremental | block | adaptive | bisector | sat-block | window | scanline | auto", "auto"},
      {"--threads", "N", "threads (0 = all cores)", "1"},
      {"--box-bits", "N", "bits of a box-relative coordinate, 1..14", "14"},
      {"--boundary", "MODE", "boundary traversal, step (the paper) | divide", "step"},
      {"--divider", "MODE", "divider iterations, adaptive (bits the box needs) | fixed (box-bits + 1)", "adaptive"},
      {"--stamp", "S", "stamp of S x S pixels tested per cycle, 1 | 2 | 4", "2"},
      {"--tile", "T", "tile of T x T pixels rejected/accepted from its corners, 8 | 16 | none", "8"},
      {"--hs-walk", "ORDER", "tile order, row (every tile) | zigzag (alternate bands, end a band after its last non-rejected tile) | forward (every band left to right, ended as zigzag ends it)", "forward"},
      {"--corner-form", "FORM", "corner values by dsp (products, 1 cycle) | radix16 (digit-serial, MSB first)", "radix16"},
      {"--hs-corner-form", "FORM", "edge values at the box corner by dsp (products, 1 cycle) | radix16 (digit-serial, MSB first: 2 + nL cycles, plus 1 + nR in the zigzag walk for a box wider than one unit: a tile, or a stamp without tiles)", "dsp"},
      {"--endpoints", "N", "rows (endpoints per edge) walked per cycle, 1 | 2 | 4", "1"},
      {"--fifo-depth", "D", "span FIFO entries (>= --endpoints)", "8"},
      {"--sink-stall", "PATTERN", "the downstream of the span output: a ready pattern none | periodic:READY:STALL (cycles) | random:SEED:PERCENT (stall percent 0..99), or queue:RATE:CAPACITY, a pixel queue that reacts to what it took (consumes RATE pixels per cycle; ready while fewer than CAPACITY pixels are queued)", "none"},
      {"--rtl-checked", "", "the checked Verilated builds (assertions, cover points, trace support) where a speed build covers the run (--coverage and --trace take them anyway; docs/rtl.md)", ""},
  };
  for (OptionSpec& spec : engine_specs)
    if (std::find(engine_options().begin(), engine_options().end(), spec.name) !=
        engine_options().end())
      spec.help = option_scope(spec.name) + ": " + spec.help;
  specs.insert(specs.end(), engine_specs.begin(), engine_specs.end());
  return specs;
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
  cfg.rtl_checked = a.has("--rtl-checked");
  cfg.halfspace.stamp = int(a.get_int("--stamp", 1, 4));
  try {
    const std::string tile = a.get("--tile");
    if (tile == "none") {
      cfg.halfspace.tile = 0;
    } else {
      cfg.halfspace.tile = int(a.get_int("--tile", 8, 16));
    }
    cfg.halfspace.walk = parse_halfspace_walk(a.get("--hs-walk"));
    cfg.cull = parse_cull_mode(a.get("--cull"));
    cfg.boundary = parse_boundary_mode(a.get("--boundary"));
    cfg.divider = parse_divider_mode(a.get("--divider"));
    cfg.improved2.corner_form = parse_corner_form(a.get("--corner-form"));
    cfg.halfspace.corner_form = parse_corner_form(a.get("--hs-corner-form"), "--hs-corner-form");
    cfg.validate();
  } catch (const std::invalid_argument& e) {
    throw UsageError("trirast " + a.command() + ": " + e.what());
  }
  return cfg;
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
      .set("read", ls.scene.source_triangles())
      .set("set_up", c.read)
      .set("accepted", c.accepted)
      .set("culled", c.culled)
      .set("degenerate", c.degenerate)
      .set("offscreen", c.offscreen)
      .set("no_pixel_centre", c.no_pixel_centre)
      .set("near_clipped", ls.scene.near_clipped)
      .set("near_dropped", ls.scene.near_dropped)
      .set("range_dropped", ls.scene.range_dropped);
}

// Golden options (--traversal, --threads) of a command; other engines ignore them.
struct GoldenOptions {
  Traversal traversal = Traversal::Auto;
  int threads = 1;
};

// The parameters that shaped the run of `engines` (compare: the golden among them): the scene's,
// then each engine option (units.hpp) that one of them reads, with the value it ran with.
Json config_json(const RasterConfig& cfg, const GoldenOptions& golden,
                 const std::vector<std::string>& engines) {
  Json j = Json::object();
  j.set("width", cfg.width)
      .set("height", cfg.height)
      .set("subpixel_bits", cfg.subpixel_bits)
      .set("coord_bits", cfg.coord_int_bits)
      .set("cull", cull_mode_name(cfg.cull));
  // Each engine option's key and the value the run used.
  const std::map<std::string, std::pair<const char*, Json>> value = {
      {"--box-bits", {"box_bits", Json::integer(cfg.box_bits)}},
      {"--boundary", {"boundary", Json::string(boundary_mode_name(cfg.boundary))}},
      {"--divider", {"divider", Json::string(divider_mode_name(cfg.divider))}},
      {"--stamp", {"stamp", Json::integer(cfg.halfspace.stamp)}},
      {"--tile", {"tile", Json::integer(cfg.halfspace.tile)}},
      {"--hs-walk", {"hs_walk", Json::string(halfspace_walk_name(cfg.halfspace.walk))}},
      {"--corner-form", {"corner_form", Json::string(corner_form_name(cfg.improved2.corner_form))}},
      {"--hs-corner-form", {"hs_corner_form", Json::string(corner_form_name(cfg.halfspace.corner_form))}},
      {"--endpoints", {"endpoints", Json::integer(cfg.endpoints)}},
      {"--fifo-depth", {"fifo_depth", Json::integer(cfg.fifo_depth)}},
      {"--sink-stall", {"sink_stall", Json::string(cfg.sink_stall)}},
      {"--traversal", {"traversal", Json::string(traversal_name(golden.traversal))}},
      {"--threads", {"threads", Json::integer(golden.threads)}},
      {"--rtl-checked", {"rtl_checked", Json::boolean(cfg.rtl_checked)}},
  };
  for (const std::string& option : engine_options())
    if (std::any_of(engines.begin(), engines.end(),
                    [&](const std::string& e) { return engine_reads(e, option); }))
      j.set(value.at(option).first, value.at(option).second);
  return j;
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
                     const GoldenOptions& golden_options, SpanList* output_order = nullptr) {
  EngineRun run{&info, {}, 0};
  auto engine = info.name == "golden"
                    ? make_golden_engine(golden_options.traversal, golden_options.threads)
                    : info.make();
  auto t0 = Clock::now();
  engine->run(ls.setup, cfg, run.result);
  run.seconds = seconds_since(t0);
  if (output_order) *output_order = run.result.spans;  // as the engine's span output gave them
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
  it = r.work.find("sim_cycles_per_cpu_second");
  if (it != r.work.end()) t.set("sim_cycles_per_cpu_second", it->second);
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
  specs.push_back({"--trace", "FILE.vcd|FILE.fst",
                   "timed engines: waveform trace, VCD or FST by the extension, and FILE.gtkw",
                   ""});
  specs.push_back({"--trace-tris", "A:B", "record only triangles A..B (scene indices) in the trace", ""});
  specs.push_back({"--vectors", "DIR",
                   "a unit's -rtl or -sc engine: write the testbench kit's stimulus and expected "
                   "spans and cycles into DIR (tb/kit, docs/port.md)",
                   ""});
  specs.push_back({"--coverage", "FILE",
                   "RTL engines: every cover point of the unit with its count (docs/coverage.md)", ""});
  add_diag_options(specs, false);
  Args a("raster", "--scene SCENE [--engine NAME] [options]", specs);
  a.parse(argc, argv, 2);
  if (a.help_requested()) {
    std::cout << "Rasterize a scene with one engine and report spans, pixels and work.\n\n"
              << a.help_text();
    return 0;
  }
  RasterConfig cfg = config_from(a);
  const EngineInfo& info = engine_or_throw(a.get("--engine"), "raster", "--engine");
  check_engine_options(a, {info.name});
  if (a.has("--trace")) {
    check_trace_engine(info, "raster");
    check_trace_path(a.get("--trace"), "raster");
    cfg.trace_path = a.get("--trace");
  }
  if (a.has("--trace-tris") && !a.has("--trace"))
    throw UsageError("trirast raster: --trace-tris: needs --trace FILE (it selects what the trace records)");
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
  if (a.has("--cycles")) {
    if (!info.timed)
      throw UsageError("trirast raster: --cycles: engine '" + info.name + "' is not timed");
    check_output_path(a.get("--cycles"), "--cycles");
  }
  // Refuse unwritable outputs before the run, so a long run cannot fail at the end.
  if (a.has("--spans")) check_output_path(a.get("--spans"), "--spans");
  if (a.has("--image")) check_png_path(a.get("--image"), "raster", "--image");
  if (a.has("--report")) check_output_path(a.get("--report"), "--report");
  if (a.has("--vectors")) check_kit_vectors(info.name, cfg, a.get("--vectors"));
  if (a.has("--coverage")) {
    check_coverage_option(a.get("--coverage"), {info.name}, "raster");
    cfg.rtl_checked = true;  // the cover points are in the checked builds
  }
  const DiagOptions diag = diag_options_from(a, false);

  auto t0 = Clock::now();
  LoadedScene ls = load_and_setup(a, cfg);
  if (a.has("--trace-tris"))
    check_trace_window(cfg.trace_first, cfg.trace_last, ls.scene.tris.size(), "raster");
  OutputStamps stamps;  // what was at the output paths before this run
  for (const char* opt : {"--spans", "--image", "--report", "--cycles", "--trace", "--coverage"})
    if (a.has(opt)) stamps.note(a.get(opt));
  if (a.has("--trace")) stamps.note(gtkw_path(a.get("--trace")));
  const GoldenOptions golden_options = golden_options_from(a);
  SpanList output_order;  // --vectors: each triangle's spans in the order its span port gave them
  EngineRun run = run_engine(info, ls, cfg, golden_options,
                             a.has("--vectors") ? &output_order : nullptr);
  const int64_t pixels = count_pixels(run.result.spans);

  Json report = Json::object();
  report.set("engine", info.name)
      .set("scene", a.get("--scene"))
      .set("config", config_json(cfg, golden_options, {info.name}))
      .set("triangles", triangle_counts(ls))
      .set("spans", uint64_t(run.result.spans.size()))
      .set("pixels", pixels)
      .set("work", work_json(run.result));
  if (!run.result.cycles.empty())
    report.set("timing", timing_json(run.result, ls.setup.counts.accepted,
                                     run.result.spans.size(), pixels));

  if (a.has("--cycles")) {
    write_cycles_file(run.result.cycles, a.get("--cycles"), "--cycles");
  }
  if (a.has("--spans")) write_spans_file(run.result.spans, a.get("--spans"), "--spans");
  if (a.has("--vectors"))
    write_kit_vectors(a.get("--vectors"), info.name, a.get("--scene"), ls.setup, cfg, run.result,
                      output_order);
  std::string coverage_summary;
  if (a.has("--coverage"))
    coverage_summary = write_coverage_report(a.get("--coverage"), {info.name},
                                             "trirast raster --engine " + info.name + " --scene " +
                                                 a.get("--scene"));
  if (a.has("--image"))
    write_png(coverage_image(run.result.spans, cfg.width, cfg.height), a.get("--image"), "--image");
  if (!diag.heatmap_path.empty()) {
    if (run.result.cycles.empty() && !ls.setup.tris.empty())
      throw UsageError("trirast raster: --heatmap: engine '" + info.name + "' is not timed");
    write_png(heatmap_image(run.result.spans, run.result.cycles, diag.heatmap_metric, info.name,
                            cycle_words(info.name).setup_title, cfg.width, cfg.height),
              diag.heatmap_path, "--heatmap");
  }
  size_t exported = 0;
  if (diag.export_tris)
    exported = export_tri_window(ls.setup, cfg, diag.export_first, diag.export_last,
                                 diag.export_path, "--export-tris", a.get("--scene"));
  report.set("wall_seconds", Json::object()
                                 .set("load", ls.load_seconds)
                                 .set("setup", ls.setup_seconds)
                                 .set("engine", run.seconds)
                                 .set("total", seconds_since(t0)));
  if (a.has("--report")) {
    add_descriptions(report);
    OutputFile out(a.get("--report"), "--report");
    out.write(report.dump());
    out.commit();
  }

  const SetupCounts& c = ls.setup.counts;
  std::printf("trirast raster: engine %s, scene %s, viewport %dx%d, S=%d\n", info.name.c_str(),
              a.get("--scene").c_str(), cfg.width, cfg.height, cfg.subpixel_bits);
  std::printf("  triangles  %llu read, %llu accepted, %llu degenerate, %llu culled, %llu offscreen, "
              "%llu without a pixel centre",
              (unsigned long long)ls.scene.source_triangles(), (unsigned long long)c.accepted,
              (unsigned long long)c.degenerate, (unsigned long long)c.culled,
              (unsigned long long)c.offscreen, (unsigned long long)c.no_pixel_centre);
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
    auto sim_cpu = run.result.work.find("sim_cycles_per_cpu_second");
    if (sim != run.result.work.end() && sim_cpu != run.result.work.end())
      std::printf("  simulated  %.1f M cycles per wall-clock second, %.1f M per CPU second\n",
                  sim->second / 1e6, sim_cpu->second / 1e6);
    else if (sim != run.result.work.end())
      std::printf("  simulated  %.1f M cycles per wall-clock second\n", sim->second / 1e6);
    std::printf("  %-26s %12s %12s\n", "module", "busy", "stall");
    for (const auto& [name, bs] : module_cycles(run.result))
      std::printf("  %-26s %12llu %12llu\n", name.c_str(), (unsigned long long)bs.first,
                  (unsigned long long)bs.second);
  }
  std::printf("  time       %.3f s (load %.3f, setup %.3f, engine %.3f)\n", seconds_since(t0),
              ls.load_seconds, ls.setup_seconds, run.seconds);
  if (!coverage_summary.empty()) std::printf("  %s\n", coverage_summary.c_str());
  // Only files this run wrote: a stale save file from an earlier run is not reported.
  for (const char* opt : {"--spans", "--image", "--report", "--cycles", "--trace", "--coverage"})
    if (a.has(opt) && stamps.written(a.get(opt)))
      std::printf("  wrote      %s (%s)\n", a.get(opt).c_str(), opt + 2);
  if (!diag.heatmap_path.empty())
    std::printf("  wrote      %s (heatmap of %s)\n", diag.heatmap_path.c_str(), diag.heatmap_metric.c_str());
  if (diag.export_tris)
    std::printf("  wrote      %s (%zu set-up triangles of %lld..%lld)\n", diag.export_path.c_str(),
                exported, (long long)diag.export_first, (long long)diag.export_last);
  if (a.has("--trace") && stamps.written(gtkw_path(a.get("--trace"))))
    std::printf("  wrote      %s (GTKWave save file)\n", gtkw_path(a.get("--trace")).c_str());
  if (a.has("--vectors"))
    std::printf("  wrote      %s/ (testbench kit vectors: %zu triangles, %zu spans; README.txt)\n",
                a.get("--vectors").c_str(), ls.setup.tris.size(), output_order.size());
  return 0;
}

// ---------------------------------------------------------------------------------------------
// The routed clock a timed engine's cycles are read at (compare's time column): its unit's iCE40
// HX8K Fmax at the run's widths from docs/synth.csv, when scripts/synth.sh placed and routed that
// configuration (FIFO 8, N = 1; the half-space unit's tile 8 and forward walk). `why` says where
// the figure came from, or why there is none.
double routed_fmax_mhz(const AreaModel& area, const std::string& engine, const RasterConfig& cfg,
                       std::string& why) {
  const UnitDescriptor* unit = unit_of(engine);
  const UnitKind kind = unit ? unit_kind_of(unit->name) : UnitKind::Cpu;
  const RasterConfig d;
  const bool built = cfg.fifo_depth == d.fifo_depth &&
                     (kind != UnitKind::Halfspace || (cfg.halfspace.tile == d.halfspace.tile &&
                                                      cfg.halfspace.walk == d.halfspace.walk));
  const double f = built ? area.csv_fmax_mhz(kind, cfg) : 0;
  char text[160];
  if (f > 0)
    std::snprintf(text, sizeof text, "%.2f MHz (%s)", f, synth_unit_name(kind, cfg).c_str());
  else
    std::snprintf(text, sizeof text, "none: no routed row of %s at these widths",
                  synth_unit_name(kind, cfg).c_str());
  why = text;
  return f;
}

int cmd_compare(int argc, char** argv) {
  auto specs = scene_options();
  specs.insert(specs.begin(), {"--engines", "A,B,...", "engines to run against the golden: " +
                                                           engine_list_help() +
                                                           ", or file:SPANS for recorded spans", "golden"});
  specs.push_back({"--diff-image", "FILE.png",
                   "PNG of the first engine that differs from golden (else the first non-golden one): grey agreed, red missing, blue extra", ""});
  specs.push_back({"--report", "FILE.json", "write the comparison as JSON", ""});
  add_diag_options(specs, true);
  Args a("compare", "--scene SCENE --engines A,B,... [options]", specs);
  a.parse(argc, argv, 2);
  if (a.help_requested()) {
    std::string inexact;
    for (const EngineInfo& e : engine_registry())
      if (!e.exact) inexact += (inexact.empty() ? "" : ", ") + e.name;
    std::cout << "Run engines on one scene and compare each with the golden pixel for pixel.\n"
              << "Exit status 0 only if every exact engine (all but " + inexact + ")\n"
              << "agrees with the golden. Engines of one unit's timed pair (its SystemC model and\n"
                 "RTL) must also agree on every triangle's cycles.\n\n"
              << a.help_text();
    return 0;
  }
  const RasterConfig cfg = config_from(a);
  // "file:PATH" stands for spans recorded by another implementation (interchange format); it
  // claims exactness, so any difference from the golden fails the comparison.
  std::vector<EngineInfo> file_engines;
  std::vector<std::string> names = split(a.get("--engines"), ',');
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
  std::vector<std::string> engine_names;  // the engines that run (recorded spans do not)
  for (const EngineInfo* info : engines)
    if (info->make) engine_names.push_back(info->name);
  check_engine_options(a, engine_names);
  if (a.has("--diff-image")) check_png_path(a.get("--diff-image"), "compare", "--diff-image");
  if (a.has("--report")) check_output_path(a.get("--report"), "--report");
  const DiagOptions diag = diag_options_from(a, true);

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
              (unsigned long long)ls.scene.source_triangles(),
              (unsigned long long)ls.setup.counts.accepted);
  std::printf("  %-17s %6s %10s %12s %10s %10s %9s %10s %10s  %s\n", "engine", "exact", "spans",
              "pixels", "missing", "extra", "seconds", "cycles", "us@Fmax", "work");
  // The time column: each timed engine's cycles at its unit's routed clock (routed_fmax_mhz).
  const std::string synth_csv = source_file("docs/synth.csv");
  const AreaModel area(synth_csv, source_file("scripts/synth.sh"));
  std::vector<std::string> fmax_notes;
  bool any_module_counters = false;
  bool all_exact_agree = true;
  std::string diff_engine;  // the engine shown in --diff-image
  bool diff_agrees = true;
  SpanDiff diff_for_image;
  std::vector<std::pair<std::string, SpanDiff>> diffs;  // every engine but the golden
  std::vector<Json> rows;  // one per engine, in --engines order
  std::vector<std::string> row_engines;
  // The timed engines' per-triangle cycles (and the first one's spans, for --heatmap).
  std::vector<std::pair<std::string, std::vector<TriangleCycles>>> timed_cycles;
  SpanList heatmap_spans;
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
    std::string fmax_why, micros = "-";
    const double fmax = timed ? routed_fmax_mhz(area, info->name, cfg, fmax_why) : 0;
    if (timed) {
      char t[32];
      std::snprintf(t, sizeof t, "%.1f", double(run.result.total_cycles) / fmax);
      micros = fmax > 0 ? t : "n/a";
      fmax_notes.push_back(info->name + " " + fmax_why);
    }
    if (timed) {
      if (timed_cycles.empty() && !diag.heatmap_path.empty()) heatmap_spans = run.result.spans;
      timed_cycles.emplace_back(info->name, run.result.cycles);
    }
    std::printf("  %-17s %6s %10zu %12lld %10lld %10lld %9.3f %10s %10s  %s%s\n", info->name.c_str(),
                info->exact ? "yes" : "no", run.result.spans.size(),
                (long long)count_pixels(run.result.spans), (long long)diff.missing_pixels,
                (long long)diff.extra_pixels, run.seconds, cycles.c_str(), micros.c_str(), work.c_str(),
                info->exact && !agrees ? "  <-- DISAGREES WITH GOLDEN" : "");
    Json row = Json::object();
    row.set("engine", info->name)
                  .set("claims_exact", info->exact)
                  .set("spans", uint64_t(run.result.spans.size()))
                  .set("pixels", count_pixels(run.result.spans))
                  .set("missing_pixels", diff.missing_pixels)
                  .set("extra_pixels", diff.extra_pixels)
                  .set("agrees", agrees)
                  .set("seconds", run.seconds)
                  .set("work", work_json(run.result));
    if (timed) {
      row.set("fmax_mhz", Json::number(fmax > 0 ? fmax : NAN));
      row.set("microseconds_at_fmax",
              Json::number(fmax > 0 ? double(run.result.total_cycles) / fmax : NAN));
      row.set("fmax_source", fmax_why);
    }
    if (info->name != "golden") {
      add_diff_listing(row, diff);
      diffs.push_back({info->name, diff});
    }
    rows.push_back(row);
    row_engines.push_back(info->name);
    // The diff image shows the first engine that differs from the golden, or else the first
    // engine other than the golden.
    if (info->name != "golden" && (diff_engine.empty() || (!agrees && diff_agrees))) {
      diff_engine = info->name;
      diff_agrees = agrees;
      diff_for_image = diff;
    }
  }
  if (!fmax_notes.empty()) {
    std::printf("  (us@Fmax: the cycles at the unit's clock placed and routed on the iCE40 HX8K, from "
                "docs/synth.csv:");
    for (size_t i = 0; i < fmax_notes.size(); ++i)
      std::printf("%s %s", i ? ";" : "", fmax_notes[i].c_str());
    std::printf(")\n");
  }
  if (any_module_counters)
    std::printf("  (cycles: total of the timed engines; per-module busy and stall cycles and the "
                "simulation speed: %s)\n",
                a.has("--report") ? ("in " + a.get("--report")).c_str() : "--report FILE.json");
  print_timed_cycles(timed_cycles, diag, a.has("--cycles") ? a.get("--cycles") : std::string(),
                     cfg.sink_stall);
  if (!diag.heatmap_path.empty()) {
    if (timed_cycles.empty())
      throw UsageError("trirast compare: --heatmap: none of --engines is timed");
    write_png(heatmap_image(heatmap_spans, timed_cycles[0].second, diag.heatmap_metric,
                            timed_cycles[0].first,
                            cycle_words(timed_cycles[0].first).setup_title, cfg.width,
                            cfg.height),
              diag.heatmap_path, "--heatmap");
    std::printf("  wrote %s (heatmap of %s, %s)\n", diag.heatmap_path.c_str(),
                diag.heatmap_metric.c_str(), timed_cycles[0].first.c_str());
  }
  if (diag.export_tris) {
    const size_t n = export_tri_window(ls.setup, cfg, diag.export_first, diag.export_last,
                                       diag.export_path, "--export-tris", a.get("--scene"));
    std::printf("  wrote %s (%zu set-up triangles of %lld..%lld)\n", diag.export_path.c_str(), n,
                (long long)diag.export_first, (long long)diag.export_last);
  }
  if (a.has("--diff-image")) {
    // FILE.png: the first engine that differs (else the first non-golden one); every other
    // engine that differs beside it as FILE.ENGINE.png. Differing pixels are ringed to be seen
    // at any size.
    const std::string path = a.get("--diff-image");
    write_png(diff_image(golden.result.spans, diff_for_image, cfg.width, cfg.height), path,
              "--diff-image");
    std::printf("  wrote %s (%s against golden: grey agreed, red missing, blue extra, ringed)\n",
                path.c_str(), diff_engine.empty() ? "golden" : diff_engine.c_str());
    for (size_t i = 0; i < diffs.size(); ++i) {
      const std::string& name = diffs[i].first;
      if (name != diff_engine && diffs[i].second.exact()) continue;  // nothing to show
      const std::string engine_path = name == diff_engine ? path : diff_image_path(path, name);
      if (name != diff_engine) {
        write_png(diff_image(golden.result.spans, diffs[i].second, cfg.width, cfg.height),
                  engine_path, "--diff-image");
        std::printf("  wrote %s (%s against golden)\n", engine_path.c_str(), name.c_str());
      }
      for (size_t r = 0; r < rows.size(); ++r)
        if (row_engines[r] == name) rows[r].set("diff_image", engine_path);
    }
  }
  if (a.has("--report")) {
    OutputFile out(a.get("--report"), "--report");
    Json report = Json::object();
    std::vector<std::string> ran = engine_names;
    ran.push_back("golden");  // the reference, run whether listed or not
    report.set("scene", a.get("--scene"))
        .set("config", config_json(cfg, golden_options, ran))
        .set("triangles", triangle_counts(ls))
        .set("golden_pixels", golden_pixels)
        .set("engines", [&] {
          Json list = Json::array();
          for (const Json& row : rows) list.push(row);
          return list;
        }())
        .set("all_exact_agree", all_exact_agree);
    add_descriptions(report);
    out.write(report.dump());
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
  Args a("engines", "[--units]",
         {{"--units", "", "list the units instead: their engines, the options they read, the "
                          "engines whose cycles must agree, their pipeline stages and states",
           ""}});
  a.parse(argc, argv, 2);
  if (a.help_requested()) {
    std::cout << "List the engines compiled into this build.\n\n" << a.help_text();
    return 0;
  }
  if (!a.has("--units")) {
    for (const EngineInfo& e : engine_registry())
      std::printf("%-18s %-8s %s\n", e.name.c_str(), e.exact ? "exact" : "inexact",
                  e.description.c_str());
    return 0;
  }
  auto joined = [](const std::vector<std::string>& items, const char* sep) {
    std::string s;
    for (const std::string& i : items) s += (s.empty() ? "" : sep) + i;
    return s;
  };
  for (const UnitDescriptor& u : units()) {
    std::printf("%s: %s (%s)\n", u.name.c_str(), u.title.c_str(), u.exact ? "exact" : "inexact");
    for (const UnitView& v : u.views) {
      const std::string name = u.name + "-" + v.view;
      const EngineDescriptor* d = find_engine_descriptor(name);
      std::printf("  engine       %-18s %s; reads %s\n", name.c_str(),
                  v.timed ? "timed" : "untimed",
                  d->options.empty() ? "no engine option" : joined(d->options, ", ").c_str());
    }
    std::printf("  cycles agree %s\n", joined(u.timed_pair, " = ").c_str());
    for (const PipelineStage& st : u.stages)
      std::printf("  stage        %s%s%s\n", st.name.c_str(), st.states.empty() ? "" : ": ",
                  joined(st.states, ", ").c_str());
  }
  for (const EngineDescriptor& d : engine_descriptors())
    if (!d.unit)
      std::printf("%s: reference engine (%s); reads %s\n", d.info.name.c_str(),
                  d.info.exact ? "exact" : "inexact",
                  d.options.empty() ? "no engine option" : joined(d.options, ", ").c_str());
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
  install_interrupt_cleanup();
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
