// The list build's distance filter: the portable loop against the distances themselves, and
// the filter the build chooses (AVX-512 where the processor has it) against the portable
// one, on ranges of every length modulo 8 and candidates placed on and around the radius.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "models/lj/verlet_list.hpp"

namespace {

struct Candidates {
  std::vector<double> x, y, z;
  std::vector<std::uint32_t> id;
};

// n candidates around the origin at distances spread over [0, 2r], some exactly at r.
Candidates around(std::size_t n, double r, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1), d(0, 2 * r);
  Candidates c;
  for (std::size_t k = 0; k < n; ++k) {
    double ux = u(rng), uy = u(rng), uz = u(rng);
    const double len = std::sqrt(ux * ux + uy * uy + uz * uz) + 1e-300;
    const double dist = k % 5 == 0 ? r : d(rng);
    c.x.push_back(ux / len * dist);
    c.y.push_back(uy / len * dist);
    c.z.push_back(uz / len * dist);
    c.id.push_back(static_cast<std::uint32_t>(1000 + 7 * k));
  }
  return c;
}

using Filter = pdq::lj::KeepNear;

std::vector<std::uint32_t> run(Filter f, const Candidates& c, std::size_t from, std::size_t to,
                               double r2) {
  std::vector<std::uint32_t> out(to - from + 8, 0xdeadbeef);  // may write 8 past the kept
  const std::size_t m =
      f(c.x.data(), c.y.data(), c.z.data(), c.id.data(), from, to, 0, 0, 0, r2, out.data());
  out.resize(m);
  return out;
}

TEST(LjListFilter, PortableKeepsExactlyThoseCloserThanTheRadius) {
  std::mt19937_64 rng(11);
  const double r = 1.3;
  const Candidates c = around(200, r, rng);
  for (std::size_t from : {0u, 3u, 8u})
    for (std::size_t to = from; to <= 40; ++to) {
      std::vector<std::uint32_t> want;
      for (std::size_t k = from; k < to; ++k)
        if (c.x[k] * c.x[k] + c.y[k] * c.y[k] + c.z[k] * c.z[k] < r * r) want.push_back(c.id[k]);
      EXPECT_EQ(run(pdq::lj::keepNear, c, from, to, r * r), want) << from << ".." << to;
    }
}

TEST(LjListFilter, ChosenFilterKeepsWhatThePortableLoopKeeps) {
  const Filter chosen = pdq::lj::chosenKeepNear();
  EXPECT_EQ(chosen == pdq::lj::keepNearAvx512, __builtin_cpu_supports("x86-64-v4") != 0);
  std::mt19937_64 rng(12);
  const double r = 1.3;
  const Candidates c = around(300, r, rng);
  std::size_t kept = 0;
  for (std::size_t from : {0u, 1u, 5u, 8u, 13u})
    for (std::size_t to = from; to <= 300; to += 1 + to % 7) {
      const auto want = run(pdq::lj::keepNear, c, from, to, r * r);
      EXPECT_EQ(run(chosen, c, from, to, r * r), want) << from << ".." << to;
      kept += want.size();
    }
  EXPECT_GT(kept, 0u);
}

}  // namespace
