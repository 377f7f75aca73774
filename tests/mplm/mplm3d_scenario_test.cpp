// The 3D member generator (mplm3d_beam) and the §4.4.7 scenario file: supports, loads and
// monitors where the file says; bad input stops with the file, line and reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <numbers>
#include <sstream>

#include "engine/error.hpp"
#include "io/standard_outputs.hpp"
#include "models/mplm/3d/attributes.hpp"
#include "prep/rebar.hpp"
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
          EXPECT_EQ(f[LOAD_Y]<0, f[FX_X]>(n[0] - 1) * c.stride[0]) << "particle " << k;
        } else {
          left += bits == (FIX_X | FIX_Y | FIX_Z);
          right += bits == (FIX_Y | FIX_Z);
          EXPECT_EQ(f[LOAD_Y]<0, f[FX_Y]>(n[1] - 1) * c.stride[1]) << "particle " << k;
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

// Steel particles of bar `id` (1, 2, ...), in the order the generator wrote them.
std::vector<const double*> barRows(const ParticleSet& ps, int id) {
  std::vector<const double*> rows;
  for (std::size_t k = 0; k < ps.size(); ++k)
    if (isSteel(ps.fixedRow(k)) && ps.fixedRow(k)[BAR] == id) rows.push_back(ps.fixedRow(k));
  return rows;
}

// §4.4.9's member: two #19 bars (ASTM A615M: 19.1 mm, 284 mm²) 4 cm clear of the bottom
// and the sides, #13 hoops (12.7 mm, 129 mm²) every 8 cm from X = 0.04 m with 2.73 cm of
// clear cover; §4.4.8's bars 4 cm clear of the top instead, clamped with the concrete.
TEST(Mplm3dScenarios, BarsAndHoopsWhereTheFilesSay) {
  const Scenario sc = readScenario(examplesDir() + "/rc_beam3d.toml");
  const ParticleSet& ps = sc.problem.particles;
  const double s = 0.02, r19 = 0.0191 / 2, r13 = 0.0127 / 2;
  for (int id : {1, 2}) {
    const auto bar = barRows(ps, id);
    // From the first plane of particles (X = s/4) to the last (2 − s/4): 100 segments.
    ASSERT_EQ(bar.size(), 101u) << "bar " << id;
    for (std::size_t k = 0; k < bar.size(); ++k) {
      EXPECT_NEAR(bar[k][FX_X], s / 4 + 1.99 * static_cast<double>(k) / 100, 1e-12);
      EXPECT_NEAR(bar[k][FX_Y], 0.04 + r19, 1e-12);
      EXPECT_NEAR(bar[k][FX_Z], id == 1 ? 0.04 + r19 : 0.16 - 0.04 - r19, 1e-12);
      EXPECT_DOUBLE_EQ(bar[k][AREA], 284e-6);
      const double I = std::numbers::pi * std::pow(0.0191, 4) / 64;
      EXPECT_NEAR(bar[k][SECOND_MOMENT], I, 1e-12 * I);
      EXPECT_EQ(bar[k][LINK], k % 2 == 0 ? 1.0 : 0.0);  // every other one, the first included
    }
  }
  // Hoops at 0.04, 0.12, ..., 1.96 m; the centre line 2.73 cm + r13 inside every face: a
  // 0.2827 × 0.0927 m rectangle of 15 + 5 segments a side, 40 particles.
  const double lo = 0.0273 + r13, yHi = 0.35 - lo, zHi = 0.16 - lo;
  int hoops = 0;
  for (int id = 3; !barRows(ps, id).empty(); ++id, ++hoops) {
    const auto hoop = barRows(ps, id);
    ASSERT_EQ(hoop.size(), 40u) << "hoop " << id;
    for (const double* f : hoop) {
      EXPECT_NEAR(f[FX_X], 0.04 + 0.08 * (id - 3), 1e-12);
      const bool onY = std::fabs(f[FX_Y] - lo) < 1e-12 || std::fabs(f[FX_Y] - yHi) < 1e-12;
      const bool onZ = std::fabs(f[FX_Z] - lo) < 1e-12 || std::fabs(f[FX_Z] - zHi) < 1e-12;
      EXPECT_TRUE(onY || onZ) << "off the hoop's centre line: " << f[FX_Y] << " " << f[FX_Z];
      EXPECT_GE(f[FX_Y], lo - 1e-12);
      EXPECT_LE(f[FX_Z], zHi + 1e-12);
      EXPECT_DOUBLE_EQ(f[AREA], 129e-6);
    }
  }
  EXPECT_EQ(hoops, 25);
  std::size_t steel = 0;
  for (std::size_t k = 0; k < ps.size(); ++k) steel += isSteel(ps.fixedRow(k));
  EXPECT_EQ(steel, 2 * 101u + 25 * 40u);

  const Scenario cant = readScenario(examplesDir() + "/rc_cantilever3d.toml");
  for (int id : {1, 2})
    for (const double* f : barRows(cant.problem.particles, id)) {
      EXPECT_NEAR(f[FX_Y], 0.35 - 0.04 - r19, 1e-12);  // at the top: the tension face
      EXPECT_EQ(static_cast<int>(f[CONSTRAINT]), f[FX_X] < 2 * s ? FIX_ALL : 0);
    }
}

// The model's interactions in a reinforced member: steel particles of one bar or hoop with
// their neighbours along it only (two, one at a bar's ends), never with another bar's; a
// linking particle with the concrete within s, a non-linking one with none.
TEST(Mplm3dScenarios, SteelInteractsAlongItsBarAndLinksEveryOtherParticle) {
  Scenario sc = scenarioFrom("mplm3d_steel/member.toml", R"(steps = 1
[model]
name = "mplm3d"
[particles]
generator = "mplm3d_beam"
length = 0.3
depth = 0.16
width = 0.12
supports = "none"
loading = "none"
bar_size = "#16"
bar_y = [0.03, 0.03, 0.125]
bar_z = [0.03, 0.09, 0.06]
stirrup_diameter = 0.008
stirrup_spacing = 0.1
stirrup_cover = 0.01
)");
  Comm comm;
  const auto sim = makeSimulation(std::move(sc.problem), comm);
  sim->setup();
  const Particles& P = sim->context().particles;
  const Bonds& B = sim->context().bonds;
  std::map<double, int> barSize;
  for (std::size_t i = 0; i < P.owned(); ++i)
    if (isSteel(P.fixed(i))) ++barSize[P.fixed(i)[BAR]];
  ASSERT_EQ(barSize.size(), 6u);  // three bars, three hoops (X = 0.05, 0.15, 0.25)
  int links = 0;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    const double* f = P.fixed(i);
    if (!isSteel(f)) continue;
    int alongBar = 0, concrete = 0;
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      const double* g = P.fixed(static_cast<std::size_t>(B.partner(b)));
      if (isSteel(g)) {
        EXPECT_EQ(g[BAR], f[BAR]);
        ++alongBar;
      } else {
        ++concrete;
        const double d = std::hypot(g[FX_X] - f[FX_X], g[FX_Y] - f[FX_Y], g[FX_Z] - f[FX_Z]);
        EXPECT_LE(d, 0.02 * (1 + 1e-6));
        EXPECT_GT(d, 0);
      }
    }
    const bool bar = f[BAR] <= 3;
    const bool end = bar && (f[FX_X] < 0.01 || f[FX_X] > 0.29);
    EXPECT_EQ(alongBar, end ? 1 : 2) << "bar " << f[BAR] << " at X = " << f[FX_X];
    if (f[LINK] != 0) {
      EXPECT_GT(concrete, 0);
      ++links;
    } else {
      EXPECT_EQ(concrete, 0);
    }
  }
  EXPECT_GT(links, 0);
}

// Reinforcement that cannot be built stops at the key's line with the reason.
TEST(Mplm3dScenarios, BadReinforcementIsRefused) {
  const std::string member = std::string("steps = 1\n[model]\nname = \"mplm3d\"\n[particles]\n") +
                             "generator = \"mplm3d_beam\"\nlength = 0.4\ndepth = 0.2\n"
                             "width = 0.12\nbar_size = \"#13\"\n";  // bar_size: line 9
  struct Bad {
    std::string keys, where, why;
  };
  const Bad cases[] = {
      {"bar_y = [0.1, 0.195]\nbar_z = [0.06, 0.06]\n", ":10:", "lies outside the"},
      {"bar_y = [0.1, 0.1]\nbar_z = [0.06, -0.01]\n", ":10:", "lies outside the"},
      {"bar_y = [0.1]\nbar_z = [0.06, 0.07]\n", ":11:", "the same number of bars"},
      {"bar_cover = 0.07\n", ":10:", "larger than half the section"},
      {"bar_count = 5\nbar_cover = 0.03\n", ":10:", "do not fit in a row"},
      {"stirrup_size = \"#10\"\nstirrup_spacing = 0.015\n", ":11:", "below the lattice spacing"},
      {"stirrup_size = \"#10\"\nstirrup_spacing = 0.1\nstirrup_cover = 0.055\n",
       ":12:", "larger than half the section"},
      {"stirrup_size = \"#10\"\nstirrup_spacing = 0.1\nstirrup_cover = 0.045\n",
       ":12:", "too small for the lattice spacing"},
      {"stirrup_size = \"#12\"\n", ":10:", "not an ASTM bar size"},
      {"bar_diameter = 0.01\n", ":10:", "give bar_size or bar_diameter, not both"},
  };
  for (const Bad& c : cases) {
    SCOPED_TRACE(c.keys);
    const std::string e = errorOf("mplm3d_bad/rebar.toml", member + c.keys);
    EXPECT_NE(e.find("rebar.toml" + c.where), std::string::npos) << e;
    EXPECT_NE(e.find(c.why), std::string::npos) << e;
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

// A fracture energy so small that the interactions would break at their elastic limit
// (α_t ≤ 1) stops at its line, as does one of zero.
TEST(Mplm3dScenarios, FractureEnergyBelowTheElasticLimitIsRefused) {
  auto member = [](const std::string& gf) {
    return "steps = 1\n[model]\nname = \"mplm3d\"\nfracture_energy = " + gf +
           "\n[particles]\ngenerator = \"mplm3d_beam\"\nlength = 0.2\ndepth = 0.1\n"
           "width = 0.1\n";
  };
  std::string e = errorOf("mplm3d_bad/gf.toml", member("5"));
  EXPECT_NE(e.find("gf.toml:4: fracture_energy gives a tensile_ratio <= 1"), std::string::npos)
      << e;
  e = errorOf("mplm3d_bad/gf0.toml", member("0"));
  EXPECT_NE(e.find("gf0.toml:4: fracture_energy must be > 0"), std::string::npos) << e;
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
  EXPECT_NE(e.find("flat.toml:5: mplm3d needs a 3D problem"), std::string::npos) << e;
}

}  // namespace
}  // namespace pdq::mplm3d
