// Analytic checks of the peridynamic models in 2D plane stress (square lattice, δ = 3 s,
// partial volumes, PMB with its surface correction):
//   * a block under uniform uniaxial strain stores the continuum energy density
//     C11 ε² / 2, C11 = E / (1 - ν²), at every particle away from the surfaces (1%);
//   * a P-wave in a long strip (periodic across it) runs at sqrt(C11 / ρ) (2%);
//   * a slowly loaded, damped cantilever comes to rest at the tip deflection of
//     Timoshenko beam theory (5%).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "pd_fixture.hpp"

namespace pdq::pdtest {
namespace {

struct Material {
  std::string model;
  double nu;  // the model's Poisson ratio in 2D plane stress
};
const Material kPmb{"pmb", 1.0 / 3.0}, kLps{"lps", 0.22};

Problem plate(const Material& mat, int nx, int ny, double dt, double damping = 0) {
  std::vector<std::pair<std::string, double>> kv{
      {"E", 1.0}, {"horizon", 3.0},         {"density", 1.0},
      {"dt", dt}, {"lattice_spacing", 1.0}, {"damping", damping}};
  if (mat.model == "lps") kv.push_back({"nu", mat.nu});
  Problem pb = latticeProblem(mat.model, kv, prep::squareLattice(nx, ny, 1.0));
  if (mat.model == "pmb") pb.params.set("surface_correction", "true");
  return pb;
}

void uniaxialStrain(const Material& mat) {
  Comm comm;
  const int n = 31;
  const double eps = 1e-4;
  Problem pb = plate(mat, n, n, 0.1);
  for (std::size_t k = 0; k < pb.ps.size(); ++k) pb.ps.alterRow(k)[0] *= 1 + eps;
  auto sim = makeSimulation(std::move(pb), 0, "pd_elastic_out", comm);
  sim->setup();
  Particles& P = sim->particles();
  std::vector<double> w(P.owned());
  sim->model().field(sim->context(), 1, w);
  const double expected = 0.5 * (1.0 / (1 - mat.nu * mat.nu)) * eps * eps;
  double worst = 0;
  long interior = 0;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    const double X = P.fixed(i)[0], Y = P.fixed(i)[1];
    if (X < 6 || X > n - 7 || Y < 6 || Y > n - 7) continue;  // 2δ from every surface
    worst = std::max(worst, std::fabs(w[i] / expected - 1));
    ++interior;
  }
  worst = sim->context().max(worst);
  EXPECT_EQ(sim->context().count(interior), 19 * 19);
  if (comm.root())
    std::printf("%s uniaxial strain: worst |W/W_theory - 1| = %.2e\n", mat.model.c_str(), worst);
  EXPECT_LT(worst, 0.01) << mat.model;
}

TEST(PdElastic, UniaxialStrainModulusPmb) { uniaxialStrain(kPmb); }
TEST(PdElastic, UniaxialStrainModulusLps) { uniaxialStrain(kLps); }

// Centroid of the right-running half of a Gaussian pulse of u_x, at two times.
void pWave(const Material& mat) {
  Comm comm;
  const int nx = 360, ny = 12;
  const double dt = 0.25, x0 = 120, width = 15, amp = 1e-3;
  Problem pb = plate(mat, nx, ny, dt);
  for (std::size_t k = 0; k < pb.ps.size(); ++k) {
    const double X = pb.ps.fixedRow(k)[0];
    pb.ps.alterRow(k)[0] += amp * std::exp(-std::pow((X - x0) / width, 2));
  }
  pb.run.periodic = {false, true, false};
  pb.run.boxLo = {0, -0.5, 0};
  pb.run.boxHi = {0, ny - 0.5, 0};
  // The left-running half, reflected at X = 0, stays left of x0 until c t = 2 x0 - 3 w.
  const long steps1 = 200, steps2 = 600;
  auto sim = makeSimulation(std::move(pb), steps2, "pd_wave_out", comm);
  sim->setup();
  Particles& P = sim->particles();
  auto centroid = [&] {
    auto& ctx = sim->context();
    auto u = [&](std::size_t i) {
      return P.fixed(i)[0] > x0 ? P.alter(i)[0] - P.fixed(i)[0] : 0.0;
    };
    return ctx.sumOwned([&](std::size_t i) { return P.fixed(i)[0] * u(i); }) / ctx.sumOwned(u);
  };
  while (sim->step() < steps1) sim->advance();
  const double c1 = centroid();
  while (sim->step() < steps2) sim->advance();
  const double c2 = centroid();
  const double speed = (c2 - c1) / ((steps2 - steps1) * dt);
  const double theory = std::sqrt(1.0 / (1 - mat.nu * mat.nu));
  if (comm.root())
    std::printf("%s P-wave: speed / theory = %.4f\n", mat.model.c_str(), speed / theory);
  EXPECT_NEAR(speed / theory, 1.0, 0.02) << mat.model << " speed " << speed;
}

TEST(PdElastic, PWaveSpeedPmb) { pWave(kPmb); }
TEST(PdElastic, PWaveSpeedLps) { pWave(kLps); }

// Cantilever: columns X < δ held, a total load F (+Y) spread over the free end, damped
// towards rest. The beam is the material of the free particles' cells: from the face
// of the support layer (X = δ - s/2) to the free end's face, depth n s, thickness 1.
void cantilever(const Material& mat) {
  Comm comm;
  const int nx = 64, ny = 11;
  const double F = 1e-4, dt = 0.5;
  const double L = (nx - 1 + 0.5) - 2.5, h = ny, E = 1.0, G = E / (2 * (1 + mat.nu));
  const double I = h * h * h / 12, omega1 = 3.516 * std::sqrt(E * I / (h * std::pow(L, 4)));
  Problem pb = plate(mat, nx, ny, dt, 2 * omega1);
  for (std::size_t k = 0; k < pb.ps.size(); ++k) {
    double* f = pb.ps.fixedRow(k);
    if (f[0] < 3) f[pb.col("bc_x")] = f[pb.col("bc_y")] = f[pb.col("bc_z")] = 1;
    if (f[0] == nx - 1) f[pb.col("fy")] = F / ny;
  }
  const double theory = F * std::pow(L, 3) / (3 * E * I) + F * L / (5.0 / 6.0 * G * h);
  const long steps = static_cast<long>(6 * 2 * 3.14159 / omega1 / dt);
  auto sim = makeSimulation(std::move(pb), steps, "pd_cantilever_test_out", comm);
  sim->run();
  Particles& P = sim->particles();
  // Deflection of the end's middle row.
  const double tip = sim->context().sumOwned([&](std::size_t i) {
    return P.fixed(i)[0] == nx - 1 && P.fixed(i)[1] == (ny - 1) / 2 ? P.alter(i)[1] - P.fixed(i)[1]
                                                                    : 0.0;
  });
  if (comm.root())
    std::printf("%s cantilever: tip / theory = %.4f\n", mat.model.c_str(), tip / theory);
  EXPECT_NEAR(tip / theory, 1.0, 0.05) << mat.model << " tip " << tip << " theory " << theory;
}

TEST(PdElastic, CantileverDeflectionPmb) { cantilever(kPmb); }

}  // namespace
}  // namespace pdq::pdtest
