// The PMB kernel this CPU uses (AVX2 where present) gives the same bits as the portable
// one, for particles with any number of bonds (tails of 0-3 bonds), with and without
// bonds breaking.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "models/lps/lps_kernel.hpp"
#include "models/pmb/pmb_kernel.hpp"

namespace pdq::peri {
namespace {

// Particle 0's nb bonds, all alive, for the kernels to kill the ones that break.
Bonds bondsOfOne(int nAttr, std::size_t nb) {
  Bonds bonds(nAttr);
  for (std::size_t b = 0; b < nb; ++b) bonds.add(0, static_cast<Gid>(b + 1));
  bonds.finish(1);
  return bonds;
}

// The kernels killed exactly the bonds whose weight they set to 0.
void expectKilledAsBroken(const Bonds& bonds, const std::vector<double>& attr, int stride) {
  for (std::size_t b = 0; b < bonds.count(); ++b)
    EXPECT_EQ(bonds.alive(b), attr[stride * b + 1] != 0) << "bond " << b;
}

TEST(PdKernel, PmbFastKernelMatchesPortableBitwise) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::size_t nA = 6, particles = 64;
  std::vector<double> x(particles * nA);
  for (auto& v : x) v = 3 * u(rng);
  std::size_t broken = 0;
  for (double sc : {0.0, 0.05}) {
    for (std::size_t nb = 0; nb < 40; ++nb) {
      std::vector<std::int32_t> partner(nb);
      std::vector<double> attr(2 * nb);
      for (std::size_t b = 0; b < nb; ++b) {
        partner[b] = static_cast<std::int32_t>(1 + rng() % (particles - 1));
        const double* xj = &x[partner[b] * nA];
        const double len = std::hypot(xj[0] - x[0], xj[1] - x[1], xj[2] - x[2]);
        attr[2 * b] = len * (1 + 0.1 * u(rng));  // stretched or compressed
        attr[2 * b + 1] = 1 + u(rng);
      }
      std::vector<double> attrB = attr;
      Bonds fastBonds = bondsOfOne(2, nb), portableBonds = bondsOfOne(2, nb);
      double fast[3], portable[3];
      pmbKernel()(PmbView{partner.data(), attr.data(), x.data(), nA, sc, &fastBonds}, 0, 0, nb,
                  fast);
      pmbKernelPortable(PmbView{partner.data(), attrB.data(), x.data(), nA, sc, &portableBonds}, 0,
                        0, nb, portable);
      EXPECT_EQ(0, std::memcmp(fast, portable, sizeof fast)) << nb << " bonds";
      EXPECT_EQ(attr, attrB) << "the same bonds break";
      expectKilledAsBroken(fastBonds, attr, 2);
      expectKilledAsBroken(portableBonds, attrB, 2);
      if (sc > 0) {
        for (std::size_t b = 0; b < nb; ++b) broken += attr[2 * b + 1] == 0;
      }
    }
  }
  EXPECT_GT(broken, 50u) << "some bonds must break for the check to mean anything";
}

TEST(PdKernel, LpsFastKernelsMatchPortableBitwise) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::size_t nA = 6, particles = 64;
  std::vector<double> x(particles * nA), theta(particles);
  for (auto& v : x) v = 3 * u(rng);
  for (auto& v : theta) v = u(rng);
  std::size_t broken = 0;
  for (double sc : {0.0, 0.05}) {
    for (std::size_t nb = 0; nb < 40; ++nb) {
      std::vector<std::int32_t> partner(nb);
      std::vector<double> attr(3 * nb);
      for (std::size_t b = 0; b < nb; ++b) {
        partner[b] = static_cast<std::int32_t>(1 + rng() % (particles - 1));
        const double* xj = &x[partner[b] * nA];
        const double len = std::hypot(xj[0] - x[0], xj[1] - x[1], xj[2] - x[2]);
        attr[3 * b] = len * (1 + 0.1 * u(rng));
        attr[3 * b + 1] = 1 + u(rng);
        attr[3 * b + 2] = 2 + u(rng);
      }
      std::vector<double> attrB = attr;
      Bonds fastBonds = bondsOfOne(3, nb), portableBonds = bondsOfOne(3, nb);
      const LpsView fastView{partner.data(), attr.data(), x.data(),  nA, theta.data(), 1.5,
                             -0.7,           sc,          &fastBonds};
      const LpsView portableView{partner.data(), attrB.data(), x.data(),      nA, theta.data(), 1.5,
                                 -0.7,           sc,           &portableBonds};
      const double d1 = lpsKernels().dilatation(fastView, 0, 0, nb);
      const double d2 = lpsKernelsPortable().dilatation(portableView, 0, 0, nb);
      EXPECT_EQ(0, std::memcmp(&d1, &d2, sizeof d1)) << nb << " bonds";
      double fast[3], portable[3];
      lpsKernels().force(fastView, 0, 0, nb, 0.3, 0.8, fast);
      lpsKernelsPortable().force(portableView, 0, 0, nb, 0.3, 0.8, portable);
      EXPECT_EQ(0, std::memcmp(fast, portable, sizeof fast)) << nb << " bonds";
      EXPECT_EQ(attr, attrB) << "the same bonds break";
      expectKilledAsBroken(fastBonds, attr, 3);
      expectKilledAsBroken(portableBonds, attrB, 3);
      if (sc > 0) {
        for (std::size_t b = 0; b < nb; ++b) broken += attr[3 * b + 1] == 0;
      }
    }
  }
  EXPECT_GT(broken, 50u) << "some bonds must break for the check to mean anything";
}

}  // namespace
}  // namespace pdq::peri
