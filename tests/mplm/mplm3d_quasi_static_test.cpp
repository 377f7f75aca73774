// The quasi-static solver's assembled stiffness on a 3D lattice whose factor fills in more
// than the solver allows for every load step: the first load step, which relaxes from rest,
// is solved with it in a few Newton steps and the later ones relax with the Gershgorin
// masses. The same bits on 1 and 2 ranks and when restarted after the first load step, and
// the same equilibrium as a run with the Gershgorin masses throughout, within the tolerance.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "quasi_static.hpp"
#include "scenario/scenario.hpp"
#include "support/harness.hpp"

namespace pdq::mplm {
namespace {

constexpr long kSteps = 2;
constexpr double kTolerance = 1e-6;

// A plain cantilever 0.6 x 0.24 x 0.16 m at s = 4 cm (455 particles), clamped at one end,
// loaded at the other below cracking: its factor holds about 10 times the matrix's entries.
std::string member(const std::string& masses) {
  return R"(description = "3D cantilever for the first load step's assembled stiffness"
[model]
name = "mplm3d"
spacing = 0.04
[loading]
load_scale = 2000
[solver]
kind = "quasi_static"
tolerance = 1e-6
load_steps = 2
masses = ")" +
         masses +
         R"("
[particles]
generator = "mplm3d_beam"
length = 0.6
depth = 0.24
width = 0.16
bonds_along = "x"
layers_along = "z"
supports = "clamped"
clamped_planes = 2
loading = "tip"
load = 1.0
)";
}

Problem problemIn(const std::string& dir, const std::string& masses) {
  std::filesystem::create_directories(dir);
  int rank = 0;  // each rank reads its own copy: none reads a file another is writing
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::string path = dir + "/member_" + std::to_string(rank) + ".toml";
  std::ofstream(path) << member(masses);
  Scenario sc = readScenario(path);
  sc.problem.run.outDir = dir;
  sc.problem.output.restartEvery = 1;
  return std::move(sc.problem);
}

pdq::test::State runOn(int ranks, const std::string& dir, const std::string& masses,
                       const std::string& first, std::optional<long> restartFrom = {}) {
  pdq::test::State s;
  test::runOnRanks(
      ranks, 1, [&](Comm&) { return problemIn(dir, masses); }, first, restartFrom,
      [&](Simulation& sim) { s = pdq::test::gatherState(sim); });
  return s;
}

long linesWith(const std::string& file, const std::string& text) {
  std::ifstream in(file);
  long n = 0;
  for (std::string line; std::getline(in, line);) n += line.find(text) != std::string::npos;
  return n;
}

TEST(Mplm3dQuasiStatic, FirstLoadStepByTheAssembledStiffnessWhereItFillsInTooMuchForTheRest) {
  int size = 0, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  ASSERT_EQ(size, 2);
  const std::string first = "qs3d_first_1";
  const pdq::test::State one = runOn(1, first, "assembled", first);
  MPI_Barrier(MPI_COMM_WORLD);
  const pdq::test::State two = runOn(2, "qs3d_first_2", "assembled", first);
  const pdq::test::State resumed = runOn(2, "qs3d_first_resumed", "assembled", first, 1);
  const pdq::test::State diagonal = runOn(1, "qs3d_first_gershgorin", "stiffness", first);
  if (rank != 0) return;
  ASSERT_FALSE(one.particles.empty());
  EXPECT_TRUE(one == two) << "1 and 2 ranks differ";
  EXPECT_TRUE(one == resumed) << "the run restarted after load step 1 differs";

  // Load step 1 by Newton steps, load step 2 with the Gershgorin masses.
  const std::string log = first + "/debug.txt";
  EXPECT_EQ(linesWith(log, "the first load step by the assembled stiffness"), 1) << log;
  EXPECT_EQ(linesWith(log, "quasi-static: assembled stiffness,"), 1) << log;
  const auto rows = test::loadStepRows(first), plain = test::loadStepRows("qs3d_first_gershgorin");
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(kSteps));
  ASSERT_EQ(plain.size(), static_cast<std::size_t>(kSteps));
  std::cout << "load step 1: " << rows[0][2]
            << " iterations (the Gershgorin masses: " << plain[0][2]
            << "); load step 2: " << rows[1][2] << " (" << plain[1][2] << ")\n";
  EXPECT_LE(rows[0][2], 5);
  EXPECT_GT(plain[0][2], 100 * rows[0][2]);
  for (const auto& r : rows) EXPECT_LE(r[5], kTolerance);

  // The same equilibrium: the load-weighted displacement of both runs' load steps agrees to
  // a few times the tolerance.
  for (long k = 0; k < kSteps; ++k) {
    const double u = rows[k][7], v = plain[k][7];
    ASSERT_NE(v, 0);
    EXPECT_LT(std::fabs(u - v), 1e-4 * std::fabs(v)) << "load step " << k + 1;
  }
}

}  // namespace
}  // namespace pdq::mplm
