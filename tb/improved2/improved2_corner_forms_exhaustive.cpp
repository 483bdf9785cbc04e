// The improved2 unit's two corner forms against each other over every input at reduced widths
// (tb/improved2/improved2_corner_forms_exhaustive.sh builds this with the package of a reduced
// configuration and improved2_corner_forms_exhaustive_tb.sv; docs/formal.md, "Not proven, and
// why", the improved2 corner unit's two forms). For every triangle (every vertex coordinate),
// every corner (x0, y0), the serial units are driven as rtl/improved2/trirast_improved2_top.sv
// drives its corner unit:
//   * a first run alone (a tiny box: the next triangle's first start follows), then
//   * for every Xmax with x0 + Xmax inside the pixel range and every edge mask: a first run
//     (all three edges), then a second run at x1 = x0 + Xmax for the edges of the mask.
// A start comes in the first cycle the unit is not busy; between starts, and at a second start,
// the triangle's inputs (vertices, A, B, A + B, x0, y0) carry another triangle's values (the
// corner stage's inputs move on), and Xmax and the bias carry other values except where the unit
// reads them. When a unit is no longer busy after a start, for both bias values of every edge
// (biases 000 and 111: in both forms edge k's bias bit enters edge k's value only, so the other
// six combinations add no case), its values must equal the products form's on the triangle of
// the last first start (at x1 for the edges of the last second run), and its far-from-0 flags
// must keep the direct 2x2 test's contract on that value E: far: |E| >= 2^(F+CoefBits) and
// fneg = E < 0; not far: |E| < 2^(F+CoefBits+3). A unit still busy after its most digits is an
// error too.
// With --random N: N random cases instead (a wider package, where every case is too many).
// Prints one line per difference (the first few) and the summary
//   improved2_corner_forms_exhaustive: N errors (...)
// exit 0 when N is 0 and the cases reached what the comparison needs (second runs, several digits),
// else 1.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>

#include "Vimproved2_corner_forms_exhaustive_tb.h"
#include "verilated.h"

namespace {

constexpr const char* kName = "improved2_corner_forms_exhaustive";

struct Widths {
  int vertex, frac, coef, edge, pix, box;
};

struct Triangle {
  uint64_t vx, vy;   // three P-bit coordinates each, vertex k at bits k*P
  unsigned x0, y0;
};

int64_t sign_extend(uint64_t v, int bits) {
  const uint64_t m = uint64_t{1} << (bits - 1);
  v &= (uint64_t{1} << bits) - 1;
  return static_cast<int64_t>(v ^ m) - static_cast<int64_t>(m);
}

class CornerForms {
 public:
  CornerForms(std::unique_ptr<Vimproved2_corner_forms_exhaustive_tb> top, long max_errors)
      : t_(std::move(top)), max_errors_(max_errors) {
    t_->eval();
    w_ = {t_->vertex_bits_o, t_->frac_bits_o, t_->coef_bits_o, t_->edge_bits_o, t_->pix_bits_o,
          t_->box_bits_o};
    // The most digits of a serial operand (P + 2 signed bits): radix 16 and radix 4.
    most_digits_[0] = (w_.vertex + 2 + 3) / 4;
    most_digits_[1] = (w_.vertex + 2 + 1) / 2;
  }

  const Widths& widths() const { return w_; }
  void final() { t_->final(); }
  bool stopped() const { return errors_ >= max_errors_; }

  void reset() {
    t_->clk_i = 0;
    t_->rst_ni = 0;
    t_->start_i = 0;
    t_->eval();
    clock();
    t_->rst_ni = 1;
    t_->eval();
  }

  // A first run (all three edges) on tri; then, when mask >= 0, a second run at x0 + xmax for
  // the edges of mask.
  void runs(const Triangle& tri, int mask, unsigned xmax) {
    held_ = tri;
    start(tri, /*second=*/false, 7, junk_box());
    t_->ref_vx_i = tri.vx;
    t_->ref_vy_i = tri.vy;
    t_->ref_x0_i = tri.x0;
    t_->ref_y0_i = tri.y0;
    t_->ref_x1_i = tri.x0;
    t_->ref_x1sel_i = 0;
    finish(-1, 0);
    ++first_runs_;
    if (mask < 0) return;
    start(other(tri), /*second=*/true, static_cast<unsigned>(mask), xmax);
    t_->ref_x1_i = tri.x0 + xmax;
    t_->ref_x1sel_i = static_cast<unsigned>(mask);
    finish(mask, xmax);
    ++second_runs_;
  }

  // need_wide: the cases must also reach radix-16 operands of two digits and far values.
  int report(bool need_wide) const {
    const bool reached = second_runs_ > 0 && digits_seen_[1] > 1 &&
                         (!need_wide || (digits_seen_[0] > 1 && far_seen_ > 0));
    std::printf("%s: %ld errors (P = %d, F = %d, PixBits = %d, BoxBits = %d: %ld first runs, "
                "%ld second runs, %ld comparisons of the three edges' values (both serial forms, "
                "biases 000 and 111); radix 16 took up to %d digits, radix 4 up to %d; far flags "
                "set in %ld edge checks)\n",
                kName, errors_, w_.vertex, w_.frac, w_.pix, w_.box, first_runs_, second_runs_,
                checks_, digits_seen_[0], digits_seen_[1], far_seen_);
    if (!reached)
      std::printf("%s: the cases fell short (a second run, radix-4 operands of two digits%s): "
                  "the comparison says too little\n", kName,
                  need_wide ? ", radix-16 operands of two digits, a far value" : "");
    return errors_ == 0 && reached ? 0 : 1;
  }

 private:
  void clock() {
    t_->clk_i = 1;
    t_->eval();
    t_->clk_i = 0;
    t_->eval();
  }

  // Values a triangle's inputs carry when the unit must not read them: every bit flipped.
  Triangle other(const Triangle& tri) const {
    const uint64_t vmask = (uint64_t{1} << (3 * w_.vertex)) - 1;
    const unsigned pmask = (1u << w_.pix) - 1;
    return {~tri.vx & vmask, ~tri.vy & vmask, ~tri.x0 & pmask, ~tri.y0 & pmask};
  }
  unsigned junk_box() const { return (1u << w_.box) - 1; }

  void drive_triangle(const Triangle& tri) {
    t_->vx_i = tri.vx;
    t_->vy_i = tri.vy;
    t_->x0_i = tri.x0;
    t_->y0_i = tri.y0;
  }

  void start(const Triangle& tri, bool second, unsigned run, unsigned xmax) {
    drive_triangle(tri);
    t_->start_i = 1;
    t_->second_i = second;
    t_->run_i = run;
    t_->xmax_i = xmax;
    t_->bias_i = 5;
    t_->eval();
    clock();
    t_->start_i = 0;
    t_->second_i = 0;
    t_->run_i = 0;
    drive_triangle(other(held_));
    t_->xmax_i = ~xmax & junk_box();
    t_->bias_i = 2;
    t_->eval();
  }

  // Clocks until both serial units are idle, checking each in the first cycle it is.
  void finish(int mask, unsigned xmax) {
    bool done[2] = {false, false};
    for (int cycle = 1;; ++cycle) {
      const bool busy[2] = {t_->busy16_o != 0, t_->busy4_o != 0};
      for (int u = 0; u < 2; ++u) {
        if (done[u] || busy[u]) continue;
        done[u] = true;
        // cycle - 1 clock edges after the start's: one digit each
        if (cycle - 1 > digits_seen_[u]) digits_seen_[u] = cycle - 1;
        check(u, mask, xmax);
      }
      if (done[0] && done[1]) return;
      for (int u = 0; u < 2; ++u) {
        if (!done[u] && cycle > most_digits_[u]) {
          error(u, mask, xmax, -1, "still busy after the most digits");
          done[u] = true;
        }
      }
      if (done[0] && done[1]) return;
      clock();
    }
  }

  void check(int u, int mask, unsigned xmax) {
    const int eb = w_.edge;
    const int64_t far_min = int64_t{1} << (w_.frac + w_.coef);
    const int64_t near_max = int64_t{1} << (w_.frac + w_.coef + 3);
    for (unsigned bias : {0u, 7u}) {
      t_->bias_i = bias;
      t_->eval();
      ++checks_;
      const uint64_t el = u == 0 ? t_->el16_o : t_->el4_o;
      const unsigned far = u == 0 ? t_->far16_o : t_->far4_o;
      const unsigned fneg = u == 0 ? t_->fneg16_o : t_->fneg4_o;
      const uint64_t ref = t_->ref_el_o;
      for (int k = 0; k < 3; ++k) {
        const int64_t got = sign_extend(el >> (k * eb), eb);
        const int64_t want = sign_extend(ref >> (k * eb), eb);
        const int64_t mag = want < 0 ? -want : want;
        const bool f = (far >> k) & 1, n = (fneg >> k) & 1;
        char what[160];
        if (got != want) {
          std::snprintf(what, sizeof what, "serial E %lld, products E %lld (bias %u)",
                        static_cast<long long>(got), static_cast<long long>(want), bias);
          error(u, mask, xmax, k, what);
        } else if (f && (mag < far_min || n != (want < 0))) {
          std::snprintf(what, sizeof what, "far with fneg %d but E = %lld (bias %u)", n,
                        static_cast<long long>(want), bias);
          error(u, mask, xmax, k, what);
        } else if (!f && mag >= near_max) {
          std::snprintf(what, sizeof what, "not far but E = %lld (bias %u)",
                        static_cast<long long>(want), bias);
          error(u, mask, xmax, k, what);
        }
        if (f) ++far_seen_;
      }
    }
  }

  void error(int u, int mask, unsigned xmax, int edge, const char* what) {
    if (errors_ < 10) {
      const int p = w_.vertex;
      char run[64];
      if (mask < 0)
        std::snprintf(run, sizeof run, "first run");
      else
        std::snprintf(run, sizeof run, "second run (mask %d%d%d, Xmax %u)", (mask >> 2) & 1,
                      (mask >> 1) & 1, mask & 1, xmax);
      std::printf("%s: radix %d, %s, edge %d: %s; triangle (%lld, %lld) (%lld, %lld) (%lld, %lld), "
                  "x0 %u, y0 %u\n",
                  kName, u == 0 ? 16 : 4, run, edge, what,
                  static_cast<long long>(sign_extend(held_.vx, p)),
                  static_cast<long long>(sign_extend(held_.vy, p)),
                  static_cast<long long>(sign_extend(held_.vx >> p, p)),
                  static_cast<long long>(sign_extend(held_.vy >> p, p)),
                  static_cast<long long>(sign_extend(held_.vx >> 2 * p, p)),
                  static_cast<long long>(sign_extend(held_.vy >> 2 * p, p)), held_.x0, held_.y0);
    }
    ++errors_;
  }

  std::unique_ptr<Vimproved2_corner_forms_exhaustive_tb> t_;
  long max_errors_;
  Widths w_{};
  int most_digits_[2] = {0, 0};
  Triangle held_{};
  long errors_ = 0, first_runs_ = 0, second_runs_ = 0, checks_ = 0, far_seen_ = 0;
  int digits_seen_[2] = {0, 0};
};

}  // namespace

// A random coordinate of P bits: uniform, an extreme (-2^(P-1) or 2^(P-1) - 1), or small.
uint64_t random_coordinate(std::mt19937_64& rng, int p) {
  const uint64_t mask = (uint64_t{1} << p) - 1;
  switch (rng() % 4) {
    case 0: return (rng() & 1) ? uint64_t{1} << (p - 1) : mask >> 1;   // -2^(P-1), 2^(P-1) - 1
    case 1: return ((rng() % 16) - 8) & mask;     // -8 .. 7
    default: return rng() & mask;
  }
}

int main(int argc, char** argv) {
  long max_errors = 100;   // stop after this many differences (--max-errors N)
  long random_cases = 0;   // --random N: N random cases instead of every case
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--max-errors") == 0 && i + 1 < argc) {
      max_errors = std::atol(argv[++i]);
    } else if (std::strcmp(argv[i], "--random") == 0 && i + 1 < argc) {
      random_cases = std::atol(argv[++i]);
    } else {
      std::fprintf(stderr, "%s: usage: %s [--max-errors N] [--random N]\n", kName, argv[0]);
      return 2;
    }
  }
  auto ctx = std::make_unique<VerilatedContext>();
  CornerForms forms(std::make_unique<Vimproved2_corner_forms_exhaustive_tb>(ctx.get()),
                    max_errors);
  const Widths& w = forms.widths();
  if (3 * w.edge > 64 || (random_cases == 0 && 6 * w.vertex > 30)) {
    std::fprintf(stderr, "%s: P = %d is too wide for this driver (every case: at most 5; "
                 "--random: at most 10)\n", kName, w.vertex);
    return 2;
  }
  forms.reset();
  const uint64_t coord_mask = (uint64_t{1} << (3 * w.vertex)) - 1;
  const unsigned pixels = 1u << w.pix, boxes = 1u << w.box;
  if (random_cases > 0) {
    // Random cases (a fixed seed): the triangle, corner, Xmax and mask drawn; one run in nine a
    // first run alone.
    std::mt19937_64 rng(1);
    for (long c = 0; c < random_cases && !forms.stopped(); ++c) {
      Triangle tri{0, 0, static_cast<unsigned>(rng() % pixels),
                   static_cast<unsigned>(rng() % pixels)};
      for (int k = 0; k < 3; ++k) {
        tri.vx |= random_coordinate(rng, w.vertex) << (k * w.vertex);
        tri.vy |= random_coordinate(rng, w.vertex) << (k * w.vertex);
      }
      const unsigned room = std::min(pixels - 1 - tri.x0, boxes - 1);
      const int mask = static_cast<int>(rng() % 9) - 1;
      forms.runs(tri, mask, static_cast<unsigned>(rng() % (room + 1)));
    }
    forms.final();
    return forms.report(/*need_wide=*/true);
  }
  for (uint64_t v = 0; v < (uint64_t{1} << (6 * w.vertex)) && !forms.stopped(); ++v) {
    for (unsigned y0 = 0; y0 < pixels; ++y0) {
      for (unsigned x0 = 0; x0 < pixels; ++x0) {
        const Triangle tri{v & coord_mask, v >> (3 * w.vertex), x0, y0};
        forms.runs(tri, -1, 0);
        for (unsigned xmax = 0; xmax < boxes && x0 + xmax < pixels; ++xmax)
          for (int mask = 0; mask < 8; ++mask) forms.runs(tri, mask, xmax);
      }
    }
  }
  forms.final();
  return forms.report(/*need_wide=*/false);
}
