// Area of a sweep configuration: LUTs and flip-flops from synthesis (docs/synth.csv, written by
// scripts/synth.sh) where it covers the configuration, otherwise an estimate from the datapath
// widths (docs/unit.md "Widths"), marked "estimate" wherever it is shown.
#pragma once
#include <string>
#include <vector>

#include "core/config.hpp"

namespace trirast {

enum class UnitKind { Improved, Trad, Cpu, Golden };
const char* unit_kind_name(UnitKind k);

struct Area {
  double luts = 0;
  double ffs = 0;
  std::string source;  // "synth:TARGET" | "estimate" | "" (no hardware: CPU baselines)
  bool estimate() const { return source == "estimate"; }
  bool known() const { return !source.empty(); }
};

// One row of docs/synth.csv: unit,config,target,luts,ffs,carry,bram,dsp,fmax_mhz.
struct SynthRow {
  std::string unit, config, target;
  double luts = 0, ffs = 0;
  // The configuration's widths, from the config name (see AreaModel::config_widths).
  int subpixel_bits = -1, coord_bits = -1, box_bits = -1;
};

// The raw width formula (before calibration), for the report.
struct AreaTerms {
  double luts = 0, ffs = 0;
};
AreaTerms improved_area_terms(const RasterConfig& cfg);
AreaTerms trad_area_terms(const RasterConfig& cfg);

class AreaModel {
 public:
  // Reads `synth_csv` when the file exists (a missing file is not an error: estimates only).
  // `synth_script` (scripts/synth.sh) names the configurations: its CONFIGS="name:S:coord:box ..."
  // line; "default", "small" and "wide" are known without it. Throws std::runtime_error naming
  // the file and line for a malformed CSV.
  AreaModel(const std::string& synth_csv, const std::string& synth_script);
  // Area of one configuration of a unit. Synthesis covers improved units with N = 1, FIFO 8 and no
  // quotient truncation (divider and boundary modes are runtime inputs of the RTL).
  Area area(UnitKind kind, const RasterConfig& cfg) const;

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
  std::vector<SynthRow> rows_;
  std::string target_;
  double lut_scale_ = 1, ff_scale_ = 1;
};

}  // namespace trirast
