// The stiffness mplm3d states at the reference configuration (Model::referenceStiffness,
// which the quasi-static solver assembles instead of probing the forces) is the derivative
// of its forces there: central differences of force() at every DOF of a small reinforced
// member whose interactions are damaged in tension, in compression, both or broken, and
// whose bars are elastic, yielded and beyond yield at the reference, in both kinematics.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "engine/rotation.hpp"
#include "engine/simulation.hpp"
#include "io/standard_outputs.hpp"
#include "models/mplm/3d/attributes.hpp"
#include "scenario/scenario.hpp"

namespace pdq::mplm3d {
namespace {

constexpr double kSpacing = 0.04;
constexpr double kYield = 0.00207;  // the bars' yield strain (the default)

// 0.36 × 0.16 × 0.16 m at s = 4 cm with two #19 bars near its top.
std::unique_ptr<Simulation> member(Comm& comm, const std::string& kinematics) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "pdq_mplm3d_stiffness.toml").string();
  std::ofstream(path) << R"(steps = 1
[model]
name = "mplm3d"
spacing = 0.04
kinematics = ")" << kinematics
                      << R"("
[particles]
generator = "mplm3d_beam"
length = 0.36
depth = 0.16
width = 0.16
bonds_along = "x"
layers_along = "z"
supports = "clamped"
clamped_planes = 1
loading = "tip"
load = 1.0
bar_size = "#19"
bar_count = 2
bar_face = "top"
bar_cover = 0.03
)";
  Scenario sc = readScenario(path);
  std::filesystem::remove(path);
  sc.problem.run.outDir =
      (std::filesystem::temp_directory_path() / "pdq_mplm3d_stiffness_out").string();
  auto sim = makeSimulation(std::move(sc.problem), comm);
  sim->setup();
  return sim;
}

// A state per interaction from its two IDs (both ends' copies alike): concrete undamaged,
// damaged in tension, in compression, in both, or broken; bars with a plastic strain inside
// the elastic range, beyond it either way, or none.
std::array<double, N_BOND> stateOf(Gid a, Gid b) {
  const Gid key = std::min(a, b) * 7 + std::max(a, b) * 3;
  static const double omegaT[5] = {0, 0.3, 0, 0.2, 1};
  static const double omegaC[5] = {0, 0, 0.4, 0.5, 0};
  static const double plastic[7] = {0,      0.5 * kYield, -1.5 * kYield, 3 * kYield,
                                    kYield, -kYield,      -0.4 * kYield};
  std::array<double, N_BOND> s{};
  s[OMEGA_T] = omegaT[key % 5];
  s[OMEGA_C] = omegaC[(key / 5) % 5];
  s[PLASTIC] = plastic[(key / 3) % 7];
  return s;
}

void checkStatedStiffness(const std::string& kinematics) {
  Comm comm;
  auto sim = member(comm, kinematics);
  Context& ctx = sim->context();
  Particles& P = ctx.particles;
  Bonds& B = ctx.bonds;
  const std::size_t n = P.owned();
  ASSERT_EQ(n, P.local()) << "one rank, no ghosts";
  long steel = 0;
  for (std::size_t i = 0; i < n; ++i) steel += isSteel(P.fixed(i));
  ASSERT_GT(steel, 0) << "the member has bars";
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      const auto s = stateOf(P.gid(i), B.partnerGid(b));
      std::copy(s.begin(), s.end(), B.attr(b));
    }

  // The stated blocks and their bounds, by the two particles' local indices.
  ASSERT_TRUE(sim->model().statesStiffness());
  std::map<std::pair<std::size_t, std::size_t>, std::vector<double>> stated, bounds;
  sim->model().referenceStiffness(ctx, [&](std::size_t i, std::size_t j, std::span<const double> K,
                                           std::span<const double> Kb) {
    EXPECT_TRUE(stated.emplace(std::pair{i, j}, std::vector<double>(K.begin(), K.end())).second)
        << "block " << i << ", " << j << " stated twice";
    bounds.emplace(std::pair{i, j}, std::vector<double>(Kb.begin(), Kb.end()));
  });
  // Each row particle's largest stated entry, per translation and rotation row: the scale
  // of the tolerance.
  std::vector<double> scale(2 * n, 0.0);
  for (const auto& [ij, K] : stated)
    for (int a = 0; a < 6; ++a)
      for (int c = 0; c < 6; ++c)
        scale[2 * ij.first + a / 3] =
            std::max(scale[2 * ij.first + a / 3], std::fabs(K[6 * a + c]));

  // Central differences, the interactions' state put back after every evaluation.
  Bonds::Saved saved;
  B.save(saved);
  auto forcesWith = [&](std::size_t j, int d, double h) {
    double* a = P.alter(j);
    const std::array<double, 7> before{a[AX], a[AY], a[AZ], a[QW], a[QX], a[QY], a[QZ]};
    if (d < 3) {
      a[AX + d] += h;
    } else {
      Vec th{0, 0, 0};
      th[d - 3] = h;
      const Quat q = normalised(mul(expRot(th), {a[QW], a[QX], a[QY], a[QZ]}));
      a[QW] = q.w, a[QX] = q.x, a[QY] = q.y, a[QZ] = q.z;
    }
    sim->model().force(ctx);
    std::vector<double> F(6 * n);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) {
        F[6 * i + c] = P.integ(i)[FORCE_X + c];
        F[6 * i + 3 + c] = P.integ(i)[MOMENT_X + c];
      }
    B.restore(saved);
    a[AX] = before[0], a[AY] = before[1], a[AZ] = before[2];
    a[QW] = before[3], a[QX] = before[4], a[QY] = before[5], a[QZ] = before[6];
    return F;
  };
  const std::vector<double> at0 = forcesWith(0, 0, 0.0);
  long compared = 0, nonzero = 0, sided = 0;
  for (std::size_t j = 0; j < n; ++j)
    for (int d = 0; d < 6; ++d) {
      const double h = d < 3 ? 1e-7 * kSpacing : 1e-7;
      const std::vector<double> plus = forcesWith(j, d, h), minus = forcesWith(j, d, -h);
      for (std::size_t i = 0; i < n; ++i)
        for (int a = 0; a < 6; ++a) {
          const std::size_t r = 6 * i + a;
          const double fd = -(plus[r] - minus[r]) / (2 * h);
          const auto it = stated.find({i, j});
          const double k = it == stated.end() ? 0.0 : it->second[6 * a + d];
          const double tol = 1e-6 * scale[2 * i + a / 3];
          ASSERT_NEAR(fd, k, tol) << kinematics << ": row " << P.gid(i) << " DOF " << a
                                  << ", column " << P.gid(j) << " DOF " << d;
          ++compared;
          nonzero += k != 0;
          // The bound: an interaction's block is its stiffer side's, the larger one-sided
          // difference; a particle's own diagonal is at least either side's.
          if (it == stated.end() || (i == j && a != d)) continue;
          const double pulled = std::fabs(plus[r] - at0[r]) / h;
          const double pushed = std::fabs(at0[r] - minus[r]) / h;
          const double kb = std::fabs(bounds.at({i, j})[6 * a + d]);
          if (i != j)
            ASSERT_NEAR(kb, std::max(pulled, pushed), tol)
                << kinematics << ": bound, row " << P.gid(i) << " DOF " << a << ", column "
                << P.gid(j) << " DOF " << d;
          else
            ASSERT_GE(kb, std::max(pulled, pushed) - tol)
                << kinematics << ": bound, row " << P.gid(i) << " DOF " << a;
          sided += std::fabs(pulled - pushed) > tol;
        }
    }
  EXPECT_GT(nonzero, 36 * static_cast<long>(n)) << "the blocks hold the interactions";
  EXPECT_EQ(compared, 36 * static_cast<long>(n * n));
  EXPECT_GT(sided, 0) << "some interaction is stiffer one way";
}

TEST(Mplm3dStiffness, StatedStiffnessIsTheForcesDerivativeCorotational) {
  checkStatedStiffness("corotational");
}

TEST(Mplm3dStiffness, StatedStiffnessIsTheForcesDerivativeSmall) { checkStatedStiffness("small"); }

}  // namespace
}  // namespace pdq::mplm3d
