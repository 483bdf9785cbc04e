#include "sweep/sweep_area.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "util.hpp"

namespace trirast {

const char* unit_kind_name(UnitKind k) {
  switch (k) {
    case UnitKind::Improved: return "improved";
    case UnitKind::Trad: return "trad";
    case UnitKind::Halfspace: return "halfspace";
    case UnitKind::Improved2: return "improved2";
    case UnitKind::Cpu: return "cpu";
    default: return "golden";
  }
}

UnitKind unit_kind_of(const std::string& unit_name) {
  if (unit_name == "improved") return UnitKind::Improved;
  if (unit_name == "trad") return UnitKind::Trad;
  if (unit_name == "halfspace") return UnitKind::Halfspace;
  if (unit_name == "improved2") return UnitKind::Improved2;
  return UnitKind::Cpu;
}

std::string synth_unit_name(UnitKind k, const RasterConfig& cfg) {
  switch (k) {
    case UnitKind::Improved:
    case UnitKind::Trad: return unit_kind_name(k);
    case UnitKind::Halfspace:
      return std::string(cfg.halfspace.corner_form == 0 ? "halfspace-s" : "halfspace-radix16-s") +
             std::to_string(cfg.halfspace.stamp);
    case UnitKind::Improved2: return cfg.improved2.corner_form == 0 ? "improved2-products" : "improved2";
    default: return "";
  }
}

namespace {

constexpr int kTagBits = 32;  // the triangle tag carried with every span (docs/synth.md)

double log2_ceil(int v) { return v <= 1 ? 0.0 : std::ceil(std::log2(double(v))); }

// The span FIFO: DEPTH entries of tag, y, x_begin, x_end (pixel coordinates: coord bits each).
AreaTerms fifo_terms(const RasterConfig& cfg, int write_ports) {
  const double entry = kTagBits + 3.0 * cfg.coord_int_bits;
  AreaTerms t;
  t.ffs = cfg.fifo_depth * entry + 2 * (log2_ceil(cfg.fifo_depth) + 1);
  t.luts = entry * (log2_ceil(cfg.fifo_depth) / 2.0 + write_ports);
  return t;
}

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r\n\"");
  if (a == std::string::npos) return "";
  const size_t b = s.find_last_not_of(" \t\r\n\"");
  return s.substr(a, b - a + 1);
}

// The trimmed items of a CSV line or a CONFIGS list.
std::vector<std::string> trimmed_items(const std::string& s, char sep) {
  std::vector<std::string> out = split(s, sep);
  for (std::string& item : out) item = trim(item);
  return out;
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

// Improved unit, from docs/unit.md "Widths": p = coord + F, edge values 2p + 2, steps and
// remainders p + F, box box_bits, quotient Q (or the truncated K), walker X' Q + 2.
// Flip-flops: every register of the stages; LUTs: one per adder / comparator bit, one per 2:1 mux
// bit (the nine corner-value products are DSPs on Xilinx and not counted).
AreaTerms improved_area_terms(const RasterConfig& cfg) {
  const double F = cfg.frac_bits(), p = cfg.coord_int_bits + F, c = cfg.coord_int_bits;
  const double A = p + 1, D = p + F, E = 2 * p + 2, bb = cfg.box_bits;
  const int qfull = cfg.box_bits + 1;
  const double Q = cfg.divider_quotient_bits > 0 ? std::min(cfg.divider_quotient_bits, qfull) : qfull;
  const double X = Q + 2, N = cfg.endpoints;
  AreaTerms t;
  // Flip-flops.
  t.ffs += 6 * p + 3 * (2 * A + E + 1);                     // triangle register (v, A, B, C, bias)
  t.ffs += 4 * c + 2 * bb + 3 * 2 * E;                      // interface: box, Xmax, Ymax, E_L, E_R
  t.ffs += 3 * (2 * E + 2 * D + E + Q + log2_ceil(qfull + 1) + E + Q + D + bb + X + D + 6);
  //        lanes: T, T1, D, s, remainder, quotient, counter, boundary value, results, flags
  t.ffs += 3 * (X + D + 2) + bb + 4 * c + 4;               // walk stage: X', e, state; row; box
  // LUTs.
  t.luts += 10 * p + 6 * E;                                 // box min/max/rounding, corner sums
  t.luts += 3 * (2 * E + 2 * D);                            // normalizers: negate / mirror
  t.luts += 3 * (2 * E + E + E + Q);                        // divider, saturation, boundary step
  t.luts += 3 * N * (3 * X + 3 * D);                        // Bresenham steps, N rows per cycle
  t.luts += N * (5 * X + 2 * c);                            // span generator, N rows
  const AreaTerms f = fifo_terms(cfg, cfg.endpoints);
  t.ffs += f.ffs;
  t.luts += f.luts;
  return t;
}

// Traditional unit (docs/timing.md, "The traditional unit"): integer pixel vertices (coord bits
// c), three Bresenham lines (x, y, dx, dy, error), two walkers, the span filler, the same FIFO.
AreaTerms trad_area_terms(const RasterConfig& cfg) {
  const double F = cfg.frac_bits(), p = cfg.coord_int_bits + F, c = cfg.coord_int_bits;
  const double cp = c + 1;
  AreaTerms t;
  t.ffs += 6 * p + 6 * c + 6 * c;                           // input, quantized, sorted vertices
  t.ffs += 3 * (2 * c + 2 * cp + (cp + 1) + 2);             // three lines: x, y, dx, dy, err, dirs
  t.ffs += 2 * (2 * c + cp + 1) + 2 * c + c + 4;            // walkers, span min/max, row, state
  t.luts += 3 * c + 12 * c + 2 * cp;                        // sort, collinearity
  t.luts += 3 * (2 * c + 2 * c + cp);                       // line set-up: deltas, abs, err init
  t.luts += 2 * (2 * cp + 2 * c + c + 2 * c);               // walkers: err, x, y, compares, muxes
  t.luts += 6 * c;                                          // span filler: min/max, clip
  const AreaTerms f = fifo_terms(cfg, 1);
  t.ffs += f.ffs;
  t.luts += f.luts;
  return t;
}

// Second-generation unit (docs/improved2.md, docs/timing.md): the same widths as the improved
// unit; its own stages: the box stage (triangle register without C, box, the corner operands),
// the corner values E_L per edge (radix 16: digit-serial accumulators with the signed
// multiplicands and a digit counter; products: the multipliers are DSPs and not counted, their
// sums are), the 2x2 direct test on E_L >> F, three lanes (remainder, quotient, counter, boundary
// results), three walkers (X', e and the bound per edge), the span generator's parallel compares
// and the FIFO.
AreaTerms improved2_area_terms(const RasterConfig& cfg) {
  const double F = cfg.frac_bits(), p = cfg.coord_int_bits + F, c = cfg.coord_int_bits;
  const double A = p + 1, D = p + F, E = 2 * p + 2, bb = cfg.box_bits;
  const double Q = cfg.box_bits + 1, X = Q + 2, N = cfg.endpoints;
  const bool radix16 = cfg.improved2.corner_form != 0;
  AreaTerms t;
  // Flip-flops.
  t.ffs += 6 * p + 3 * 2 * A;                               // triangle register (v, A, B)
  t.ffs += 4 * c + 2 * bb + 3 * 2 * (A + 1);                // box, corner operands
  t.ffs += 3 * E + (radix16 ? 3 * 2 * (A + 1) + log2_ceil(int(E / 4) + 1) : 0);  // E_L; digits
  t.ffs += 2 * (3 * c + kTagBits);                          // 2x2 test's output (two spans, tag)
  t.ffs += 3 * (E + Q + log2_ceil(int(Q) + 1) + 2 * D + X + 4);  // lanes
  t.ffs += 3 * (X + 2 * D + 2) + bb + 4 * c + 4;            // walk stage: X', e, bound; row; box
  // LUTs.
  t.luts += 10 * p + 6 * A;                                 // box min/max/clip, corner operands
  t.luts += radix16 ? 3 * (E + 4 * (A + 1)) : 3 * 2 * E;    // digit adds and accumulators / sums
  t.luts += 12 * (E - F);                                   // 2x2 direct test
  t.luts += 3 * (2 * E + Q + 2 * D);                        // lanes: divider, steps, boundary
  t.luts += 3 * N * (2 * X + 2 * D);                        // walkers, N rows per cycle
  t.luts += N * (6 * X + 2 * c);                            // span generator, N rows
  const AreaTerms f = fifo_terms(cfg, cfg.endpoints);
  t.ffs += f.ffs;
  t.luts += f.luts;
  return t;
}

AreaModel::AreaModel(const std::string& synth_csv, const std::string& synth_script) {
  // Configuration names -> widths: scripts/synth.sh's CONFIGS line, else the names it used.
  std::map<std::string, std::vector<int>> widths = {
      {"default", {8, 16, 14}}, {"small", {4, 12, 10}}, {"wide", {8, 20, 14}}};
  {
    std::ifstream script(synth_script);
    std::string line;
    while (std::getline(script, line)) {
      const size_t at = line.find("CONFIGS=\"");
      if (at != 0) continue;
      const std::string list = line.substr(9, line.find('"', 9) - 9);
      for (const std::string& item : trimmed_items(list, ' ')) {
        const auto f = trimmed_items(item, ':');
        if (f.size() != 4) continue;
        try {
          widths[f[0]] = {std::stoi(f[1]), std::stoi(f[2]), std::stoi(f[3])};
        } catch (const std::exception&) {
        }
      }
    }
  }
  std::ifstream in(synth_csv);
  if (!in) return;  // no synthesis yet: estimates only
  std::string line;
  int lineno = 0;
  std::map<std::string, int> col;
  while (std::getline(in, line)) {
    ++lineno;
    if (trim(line).empty()) continue;
    const auto f = trimmed_items(line, ',');
    if (col.empty()) {
      for (size_t i = 0; i < f.size(); ++i) col[lower(f[i])] = int(i);
      for (const char* need : {"unit", "config", "target", "luts", "ffs"})
        if (!col.count(need))
          throw std::runtime_error(synth_csv + ":1: no column '" + need + "'");
      continue;
    }
    auto get = [&](const char* name) -> std::string {
      const size_t i = size_t(col[name]);
      return i < f.size() ? f[i] : "";
    };
    SynthRow r;
    r.unit = lower(get("unit"));
    r.config = get("config");
    r.target = get("target");
    try {
      r.luts = std::stod(get("luts"));
      r.ffs = std::stod(get("ffs"));
    } catch (const std::exception&) {
      continue;  // a row without numbers (a failed synthesis) is skipped
    }
    auto w = widths.find(r.config);
    if (w == widths.end()) continue;  // a configuration the sweep cannot place
    r.subpixel_bits = w->second[0];
    r.coord_bits = w->second[1];
    r.box_bits = w->second[2];
    r.origin = synth_csv;
    if (col.count("fmax_mhz") && r.target == "ice40" && !get("fmax_mhz").empty()) {
      SynthRow f = r;
      try {
        f.fmax_mhz = std::stod(get("fmax_mhz"));
      } catch (const std::exception&) {
        throw std::runtime_error(synth_csv + ":" + std::to_string(lineno) + ": fmax_mhz '" +
                                 get("fmax_mhz") + "' is not a number");
      }
      csv_fmax_rows_.push_back(f);
    }
    rows_.push_back(r);
  }
  // One target for every number: Xilinx 7 when present (the paper's FPGA LUTs), else the first.
  for (const SynthRow& r : rows_)
    if (lower(r.target).find("xilinx") != std::string::npos || lower(r.target).find("xc7") == 0) {
      target_ = r.target;
      break;
    }
  if (target_.empty() && !rows_.empty()) target_ = rows_.front().target;
  rows_.erase(std::remove_if(rows_.begin(), rows_.end(),
                             [&](const SynthRow& r) { return r.target != target_; }),
              rows_.end());
  calibrate();
}

// Scales the estimate to the synthesized default improved unit, when synthesis has it; the
// traditional unit's to its own synthesized default when there is one (else the improved unit's
// scale). The second-generation unit's estimate is scaled to its own synthesis at the default
// widths, per corner form; without that row it has none (never the first generation's scale).
void AreaModel::calibrate() {
  const RasterConfig def;
  // (LUT, FF) = synthesis / formula of `unit` at cfg, or `fallback` without that synthesis row.
  using Scale = std::pair<double, double>;
  auto scale = [&](const std::string& unit, const RasterConfig& cfg,
                   AreaTerms (*terms)(const RasterConfig&), Scale fallback) {
    const SynthRow* d = find(unit, cfg);
    if (!d) return fallback;
    const AreaTerms t = terms(cfg);
    return Scale{d->luts / t.luts, d->ffs / t.ffs};
  };
  std::tie(lut_scale_, ff_scale_) =
      scale("improved", def, improved_area_terms, {lut_scale_, ff_scale_});
  trad_scale_ = scale("trad", def, trad_area_terms, {lut_scale_, ff_scale_});
  for (int form = 0; form < 2; ++form) {
    RasterConfig g2 = def;
    g2.improved2.corner_form = form;
    g2_scale_[form] = scale(synth_unit_name(UnitKind::Improved2, g2), g2, improved2_area_terms, {0, 0});
  }
}

const SynthRow* AreaModel::find(const std::string& unit, const RasterConfig& cfg) const {
  for (const SynthRow& r : rows_)
    if (r.unit == unit && r.subpixel_bits == cfg.subpixel_bits &&
        r.coord_bits == cfg.coord_int_bits && r.box_bits == cfg.box_bits &&
        r.endpoints == cfg.endpoints)
      return &r;
  return nullptr;
}

void AreaModel::add_rows(const std::vector<SynthRow>& rows) {
  for (const SynthRow& r : rows) {
    if (r.fmax_mhz > 0) fmax_rows_.push_back(r);
    if (r.target != target_ && !(target_.empty() && r.target == "xilinx7")) continue;
    if (target_.empty()) target_ = r.target;
    auto same = [&](const SynthRow& o) {
      return o.unit == r.unit && o.subpixel_bits == r.subpixel_bits &&
             o.coord_bits == r.coord_bits && o.box_bits == r.box_bits &&
             o.endpoints == r.endpoints;
    };
    rows_.erase(std::remove_if(rows_.begin(), rows_.end(), same), rows_.end());
    rows_.push_back(r);
    rows_.back().from_run = true;
  }
  calibrate();
}

Area AreaModel::estimate(UnitKind kind, const RasterConfig& cfg) const {
  Area a;
  if (kind == UnitKind::Improved2) {
    const std::pair<double, double>& k = g2_scale_[cfg.improved2.corner_form != 0];
    if (k.first <= 0) return a;  // not calibrated: no synthesis of this corner form
    const AreaTerms t = improved2_area_terms(cfg);
    a.luts = std::round(t.luts * k.first);
    a.ffs = std::round(t.ffs * k.second);
    a.source = "estimate";
    return a;
  }
  if (kind != UnitKind::Improved && kind != UnitKind::Trad) return a;
  const bool trad = kind == UnitKind::Trad;
  const AreaTerms t = trad ? trad_area_terms(cfg) : improved_area_terms(cfg);
  a.luts = std::round(t.luts * (trad ? trad_scale_.first : lut_scale_));
  a.ffs = std::round(t.ffs * (trad ? trad_scale_.second : ff_scale_));
  a.source = "estimate";
  return a;
}

double AreaModel::fmax_mhz(UnitKind kind, const RasterConfig& cfg) const {
  return fmax_in(fmax_rows_, kind, cfg);
}

double AreaModel::csv_fmax_mhz(UnitKind kind, const RasterConfig& cfg) const {
  return fmax_in(csv_fmax_rows_, kind, cfg);
}

double AreaModel::fmax_in(const std::vector<SynthRow>& rows, UnitKind kind,
                          const RasterConfig& cfg) {
  const std::string unit = synth_unit_name(kind, cfg);
  if (unit.empty()) return 0;  // no hardware, or none scripts/synth.sh builds
  for (const SynthRow& r : rows)
    if (r.unit == unit && r.subpixel_bits == cfg.subpixel_bits &&
        r.coord_bits == cfg.coord_int_bits && r.box_bits == cfg.box_bits &&
        r.endpoints == cfg.endpoints)
      return r.fmax_mhz;
  return 0;
}

Area AreaModel::area(UnitKind kind, const RasterConfig& cfg) const {
  Area a;
  // No hardware (the CPU baselines).
  if (kind != UnitKind::Improved && kind != UnitKind::Trad && kind != UnitKind::Halfspace &&
      kind != UnitKind::Improved2)
    return a;
  // What synthesis fixes: FIFO 8; no truncation (improved); TileSize and walk (half-space); N:
  // the row's.
  const RasterConfig synth_like;
  bool fixed_match = cfg.fifo_depth == synth_like.fifo_depth;
  if (kind == UnitKind::Improved) fixed_match = fixed_match && cfg.divider_quotient_bits == 0;
  if (kind == UnitKind::Halfspace)
    fixed_match = fixed_match && cfg.halfspace.tile == synth_like.halfspace.tile && cfg.halfspace.walk == synth_like.halfspace.walk;
  if (fixed_match)
    if (const SynthRow* r = find(synth_unit_name(kind, cfg), cfg)) {
      a.luts = r->luts;
      a.ffs = r->ffs;
      a.source = "synth:" + r->target;
      a.origin = r->origin;
      a.from_run = r->from_run;
      return a;
    }
  return estimate(kind, cfg);
}

std::string AreaModel::formula_text() const {
  std::ostringstream s;
  s << "Estimate (app/sweep/sweep_area.cpp): flip-flops = the bits of every register of the stages; "
       "LUTs = one per adder, comparator and 2:1 multiplexer bit; from the widths of docs/unit.md "
       "(p = coord + F, edge values 2p + 2, steps and remainders p + F, box bits, quotient Q or the "
       "truncated K, walker Q + 2), the walker adders and span generator counted N times for N "
       "endpoints, a span FIFO of DEPTH x (32-bit tag + 3 x coord) bits; the traditional unit from "
       "integer pixel coordinates (three Bresenham lines, two walkers, span filler, the same "
       "FIFO); the second-generation unit from its own stages (box stage, corner values per "
       "corner form, 2x2 direct test, lanes, walkers, span generator, the same FIFO), scaled to "
       "its own synthesis at the default widths per corner form and unknown without it. ";
  if (lut_scale_ != 1 || ff_scale_ != 1)
    s << "Scaled to the synthesized default improved unit (" << target_ << "): LUT x "
      << lut_scale_ << ", FF x " << ff_scale_ << ".";
  else
    s << "Unscaled (no synthesis of the default improved unit was found).";
  if (trad_scale_ != std::make_pair(lut_scale_, ff_scale_))
    s << " The traditional unit's to its own synthesized default: LUT x " << trad_scale_.first
      << ", FF x " << trad_scale_.second << ".";
  return s.str();
}

}  // namespace trirast
