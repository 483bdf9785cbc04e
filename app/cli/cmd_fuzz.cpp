// trirast fuzz: random scenes biased toward docs/hard-cases.md, run through several engines
// and held against the golden; every disagreement is written to a .tri reproducer.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
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
             {"--inject-fault", "ENGINE",
              "self-test: ENGINE drops one pixel per scene, so the checker must report it", ""},
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
  const auto t0 = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  double next_report = 1.0;
  uint64_t scenes = 0, triangles = 0, pixels = 0, disagreements = 0, written = 0;
  std::vector<uint64_t> skips(engines.size(), 0);  // scenes an engine's build does not cover
  auto progress = [&] {
    std::fprintf(stderr, "fuzz: %.1f s, %llu triangles, %llu disagreements\n", elapsed(),
                 (unsigned long long)triangles, (unsigned long long)disagreements);
  };
  while ((max_scenes == 0 || scenes < uint64_t(max_scenes)) &&
         (!time_limited || elapsed() < double(seconds))) {
    const uint64_t n = scenes++;
    RngDraws draws(scene_seed(seed, n));
    RasterConfig cfg = draw_fuzz_config(draws, widths);
    const std::vector<InputTriangle> tris = draw_fuzz_scene(draws, cfg, int(max_tris));
    // The half-space unit's stamp, tile and walk: among halfspace-rtl's builds of these widths
    // when it runs (it then never skips a scene for them), else among all.
    draw_fuzz_hs_config(draws, cfg,
                        hs_rtl ? rtl::halfspace_built_params(cfg) : std::vector<HalfspaceParams>{});
    triangles += tris.size();
    uint64_t golden_pixels = 0;
    std::vector<std::string> skipped;
    const std::vector<FuzzDisagreement> found =
        check_engines(tris, cfg, engines, &golden_pixels, &skipped);
    for (const std::string& name : skipped)
      for (size_t i = 0; i < engines.size(); ++i) skips[i] += engines[i]->name == name;
    pixels += golden_pixels;
    if (!found.empty()) {
      ++disagreements;
      std::string note = "seed " + std::to_string(seed) + ", scene " + std::to_string(n) + " (" +
                         std::to_string(tris.size()) + " triangles)";
      std::string summary;
      for (const FuzzDisagreement& f : found) {
        note += "\n" + f.engine + " disagrees with golden: " + f.what;
        summary += (summary.empty() ? "" : "; ") + f.engine + ": " + f.what;
      }
      if (written < uint64_t(max_repro)) {
        const EngineInfo* first = nullptr;
        for (const EngineInfo* e : engines)
          if (e->name == found[0].engine) first = e;
        const std::vector<InputTriangle> small = reduce_scene(tris, cfg, *first, found[0]);
        if (small.size() < tris.size())
          note += "\nreduced to " + std::to_string(small.size()) + " of " +
                  std::to_string(tris.size()) + " triangles";
        if (!faulty.name.empty())
          note += "\n" + faulty.name + " ran with --inject-fault: the replay, without the fault, agrees";
        // The replay names the engines that ran on this scene (not those whose build does not
        // cover its configuration), so it runs as written.
        std::vector<std::string> ran;
        for (const std::string& name : names)
          if (std::find(skipped.begin(), skipped.end(), name) == skipped.end()) ran.push_back(name);
        // Options none of them reads (compare refuses those) stay out of the replay.
        std::vector<std::string> unread;
        for (const std::string& option : engine_options())
          if (!engine_reads("golden", option) &&
              std::none_of(ran.begin(), ran.end(),
                           [&](const std::string& e) { return engine_reads(e, option); }))
            unread.push_back(option);
        OutputFile out(repro_path(n), "--out");
        out.write(format_reproducer(small, cfg, ran, note, repro_path(n), unread));
        out.commit();
        ++written;
        std::fprintf(stderr, "fuzz: DISAGREEMENT in scene %llu (%s): wrote %s\nfuzz: replay: %s\n",
                     (unsigned long long)n, summary.c_str(), repro_path(n).c_str(),
                     replay_command(cfg, ran, repro_path(n), unread).c_str());
      } else {
        std::fprintf(stderr, "fuzz: DISAGREEMENT in scene %llu (%s)\n", (unsigned long long)n,
                     summary.c_str());
      }
    }
    if (elapsed() >= next_report) {
      progress();
      while (next_report <= elapsed()) next_report += 1.0;
    }
  }
  progress();
  const double total = elapsed();
  std::printf("trirast fuzz: seed %llu, engines %s\n", (unsigned long long)seed, engine_list.c_str());
  std::printf("  ran        %.1f s, %llu scenes, %llu triangles, %llu golden pixels (%.0f triangles/s)\n",
              total, (unsigned long long)scenes, (unsigned long long)triangles,
              (unsigned long long)pixels, total > 0 ? double(triangles) / total : 0.0);
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
