#include "post/colour.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace pdq::post {
namespace {

// Piecewise-linear interpolation between equally spaced stops.
template <std::size_t N>
Rgb ramp(const std::array<Rgb, N>& stops, double t) {
  if (!(t > 0)) return stops.front();  // also NaN
  if (t >= 1) return stops.back();
  const double u = t * (N - 1);
  const std::size_t k = std::min(static_cast<std::size_t>(u), N - 2);
  const double f = u - k;
  const Rgb &a = stops[k], &b = stops[k + 1];
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

constexpr std::array<Rgb, 4> kDamage{
    {{1.0, 0.92, 0.0}, {1.0, 0.55, 0.0}, {0.85, 0.0, 0.0}, {0.0, 0.0, 0.0}}};
// Samples of the viridis colour map at 0, 1/6, ..., 1.
constexpr std::array<Rgb, 7> kViridis{{{0.267, 0.005, 0.329},
                                       {0.267, 0.224, 0.514},
                                       {0.190, 0.407, 0.556},
                                       {0.128, 0.567, 0.551},
                                       {0.208, 0.719, 0.473},
                                       {0.565, 0.843, 0.262},
                                       {0.993, 0.906, 0.144}}};
constexpr std::array<Rgb, 10> kSeries{{{0.122, 0.467, 0.706},
                                       {0.839, 0.153, 0.157},
                                       {0.173, 0.627, 0.173},
                                       {1.000, 0.498, 0.055},
                                       {0.580, 0.404, 0.741},
                                       {0.549, 0.337, 0.294},
                                       {0.890, 0.467, 0.761},
                                       {0.498, 0.498, 0.498},
                                       {0.737, 0.741, 0.133},
                                       {0.090, 0.745, 0.812}}};

}  // namespace

Rgb damageColour(double omega) { return ramp(kDamage, omega); }
Rgb valueColour(double t) { return ramp(kViridis, t); }
Rgb seriesColour(std::size_t k) { return kSeries[k % kSeries.size()]; }

}  // namespace pdq::post
