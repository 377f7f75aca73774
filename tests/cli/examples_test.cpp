// Every scenario under examples/ runs as it is (shortened to a few steps) and its
// thesis-format files can be written by pdq prep.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <utility>
#include <vector>

#include "pdq_process.hpp"

namespace fs = std::filesystem;
using namespace pdq::test;

TEST(CliExamples, EveryScenarioRuns) {
  std::vector<fs::path> scenarios;
  for (const auto& e : fs::recursive_directory_iterator(sourceDir() + "/examples"))
    if (e.path().extension() == ".toml" && e.path().parent_path().filename() != "plugin")
      scenarios.push_back(e.path());
  std::sort(scenarios.begin(), scenarios.end());
  ASSERT_GE(scenarios.size(), 1u);
  for (const auto& sc : scenarios) {
    SCOPED_TRACE(sc.string());
    const std::string dir = freshDir("example_" + sc.stem().string());
    auto r = runPdq({"info", sc.string()}, dir);
    EXPECT_EQ(r.code, 0) << r.all();
    r = runPdq({"run", sc.string(), "--steps", "5", "-q", "--out", "out"}, dir);
    EXPECT_EQ(r.code, 0) << r.all();
    EXPECT_TRUE(fs::exists(dir + "/out/ParticleAlterAttrs.5.rst"));
    r = runPdq({"prep", sc.string(), "-o", "dat"}, dir);
    EXPECT_EQ(r.code, 0) << r.all();
    EXPECT_TRUE(fs::exists(dir + "/dat/ParticleFixedAttrs.dat"));
  }
}

// The reinforced beams of examples/lab/ build as their comments say: the lattice's particle
// count, the bar layers (one line of steel particles each, of the stated area at the stated
// height), the steel plates' particles (OA1: a loading plate over 3 top particles and two
// bearing plates of 3; Janney: two loading plates and two bearing plates of 3) and no load:
// the plates are moved by displacement control.
TEST(CliExamples, LabBeamsBuild) {
  struct Beam {
    std::string name;
    int columns, rows;  // of the lattice: even rows have `columns` particles, odd ones one fewer
    std::vector<std::pair<double, double>> bars;  // area, height
    int plateParticles;
  };
  const double pi = std::acos(-1.0);
  auto area = [&](double d, int n) { return n * pi * d * d / 4; };
  for (const Beam& b :
       {Beam{"vecchio_shim_oa1", 57, 9, {{area(0.0299, 2), 0.064}, {area(0.0252, 2), 0.128}}, 9},
        Beam{"janney_flexure", 61, 7, {{area(0.02764, 1), 0.094}}, 12}}) {
    SCOPED_TRACE(b.name);
    const std::string dir = freshDir("lab_" + b.name);
    const auto r =
        runPdq({"prep", sourceDir() + "/examples/lab/" + b.name + ".toml", "-o", "dat"}, dir);
    ASSERT_EQ(r.code, 0) << r.all();
    std::istringstream in(readFile(dir + "/dat/ParticleFixedAttrs.dat"));
    int concrete = 0, plate = 0, loaded = 0;
    std::vector<int> steel(b.bars.size(), 0);
    for (std::string line; std::getline(in, line);) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream row(line);
      double id, x, y, z, material, bar, link, barArea, inertia, constraint, loadX, loadY;
      row >> id >> x >> y >> z >> material >> bar >> link >> barArea >> inertia >> constraint >>
          loadX >> loadY;
      const auto layer = static_cast<std::size_t>(bar) - 1;
      if (material == 1 && layer >= b.bars.size()) {
        ++plate;
      } else if (material == 1) {
        ++steel[layer];
        EXPECT_NEAR(barArea, b.bars[layer].first, 1e-9 * b.bars[layer].first);
        EXPECT_NEAR(y, b.bars[layer].second, 1e-9);
      } else {
        ++concrete;
      }
      if (loadY != 0) ++loaded;
    }
    EXPECT_EQ(concrete, (b.rows + 1) / 2 * b.columns + b.rows / 2 * (b.columns - 1));
    for (const int n : steel) EXPECT_EQ(n, b.columns);  // each bar the lattice's length
    EXPECT_EQ(plate, b.plateParticles);
    EXPECT_EQ(loaded, 0);
  }
}

// The notched plain beam turns freely on its supports, as on the test's rollers: one bottom
// particle held at each support line (pinned at x = 25 mm, on a roller at 150 mm); held over
// several particles the supports would clamp the beam's ends.
TEST(CliExamples, NotchedBeamRestsOnOneParticlePerSupport) {
  const std::string dir = freshDir("lab_gregoire_notched");
  const auto r =
      runPdq({"prep", sourceDir() + "/examples/lab/gregoire_notched.toml", "-o", "dat"}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  std::istringstream in(readFile(dir + "/dat/ParticleFixedAttrs.dat"));
  std::vector<std::pair<double, int>> held;  // x, constraint
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    double id, x, y, z, material, bar, link, barArea, inertia, constraint;
    row >> id >> x >> y >> z >> material >> bar >> link >> barArea >> inertia >> constraint;
    if (constraint != 0) {
      EXPECT_NEAR(y, 0.0, 1e-12);
      held.emplace_back(x, static_cast<int>(constraint));
    }
  }
  std::sort(held.begin(), held.end());
  ASSERT_EQ(held.size(), 2u);
  EXPECT_NEAR(held[0].first, 0.025, 1e-9);
  EXPECT_EQ(held[0].second, 3);  // u_x and u_y held: a pin
  EXPECT_NEAR(held[1].first, 0.15, 1e-9);
  EXPECT_EQ(held[1].second, 2);  // u_y held: a roller
}
