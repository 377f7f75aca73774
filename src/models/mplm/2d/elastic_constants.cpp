#include "models/mplm/2d/elastic_constants.hpp"

#include <cmath>
#include <stdexcept>

namespace pdq::mplm {

ElasticConstants planeStress(double E, double nu, double s, double t) {
  if (!(nu > -1 && nu < 1.0 / 3))
    throw std::domain_error("plane stress needs -1 < poisson_ratio < 1/3 (else b <= 0)");
  const double r3 = std::sqrt(3.0);
  return {E * s * t / (r3 * (1 - nu)),
          E * s * s * s * (1 - 3 * nu) * t / (12 * r3 * (1 - nu * nu))};
}

ElasticConstants planeStrain(double E, double nu, double s, double t) {
  if (!(nu > -1 && nu < 0.25))
    throw std::domain_error("plane strain needs -1 < poisson_ratio < 1/4 (else b <= 0)");
  const double r3 = std::sqrt(3.0);
  const double c = (1 + nu) * (1 - 2 * nu);
  return {E * s * t / (r3 * c), E * s * s * s * t * (1 - 4 * nu) / (12 * r3 * c)};
}

ElasticConstants forContinuum(const std::string& form, double E, double nu, double s, double t) {
  if (form == "plane_stress") return planeStress(E, nu, s, t);
  if (form == "plane_strain") return planeStrain(E, nu, s, t);
  throw std::domain_error("unknown elasticity form '" + form + "'");
}

}  // namespace pdq::mplm
