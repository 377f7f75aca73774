// A pre-notched plate pulled apart breaks bonds only along the crack path: a square PMB
// plate with a notch from its left edge to the middle row, the top and bottom three rows
// moved apart at constant speed. Every broken bond must straddle the notch's line (its
// midpoint within δ of it), and the crack must run well beyond the notch tip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "pd_fixture.hpp"

namespace pdq::pdtest {
namespace {

void notchedPlate(const std::string& model) {
  Comm comm;
  const int n = 40;
  const double lineY = 19.5, tipX = 12.5, delta = 3.0, speed = 2e-4;
  std::vector<std::pair<std::string, double>> kv{
      {"E", 1.0},         {"horizon", delta},          {"density", 1.0},        {"dt", 0.5},
      {"damping", 0.002}, {"critical_stretch", 0.005}, {"lattice_spacing", 1.0}};
  if (model == "lps") kv.push_back({"nu", 0.25});
  Problem pb = latticeProblem(model, kv, prep::squareLattice(n, n, 1.0));
  pb.params.set("notch", "-1 19.5 12.5 19.5");
  if (model == "pmb") pb.params.set("surface_correction", "true");
  for (std::size_t k = 0; k < pb.ps.size(); ++k) {
    const double Y = pb.ps.fixedRow(k)[1];
    if (Y < 3 || Y > n - 4) {
      pb.ps.fixedRow(k)[pb.col("bc_y")] = 1;
      pb.ps.alterRow(k)[pb.acol("vy")] = Y < 3 ? -speed : speed;
    }
  }
  auto sim = makeSimulation(std::move(pb), 1400, "pd_fracture_out", comm);
  sim->run();
  Particles& P = sim->particles();
  Bonds& B = sim->bonds();
  long broken = 0;
  double farthest = 0, tipReach = -1e9;
  for (std::size_t i = 0; i < P.owned(); ++i)
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      if (B.attr(b)[1] != 0) continue;
      const double* Xi = P.fixed(i);
      const double* Xj = P.fixed(B.partner(b));
      ++broken;
      farthest = std::max(farthest, std::fabs(0.5 * (Xi[1] + Xj[1]) - lineY));
      tipReach = std::max(tipReach, 0.5 * (Xi[0] + Xj[0]));
    }
  Context& ctx = sim->context();
  broken = ctx.count(broken);
  farthest = ctx.max(farthest);
  tipReach = ctx.max(tipReach);
  if (comm.root())
    std::printf(
        "%s notched plate: %ld broken bonds, farthest midpoint %.2f from the line, crack "
        "reaches X = %.1f\n",
        model.c_str(), broken / 2, farthest, tipReach);
  EXPECT_GT(broken, 0);
  EXPECT_LE(farthest, delta) << "a bond broke off the crack path";
  EXPECT_GT(tipReach, tipX + 10) << "the crack did not grow from the notch";
}

TEST(PdFracture, NotchedPlatePmb) { notchedPlate("pmb"); }
TEST(PdFracture, NotchedPlateLps) { notchedPlate("lps"); }

}  // namespace
}  // namespace pdq::pdtest
