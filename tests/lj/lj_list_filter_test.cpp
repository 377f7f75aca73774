// The distance filters: the list build's, and the force kernel's first pass (which keeps
// the separations and squared distances too). Each portable loop against the distances
// themselves, and the filter chosen (AVX-512 where the processor has it) against the
// portable one, bit for bit, on ranges of every length modulo 8 and candidates placed on
// and around the radius. The kernel's third pass, which gives the partners their forces,
// likewise: the chosen one against the portable one, on every count modulo 8.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "models/lj/kernel.hpp"
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

// The kernel's rows: x y z and a fourth double; candidate k at row 3 + 2k (rows between and
// around them hold other values), particle i at row 0, (0.25, -0.5, 1).
std::vector<double> kernelRows(const Candidates& c) {
  std::vector<double> pos(4 * (2 * c.x.size() + 4), -7.0);
  pos[0] = 0.25, pos[1] = -0.5, pos[2] = 1;
  for (std::size_t k = 0; k < c.x.size(); ++k) {
    double* r = &pos[4 * (3 + 2 * k)];
    r[0] = c.x[k] + 0.25, r[1] = c.y[k] - 0.5, r[2] = c.z[k] + 1, r[3] = 1e300;
  }
  return pos;
}

// The rows kernelRows put the candidates in, in candidate order.
std::vector<std::uint32_t> rowsOf(const Candidates& c) {
  std::vector<std::uint32_t> rows;
  for (std::size_t k = 0; k < c.x.size(); ++k)
    rows.push_back(static_cast<std::uint32_t>(3 + 2 * k));
  return rows;
}

// The kept pairs of candidates [from, to) (appended after `before` already kept, which the
// filter must leave alone).
struct Kept {
  std::vector<double> dx, dy, dz, r2;
  std::vector<std::uint32_t> j;
  bool operator==(const Kept&) const = default;
};
Kept keepWith(pdq::lj::KeepPairs f, const std::vector<double>& pos,
              const std::vector<std::uint32_t>& rows, std::size_t from, std::size_t to, double r2,
              std::size_t before) {
  pdq::lj::KernelScratch s;
  s.reserve(before + rows.size());
  for (std::size_t q = 0; q < before; ++q) s.dx[q] = s.dy[q] = s.dz[q] = s.r2[q] = 3.0 + q;
  const std::size_t m =
      f(pos.data(), 4, rows.data() + from, rows.data() + to, pos[0], pos[1], pos[2], r2, s, before);
  Kept k;
  k.dx.assign(s.dx.begin(), s.dx.begin() + m);
  k.dy.assign(s.dy.begin(), s.dy.begin() + m);
  k.dz.assign(s.dz.begin(), s.dz.begin() + m);
  k.r2.assign(s.r2.begin(), s.r2.begin() + m);
  k.j.assign(s.j.begin() + before, s.j.begin() + m);
  return k;
}

TEST(LjKernelFilter, PortableKeepsThoseCloserThanTheCutWithTheirSeparations) {
  std::mt19937_64 rng(13);
  const double r = 1.3;
  const Candidates c = around(120, r, rng);
  const std::vector<double> pos = kernelRows(c);
  const std::vector<std::uint32_t> rows = rowsOf(c);
  for (std::size_t from : {0u, 3u, 8u})
    for (std::size_t to = from; to <= 40; ++to) {
      const Kept got = keepWith(pdq::lj::keepPairs, pos, rows, from, to, r * r, 2);
      std::vector<std::uint32_t> want;
      for (std::size_t k = from; k < to; ++k) {
        const double* xk = &pos[4 * rows[k]];
        const double ex = pos[0] - xk[0], ey = pos[1] - xk[1], ez = pos[2] - xk[2];
        if (ex * ex + ey * ey + ez * ez < r * r) want.push_back(rows[k]);
      }
      ASSERT_EQ(got.j, want) << from << ".." << to;
      for (std::size_t q = 0; q < got.j.size(); ++q) {
        const double* xk = &pos[4 * got.j[q]];
        EXPECT_EQ(got.dx[2 + q], pos[0] - xk[0]);
        EXPECT_EQ(got.dz[2 + q], pos[2] - xk[2]);
        EXPECT_LT(got.r2[2 + q], r * r);
      }
      EXPECT_EQ(got.dx[0], 3.0);  // what was kept before stays
      EXPECT_EQ(got.r2[1], 4.0);
    }
}

TEST(LjKernelFilter, ChosenFilterKeepsThePortableBits) {
  const pdq::lj::KeepPairs chosen = pdq::lj::chosenKeepPairs();
  EXPECT_EQ(chosen == pdq::lj::keepPairsAvx512, __builtin_cpu_supports("x86-64-v4") != 0);
  std::mt19937_64 rng(14);
  const double r = 1.3;
  const Candidates c = around(300, r, rng);
  const std::vector<double> pos = kernelRows(c);
  std::vector<std::uint32_t> rows = rowsOf(c);
  std::shuffle(rows.begin(), rows.end(), rng);  // rows in any order, as a list's partners
  std::size_t kept = 0;
  for (std::size_t before : {0u, 5u})
    for (std::size_t from : {0u, 1u, 5u, 8u, 13u})
      for (std::size_t to = from; to <= 300; to += 1 + to % 7) {
        const Kept want = keepWith(pdq::lj::keepPairs, pos, rows, from, to, r * r, before);
        EXPECT_TRUE(keepWith(chosen, pos, rows, from, to, r * r, before) == want)
            << before << ": " << from << ".." << to;
        kept += want.j.size();
      }
  EXPECT_GT(kept, 0u);
}

// The forces of `rows` partners (rows of kForceRow, adjacent, as the kernel's are) after
// giving them the terms of the first `owned` of `partners` pairs.
std::vector<double> givenWith(pdq::lj::GiveForces f, const pdq::lj::KernelScratch& s,
                              std::size_t owned, std::size_t rows) {
  std::vector<double> force(rows * pdq::lj::kForceRow);
  for (std::size_t k = 0; k < force.size(); ++k) force[k] = 0.125 * static_cast<double>(k % 13);
  f(s, owned, force.data());
  return force;
}

// n pairs whose partners are the first n of `partners`, every row of `rows` in random
// order, with force terms in [-1, 1) times 2^(q mod `spread`) for pair q.
pdq::lj::KernelScratch pairsTo(std::size_t n, std::size_t rows, std::uint64_t seed, int spread,
                               std::vector<std::uint32_t>& partners) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  pdq::lj::KernelScratch s;
  s.reserve(n);
  partners.resize(rows);
  std::iota(partners.begin(), partners.end(), 0u);
  std::shuffle(partners.begin(), partners.end(), rng);
  for (std::size_t q = 0; q < n; ++q) {
    s.j[q] = partners[q];
    for (int c = 0; c < 6; ++c)
      s.t[c][q] = u(rng) * std::ldexp(1.0, static_cast<int>(q % static_cast<std::size_t>(spread)));
  }
  return s;
}

TEST(LjKernelGive, PortableSubtractsEachPairsTermsFromItsPartner) {
  const std::size_t rows = 60;
  std::vector<std::uint32_t> partners;
  const pdq::lj::KernelScratch s = pairsTo(40, rows, 15, 1, partners);
  const auto before =
      givenWith([](const pdq::lj::KernelScratch&, std::size_t, double*) {}, s, 0, rows);
  const auto after = givenWith(pdq::lj::giveForces, s, 40, rows);
  for (std::size_t q = 0; q < 40; ++q)
    for (int c = 0; c < 6; ++c) {
      const std::size_t k = s.j[q] * pdq::lj::kForceRow + c;
      EXPECT_EQ(after[k], before[k] - s.t[c][q]) << q << " " << c;
    }
  for (std::size_t r = 40; r < rows; ++r)  // the rows of no pair are left alone
    for (int c = 0; c < 6; ++c) {
      const std::size_t k = partners[r] * pdq::lj::kForceRow + c;
      EXPECT_EQ(after[k], before[k]);
    }
}

TEST(LjKernelGive, ChosenGivesThePortableBits) {
  const pdq::lj::GiveForces chosen = pdq::lj::chosenGiveForces();
  EXPECT_EQ(chosen == pdq::lj::giveForcesAvx512, __builtin_cpu_supports("x86-64-v4") != 0);
  const std::size_t rows = 120;
  std::vector<std::uint32_t> partners;
  const pdq::lj::KernelScratch s = pairsTo(100, rows, 16, 9, partners);
  for (std::size_t owned = 0; owned <= 100; ++owned)
    EXPECT_TRUE(givenWith(chosen, s, owned, rows) == givenWith(pdq::lj::giveForces, s, owned, rows))
        << owned;
}

}  // namespace
