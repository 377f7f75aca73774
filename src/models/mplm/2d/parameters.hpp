#pragma once
// The parameters of mplm2d: the shared MPLM ones plus the thickness and the micropolar
// constants of the hexagonal lattice.
#include <cmath>
#include <string>

#include "models/mplm/2d/elastic_constants.hpp"
#include "models/mplm/common/parameters.hpp"

namespace pdq::mplm {

struct Parameters2d : Parameters {
  double thickness = 0.12;                  // t (m)
  std::string elasticity = "plane_stress";  // plane_stress | plane_strain | given
  ElasticConstants concrete;                // a, b in use

  void read(const Params& p);
  double concreteMass() const;  // ρ (√3/2) s² t
};

// α_t from the fracture energy G_F: cutting one row of interactions per unit crack length
// releases the area under the linear softening curve, G_F = 2 a ε_t² α_t / (√3 t), so
// α_t = √3 G_F t / (2 a ε_t²) (MPLM-NOTES; ≈ 27 for the thesis's data, which used 10).
inline double alphaFromFractureEnergy(double GF, double a, double t, double epsT) {
  return std::sqrt(3.0) * GF * t / (2 * a * epsT * epsT);
}

}  // namespace pdq::mplm
