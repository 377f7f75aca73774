// MPLM scenarios: a scenario whose lattice spacing disagrees with the model's is refused;
// supports, bearings and displacement control set by [[particles.set]] act as they should;
// mplm_beam's laboratory specimens (overhangs, a notch, steel plates) are where the keys put
// them, and its plates spread a load and turn on their supports.
#include "scenario/scenario.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <tuple>
#include <vector>

#include "engine/error.hpp"
#include "engine/simulation.hpp"
#include "io/standard_outputs.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "prep/hexagonal.hpp"
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

// mplm_beam with overhangs and a notch: a 0.2 m span with 0.04 m beyond each support and a
// slot 0.05 m deep, 0.03 m wide at midspan. The lattice covers the span and the overhangs;
// no concrete particle lies in the slot and every other point of the rectangle is there;
// the supports are the bottom particles within support_width/2 of x = 0.04 and 0.24; the
// monitored particles are the bottom ones nearest midspan, one each side of the slot. A
// notch narrower than the spacing, or an overhang that is not a whole number of spacings,
// is refused at the generator's line.
TEST(MplmScenarios, BeamWithOverhangsAndNotch) {
  const double s = 0.02, span = 0.2, over = 0.04, depth = 0.12, length = span + 2 * over;
  const double notchDepth = 0.05, notchWidth = 0.03, mid = length / 2, tol = 1e-9;
  const std::string text = fmt::format(R"(steps = 1
[model]
name = "mplm2d"
[particles]
generator = "mplm_beam"
span = {}
overhang = {}
depth = {}
notch_depth = {}
notch_width = {}
support_width = 0.04
line_load = 0
)",
                                       span, over, depth, notchDepth, notchWidth);
  Scenario sc = scenarioFrom("mplm_lab_beam/notched.toml", text);
  const ParticleSet& ps = sc.problem.particles;
  std::size_t inSlot = 0, lattice = 0;
  for (const auto& p :
       prep::hexagonalRectangle(length, depth, s, prep::HexOrientation::BondsAlongX)) {
    const bool slot = p[1] < notchDepth && std::fabs(p[0] - mid) <= notchWidth / 2 + tol;
    inSlot += slot;
    lattice += !slot;
  }
  ASSERT_GT(inSlot, 3u);
  EXPECT_EQ(ps.size(), lattice);
  double xMax = 0;
  std::vector<double> pinned, roller, monitored;
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const double* f = ps.fixedRow(k);
    xMax = std::max(xMax, f[0]);
    EXPECT_FALSE(f[1] < notchDepth && std::fabs(f[0] - mid) <= notchWidth / 2 + tol)
        << "a particle in the notch at " << f[0] << ", " << f[1];
    const int c = static_cast<int>(f[CONSTRAINT]);
    if (c == (FIX_X | FIX_Y)) pinned.push_back(f[0]);
    if (c == FIX_Y) roller.push_back(f[0]);
    if (c != 0) {
      EXPECT_LT(f[1], tol) << "a support off the bottom face";
    }
    if (f[MONITOR] != 0) monitored.push_back(f[0]);
  }
  EXPECT_NEAR(xMax, length, tol);
  EXPECT_EQ(pinned, (std::vector<double>{over - s, over, over + s}));
  ASSERT_EQ(roller.size(), 3u);
  EXPECT_NEAR(roller[1], length - over, tol);
  ASSERT_EQ(monitored.size(), 2u);
  EXPECT_NEAR(monitored[0], mid - s, tol);  // the slot is mid ± 0.015
  EXPECT_NEAR(monitored[1], mid + s, tol);

  for (const auto& [from, to, expected] :
       {std::tuple{"notch_width = 0.03", "notch_width = 0.01", "is less than the spacing"},
        std::tuple{"overhang = 0.04", "overhang = 0.03", "the overhang, 0.0299"}}) {
    std::string bad = text;
    bad.replace(bad.find(from), std::string(from).size(), to);
    try {
      scenarioFrom("mplm_lab_beam/bad.toml", bad);
      ADD_FAILURE() << to << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("bad.toml:5:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
}

// mplm_beam's bar layers: bar_diameter, bar_centroid and bar_count as arrays give one line
// of steel particles per layer at its height, carrying the summed area and second moment
// of its bars; arrays of different lengths are refused at their line.
TEST(MplmScenarios, BeamWithBarLayers) {
  const std::string text = R"(steps = 1
[model]
name = "mplm2d"
[particles]
generator = "mplm_beam"
span = 0.4
depth = 0.2
bar_diameter = [0.02, 0.01]
bar_centroid = [0.03, 0.07]
bar_count = [2, 3]
)";
  Scenario sc = scenarioFrom("mplm_bar_layers/two.toml", text);
  const ParticleSet& ps = sc.problem.particles;
  std::map<int, std::vector<const double*>> bars;
  for (std::size_t k = 0; k < ps.size(); ++k)
    if (isSteel(ps.fixedRow(k)))
      bars[static_cast<int>(ps.fixedRow(k)[BAR])].push_back(ps.fixedRow(k));
  ASSERT_EQ(bars.size(), 2u);
  const double pi = std::numbers::pi;
  const std::array<std::array<double, 3>, 2> expected = {
      {{0.03, 2 * pi * 0.02 * 0.02 / 4, 2 * pi * std::pow(0.02, 4) / 64},
       {0.07, 3 * pi * 0.01 * 0.01 / 4, 3 * pi * std::pow(0.01, 4) / 64}}};
  int layer = 0;
  for (const auto& [id, row] : bars) {
    EXPECT_EQ(row.size(), 21u);  // 0.4 m at s = 0.02, both ends
    for (const double* f : row) {
      EXPECT_DOUBLE_EQ(f[1], expected[layer][0]);
      EXPECT_DOUBLE_EQ(f[AREA], expected[layer][1]);
      EXPECT_DOUBLE_EQ(f[SECOND_MOMENT], expected[layer][2]);
    }
    ++layer;
  }
  std::string bad = text;
  bad.replace(bad.find("bar_count = [2, 3]"), 18, "bar_count = [2, 3, 1]");
  try {
    scenarioFrom("mplm_bar_layers/bad.toml", bad);
    ADD_FAILURE() << "three counts for two layers were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.toml:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bar_diameter has 2 values where another bar_ key has 3"),
              std::string::npos)
        << e.what();
  }
}

// mplm_beam's steel plates: a loading plate at midspan over the top particles within
// plate_width/2 and bearing plates under the supports, each plate particle one spacing
// above or below the face particle it covers, all of them linked, the load shared by the
// loading plate's particles, each bearing plate held at its particle on the support's line
// only. Loaded elastically to equilibrium, the loading plate moves as one: the spread of its
// particles' vertical displacements is under a fifth of the covered particles' spread when
// the same load is put on them directly; each bearing plate turns on its pin (its end
// particles move opposite ways) and no other particle is held.
TEST(MplmScenarios, BeamWithSteelPlates) {
  const double s = 0.02, pitch = std::sqrt(3.0) / 2 * s, over = 0.04, mid = 0.16, tol = 1e-9;
  auto text = [](const std::string& plates) {
    return fmt::format(R"([model]
name = "mplm2d"
damage = false
[particles]
generator = "mplm_beam"
span = 0.24
depth = 0.08
overhang = 0.04
support_width = 0.04
line_load = 0
{}
[solver]
kind = "quasi_static"
tolerance = 1e-6
max_iterations = 100000
load_steps = 1
)",
                       plates);
  };
  const double top = 4 * pitch;
  const std::string noPlates = R"([[particles.set]]
attribute = "load_y"
value = -333.33333333333333
x = [0.139, 0.181]
y = [0.06, 0.08])";
  const std::string plates =
      "load_plates = [0.16]\nplate_width = 0.04\nplate_load = 1000\nbearing_plates = true";
  // Vertical displacement of every particle by position after the run.
  struct Moved {
    double x, y, uy;
    bool steel;
    int constraint;
  };
  auto run = [&](const std::string& dir, const std::string& extra) {
    Scenario sc = scenarioFrom(dir + "/beam.toml", text(extra));
    double load = 0;
    for (std::size_t k = 0; k < sc.problem.particles.size(); ++k)
      load += sc.problem.particles.fixedRow(k)[LOAD_Y];
    EXPECT_NEAR(load, -1000, 1e-9);
    Comm comm;
    auto sim = simulation(sc, comm);
    sim->run();
    std::vector<Moved> out;
    Particles& P = sim->particles();
    for (std::size_t i = 0; i < P.owned(); ++i) {
      const double* f = P.fixed(i);
      out.push_back({f[FX_X], f[FX_Y], P.alter(i)[AY] - f[FX_Y], isSteel(f),
                     static_cast<int>(f[CONSTRAINT])});
    }
    return out;
  };
  auto coveredSpread = [&](const std::vector<Moved>& ps) {
    double lo = 1e300, hi = -1e300;
    int n = 0;
    for (const Moved& m : ps)
      if (!m.steel && std::fabs(m.y - top) < tol && std::fabs(m.x - mid) <= 0.02 + tol) {
        lo = std::min(lo, m.uy);
        hi = std::max(hi, m.uy);
        ++n;
      }
    EXPECT_EQ(n, 3);
    EXPECT_LT(hi, 0.0);
    return hi - lo;
  };
  const auto bare = run("mplm_plates/bare", noPlates);
  const auto plated = run("mplm_plates/plated", plates);
  std::vector<Moved> loading, leftBearing;
  int held = 0;
  for (const Moved& m : plated) {
    if (m.constraint != 0) {
      ++held;
      EXPECT_TRUE(m.steel);
      EXPECT_NEAR(m.y, -s, tol);
      EXPECT_TRUE(std::fabs(m.x - over) < tol || std::fabs(m.x - (mid * 2 - over)) < tol) << m.x;
    }
    if (m.steel && std::fabs(m.y - (top + s)) < tol) loading.push_back(m);
    if (m.steel && std::fabs(m.y + s) < tol && m.x < mid) leftBearing.push_back(m);
  }
  EXPECT_EQ(held, 2);
  ASSERT_EQ(loading.size(), 3u);
  EXPECT_NEAR(loading.front().x, mid - s, tol);
  EXPECT_NEAR(loading.back().x, mid + s, tol);
  ASSERT_EQ(leftBearing.size(), 3u);
  EXPECT_EQ(leftBearing[1].uy, 0.0);
  EXPECT_LT(leftBearing.front().uy * leftBearing.back().uy, 0.0);  // turned on its pin
  const double spreadBare = coveredSpread(bare);
  const auto [lo, hi] = std::minmax_element(
      loading.begin(), loading.end(), [](const Moved& a, const Moved& b) { return a.uy < b.uy; });
  EXPECT_LT(hi->uy - lo->uy, 0.2 * spreadBare) << hi->uy - lo->uy << " against " << spreadBare;

  // Every plate particle bonded to the concrete; a plate that covers nothing is refused.
  Scenario sc = scenarioFrom("mplm_plates/built.toml", text(plates));
  int steel = 0;
  for (std::size_t k = 0; k < sc.problem.particles.size(); ++k) {
    const double* f = sc.problem.particles.fixedRow(k);
    if (isSteel(f)) {
      ++steel;
      EXPECT_EQ(f[LINK], 1.0);
      EXPECT_NEAR(f[AREA], 0.025 * 0.12, 1e-15);
    }
  }
  EXPECT_EQ(steel, 9);
  try {
    scenarioFrom("mplm_plates/bad.toml", text("load_plates = [0.17]\nplate_width = 0.01"));
    ADD_FAILURE() << "a plate covering no particle was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.toml:5:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("covers no top particle"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pdq::mplm
