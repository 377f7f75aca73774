#pragma once
// The MPLM parameters that do not depend on the lattice's dimension, with their documented
// defaults (thesis Tables 4.1–4.3 where it gives one; docs/mplm.md lists them all). A
// model of a given dimension adds its own (2d/parameters.hpp).
#include <string>

#include "engine/params.hpp"
#include "models/mplm/common/damage.hpp"

namespace pdq::mplm {

struct Parameters {
  // Lattice and concrete
  double s = 0.02;             // spacing (m)
  double horizonFactor = 1.5;  // δ = 1.5 s: nearest neighbours only
  double E = 24.86e9, nu = 0.2, rho = 2323;
  std::string kinematics = "corotational";  // corotational | small
  // Damage
  bool damage = true;
  DamageLaw law;
  // G_F (N/m, thesis Table 4.1). Unless `tensile_ratio` is given, each lattice sets α_t so
  // that a crack normal to a bond dissipates G_F whatever the spacing (setAlphaT).
  double fractureEnergy = 175;
  // Steel (Table 4.3)
  double steelE = 200e9, steelRho = 7850, steelYield = 0.00207;
  // Multiplies the steel particles' rotational inertia. A bar thicker than the spacing
  // (the 10 cm bar of §4.4.6 at s = 2 cm) is a stubby beam whose rotation sets the highest
  // frequency; scaling its rotary inertia is the usual explicit-dynamics remedy for
  // quasi-static runs: statics are unchanged and Δt grows (docs/mplm.md).
  double steelRotaryScale = 1;
  std::string link = "concrete";  // concrete: link = concrete interaction's stiffness; length
  // Damping (eq. 4.21) and time stepping
  double zeta = 0.05;          // ζ of relative translational velocity
  double zetaRotation = 0.05;  // ζ of relative angular velocity
  double viscous = 0;          // mass-proportional damping c/m (1/s), dynamic relaxation
  double dt = 0;               // 0: from the highest frequency
  double dtSafety = 0.9;
  int powerIterations = 60;

  void read(const Params& p);
  // α_t = the lattice's value for fractureEnergy, unless `tensile_ratio` was given; an
  // α_t ≤ 1 (interactions breaking at their elastic limit) is an error at the line of
  // `fracture_energy`.
  void setAlphaT(const Params& p, double alphaFromEnergy);
  double horizon() const { return horizonFactor * s; }
  double steelMass(double area) const;  // ρ_s A_s s: a bar segment of one spacing
  static double rotationalInertia(double m, double s) { return m * s * s / 10; }  // r = s/2
  // A particle's rotational inertia, a steel one's scaled by steelRotaryScale.
  double inertia(double m, bool steel) const {
    return rotationalInertia(m, s) * (steel ? steelRotaryScale : 1.0);
  }
};

}  // namespace pdq::mplm
