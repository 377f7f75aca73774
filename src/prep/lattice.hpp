#pragma once
// Lattice generators: square (2D) and simple-cubic (3D) point lattices appended to a
// ParticleSet, IDs consecutive with X varying fastest, then Y, then Z (so the last ID is
// the corner of largest coordinates). Extra attributes are zero; the caller sets them.
#include <array>

#include "engine/particle_set.hpp"

namespace pdq::prep {

struct Lattice {
  std::array<int, 3> n{1, 1, 1};  // points along X, Y, Z (n[2] = 1 for a square lattice)
  double spacing = 1;
  std::array<double, 3> origin{0, 0, 0};
  Gid firstId = 1;
};

// Index (row) in `ps` of the first particle appended; particle (i, j, k) is at row
// first + i + n0 (j + n1 k).
std::size_t appendLattice(ParticleSet& ps, const Lattice& lattice);

// How many of first, first + step, first + 2 step, ... are at most `length` (a row of a
// lattice, counted without making it).
double latticeSteps(double length, double first, double step);

Lattice squareLattice(int nx, int ny, double spacing, std::array<double, 3> origin = {});
Lattice cubicLattice(int nx, int ny, int nz, double spacing, std::array<double, 3> origin = {});

}  // namespace pdq::prep
