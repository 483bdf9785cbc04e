// trirast raster --vectors DIR: the stimulus and the expected results of one run for the
// testbench kit (tb/kit, docs/port.md "Testbench kit"): the set-up triangles in the unit top's
// port packing, each triangle's spans in the order the span port gives them, each triangle's
// accept, first-span and done cycles, the top's parameters and the downstream's ready pattern.
// The format is described in the README.txt written into DIR (kit_vectors.cpp, kReadme).
#pragma once
#include <string>

#include "common/config.hpp"
#include "common/engine.hpp"
#include "common/setup.hpp"

namespace trirast {

// Throws UsageError "trirast raster: --vectors ...: ..." before the run when the kit cannot
// replay it: an engine that is not a unit's SystemC model or RTL (golden, float-scanline, a
// datapath model: no RTL top, or no cycles), widths other than the kit's RTL package
// (rtl/common/trirast_pkg.sv), a downstream that reacts to the spans it takes (queue:RATE:CAPACITY),
// or a DIR that cannot be created.
void check_kit_vectors(const std::string& engine, const RasterConfig& cfg, const std::string& dir);

// Writes DIR/README.txt, tris.hex, spans.hex, expect.hex, params.txt and plusargs.txt.
// `output_order`: the engine's spans in the order its span port gave them (unsorted).
void write_kit_vectors(const std::string& dir, const std::string& engine, const std::string& scene,
                       const SetupResult& setup, const RasterConfig& cfg,
                       const EngineResult& result, const SpanList& output_order);

}  // namespace trirast
