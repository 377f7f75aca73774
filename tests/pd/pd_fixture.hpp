#pragma once
// Helpers shared by the peridynamics tests: building a model's particle set on a lattice
// and reading back a global table of positions.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/comm.hpp"
#include "engine/model.hpp"
#include "engine/params.hpp"
#include "engine/simulation.hpp"
#include "io/standard_outputs.hpp"
#include "prep/lattice.hpp"
#include "support/harness.hpp"

namespace pdq::pdtest {

struct Problem {
  std::string model;
  Params params{"test"};
  ParticleSet ps;
  Schema schema;
  RunConfig run{};
  int col(const std::string& fixedName) const { return schema.fixedIndex(fixedName); }
  int acol(const std::string& alterName) const { return schema.alterIndex(alterName); }
};

// A lattice problem for `model` with parameters `kv` (key, value); volume = s^2 t (2D)
// or s^3 (3D) on every particle.
inline Problem latticeProblem(const std::string& model,
                              const std::vector<std::pair<std::string, double>>& kv,
                              const prep::Lattice& lattice, double thickness = 1.0) {
  Problem pb;
  pb.model = model;
  for (auto& [k, v] : kv) pb.params.set(k, numberText(v));
  pb.schema = ModelRegistry::create(model)->schema();
  pb.ps.nFixed = pb.schema.nFixed();
  pb.ps.nAlter = pb.schema.nAlter();
  prep::appendLattice(pb.ps, lattice);
  const double s = lattice.spacing;
  const double vol = lattice.n[2] == 1 ? s * s * thickness : s * s * s;
  for (std::size_t k = 0; k < pb.ps.size(); ++k) pb.ps.fixedRow(k)[pb.col("volume")] = vol;
  return pb;
}

inline std::unique_ptr<Simulation> makeSimulation(Problem pb, Comm& comm) {
  return pdq::makeSimulation(
      pdq::makeProblem(pb.model, pb.params, std::move(pb.ps), std::move(pb.run)), comm);
}

// ... running `steps` steps, its output folder `outDir`.
inline std::unique_ptr<Simulation> makeSimulation(Problem pb, long steps, const std::string& outDir,
                                                  Comm& comm) {
  pb.run.steps = steps;
  pb.run.outDir = outDir;
  return makeSimulation(std::move(pb), comm);
}

// Every particle's alterable row, by ID, gathered on rank 0 (empty elsewhere).
inline std::map<Gid, std::vector<double>> gatherAlter(Simulation& sim) {
  const int width = 1 + sim.particles().schema().nAlter();
  const std::vector<double> rows = test::gatherState(sim).particles;
  std::map<Gid, std::vector<double>> out;
  for (std::size_t k = 0; k < rows.size(); k += width)
    out[static_cast<Gid>(rows[k])].assign(&rows[k + 1], &rows[k] + width);
  return out;
}

}  // namespace pdq::pdtest
