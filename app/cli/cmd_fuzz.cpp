// trirast fuzz: random scenes biased toward docs/hard-cases.md, run through several engines
// and held against the golden; every disagreement is written to a .tri reproducer.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <tuple>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "common/engine.hpp"
#include "engines.hpp"
#include "fuzz/fuzz_scene.hpp"
#include "io/output_file.hpp"
#include "units.hpp"
#include "util.hpp"
#include "common/rtl_builds.hpp"
#include "halfspace/halfspace_rtl_engine.hpp"
#include "cli/fuzz_schedule.hpp"

namespace trirast {

namespace {

using Clock = std::chrono::steady_clock;

// Self-test of the checker (--inject-fault): the wrapped engine loses the last pixel of its
// longest span, so every scene with a pixel must come out as a disagreement.
class FaultyEngine : public Engine {
 public:
  explicit FaultyEngine(std::unique_ptr<Engine> inner) : inner_(std::move(inner)) {}
  void run(const SetupResult& setup, const RasterConfig& cfg, EngineResult& out) override {
    inner_->run(setup, cfg, out);
    Span* longest = nullptr;
    for (Span& s : out.spans)
      if (!longest || s.pixels() > longest->pixels()) longest = &s;
    if (!longest) return;
    if (longest->pixels() == 1) out.spans.erase(out.spans.begin() + (longest - out.spans.data()));
    else --longest->x_end;
  }

 private:
  std::unique_ptr<Engine> inner_;
};

std::string exact_engine_names() {
  std::string s;
  for (const EngineInfo& e : engine_registry())
    if (e.exact && s.find(e.name) == std::string::npos) s += (s.empty() ? "" : ",") + e.name;
  return s;
}

// splitmix64 of (seed, scene): every scene can be drawn again from the two numbers alone.
uint64_t scene_seed(uint64_t seed, uint64_t scene) {
  uint64_t z = seed * 0x9e3779b97f4a7c15ull + scene + 1;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

uint64_t parse_seed(const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if (text.empty() || !std::isdigit((unsigned char)text[0]) || *end != '\0' || errno != 0)
    throw UsageError("trirast fuzz: --seed: '" + text + "' is not a non-negative integer");
  return v;
}


// What one engine did in a run: the scenes it ran (cut: on a cropped viewport or a window of the
// triangles), their triangles and golden pixels, the generator's classes among those triangles,
// its CPU time and what the schedule estimated of it.
struct EngineTally {
  uint64_t scenes = 0, cut = 0, triangles = 0, pixels = 0;
  uint64_t classes[int(FuzzClass::kCount)] = {};
  double cpu_seconds = 0, estimate_ns = 0;
  int classes_seen() const {
    return int(std::count_if(std::begin(classes), std::end(classes), [](uint64_t n) { return n; }));
  }
};

// The engines of a scene that run the same part of it (the same viewport and triangles), the
// golden held against them once.
struct SceneGroup {
  int width, height;
  uint32_t tri_begin, tri_end;
  std::vector<size_t> engines;  // indices into the run's engine list
};

std::vector<SceneGroup> group_assignments(const std::vector<FuzzAssignment>& plan,
                                          const std::vector<std::string>& names) {
  std::map<std::tuple<int, int, uint32_t, uint32_t>, size_t> at;
  std::vector<SceneGroup> groups;
  for (size_t e = 0; e < plan.size(); ++e) {
    const FuzzAssignment& a = plan[e];
    if (!a.runs || names[e] == "golden") continue;
    const auto key = std::make_tuple(a.width, a.height, a.tri_begin, a.tri_end);
    auto it = at.find(key);
    if (it == at.end()) {
      it = at.emplace(key, groups.size()).first;
      groups.push_back({a.width, a.height, a.tri_begin, a.tri_end, {}});
    }
    groups[it->second].engines.push_back(e);
  }
  return groups;
}

void print_engine_table(const std::vector<std::string>& names, const std::vector<EngineTally>& tally,
                        uint64_t scenes) {
  const int k_all = int(FuzzClass::kCount);
  std::printf("  %-19s %8s %6s %7s %10s %14s %8s %9s %9s\n", "engine", "scenes", "share", "cut",
              "triangles", "pixels", "classes", "CPU s", "est. s");
  for (size_t e = 0; e < names.size(); ++e) {
    const EngineTally& t = tally[e];
    std::printf("  %-19s %8llu %5.1f%% %7llu %10llu %14llu %5d/%-2d %9.2f %9.2f\n", names[e].c_str(),
                (unsigned long long)t.scenes, scenes ? 100.0 * double(t.scenes) / double(scenes) : 0.0,
                (unsigned long long)t.cut, (unsigned long long)t.triangles,
                (unsigned long long)t.pixels, t.classes_seen(), k_all, t.cpu_seconds,
                t.estimate_ns * 1e-9);
  }
}

}  // namespace

int cmd_fuzz(int argc, char** argv) {
  const std::string all_exact = exact_engine_names();
  Args a("fuzz", "[--seconds N] [--engines A,B,...] [--seed S] [--out DIR]",
         {
             {"--seconds", "N", "run for N seconds (0: no time limit; needs --scenes)", "60"},
             {"--engines", "A,B,...", "exact engines held against the golden (the golden always runs)",
              all_exact},
             {"--seed", "S", "seed of the scene generator (default: from the clock, printed)", ""},
             {"--out", "DIR", "directory for reproducers fuzz-<seed>-<scene>.tri", "."},
             {"--scenes", "N", "stop after N scenes (0: no limit)", "0"},
             {"--max-triangles", "N", "largest scene, in triangles", "400"},
             {"--max-reproducers", "N", "write at most N reproducers (the count goes on)", "20"},
             {"--coverage", "FILE",
              "write the RTL engines' cover points with their counts over the whole run "
              "(docs/coverage.md)",
              ""},
             {"--rtl-checked", "",
              "the RTL engines run their checked Verilated builds (assertions, cover points) where "
              "a speed build covers the configuration (--coverage implies it; docs/rtl.md)",
              ""},
             {"--inject-fault", "ENGINE",
              "self-test: ENGINE drops one pixel per scene, so the checker must report it", ""},
             {"--calibrate", "", "measure the --engines' cost constants (the schedule's table), print them, exit", ""},
         });
  a.parse(argc, argv, 2);
  if (a.help_requested()) {
    std::cout << "Differential fuzzing: random configurations and scenes biased toward the hard\n"
                 "cases (lattice vertices, subpixel offsets from centres, extreme coordinates,\n"
                 "slivers, ...) through every engine, each held against the golden. A disagreement\n"
                 "is written as a .tri reproducer whose header names the engines and the\n"
                 "configuration, with a \"# replay:\" line (also printed) that runs as written\n"
                 "from this folder: trirast compare on the reproducer, exit status 1 while the\n"
                 "disagreement holds, 0 once fixed (and for an --inject-fault run, whose fault the\n"
                 "replay does not have). Progress on stderr once a second. With an RTL engine\n"
                 "among --engines, the widths (subpixel, coordinate and box bits) are those of\n"
                 "the Verilated builds, so no scene skips the RTL; without one, any widths.\n"
                 "Each scene goes to the golden and to the engines the schedule picks: an engine\n"
                 "runs about its share of CPU time per scene (its cost estimated from the set-up\n"
                 "boxes before it runs), at least one scene in ten, and a scene too costly for it\n"
                 "on a cropped viewport or a window of the triangles (fuzz_schedule.hpp); the\n"
                 "choice depends on the seed and the scene alone. No scene starts that is not\n"
                 "expected to end by --seconds. The summary has a row per engine: scenes, cut\n"
                 "scenes, triangles, pixels, classes of the generator seen, CPU and estimated s.\n"
                 "Exit status: 0 no disagreement, 1 a disagreement, 2 bad usage.\n\n"
              << a.help_text();
    return 0;
  }
  const long seconds = a.get_int("--seconds", 0, 100L * 24 * 3600);
  const long max_scenes = a.get_int("--scenes", 0, 1L << 40);
  const long max_tris = a.get_int("--max-triangles", 1, 100000);
  const long max_repro = a.get_int("--max-reproducers", 0, 100000);
  if (seconds == 0 && max_scenes == 0)
    throw UsageError("trirast fuzz: --seconds 0 needs --scenes N (the run would never end)");
  const bool time_limited = seconds > 0 && (a.has("--seconds") || max_scenes == 0);
  const uint64_t seed =
      a.has("--seed") ? parse_seed(a.get("--seed"))
                      : uint64_t(std::chrono::system_clock::now().time_since_epoch().count()) %
                            1000000000ull;

  // The engines: known, exact, each once. Unknown ones name the known ones.
  std::vector<std::string> names;
  std::vector<const EngineInfo*> engines;
  for (const std::string& given : split(a.get("--engines"), ',')) {
    if (given.empty())
      throw UsageError("trirast fuzz: --engines: empty engine name in '" + a.get("--engines") + "'");
    const std::string& name = given;
    const EngineInfo* info = find_engine(name);
    if (!info) {
      std::string known;
      for (const EngineInfo& e : engine_registry())
        if (known.find(e.name) == std::string::npos) known += (known.empty() ? "" : ", ") + e.name;
      throw UsageError("trirast fuzz: --engines: unknown engine '" + name + "' (known: " + known +
                       ")");
    }
    if (!info->exact)
      throw UsageError("trirast fuzz: --engines: '" + name +
                       "' is not exact (its own coverage, not the rule); fuzz compares exact engines");
    bool seen = false;
    for (const std::string& n : names) seen = seen || n == name;
    if (seen) continue;
    names.push_back(name);
    engines.push_back(info);
  }
  if (names.empty()) throw UsageError("trirast fuzz: --engines: empty list");
  if (names.size() == 1 && names[0] == "golden")
    throw UsageError("trirast fuzz: --engines: nothing to compare with the golden");
  if (a.has("--calibrate")) {
    std::fprintf(stderr, "fuzz: calibrating %zu engines (CPU time, about 1 s each)\n", names.size());
    fuzz_calibrate(names, stdout);
    return 0;
  }

  EngineInfo faulty;
  if (a.has("--inject-fault")) {
    const std::string victim = a.get("--inject-fault");
    for (const EngineInfo*& info : engines)
      if (info->name == victim && victim != "golden") {
        const auto make = info->make;
        faulty = {info->name, info->description, true,
                  [make]() -> std::unique_ptr<Engine> { return std::make_unique<FaultyEngine>(make()); }};
        info = &faulty;
      }
    if (faulty.name.empty())
      throw UsageError("trirast fuzz: --inject-fault: '" + victim +
                       "' is not one of the non-golden --engines");
  }

  const std::string out_dir = a.get("--out");
  auto repro_path = [&](uint64_t scene) {
    return out_dir + "/fuzz-" + std::to_string(seed) + "-" + std::to_string(scene) + ".tri";
  };
  check_output_path(repro_path(0), "--out");
  if (a.has("--coverage")) check_coverage_option(a.get("--coverage"), names, "fuzz");
  if (a.has("--rtl-checked") && std::none_of(names.begin(), names.end(), is_rtl_engine))
    throw UsageError("trirast fuzz: --rtl-checked: applies to none of the engines run (it applies "
                     "to the RTL engines)");
  const bool rtl_checked = a.has("--rtl-checked") || a.has("--coverage");

  std::string engine_list;
  for (const std::string& n : names) engine_list += (engine_list.empty() ? "" : ",") + n;
  // With RTL engines among them (units.hpp: a view with Verilated builds), the widths are those
  // every one of them has a build of (for the improved units: every width configuration of
  // docs/synth.md), so that no scene skips them.
  auto same = [](const FuzzWidths& a, const FuzzWidths& b) {
    return a.subpixel_bits == b.subpixel_bits && a.coord_int_bits == b.coord_int_bits &&
           a.box_bits == b.box_bits;
  };
  auto holds = [&](const std::vector<FuzzWidths>& list, const FuzzWidths& w) {
    return std::any_of(list.begin(), list.end(), [&](const FuzzWidths& o) { return same(o, w); });
  };
  std::vector<FuzzWidths> widths;
  bool any_rtl = false;
  for (const EngineInfo* info : engines) {
    const EngineDescriptor* d = find_engine_descriptor(info->name);
    if (!d || !d->rtl_builds) continue;
    std::vector<FuzzWidths> own;  // this engine's widths, in the order of its builds
    for (const rtl::RtlBuild& b : d->rtl_builds()) {
      const FuzzWidths w{b.subpixel_bits, b.coord_int_bits, b.box_bits};
      if (!holds(own, w)) own.push_back(w);
    }
    if (any_rtl)  // the widths every RTL engine so far has, in the first one's order
      widths.erase(std::remove_if(widths.begin(), widths.end(),
                                  [&](const FuzzWidths& w) { return !holds(own, w); }),
                   widths.end());
    else
      widths = own;
    any_rtl = true;
  }
  if (any_rtl && widths.empty())
    throw UsageError("trirast fuzz: --engines: the RTL engines among them have no width "
                     "configuration in common");
  std::fprintf(stderr, "fuzz: seed %llu, engines %s, widths %s, %s\n", (unsigned long long)seed,
               engine_list.c_str(), widths.empty() ? "any" : "of the RTL builds",
               time_limited ? (std::to_string(seconds) + " s").c_str()
                            : (std::to_string(max_scenes) + " scenes").c_str());

  // An RTL engine that reads --stamp (the half-space unit's): its builds' stamp, tile and walk.
  const bool hs_rtl = std::any_of(names.begin(), names.end(), [](const std::string& n) {
    const EngineDescriptor* d = find_engine_descriptor(n);
    return d && d->rtl_builds && engine_reads(n, "--stamp");
  });
  // The golden runs every part of every scene the engines run; its row in the table counts
  // those runs (listed or not among --engines).
  const EngineInfo* golden_info = find_engine("golden");
  const bool golden_listed = std::find(names.begin(), names.end(), "golden") != names.end();
  std::vector<std::string> rows = names;
  if (!golden_listed) rows.insert(rows.begin(), "golden");
  const size_t golden_row = size_t(std::find(rows.begin(), rows.end(), "golden") - rows.begin());
  auto row_of = [&](size_t e) { return golden_listed ? e : e + 1; };
  std::vector<EngineTally> tally(rows.size());

  const auto t0 = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  double next_report = 1.0;
  uint64_t scenes = 0, triangles = 0, pixels = 0, disagreements = 0, written = 0;
  double estimated_ns = 0;  // of the scenes run so far, golden included
  std::vector<uint64_t> skips(engines.size(), 0);  // scenes an engine's build does not cover
  auto progress = [&] {
    std::fprintf(stderr, "fuzz: %.1f s, %llu triangles, %llu disagreements\n", elapsed(),
                 (unsigned long long)triangles, (unsigned long long)disagreements);
  };
  bool deadline_stop = false;
  while ((max_scenes == 0 || scenes < uint64_t(max_scenes)) &&
         (!time_limited || elapsed() < double(seconds))) {
    const uint64_t n = scenes;
    RngDraws draws(scene_seed(seed, n));
    RasterConfig cfg = draw_fuzz_config(draws, widths);
    cfg.rtl_checked = rtl_checked;
    std::vector<FuzzClass> classes;
    const std::vector<InputTriangle> tris = draw_fuzz_scene(draws, cfg, int(max_tris), &classes);
    // The half-space unit's stamp, tile and walk: among halfspace-rtl's builds of these widths
    // when it runs (it then never skips a scene for them), else among all.
    draw_fuzz_hs_config(draws, cfg,
                        hs_rtl ? rtl::halfspace_built_params(cfg) : std::vector<HalfspaceParams>{});
    // The schedule (fuzz_schedule.hpp): which engines run the scene, and which part of it.
    const SetupResult setup = setup_scene(tris, cfg);
    const std::vector<FuzzAssignment> plan =
        fuzz_schedule_scene(seed, n, setup, uint32_t(tris.size()), cfg, names);
    const std::vector<SceneGroup> groups = group_assignments(plan, names);
    const FuzzEngineCost& golden_cost = fuzz_engine_cost("golden");
    double scene_ns = 0;
    for (const SceneGroup& g : groups) {
      scene_ns += fuzz_estimate_ns(golden_cost, fuzz_cost_features(setup, cfg, g.width, g.height,
                                                                   g.tri_begin, g.tri_end));
      for (size_t e : g.engines) scene_ns += plan[e].estimate_ns;
    }
    // A time-limited run starts no scene it expects to end after the deadline: the estimate
    // times the wall seconds per estimated second so far (at least 1; a loaded machine's more).
    if (time_limited && scenes > 0) {
      const double wall_per_est = std::max(1.0, elapsed() / (estimated_ns * 1e-9));
      if (elapsed() + scene_ns * 1e-9 * wall_per_est > double(seconds)) {
        deadline_stop = true;
        break;
      }
    }
    ++scenes;
    estimated_ns += scene_ns;
    triangles += tris.size();
    if (!groups.empty()) {  // the golden runs a scene when some engine does
      tally[golden_row].scenes += 1;
      tally[golden_row].triangles += tris.size();
      for (FuzzClass c : classes)
        if (c != FuzzClass::kCount) ++tally[golden_row].classes[int(c)];
    }

    std::string note, summary;
    bool disagreed = false;
    for (const SceneGroup& g : groups) {
      RasterConfig part_cfg = cfg;
      part_cfg.width = g.width;
      part_cfg.height = g.height;
      const std::vector<InputTriangle> part(tris.begin() + g.tri_begin, tris.begin() + g.tri_end);
      std::vector<const EngineInfo*> list = {golden_info};
      for (size_t e : g.engines) list.push_back(engines[e]);
      uint64_t golden_pixels = 0;
      std::vector<std::string> skipped;
      std::vector<double> cpu;
      const std::vector<FuzzDisagreement> found =
          check_engines(part, part_cfg, list, &golden_pixels, &skipped, &cpu);
      tally[golden_row].cpu_seconds += cpu[0];
      tally[golden_row].estimate_ns += fuzz_estimate_ns(
          golden_cost, fuzz_cost_features(setup, cfg, g.width, g.height, g.tri_begin, g.tri_end));
      const bool whole = g.width == cfg.width && g.height == cfg.height && g.tri_begin == 0 &&
                         g.tri_end == tris.size();
      pixels += golden_pixels;
      tally[golden_row].pixels += golden_pixels;
      for (size_t k = 0; k < g.engines.size(); ++k) {
        const size_t e = g.engines[k];
        if (std::find(skipped.begin(), skipped.end(), names[e]) != skipped.end()) {
          ++skips[e];
          continue;
        }
        EngineTally& t = tally[row_of(e)];
        t.scenes += 1;
        t.cut += plan[e].cut;
        t.triangles += part.size();
        t.pixels += golden_pixels;
        for (uint32_t i = g.tri_begin; i < g.tri_end; ++i)
          if (classes[i] != FuzzClass::kCount) ++t.classes[int(classes[i])];
        t.cpu_seconds += cpu[k + 1];
        t.estimate_ns += plan[e].estimate_ns;
      }
      if (found.empty()) continue;
      const std::string where =
          whole ? std::string()
                : " (on the schedule's cut: viewport " + std::to_string(g.width) + "x" +
                      std::to_string(g.height) + ", triangles " + std::to_string(g.tri_begin) +
                      ".." + std::to_string(g.tri_end - 1) + ")";
      for (const FuzzDisagreement& f : found) {
        summary += (summary.empty() ? "" : "; ") + f.engine + ": " + f.what;
        if (disagreed) note += "\n" + f.engine + " disagrees with golden" + where + ": " + f.what;
      }
      if (disagreed) continue;  // the first disagreeing part of the scene is written out
      disagreed = true;
      note = "seed " + std::to_string(seed) + ", scene " + std::to_string(n) + " (" +
             std::to_string(tris.size()) + " triangles)";
      if (!whole)
        note += "; the engines below ran the fuzz schedule's cut of it: viewport " +
                std::to_string(g.width) + "x" + std::to_string(g.height) + " of " +
                std::to_string(cfg.width) + "x" + std::to_string(cfg.height) + ", triangles " +
                std::to_string(g.tri_begin) + ".." + std::to_string(g.tri_end - 1);
      for (const FuzzDisagreement& f : found)
        note += "\n" + f.engine + " disagrees with golden: " + f.what;
      if (written < uint64_t(max_repro)) {
        const EngineInfo* first = nullptr;
        for (const EngineInfo* e : engines)
          if (e->name == found[0].engine) first = e;
        const std::vector<InputTriangle> small = reduce_scene(part, part_cfg, *first, found[0]);
        if (small.size() < part.size())
          note += "\nreduced to " + std::to_string(small.size()) + " of " +
                  std::to_string(part.size()) + " triangles";
        if (!faulty.name.empty())
          note += "\n" + faulty.name + " ran with --inject-fault: the replay, without the fault, agrees";
        // The replay names the engines that ran this part of the scene (not those whose build
        // does not cover its configuration), so it runs as written.
        std::vector<std::string> ran;
        for (size_t e : g.engines)
          if (std::find(skipped.begin(), skipped.end(), names[e]) == skipped.end())
            ran.push_back(names[e]);
        if (golden_listed) ran.insert(ran.begin(), "golden");
        // Options none of them reads (compare refuses those) stay out of the replay.
        std::vector<std::string> unread;
        for (const std::string& option : engine_options())
          if (!engine_reads("golden", option) &&
              std::none_of(ran.begin(), ran.end(),
                           [&](const std::string& e) { return engine_reads(e, option); }))
            unread.push_back(option);
        OutputFile out(repro_path(n), "--out");
        out.write(format_reproducer(small, part_cfg, ran, note, repro_path(n), unread));
        out.commit();
        ++written;
        note = "wrote " + repro_path(n) + "\nfuzz: replay: " +
               replay_command(part_cfg, ran, repro_path(n), unread);
      } else {
        note.clear();
      }
    }
    if (disagreed) {
      ++disagreements;
      std::fprintf(stderr, "fuzz: DISAGREEMENT in scene %llu at %.1f s (%s)%s%s\n",
                   (unsigned long long)n, elapsed(), summary.c_str(), note.rfind("wrote ", 0) == 0 ? ": " : "",
                   note.rfind("wrote ", 0) == 0 ? note.c_str() : "");
    }
    if (elapsed() >= next_report) {
      progress();
      while (next_report <= elapsed()) next_report += 1.0;
    }
  }
  progress();
  const double total = elapsed();
  std::printf("trirast fuzz: seed %llu, engines %s\n", (unsigned long long)seed, engine_list.c_str());
  std::printf("  ran        %.1f s, %llu scenes, %llu triangles, %llu pixels of the golden (%.1f scenes/s, %.0f triangles/s)\n",
              total, (unsigned long long)scenes, (unsigned long long)triangles,
              (unsigned long long)pixels, total > 0 ? double(scenes) / total : 0.0,
              total > 0 ? double(triangles) / total : 0.0);
  if (time_limited) {
    const double late = total - double(seconds);  // < 0: stopped early, the next scene would not fit
    std::printf("  deadline   %ld s, ended %.1f s %s it (%s)\n", seconds, late < 0 ? -late : late,
                late < 0 ? "before" : "after",
                deadline_stop ? "the next scene's estimate did not fit" : "no scene after it");
  }
  print_engine_table(rows, tally, scenes);
  for (size_t i = 0; i < engines.size(); ++i)
    if (skips[i])
      std::printf("  skipped    %s: %llu of %llu scenes had a configuration its build does not cover\n",
                  names[i].c_str(), (unsigned long long)skips[i], (unsigned long long)scenes);
  if (a.has("--coverage")) {
    const std::string summary = write_coverage_report(
        a.get("--coverage"), names,
        "trirast fuzz --seed " + std::to_string(seed) + " (" + std::to_string(scenes) + " scenes, " +
            std::to_string(triangles) + " triangles, " + std::to_string(long(total)) + " s)");
    std::printf("%s\n", summary.c_str());
    std::printf("  wrote      %s (coverage)\n", a.get("--coverage").c_str());
  }
  std::printf("  result     %llu disagreements%s\n", (unsigned long long)disagreements,
              disagreements ? (", " + std::to_string(written) + " reproducers in " + out_dir).c_str()
                            : "");
  return disagreements ? 1 : 0;
}

}  // namespace trirast
