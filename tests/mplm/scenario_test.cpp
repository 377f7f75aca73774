// The §4.4 examples as scenario files (examples/mplm/*.toml, generators mplm_plate and
// mplm_beam) are the same specimens as the C++ examples the validation table runs: the
// same particles bit for bit, the same model parameters and steps. And a scenario whose
// lattice spacing disagrees with the model's is refused.
#include "scenario/scenario.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "engine/error.hpp"
#include "engine/simulation.hpp"
#include "models/mplm/examples.hpp"
#include "models/mplm/parameters.hpp"

namespace pdq::mplm {
namespace {

std::string examplesDir() { return std::string(std::getenv("PDQ_SOURCE_DIR")) + "/examples/mplm"; }

TEST(MplmScenarios, EveryExampleFileBuildsTheThesisSpecimen) {
  for (const auto& name : exampleNames()) {
    SCOPED_TRACE(name);
    const Scenario sc = readScenario(examplesDir() + "/" + name + ".toml");
    const Example ex = example(name);
    const ParticleSet& a = sc.problem.particles;
    const ParticleSet& b = ex.particles;
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(a.gid, b.gid);
    EXPECT_EQ(a.fixed, b.fixed);  // positions, materials, bars, supports, loads, monitor
    EXPECT_EQ(a.alter, b.alter);
    EXPECT_EQ(sc.problem.run.steps, ex.steps);
    Params exParams("example");
    for (const auto& [key, text] : ex.params) exParams.set(key, text);
    Parameters fromFile, fromExample;
    fromFile.read(sc.modelParams);
    fromExample.read(exParams);
    EXPECT_EQ(fromFile.s, fromExample.s);
    EXPECT_EQ(fromFile.thickness, fromExample.thickness);
    EXPECT_EQ(fromFile.dt, fromExample.dt);
  }
}

TEST(MplmScenarios, SpacingMustMatchTheLattice) {
  const std::string dir = "mplm_spacing";
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/bad.toml";
  std::ofstream(path) << "steps = 1\n[model]\nname = \"mplm2d\"\n"
                         "[particles]\ngenerator = \"square\"\nnx = 5\nny = 5\nspacing = 0.01\n";
  Scenario sc = readScenario(path);
  Comm comm(MPI_COMM_WORLD);
  Simulation sim(std::move(sc.problem.model), std::move(sc.problem.particles), sc.problem.run,
                 comm);
  try {
    sim.setup();
    FAIL() << "setup accepted particles 0.01 apart with spacing 0.02";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lattice spacing is 0.02"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pdq::mplm
