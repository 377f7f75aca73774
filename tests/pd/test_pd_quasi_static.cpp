// The quasi-static solver on PMB: the cantilever of test_pd_elastic (64 x 11, δ = 3 s,
// surface correction, three columns held) under a small tip load relaxes to the linear
// static solution K u = P (K by finite differences, solved directly): the tip deflection
// within 1e-6, the deflection field within 1e-5 (docs/quasi-static.md). PMB is geometrically exact,
// so the axial displacements also carry the second-order shortening of the bent beam (about 1e-4 of
// them at this load), which the linear solution lacks; the load is small enough for the
// deflections' own second-order part (rotation² ≈ 1e-8) and large enough to keep the residual's
// round-off floor (near 1e-8 of the load) below the tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "pd_fixture.hpp"
#include "support/static_reference.hpp"

namespace pdq::pdtest {
namespace {

Problem cantilever(int nx, int ny, double F) {
  Problem pb = latticeProblem(
      "pmb",
      {{"E", 1.0}, {"horizon", 3.0}, {"density", 1.0}, {"dt", 0.5}, {"lattice_spacing", 1.0}},
      prep::squareLattice(nx, ny, 1.0));
  pb.params.set("surface_correction", "true");
  for (std::size_t k = 0; k < pb.ps.size(); ++k) {
    double* f = pb.ps.fixedRow(k);
    if (f[0] < 3) f[pb.col("bc_x")] = f[pb.col("bc_y")] = f[pb.col("bc_z")] = 1;
    if (f[0] == nx - 1) f[pb.col("fy")] = F / ny;
  }
  return pb;
}

// The cantilever relaxed with the given fictitious masses against K u = P; returns the
// iterations.
long expectLinearStaticSolution(Solver::Masses masses, const std::string& dir) {
  Comm comm;
  EXPECT_EQ(comm.size(), 1) << "the direct reference solve runs on one rank";
  const int nx = 64, ny = 11;
  const double F = 1e-5, tol = 1e-7;
  RunConfig cfg;
  cfg.solver.masses = masses;
  cfg.solver.quasiStatic = true;
  cfg.solver.tolerance = tol;
  cfg.solver.maxIterations = 200000;
  cfg.steps = 1;
  cfg.outDir = dir;
  Problem qs = cantilever(nx, ny, F);
  qs.run = cfg;
  auto sim = makeSimulation(std::move(qs), comm);
  sim->run();
  std::ifstream csv(dir + "/quasi_static.csv");
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_FALSE(row.empty());
  if (row.empty()) return 0;
  const long iterations = std::stol(row.substr(row.find(',', 2) + 1));

  RunConfig refCfg;
  refCfg.steps = 0;
  refCfg.outDir = dir + "_ref";
  Problem pb = cantilever(nx, ny, F);
  const int fy = pb.col("fy"), bc = pb.col("bc_x");
  pb.run = refCfg;
  auto ref = makeSimulation(std::move(pb), comm);
  ref->setup();
  Particles& R = ref->particles();
  std::vector<test::FreeDof> dofs;
  for (std::size_t i = 0; i < R.owned(); ++i) {
    if (R.fixed(i)[bc] != 0) continue;
    dofs.push_back({i, 0, 0, 1.0, 0.0});  // mass = density × volume = 1
    dofs.push_back({i, 1, 1, 1.0, R.fixed(i)[fy]});
  }
  const std::vector<double> u = test::linearStatic(*ref, dofs, 1e-6);
  Particles& P = sim->particles();
  double d2 = 0, n2 = 0, tip = 0, tipRef = 0;
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    const std::size_t i = dofs[k].particle;
    EXPECT_EQ(P.gid(i), R.gid(i));
    const int c = dofs[k].alter;
    const double got = P.alter(i)[c] - P.fixed(i)[c];
    if (c == 1) {
      d2 += (got - u[k]) * (got - u[k]);
      n2 += u[k] * u[k];
    }
    if (c == 1 && P.fixed(i)[0] == nx - 1 && P.fixed(i)[1] == (ny - 1) / 2)
      tip = got, tipRef = u[k];
  }
  const double err = std::sqrt(d2 / n2);
  std::printf(
      "pmb cantilever (%s): %ld iterations, deflections |u - u_K|/|u_K| = %.2e, tip %.9g vs %.9g\n",
      dir.c_str(), iterations, err, tip, tipRef);
  EXPECT_LT(err, 1e-5);
  EXPECT_NEAR(tip, tipRef, 1e-6 * std::fabs(tipRef));
  return iterations;
}

TEST(PdQuasiStatic, PmbCantileverRelaxesToTheLinearStaticSolution) {
  expectLinearStaticSolution(Solver::Masses::Stiffness, "pd_quasi_static_out");
}

// The assembled stiffness (a modified Newton iteration) on a model whose forces are per unit
// mass and whose bonds reach three spacings: PMB is geometrically exact, so a few steps.
TEST(PdQuasiStatic, PmbCantileverByTheAssembledStiffness) {
  const long its = expectLinearStaticSolution(Solver::Masses::Assembled, "pd_quasi_static_asm");
  EXPECT_GE(its, 1);
  EXPECT_LE(its, 5);
}

}  // namespace
}  // namespace pdq::pdtest
