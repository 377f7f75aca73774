#include "models/mplm/2d/parameters.hpp"

#include <cmath>
#include <stdexcept>

#include "engine/error.hpp"

namespace pdq::mplm {

void Parameters2d::read(const Params& p) {
  constexpr double big = 1e300;
  Parameters::read(p);
  thickness = p.number("thickness", thickness, 1e-12, big);
  elasticity = p.choice("elasticity", elasticity, {"plane_stress", "plane_strain", "given"});
  if (elasticity == "given") {
    concrete.a = p.number("micro_a", 0.0, 1e-300, big);
    concrete.b = p.number("micro_b", 0.0, 0.0, big);
    if (!(concrete.a > 0))
      throw InputError(p.owner(), 0, "elasticity = \"given\" needs micro_a > 0 (and micro_b)");
  } else {
    try {
      concrete = forContinuum(elasticity, E, nu, s, thickness);
    } catch (const std::domain_error& e) {
      const auto v = p.raw("poisson_ratio");
      throw InputError(v ? v->file : p.owner(), v ? v->line : 0, e.what());
    }
  }
  setAlphaT(p, alphaFromFractureEnergy(fractureEnergy, concrete.a, thickness, law.epsT));
}

double Parameters2d::concreteMass() const { return rho * std::sqrt(3.0) / 2 * s * s * thickness; }

}  // namespace pdq::mplm
