#include "models/mplm/common/parameters.hpp"

#include "engine/error.hpp"

namespace pdq::mplm {

void Parameters::read(const Params& p) {
  constexpr double big = 1e300;
  s = p.number("spacing", s, 1e-12, big);
  horizonFactor = p.number("horizon_factor", horizonFactor, 1.0, 1.7320508);
  E = p.number("youngs_modulus", E, 1e-12, big);
  nu = p.number("poisson_ratio", nu, -0.99, 0.3333);
  rho = p.number("density", rho, 1e-12, big);
  kinematics = p.choice("kinematics", kinematics, {"corotational", "small"});

  damage = p.flag("damage", damage);
  law.epsT = p.number("tensile_strain", law.epsT, 1e-300, big);
  law.epsC = p.number("compressive_strain", law.epsC, -big, -1e-300);
  law.alphaC = p.number("compressive_ratio", law.alphaC, 1.000001, big);
  law.beta = p.number("beta", law.beta, 0.0, big);
  law.crushing = p.flag("crushing", law.crushing);
  fractureEnergy = p.number("fracture_energy", fractureEnergy, 0.0, big);
  law.alphaT = p.number("tensile_ratio", law.alphaT, 1.000001, big);
  if (p.has("fracture_energy") && p.has("tensile_ratio"))
    throw InputError(p.owner(), 0, "give either tensile_ratio or fracture_energy, not both");
  if (!(fractureEnergy > 0)) {
    const auto v = p.raw("fracture_energy");
    throw InputError(v ? v->file : p.owner(), v ? v->line : 0,
                     "fracture_energy must be > 0 (or give tensile_ratio)");
  }

  steelE = p.number("steel_modulus", steelE, 1e-12, big);
  steelRho = p.number("steel_density", steelRho, 1e-12, big);
  steelYield = p.number("steel_yield_strain", steelYield, 1e-300, big);
  steelRotaryScale = p.number("steel_rotary_inertia_scale", steelRotaryScale, 1e-6, 1e12);
  link = p.choice("link_stiffness", link, {"concrete", "length"});

  zeta = p.number("damping_ratio", zeta, 0.0, 10.0);
  zetaRotation = p.number("rotational_damping_ratio", zetaRotation, 0.0, 10.0);
  viscous = p.number("viscous_damping", viscous, 0.0, big);
  dt = p.number("dt", dt, 0.0, big);
  dtSafety = p.number("dt_safety", dtSafety, 1e-6, 1.0);
  powerIterations = static_cast<int>(p.integer("power_iterations", powerIterations));
  if (powerIterations < 1) throw InputError(p.owner(), 0, "power_iterations must be >= 1");
}

void Parameters::setAlphaT(const Params& p, double alphaFromEnergy) {
  if (p.has("tensile_ratio")) return;
  if (!(alphaFromEnergy > 1)) {
    const auto v = p.raw("fracture_energy");
    throw InputError(v ? v->file : p.owner(), v ? v->line : 0,
                     "fracture_energy gives a tensile_ratio <= 1 at this spacing and "
                     "tensile_strain");
  }
  law.alphaT = alphaFromEnergy;
}

double Parameters::steelMass(double area) const { return steelRho * area * s; }

}  // namespace pdq::mplm
