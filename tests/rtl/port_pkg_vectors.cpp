// Writes triangles and what the CLI's setup (model/common/setup.cpp) forms from them, for the
// testbench of rtl/common/trirast_port_pkg.sv (tests/rtl/port_pkg_tb.sv, ctest rtl_port_pkg_*):
//   trirast_port_pkg_vectors OUT SUBPIXEL_BITS COORD_BITS COUNT SEED
// Line 1: "P CB EB S N" (the vertex, coefficient and edge-value widths of the configuration, S,
// the number of triangles). Then one triangle a line, every field in hex, two's complement at
// its width:
//   sx0 sx1 sx2 sy0 sy1 sy2   the vertices in 1/2^S pixel (P bits; as the CLI snaps them)
//   degenerate swapped        setup's verdict (area2 == 0) and whether it swapped v1 and v2
//   vx0 vx1 vx2 vy0 vy1 vy2   the ordered vertices in 1/2^F pixel (P bits)
//   a0 a1 a2 b0 b1 b2         A, B per edge (CB bits)
//   c0 c1 c2                  C per edge (EB bits)
//   bias                      bit k = 1: edge k's bias is -1
// A degenerate triangle has nothing else set up: its other fields are 0 and the testbench
// compares its flag alone.
// The triangles (seeded): a quarter anywhere in the coordinate range, a quarter small (vertices
// within 64 subpixels of a corner: many horizontal and vertical edges, both biases), a quarter of
// axis-aligned right triangles (top, left, bottom and right edges), the rest degenerate (a
// repeated vertex or three on a line); each in either orientation.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "common/config.hpp"
#include "common/setup.hpp"

namespace {

uint64_t field(int64_t v, int bits) {
  return bits >= 64 ? uint64_t(v) : uint64_t(v) & ((uint64_t(1) << bits) - 1);
}

int fail(const std::string& msg) {
  std::fprintf(stderr, "trirast_port_pkg_vectors: %s\n", msg.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6)
    return fail("usage: trirast_port_pkg_vectors OUT SUBPIXEL_BITS COORD_BITS COUNT SEED");
  trirast::RasterConfig cfg;
  cfg.subpixel_bits = std::atoi(argv[2]);
  cfg.coord_int_bits = std::atoi(argv[3]);
  cfg.width = cfg.height = int(std::min<int64_t>(cfg.coord_limit_px(), trirast::kMaxViewport));
  const long count = std::atol(argv[4]);
  const unsigned seed = unsigned(std::strtoul(argv[5], nullptr, 10));
  try {
    cfg.validate();
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  if (count < 1) return fail("COUNT '" + std::string(argv[4]) + "' is not a positive count");
  FILE* out = std::fopen(argv[1], "w");
  if (!out) return fail(std::string(argv[1]) + ": cannot write");

  const int P = cfg.vertex_bits(), CB = P + 1, EB = 2 * P + 2, S = cfg.subpixel_bits;
  const int64_t lim = cfg.coord_limit_px() << S;  // subpixel coordinates lie in [-lim, lim)
  std::mt19937_64 rng(seed);
  auto uni = [&](int64_t lo, int64_t hi) {  // [lo, hi]
    return std::uniform_int_distribution<int64_t>(lo, hi)(rng);
  };
  auto clamp = [&](int64_t v) { return std::max(-lim, std::min(lim - 1, v)); };
  std::fprintf(out, "%d %d %d %d %ld\n", P, CB, EB, S, count);
  for (long n = 0; n < count; ++n) {
    int64_t sx[3], sy[3];
    const int kind = int(n % 4);
    if (kind == 0) {
      for (int k = 0; k < 3; ++k) sx[k] = uni(-lim, lim - 1), sy[k] = uni(-lim, lim - 1);
    } else if (kind == 1) {
      const int64_t x0 = uni(-lim, lim - 1), y0 = uni(-lim, lim - 1);
      for (int k = 0; k < 3; ++k) sx[k] = clamp(x0 + uni(-64, 64)), sy[k] = clamp(y0 + uni(-64, 64));
    } else if (kind == 2) {
      const int64_t x0 = uni(-lim, lim - 1), y0 = uni(-lim, lim - 1);
      const int64_t x1 = clamp(x0 + uni(-4096, 4096)), y1 = clamp(y0 + uni(-4096, 4096));
      // The right angle at one of the four corners of the box (x0, y0)-(x1, y1).
      const int64_t cx[4] = {x0, x1, x1, x0}, cy[4] = {y0, y0, y1, y1};
      const int c = int(uni(0, 3));
      sx[0] = cx[c], sy[0] = cy[c];
      sx[1] = cx[(c + 1) % 4], sy[1] = cy[(c + 1) % 4];
      sx[2] = cx[(c + 3) % 4], sy[2] = cy[(c + 3) % 4];
    } else {
      sx[0] = uni(-lim / 2, lim / 2 - 1), sy[0] = uni(-lim / 2, lim / 2 - 1);
      const int64_t d = std::min<int64_t>(300, lim / 8);
      const int64_t dx = uni(-d, d), dy = uni(-d, d);
      const int64_t t1 = uni(0, 3), t2 = uni(-3, 3);
      sx[1] = sx[0] + t1 * dx, sy[1] = sy[0] + t1 * dy;
      sx[2] = sx[0] + t2 * dx, sy[2] = sy[0] + t2 * dy;
    }
    if (uni(0, 1)) std::swap(sx[1], sx[2]), std::swap(sy[1], sy[2]);

    trirast::InputTriangle in;
    for (int k = 0; k < 3; ++k) {
      in.x[k] = std::ldexp(double(sx[k]), -S);  // exact: an integer over a power of two
      in.y[k] = std::ldexp(double(sy[k]), -S);
    }
    trirast::TriangleSetup t{};
    const char* why = nullptr;
    bool ok = false;
    try {
      ok = trirast::setup_triangle(in, uint32_t(n), cfg, t, &why);
    } catch (const std::exception& e) {
      return fail(e.what());
    }
    if (!ok && std::string(why) != "degenerate")
      return fail("triangle " + std::to_string(n) + ": setup says " + why);
    for (int k = 0; k < 3; ++k) std::fprintf(out, "%llx ", (unsigned long long)field(sx[k], P));
    for (int k = 0; k < 3; ++k) std::fprintf(out, "%llx ", (unsigned long long)field(sy[k], P));
    std::fprintf(out, "%d %d", ok ? 0 : 1, ok && t.swapped ? 1 : 0);
    auto put = [&](auto get, int bits) {
      for (int k = 0; k < 3; ++k)
        std::fprintf(out, " %llx", ok ? (unsigned long long)field(get(k), bits) : 0ull);
    };
    put([&](int k) { return t.v[k].x; }, P);
    put([&](int k) { return t.v[k].y; }, P);
    put([&](int k) { return t.edge[k].A; }, CB);
    put([&](int k) { return t.edge[k].B; }, CB);
    put([&](int k) { return t.edge[k].C; }, EB);
    int bias = 0;
    for (int k = 0; k < 3; ++k) bias |= (ok && t.edge[k].bias != 0) << k;
    std::fprintf(out, " %x\n", bias);
  }
  if (std::fclose(out) != 0) return fail(std::string(argv[1]) + ": write failed");
  return 0;
}
