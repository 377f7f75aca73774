#pragma once
// Shared set-up of the Lennard-Jones tests: a periodic fcc crystal (optionally melting
// from random velocities) run by the "lj" model.
#include <memory>
#include <string>

#include "engine/model.hpp"
#include "engine/simulation.hpp"
#include "io/standard_outputs.hpp"
#include "prep/fcc.hpp"
#include "support/harness.hpp"

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
  int divisions = 0;       // cells cut into divisions^3 sub-cells; 0: the model's default
  bool portable = false;   // the model's kernel = "portable"
  std::uint64_t seed = 2026;
};

inline std::unique_ptr<Simulation> makeMelt(const Melt& m, Comm& comm) {
  Params p("lj test");
  p.set("cutoff", numberText(m.cutoff));
  p.set("skin", numberText(m.skin));
  p.set("shift", m.shift);
  p.set("dt", numberText(m.dt));
  p.set("epsilon", numberText(m.epsilon));
  p.set("sigma", numberText(m.sigma));
  if (m.divisions > 0) p.set("cell_divisions", std::to_string(m.divisions));
  if (m.portable) p.set("kernel", "portable");
  Problem pb = makeProblem("lj", p, {});
  FccSpec spec;
  spec.cells = {m.cells, m.cells, m.cells};
  spec.density = m.density;
  spec.temperature = m.temperature;
  spec.seed = m.seed;
  spec.velocityColumn = pb.model->schema().alterIndex("vx");
  const FccBox box = makeFcc(spec, pb.particles);
  RunConfig& cfg = pb.run;
  cfg.periodic = {true, true, true};
  cfg.boxLo = box.lo;
  cfg.boxHi = box.hi;
  cfg.minCellSize = m.minCellSize > 0 ? m.minCellSize : m.cutoff + m.skin;
  cfg.procs = m.procs;
  cfg.steps = m.steps;
  cfg.checkEvery = 0;
  auto sim = makeSimulation(std::move(pb), comm);
  sim->setup();
  return sim;
}

}  // namespace pdq::ljtest
