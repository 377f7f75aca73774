// The perfect fcc crystal: the model's potential energy per atom equals a direct sum over
// an infinite fcc lattice written out here, independently of the model's pair law; the
// forces vanish by symmetry; and away from the lattice the forces are minus the gradient
// of the potential energy (central finite differences).
#include <gtest/gtest.h>

#include <cmath>

#include "engine/error.hpp"
#include "lj_setup.hpp"

namespace pdq {
namespace {

using ljtest::makeMelt;
using ljtest::Melt;
using test::global;

// Energy per atom of an infinite fcc lattice of lattice constant a: half the sum of the
// truncated pair energies between the atom at the origin and every other site.
double directLatticeSum(double a, double eps, double sigma, double rc, const std::string& shift) {
  auto lj = [&](double r) { return 4 * eps * (std::pow(sigma / r, 12) - std::pow(sigma / r, 6)); };
  // -dU/dr at the cut-off, for the force-shifted form.
  const double fc = 24 * eps * (2 * std::pow(sigma / rc, 12) - std::pow(sigma / rc, 6)) / rc;
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  const int m = static_cast<int>(std::ceil(rc / a)) + 1;
  double sum = 0;
  for (int i = -m; i <= m; ++i)
    for (int j = -m; j <= m; ++j)
      for (int k = -m; k <= m; ++k)
        for (const auto& b : basis) {
          const double x = a * (i + b[0]), y = a * (j + b[1]), z = a * (k + b[2]);
          const double r = std::sqrt(x * x + y * y + z * z);
          if (r == 0 || r >= rc) continue;
          double u = lj(r);
          if (shift != "none") u -= lj(rc);
          if (shift == "force") u += (r - rc) * fc;
          sum += u;
        }
  return 0.5 * sum;
}

double maxForce(Simulation& sim) {
  const Particles& P = sim.particles();
  double m = 0;
  for (std::size_t i = 0; i < P.owned(); ++i)
    for (int a = 0; a < 3; ++a) m = std::max(m, std::fabs(P.integ(i)[a]));
  return sim.comm().max(m);
}

class LjLattice : public ::testing::TestWithParam<std::string> {};

TEST_P(LjLattice, PotentialEnergyAndPressureAreThoseOfTheDirectLatticeSum) {
  Comm comm;
  Melt m;
  m.temperature = 0;
  m.shift = GetParam();
  auto sim = makeMelt(m, comm);
  const double n = 4.0 * m.cells * m.cells * m.cells;
  const double perAtom = global(*sim, "potential") / n;
  const double a = std::cbrt(4 / m.density);
  const double expected = directLatticeSum(a, 1, 1, m.cutoff, m.shift);
  EXPECT_NEAR(perAtom, expected, 1e-10) << "shift " << m.shift;
  if (comm.root())
    std::printf("fcc 0.8442, rc 2.5, %s shift: %.12f per atom (direct sum %.12f)\n",
                m.shift.c_str(), perAtom, expected);
  // The pressure's virial part: the crystal at rest presses with P = −dE/dV, E(a) the
  // direct sum's lattice energy and V = a³/4 per atom, by central differences in the
  // lattice constant (no neighbour shell lies near rc).
  const double h = 1e-5 * a;
  const double dEda = (directLatticeSum(a + h, 1, 1, m.cutoff, m.shift) -
                       directLatticeSum(a - h, 1, 1, m.cutoff, m.shift)) /
                      (2 * h);
  const double dEdV = dEda / (0.75 * a * a), pressure = global(*sim, "pressure");
  EXPECT_NEAR(pressure, -dEdV, 1e-7 * std::fabs(dEdV)) << "shift " << m.shift;
  EXPECT_GT(std::fabs(dEdV), 0.1);  // a real pressure, not a trivially zero one
  if (comm.root()) std::printf("  pressure %.12f (-dE/dV %.12f)\n", pressure, -dEdV);
  EXPECT_LT(maxForce(*sim), 1e-11);
  // At rest: the kinetic energy is that of the half-step velocities the zero (to
  // rounding) forces would give.
  EXPECT_LT(global(*sim, "kinetic"), 1e-20);
}

// The direct sum itself, checked against the fcc lattice constants (sums of r^-12 and r^-6
// over the lattice in units of the nearest-neighbour distance: 12.13188 and 14.45392)
// with a far cut-off and the continuum tail -8 pi rho / (3 rc^3) beyond it.
TEST(DirectLatticeSum, MatchesTheFccLatticeConstants) {
  const double density = 0.8442, rc = 30;
  const double a = std::cbrt(4 / density);
  const double s6 = 1 / std::pow(a / std::sqrt(2.0), 6);
  const double full = 2 * (12.13188 * s6 * s6 - 14.45392 * s6);
  const double tail = -8 * M_PI * density / (3 * rc * rc * rc);
  EXPECT_NEAR(directLatticeSum(a, 1, 1, rc, "none") + tail, full, 1e-5);
}

TEST_P(LjLattice, EpsilonAndSigmaScaleTheLattice) {
  Comm comm;
  Melt m;
  m.temperature = 0;
  m.shift = GetParam();
  m.epsilon = 1.7;
  m.sigma = 0.9;
  m.density = 0.8442 / (0.9 * 0.9 * 0.9);
  m.cutoff = 2.5 * 0.9;
  m.skin = 0.3 * 0.9;
  auto sim = makeMelt(m, comm);
  const double n = 4.0 * m.cells * m.cells * m.cells;
  const double a = std::cbrt(4 / m.density);
  EXPECT_NEAR(global(*sim, "potential") / n,
              directLatticeSum(a, m.epsilon, m.sigma, m.cutoff, m.shift), 1e-10);
}

INSTANTIATE_TEST_SUITE_P(Shifts, LjLattice, ::testing::Values("none", "energy", "force"));

// The pressure's kinetic part: atoms too far apart to interact (fcc at density 0.001, nearest
// neighbours 11.2 apart, beyond rc) are an ideal gas, P V = (N − 1) T (T from the 3N − 3
// degrees of freedom left after the momentum is removed).
TEST(LjPressure, DiluteGasIsIdeal) {
  Comm comm;
  Melt m;
  m.density = 0.001;
  m.temperature = 1.44;
  auto sim = makeMelt(m, comm);
  const double n = 4.0 * m.cells * m.cells * m.cells, volume = n / m.density;
  const double t = global(*sim, "temperature");
  EXPECT_NEAR(t, m.temperature, 1e-12);
  EXPECT_NEAR(global(*sim, "pressure"), (n - 1) * t / volume, 1e-12 * t * n / volume);
  EXPECT_EQ(global(*sim, "potential"), 0.0);  // really no pair within rc
}

// Two atoms brought within 0.3 sigma: their pair terms would leave the range of the exact
// sums (closer than about 0.37 sigma), and the run stops with an error saying so; at
// 0.5 sigma it goes on. On one rank each (the error is this rank's).
TEST(LjOverlap, AtomsFarInsideTheWallStopTheRun) {
  for (const double r : {0.5, 0.3}) {
    Comm comm(MPI_COMM_SELF);
    Melt m;
    m.temperature = 0;
    auto sim = makeMelt(m, comm);
    Particles& P = sim->particles();
    // Atom 0 and its nearest owned neighbour (the lattice spacing away).
    std::size_t b = 1;
    auto dist2 = [&](std::size_t j) {
      double d2 = 0;
      for (int a = 0; a < 3; ++a) d2 += std::pow(P.alter(j)[a] - P.alter(0)[a], 2);
      return d2;
    };
    for (std::size_t j = 2; j < P.owned(); ++j)
      if (dist2(j) < dist2(b)) b = j;
    const double d = std::sqrt(dist2(b));
    ASSERT_LT(d, 1.2);
    for (int a = 0; a < 3; ++a)
      P.alter(b)[a] = P.alter(0)[a] + (P.alter(b)[a] - P.alter(0)[a]) * (r / d);
    sim->procCube().halo();
    if (r > 0.4) {
      EXPECT_GT(global(*sim, "potential"), 1e3);  // the wall, evaluated
      continue;
    }
    try {
      global(*sim, "potential");
      ADD_FAILURE() << "atoms " << r << " apart did not stop the run";
    } catch (const RunError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("closer than"), std::string::npos) << what;
      EXPECT_NE(what.find("0.3 apart"), std::string::npos) << what;
    }
  }
}

class LjForce : public ::testing::TestWithParam<std::string> {};

TEST_P(LjForce, IsMinusTheGradientOfThePotentialEnergy) {
  Comm comm;
  Melt m;
  m.shift = GetParam();
  m.steps = 30;  // leave the lattice: forces are then large and irregular
  auto sim = makeMelt(m, comm);
  while (sim->advance()) {
  }
  Context& ctx = sim->context();
  Particles& P = sim->particles();
  const double h = 1e-5;
  int checked = 0;
  for (Gid g : {1, 137, 500, 864}) {
    std::size_t mine = P.owned();
    for (std::size_t i = 0; i < P.owned(); ++i)
      if (P.gid(i) == g) mine = i;
    global(*sim, "potential");  // forces at the unperturbed positions into the integ table
    double F[3];
    for (int a = 0; a < 3; ++a) F[a] = ctx.max(mine < P.owned() ? P.integ(mine)[a] : -INFINITY);
    for (int a = 0; a < 3; ++a) {
      const double f = F[a];
      double pe[2];
      for (int s = 0; s < 2; ++s) {
        const double x0 = mine < P.owned() ? P.alter(mine)[a] : 0;
        if (mine < P.owned()) P.alter(mine)[a] = x0 + (s ? h : -h);
        sim->procCube().halo();
        pe[s] = global(*sim, "potential");
        if (mine < P.owned()) P.alter(mine)[a] = x0;
        sim->procCube().halo();
      }
      const double fd = -(pe[1] - pe[0]) / (2 * h);
      EXPECT_NEAR(f, fd, 1e-6 * std::max(1.0, std::fabs(f)))
          << "particle " << g << " axis " << a << " shift " << m.shift;
      EXPECT_GT(std::fabs(f), 1e-3);  // a real force, not a trivially zero one
      ++checked;
    }
  }
  EXPECT_EQ(checked, 12);
}

INSTANTIATE_TEST_SUITE_P(Shifts, LjForce, ::testing::Values("none", "energy", "force"));

}  // namespace
}  // namespace pdq
