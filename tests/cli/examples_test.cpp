// Every scenario under examples/ runs as it is (shortened to a few steps) and its
// thesis-format files can be written by pdq prep.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

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

// The reinforced beams of bench/lab/ (too long to run here) build as their comments say:
// the lattice's particle count, one bar of the stated area at the stated height, the steel
// plates' particles (OA1: a loading plate over 4 top particles and two bearing plates of 3),
// and the loads: 1 kN on OA1's plate or 1000 / 0.9144 N per load point (Janney) at
// load_scale 1.
TEST(CliExamples, LabBeamsBuild) {
  struct Beam {
    std::string name;
    int columns, rows;  // of the lattice: even rows have `columns` particles, odd ones one fewer
    double barArea, barY, plateLoad;
    int loaded, plateParticles;
  };
  const double pi = std::acos(-1.0);
  for (const Beam& b :
       {Beam{"vecchio_shim_oa1", 113, 18, pi * 0.05528 * 0.05528 / 4, 0.0907, -1000.0, 4, 10},
        Beam{"janney_flexure", 121, 14, pi * 0.02764 * 0.02764 / 4, 0.094, -2 * 1000 / 0.9144, 4,
             0}}) {
    SCOPED_TRACE(b.name);
    const std::string dir = freshDir("lab_" + b.name);
    const auto r =
        runPdq({"prep", sourceDir() + "/bench/lab/" + b.name + ".toml", "-o", "dat"}, dir);
    ASSERT_EQ(r.code, 0) << r.all();
    std::istringstream in(readFile(dir + "/dat/ParticleFixedAttrs.dat"));
    int concrete = 0, steel = 0, plate = 0, loaded = 0;
    double load = 0;
    for (std::string line; std::getline(in, line);) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream row(line);
      double id, x, y, z, material, bar, link, area, inertia, constraint, loadX, loadY;
      row >> id >> x >> y >> z >> material >> bar >> link >> area >> inertia >> constraint >>
          loadX >> loadY;
      if (material == 1 && bar > 1) {
        ++plate;
      } else if (material == 1) {
        ++steel;
        EXPECT_NEAR(area, b.barArea, 1e-6 * b.barArea);
        EXPECT_NEAR(y, b.barY, 1e-9);
      } else {
        ++concrete;
      }
      if (loadY != 0) ++loaded, load += loadY;
    }
    EXPECT_EQ(concrete, (b.rows / 2) * (2 * b.columns - 1));
    EXPECT_EQ(steel, b.columns);  // one bar the lattice's length, at the spacing
    EXPECT_EQ(plate, b.plateParticles);
    EXPECT_EQ(loaded, b.loaded);
    EXPECT_NEAR(load, b.plateLoad, 1e-9 * std::fabs(b.plateLoad));
  }
}
