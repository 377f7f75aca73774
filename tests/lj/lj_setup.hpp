#pragma once
// Shared set-up of the Lennard-Jones tests: a periodic fcc crystal (optionally melting
// from random velocities) run by the "lj" model, and the gathered final state.
#include <algorithm>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "engine/simulation.hpp"
#include "prep/fcc.hpp"

namespace pdq::ljtest {

struct Melt {
  int cells = 6;              // fcc unit cells per side (4 cells^3 particles)
  double density = 0.8442;    // reduced number density
  double temperature = 1.44;  // 0: the perfect lattice at rest
  std::string shift = "energy";
  double dt = 0.005;
  double cutoff = 2.5, skin = 0.3;
  double epsilon = 1, sigma = 1;
  long steps = 0;
  std::array<int, 3> procs{0, 0, 0};
  double minCellSize = 0;  // 0: cutoff + skin, as the model requires
  std::uint64_t seed = 2026;
};

// A number as text that reads back as the same double.
inline std::string num(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

inline std::unique_ptr<Simulation> makeMelt(const Melt& m, Comm& comm) {
  Params p("lj test");
  p.set("cutoff", num(m.cutoff));
  p.set("skin", num(m.skin));
  p.set("shift", m.shift);
  p.set("dt", num(m.dt));
  p.set("epsilon", num(m.epsilon));
  p.set("sigma", num(m.sigma));
  auto model = ModelRegistry::create("lj");
  model->configure(p);
  const Schema schema = model->schema();
  ParticleSet ps;
  ps.nFixed = schema.nFixed();
  ps.nAlter = schema.nAlter();
  FccSpec spec;
  spec.cells = {m.cells, m.cells, m.cells};
  spec.density = m.density;
  spec.temperature = m.temperature;
  spec.seed = m.seed;
  spec.velocityColumn = schema.alterIndex("vx");
  const FccBox box = makeFcc(spec, ps);
  RunConfig cfg;
  cfg.periodic = {true, true, true};
  cfg.boxLo = box.lo;
  cfg.boxHi = box.hi;
  cfg.minCellSize = m.minCellSize > 0 ? m.minCellSize : m.cutoff + m.skin;
  cfg.procs = m.procs;
  cfg.steps = m.steps;
  cfg.checkEvery = 0;
  auto sim = std::make_unique<Simulation>(std::move(model), std::move(ps), cfg, comm);
  sim->setup();
  return sim;
}

// One global value of the model by name (a collective call).
inline double global(Simulation& sim, const std::string& name) {
  const auto names = sim.model().globals();
  const auto values = sim.model().globalValues(sim.context());
  const auto it = std::find(names.begin(), names.end(), name);
  return values.at(static_cast<std::size_t>(it - names.begin()));
}

// Every particle's global ID and alterable row, sorted by ID, on rank 0 of the
// simulation's communicator (empty elsewhere).
struct State {
  std::vector<Gid> gid;
  std::vector<double> alter;  // nAlter per particle
};

inline State gatherState(Simulation& sim) {
  const Particles& P = sim.particles();
  const int nA = P.schema().nAlter();
  const std::size_t rec = sizeof(Gid) + nA * sizeof(double);
  std::vector<char> mine(P.owned() * rec);
  for (std::size_t i = 0; i < P.owned(); ++i) {
    const Gid g = P.gid(i);
    std::memcpy(&mine[i * rec], &g, sizeof g);
    std::memcpy(&mine[i * rec + sizeof g], P.alter(i), nA * sizeof(double));
  }
  const auto blocks = sim.comm().gather(mine);
  std::vector<std::pair<Gid, std::vector<double>>> all;
  for (const auto& b : blocks)
    for (std::size_t k = 0; k < b.size() / rec; ++k) {
      Gid g;
      std::vector<double> row(nA);
      std::memcpy(&g, &b[k * rec], sizeof g);
      std::memcpy(row.data(), &b[k * rec + sizeof g], nA * sizeof(double));
      all.emplace_back(g, std::move(row));
    }
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  State s;
  for (auto& [g, row] : all) {
    s.gid.push_back(g);
    s.alter.insert(s.alter.end(), row.begin(), row.end());
  }
  return s;
}

}  // namespace pdq::ljtest
