#pragma once
// The Lennard-Jones pair law with a cut-off rc,
//     U(r) = 4 eps [ (sigma/r)^12 - (sigma/r)^6 ],   F(r) = -dU/dr,
// truncated in one of three ways:
//   none    U(r) for r < rc, 0 beyond (energy and force jump at rc)
//   energy  U(r) - U(rc): the energy is continuous, the force still jumps
//   force   U(r) - U(rc) + (r - rc) F(rc): energy and force both go smoothly to zero
//           (the force-shifted or "smooth" cut-off)
// forceOverR(r2) is F(r)/r, so the force on i from j is forceOverR(r2) * (x_i - x_j).
#include <cmath>

namespace pdq::lj {

enum class Shift { None, Energy, Force };

struct PairLJ {
  PairLJ() = default;
  PairLJ(double epsilon, double sigma, double cutoff, Shift s)
      : shift(s), rc(cutoff), rc2(cutoff * cutoff) {
    const double s6 = std::pow(sigma, 6);
    u12 = 4 * epsilon * s6 * s6;
    u6 = 4 * epsilon * s6;
    f12 = 48 * epsilon * s6 * s6;
    f6 = 24 * epsilon * s6;
    const double ir6 = 1 / (rc2 * rc2 * rc2);
    uc = (u12 * ir6 - u6) * ir6;
    fc = (f12 * ir6 - f6) * ir6 / rc;
  }

  // F(r)/r for r < rc (callers test r2 < rc2).
  double forceOverR(double r2) const {
    const double ir2 = 1 / r2;
    const double ir6 = ir2 * ir2 * ir2;
    const double f = (f12 * ir6 - f6) * ir6 * ir2;
    return shift == Shift::Force ? f - fc / std::sqrt(r2) : f;
  }
  double energy(double r2) const {
    const double ir2 = 1 / r2;
    const double ir6 = ir2 * ir2 * ir2;
    const double u = (u12 * ir6 - u6) * ir6;
    switch (shift) {
      case Shift::None:
        return u;
      case Shift::Energy:
        return u - uc;
      case Shift::Force:
        return u - uc + (std::sqrt(r2) - rc) * fc;
    }
    return u;
  }

  Shift shift = Shift::Energy;
  double rc = 0, rc2 = 0;
  double u12 = 0, u6 = 0, f12 = 0, f6 = 0;  // 4 eps s^12, 4 eps s^6, 48 eps s^12, 24 eps s^6
  double uc = 0, fc = 0;                    // U(rc) and F(rc)
};

}  // namespace pdq::lj
