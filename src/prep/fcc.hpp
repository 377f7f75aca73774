#pragma once
// Face-centred cubic lattice generator (3D): nx x ny x nz cubic unit cells of four
// particles each, optionally with random velocities for a target temperature.
//
// Velocities come from a seeded 64-bit Mersenne Twister (its sequence is fixed by the C++
// standard) through Box-Muller, so a seed gives the same lattice on every machine and
// rank. The total momentum is then removed and the velocities scaled so that the
// temperature 2 KE / (k_B (3N - 3)) is exactly the target (k_B = 1: reduced units).
#include <array>
#include <cstdint>

#include "engine/particle_set.hpp"

namespace pdq {

struct FccSpec {
  std::array<int, 3> cells{1, 1, 1};      // unit cells along X, Y, Z
  double density = 0;                     // particles per unit volume: a = (4 / density)^(1/3)
  std::array<double, 3> origin{0, 0, 0};  // corner of the box
  Gid firstId = 1;                        // IDs firstId, firstId + 1, ... in lattice order
  double temperature = 0;                 // 0: particles at rest
  double mass = 1;
  std::uint64_t seed = 1;
  int velocityColumn = -1;  // alterable column of vx (vy, vz follow); needed if temperature > 0
};

struct FccBox {
  double latticeConstant = 0;
  std::array<double, 3> lo{}, hi{};  // the periodic box the lattice fills
};

// Appends the lattice to `out` (whose nFixed/nAlter are the model's widths; extra columns
// are zero). Throws InputError for a non-positive size or density, or for a temperature
// without a velocity column.
FccBox makeFcc(const FccSpec& spec, ParticleSet& out);

}  // namespace pdq
