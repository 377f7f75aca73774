#pragma once
// Running mplm2d (or mplm3d) on a ParticleSet in a test, on whatever ranks the test runs on,
// and the thesis's examples as the scenario files examples/mplm/*.toml give them.
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/comm.hpp"
#include "engine/model.hpp"
#include "engine/params.hpp"
#include "engine/simulation.hpp"
#include "scenario/scenario.hpp"

namespace pdq::mplm::test {

// The nine examples of thesis §4.4.1–4.4.6.
inline const std::vector<std::string> examples = {
    "tension_x", "tension_y",        "compression_x", "compression_y", "plain_beam",
    "rc_beam",   "rc_beam_stirrups", "rc_beam_shear", "deep_beam"};

// examples/mplm/<name>.toml, read by the scenario loader.
inline Scenario example(const std::string& name) {
  return readScenario(std::string(std::getenv("PDQ_SOURCE_DIR")) + "/examples/mplm/" + name +
                      ".toml");
}

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
