// Halo traffic per step: at most 6 messages in 3D and 4 in 2D, carrying exactly the wall
// particles' alterable attributes; a shuffle step adds at most as many messages again.
#include <gtest/gtest.h>

#include "support/harness.hpp"

namespace pdq {
namespace {

Simulation makeRun(Comm& comm, int nz, bool shuffle, long steps) {
  auto model = test::makeModel(
      "spring", {{"horizon", "1.5"}, {"dt", "0.05"}, {"shuffle", shuffle ? "true" : "false"}});
  ParticleSet ps = test::cubicBlock(model->schema(), 12, 12, nz, 1.0);
  for (std::size_t k = 0; k < ps.size(); ++k) ps.alterRow(k)[3] = (ps.gid[k] % 2 ? 0.2 : -0.2);
  RunConfig cfg;
  cfg.steps = steps;
  cfg.outDir = "out_exchange";
  return Simulation(std::move(model), std::move(ps), cfg, comm);
}

TEST(Exchange, HaloMessagesAndBytes3D) {
  Comm comm;
  Simulation sim = makeRun(comm, 6, false, 3);
  sim.run();
  const StepStats& s = sim.stats();
  EXPECT_LE(s.haloMessages, 6u);
  EXPECT_EQ(s.haloBytes, s.haloWallParticles * sim.particles().schema().nAlter() * sizeof(double));
  if (comm.size() > 1)
    EXPECT_GT(s.haloMessages, 0u);
  else
    EXPECT_EQ(s.haloMessages, 0u);
}

TEST(Exchange, HaloMessages2D) {
  Comm comm;
  Simulation sim = makeRun(comm, 1, false, 3);
  sim.run();
  EXPECT_EQ(sim.decomposition().dim(), 2);
  EXPECT_LE(sim.stats().haloMessages, 4u);
}

TEST(Exchange, ShuffleStepAddsAtMostAsManyAgain) {
  Comm comm;
  Simulation sim = makeRun(comm, 6, true, 40);
  sim.run();
  EXPECT_GT(sim.stats().shuffles, 0u);
  EXPECT_LE(sim.stats().maxShuffleMessages, 12u);
}

}  // namespace
}  // namespace pdq
