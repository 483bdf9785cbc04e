#include "sweep/sweep.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>

#include "common/engine.hpp"
#include "common/fixed_point.hpp"
#include "common/span_diff.hpp"
#include "engines.hpp"
#include "units.hpp"
#include "common/watertight.hpp"
#include "util.hpp"

namespace trirast {

namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// Parts per million of `ref` pixels (a scene without reference pixels: any pixel is a full error).
double ppm(int64_t n, int64_t ref) { return n == 0 ? 0.0 : 1e6 * double(n) / double(std::max<int64_t>(ref, 1)); }

}  // namespace

// ---- scenes and points -------------------------------------------------------------------------

SweepScene parse_sweep_scene(const std::string& text) {
  SweepScene s;
  std::string rest = text;
  // Suffixes after the last '@'s: cull mode and "closed".
  for (;;) {
    const size_t at = rest.rfind('@');
    if (at == std::string::npos) break;
    const std::string suffix = rest.substr(at + 1);
    if (suffix == "closed") {
      s.closed = true;
    } else if (suffix == "back" || suffix == "front" || suffix == "none") {
      s.cull = parse_cull_mode(suffix);
    } else {
      break;
    }
    rest = rest.substr(0, at);
  }
  if (rest.empty()) throw std::invalid_argument("empty scene in '" + text + "'");
  s.spec = rest;
  s.label = rest.rfind("builtin:", 0) == 0 ? rest.substr(8) : rest;
  if (s.cull != CullMode::None) s.label += std::string(" (cull ") + cull_mode_name(s.cull) + ")";
  return s;
}

std::vector<SweepScene> sweep_scenes(bool quick) {
  const std::vector<std::string> full = {
      "builtin:lowpoly-far",  "builtin:lowpoly-near",          "builtin:highpoly-far",
      "builtin:highpoly-near@back@closed", "builtin:mixed",   "builtin:sphere@back@closed",
      "builtin:torus@back",   "builtin:surface",               "builtin:hard-all"};
  const std::vector<std::string> small = {"builtin:sphere:tess=12@back@closed",
                                          "builtin:lowpoly-near",
                                          "builtin:mixed:objects=2,tess=8"};
  std::vector<SweepScene> out;
  for (const std::string& s : quick ? small : full) out.push_back(parse_sweep_scene(s));
  return out;
}

UnitKind SweepPoint::kind() const {
  if (const UnitDescriptor* unit = unit_of(engine)) return unit_kind_of(unit->name);
  if (engine == "golden") return UnitKind::Golden;
  return UnitKind::Cpu;
}

bool SweepPoint::rtl() const {
  const UnitKind k = kind();
  // Stamp, tile and walk of the half-space unit are build parameters of its RTL.
  if (k == UnitKind::Trad || k == UnitKind::Halfspace)
    return cfg.fifo_depth == RasterConfig{}.fifo_depth;
  // The second-generation unit's RTL is parametric in the widths; N = 1 is all its points have.
  if (k == UnitKind::Improved2) return cfg.fifo_depth == RasterConfig{}.fifo_depth;
  return k == UnitKind::Improved && cfg.divider_quotient_bits == 0 &&
         cfg.fifo_depth == RasterConfig{}.fifo_depth;
}

std::string SweepPoint::config_name() const {
  std::string s = "S" + std::to_string(cfg.subpixel_bits) + " c" + std::to_string(cfg.coord_int_bits);
  if (kind() == UnitKind::Improved) {
    s += " b" + std::to_string(cfg.box_bits);
    s += cfg.divider_quotient_bits > 0 ? " K" + std::to_string(cfg.divider_quotient_bits) : " K-";
    s += " N" + std::to_string(cfg.endpoints);
    if (cfg.divider == DividerMode::Fixed) s += " fixed";
    if (cfg.boundary == BoundaryMode::Divide) s += " divide";
  } else if (kind() == UnitKind::Improved2) {
    // Step, adaptive, untruncated always (the gen2 engines ignore those options): not named.
    s += " b" + std::to_string(cfg.box_bits) + " N" + std::to_string(cfg.endpoints) + " gen2";
    if (engine_reads(engine, "--corner-form")) s += cfg.improved2.corner_form == 0 ? " dsp" : " radix16";
  } else if (kind() == UnitKind::Halfspace) {
    s += " b" + std::to_string(cfg.box_bits) + " s" + std::to_string(cfg.halfspace.stamp) +
         (cfg.halfspace.tile > 0 ? " t" + std::to_string(cfg.halfspace.tile) : std::string(" t-")) + " " +
         halfspace_walk_name(cfg.halfspace.walk);
  }
  return s;
}

std::vector<SweepPoint> sweep_points(bool quick, const std::vector<std::string>& engines) {
  std::vector<std::string> want = engines;
  if (want.empty()) want = {"golden", "improved-sc", "trad-sc", "float-scanline", "improved-rtl"};
  auto wanted = [&](const std::string& e) {
    return std::find(want.begin(), want.end(), e) != want.end();
  };
  std::vector<SweepPoint> pts;
  std::set<std::string> seen;
  auto add = [&](const std::string& engine, const std::string& group, int S, int coord, int box,
                 int K, int N, DividerMode div = DividerMode::Adaptive,
                 BoundaryMode bnd = BoundaryMode::Step, int improved2_corner_form = 1) {
    SweepPoint p;
    p.engine = engine;
    p.group = group;
    p.cfg.subpixel_bits = S;
    p.cfg.coord_int_bits = coord;
    p.cfg.box_bits = box;
    p.cfg.divider_quotient_bits = K;
    p.cfg.endpoints = N;
    p.cfg.divider = div;
    p.cfg.boundary = bnd;
    p.cfg.improved2.corner_form = improved2_corner_form;
    if (!wanted(engine)) return;
    if (!seen.insert(p.label()).second) return;  // the same configuration in two groups
    pts.push_back(p);
  };
  // The half-space unit (only when --engines names it): its build parameters at the default
  // widths; its RTL at the stamp / tile / walk configurations that are Verilated
  // (cmake/trirast_rtl_builds.cmake).
  auto add_hs = [&](const std::string& engine, int stamp, int tile, HalfspaceWalk walk) {
    if (!wanted(engine)) return;
    SweepPoint p;
    p.engine = engine;
    p.group = "half-space";
    p.cfg.halfspace.stamp = stamp;
    p.cfg.halfspace.tile = tile;
    p.cfg.halfspace.walk = walk;
    if (seen.insert(p.label()).second) pts.push_back(p);
  };
  const auto Row = HalfspaceWalk::Row, Zz = HalfspaceWalk::Zigzag, Fw = HalfspaceWalk::Forward;
  auto add_hs_points = [&] {
    if (quick) {
      add_hs("halfspace-sc", 1, 8, Fw);
      add_hs("halfspace-sc", 2, 8, Fw);
      add_hs("halfspace-sc", 4, 16, Row);
    } else {
      for (int stamp : {1, 2, 4})
        for (int tile : {8, 16, 0})
          for (HalfspaceWalk walk : {Fw, Zz, Row}) add_hs("halfspace-sc", stamp, tile, walk);
    }
    add_hs("halfspace-datapath", 2, 8, Fw);
    add_hs("halfspace-rtl", 2, 8, Fw);
    if (!quick) {
      add_hs("halfspace-rtl", 4, 16, Row);
      add_hs("halfspace-rtl", 1, 0, Zz);
    }
  };
  // The second-generation unit (only when --engines names it): the improved unit's width
  // configurations that apply to it (N = 1, as the improved unit's width axes; no quotient
  // truncation, fixed divider or divide boundary: the gen2 engines run step, adaptive,
  // untruncated) in both corner forms; the untimed datapath, whose spans the corner form does not
  // change, once per width. The improved unit's sweep keeps the default FIFO depth: so does this.
  auto add_g2 = [&](const std::string& group, int S, int coord, int box) {
    for (const std::string engine : {"improved2-sc", "improved2-datapath"})
      for (int form : {0, 1})
        if (engine_reads(engine, "--corner-form") || form == 1)  // else the default form only
          add(engine, group, S, coord, box, 0, 1, DividerMode::Adaptive, BoundaryMode::Step, form);
  };
  auto add_g2_points = [&] {
    const char* g = "gen2 ";
    if (quick) {
      add_g2(std::string(g) + "S", 8, 16, 14);
      add_g2(std::string(g) + "S", 4, 16, 14);
      add_g2(std::string(g) + "box bits", 8, 16, 8);
      return;
    }
    for (int S : {8, 6, 4, 2, 0}) add_g2(std::string(g) + "S", S, 16, 14);
    for (int S : {8, 4})
      for (int box : {12, 10, 9, 8, 7, 6}) add_g2(std::string(g) + "box bits", S, 16, box);
    for (int S : {8, 4})
      for (int coord : {14, 13, 12, 11}) add_g2(std::string(g) + "coord bits", S, coord, 14);
    add_g2(std::string(g) + "synthesized widths", 4, 12, 10);  // scripts/synth.sh "small"
    add_g2(std::string(g) + "synthesized widths", 8, 20, 14);  // scripts/synth.sh "wide"
    for (int S : {6, 4, 2}) add_g2(std::string(g) + "narrow", S, 12, 10);
  };
  const auto A = DividerMode::Adaptive, Fx = DividerMode::Fixed;
  add("golden", "reference", 8, 16, 14, 0, 1);
  if (quick) {
    for (int S : {8, 4, 0})
      for (int N : {1, 4})
        for (int K : {0, 6}) add("improved-sc", "S x N x K", S, 16, 14, K, N);
    add("improved-sc", "box bits", 8, 16, 8, 0, 1);
    add("improved-sc", "coord bits", 8, 12, 14, 0, 1);
    add("improved-sc", "fixed divider", 8, 16, 14, 0, 1, Fx);
    for (int S : {8, 4}) add("trad-sc", "traditional", S, 16, 14, 0, 1);
    add("float-scanline", "CPU baseline", 8, 16, 14, 0, 1);
    for (int N : {1, 4}) add("improved-rtl", "RTL", 8, 16, 14, 0, N);
    add_hs_points();
    add_g2_points();
    return pts;
  }
  for (int S : {8, 6, 4, 2, 0})
    for (int N : {1, 2, 4})
      for (int K : {0, 10, 8, 6, 5, 4}) add("improved-sc", "S x N x K", S, 16, 14, K, N);
  for (int S : {8, 4})
    for (int box : {12, 10, 9, 8, 7, 6}) add("improved-sc", "box bits", S, 16, box, 0, 1);
  for (int S : {8, 4})
    for (int coord : {14, 13, 12, 11}) add("improved-sc", "coord bits", S, coord, 14, 0, 1);
  for (int S : {8, 4, 0})
    for (int K : {0, 8}) add("improved-sc", "fixed divider", S, 16, 14, K, 1, Fx);
  add("improved-sc", "fixed divider", 8, 16, 10, 0, 1, Fx);
  for (int N : {1, 4})
    add("improved-sc", "boundary divide", 8, 16, 14, 0, N, A, BoundaryMode::Divide);
  add("improved-sc", "synthesized", 4, 12, 10, 0, 1);  // scripts/synth.sh "small"
  add("improved-sc", "synthesized", 8, 20, 14, 0, 1);  // scripts/synth.sh "wide"
  for (int S : {6, 4, 2})
    for (int K : {0, 8, 6}) add("improved-sc", "narrow", S, 12, 10, K, 1);
  for (int S : {8, 6, 4, 2, 0})
    for (int coord : {16, 12}) add("trad-sc", "traditional", S, coord, 14, 0, 1);
  for (int S : {8, 6, 4, 2, 0}) add("float-scanline", "CPU baseline", S, 16, 14, 0, 1);
  for (int N : {1, 2, 4}) add("improved-rtl", "RTL", 8, 16, 14, 0, N);
  add_hs_points();
  add_g2_points();
  return pts;
}

// ---- the reference -----------------------------------------------------------------------------

SweepSceneData load_sweep_scene(const SweepScene& s, const RasterConfig& base) {
  SweepSceneData d;
  d.spec = s;
  RasterConfig cfg = base;
  cfg.cull = s.cull;
  d.scene = load_scene(s.spec, cfg, s.camera);
  SetupResult setup;
  try {
    setup = setup_scene(d.scene.tris, cfg);
  } catch (const SetupError& e) {
    throw SceneError(s.spec + ": " + e.what());
  }
  d.reference_triangles = setup.tris.size();
  EngineResult r;
  auto golden = find_engine("golden")->make();
  const auto t0 = Clock::now();
  golden->run(setup, cfg, r);
  d.golden_seconds = seconds_since(t0);
  sort_spans(r.spans);
  d.reference = std::move(r.spans);
  d.reference_pixels = count_pixels(d.reference);
  if (s.closed) {
    const WatertightResult c = check_watertight(setup, d.reference, cfg);
    d.reference_cracks = c.cracks;
    d.reference_doubles = c.doubles;
  }
  return d;
}

// ---- one point -----------------------------------------------------------------------------------

namespace {

// Runs `tris` and, when the engine's widths refuse a triangle, finds the refused ones by halving
// (their spans are dropped; the final run of the kept triangles is the measured one).
void isolate_width_errors(Engine& engine, const std::vector<TriangleSetup>& tris,
                          const RasterConfig& cfg, std::vector<TriangleSetup>& keep,
                          uint64_t& rejected) {
  SetupResult sub;
  sub.tris = tris;
  EngineResult scratch;
  try {
    engine.run(sub, cfg, scratch);
    keep.insert(keep.end(), tris.begin(), tris.end());
  } catch (const WidthError&) {
    if (tris.size() == 1) {
      ++rejected;
      return;
    }
    const size_t half = tris.size() / 2;
    isolate_width_errors(engine, {tris.begin(), tris.begin() + half}, cfg, keep, rejected);
    isolate_width_errors(engine, {tris.begin() + half, tris.end()}, cfg, keep, rejected);
  }
}

}  // namespace

PointResult run_sweep_point(const SweepPoint& p, const SweepSceneData& scene) {
  PointResult r;
  RasterConfig cfg = p.cfg;
  cfg.cull = scene.spec.cull;
  r.read = scene.scene.tris.size();
  try {
    cfg.validate();
    const EngineInfo* info = find_engine(p.engine);
    if (!info) throw std::runtime_error("engine '" + p.engine + "' is not in this build");
    // Setup one triangle at a time: a vertex outside this coordinate width rejects its triangle.
    SetupResult setup;
    setup.counts.read = r.read;
    const int64_t box_limit = int64_t(1) << cfg.box_bits;
    for (size_t i = 0; i < scene.scene.tris.size(); ++i) {
      TriangleSetup t;
      const char* why = nullptr;
      try {
        if (!setup_triangle(scene.scene.tris[i], uint32_t(i), cfg, t, &why)) {
          if (why[0] == 'd') ++r.degenerate;
          else ++r.culled;
          continue;
        }
      } catch (const SetupError&) {
        ++r.rejected_range;
        continue;
      }
      // The improved unit's interface refuses a box wider or taller than 2^box_bits pixels (the
      // second generation's box stage is the same interface).
      if ((p.kind() == UnitKind::Improved || p.kind() == UnitKind::Improved2) && !t.box.empty() &&
          (t.box.width() - 1 >= box_limit || t.box.height() - 1 >= box_limit)) {
        ++r.rejected_width;
        continue;
      }
      setup.tris.push_back(t);
    }
    setup.counts.accepted = setup.tris.size();
    auto engine = info->make();
    EngineResult out;
    auto t0 = Clock::now();
    try {
      engine->run(setup, cfg, out);
    } catch (const WidthError&) {
      std::vector<TriangleSetup> keep;
      isolate_width_errors(*engine, setup.tris, cfg, keep, r.rejected_width);
      setup.tris = std::move(keep);
      setup.counts.accepted = setup.tris.size();
      out = EngineResult{};
      t0 = Clock::now();
      engine->run(setup, cfg, out);
    }
    r.wall_seconds = seconds_since(t0);
    r.offered = setup.tris.size();
    sort_spans(out.spans);
    r.spans = out.spans.size();
    r.pixels = count_pixels(out.spans);
    r.total_cycles = out.total_cycles;
    auto it = out.work.find("divider_iterations");
    if (it != out.work.end()) r.divider_iterations = it->second;
    const SpanDiff diff = diff_spans(scene.reference, out.spans);
    r.missing = diff.missing_pixels;
    r.extra = diff.extra_pixels;
    if (scene.spec.closed) {
      const WatertightResult c = check_watertight(setup, out.spans, cfg);
      r.cracks = c.cracks;
      r.doubles = c.doubles;
    }
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  return r;
}

// ---- aggregation -----------------------------------------------------------------------------------

PointSummary summarize(const SweepPoint& p, const std::vector<SweepSceneData>& scenes,
                       const std::vector<PointResult>& results, const AreaModel& area) {
  PointSummary s;
  s.area = area.area(p.kind(), p.cfg);
  s.rtl = p.rtl();
  double golden_seconds = 0;
  int n = 0;
  for (size_t i = 0; i < scenes.size(); ++i) {
    const PointResult& r = results[i];
    if (!r.error.empty()) {
      ++s.failures;
      continue;
    }
    const int64_t ref = scenes[i].reference_pixels;
    const double e = ppm(r.missing + r.extra, ref);
    s.error_ppm += e;
    s.missing_ppm += ppm(r.missing, ref);
    s.extra_ppm += ppm(r.extra, ref);
    s.max_error_ppm = std::max(s.max_error_ppm, e);
    ++n;
    s.missing += r.missing;
    s.extra += r.extra;
    s.reference_pixels += ref;
    if (r.cracks >= 0) s.cracks = std::max<int64_t>(s.cracks, 0) + r.cracks;
    if (r.doubles >= 0) s.doubles = std::max<int64_t>(s.doubles, 0) + r.doubles;
    s.offered += r.offered;
    s.scene_triangles += scenes[i].reference_triangles;
    s.rejected += r.rejected_range + r.rejected_width;
    s.total_cycles += r.total_cycles;
    s.pixels += r.pixels;
    s.wall_seconds += r.wall_seconds;
    golden_seconds += scenes[i].golden_seconds;
  }
  if (n > 0) {
    s.error_ppm /= n;
    s.missing_ppm /= n;
    s.extra_ppm /= n;
  }
  s.exact = s.failures == 0 && s.missing == 0 && s.extra == 0;
  s.timed = s.total_cycles > 0;
  s.cycles_per_triangle =
      s.scene_triangles ? double(s.total_cycles) / double(s.scene_triangles) : 0;
  s.cycles_per_pixel = s.pixels ? double(s.total_cycles) / double(s.pixels) : 0;
  s.wall_ratio = golden_seconds > 0 ? s.wall_seconds / golden_seconds : 0;
  return s;
}

void mark_pareto(std::vector<PointSummary>& all) {
  // Whether `a` is undominated among the points `competes` admits.
  auto undominated = [&](const PointSummary& a, auto y_of, auto competes) {
    for (const PointSummary& b : all) {
      if (&a == &b || !competes(b)) continue;
      const bool le = b.error_ppm <= a.error_ppm && y_of(b) <= y_of(a);
      const bool lt = b.error_ppm < a.error_ppm || y_of(b) < y_of(a);
      if (le && lt) return false;
    }
    return true;
  };
  auto fronts = [&](auto y_of, auto eligible, bool PointSummary::*hw, bool PointSummary::*whatif) {
    auto hardware = [&](const PointSummary& s) { return eligible(s) && s.rtl; };
    for (PointSummary& a : all) {
      a.*hw = hardware(a) && undominated(a, y_of, hardware);
      a.*whatif = eligible(a) && !a.rtl && undominated(a, y_of, eligible);
    }
  };
  fronts([](const PointSummary& s) { return s.cycles_per_triangle; },
         [](const PointSummary& s) { return s.timed && s.failures == 0; },
         &PointSummary::pareto_cycles, &PointSummary::whatif_cycles);
  fronts([](const PointSummary& s) { return s.area.luts; },
         [](const PointSummary& s) { return s.area.known() && s.failures == 0; },
         &PointSummary::pareto_area, &PointSummary::whatif_area);
}

// ---- outputs ---------------------------------------------------------------------------------------

namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return q + "\"";
}

std::string config_columns(const SweepPoint& p) {
  const RasterConfig& c = p.cfg;
  const bool improved = p.kind() == UnitKind::Improved;
  const bool boxed =
      improved || p.kind() == UnitKind::Halfspace || p.kind() == UnitKind::Improved2;
  return p.engine + "," + unit_kind_name(p.kind()) + "," + csv_field(p.group) + "," +
         csv_field(p.config_name()) + "," + std::to_string(c.subpixel_bits) + "," +
         std::to_string(c.coord_int_bits) + "," + (boxed ? std::to_string(c.box_bits) : "") +
         "," + (improved ? divider_mode_name(c.divider) : "") + "," +
         (improved ? std::to_string(c.divider_quotient_bits) : "") + "," +
         (improved || p.kind() == UnitKind::Improved2 ? std::to_string(c.endpoints) : "") + "," +
         (improved ? boundary_mode_name(c.boundary) : "");
}

const char* kConfigHeader =
    "engine,unit,group,config,subpixel_bits,coord_bits,box_bits,divider,quotient_bits,endpoints,"
    "boundary";

std::string opt_int(int64_t v) { return v < 0 ? "" : std::to_string(v); }

std::string area_columns(const Area& a) {
  if (!a.known()) return ",,";
  return fmt("%.0f", a.luts) + "," + fmt("%.0f", a.ffs) + "," + a.source;
}

}  // namespace

std::string sweep_csv(const std::vector<SweepPoint>& points,
                      const std::vector<SweepSceneData>& scenes,
                      const std::vector<std::vector<PointResult>>& results,
                      const std::vector<PointSummary>& summaries) {
  std::string out = std::string(kConfigHeader) +
                    ",scene,cull,closed,triangles,offered,degenerate,culled,rejected_range,"
                    "rejected_width,spans,pixels,reference_pixels,missing,extra,missing_ppm,"
                    "extra_ppm,error_ppm,cracks,doubles,total_cycles,cycles_per_triangle,"
                    "cycles_per_pixel,divider_iterations,luts,ffs,area_source,wall_seconds,"
                    "wall_ratio,error\n";
  for (size_t p = 0; p < points.size(); ++p)
    for (size_t s = 0; s < scenes.size(); ++s) {
      const PointResult& r = results[p][s];
      const SweepSceneData& sc = scenes[s];
      const bool timed = r.total_cycles > 0;
      out += config_columns(points[p]) + "," + csv_field(sc.spec.spec) + "," +
             cull_mode_name(sc.spec.cull) + "," + (sc.spec.closed ? "1" : "0") + "," +
             std::to_string(r.read) + "," + std::to_string(r.offered) + "," +
             std::to_string(r.degenerate) + "," + std::to_string(r.culled) + "," +
             std::to_string(r.rejected_range) + "," + std::to_string(r.rejected_width) + "," +
             std::to_string(r.spans) + "," + std::to_string(r.pixels) + "," +
             std::to_string(sc.reference_pixels) + "," + std::to_string(r.missing) + "," +
             std::to_string(r.extra) + "," + fmt("%.3f", ppm(r.missing, sc.reference_pixels)) +
             "," + fmt("%.3f", ppm(r.extra, sc.reference_pixels)) + "," +
             fmt("%.3f", ppm(r.missing + r.extra, sc.reference_pixels)) + "," +
             opt_int(r.cracks) + "," + opt_int(r.doubles) + "," +
             (timed ? std::to_string(r.total_cycles) : "") + "," +
             (timed && sc.reference_triangles
                  ? fmt("%.4f", double(r.total_cycles) / double(sc.reference_triangles))
                  : "") +
             "," + (timed && r.pixels ? fmt("%.5f", double(r.total_cycles) / double(r.pixels)) : "") +
             "," + std::to_string(r.divider_iterations) + "," + area_columns(summaries[p].area) +
             "," + fmt("%.6f", r.wall_seconds) + "," +
             fmt("%.4f", sc.golden_seconds > 0 ? r.wall_seconds / sc.golden_seconds : 0.0) + "," +
             csv_field(r.error) + "\n";
    }
  return out;
}

std::string sweep_configs_csv(const std::vector<SweepPoint>& points,
                              const std::vector<PointSummary>& summaries) {
  std::string out = std::string(kConfigHeader) +
                    ",error_ppm,missing_ppm,extra_ppm,max_error_ppm,exact,cracks,doubles,offered,"
                    "rejected,total_cycles,cycles_per_triangle,cycles_per_pixel,luts,ffs,"
                    "area_source,wall_seconds,wall_ratio,pareto_cycles,pareto_area,failures,rtl,"
                    "whatif_cycles,whatif_area\n";
  for (size_t p = 0; p < points.size(); ++p) {
    const PointSummary& s = summaries[p];
    out += config_columns(points[p]) + "," + fmt("%.3f", s.error_ppm) + "," +
           fmt("%.3f", s.missing_ppm) + "," + fmt("%.3f", s.extra_ppm) + "," +
           fmt("%.3f", s.max_error_ppm) + "," + (s.exact ? "1" : "0") + "," + opt_int(s.cracks) +
           "," + opt_int(s.doubles) + "," + std::to_string(s.offered) + "," +
           std::to_string(s.rejected) + "," + (s.timed ? std::to_string(s.total_cycles) : "") +
           "," + (s.timed ? fmt("%.4f", s.cycles_per_triangle) : "") + "," +
           (s.timed ? fmt("%.5f", s.cycles_per_pixel) : "") + "," + area_columns(s.area) + "," +
           fmt("%.6f", s.wall_seconds) + "," + fmt("%.4f", s.wall_ratio) + "," +
           (s.pareto_cycles ? "1" : "0") + "," + (s.pareto_area ? "1" : "0") + "," +
           std::to_string(s.failures) + "," + (s.rtl ? "1" : "0") + "," +
           (s.whatif_cycles ? "1" : "0") + "," + (s.whatif_area ? "1" : "0") + "\n";
  }
  return out;
}

Json sweep_point_json(const SweepPoint& p) {
  const RasterConfig& c = p.cfg;
  Json j = Json::object();
  j.set("engine", p.engine)
      .set("unit", unit_kind_name(p.kind()))
      .set("group", p.group)
      .set("config", p.config_name())
      .set("subpixel_bits", c.subpixel_bits)
      .set("coord_bits", c.coord_int_bits);
  if (p.kind() == UnitKind::Improved)
    j.set("box_bits", c.box_bits)
        .set("divider", divider_mode_name(c.divider))
        .set("quotient_bits", c.divider_quotient_bits)
        .set("endpoints", c.endpoints)
        .set("boundary", boundary_mode_name(c.boundary));
  if (p.kind() == UnitKind::Halfspace)
    j.set("box_bits", c.box_bits)
        .set("stamp", c.halfspace.stamp)
        .set("tile", c.halfspace.tile)
        .set("walk", halfspace_walk_name(c.halfspace.walk));
  if (p.kind() == UnitKind::Improved2) {
    j.set("box_bits", c.box_bits).set("endpoints", c.endpoints);
    if (engine_reads(p.engine, "--corner-form"))
      j.set("corner_form", c.improved2.corner_form == 0 ? "dsp" : "radix16");
  }
  return j;
}

Json point_result_json(const PointResult& r) {
  Json j = Json::object();
  j.set("triangles", r.read)
      .set("offered", r.offered)
      .set("degenerate", r.degenerate)
      .set("culled", r.culled)
      .set("rejected_range", r.rejected_range)
      .set("rejected_width", r.rejected_width)
      .set("spans", r.spans)
      .set("pixels", r.pixels)
      .set("missing", r.missing)
      .set("extra", r.extra);
  if (r.cracks >= 0) j.set("cracks", r.cracks).set("doubles", r.doubles);
  if (r.total_cycles) j.set("total_cycles", r.total_cycles);
  j.set("divider_iterations", r.divider_iterations).set("wall_seconds", r.wall_seconds);
  if (!r.error.empty()) j.set("error", r.error);
  return j;
}

Json point_summary_json(const PointSummary& s) {
  Json j = Json::object();
  j.set("error_ppm", s.error_ppm)
      .set("missing_ppm", s.missing_ppm)
      .set("extra_ppm", s.extra_ppm)
      .set("max_error_ppm", s.max_error_ppm)
      .set("exact", s.exact)
      .set("missing", s.missing)
      .set("extra", s.extra)
      .set("reference_pixels", s.reference_pixels);
  if (s.cracks >= 0) j.set("cracks", s.cracks).set("doubles", s.doubles);
  j.set("offered", s.offered).set("rejected", s.rejected).set("pixels", s.pixels);
  j.set("scene_triangles", s.scene_triangles);
  if (s.timed)
    j.set("total_cycles", s.total_cycles)
        .set("cycles_per_triangle", s.cycles_per_triangle)
        .set("cycles_per_pixel", s.cycles_per_pixel);
  if (s.area.known()) {
    j.set("luts", s.area.luts).set("ffs", s.area.ffs).set("area_source", s.area.source);
    if (!s.area.origin.empty()) j.set("area_origin", s.area.origin);
  }
  j.set("wall_seconds", s.wall_seconds)
      .set("wall_ratio", s.wall_ratio)
      .set("pareto_cycles", s.pareto_cycles)
      .set("pareto_area", s.pareto_area)
      .set("rtl", s.rtl)
      .set("whatif_cycles", s.whatif_cycles)
      .set("whatif_area", s.whatif_area)
      .set("failures", s.failures);
  return j;
}

}  // namespace trirast
