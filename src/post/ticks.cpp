#include "post/ticks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace pdq::post {

Ticks niceTicks(double lo, double hi, int target) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0, hi = 1;
  if (lo > hi) std::swap(lo, hi);
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) {
    const double pad = lo == 0 ? 1.0 : 0.1 * std::abs(lo);
    lo -= pad;
    hi += pad;
  }
  const double raw = (hi - lo) / std::max(target, 1);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * mag;
  for (double m : {1.0, 2.0, 5.0})
    if (raw <= m * mag) {
      step = m * mag;
      break;
    }
  Ticks t{std::floor(lo / step) * step, std::ceil(hi / step) * step, step, {}};
  const long n = std::lround((t.hi - t.lo) / step);
  for (long k = 0; k <= n; ++k) {
    double v = t.lo + k * step;
    if (std::abs(v) < 1e-9 * step) v = 0;  // no "-0" or 1e-17 labels
    t.values.push_back(v);
  }
  return t;
}

std::string tickLabel(double value, double step) {
  const double big = std::max(std::abs(value), step);
  if (value != 0 && (big >= 1e5 || big < 1e-3)) {
    const int digits = std::max(0, static_cast<int>(std::floor(std::log10(big))) -
                                       static_cast<int>(std::floor(std::log10(step))));
    return fmt::format("{:.{}e}", value, std::min(digits, 6));
  }
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  return fmt::format("{:.{}f}", value, decimals);
}

}  // namespace pdq::post
