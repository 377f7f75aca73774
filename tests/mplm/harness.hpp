#pragma once
// Running mplm2d (or mplm3d) on a ParticleSet in a test, on whatever ranks the test runs on.
#include <map>
#include <memory>
#include <string>

#include "engine/comm.hpp"
#include "engine/model.hpp"
#include "engine/params.hpp"
#include "engine/simulation.hpp"

namespace pdq::mplm::test {

inline Params params(const std::map<std::string, std::string>& kv) {
  Params p("test");
  for (const auto& [k, v] : kv) p.set(k, v);
  return p;
}

inline std::unique_ptr<Simulation> simulation(Comm& comm, const Params& p, ParticleSet ps,
                                              long steps, const std::string& modelName = "mplm2d") {
  auto model = ModelRegistry::create(modelName);
  model->configure(p);
  p.checkAllUsed();
  RunConfig cfg;
  cfg.steps = steps;
  cfg.outDir = "mplm_test_out";
  auto sim = std::make_unique<Simulation>(std::move(model), std::move(ps), cfg, comm);
  sim->setup();
  return sim;
}

// A named global of the model (load, displacement, kinetic energy, ...), same on all ranks.
inline double global(Simulation& sim, const std::string& name) {
  const auto names = sim.model().globals();
  const auto values = sim.model().globalValues(sim.context());
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return values[k];
  throw std::runtime_error("no global " + name);
}

}  // namespace pdq::mplm::test
