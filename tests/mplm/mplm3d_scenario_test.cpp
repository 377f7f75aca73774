// The 3D member generator (mplm3d_beam) and the §4.4.7 scenario file: supports, loads and
// monitors where the file says; bad input stops with the file, line and reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "engine/error.hpp"
#include "io/standard_outputs.hpp"
#include "models/mplm/3d/attributes.hpp"
#include "scenario/scenario.hpp"

namespace pdq::mplm3d {
namespace {

std::string examplesDir() { return std::string(std::getenv("PDQ_SOURCE_DIR")) + "/examples/mplm"; }

Scenario scenarioFrom(const std::string& path, const std::string& text) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path) << text;
  return readScenario(path);
}

// The message of the InputError that reading (and setting up) the scenario throws.
std::string errorOf(const std::string& path, const std::string& text) {
  try {
    Scenario sc = scenarioFrom(path, text);
    Comm comm;
    makeSimulation(std::move(sc.problem), comm)->setup();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Mplm3dScenarios, CantileverExampleClampsLoadsAndMonitors) {
  const Scenario sc = readScenario(examplesDir() + "/cantilever3d.toml");
  const ParticleSet& ps = sc.problem.particles;
  ASSERT_GT(ps.size(), 10000u);
  double xmax = 0, loadY = 0, loadOther = 0;
  for (std::size_t k = 0; k < ps.size(); ++k) xmax = std::max(xmax, ps.fixedRow(k)[FX_X]);
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const double* f = ps.fixedRow(k);
    const int c = static_cast<int>(f[CONSTRAINT]);
    // Two planes of particles clamped (X = s/4 and 3s/4 with bonds along X: the cells fill
    // the box from X = 0), nothing else held.
    EXPECT_EQ(c, f[FX_X] < 0.016 ? FIX_ALL : 0) << "particle " << k;
    EXPECT_GT(f[FX_X], 0.0049);
    const bool tip = std::fabs(f[FX_X] - xmax) < 1e-9;
    EXPECT_EQ(f[MONITOR], tip ? 1.0 : 0.0);
    EXPECT_EQ(f[LOAD_Y] < 0, tip);
    loadY += f[LOAD_Y];
    loadOther += std::fabs(f[LOAD_X]) + std::fabs(f[LOAD_Z]);
  }
  EXPECT_NEAR(loadY, -1.0, 1e-12);  // 1 N at load_scale 1
  EXPECT_EQ(loadOther, 0.0);
}

const char* model3d = "steps = 1\n[model]\nname = \"mplm3d\"\n[particles]\n";

TEST(Mplm3dScenarios, LatticeThatDoesNotFitTheBoxIsRefused) {
  const std::string e =
      errorOf("mplm3d_bad/thin.toml", std::string(model3d) +
                                          "generator = \"mplm3d_beam\"\nlength = 1\ndepth = 0.2\n"
                                          "width = 0.01\n");
  EXPECT_NE(e.find("thin.toml:8"), std::string::npos) << e;  // the width line
  EXPECT_NE(e.find("does not fit the box"), std::string::npos) << e;
}

TEST(Mplm3dScenarios, TwoDimensionalParticlesAndGeneratorsAreRefused) {
  // The 2D beam generator for the 3D model, and the 3D one for the 2D model.
  std::string e =
      errorOf("mplm3d_bad/gen2d.toml", std::string(model3d) + "generator = \"mplm_beam\"\n");
  EXPECT_NE(e.find("gen2d.toml:5"), std::string::npos) << e;
  EXPECT_NE(e.find("mplm2d"), std::string::npos) << e;
  e = errorOf("mplm3d_bad/gen3d.toml",
              "steps = 1\n[model]\nname = \"mplm2d\"\n[particles]\ngenerator = \"mplm3d_beam\"\n");
  EXPECT_NE(e.find("gen3d.toml:5"), std::string::npos) << e;
  EXPECT_NE(e.find("model mplm3d"), std::string::npos) << e;
  // A flat particle set (all Z equal) for the 3D model.
  e = errorOf("mplm3d_bad/flat.toml", std::string(model3d) +
                                          "generator = \"square\"\nnx = 5\nny = 5\n"
                                          "spacing = 0.02\n");
  EXPECT_NE(e.find("needs a 3D problem"), std::string::npos) << e;
}

}  // namespace
}  // namespace pdq::mplm3d
