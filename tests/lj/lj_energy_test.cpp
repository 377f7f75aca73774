// Energy conservation of a melting fcc crystal (T* = 1.44, density 0.8442, rc = 2.5):
// with the energy-shifted potential the total energy stays within 1e-3 relative over
// 1000 steps at dt = 0.005 (read every 5 steps); with the force-shifted (smooth) cut-off the
// integrator's second order shows: halving dt shrinks the energy error about fourfold.
#include <gtest/gtest.h>

#include <cmath>

#include "lj_setup.hpp"

namespace pdq {
namespace {

using ljtest::makeMelt;
using ljtest::Melt;
using test::global;

struct Drift {
  double e0 = 0, maxError = 0;  // initial total energy, largest |E(n) - E(0)|
  double pe0 = 0, pe = 0;       // potential energy at the start and the end
};

// Runs the melt, reading the total energy every `every` steps and at the end.
Drift run(const Melt& m, long every, Comm& comm) {
  auto sim = makeMelt(m, comm);
  Drift d;
  d.e0 = global(*sim, "total");
  d.pe0 = global(*sim, "potential");
  while (sim->advance())
    if (sim->step() % every == 0)
      d.maxError = std::max(d.maxError, std::fabs(global(*sim, "total") - d.e0));
  d.maxError = std::max(d.maxError, std::fabs(global(*sim, "total") - d.e0));
  d.pe = global(*sim, "potential");
  return d;
}

TEST(LjMelt, EnergyShiftedKeepsTotalEnergyWithin1e3Over1000Steps) {
  Comm comm;
  Melt m;
  m.shift = "energy";
  m.dt = 0.005;
  m.steps = 1000;
  const Drift d = run(m, 5, comm);
  const double n = 4.0 * m.cells * m.cells * m.cells;
  EXPECT_LT(d.maxError / std::fabs(d.e0), 1e-3) << "E0 = " << d.e0;
  // The crystal really melted: half the kinetic energy went into potential energy.
  EXPECT_GT((d.pe - d.pe0) / n, 0.5) << "potential per atom " << d.pe0 / n << " -> " << d.pe / n;
  if (comm.root())
    std::printf("energy-shifted, dt 0.005, 1000 steps: E0/N = %.9f, max |E-E0|/|E0| = %.3e\n",
                d.e0 / n, d.maxError / std::fabs(d.e0));
}

TEST(LjMelt, ForceShiftedEnergyErrorShrinksFourfoldWhenDtHalves) {
  Comm comm;
  Melt m;
  m.shift = "force";
  const double time = 1.25;
  m.dt = 0.005;
  m.steps = std::lround(time / m.dt);
  const Drift coarse = run(m, 5, comm);  // every 0.025 time units
  m.dt = 0.0025;
  m.steps = std::lround(time / m.dt);
  const Drift fine = run(m, 10, comm);
  const double ratio = coarse.maxError / fine.maxError;
  EXPECT_GT(ratio, 3.5);
  EXPECT_LT(ratio, 4.5);
  if (comm.root())
    std::printf(
        "force-shifted, t = %.2f: max |E-E0| = %.3e (dt 0.005), %.3e (dt 0.0025), "
        "ratio %.3f\n",
        time, coarse.maxError, fine.maxError, ratio);
}

}  // namespace
}  // namespace pdq
