// pdq and LAMMPS's PERI package (peri/pmb, peri/lps) on the same undamped, undamaged 3D
// block for 200 steps: every particle's displacement agrees to 1e-9 of the largest one,
// from a velocity field, and (PMB) from rest pulled at its top layer from step 0, which
// only a velocity Verlet started right (half a kick on the first step) reproduces.
// Fails where LAMMPS's lmp is missing (installed by `make test`: tools/install-deps.sh test).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "lammps_peer.hpp"
#include "pd_fixture.hpp"

namespace pdq::pdtest {
namespace {

void sideBySide(const std::string& model, double topLoad = 0) {
  Comm comm;
  lammps::Block bl;
  bl.n = 10;
  if (topLoad != 0) {
    bl.v0 = 0;
    bl.topLoad = topLoad;
  }
  const long steps = 200;
  const std::string dir = std::filesystem::absolute(
      "pd_lammps_" + model + (topLoad != 0 ? "_loaded" : "") + "_np" + std::to_string(comm.size()));
  if (comm.root()) std::filesystem::create_directories(dir);
  pdq::Problem pb = makeProblem(model, lammps::blockParams(bl, model), {});
  pb.particles = lammps::blockParticles(bl, pb.model->schema());
  if (comm.root()) lammps::writeLammps(bl, model, steps, dir, pb.particles);
  pb.run.steps = steps;
  pb.run.outDir = dir + "/pdq_out";
  const auto sim = pdq::makeSimulation(std::move(pb), comm);
  sim->run();
  const auto state = gatherAlter(*sim);
  if (!comm.root()) return;
  lammps::Displacements pdqU;
  for (auto& [id, row] : state) {
    // Reference positions are the lattice's: (i, j, k) s from the ID.
    const long q = id - 1;
    const double X[3] = {(q % bl.n) * bl.s, (q / bl.n % bl.n) * bl.s, (q / (bl.n * bl.n)) * bl.s};
    pdqU[id] = {row[0] - X[0], row[1] - X[1], row[2] - X[2]};
  }
  // A clean environment, so that lmp does not take itself for part of this MPI job.
  ASSERT_TRUE(std::filesystem::exists(PDQ_LMP))
      << "LAMMPS's lmp was not found when pdq was configured: install it "
         "(tools/install-deps.sh test) and configure again";
  const std::string cmd = "cd '" + dir +
                          "' && env -i PATH=/usr/bin:/bin HOME=/tmp OMP_NUM_THREADS=1 " PDQ_LMP
                          " -in lammps.in -log lammps.log > lmp.out 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << "LAMMPS failed, see " << dir << "/lmp.out";
  const lammps::Difference d =
      lammps::compare(pdqU, lammps::readDisplacements(dir + "/lammps.dump"), "lammps.dump");
  std::printf(
      "%s vs LAMMPS: %zu particles, max |u| %.3e, max |u_pdq - u_lammps| %.3e "
      "(relative %.2e)\n",
      model.c_str(), d.particles, d.maxU, d.maxDiff, d.relative());
  EXPECT_EQ(d.particles, std::size_t(bl.n * bl.n * bl.n));
  EXPECT_GT(d.maxU, 1e-6);
  EXPECT_LT(d.relative(), 1e-9);
}

TEST(PdLammps, Pmb) { sideBySide("pmb"); }
TEST(PdLammps, Lps) { sideBySide("lps"); }
TEST(PdLammps, PmbLoadedFromRest) { sideBySide("pmb", 2.0e4); }

}  // namespace
}  // namespace pdq::pdtest
