#include "io/kit_vectors.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include <unistd.h>

#include "cli/args.hpp"
#include "common/sink_pattern.hpp"
#include "common/span_downstream.hpp"
#include "common/trirast_rtl_params.hpp"
#include "io/output_file.hpp"
#include "units.hpp"

namespace trirast {

namespace {

// The directory's description, written into it as README.txt (docs/port.md, "Testbench kit",
// says the same).
const char* const kReadme = R"(Vectors of the trirast testbench kit (tb/kit; docs/port.md, "Testbench kit"),
written by `trirast raster --vectors DIR`. Run them with
  tb/kit/run.sh --sim verilator|icarus DIR WORKDIR

Triangles are numbered by their position p in this run (0, 1, ...); p is the tag the driver puts
on tri_tag_i and the unit returns on span_tag_o. Cycle 0 is the first clock cycle after reset, in
which triangle 0 is on the port; a handshake in cycle c is the rising edge that ends cycle c.
Every .hex file is one value per line, hexadecimal, most significant digit first ($readmemh); a
value is its fields concatenated, the first named field in the most significant bits.

tris.hex     per triangle p, the unit top's triangle port (rtl/common/trirast_ports.svh):
               improved, improved2, halfspace:
                 {tri_bias_i[2:0], tri_c_i[3*EdgeBits], tri_b_i[3*CoefBits], tri_a_i[3*CoefBits],
                  tri_vy_i[3*VertexBits], tri_vx_i[3*VertexBits], tri_tag_i[TagBits]}
               trad (vertices only): {tri_vy_i, tri_vx_i, tri_tag_i}
             (edge k of a field at [k*width +: width]; widths of rtl/common/trirast_pkg.sv:
             VertexBits 24, CoefBits 25, EdgeBits 50, TagBits 32)
spans.hex    the expected spans {order[32], tag[TagBits], y[PixBits], x_begin[PixBits],
             x_end[PixBits+1]} (PixBits 15; x_end exclusive), triangle by triangle (0 first), each
             triangle's in the order its span port gives them; order: the span's position in the
             span port's whole output (0 first)
expect.hex   per triangle p: {first[32], count[32], accept[32], first_span[32], done[32]}:
             its spans are lines first .. first+count-1 of spans.hex; accept: the cycle of its
             triangle-port handshake; first_span, done: the cycles of its first and last span
             handshakes, or both the cycle it retired without a span (box_retire_o,
             setup_retire_o, walk_retire_o)
params.txt   "unit UNIT" and the top's parameters, "NAME VALUE" per line (run.sh gives them to
             the simulator: trirast_UNIT_top's NumEndpoints, FifoDepth, CornerForm, StampSize,
             TileSize, WalkMode, as the unit has them)
plusargs.txt the bench's run-time plusargs: +kit_format (this format's number, 1: the bench
             refuses another) +ntris +nspans; the static inputs +vp_xmax +vp_ymax
             (cfg_vp_xmax_i, cfg_vp_ymax_i), +fifo_depth (cfg_fifo_depth_i), +endpoints
             (cfg_endpoints_i), +divide (cfg_divide_i), +adaptive (cfg_adaptive_i); the
             downstream's span_ready_i pattern +sink=none|periodic|random with +sink_ready
             +sink_stall (periodic: ready for READY cycles, then STALL cycles not) or +sink_seed
             +sink_percent (random: not ready in cycle c when splitmix64(SEED * 0x9E3779B97F4A7C15
             + c) % 100 < PERCENT); +last, the last expected done cycle
)";

// The format's number (+kit_format in plusargs.txt); tb/kit/trirast_kit_scoreboard.sv's KitFormat.
constexpr int kKitFormat = 1;

// Hex of a bit vector of `bits` bits, bit 0 first in `bitsv` (MSB first in the text, as
// $readmemh reads it).
struct HexBits {
  std::string bitsv;
  void put(int width, int64_t v) {
    for (int b = 0; b < width; ++b)
      bitsv.push_back(((uint64_t(v) >> (b < 64 ? b : 63)) & 1) ? '1' : '0');
  }
  std::string hex() const {
    std::string out;
    const int n = int(bitsv.size());
    for (int d = (n + 3) / 4 - 1; d >= 0; --d) {
      int v = 0;
      for (int b = 3; b >= 0; --b) {
        const int i = d * 4 + b;
        v = v * 2 + (i < n && bitsv[size_t(i)] == '1' ? 1 : 0);
      }
      out.push_back("0123456789abcdef"[v]);
    }
    return out;
  }
};

[[noreturn]] void refuse(const std::string& dir, const std::string& why) {
  throw UsageError("trirast raster: --vectors " + dir + ": " + why);
}

int pow2_at_least(int n) {
  int p = 1;
  while (p < n) p *= 2;
  return p;
}

// The folder's nearest existing ancestor (itself when it exists): where it would be created.
std::filesystem::path existing_ancestor(const std::string& dir) {
  std::filesystem::path p = std::filesystem::absolute(dir);
  while (!std::filesystem::exists(p) && p.has_parent_path() && p != p.parent_path())
    p = p.parent_path();
  return p;
}

}  // namespace

void check_kit_vectors(const std::string& engine, const RasterConfig& cfg, const std::string& dir) {
  const UnitDescriptor* unit = unit_of(engine);
  const std::string view = unit ? engine.substr(unit->name.size() + 1) : "";
  if (!unit || (view != "sc" && view != "rtl"))
    refuse(dir, "engine '" + engine +
                    "' has no RTL top with cycles to replay (the kit runs a unit's "
                    "trirast_UNIT_top against the cycles of its -rtl or -sc engine, e.g. --engine "
                    "improved-rtl)");
  if (cfg.subpixel_bits != rtl::kSubpixelBits || cfg.coord_int_bits != rtl::kCoordIntBits ||
      cfg.box_bits != rtl::kBoxBits)
    refuse(dir, "the kit's RTL has the widths of rtl/common/trirast_pkg.sv (--subpixel-bits " +
                    std::to_string(rtl::kSubpixelBits) + " --coord-bits " +
                    std::to_string(rtl::kCoordIntBits) + " --box-bits " +
                    std::to_string(rtl::kBoxBits) + "); this run has " +
                    std::to_string(cfg.subpixel_bits) + ", " + std::to_string(cfg.coord_int_bits) +
                    ", " + std::to_string(cfg.box_bits));
  if (!is_cycle_pattern(cfg.sink_stall))
    refuse(dir, "--sink-stall " + cfg.sink_stall +
                    ": a downstream that reacts to the spans it takes cannot be replayed by the "
                    "kit's downstream (it plays none, periodic:READY:STALL or random:SEED:PERCENT)");
  (void)SinkPattern::parse(cfg.sink_stall);  // a malformed pattern names --sink-stall
  // Checked before the run, created only when the files are written (write_kit_vectors), so a
  // refused or interrupted run leaves no folder behind.
  const std::filesystem::path base = existing_ancestor(dir);
  if (!std::filesystem::is_directory(base) || access(base.c_str(), W_OK) != 0)
    refuse(dir, "cannot create the directory (" + base.string() + " is not a writable directory)");
}

void write_kit_vectors(const std::string& dir, const std::string& engine, const std::string& scene,
                       const SetupResult& setup, const RasterConfig& cfg,
                       const EngineResult& result, const SpanList& output_order) {
  const UnitDescriptor* unit = unit_of(engine);
  const std::string name = unit->name;
  const size_t n = setup.tris.size();
  if (result.cycles.size() != n)
    refuse(dir, "engine '" + engine + "' reported " + std::to_string(result.cycles.size()) +
                    " triangles' cycles for " + std::to_string(n) + " triangles");

  // Spans grouped by triangle position, each triangle's in output order.
  std::map<uint32_t, size_t> pos_of;
  for (size_t p = 0; p < n; ++p) pos_of[setup.tris[p].index] = p;
  std::vector<std::vector<std::pair<Span, uint64_t>>> by_tri(n);  // each span with its order
  for (size_t i = 0; i < output_order.size(); ++i)
    by_tri[pos_of.at(output_order[i].tri)].push_back({output_order[i], uint64_t(i)});

  uint64_t last = 0;
  for (const TriangleCycles& tc : result.cycles) last = std::max(last, tc.done_cycle);
  if (last >= (uint64_t(1) << 32))
    refuse(dir, "cycle " + std::to_string(last) + " does not fit expect.hex's 32-bit cycles");

  // Every file is formed in memory and written whole through OutputFile (a temporary file
  // renamed on commit, removed on failure and on SIGINT / SIGTERM).
  std::ostringstream tris, spans, expect, params, args, readme;
  const bool vertices_only = name == "trad";
  uint64_t first = 0;
  for (size_t p = 0; p < n; ++p) {
    const TriangleSetup& t = setup.tris[p];
    HexBits h;
    h.put(rtl::kTagBits, int64_t(p));
    for (int k = 0; k < 3; ++k) h.put(rtl::kVertexBits, t.v[k].x);
    for (int k = 0; k < 3; ++k) h.put(rtl::kVertexBits, t.v[k].y);
    if (!vertices_only) {
      for (int k = 0; k < 3; ++k) h.put(rtl::kCoefBits, t.edge[k].A);
      for (int k = 0; k < 3; ++k) h.put(rtl::kCoefBits, t.edge[k].B);
      for (int k = 0; k < 3; ++k) h.put(rtl::kEdgeBits, t.edge[k].C);
      for (int k = 0; k < 3; ++k) h.put(1, t.edge[k].bias != 0);
    }
    tris << h.hex() << "\n";
    for (const auto& [s, order] : by_tri[p]) {
      HexBits hs;
      hs.put(rtl::kPixBits + 1, s.x_end);
      hs.put(rtl::kPixBits, s.x_begin);
      hs.put(rtl::kPixBits, s.y);
      hs.put(rtl::kTagBits, int64_t(p));
      hs.put(32, int64_t(order));
      spans << hs.hex() << "\n";
    }
    const TriangleCycles& tc = result.cycles[p];
    HexBits he;
    he.put(32, int64_t(tc.done_cycle));
    he.put(32, int64_t(tc.first_span_cycle));
    he.put(32, int64_t(tc.accept_cycle));
    he.put(32, int64_t(by_tri[p].size()));
    he.put(32, int64_t(first));
    expect << he.hex() << "\n";
    first += by_tri[p].size();
  }

  // The top's parameters: the smallest hardware that holds the run's --endpoints and
  // --fifo-depth (FifoDepth a power of two), as the synthesized unit is built.
  params << "unit " << name << "\n";
  if (name == "improved" || name == "improved2") params << "NumEndpoints " << cfg.endpoints << "\n";
  params << "FifoDepth " << pow2_at_least(cfg.fifo_depth) << "\n";
  if (name == "improved2") params << "CornerForm " << cfg.improved2.corner_form << "\n";
  if (name == "halfspace")
    params << "StampSize " << cfg.halfspace.stamp << "\nTileSize " << cfg.halfspace.tile
           << "\nWalkMode " << int(cfg.halfspace.walk)
           << "\nCornerForm " << cfg.halfspace.corner_form << "\n";

  const SinkPattern sink = SinkPattern::parse(cfg.sink_stall);
  const char* kind = sink.kind() == SinkPattern::Kind::Periodic ? "periodic"
                     : sink.kind() == SinkPattern::Kind::Random ? "random"
                                                                : "none";
  args << "+kit_format=" << kKitFormat << " +ntris=" << n << " +nspans=" << first << " +vp_xmax=" << cfg.width - 1
       << " +vp_ymax=" << cfg.height - 1 << " +fifo_depth=" << cfg.fifo_depth
       << " +endpoints=" << cfg.endpoints
       << " +divide=" << (cfg.boundary == BoundaryMode::Divide ? 1 : 0)
       << " +adaptive=" << (cfg.divider == DividerMode::Adaptive ? 1 : 0) << " +sink=" << kind
       << " +sink_ready=" << sink.ready_cycles() << " +sink_stall=" << sink.stall_cycles()
       << " +sink_seed=" << sink.seed() << " +sink_percent=" << sink.percent() << " +last=" << last
       << "\n";

  readme << "engine " << engine << ", scene " << scene << ", --sink-stall " << cfg.sink_stall
         << ": " << n << " triangles, " << first << " spans, last done cycle " << last << "\n\n"
         << kReadme;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    refuse(dir, "cannot create the directory" + (ec ? " (" + ec.message() + ")" : std::string()));
  const std::pair<const char*, const std::ostringstream*> files[] = {
      {"tris.hex", &tris},     {"spans.hex", &spans},      {"expect.hex", &expect},
      {"params.txt", &params}, {"plusargs.txt", &args},    {"README.txt", &readme}};
  for (const auto& [file, text] : files) {
    OutputFile out(dir + "/" + file, "--vectors");
    out.write(text->str());
    out.commit();
  }
}

}  // namespace trirast
