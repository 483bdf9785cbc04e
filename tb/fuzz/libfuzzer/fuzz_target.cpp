// libFuzzer target: decodes the fuzzer's bytes into a configuration (the half-space unit's
// stamp, tile and walk included) and triangles biased toward docs/hard-cases.md (the same generator as `trirast fuzz`, drawing from the bytes instead
// of a PRNG), then holds every engine of kEngines against the golden. Any difference, exception or
// out-of-viewport span aborts with the reproducer on stderr.
//
// Also fuzzed: setup's handling of arbitrary doubles (NaN, infinities, 1e300, subnormals, values
// just past the range): it must throw a SetupError exactly when a coordinate is not representable,
// and never hand a wrapped value to the engines.
//
// Build and run: scripts/fuzz.sh [SECONDS]   (clang++ -fsanitize=fuzzer,address,undefined)
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "common/engine.hpp"
#include "common/setup.hpp"
#include "golden/golden.hpp"
#include "fuzz/fuzz_scene.hpp"
#include "halfspace/halfspace_unit.hpp"
#include "improved/improved_unit.hpp"
#ifdef TRIRAST_FUZZ_HAS_RTL
#include "improved/improved_rtl_engine.hpp"
#endif

namespace trirast {
namespace {

// The engines held against the golden, one line each. Each run() starts from reset (a fresh
// engine per input; the rtl harness resets the Verilated model at the start of every run), so one
// input cannot leak state into the next. An engine built for fewer configurations (the rtl: one
// set of widths) throws std::invalid_argument for the others and is skipped on those inputs.
const std::vector<EngineInfo> kEngines = {
    {"improved-datapath", "bit-accurate unit model", true, make_improved_datapath_engine},
    {"halfspace-datapath", "bit-accurate half-space tile model", true, make_halfspace_datapath_engine},
#ifdef TRIRAST_FUZZ_HAS_RTL
    {"improved-rtl", "Verilated RTL through its harness", true, make_improved_rtl_engine},
#endif
};

// Self-test of the target (TRIRAST_FUZZ_INJECT_FAULT=1 in the environment): the first engine
// loses the last pixel of one span per input, so the fuzzer must stop at once with a reproducer.
class FaultyEngine : public Engine {
 public:
  explicit FaultyEngine(std::unique_ptr<Engine> inner) : inner_(std::move(inner)) {}
  void run(const SetupResult& setup, const RasterConfig& cfg, EngineResult& out) override {
    inner_->run(setup, cfg, out);
    for (Span& s : out.spans)
      if (s.pixels() > 1) {
        --s.x_end;
        return;
      }
  }

 private:
  std::unique_ptr<Engine> inner_;
};

std::vector<EngineInfo> engines_under_test() {
  std::vector<EngineInfo> list = kEngines;
  if (std::getenv("TRIRAST_FUZZ_INJECT_FAULT")) {
    const auto make = list[0].make;
    list[0].make = [make]() -> std::unique_ptr<Engine> {
      return std::make_unique<FaultyEngine>(make());
    };
  }
  return list;
}

[[noreturn]] void report(const std::vector<InputTriangle>& tris, const RasterConfig& cfg,
                         const std::string& what) {
  std::vector<std::string> names = {"golden"};
  for (const EngineInfo& e : kEngines) names.push_back(e.name);
  // The datapath engines read no timing option: without the RTL, trirast compare would refuse
  // them in the replay.
#ifdef TRIRAST_FUZZ_HAS_RTL
  const std::vector<std::string> unread = {};
#else
  const std::vector<std::string> unread = {"--endpoints", "--fifo-depth", "--sink-stall"};
#endif
  std::fprintf(stderr, "\n==== trirast fuzz target: %s\n%s====\n", what.c_str(),
               format_reproducer(tris, cfg, names, what, "THIS_FILE", unread).c_str());
  std::abort();
}

// Whether `v` snaps into the configured range: the rule of docs/coverage-rule.md, written out apart
// from setup's implementation (long double, no ldexp).
bool representable(double v, const RasterConfig& cfg) {
  if (!std::isfinite(v)) return false;
  const long double scaled = (long double)v * (long double)(1u << cfg.subpixel_bits);
  const long double snapped = std::nearbyintl(scaled);  // round half to even
  const long double limit = (long double)cfg.coord_limit_px() * (1u << cfg.subpixel_bits);
  return snapped >= -limit && snapped < limit;
}

double raw_double(ByteDraws& d) {
  const uint64_t bits = d.bits(64);
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

}  // namespace
}  // namespace trirast

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace trirast;
  ByteDraws d(data, size);
  RasterConfig cfg = draw_fuzz_config(d);
  // The half-space unit's stamp, tile and walk, with tiles: without them a screen-sized triangle
  // is tested stamp by stamp (a million tests, seconds per input under the sanitizers; `trirast
  // fuzz` and the tests cover that configuration).
  static const std::vector<HalfspaceParams> kTiled = [] {
    std::vector<HalfspaceParams> v;
    for (int stamp : {1, 2, 4})
      for (int tile : {8, 16})
        for (HalfspaceWalk walk : {HalfspaceWalk::Row, HalfspaceWalk::Zigzag, HalfspaceWalk::Forward})
          v.push_back({stamp, tile, walk});
    return v;
  }();
  draw_fuzz_hs_config(d, cfg, kTiled);
  std::vector<InputTriangle> tris;
  bool raw = false;  // some coordinate came from raw bytes, not the generator
  while (!d.exhausted() && tris.size() < 48) {
    InputTriangle t = draw_fuzz_triangle(d, cfg);
    // One triangle in eight gets a coordinate from raw bytes: any double at all.
    if (d.below(8) == 0) {
      const int i = int(d.below(6));
      (i < 3 ? t.x[i] : t.y[i - 3]) = raw_double(d);
      raw = true;
    }
    tris.push_back(t);
  }
  if (tris.empty()) tris.push_back(draw_fuzz_triangle(d, cfg));

  // Setup must refuse exactly the triangles that hold an unrepresentable coordinate.
  if (raw) {
    for (size_t i = 0; i < tris.size(); ++i) {
      bool ok = true;
      for (int k = 0; k < 3; ++k)
        ok = ok && representable(tris[i].x[k], cfg) && representable(tris[i].y[k], cfg);
      TriangleSetup t;
      const char* why = nullptr;
      bool threw = false;
      try {
        setup_triangle(tris[i], uint32_t(i), cfg, t, &why);
      } catch (const SetupError&) {
        threw = true;
      }
      if (threw == ok)
        report({tris[i]}, cfg, ok ? "setup refused a representable triangle"
                                  : "setup accepted an unrepresentable triangle");
    }
    // Keep the representable ones for the engines.
    std::vector<InputTriangle> kept;
    for (const InputTriangle& t : tris) {
      bool ok = true;
      for (int k = 0; k < 3; ++k) ok = ok && representable(t.x[k], cfg) && representable(t.y[k], cfg);
      if (ok) kept.push_back(t);
    }
    tris.swap(kept);
    if (tris.empty()) return 0;
  }

  static const std::vector<EngineInfo> under_test = engines_under_test();
  std::vector<const EngineInfo*> engines;
  for (const EngineInfo& e : under_test) {
    // The half-space datapath tests a box tile by tile and its edge tiles stamp by stamp: on
    // viewports up to 320 x 240 here (fuzzing speed: larger ones took the target from about 400
    // to 33 inputs per second; `trirast fuzz` and the tests run it on large viewports).
    if (e.name == "halfspace-datapath" && int64_t(cfg.width) * cfg.height > 320 * 240) continue;
    engines.push_back(&e);
  }
  const std::vector<FuzzDisagreement> found = check_engines(tris, cfg, engines);
  if (!found.empty()) {
    const EngineInfo* culprit = engines[0];
    for (const EngineInfo* e : engines)
      if (e->name == found[0].engine) culprit = e;
    const std::vector<InputTriangle> small = reduce_scene(tris, cfg, *culprit, found[0]);
    report(small, cfg, found[0].engine + " disagrees with golden: " + found[0].what);
  }
  return 0;
}
