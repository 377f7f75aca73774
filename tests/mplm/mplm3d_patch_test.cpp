// Patch test of the 3D lattice: a uniform strain imposed on a block of the fcc lattice gives
// back the continuum's E and ν in the interior (virial stress), in three lattice
// orientations, and the same moduli along three different lattice directions (isotropy).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <vector>

#include "harness.hpp"
#include "models/mplm/3d/attributes.hpp"
#include "prep/fcc.hpp"
#include "prep/mplm/specimen3d.hpp"

namespace pdq::mplm3d {
namespace {

constexpr double E = 24.86e9, nu = 0.2, s = 0.02, L = 0.24;
using Tensor = std::array<std::array<double, 3>, 3>;

// Mean virial stress (xx, yy, zz, yz, xz, xy) of the interior particles of an L-cube under
// the displacement gradient `grad` imposed on every particle: more than 2√2 s from every
// face, so that no interaction of theirs carries the surface correction (an interaction
// is corrected when the lattice site beyond either end, up to 2√2 s away, is missing).
std::array<double, 6> interiorStress(const ClosePacked& lattice, const Tensor& grad,
                                     const std::string& kinematics) {
  Comm comm;
  ParticleSet ps = newParticleSet();
  addConcrete(ps, closePackedBox(lattice, {L, L, L}));
  for (std::size_t k = 0; k < ps.size(); ++k)
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q)
        ps.alterRow(k)[AX + p] += grad[p][q] * (ps.fixedRow(k)[q] - L / 2);
  auto sim = mplm::test::simulation(
      comm, mplm::test::params({{"kinematics", kinematics}, {"damage", "false"}}), std::move(ps), 1,
      "mplm3d");
  Context& ctx = sim->context();
  const std::size_t n = ctx.particles.owned();
  const auto names = sim->model().fields();
  auto interior = [&](std::size_t i) {
    const double* X = ctx.particles.fixed(i);
    const double m = 2.85 * s;
    return std::all_of(X, X + 3, [&](double x) { return x > m && x < L - m; });
  };
  const double count = ctx.sumOwned([&](std::size_t i) { return interior(i) ? 1.0 : 0.0; });
  EXPECT_GT(count, 300);
  std::array<double, 6> mean{};
  const char* comp[6] = {"sxx", "syy", "szz", "syz", "sxz", "sxy"};
  for (int c = 0; c < 6; ++c) {
    std::vector<double> v(n);
    const int k = static_cast<int>(std::find(names.begin(), names.end(), comp[c]) - names.begin());
    sim->model().field(ctx, k, v);
    mean[c] = ctx.sumOwned([&](std::size_t i) { return interior(i) ? v[i] : 0.0; }) / count;
  }
  return mean;
}

Tensor uniaxial(const std::array<double, 3>& n, double e) {
  Tensor t{};
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) t[p][q] = e * n[p] * n[q];
  return t;
}

const ClosePacked orientations[3] = {{s, 0, 2}, {s, 1, 2}, {s, 0, 1}};

// Uniaxial strain along X: σxx = (λ + 2μ) e, σyy = σzz = λ e give back E and ν.
TEST(Mplm3dPatch, UniformStrainGivesBackEAndNu) {
  const double e = 1e-4;
  for (const auto& o : orientations)
    for (const char* kin : {"small", "corotational"}) {
      const auto st = interiorStress(o, uniaxial({1, 0, 0}, e), kin);
      const double r = 0.5 * (st[1] + st[2]) / st[0];
      const double v = r / (1 + r);
      const double Eg = st[0] * (1 + v) * (1 - 2 * v) / ((1 - v) * e);
      const std::string what = std::string(kin) + ", bonds along axis " +
                               std::to_string(o.bondAxis) + ", layers along " +
                               std::to_string(o.stackAxis);
      std::cout << what << ": E error " << (Eg - E) / E << ", nu error " << (v - nu) / nu << "\n";
      EXPECT_NEAR(Eg, E, 0.01 * E) << what;
      EXPECT_NEAR(v, nu, 0.01 * nu) << what;
      EXPECT_NEAR(st[1], st[2], 0.01 * st[1]) << what;
      for (int c = 3; c < 6; ++c) EXPECT_NEAR(st[c], 0, 1e-3 * st[0]) << what << " shear " << c;
    }
}

// The uniaxial-strain modulus n·σn/e and the shear modulus along three lattice directions
// (a bond direction, the normal to the close-packed layers, and a direction between them)
// agree within 2 %.
TEST(Mplm3dPatch, SameModuliAlongThreeLatticeDirections) {
  const double e = 1e-4, r2 = std::sqrt(0.5), r3 = std::sqrt(1.0 / 3);
  const ClosePacked lattice{s, 0, 2};
  const std::array<double, 3> dirs[3] = {{1, 0, 0}, {0, 0, 1}, {r3, r3, r3}};
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  for (const auto& n : dirs) {
    const auto st = interiorStress(lattice, uniaxial(n, e), "small");
    const double sigma[3][3] = {
        {st[0], st[5], st[4]}, {st[5], st[1], st[3]}, {st[4], st[3], st[2]}};
    double nn = 0;
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) nn += n[p] * sigma[p][q] * n[q];
    EXPECT_NEAR(nn / e, lambda + 2 * mu, 0.02 * (lambda + 2 * mu))
        << "direction " << n[0] << " " << n[1] << " " << n[2];
  }
  // Shear in the plane of the layers, across them, and in a rotated plane: σ = 2μ ε.
  const std::array<std::array<double, 3>, 2> planes[3] = {
      {{{1, 0, 0}, {0, 1, 0}}}, {{{1, 0, 0}, {0, 0, 1}}}, {{{r2, r2, 0}, {-r3, r3, r3}}}};
  for (const auto& pl : planes) {
    const auto& a = pl[0];
    std::array<double, 3> b = pl[1];
    const double ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    for (int p = 0; p < 3; ++p) b[p] -= ab * a[p];
    const double nb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    for (double& x : b) x /= nb;
    Tensor g{};
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) g[p][q] = e * (a[p] * b[q] + b[p] * a[q]);
    const auto st = interiorStress(lattice, g, "small");
    const double sigma[3][3] = {
        {st[0], st[5], st[4]}, {st[5], st[1], st[3]}, {st[4], st[3], st[2]}};
    double ab2 = 0;
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) ab2 += a[p] * sigma[p][q] * b[q];
    EXPECT_NEAR(ab2 / e, 2 * mu, 0.02 * 2 * mu) << "shear plane " << a[0] << " " << a[1];
  }
}

}  // namespace
}  // namespace pdq::mplm3d
