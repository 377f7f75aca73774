#pragma once
// The highest natural frequency of an undamaged, undamped lattice with `dofs` degrees of
// freedom per particle, by power iteration on M^(−½) K M^(−½), and the stable time step
// it sets (thesis §4.3.3). The lattice enters only through the product with its stiffness.
#include <cmath>
#include <functional>
#include <span>
#include <vector>

#include "engine/context.hpp"

namespace pdq::mplm {

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

// Logs the frequency and the steps, and warns (on standard error through the pdq command)
// when the time step in use exceeds the stable one.
void reportTimeStep(Context& ctx, const char* model, double omegaMax, double stable,
                    double thesisDt);

}  // namespace pdq::mplm
