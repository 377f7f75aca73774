// MPLM scenarios: a scenario whose lattice spacing disagrees with the model's is refused;
// supports, bearings and displacement control set by [[particles.set]] act as they should.
#include "scenario/scenario.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "engine/error.hpp"
#include "engine/simulation.hpp"
#include "io/standard_outputs.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "support/harness.hpp"

namespace pdq::mplm {
namespace {

// Writes `text` to `path` (its folder created) and reads it as a scenario.
Scenario scenarioFrom(const std::string& path, const std::string& text) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path) << text;
  return readScenario(path);
}

// The scenario's simulation on `comm`, without its outputs.
std::unique_ptr<Simulation> simulation(Scenario& sc, Comm& comm) {
  sc.problem.output = {.finalRestart = false};
  return makeSimulation(std::move(sc.problem), comm);
}

// An undamaged, damped plate 0.2 m wide and `height` high (loading = "none") for `steps`
// steps: its bottom row has constraint `bottom`, the corner at X = 0 has X held too
// (bottom | 1); then the [[particles.set]] entries `sets`; the rows with Y in `monitored`
// are monitored; `loading` is its [loading] table.
std::string supportedPlate(long steps, double height, int bottom, const std::string& monitored,
                           const std::string& sets, const std::string& loading = "") {
  return fmt::format(R"(steps = {}
[model]
name = "mplm2d"
damage = false
viscous_damping = 20000
{}[particles]
generator = "mplm_plate"
width = 0.2
height = {}
loading = "none"
[[particles.set]]
attribute = "constraint"
value = {}
y = [-0.001, 0.001]
[[particles.set]]
attribute = "constraint"
value = {}
x = [-0.001, 0.001]
y = [-0.001, 0.001]
{}[[particles.set]]
attribute = "monitor"
value = 0
[[particles.set]]
attribute = "monitor"
value = 1
y = {}
)",
                     steps, loading, height, bottom, bottom | 1, sets, monitored);
}

TEST(MplmScenarios, SpacingMustMatchTheLattice) {
  Scenario sc = scenarioFrom("mplm_spacing/bad.toml",
                             "steps = 1\n[model]\nname = \"mplm2d\"\n[particles]\n"
                             "generator = \"square\"\nnx = 5\nny = 5\nspacing = 0.01\n");
  Comm comm;
  auto sim = simulation(sc, comm);
  try {
    sim->setup();
    FAIL() << "setup accepted particles 0.01 apart with spacing 0.02";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lattice spacing is 0.02"), std::string::npos) << e.what();
  }
}

// A plain rectangle (loading = "none") with supports, a prescribed displacement and a
// monitor set by [[particles.set]]: the top row pulled up by 1e-5 m, the bottom row held
// in Y (one corner in X too). Displacement control reaches the prescribed value, and the
// reaction is the uniaxial force E ε A through the 20 diagonal interactions of a row
// (an effective width of 10 s), within the lattice's free-edge effect.
TEST(MplmScenarios, SupportsAndDisplacementControlFromTheScenario) {
  const double s = 0.02, pitch = std::sqrt(3.0) / 2 * s, top = 11 * pitch, u = 1e-5;
  Scenario sc = scenarioFrom("mplm_displacement/pull.toml",
                             supportedPlate(8000, 0.2, 2, "[0.19, 0.2]", R"([[particles.set]]
attribute = "constraint"
value = 2
y = [0.19, 0.2]
[[particles.set]]
attribute = "disp_y"
value = 1e-5
y = [0.19, 0.2]
)"));
  Comm comm;
  auto simPtr = simulation(sc, comm);
  Simulation& sim = *simPtr;
  sim.run();
  EXPECT_NEAR(test::global(sim, "uy"), u, 1e-15);
  const double E = 24.86e9, t = 0.12;
  const double expected = E * (u / top) * 10 * s * t;
  EXPECT_NEAR(test::global(sim, "reaction_y") / expected, 1.0, 0.01);
  EXPECT_LT(test::global(sim, "kinetic"), 1e-12);
}

// A plate resting on a bearing (constraint 8 = REST_Y on its bottom row, X held at one
// corner): pushed down by a load on its top row it sits on the bearing, which carries the
// whole load; pulled up by the same load it lifts off and the bearing carries nothing.
TEST(MplmScenarios, BearingsPushButNeverPull) {
  for (double load : {-100.0, 100.0}) {
    SCOPED_TRACE(load);
    const std::string sets = fmt::format(
        "[[particles.set]]\nattribute = \"load_y\"\nvalue = {}\ny = [0.08, 0.1]\n", load);
    Scenario sc = scenarioFrom(
        "mplm_bearing/rest.toml",
        supportedPlate(6000, 0.1, 8, "[-0.001, 0.001]", sets, "[loading]\nramp_time = 0.004\n"));
    double total = 0;
    const ParticleSet& ps = sc.problem.particles;
    for (std::size_t k = 0; k < ps.size(); ++k) total += ps.fixedRow(k)[LOAD_Y];
    Comm comm;
    auto simPtr = simulation(sc, comm);
    Simulation& sim = *simPtr;
    sim.run();
    if (load < 0) {
      EXPECT_EQ(test::global(sim, "uy"), 0.0);  // on the bearing, never below it
      EXPECT_NEAR(test::global(sim, "reaction_y"), -total, 1e-6 * std::fabs(total));
    } else {
      EXPECT_GT(test::global(sim, "uy"), 0.0);  // lifted off
      EXPECT_EQ(test::global(sim, "reaction_y"), 0.0);
    }
  }
}

}  // namespace
}  // namespace pdq::mplm
