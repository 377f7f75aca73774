#include "prep/rebar.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/memory.hpp"

namespace pdq::prep {

double Bar::area() const { return std::numbers::pi * diameter * diameter / 4; }
double Bar::secondMoment() const { return std::numbers::pi * std::pow(diameter, 4) / 64; }

std::vector<std::array<double, 2>> barPoints(const Bar& bar, double s) {
  if (!(s > 0) || !(bar.diameter > 0))
    throw std::invalid_argument("a bar needs a positive diameter and spacing");
  const double len = std::hypot(bar.x1 - bar.x0, bar.y1 - bar.y0);
  checkParticleCount(len / s + 1, sizeof(std::array<double, 2>), "a bar");
  const long segments = std::max(1L, static_cast<long>(std::ceil(len / s - 1e-9)));
  std::vector<std::array<double, 2>> pts;
  for (long k = 0; k <= segments; ++k) {
    const double f = static_cast<double>(k) / segments;
    pts.push_back({bar.x0 + f * (bar.x1 - bar.x0), bar.y0 + f * (bar.y1 - bar.y0)});
  }
  return pts;
}

Bar longitudinalBar(double xStart, double xEnd, double y0, double centroid, double diameter) {
  return {xStart, y0 + centroid, xEnd, y0 + centroid, diameter};
}

std::vector<Bar> stirrups(double first, double spacing, double xMax, double yBottom, double yTop,
                          double diameter) {
  if (!(spacing > 0)) throw std::invalid_argument("stirrup spacing must be positive");
  checkParticleCount((xMax - first) / spacing + 1, sizeof(Bar), "the stirrups");
  std::vector<Bar> bars;
  for (long k = 0; first + k * spacing <= xMax + 1e-9 * spacing; ++k)
    bars.push_back({first + k * spacing, yBottom, first + k * spacing, yTop, diameter});
  return bars;
}

}  // namespace pdq::prep
