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
#include "prep/mplm/generators.hpp"
#include "scenario/scenario.hpp"
#include "support/harness.hpp"

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

using pdq::test::global;
using pdq::test::params;

inline std::unique_ptr<Simulation> simulation(Comm& comm, const Params& p, ParticleSet ps,
                                              long steps, const std::string& modelName = "mplm2d",
                                              const Loading& loading = {}) {
  return pdq::test::simulation(comm, modelName, p, std::move(ps), steps, loading);
}

// A small reinforced beam under its line load (it cracks: the quasi-static tests load it
// to load_scale 120, the determinism test dynamically to 200).
inline ParticleSet smallBeam() {
  BeamSpec b;
  b.span = 0.4;
  b.depth = 0.1;
  b.bars = {{.diameter = 0.01}};
  b.stirrupDiameter = 0.006;
  b.stirrupFirst = 0.04;
  b.stirrupSpacing = 0.1;
  return beam(b);
}

}  // namespace pdq::mplm::test
