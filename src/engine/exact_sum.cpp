#include "engine/exact_sum.hpp"

#include <cmath>
#include <cstring>
#include <limits>

namespace pdq {

void ExactSum::add(double v) {
  if (!std::isfinite(v)) {
    special_[std::isnan(v) ? 0 : (v > 0 ? 1 : 2)]++;
    return;
  }
  if (v == 0.0) return;
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  const bool negative = bits >> 63;
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t mant = bits & ((std::uint64_t{1} << 52) - 1);
  int shift;  // position of the mantissa's lowest bit, counted from 2^-1074
  if (biased == 0) {
    shift = 0;  // subnormal
  } else {
    mant |= std::uint64_t{1} << 52;
    shift = biased - 1;
  }
  const int k = shift / 32, o = shift % 32;
  // mant << o has at most 84 bits: split it over three 32-bit limbs.
  const unsigned __int128 wide = static_cast<unsigned __int128>(mant) << o;
  const std::int64_t parts[3] = {static_cast<std::int64_t>(wide & 0xffffffffu),
                                 static_cast<std::int64_t>((wide >> 32) & 0xffffffffu),
                                 static_cast<std::int64_t>(wide >> 64)};
  for (int p = 0; p < 3 && k + p < kLimbs; ++p) limb_[k + p] += negative ? -parts[p] : parts[p];
  if (++pending_ >= (std::int64_t{1} << 29)) normalize();
}

void ExactSum::normalize() {
  for (int k = 0; k + 1 < kLimbs; ++k) {
    const std::int64_t carry = limb_[k] >> 32;  // arithmetic shift: floor division
    limb_[k] -= carry * (std::int64_t{1} << 32);
    limb_[k + 1] += carry;
  }
  pending_ = 0;
}

ExactSum& ExactSum::operator+=(const ExactSum& o) {
  normalize();
  ExactSum other = o;
  other.normalize();
  for (int k = 0; k < kLimbs; ++k) limb_[k] += other.limb_[k];
  for (int s = 0; s < 3; ++s) special_[s] += other.special_[s];
  normalize();
  return *this;
}

double ExactSum::value() const {
  if (special_[0] || (special_[1] && special_[2])) return std::numeric_limits<double>::quiet_NaN();
  if (special_[1]) return std::numeric_limits<double>::infinity();
  if (special_[2]) return -std::numeric_limits<double>::infinity();
  ExactSum n = *this;
  n.normalize();
  const bool negative = n.limb_[kLimbs - 1] < 0;
  if (negative) {  // two's complement negation of the multi-limb integer
    std::int64_t borrow = 0;
    for (int k = 0; k < kLimbs; ++k) {
      std::int64_t x = -n.limb_[k] - borrow;
      borrow = 0;
      if (k + 1 < kLimbs && x < 0) {
        x += std::int64_t{1} << 32;
        borrow = 1;
      }
      n.limb_[k] = x;
    }
  }
  int top = kLimbs - 1;
  while (top > 0 && n.limb_[top] == 0) --top;
  // The top three limbs carry at least 65 significant bits; the lower ones only decide
  // the rounding of ties, so fold them into a sticky bit.
  unsigned __int128 m = 0;
  int low = top >= 2 ? top - 2 : 0;
  for (int k = top; k >= low; --k) m = (m << 32) | static_cast<std::uint64_t>(n.limb_[k]);
  bool sticky = false;
  for (int k = 0; k < low; ++k) sticky |= n.limb_[k] != 0;
  // Round m (with sticky) to 53 bits by hand so the result is correctly rounded.
  int bitsInM = 0;
  for (unsigned __int128 t = m; t; t >>= 1) ++bitsInM;
  int exponent = 32 * low - 1074;
  if (bitsInM > 53) {
    const int drop = bitsInM - 53;
    const unsigned __int128 rem = m & ((static_cast<unsigned __int128>(1) << drop) - 1);
    const unsigned __int128 half = static_cast<unsigned __int128>(1) << (drop - 1);
    m >>= drop;
    exponent += drop;
    if (rem > half || (rem == half && (sticky || (m & 1)))) ++m;
  }
  const double r = std::ldexp(static_cast<double>(static_cast<std::uint64_t>(m)), exponent);
  return negative ? -r : r;
}

}  // namespace pdq
