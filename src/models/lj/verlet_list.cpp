#include "models/lj/verlet_list.hpp"

#include <omp.h>

#include <algorithm>
#include <numeric>

namespace pdq::lj {

void VerletList::build(const Context& ctx, double radius) {
  const Particles& P = ctx.particles;
  const std::size_t nLocal = P.local(), n = P.owned();
  // Rank every local particle by global ID once, so each list is sorted by small integer
  // keys rather than by looking IDs up (a ghost may repeat an owned ID as a periodic
  // image, but never within one list: images are a whole box length apart).
  byRank_.resize(nLocal);
  std::iota(byRank_.begin(), byRank_.end(), 0u);
  std::sort(byRank_.begin(), byRank_.end(),
            [&](std::uint32_t a, std::uint32_t b) { return P.gid(a) < P.gid(b); });
  rank_.resize(nLocal);
  for (std::size_t k = 0; k < nLocal; ++k) rank_[byRank_[k]] = static_cast<std::uint32_t>(k);

  const double r2max = radius * radius;
  start_.assign(n + 1, 0);
  // Each thread lists a contiguous block of particles into its own buffer; the blocks are
  // then concatenated in order, so the result does not depend on the number of threads.
#pragma omp parallel
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
#pragma omp single
    blocks_.resize(nt);
    const std::size_t lo = n * t / nt, hi = n * (t + 1) / nt;
    std::vector<std::uint32_t>& out = blocks_[t];
    out.clear();
    for (std::size_t i = lo; i < hi; ++i) {
      const double* xi = P.alter(i);
      const std::size_t first = out.size();
      ctx.forEachNearby(i, [&](std::size_t j) {
        const double* xj = P.alter(j);
        const double dx = xj[0] - xi[0], dy = xj[1] - xi[1], dz = xj[2] - xi[2];
        if (dx * dx + dy * dy + dz * dz < r2max) out.push_back(rank_[j]);
      });
      std::sort(out.begin() + first, out.end());
      for (std::size_t k = first; k < out.size(); ++k) out[k] = byRank_[out[k]];
      start_[i + 1] = out.size() - first;
    }
  }
  for (std::size_t i = 0; i < n; ++i) start_[i + 1] += start_[i];
  index_.resize(start_[n]);
  std::size_t at = 0;
  for (const auto& b : blocks_) {
    std::copy(b.begin(), b.end(), index_.begin() + at);
    at += b.size();
  }
}

}  // namespace pdq::lj
