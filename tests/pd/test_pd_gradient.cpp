// Generic check every force law must pass: the force on a particle is minus the gradient
// of the model's elastic energy (central finite differences), for PMB and LPS in 2D and
// 3D, at a random deformation that stretches and shears every bond differently.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pd_fixture.hpp"

namespace pdq::pdtest {
namespace {

void checkGradient(const std::string& model, bool threeD, bool correction = false,
                   bool constantInfluence = false) {
  Comm comm;
  const int n = threeD ? 6 : 9;
  std::vector<std::pair<std::string, double>> kv{
      {"E", 2.0}, {"horizon", 2.2}, {"density", 3.0}, {"dt", 0.01}, {"lattice_spacing", 1.0}};
  if (model == "lps") kv.push_back({"nu", 0.3});
  Problem pb = latticeProblem(
      model, kv, threeD ? prep::cubicLattice(n, n, n, 1.0) : prep::squareLattice(n, n, 1.0), 0.5);
  if (!threeD) pb.params.set("thickness", "0.5");
  if (correction) pb.params.set("surface_correction", "true");
  if (constantInfluence) pb.params.set("influence", "constant");
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (std::size_t k = 0; k < pb.ps.size(); ++k)
    for (int a = 0; a < (threeD ? 3 : 2); ++a) pb.ps.alterRow(k)[a] += u(rng);
  auto sim = makeSimulation(std::move(pb), 1, "pd_gradient_out", comm);
  sim->setup();
  Context& ctx = sim->context();
  Particles& P = sim->particles();
  sim->model().force(ctx);
  const double h = 1e-6;
  double worst = 0, scale = 0;
  for (Gid probe : {Gid(1), Gid(n + 2), Gid(n * n / 2 + 3)}) {
    for (int a = 0; a < (threeD ? 3 : 2); ++a) {
      double force = 0;  // on the owning rank, summed so every rank has it
      auto shift = [&](double d) {
        for (std::size_t i = 0; i < P.owned(); ++i)
          if (P.gid(i) == probe) P.alter(i)[a] += d;
        sim->procCube().halo();
      };
      force = ctx.sumOwned([&](std::size_t i) {
        return P.gid(i) == probe ? P.integ(i)[a] * 3.0 * P.fixed(i)[P.schema().fixedIndex("volume")]
                                 : 0.0;
      });
      shift(h);
      const double ep = sim->model().globalValues(ctx)[1];
      shift(-2 * h);
      const double em = sim->model().globalValues(ctx)[1];
      shift(h);
      const double fd = -(ep - em) / (2 * h);
      worst = std::max(worst, std::fabs(fd - force));
      scale = std::max(scale, std::fabs(force));
    }
  }
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(worst, 1e-6 * scale) << model << (threeD ? " 3D" : " 2D");
}

TEST(PdGradient, Pmb2D) { checkGradient("pmb", false); }
TEST(PdGradient, Pmb3D) { checkGradient("pmb", true); }
TEST(PdGradient, PmbSurfaceCorrection3D) { checkGradient("pmb", true, true); }
TEST(PdGradient, Lps2D) { checkGradient("lps", false); }
TEST(PdGradient, Lps3D) { checkGradient("lps", true); }
TEST(PdGradient, Lps3DConstantInfluence) { checkGradient("lps", true, false, true); }

}  // namespace
}  // namespace pdq::pdtest
