// The PMB and LPS kernels of every vector width this CPU runs (AVX2, AVX-512) give the same
// bits as the portable ones, for particles with any number of bonds (tails of 0-7 bonds), with
// and without bonds breaking, and leave the bonds before and after the particle's alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <random>
#include <vector>

#include "models/lps/lps_kernel.hpp"
#include "models/peri/bond_classes.hpp"
#include "models/pmb/pmb_kernel.hpp"

namespace pdq::peri {
namespace {

// The vector widths this CPU runs (whatever PDQ_SIMD says), and the bonds of other particles
// around the kernels' range: before it, and after it none (the arrays end with the range's
// bonds: the kernels copy their last bonds) or as many as a vector's tail reads in place.
std::vector<Simd> widths() {
  std::vector<Simd> w;
  for (Simd s : {Simd::avx2, Simd::avx512})
    if (s <= processorSimd()) w.push_back(s);
  std::printf("vector widths tested: %zu of 2 (AVX2, AVX-512)\n", w.size());
  return w;
}
constexpr std::size_t kBefore = 3, kAfter = 8;

// Particle i's count[i] bonds, all alive, for the kernels to kill the ones that break.
Bonds bondsOf(int nAttr, const std::vector<std::size_t>& count) {
  Bonds bonds(nAttr);
  Gid partner = 0;
  for (std::size_t i = 0; i < count.size(); ++i)
    for (std::size_t b = 0; b < count[i]; ++b) bonds.add(i, ++partner);
  bonds.finish(count.size());
  return bonds;
}

Bonds bondsOfOne(int nAttr, std::size_t nb) { return bondsOf(nAttr, {nb}); }

// The kernels killed exactly the bonds whose weight they set to 0.
void expectKilledAsBroken(const Bonds& bonds, const std::vector<double>& attr, int stride) {
  for (std::size_t b = 0; b < bonds.count(); ++b)
    EXPECT_EQ(bonds.alive(b), attr[stride * b + 1] != 0) << "bond " << b;
}

// One case: particles 0, 1, ... with count[0], count[1], ... bonds, in two sets of bonds alike
// (for the fast and the portable kernel), particle i at position row i and its partners at
// random rows beyond the particles'; length and weight from one of the `shared` rows, as on a
// lattice, or each bond its own (stretched or compressed); a third attribute, where there is
// one, is the partner's 1/m (its position row's fourth column). The kernels take the particles
// between the first and the last. The fast set's rows are made.
struct Case {
  std::vector<std::size_t> count;
  std::size_t total;
  Bonds fast, portable;
  std::vector<std::int32_t> partner;
  BondClasses classes;

  Case(std::mt19937_64& rng, const std::vector<double>& x, std::size_t nA,
       const std::vector<std::array<double, 2>>& shared, bool fewRows, int nAttr,
       std::vector<std::size_t> count_)
      : count(std::move(count_)),
        total(std::accumulate(count.begin(), count.end(), std::size_t{0})),
        fast(bondsOf(nAttr, count)),
        portable(bondsOf(nAttr, count)),
        partner(total),
        classes(nA) {
    std::uniform_real_distribution<double> u(-1, 1);
    const std::size_t rows = x.size() / nA, owners = count.size();
    for (std::size_t i = 0; i < owners; ++i)
      for (std::size_t b = fast.begin(i); b < fast.end(i); ++b) {
        partner[b] = static_cast<std::int32_t>(owners + rng() % (rows - owners));
        const double* xi = &x[i * nA];
        const double* xj = &x[partner[b] * nA];
        const double len = std::hypot(xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]);
        double* a = fast.attr(b);
        if (fewRows) {
          std::copy_n(shared[rng() % shared.size()].data(), 2, a);
        } else {
          a[0] = len * (1 + 0.1 * u(rng));
          a[1] = 1 + u(rng);
        }
        if (nAttr > 2) a[2] = xj[3];
        std::copy_n(a, nAttr, portable.attr(b));
      }
    fast.renumberPartners() = partner;  // the partners' row offsets are made from these
    classes.update(fast);
    for (std::size_t b = 0; b < total; ++b)
      secondHalf.insert(secondHalf.end(), rowOf(classes.rows(), b) + 2,
                        rowOf(classes.rows(), b) + 4);
  }

  std::vector<double> secondHalf;  // each pair row's second half as made

  // After the kernels: the same bonds broke in both sets, and each fast bond's row follows
  // its attributes; returns how many bonds are broken.
  std::size_t expectSameBonds() {
    const int stride = fast.nAttr();
    const double* attr = fast.attr(0);
    const double* attrB = portable.attr(0);
    const BondRows r = classes.rows();
    std::size_t broken = 0;
    for (std::size_t b = 0; b < total; ++b) {
      EXPECT_EQ(0, std::memcmp(attr + stride * b, attrB + stride * b, stride * sizeof(double)))
          << "the same bonds break";
      EXPECT_EQ(0, std::memcmp(rowOf(r, b), attr + stride * b, 2 * sizeof(double)))
          << "bond " << b << ": its row follows it as it breaks";
      // The pair row's second half is the next bond's, but for a particle's last bond, whose
      // second half no kernel of the next particle may write.
      bool last = false;
      for (std::size_t i = 1; i < count.size(); ++i) last |= b + 1 == fast.begin(i);
      if (b + 1 < total && !last) {
        EXPECT_EQ(0, std::memcmp(rowOf(r, b) + 2, attr + stride * (b + 1), 2 * sizeof(double)))
            << "bond " << b << ": its pair row follows the next bond";
      }
      if (last) {
        EXPECT_EQ(0, std::memcmp(rowOf(r, b) + 2, &secondHalf[2 * b], 2 * sizeof(double)))
            << "bond " << b << ": the next particle's kernel left its pair row alone";
      }
      broken += attr[stride * b + 1] == 0;
    }
    expectKilledAsBroken(fast, std::vector<double>(attr, attr + stride * total), stride);
    expectKilledAsBroken(portable, std::vector<double>(attrB, attrB + stride * total), stride);
    return broken;
  }
};

// The fast PMB kernels read the bonds' (length, weight) rows (BondClasses); the portable
// one the attributes themselves. Bonds with a few shared rows, as on a lattice, and bonds
// with rows of their own. The kernels take two particles (the AVX-512 one together: four
// bonds of each a group while both have four left), or each on its own.
TEST(PdKernel, PmbFastKernelMatchesPortableBitwise) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::size_t nA = 6, particles = 64;
  std::vector<double> x(particles * nA);
  for (auto& v : x) v = 3 * u(rng);
  const std::vector<std::array<double, 2>> shared = {{2.0, 1.25}, {3.5, 0.75}, {5.0, 1.5}};
  std::size_t broken = 0, sharedBroken = 0;
  for (Simd width : widths())
    for (bool fewRows : {false, true})
      for (double sc : {0.0, 0.05})
        for (bool together : {true, false})
          for (std::size_t na = 0; na < 40; ++na)
            for (std::size_t nb : {na, (7 * na + 3) % 40, static_cast<std::size_t>(rng() % 40)})
              for (std::size_t after : {std::size_t{0}, kAfter}) {
                SCOPED_TRACE(static_cast<int>(width));
                Case c(rng, x, nA, shared, fewRows, 2, {kBefore, na, nb, after});
                // The other particles' pair offsets, which no kernel of these two may write.
                const std::uint32_t* pair = c.classes.rows().pair;
                const std::vector<std::uint32_t> before(pair, pair + kBefore),
                    beyond(pair + c.fast.begin(3), pair + c.total);
                // Twice: the second pass meets the bonds the first one broke.
                for (int pass = 0; pass < 2; ++pass) {
                  double fast[3 * 4], portable[3 * 4];
                  const PmbView fastView{
                      c.partner.data(), c.fast.attr(0), c.classes.rows(), x.data(), nA, sc,
                      &c.fast};
                  if (together) {
                    pmbKernel(width).force(fastView, 1, 3, fast, 3);
                  } else {
                    pmbKernel(width).force(fastView, 1, 2, fast, 3);
                    pmbKernel(width).force(fastView, 2, 3, fast, 3);
                  }
                  pmbKernelPortable(
                      PmbView{
                          c.partner.data(), c.portable.attr(0), {}, x.data(), nA, sc, &c.portable},
                      1, 3, portable, 3);
                  EXPECT_EQ(0, std::memcmp(fast + 3, portable + 3, 6 * sizeof(double)))
                      << na << " and " << nb << " bonds, pass " << pass;
                  const std::size_t n = c.expectSameBonds();
                  if (pass == 1) (fewRows ? sharedBroken : broken) += n;
                }
                EXPECT_TRUE(std::equal(before.begin(), before.end(), pair));
                EXPECT_TRUE(std::equal(beyond.begin(), beyond.end(), pair + c.fast.begin(3)));
              }
  EXPECT_GT(broken, 50u) << "some bonds must break for the check to mean anything";
  EXPECT_GT(sharedBroken, 50u);
}

// The fast LPS kernels read the bonds' (length, weight) rows (BondClasses) and the
// partner's 1/m from its position row's fourth column; the portable ones the attributes
// themselves. Bonds with a few shared rows, as on a lattice, and bonds with rows of their
// own.
TEST(PdKernel, LpsFastKernelsMatchPortableBitwise) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::size_t nA = 6, particles = 64;
  std::vector<double> x(particles * nA), theta(particles);
  for (auto& v : x) v = 3 * u(rng);
  for (auto& v : theta) v = u(rng);
  const std::vector<std::array<double, 2>> shared = {
      {2.0, 1.25}, {3.0, 0.75}, {4.5, 1.5}, {6, 0.5}};
  std::size_t broken = 0, sharedBroken = 0;
  for (Simd width : widths())
    for (bool fewRows : {false, true})
      for (double sc : {0.0, 0.05}) {
        for (std::size_t nb = 0; nb < 40; ++nb)
          for (std::size_t after : {std::size_t{0}, kAfter}) {
            SCOPED_TRACE(static_cast<int>(width));
            Case c(rng, x, nA, shared, fewRows, 3, {kBefore, nb, after});
            if (fewRows && nb > 0) {
              EXPECT_LE(c.classes.count(), 8u) << "four rows and their twins";
            }
            const LpsView fastView{c.partner.data(),
                                   c.fast.attr(0),
                                   c.classes.rows(),
                                   x.data(),
                                   nA,
                                   theta.data(),
                                   1.5,
                                   -0.7,
                                   sc,
                                   &c.fast};
            const LpsView portableView{
                c.partner.data(), c.portable.attr(0), {}, x.data(), nA, theta.data(), 1.5, -0.7, sc,
                &c.portable};
            // Twice: the second pass meets the bonds the first one broke.
            for (int pass = 0; pass < 2; ++pass) {
              const double d1 = lpsKernels(width).dilatation(fastView, 1, kBefore, kBefore + nb);
              const double d2 =
                  lpsKernelsPortable().dilatation(portableView, 1, kBefore, kBefore + nb);
              EXPECT_EQ(0, std::memcmp(&d1, &d2, sizeof d1)) << nb << " bonds";
              double fast[3], portable[3];
              lpsKernels(width).force(fastView, 1, kBefore, kBefore + nb, 0.3, 0.8, fast);
              lpsKernelsPortable().force(portableView, 1, kBefore, kBefore + nb, 0.3, 0.8,
                                         portable);
              EXPECT_EQ(0, std::memcmp(fast, portable, sizeof fast)) << nb << " bonds";
              const std::size_t n = c.expectSameBonds();
              if (pass == 1) (fewRows ? sharedBroken : broken) += n;
            }
          }
      }
  EXPECT_GT(broken, 50u) << "some bonds must break for the check to mean anything";
  EXPECT_GT(sharedBroken, 50u);
}

// The partners' row offsets are their local indices times the row's doubles, and follow
// the partners when the engine renumbers them.
TEST(PdKernel, PartnerRowOffsetsFollowThePartners) {
  Bonds bonds = bondsOfOne(2, 5);
  bonds.renumberPartners() = {4, 9, 2, 7, 0};
  BondClasses classes(6);
  classes.update(bonds);
  for (std::size_t b = 0; b < 5; ++b) EXPECT_EQ(classes.rows().at[b], 6 * bonds.partner(b));
  bonds.renumberPartners() = {1, 3, 5, 8, 11};
  EXPECT_TRUE(classes.update(bonds)) << "renumbered partners are a change";
  for (std::size_t b = 0; b < 5; ++b) EXPECT_EQ(classes.rows().at[b], 6 * bonds.partner(b));
  EXPECT_EQ(BondClasses().rows().at, nullptr) << "made only when asked for";
}

// The rows are rebuilt when the bonds change (here: put back to a saved state) or when the
// model rewrites their attributes (forget), and kept otherwise; each pair row holds its bond's
// row and the next one's, and its broken twins zero the weight of one bond or the other.
TEST(PdKernel, BondRowsFollowTheBonds) {
  Bonds bonds = bondsOfOne(3, 6);
  for (std::size_t b = 0; b < 6; ++b) {
    bonds.attr(b)[0] = 1.0 + b % 2;
    bonds.attr(b)[1] = 0.5;
  }
  Bonds::Saved intact;
  bonds.save(intact);
  BondClasses classes;
  classes.update(bonds);
  EXPECT_EQ(classes.count(), 4u) << "two rows and their broken twins";
  EXPECT_NE(classes.rows().pair[0], classes.rows().pair[1]);
  EXPECT_EQ(classes.rows().pair[0], classes.rows().pair[2]);
  bonds.attr(0)[0] = 7;  // written by no kernel, unseen until forgotten
  classes.update(bonds);
  EXPECT_EQ(rowOf(classes.rows(), 0)[0], 1.0);
  classes.forget();
  classes.update(bonds);
  EXPECT_EQ(rowOf(classes.rows(), 0)[0], 7.0);
  EXPECT_EQ(classes.count(), 6u);
  bonds.restore(intact);
  classes.update(bonds);
  EXPECT_EQ(rowOf(classes.rows(), 0)[0], 1.0);
  EXPECT_EQ(classes.count(), 4u);
  const BondRows r = classes.rows();
  for (std::size_t b = 0; b < 6; ++b) {
    const double* own = rowOf(r, b);
    const double* next = bonds.attr(b + 1 < 6 ? b + 1 : b);
    EXPECT_EQ(own[0], bonds.attr(b)[0]);
    EXPECT_EQ(own[2], next[0]) << "the next bond's row (the last bond's own)";
    for (int s = 0; s < 2; ++s) {
      const std::uint32_t twin = r.broken[r.pair[b] / 2 + s];
      const double* t = r.row + twin;
      EXPECT_EQ(t[0], own[0]);
      EXPECT_EQ(t[2], own[2]);
      EXPECT_EQ(t[1], s == 0 ? 0.0 : own[1]);
      EXPECT_EQ(t[3], s == 1 ? 0.0 : own[3]);
      EXPECT_EQ(r.broken[twin / 2 + s], twin) << "a twin is its own";
    }
  }
}

}  // namespace
}  // namespace pdq::peri
