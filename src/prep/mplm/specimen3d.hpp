#pragma once
// Building blocks for 3D MPLM problems (model mplm3d): fcc concrete lattices, supports,
// loads and monitored particles written into the fixed attributes of a ParticleSet.
// Particles are picked with mplm::select (prep/mplm/specimen.hpp).
#include <array>
#include <cstddef>
#include <vector>

#include "engine/particle_set.hpp"

namespace pdq::mplm3d {

// An empty set in the mplm3d attribute widths.
ParticleSet newParticleSet();
// Appends concrete particles at the points (global IDs continue from the set's size).
void addConcrete(ParticleSet& ps, const std::vector<std::array<double, 3>>& points);
// Prescribes DOFs (Constraint bits) of the particles, with peak values of the prescribed
// displacements and rotations (u_x, u_y, u_z, θ_x, θ_y, θ_z).
void constrain(ParticleSet& ps, const std::vector<std::size_t>& idx, int bits,
               const std::array<double, 6>& peak = {});
// Adds a peak external force and moment (F_x, F_y, F_z, M_x, M_y, M_z) to each particle.
void load(ParticleSet& ps, const std::vector<std::size_t>& idx, const std::array<double, 6>& fm);
void monitor(ParticleSet& ps, const std::vector<std::size_t>& idx);

}  // namespace pdq::mplm3d
