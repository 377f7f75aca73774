// The distance filters of the list build and of the force kernel's first pass: the portable
// loops against the distances themselves, and the filters chosen (AVX-512 where the
// processor has it) against the portable ones, bit for bit, on ranges of every length
// modulo 8 and candidates placed on and around the radius.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
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

// The kernel's filter: local particles in rows of `kStride` doubles (x, y, z first) around
// particle 0 at the origin's neighbour (0.25, -0.5, 0.125), partners listed out of order.
constexpr std::size_t kStride = 5;

struct Rows {
  std::vector<double> pos;
  std::vector<std::uint32_t> list;
};

Rows rows(std::size_t n, double r, std::mt19937_64& rng) {
  const double at[3] = {0.25, -0.5, 0.125};
  const Candidates c = around(n, r, rng);
  Rows w;
  w.pos.assign((n + 1) * kStride, -7.0);
  for (int a = 0; a < 3; ++a) w.pos[a] = at[a];
  for (std::size_t k = 0; k < n; ++k) {
    w.pos[(k + 1) * kStride + 0] = at[0] - c.x[k];
    w.pos[(k + 1) * kStride + 1] = at[1] - c.y[k];
    w.pos[(k + 1) * kStride + 2] = at[2] - c.z[k];
    w.list.push_back(static_cast<std::uint32_t>(1 + (k * 37) % n));
  }
  return w;
}

struct Out {
  std::vector<double> dx, dy, dz, r2;
  std::vector<std::uint32_t> j;
  // Bit for bit (-0 and 0 differ).
  bool operator==(const Out& o) const {
    auto same = [](const auto& a, const auto& b) {
      return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof a[0]) == 0;
    };
    return same(dx, o.dx) && same(dy, o.dy) && same(dz, o.dz) && same(r2, o.r2) && same(j, o.j);
  }
};

// Two calls, as the kernel makes them: [0, split) then [split, to) after the first's.
Out keep(pdq::lj::KeepWithin f, const Rows& w, std::size_t split, std::size_t to, double r2) {
  Out o;
  for (auto* v : {&o.dx, &o.dy, &o.dz, &o.r2}) v->assign(to + 16, 99.0);
  o.j.assign(to + 16, 0xdeadbeef);
  const pdq::lj::Kept into{o.dx.data(), o.dy.data(), o.dz.data(), o.r2.data(), o.j.data()};
  const double* xi = w.pos.data();
  const auto* l = w.list.data();
  std::size_t m = f(w.pos.data(), kStride, l, l + split, xi, r2, into, 0);
  m = f(w.pos.data(), kStride, l + split, l + to, xi, r2, into, m);
  for (auto* v : {&o.dx, &o.dy, &o.dz, &o.r2}) v->resize(m);
  o.j.resize(m);
  return o;
}

TEST(LjKernelFilter, PortableKeepsExactlyThosePairsCloserThanRc) {
  std::mt19937_64 rng(21);
  const double r = 2.5;
  const Rows w = rows(120, r, rng);
  for (std::size_t split : {0u, 5u, 8u})
    for (std::size_t to = split; to <= 40; ++to) {
      Out want;
      for (std::size_t k = 0; k < to; ++k) {
        const double* xj = &w.pos[w.list[k] * kStride];
        const double ex = w.pos[0] - xj[0], ey = w.pos[1] - xj[1], ez = w.pos[2] - xj[2];
        const double d2 = ex * ex + ey * ey + ez * ez;
        if (!(d2 < r * r)) continue;
        want.dx.push_back(ex), want.dy.push_back(ey), want.dz.push_back(ez);
        want.r2.push_back(d2), want.j.push_back(w.list[k]);
      }
      EXPECT_TRUE(keep(pdq::lj::keepWithin, w, split, to, r * r) == want) << split << ".." << to;
    }
}

TEST(LjKernelFilter, ChosenFilterKeepsThePortableBits) {
  const pdq::lj::KeepWithin chosen = pdq::lj::chosenKeepWithin();
  EXPECT_EQ(chosen == pdq::lj::keepWithinAvx512, __builtin_cpu_supports("x86-64-v4") != 0);
  std::mt19937_64 rng(22);
  const double r = 2.5;
  const Rows w = rows(300, r, rng);
  std::size_t kept = 0;
  for (std::size_t split : {0u, 1u, 7u, 8u, 13u})
    for (std::size_t to = split; to <= 300; to += 1 + to % 7) {
      const Out want = keep(pdq::lj::keepWithin, w, split, to, r * r);
      const Out got = keep(chosen, w, split, to, r * r);
      EXPECT_TRUE(got == want) << split << ".." << to;
      kept += want.j.size();
    }
  EXPECT_GT(kept, 0u);
}

}  // namespace
