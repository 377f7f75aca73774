// The 3D member generator (mplm3d_beam) and the §4.4.7 scenario file: supports, loads and
// monitors where the file says; bad input stops with the file, line and reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

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
    // Two planes of particles clamped (with bonds along X a plane is s thick: X = s/4, 3s/4,
    // 5s/4 and 7s/4, the cells filling the box from X = 0), nothing else held; the last
    // plane (X > 2.0 − s) loaded.
    EXPECT_EQ(c, f[FX_X] < 0.04 ? FIX_ALL : 0) << "particle " << k;
    EXPECT_GT(f[FX_X], 0.0049);
    const bool tip = f[FX_X] > 2.0 - 0.02;
    EXPECT_EQ(f[MONITOR], tip ? 1.0 : 0.0);
    EXPECT_EQ(f[LOAD_Y] < 0, tip);
    loadY += f[LOAD_Y];
    loadOther += std::fabs(f[LOAD_X]) + std::fabs(f[LOAD_Z]);
  }
  EXPECT_NEAR(loadY, -1.0, 1e-12);  // 1 N at load_scale 1
  EXPECT_EQ(loadOther, 0.0);
}

// Clamped, loaded and supported planes hold every row of every layer, whatever the
// lattice's orientation: in a box of whole strides (s along the bonds, (√3/2)s across the
// rows, √(2/3)s across the layers; the stride box's volume s³/√2 is one particle's) there
// are nx·ny·nz particles, and a plane normal to X holds ny·nz of them.
TEST(Mplm3dScenarios, PlanesHoldEveryRowOfEveryLayer) {
  const double s = 0.02, row = std::sqrt(3.0) / 2 * s, layer = std::sqrt(2.0 / 3) * s;
  struct Case {
    const char *bonds, *layers;
    std::array<double, 3> stride;
  };
  const Case cases[] = {{"x", "z", {s, row, layer}},   // the thesis's orientation
                        {"y", "z", {row, s, layer}},   // rows across the axis
                        {"y", "x", {layer, s, row}}};  // layers across the axis
  const std::array<long, 3> n{12, 5, 3};
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string("bonds ") + c.bonds + ", layers " + c.layers);
    for (const char* loading : {"tip", "top"}) {
      std::ostringstream text;
      text << std::setprecision(17) << "steps = 1\n[model]\nname = \"mplm3d\"\n[particles]\n"
           << "generator = \"mplm3d_beam\"\nbonds_along = \"" << c.bonds << "\"\n"
           << "layers_along = \"" << c.layers << "\"\nlength = " << n[0] * c.stride[0]
           << "\ndepth = " << n[1] * c.stride[1] << "\nwidth = " << n[2] * c.stride[2]
           << "\nclamped_planes = 3\nloading = \"" << loading << "\"\n"
           << "supports = \"" << (loading == std::string("tip") ? "clamped" : "simple")
           << "\"\nsupport_width = " << 2 * c.stride[0] << "\n";
      const Scenario sc = scenarioFrom("mplm3d_planes/beam.toml", text.str());
      const ParticleSet& ps = sc.problem.particles;
      ASSERT_EQ(static_cast<long>(ps.size()), n[0] * n[1] * n[2]);
      long held = 0, loaded = 0, left = 0, right = 0;
      for (std::size_t k = 0; k < ps.size(); ++k) {
        const double* f = ps.fixedRow(k);
        const int bits = static_cast<int>(f[CONSTRAINT]);
        loaded += f[LOAD_Y] < 0;
        if (loading == std::string("tip")) {
          held += bits == FIX_ALL;
          EXPECT_EQ(bits == FIX_ALL, f[FX_X] < 3 * c.stride[0]) << "particle " << k;
          EXPECT_EQ(f[LOAD_Y] < 0, f[FX_X] > (n[0] - 1) * c.stride[0]) << "particle " << k;
        } else {
          left += bits == (FIX_X | FIX_Y | FIX_Z);
          right += bits == (FIX_Y | FIX_Z);
          EXPECT_EQ(f[LOAD_Y] < 0, f[FX_Y] > (n[1] - 1) * c.stride[1]) << "particle " << k;
        }
      }
      if (loading == std::string("tip")) {
        EXPECT_EQ(held, 3 * n[1] * n[2]);
        EXPECT_EQ(loaded, n[1] * n[2]);
      } else {
        // The bottom plane's particles within two strides of each end.
        EXPECT_EQ(left, 2 * n[2]);
        EXPECT_EQ(right, 2 * n[2]);
        EXPECT_EQ(loaded, n[0] * n[2]);
      }
    }
  }
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
