#pragma once
// A small breaking spring lattice for the output tests: nx x ny particles at unit
// spacing (2D), pulled apart along X by an initial velocity field: fast in the upper
// half, whose springs break within a few steps, slow in the lower half, whose do not.
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "engine/comm.hpp"
#include "engine/model.hpp"
#include "engine/params.hpp"
#include "engine/simulation.hpp"
#include "io/standard_outputs.hpp"
#include "support/harness.hpp"

namespace pdq::test {

inline std::unique_ptr<Simulation> springLattice(Comm& comm, int nx, int ny, long steps,
                                                 const std::string& outDir, long firstStep = 0) {
  Params p("test");
  p.set("critical_stretch", "0.02");
  p.set("dt", "0.05");
  p.set("horizon", "1.5");
  Problem pb = makeProblem("spring", p, {});
  ParticleSet& ps = pb.particles;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t k = ps.add(j * nx + i, i, j, 0);
      ps.alterRow(k)[3] = 0.05 * (i - 0.5 * (nx - 1)) * (2 * j >= ny ? 1.0 : 0.1);  // vx
      ps.alterRow(k)[4] = 0.005 * (j - 0.5 * (ny - 1));                             // vy
    }
  pb.run.steps = steps;
  pb.run.firstStep = firstStep;
  pb.run.outDir = outDir;
  return makeSimulation(std::move(pb), comm);
}

// Every rank's (global ID -> value of alterable column k) for its owned particles,
// gathered on rank 0.
inline std::map<long, double> gatherAlter(Simulation& sim, int k) {
  const int width = 1 + sim.particles().schema().nAlter();
  const std::vector<double> rows = gatherState(sim).particles;
  std::map<long, double> all;
  for (std::size_t r = 0; r < rows.size(); r += width)
    all[static_cast<long>(rows[r])] = rows[r + 1 + k];
  return all;
}

// Every bond once, (smaller ID, larger ID) -> broken (1) or not (0), gathered on rank 0.
inline std::map<std::pair<long, long>, double> gatherBonds(Simulation& sim) {
  const int width = 3 + sim.bonds().nAttr();
  const std::vector<double> rows = gatherState(sim).bonds;  // owner, partner, dead, ...
  std::map<std::pair<long, long>, double> all;
  for (std::size_t r = 0; r < rows.size(); r += width)
    if (rows[r] < rows[r + 1])
      all[{static_cast<long>(rows[r]), static_cast<long>(rows[r + 1])}] = rows[r + 2];
  return all;
}

}  // namespace pdq::test
