#pragma once
// The numeric factorisation L Lᵀ = P K Pᵀ of a supernodal factor whose structure CHOLMOD's
// analysis gave (SupernodalLayout), left-looking by dense blocks (BLAS and LAPACK), as
// CHOLMOD's own, on one thread or two (docs/quasi-static.md, "Factorisation on two
// threads"). A large supernode's updates from the supernodes below it, and the solve of its
// rows below the diagonal block, are cut in two by its rows at a place the structure alone
// fixes; the rows above the cut are one thread's, those below the other's. The BLAS calls
// and their arguments are the same whatever the number of threads, and each entry is
// updated by its descendants in their order: the same bits on one thread or two.
#include <vector>

#include "engine/supernodal_solve.hpp"

namespace pdq {

class HelperThread;

class SupernodalFactor {
 public:
  // The structure (copied), and K's pattern: its lower half by compressed columns in the
  // unknowns' order (colStart[n] entries, rowOf of each), whose every entry must have its
  // place in the factor.
  void analyse(const SupernodalLayout& L, const int* colStart, const int* rowOf);
  // Factorises K, its values in the pattern's order; with a helper, the cut supernodes on
  // two threads where the BLAS allows it. False when K is not positive definite.
  bool factorise(const double* values, HelperThread* helper);
  // Whether two threads may call the BLAS at once: OpenBLAS's pthreads build (Debian's
  // libopenblas0-pthread). Its serial build shares its buffers between callers, and another
  // BLAS is not known to allow it. The first call also sets OpenBLAS to one thread of its
  // own: the factor's bits must not depend on how many it finds.
  static bool blasFromTwoThreads();
  // The factor's values as CHOLMOD lays them out (SupernodalLayout::px), after factorise().
  const double* values() const { return values_.data(); }
  // The share of the factorisation's operations in supernodes cut in two.
  double cutShare() const { return cutShare_; }

 private:
  // Supernode d's update of the supernode it is listed for: d's rows rows_[first] on, of
  // which those before rows_[last] are the supernode's columns.
  struct Update {
    int d, first, last;
  };
  // The updates of supernode s by its descendants, and the solve of its rows below the
  // diagonal block, for its rows [lo, hi) (of its row list) in workspace `c`.
  void update(long s, int lo, int hi, std::vector<double>& c);
  void solveBelow(long s, int lo, int hi);

  long n_ = 0, nsuper_ = 0;
  std::vector<int> super_, pi_, rows_, owner_;
  std::vector<long> px_;
  std::vector<long> updatesFrom_;  // supernode s's updates: updates_[updatesFrom_[s]] on
  std::vector<Update> updates_;
  // Per supernode, the first row of the second thread's updates and of its solve below the
  // diagonal block (0: not cut).
  std::vector<int> cutUpdates_, cutSolve_;
  std::vector<long> place_;  // per entry of K: its place in values_
  std::vector<double> values_, work0_, work1_;
  std::vector<int> map_;  // per row of the factor: its place in the supernode at hand
  double cutShare_ = 0;
};

}  // namespace pdq
