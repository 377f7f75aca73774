#include "models/mplm/3d/elastic_constants.hpp"

#include <cmath>
#include <stdexcept>

namespace pdq::mplm3d {

ElasticConstants isotropicFcc(double E, double nu, double s) {
  if (!(nu >= 0 && nu < 0.25))
    throw std::domain_error(
        "the 3D lattice needs 0 <= poisson_ratio < 1/4 (else the bending or the "
        "second-neighbour stiffness is not positive)");
  const double k = (1 + nu) * (1 - 2 * nu), r2 = std::sqrt(2.0);
  ElasticConstants c;
  c.a = E * s * s / (2 * r2 * k);
  c.b = E * s * s * s * s * (1 - 4 * nu) / (24 * r2 * k);
  c.c = c.b / (1 + nu);
  c.a2 = E * s * s * nu / (2 * k);
  return c;
}

double alphaFromFractureEnergy(const ElasticConstants& k, double s, double GF, double epsT) {
  return GF * s / (epsT * epsT * (1.5 * std::sqrt(2.0) * k.a + 2 * k.a2));
}

}  // namespace pdq::mplm3d
