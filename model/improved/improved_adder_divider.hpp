// Stage 3 of the unit, `adder_divider`: a restoring divider shared by the three edges
// (docs/unit.md, section 3). One quotient bit per iteration, MSB first, Q iterations: each
// iteration compares the partial remainder with the divisor shifted to that bit and subtracts
// when it fits. A quotient that needs more than Q bits raises the saturation flag instead of
// wrapping.
#pragma once
#include <cstdint>

#include "common/unit_widths.hpp"

namespace trirast {

// The divider's output register.
struct DivideResult {
  int64_t quotient;   // q, Q bits unsigned (all ones when saturated)
  int64_t remainder;  // r = n - q*d, 0 <= r < d when not saturated
  bool saturated;     // n >= d * 2^Q: the true quotient does not fit Q bits
  int iterations;     // iterations the division took (Q, or the quotient_bits asked for)
};

class ImprovedAdderDivider {
 public:
  // quotient_bits = Q; numerator_bits and divisor_bits are the unsigned widths of the inputs.
  ImprovedAdderDivider(int quotient_bits, int numerator_bits, int divisor_bits);
  // The unit's divider: Q = box_bits + 1, numerator 2p + 2 bits, divisor p + F bits.
  explicit ImprovedAdderDivider(const RasterConfig& cfg);

  // n = q*d + r for n >= 0, d > 0. Throws WidthError (naming triangle `tri` and `what`) when an
  // input does not fit its port, std::invalid_argument when d == 0.
  // `quotient_bits` (1..Q) runs a shorter division for a small box: the quotient saturates at
  // 2^quotient_bits instead of 2^Q; 0 means Q.
  DivideResult divide(int64_t n, int64_t d, uint32_t tri, const char* what,
                      int quotient_bits = 0) const;

  int quotient_bits() const { return q_bits_; }
  int iterations_per_division() const { return q_bits_; }

 private:
  int q_bits_;
  int n_bits_;
  int d_bits_;
};

}  // namespace trirast
