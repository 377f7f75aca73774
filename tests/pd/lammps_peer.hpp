#pragma once
// The 3D block problem that pdq and LAMMPS's PERI package both run, for the side-by-side
// comparison (bench/pd/run.sh and tests/pd/test_pd_lammps.cpp): an n×n×n simple-cubic
// lattice, δ = 3 s, partial volumes, no breaking, no damping, started at the reference
// positions from a smooth velocity field (and, optionally, pulled at its top layer from
// step 0: LAMMPS's fix addforce). Unit mapping (docs/peridynamics.md): LAMMPS
// units si; atom_style peri "volume" = pdq volume, "density" (LAMMPS's rmass) = pdq
// density; LAMMPS forces are force densities, so its f/ρ is pdq's acceleration.
#include <array>
#include <map>
#include <string>

#include "engine/params.hpp"
#include "engine/particle_set.hpp"
#include "engine/schema.hpp"

namespace pdq::lammps {

struct Block {
  int n = 47;
  double s = 0.0254, E = 24.85e9, nu = 0.25, rho = 2323, dt = 1.0e-6;
  double v0 = 0.5;     // m/s amplitude of the initial velocity field
  double topLoad = 0;  // N along +Z on each particle of the top layer, from step 0
  double delta() const { return 3.0 * s; }
  void velocity(const double* X, double* v) const;
};

// The model's parameters and particles (in `schema`) for the block.
Params blockParams(const Block& bl, const std::string& model);
ParticleSet blockParticles(const Block& bl, const Schema& schema);
// DIR/lammps.data and DIR/lammps.in: the same problem for `lmp -in lammps.in`, which
// writes DIR/lammps.dump (id x y z, sorted) after `steps` steps.
void writeLammps(const Block& bl, const std::string& model, long steps, const std::string& dir,
                 const ParticleSet& ps);

using Displacements = std::map<long, std::array<double, 3>>;
// "ID ux uy uz" lines, or a LAMMPS dump (*.dump: positions, minus those of lammps.data
// in the same folder).
Displacements readDisplacements(const std::string& file);
struct Difference {
  std::size_t particles = 0;
  double maxU = 0, maxDiff = 0;
  double relative() const { return maxDiff / maxU; }
};
Difference compare(const Displacements& a, const Displacements& b, const std::string& nameB);

}  // namespace pdq::lammps
