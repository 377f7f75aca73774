// Halo traffic per step: at most 6 messages in 3D and 4 in 2D, carrying exactly the wall
// particles' alterable attributes that ghosts need (all of them for the spring model, the
// positions for peridynamics); a shuffle step adds at most as many messages again.
#include <gtest/gtest.h>

#include "io/standard_outputs.hpp"
#include "support/harness.hpp"

namespace pdq {
namespace {

std::unique_ptr<Simulation> makeRun(Comm& comm, int nz, bool shuffle, long steps) {
  Problem pb = makeProblem(
      "spring",
      test::params({{"horizon", "1.5"}, {"dt", "0.05"}, {"shuffle", shuffle ? "true" : "false"}}),
      {});
  ParticleSet& ps = pb.particles = test::cubicBlock(pb.model->schema(), 12, 12, nz, 1.0);
  for (std::size_t k = 0; k < ps.size(); ++k) ps.alterRow(k)[3] = (ps.gid[k] % 2 ? 0.2 : -0.2);
  pb.run.steps = steps;
  pb.run.outDir = "out_exchange";
  return makeSimulation(std::move(pb), comm);
}

TEST(Exchange, HaloMessagesAndBytes3D) {
  Comm comm;
  const auto simulation = makeRun(comm, 6, false, 3);
  Simulation& sim = *simulation;
  sim.run();
  const StepStats& s = sim.stats();
  EXPECT_LE(s.haloMessages, 6u);
  EXPECT_EQ(sim.particles().schema().nHalo(), sim.particles().schema().nAlter());
  EXPECT_EQ(s.haloBytes, s.haloWallParticles * sim.particles().schema().nAlter() * sizeof(double));
  if (comm.size() > 1)
    EXPECT_GT(s.haloMessages, 0u);
  else
    EXPECT_EQ(s.haloMessages, 0u);
}

// A state-based model's dilatation is scratch refreshed inside its force step, and its bonds
// read their ghost partners' positions only: the halo carries the positions alone.
TEST(Exchange, LpsHaloCarriesPositionsOnly) {
  Comm comm;
  Problem pb = makeProblem(
      "lps",
      test::params(
          {{"E", "1e9"}, {"nu", "0.25"}, {"horizon", "3.1"}, {"density", "1000"}, {"dt", "1e-5"}}),
      {});
  ParticleSet& ps = pb.particles = test::cubicBlock(pb.model->schema(), 10, 10, 6, 1.0);
  for (std::size_t k = 0; k < ps.size(); ++k) {
    ps.fixedRow(k)[9] = 1.0;  // volume
    ps.alterRow(k)[3] = (ps.gid[k] % 2 ? 0.01 : -0.01);
  }
  pb.run.steps = 3;
  pb.run.outDir = "out_exchange_lps";
  const auto simulation = makeSimulation(std::move(pb), comm);
  Simulation& sim = *simulation;
  sim.run();
  const StepStats& s = sim.stats();
  EXPECT_EQ(sim.particles().schema().nAlter(), 6);
  EXPECT_EQ(s.haloBytes, s.haloWallParticles * 3 * sizeof(double));
  if (comm.size() > 1) {
    EXPECT_GT(s.haloWallParticles, 0u);
  }
}

TEST(Exchange, HaloMessages2D) {
  Comm comm;
  const auto simulation = makeRun(comm, 1, false, 3);
  Simulation& sim = *simulation;
  sim.run();
  EXPECT_EQ(sim.decomposition().dim(), 2);
  EXPECT_LE(sim.stats().haloMessages, 4u);
}

TEST(Exchange, ShuffleStepAddsAtMostAsManyAgain) {
  Comm comm;
  const auto simulation = makeRun(comm, 6, true, 40);
  Simulation& sim = *simulation;
  sim.run();
  EXPECT_GT(sim.stats().shuffles, 0u);
  EXPECT_LE(sim.stats().maxShuffleMessages, 12u);
}

}  // namespace
}  // namespace pdq
