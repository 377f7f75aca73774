#pragma once
// Helpers shared by the peridynamics tests: building a model's particle set on a lattice
// and reading back a global table of positions.
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "engine/comm.hpp"
#include "engine/model.hpp"
#include "engine/params.hpp"
#include "engine/simulation.hpp"
#include "prep/lattice.hpp"

namespace pdq::pdtest {

inline std::string num(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

struct Problem {
  std::string model;
  Params params{"test"};
  ParticleSet ps;
  Schema schema;
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
  for (auto& [k, v] : kv) pb.params.set(k, num(v));
  pb.schema = ModelRegistry::create(model)->schema();
  pb.ps.nFixed = pb.schema.nFixed();
  pb.ps.nAlter = pb.schema.nAlter();
  prep::appendLattice(pb.ps, lattice);
  const double s = lattice.spacing;
  const double vol = lattice.n[2] == 1 ? s * s * thickness : s * s * s;
  for (std::size_t k = 0; k < pb.ps.size(); ++k) pb.ps.fixedRow(k)[pb.col("volume")] = vol;
  return pb;
}

inline std::unique_ptr<Simulation> makeSimulation(Problem pb, RunConfig cfg, Comm& comm) {
  auto m = ModelRegistry::create(pb.model);
  m->configure(pb.params);
  pb.params.checkAllUsed();
  return std::make_unique<Simulation>(std::move(m), std::move(pb.ps), cfg, comm);
}

// Every particle's alterable row, by ID, gathered on rank 0 (empty elsewhere).
inline std::map<Gid, std::vector<double>> gatherAlter(Simulation& sim) {
  Particles& P = sim.particles();
  const int nA = P.schema().nAlter();
  std::vector<char> bytes;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    const Gid g = P.gid(i);
    bytes.insert(bytes.end(), reinterpret_cast<const char*>(&g),
                 reinterpret_cast<const char*>(&g) + sizeof g);
    bytes.insert(bytes.end(), reinterpret_cast<const char*>(P.alter(i)),
                 reinterpret_cast<const char*>(P.alter(i) + nA));
  }
  std::map<Gid, std::vector<double>> out;
  for (auto& block : sim.comm().gather(bytes)) {
    const std::size_t rec = sizeof(Gid) + nA * sizeof(double);
    for (std::size_t o = 0; o + rec <= block.size(); o += rec) {
      Gid g;
      std::memcpy(&g, &block[o], sizeof g);
      std::vector<double> row(nA);
      std::memcpy(row.data(), &block[o + sizeof g], nA * sizeof(double));
      out[g] = std::move(row);
    }
  }
  return out;
}

}  // namespace pdq::pdtest
