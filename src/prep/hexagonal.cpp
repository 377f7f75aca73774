#include "prep/hexagonal.hpp"

#include <cmath>
#include <stdexcept>

#include "engine/memory.hpp"
#include "prep/lattice.hpp"

namespace pdq::prep {

HexOrientation hexOrientation(const std::string& name) {
  if (name == "x") return HexOrientation::BondsAlongX;
  if (name == "y") return HexOrientation::BondsAlongY;
  throw std::invalid_argument("lattice orientation must be \"x\" or \"y\", not \"" + name + "\"");
}

double hexPitch(double s) { return std::sqrt(3.0) / 2 * s; }

std::vector<std::array<double, 2>> hexagonalRectangle(double lx, double ly, double s,
                                                      HexOrientation o, double x0, double y0) {
  if (!(s > 0) || !(lx >= 0) || !(ly >= 0))
    throw std::invalid_argument("hexagonal lattice needs s > 0 and a non-negative size");
  const bool alongX = o == HexOrientation::BondsAlongX;
  // Work in (along, across) coordinates: `along` the bonded rows, `across` between them.
  const double along = alongX ? lx : ly, across = alongX ? ly : lx;
  const double p = hexPitch(s), tol = 1e-9 * s;
  checkParticleCount((across / p + 1) * (along / s + 1), sizeof(std::array<double, 2>),
                     "the hexagonal lattice");
  std::vector<std::array<double, 2>> pts;
  for (long r = 0; r * p <= across + tol; ++r) {
    const double shift = (r % 2) ? s / 2 : 0.0;
    for (long k = 0; shift + k * s <= along + tol; ++k) {
      const double u = shift + k * s, v = r * p;
      pts.push_back(alongX ? std::array<double, 2>{x0 + u, y0 + v}
                           : std::array<double, 2>{x0 + v, y0 + u});
    }
  }
  return pts;
}

double hexagonalRectangleCount(double lx, double ly, double s, HexOrientation o) {
  const bool alongX = o == HexOrientation::BondsAlongX;
  const double along = alongX ? lx : ly, across = alongX ? ly : lx, tol = 1e-9 * s;
  const double rows = latticeSteps(across + tol, 0, hexPitch(s));
  // Even rows start at 0 along the row, odd ones at s/2.
  return std::ceil(rows / 2) * latticeSteps(along + tol, 0, s) +
         std::floor(rows / 2) * latticeSteps(along + tol, s / 2, s);
}

}  // namespace pdq::prep
