// Differential fuzzing: random configurations and triangles biased toward the classes of
// docs/hard-cases.md, a checker that runs engines against the golden, and the .tri reproducer
// format.
//
// One generator serves two masters through FuzzDraws: `trirast fuzz` draws from a seeded PRNG,
// the libFuzzer target (tb/fuzz/libfuzzer/) draws from the fuzzer's bytes, so both explore the same
// classes and a byte string the fuzzer mutates maps to a small, local change of the scene.
//
// Depends only on model/common and model/golden, so the libFuzzer build (clang, separate build
// directory) can compile it without the rest of tb/ and app/.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "common/config.hpp"
#include "halfspace/halfspace_setup.hpp"
#include "common/engine.hpp"
#include "common/setup.hpp"
#include "scene/rng.hpp"

namespace trirast {

// A source of random draws.
class FuzzDraws {
 public:
  virtual ~FuzzDraws() = default;
  // `n` (1..64) uniformly random bits.
  virtual uint64_t bits(int n) = 0;
  // Integer in [0, n), n > 0.
  uint64_t below(uint64_t n);
  // Integer in [lo, hi], lo <= hi.
  int64_t range(int64_t lo, int64_t hi);
  // True with probability percent/100.
  bool chance(int percent) { return below(100) < uint64_t(percent); }
};

// Draws from xoshiro256** seeded with `seed` (deterministic on every platform).
class RngDraws : public FuzzDraws {
 public:
  explicit RngDraws(uint64_t seed) : rng_(seed) {}
  uint64_t bits(int n) override { return n >= 64 ? rng_.next_u64() : rng_.next_u64() >> (64 - n); }

 private:
  SceneRng rng_;
};

// Draws from a byte string, little-endian, as few bytes per draw as the draw needs; zeros once
// the bytes run out (so every byte string decodes to something).
class ByteDraws : public FuzzDraws {
 public:
  ByteDraws(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  uint64_t bits(int n) override;
  bool exhausted() const { return pos_ >= size_; }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

// The triangle classes of docs/hard-cases.md the generator draws from.
enum class FuzzClass {
  Lattice,         // vertices on pixel centres and pixel corners (cases 2, 3, 4, 5)
  NearCentre,      // pixel centres offset by 0..2 subpixels (cases 2, 3, 10)
  AxisAndDiagonal, // edges at x = k + 0.5 / y = m + 0.5 and 45-degree edges through centres (2, 4)
  NearVertical,    // dx of 0 or +-1..3 subpixels over many rows (case 6)
  NearHorizontal,  // dy of 0..3 subpixels over a long dx (case 7)
  Sliver,          // third vertex a few subpixels off the line through the other two (case 8)
  Degenerate,      // collinear, repeated, all equal (case 9)
  Tiny,            // all vertices within a few pixels (case 10)
  Extreme,         // vertices at or near the coordinate limits (case 11)
  Straddle,        // straddling x = 0 / y = 0, negative coordinates (case 12)
  SnapTie,         // coordinates exactly halfway between two subpixel steps (case 13)
  ViewportEdge,    // spans ending at 0, W-1 and tile multiples (case 14)
  Cover,           // huge triangles over the whole viewport (case 15)
  Random,          // uniform around the viewport, any size
  kCount
};
const char* fuzz_class_name(FuzzClass c);

// Widths a configuration may be drawn with (a Verilated RTL build's package).
struct FuzzWidths {
  int subpixel_bits, coord_int_bits, box_bits;
};

// Whether draw_fuzz_config also draws queue:RATE:CAPACITY downstreams (--sink-stall; RATE 8..128,
// CAPACITY 1..512: a downstream whose ready reacts to the spans it took, span_downstream.hpp), one
// configuration in ten, in place of a tenth of the random patterns. Every timed engine, SystemC
// and RTL, drives the same downstream object.
inline constexpr bool kFuzzDrawsQueueDownstreams = true;

// A configuration every engine must accept: viewport, subpixel bits, coordinate range, box bits
// (always large enough for the viewport), boundary mode, culling, and the timed engines'
// endpoints, FIFO depth and sink pattern (or queue: kFuzzDrawsQueueDownstreams). With `widths` given, the widths are one of them (drawn
// evenly) and the viewport is cut to what they hold; otherwise any widths.
RasterConfig draw_fuzz_config(FuzzDraws& d, const std::vector<FuzzWidths>& widths = {});

// One triangle of class `c`, vertices inside the configured coordinate range, in a random vertex
// order and winding.
InputTriangle draw_fuzz_triangle(FuzzDraws& d, const RasterConfig& cfg, FuzzClass c);
// The same with a class drawn at random.
InputTriangle draw_fuzz_triangle(FuzzDraws& d, const RasterConfig& cfg);

// A scene of 1..max_tris triangles; sometimes a closed fan or quad grid, sometimes runs of one
// class, tiny after huge, so pipelined engines see every kind of neighbour. `classes`, when
// given, gets each triangle's class (FuzzClass::kCount for a fan's); the draws are the same.
std::vector<InputTriangle> draw_fuzz_scene(FuzzDraws& d, const RasterConfig& cfg, int max_tris,
                                           std::vector<FuzzClass>* classes = nullptr);

// The half-space unit's build parameters (--stamp, --tile, --hs-walk), drawn after the scene (so
// a seed's scenes stay those it drew before these existed): uniformly among `among` (e.g. the
// Verilated builds of halfspace-rtl at cfg's widths, so that engine runs every scene it can), or
// among all 18 when it is empty.
void draw_fuzz_hs_config(FuzzDraws& d, RasterConfig& cfg, const std::vector<HalfspaceParams>& among);

// The command-line options that reproduce `cfg` with `trirast compare` / `raster` (the half-space
// options only when they are not the defaults: hs_options()).
std::string config_options(const RasterConfig& cfg);
std::string hs_options(const RasterConfig& cfg);
// Parses what config_options() writes (and any subset of it); throws std::invalid_argument.
RasterConfig parse_config_options(const std::string& options);

// One engine that did not agree with the golden on a scene.
struct FuzzDisagreement {
  std::string engine;
  std::string what;             // "missing 3, extra 0 pixels", "threw: ...", "span out of the viewport ..."
  std::vector<uint32_t> tris;   // scene indices of the triangles involved (empty: unknown)
};

// Runs the golden and every engine in `engines` (golden entries skipped) on the scene and returns
// the engines that differ from the golden pixel for pixel, throw, or emit spans outside the
// viewport. An engine built for fewer configurations (the rtl: one set of widths) says so by
// throwing std::invalid_argument before it runs (tb/improved/improved_rtl_engine.hpp); it is then listed in
// `skipped`, not counted as a disagreement. A SetupError propagates (the scene is bad, not an
// engine). `cpu_seconds`, when given, gets each entry of `engines` its run's process CPU time
// (a "golden" entry: the golden's run with the scene's set-up; others: the run and the check).
std::vector<FuzzDisagreement> check_engines(const std::vector<InputTriangle>& tris,
                                            const RasterConfig& cfg,
                                            const std::vector<const EngineInfo*>& engines,
                                            uint64_t* golden_pixels = nullptr,
                                            std::vector<std::string>* skipped = nullptr,
                                            std::vector<double>* cpu_seconds = nullptr);

// Cuts a disagreeing scene down: the triangles the disagreement names, if those alone still
// disagree for the same engine; else each triangle alone; else the whole scene.
std::vector<InputTriangle> reduce_scene(const std::vector<InputTriangle>& tris,
                                        const RasterConfig& cfg, const EngineInfo& engine,
                                        const FuzzDisagreement& found);

// The reproducer file: a '#' header naming the engines, the configuration (a "# config:" line
// that parse_reproducer_config reads back), the command that replays it and `note`, then one
// triangle per line with coordinates printed so that they read back bit for bit. The replay
// command names the file `scene_path` (trirast fuzz: the path it writes, so the line runs as
// written from the fuzz run's folder; the libFuzzer target: THIS_FILE, its crash file's name).
// `unread`: options (with their values) the replay leaves out, as none of its engines reads
// them (trirast refuses those); the "# config:" line keeps them.
std::string format_reproducer(const std::vector<InputTriangle>& tris, const RasterConfig& cfg,
                              const std::vector<std::string>& engines, const std::string& note,
                              const std::string& scene_path = "THIS_FILE",
                              const std::vector<std::string>& unread = {});
// The replay command of a reproducer: trirast compare on scene_path with its engines and options
// (those in `unread` left out).
std::string replay_command(const RasterConfig& cfg, const std::vector<std::string>& engines,
                           const std::string& scene_path,
                           const std::vector<std::string>& unread = {});
// The configuration of a reproducer's "# config:" line (defaults when there is none).
RasterConfig parse_reproducer_config(const std::string& text);

}  // namespace trirast
