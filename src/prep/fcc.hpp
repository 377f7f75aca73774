#pragma once
// Face-centred cubic lattices (3D). makeFcc: nx x ny x nz cubic unit cells of four
// particles each, optionally with random velocities for a target temperature (molecular
// dynamics). closePackedBox: the same lattice built as the MPLM thesis builds it, close-packed
// layers stacked in ABC order, filling a box (lattice models of solids).
//
// Velocities come from a seeded 64-bit Mersenne Twister (its sequence is fixed by the C++
// standard) through Box-Muller, so a seed gives the same lattice on every machine and
// rank. The total momentum is then removed and the velocities scaled so that the
// temperature 2 KE / (k_B (3N - 3)) is exactly the target (k_B = 1: reduced units).
#include <array>
#include <cstdint>
#include <vector>

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

// The close-packed layer of the 2D hexagonal lattice (rows of particles at spacing s along
// `bondAxis`, rows (√3/2)s apart, every other row shifted by s/2) stacked along `stackAxis`
// at √(2/3)s, each layer shifted by s/2 along and (√3/6)s across its rows from the one
// below (A, B, C, A, ...): the fcc lattice with 12 nearest neighbours at s and 6 second
// nearest at √2 s. The points inside the box [origin, origin + size] (faces included up to
// 1e-9 s), one at the origin, layer by layer, row by row. Throws std::invalid_argument
// when the lattice does not fit the box: fewer than two particles along any direction.
struct ClosePacked {
  double s = 0;
  int bondAxis = 0, stackAxis = 2;  // 0 = X, 1 = Y, 2 = Z; different
};
std::vector<std::array<double, 3>> closePackedBox(const ClosePacked& lattice,
                                                  const std::array<double, 3>& size,
                                                  const std::array<double, 3>& origin = {0, 0, 0});
// The same lattice shifted so that its particles' cells fill the box: a particle stands for
// the cell of volume s³/√2 around it (half a plane spacing to each side), and the lattice
// model is the body those cells fill. The first plane is half a spacing inside each face
// (along the rows, whose alternate rows are shifted by s/2, a quarter of s; across the
// rows, whose layers are shifted by a third of the row spacing, a sixth of it), so the
// cells' mean boundary lies on the faces; the particles whose centres lie in the box.
std::vector<std::array<double, 3>> closePackedFill(const ClosePacked& lattice,
                                                   const std::array<double, 3>& size,
                                                   const std::array<double, 3>& origin = {0, 0, 0});
// How many points closePackedFill makes, counted without making them.
double closePackedFillCount(const ClosePacked& lattice, const std::array<double, 3>& size);
// The lattice's three vectors: along the bonds, to the next row, to the next layer.
std::array<std::array<double, 3>, 3> closePackedVectors(const ClosePacked& lattice);
// closePackedFill's first plane from each box corner face: s/4 along the bonds, (√3/12)s
// across the rows, half the layer pitch along the stacking.
std::array<double, 3> closePackedInset(const ClosePacked& lattice);
// The smallest box the lattice fits (two particles along every axis): s along the bonds,
// (√3/2)s across the rows, √(2/3)s along the stacking.
std::array<double, 3> closePackedMinimumBox(const ClosePacked& lattice);
// Distance between close-packed layers, √(2/3) s.
double closePackedLayerPitch(double s);

}  // namespace pdq
