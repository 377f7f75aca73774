// Scenario generator for the fcc crystal of prep/fcc.hpp (a periodic box of it):
//     [particles]
//     generator = "fcc"
//     cells = [10, 10, 10]      # unit cells along X, Y, Z (4 atoms each)
//     density = 0.8442          # atoms per unit volume
//     temperature = 1.44        # optional: random velocities (into vx, vy, vz)
//     seed = 87287              # optional
//     mass = 1.0                # optional, for the temperature
#include <cmath>

#include "engine/error.hpp"
#include "prep/fcc.hpp"
#include "prep/generator.hpp"

namespace pdq {
namespace {

FccSpec readFcc(const Params& p) {
  FccSpec s;
  const auto cells = p.numbers("cells");
  const auto where = p.raw("cells");
  if (cells.size() != 3) throw InputError(where->file, where->line, "cells needs 3 whole numbers");
  for (int a = 0; a < 3; ++a) {
    if (cells[a] < 1 || cells[a] != static_cast<int>(cells[a]))
      throw InputError(where->file, where->line, "cells must be whole numbers >= 1");
    s.cells[a] = static_cast<int>(cells[a]);
  }
  s.density = p.number("density");
  if (!(s.density > 0)) {
    const auto v = p.raw("density");
    throw InputError(v->file, v->line, "density must be positive");
  }
  s.temperature = p.number("temperature", 0.0, 0.0, 1e300);
  s.mass = p.number("mass", 1.0, 1e-300, 1e300);
  s.seed = static_cast<std::uint64_t>(p.integer("seed", 1));
  s.firstId = p.integer("first_id", 1);
  return s;
}

Generated fcc(const Params& p, const Schema& schema) {
  FccSpec s = readFcc(p);
  s.velocityColumn = schema.alterIndex("vx");
  Generated g;
  g.particles.nFixed = schema.nFixed();
  g.particles.nAlter = schema.nAlter();
  const FccBox box = makeFcc(s, g.particles);
  g.boxLo = box.lo;
  g.boxHi = box.hi;
  return g;
}

// Four sites a cell, a quarter of a cell from its faces (makeFcc); the fcc lattice's
// vectors join a site to its twelve nearest neighbours.
SizeEstimate fccSize(const Params& p, const Params&) {
  const FccSpec s = readFcc(p);
  const double a = std::cbrt(4.0 / s.density);
  SizeEstimate e;
  e.particles = 4.0 * s.cells[0] * s.cells[1] * s.cells[2];
  for (int k = 0; k < 3; ++k) {
    e.lo[k] = s.origin[k] + a / 4;
    e.hi[k] = s.origin[k] + (s.cells[k] - 0.25) * a;
    e.stride[k] = a / 2;
  }
  e.primitive = {{0, a / 2, a / 2}, {a / 2, 0, a / 2}, {a / 2, a / 2, 0}};
  return e;
}

}  // namespace

PDQ_REGISTER_ESTIMATE(fccSize, "fcc");
PDQ_REGISTER_GENERATOR(fcc, "fcc",
                       "fcc crystal filling a periodic box: cells, density, temperature, seed\n"
                       "  cells        [nx, ny, nz] unit cells of 4 sites (required)\n"
                       "  density      sites per unit volume (required)\n"
                       "  temperature  initial velocities from Maxwell-Boltzmann (default 0)\n"
                       "  mass         each particle's mass for the velocities (default 1)\n"
                       "  seed         of the velocities' random numbers (default 1)\n"
                       "  first_id     ID of the first site (default 1)\n"
                       "  IDs          from first_id: the 4 sites of a cell, cells X fastest, "
                       "then Y, then Z; the box is the cells'");

}  // namespace pdq
