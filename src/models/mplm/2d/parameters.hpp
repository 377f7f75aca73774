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

// α_t from the fracture energy G_F. Under linear softening an interaction (axial force
// a·strain, length s) dissipates ½ a s ε_t² α_t as it breaks. A line of unit normal n is
// crossed, per unit length, by (2/(√3 s²)) Σ|d·n| interactions (the three bond directions
// d); for n along a bond Σ|d·n| = 2s, so a crack normal to a bond dissipates per unit area
// G_F = 2 a ε_t² α_t / (√3 t), hence α_t = √3 G_F t / (2 a ε_t²): in plane stress
// 3 G_F (1−ν) / (2 E s ε_t²), proportional to 1/s. A crack along the bonds (Σ|d·n| = √3 s)
// dissipates √3/2 of it.
inline double alphaFromFractureEnergy(double GF, double a, double t, double epsT) {
  return std::sqrt(3.0) * GF * t / (2 * a * epsT * epsT);
}

}  // namespace pdq::mplm
