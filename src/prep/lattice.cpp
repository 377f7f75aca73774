#include "prep/lattice.hpp"

#include <cmath>

#include "engine/error.hpp"
#include "engine/memory.hpp"

namespace pdq::prep {

std::size_t appendLattice(ParticleSet& ps, const Lattice& L) {
  if (L.n[0] < 1 || L.n[1] < 1 || L.n[2] < 1 || !(L.spacing > 0))
    throw InputError("lattice", 0,
                     "a lattice needs at least one point per axis and a positive spacing");
  checkParticleCount(double(L.n[0]) * L.n[1] * L.n[2], 8.0 * (1 + ps.nFixed + ps.nAlter),
                     "the lattice");
  const std::size_t first = ps.size();
  const std::size_t total = std::size_t(L.n[0]) * L.n[1] * L.n[2];
  ps.gid.reserve(first + total);
  ps.fixed.reserve((first + total) * ps.nFixed);
  ps.alter.reserve((first + total) * ps.nAlter);
  Gid id = L.firstId;
  for (int k = 0; k < L.n[2]; ++k)
    for (int j = 0; j < L.n[1]; ++j)
      for (int i = 0; i < L.n[0]; ++i)
        ps.add(id++, L.origin[0] + i * L.spacing, L.origin[1] + j * L.spacing,
               L.origin[2] + k * L.spacing);
  return first;
}

double latticeSteps(double length, double first, double step) {
  return length >= first ? std::floor((length - first) / step) + 1 : 0.0;
}

Lattice squareLattice(int nx, int ny, double spacing, std::array<double, 3> origin) {
  return Lattice{{nx, ny, 1}, spacing, origin};
}

Lattice cubicLattice(int nx, int ny, int nz, double spacing, std::array<double, 3> origin) {
  return Lattice{{nx, ny, nz}, spacing, origin};
}

}  // namespace pdq::prep
