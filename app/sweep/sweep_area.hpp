// Area of a sweep configuration: LUTs and flip-flops from synthesis (docs/synth.csv, written by
// scripts/synth.sh) where it covers the configuration, otherwise an estimate from the datapath
// widths (docs/unit.md "Widths"), marked "estimate" wherever it is shown.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "common/config.hpp"

namespace trirast {

// Improved2: the second-generation improved unit (improved2-* engines, rtl/improved2/trirast_improved2.f,
// docs/improved2.md); scripts/synth.sh synthesizes it at the default widths (and the distributed
// sweep's synthesis jobs at others); it has no width formula: elsewhere its area is unknown.
enum class UnitKind { Improved, Trad, Halfspace, Improved2, Cpu, Golden };
const char* unit_kind_name(UnitKind k);
// The kind of the unit named in app/units.cpp ("improved", "improved2", "trad", "halfspace");
// UnitKind::Cpu for any other name.
UnitKind unit_kind_of(const std::string& unit_name);
// The unit's name in docs/synth.csv for a configuration: "improved", "trad", the half-space
// unit's "halfspace-sS" (scripts/synth.sh names one unit per stamp size S; in the digit-serial
// corner form "halfspace-radix16-sS"), the second-generation
// unit's "improved2" (radix-16 corner form) or "improved2-products" (the products form); "" for no
// hardware.
std::string synth_unit_name(UnitKind k, const RasterConfig& cfg);

struct Area {
  double luts = 0;
  double ffs = 0;
  std::string source;  // "synth:TARGET" | "estimate" | "" (no hardware: CPU baselines)
  std::string origin;  // synthesized: the file it was read from (docs/synth.csv or a run's .synth)
  bool from_run = false;  // synthesized by the distributed run's own synthesis jobs (add_rows)
  bool estimate() const { return source == "estimate"; }
  bool known() const { return !source.empty(); }
};

// One row of docs/synth.csv: unit,config,target,luts,ffs,carry,bram,dsp,fmax_mhz (and xc7_mapper,
// the xilinx7 row's Yosys LUT mapper, which the area model does not need).
struct SynthRow {
  std::string unit, config, target;
  double luts = 0, ffs = 0;
  // The configuration's widths, from the config name (see AreaModel::config_widths).
  int subpixel_bits = -1, coord_bits = -1, box_bits = -1;
  int endpoints = 1;     // NumEndpoints of the synthesized unit (docs/synth.csv: 1)
  double fmax_mhz = 0;   // iCE40 place and route of the same configuration, 0 when none
  std::string origin;    // the file it was read from
  bool from_run = false;  // added by AreaModel::add_rows (a distributed run's synthesis job)
};

// The raw width formula (before calibration), for the report.
struct AreaTerms {
  double luts = 0, ffs = 0;
};
AreaTerms improved_area_terms(const RasterConfig& cfg);
AreaTerms trad_area_terms(const RasterConfig& cfg);
AreaTerms improved2_area_terms(const RasterConfig& cfg);

class AreaModel {
 public:
  // Reads `synth_csv` when the file exists (a missing file is not an error: estimates only).
  // `synth_script` (scripts/synth.sh) names the configurations: its CONFIGS="name:S:coord:box ..."
  // line; "default", "small" and "wide" are known without it. Throws std::runtime_error naming
  // the file and line for a malformed CSV.
  AreaModel(const std::string& synth_csv, const std::string& synth_script);
  // Area of one configuration of a unit. Synthesis covers improved units with N = 1, FIFO 8 and no
  // quotient truncation (divider and boundary modes are runtime inputs of the RTL), and the
  // half-space unit at the tile size and walk scripts/synth.sh builds (TileSize 8, forward), per
  // stamp size, and the second-generation unit per corner form (FIFO 8, N = 1). The half-space
  // unit has no width formula: elsewhere its area is unknown; the second-generation unit's
  // formula is scaled to its own synthesis of the corner form (unknown without it).
  Area area(UnitKind kind, const RasterConfig& cfg) const;

  // Results of the distributed sweep's synthesis jobs (sweep_shard.hpp read_synth_results): a
  // row replaces one of docs/synth.csv for the same unit, widths and endpoints (and, for the
  // default improved unit, recalibrates the estimate to it: the RTL of this run). Rows of another
  // target than target() (or of "ice40-pnr", which carries Fmax only) give only their Fmax.
  void add_rows(const std::vector<SynthRow>& rows);
  // The width formula, scaled, whatever synthesis covers (to report its error against synthesis);
  // unknown (Area::known() false) for a unit without one (the half-space unit, CPU engines) and
  // for the second-generation unit when no synthesis of its corner form calibrates it.
  Area estimate(UnitKind kind, const RasterConfig& cfg) const;
  // iCE40 Fmax of the configuration's place and route by the distributed run's synthesis jobs
  // (add_rows), 0 when none was measured.
  double fmax_mhz(UnitKind kind, const RasterConfig& cfg) const;
  // iCE40 HX8K Fmax of the configuration's place and route as the synthesis CSV records it (its
  // fmax_mhz column, the whole unit's row of target ice40), 0 when none.
  double csv_fmax_mhz(UnitKind kind, const RasterConfig& cfg) const;

  bool have_synth() const { return !rows_.empty(); }
  const std::vector<SynthRow>& rows() const { return rows_; }
  const std::string& target() const { return target_; }  // the target used ("" when none)
  // The estimate's scale factors: synthesis / formula at the default improved configuration
  // when synthesis has it, else 1.
  double lut_scale() const { return lut_scale_; }
  double ff_scale() const { return ff_scale_; }
  std::string formula_text() const;  // one paragraph for the report

 private:
  const SynthRow* find(const std::string& unit, const RasterConfig& cfg) const;
  static double fmax_in(const std::vector<SynthRow>& rows, UnitKind kind, const RasterConfig& cfg);
  void calibrate();
  std::vector<SynthRow> rows_, fmax_rows_, csv_fmax_rows_;
  std::string target_;
  double lut_scale_ = 1, ff_scale_ = 1;
  std::pair<double, double> trad_scale_{1, 1};  // (LUT, FF) of the traditional unit
  std::pair<double, double> g2_scale_[2];  // (LUT, FF) per corner form (0 products, 1 radix 16)
};

}  // namespace trirast
