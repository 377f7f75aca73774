#pragma once
// An exact accumulator for sums of doubles (a "superaccumulator"): every double is added
// without rounding into fixed-point limbs spanning the whole double range, so the total
// is the same bits whatever the order of the additions and however they are split over
// ranks and threads. Global energies, loads and stopping criteria go through it, which is
// what makes them bitwise identical on any number of ranks.
#include <array>
#include <cstdint>

namespace pdq {

class ExactSum {
 public:
  static constexpr int kLimbs = 68;  // 32 bits each, bit 0 weighs 2^-1074

  void add(double v);
  ExactSum& operator+=(const ExactSum& o);
  // The total, rounded once to the nearest double (NaN if a NaN or +Inf and -Inf were added).
  double value() const;
  // Carries so every limb but the top lies in [0, 2^32); required before limbs are summed
  // across ranks (the engine does this) so that the integer sums cannot overflow.
  void normalize();
  std::array<std::int64_t, kLimbs>& limbs() { return limb_; }
  std::array<std::int64_t, 3>& specials() { return special_; }  // NaN, +Inf, -Inf counts

 private:
  std::array<std::int64_t, kLimbs> limb_{};
  std::array<std::int64_t, 3> special_{};
  std::int64_t pending_ = 0;  // additions since the last normalize
};

}  // namespace pdq
