#pragma once
// The highest natural frequency of the undamaged, undamped lattice, by power iteration on
// M^(−½) K M^(−½) (K the small-deformation stiffness of eq. 4.3). It sets the stable time
// step Δt = safety · (2/ω_max) (√(1+ζ²) − ζ) (thesis §4.3.3).
#include <vector>

#include "engine/context.hpp"
#include "models/mplm/2d/interaction.hpp"

namespace pdq::mplm {

struct Inertia {
  std::vector<double> mass, inertia;  // per owned particle
  std::vector<int> constraint;        // Constraint bits per owned particle
};

// ω_max (rad/s) after `iterations` steps, identical on every number of ranks. Uses the
// velocity columns as the iteration vector (so its ghosts follow by refreshGhosts) and
// restores them before returning.
double highestFrequency(Context& ctx, const std::vector<Interaction>& interactions,
                        const Inertia& inertia, int iterations);

}  // namespace pdq::mplm
