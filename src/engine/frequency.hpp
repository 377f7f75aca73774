#pragma once
// The highest natural frequency of a lattice with `dofs` degrees of freedom per particle,
// by power iteration on M^(−½) K M^(−½), and the stable time step it sets (thesis §4.3.3).
// The lattice enters only through the product with its stiffness: the MPLM gives it
// analytically, the quasi-static solver by finite differences of any model's forces.
#include <cmath>
#include <functional>
#include <span>
#include <vector>

#include "engine/context.hpp"

namespace pdq {

struct DofSystem {
  int dofs = 0;
  std::vector<double> mass;         // per owned particle and DOF: mass or moment of inertia
  std::vector<unsigned char> held;  // per owned particle and DOF: 1 = prescribed (no motion)
};

// Writes, for every owned particle, the elastic force (dofs values: forces, then moments)
// of the small displacement field `u` given at every local particle (owned and ghosts),
// i.e. −K u.
using RestoringForce = std::function<void(std::span<const double> u, std::span<double> force)>;

// ω_max (rad/s) after `iterations` steps, identical on every number of ranks; the
// iteration vector reaches the ghosts by ctx.refreshGhosts.
double highestFrequency(Context& ctx, const DofSystem& system, const RestoringForce& restoring,
                        int iterations);

// The largest stable step of central differences for a mode at ω_max that sees a damping
// ratio ζ: Δt = (2/ω_max)(√(1+ζ²) − ζ).
inline double stableStep(double omegaMax, double zeta) {
  return 2 / omegaMax * (std::sqrt(1 + zeta * zeta) - zeta);
}

}  // namespace pdq
