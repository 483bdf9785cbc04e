#include "improved/improved_adder_divider.hpp"

#include <stdexcept>
#include <string>

namespace trirast {

ImprovedAdderDivider::ImprovedAdderDivider(int quotient_bits, int numerator_bits, int divisor_bits)
    : q_bits_(quotient_bits), n_bits_(numerator_bits), d_bits_(divisor_bits) {
  // The shifted divisor d << (Q-1) and the numerator must both fit the int64 model.
  if (q_bits_ < 1 || n_bits_ > 63 || d_bits_ + q_bits_ > 62)
    throw std::invalid_argument("ImprovedAdderDivider: widths too large for the model");
}

ImprovedAdderDivider::ImprovedAdderDivider(const RasterConfig& cfg)
    : ImprovedAdderDivider(unit_widths(cfg).quotient, unit_widths(cfg).numerator,
                   unit_widths(cfg).remainder) {}

DivideResult ImprovedAdderDivider::divide(int64_t n, int64_t d, uint32_t tri, const char* what,
                                  int quotient_bits) const {
  const int q_bits = quotient_bits > 0 ? quotient_bits : q_bits_;
  if (q_bits > q_bits_)
    throw std::invalid_argument("ImprovedAdderDivider: " + std::to_string(q_bits) +
                                " quotient bits asked of a " + std::to_string(q_bits_) +
                                "-bit divider");
  // Ports: an unsigned numerator and a positive divisor of the configured widths.
  check_unsigned(n, n_bits_, tri, what, "divider numerator");
  check_unsigned(d, d_bits_, tri, what, "divider divisor");
  if (d == 0)
    throw std::invalid_argument("triangle " + std::to_string(tri) + ": " + what +
                                ": division by zero");
  DivideResult res{};
  // Saturation: the quotient needs more than q_bits bits iff n >> q_bits >= d (a compare).
  res.saturated = (n >> q_bits) >= d;
  // Restoring division, MSB first: bit k of q is set when d << k fits the partial remainder.
  int64_t rem = n;
  int64_t q = 0;
  for (int k = q_bits - 1; k >= 0; --k) {
    const int64_t trial = rem - (d << k);  // the adder: partial remainder minus shifted divisor
    const bool fits = trial >= 0;          // its sign bit is the quotient bit (inverted)
    if (fits) rem = trial;                 // restore (keep rem) when it did not fit
    q = (q << 1) | (fits ? 1 : 0);
    ++res.iterations;
  }
  res.quotient = q;
  res.remainder = rem;
  return res;
}

}  // namespace trirast
