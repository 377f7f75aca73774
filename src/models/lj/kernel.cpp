#include "models/lj/kernel.hpp"

#include <algorithm>

namespace pdq::lj {

namespace {

template <bool ForceShift, bool Energy>
[[gnu::always_inline]] inline void range(const PairLJ& pair, const double* pos, std::size_t stride,
                                         const VerletList& lists, long first, long last,
                                         double* force, double* energy, double* virial,
                                         KernelScratch& scratch) {
  for (long i = first; i < last; ++i) {
    const PairSums s = pairSums<ForceShift, Energy>(pair, pos + i * stride, pos, stride,
                                                    lists.begin(i), lists.end(i), scratch);
    if (force) std::copy_n(s.f, 3, force + 3 * i);
    if constexpr (Energy) energy[i] = 0.5 * s.u, virial[i] = 0.5 * s.w;
  }
}

}  // namespace

// Compiled for several instruction sets, chosen at load time. The arithmetic is the same
// IEEE operations in the same order on each, so the results are the same bits.
[[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]] void pairSumsRange(
    const PairLJ& pair, const double* pos, std::size_t stride, const VerletList& lists, long first,
    long last, double* force, double* energy, double* virial, KernelScratch& scratch) {
  const bool fs = pair.shift == Shift::Force;
  if (energy) {
    if (fs)
      range<true, true>(pair, pos, stride, lists, first, last, force, energy, virial, scratch);
    else
      range<false, true>(pair, pos, stride, lists, first, last, force, energy, virial, scratch);
  } else {
    if (fs)
      range<true, false>(pair, pos, stride, lists, first, last, force, energy, virial, scratch);
    else
      range<false, false>(pair, pos, stride, lists, first, last, force, energy, virial, scratch);
  }
}

}  // namespace pdq::lj
