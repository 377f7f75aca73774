#include "models/lj/verlet_list.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <bit>
#include <numeric>

namespace pdq::lj {

namespace {
// Particles whose lists are sorted together (their entries fit in the second-level cache).
constexpr std::size_t kBlock = 1024;
constexpr int kDigitBits = 11;
constexpr std::uint64_t kDigitMask = (1u << kDigitBits) - 1;
}  // namespace

void VerletList::build(const Context& ctx, double radius) {
  const Particles& P = ctx.particles;
  const std::size_t nLocal = P.local(), n = P.owned();
  // Rank every local particle by global ID (a ghost may repeat an owned ID as a periodic
  // image, but never within one list: images are a whole box length apart).
  byRank_.resize(nLocal);
  std::iota(byRank_.begin(), byRank_.end(), 0u);
  std::sort(byRank_.begin(), byRank_.end(),
            [&](std::uint32_t a, std::uint32_t b) { return P.gid(a) < P.gid(b); });
  rank_.resize(nLocal);
  xyz_.resize(3 * nLocal);
  for (std::size_t k = 0; k < nLocal; ++k) {
    rank_[byRank_[k]] = static_cast<std::uint32_t>(k);
    std::copy_n(P.alter(k), 3, &xyz_[3 * k]);
  }

  const int rankBits = std::max(1, static_cast<int>(std::bit_width(nLocal - (nLocal > 0))));
  const double r2max = radius * radius;
  start_.assign(n + 1, 0);
  // Each thread lists a contiguous range of particles into its own buffer; the buffers
  // are then concatenated in order, so the lists do not depend on the number of threads.
#pragma omp parallel
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
#pragma omp single
    threads_.resize(nt);
    Scratch& s = threads_[t];
    s.out.clear();
    s.near.resize(nLocal);
    const double* xyz = xyz_.data();
    const std::uint32_t* rank = rank_.data();
    const std::size_t lo = n * t / nt, hi = n * (t + 1) / nt;
    for (std::size_t b0 = lo; b0 < hi; b0 += kBlock) {
      const std::size_t b1 = std::min(hi, b0 + kBlock);
      // 1. The neighbours of each particle of the block, as (rank, particle) pairs in
      //    the engine's cell order.
      s.pairs.clear();
      for (std::size_t i = b0; i < b1; ++i) {
        const double x = xyz[3 * i], y = xyz[3 * i + 1], z = xyz[3 * i + 2];
        std::uint32_t* c = s.near.data();
        std::size_t m = 0;
        ctx.forEachNearby(i, [&](std::size_t j) {
          const double dx = xyz[3 * j] - x, dy = xyz[3 * j + 1] - y, dz = xyz[3 * j + 2] - z;
          c[m] = rank[j];
          m += dx * dx + dy * dy + dz * dz < r2max;
        });
        const std::uint64_t who = i - b0;
        for (std::size_t k = 0; k < m; ++k) s.pairs.push_back(std::uint64_t(c[k]) << 32 | who);
        start_[i + 1] = m;
      }
      // 2. Stable radix sort of the pairs by rank, 11 bits a pass; dealing them out in
      //    that order leaves every list sorted by global ID.
      s.spare.resize(s.pairs.size());
      for (int shift = 32; shift < 32 + rankBits; shift += kDigitBits) {
        std::array<std::uint32_t, (1u << kDigitBits) + 1> count{};
        for (std::uint64_t q : s.pairs) count[((q >> shift) & kDigitMask) + 1]++;
        for (std::size_t d = 0; d < (1u << kDigitBits); ++d) count[d + 1] += count[d];
        for (std::uint64_t q : s.pairs) s.spare[count[(q >> shift) & kDigitMask]++] = q;
        s.pairs.swap(s.spare);
      }
      const std::size_t base = s.out.size();
      s.cursor.resize(b1 - b0);
      std::size_t at = base;
      for (std::size_t i = b0; i < b1; ++i) {
        s.cursor[i - b0] = at;
        at += start_[i + 1];
      }
      s.out.resize(at);
      for (std::uint64_t q : s.pairs) s.out[s.cursor[q & 0xffffffffu]++] = byRank_[q >> 32];
    }
  }
  longest_ = 0;
  for (std::size_t i = 0; i < n; ++i) {
    longest_ = std::max(longest_, start_[i + 1]);
    start_[i + 1] += start_[i];
  }
  index_.resize(start_[n]);
  std::size_t at = 0;
  for (const Scratch& s : threads_) {
    std::copy(s.out.begin(), s.out.end(), index_.begin() + at);
    at += s.out.size();
  }
}

}  // namespace pdq::lj
