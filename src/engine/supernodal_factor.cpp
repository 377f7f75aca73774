#include "engine/supernodal_factor.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <stdexcept>

#include "engine/helper_thread.hpp"

extern "C" {
void dgemm_(const char* transA, const char* transB, const int* m, const int* n, const int* k,
            const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
            const double* beta, double* c, const int* ldc);
void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha,
            const double* a, const int* lda, const double* beta, double* c, const int* ldc);
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
void dtrsm_(const char* side, const char* uplo, const char* transA, const char* diag, const int* m,
            const int* n, const double* alpha, const double* a, const int* lda, double* b,
            const int* ldb);
}

namespace pdq {
namespace {

// A supernode is cut in two where a part holds at least this many operations: below it,
// waking the second thread costs more than it saves.
constexpr double kCutWork = 2e6;

// The first place in [0, count) whose value of f is at least `at` (f ascending).
template <class F>
int firstAtLeast(int count, int at, F&& f) {
  int lo = 0, hi = count;
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (f(mid) < at)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo;
}

// The place where the running sum of `work` first reaches half its total, when each side
// of it holds kCutWork (0 otherwise).
int halfway(const std::vector<double>& work) {
  double total = 0;
  for (double w : work) total += w;
  double sum = 0;
  for (int r = 0; r < static_cast<int>(work.size()); ++r) {
    sum += work[r];
    if (2 * sum >= total) return sum >= kCutWork && total - sum >= kCutWork ? r + 1 : 0;
  }
  return 0;
}

}  // namespace

void SupernodalFactor::analyse(const SupernodalLayout& L, const int* colStart, const int* rowOf) {
  n_ = L.n, nsuper_ = L.nsuper;
  super_.assign(L.super, L.super + nsuper_ + 1);
  pi_.assign(L.pi, L.pi + nsuper_ + 1);
  rows_.assign(L.rows, L.rows + pi_[nsuper_]);
  px_.assign(L.px, L.px + nsuper_ + 1);
  owner_.resize(n_);
  for (long s = 0; s < nsuper_; ++s)
    for (int k = super_[s]; k < super_[s + 1]; ++k) owner_[k] = static_cast<int>(s);

  // Each supernode's updates, from its descendants in ascending order: d updates s where
  // d's rows below its own columns meet s's columns.
  std::vector<std::vector<Update>> of(nsuper_);
  for (long d = 0; d < nsuper_; ++d) {
    int p = pi_[d] + (super_[d + 1] - super_[d]);
    while (p < pi_[d + 1]) {
      const int s = owner_[rows_[p]];
      int q = p;
      while (q < pi_[d + 1] && rows_[q] < super_[s + 1]) ++q;
      of[s].push_back({static_cast<int>(d), p, q});
      p = q;
    }
  }
  updatesFrom_.assign(nsuper_ + 1, 0);
  updates_.clear();
  for (long s = 0; s < nsuper_; ++s) {
    updates_.insert(updates_.end(), of[s].begin(), of[s].end());
    updatesFrom_[s + 1] = static_cast<long>(updates_.size());
  }

  // The cuts: each row's share of the updates' operations (a row of d meeting the columns
  // below it), and of the solve below the diagonal block (the same for every row).
  cutUpdates_.assign(nsuper_, 0);
  cutSolve_.assign(nsuper_, 0);
  std::size_t most = 1;
  double total = 0, cut = 0;
  std::vector<double> work;
  std::vector<int> at(n_);
  for (long s = 0; s < nsuper_; ++s) {
    const int nscol = super_[s + 1] - super_[s], nsrow = pi_[s + 1] - pi_[s];
    for (int k = 0; k < nsrow; ++k) at[rows_[pi_[s] + k]] = k;
    work.assign(nsrow, 0.0);
    for (long u = updatesFrom_[s]; u < updatesFrom_[s + 1]; ++u) {
      const Update& up = updates_[u];
      const int ndcol = super_[up.d + 1] - super_[up.d];
      const int ndrow1 = up.last - up.first, ndrow2 = pi_[up.d + 1] - up.first;
      for (int r = 0; r < ndrow2; ++r)
        work[at[rows_[up.first + r]]] += 2.0 * ndcol * std::min(r + 1, ndrow1);
      most = std::max(most, static_cast<std::size_t>(ndrow2) * ndrow1);
    }
    double updating = 0;
    for (double w : work) updating += w;
    cutUpdates_[s] = halfway(work);
    const double solving = static_cast<double>(nsrow - nscol) * nscol * nscol;
    if (solving >= 2 * kCutWork && nsrow - nscol >= 2) cutSolve_[s] = nscol + (nsrow - nscol) / 2;
    const double own = static_cast<double>(nscol) * nscol * nscol / 3;
    total += updating + solving + own;
    cut += (cutUpdates_[s] > 0 ? updating : 0) + (cutSolve_[s] > 0 ? solving : 0);
  }
  cutShare_ = total > 0 ? cut / total : 0;
  work0_.resize(most);
  work1_.resize(most);
  map_.assign(n_, 0);

  // Each entry of K at its place in the factor: row and column in the factor's order, the
  // column's supernode, the row's place in its row list.
  std::vector<int> inverse(n_);
  for (long k = 0; k < n_; ++k) inverse[L.perm[k]] = static_cast<int>(k);
  place_.resize(static_cast<std::size_t>(colStart[n_]));
  for (long j = 0; j < n_; ++j)
    for (int e = colStart[j]; e < colStart[j + 1]; ++e) {
      const int a = inverse[rowOf[e]], b = inverse[j];
      const int row = std::max(a, b), col = std::min(a, b), s = owner_[col];
      const int* first = rows_.data() + pi_[s];
      const int* last = rows_.data() + pi_[s + 1];
      const int* it = std::lower_bound(first, last, row);
      if (it == last || *it != row)
        throw std::logic_error("supernodal factor: an entry of K outside the factor's pattern");
      place_[e] = px_[s] + static_cast<long>(col - super_[s]) * (last - first) + (it - first);
    }
  values_.assign(static_cast<std::size_t>(px_[nsuper_]), 0.0);
}

void SupernodalFactor::update(long s, int lo, int hi, std::vector<double>& c) {
  const int k1 = super_[s], nsrow = pi_[s + 1] - pi_[s];
  double* S = values_.data() + px_[s];
  const double one = 1, zero = 0;
  for (long u = updatesFrom_[s]; u < updatesFrom_[s + 1]; ++u) {
    const Update& up = updates_[u];
    const int ndcol = super_[up.d + 1] - super_[up.d], ndrow = pi_[up.d + 1] - pi_[up.d];
    const int ndrow1 = up.last - up.first, ndrow2 = pi_[up.d + 1] - up.first;
    const int* at = rows_.data() + up.first;
    // d's rows whose places in s lie in [lo, hi): a range, both row lists ascending.
    const int r0 = firstAtLeast(ndrow2, lo, [&](int r) { return map_[at[r]]; });
    const int r1 = firstAtLeast(ndrow2, hi, [&](int r) { return map_[at[r]]; });
    if (r0 == r1) continue;
    // C = A Aᵀ for rows [r0, r1) and the columns up to each row (A: d's rows from `first`),
    // rows by columns with leading dimension r1 − r0: the block left of the diagonal, the
    // diagonal's triangle, the block below it.
    const double* A = values_.data() + px_[up.d] + (up.first - pi_[up.d]);
    const int ldc = r1 - r0, left = std::min(r0, ndrow1), end = std::min(r1, ndrow1);
    double* C = c.data();
    if (left > 0)
      dgemm_("N", "T", &ldc, &left, &ndcol, &one, A + r0, &ndrow, A, &ndrow, &zero, C, &ldc);
    if (r0 < ndrow1) {
      const int m = end - r0, below = r1 - end;
      double* D = C + static_cast<long>(r0) * ldc;
      dsyrk_("L", "N", &m, &ndcol, &one, A + r0, &ndrow, &zero, D, &ldc);
      if (below > 0)
        dgemm_("N", "T", &below, &m, &ndcol, &one, A + end, &ndrow, A + r0, &ndrow, &zero, D + m,
               &ldc);
    }
    for (int col = 0; col < end; ++col) {
      double* Sc = S + static_cast<long>(at[col] - k1) * nsrow;
      const double* Cc = C + static_cast<long>(col) * ldc;
      for (int r = std::max(r0, col); r < r1; ++r) Sc[map_[at[r]]] -= Cc[r - r0];
    }
  }
}

void SupernodalFactor::solveBelow(long s, int lo, int hi) {
  const int nscol = super_[s + 1] - super_[s], nsrow = pi_[s + 1] - pi_[s], m = hi - lo;
  if (m <= 0) return;
  double* S = values_.data() + px_[s];
  const double one = 1;
  dtrsm_("R", "L", "T", "N", &m, &nscol, &one, S, &nsrow, S + lo, &nsrow);
}

bool SupernodalFactor::blasFromTwoThreads() {
  static const bool allowed = [] {
    using SetThreads = void (*)(int);
    if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      set(1);
    using Parallel = int (*)();
    const auto parallel = reinterpret_cast<Parallel>(dlsym(RTLD_DEFAULT, "openblas_get_parallel"));
    return parallel && parallel() == 1;
  }();
  return allowed;
}

bool SupernodalFactor::factorise(const double* values, HelperThread* helper) {
  if (!blasFromTwoThreads()) helper = nullptr;
  std::fill(values_.begin(), values_.end(), 0.0);
  for (std::size_t e = 0; e < place_.size(); ++e) values_[place_[e]] = values[e];
  for (long s = 0; s < nsuper_; ++s) {
    const int nscol = super_[s + 1] - super_[s], nsrow = pi_[s + 1] - pi_[s];
    for (int k = 0; k < nsrow; ++k) map_[rows_[pi_[s] + k]] = k;
    if (const int h = cutUpdates_[s]; h > 0)
      inTwo(
          helper, [&] { update(s, 0, h, work0_); }, [&] { update(s, h, nsrow, work1_); });
    else
      update(s, 0, nsrow, work0_);
    int info = 0;
    dpotrf_("L", &nscol, values_.data() + px_[s], &nsrow, &info);
    if (info != 0) return false;
    if (const int h = cutSolve_[s]; h > 0)
      inTwo(
          helper, [&] { solveBelow(s, nscol, h); }, [&] { solveBelow(s, h, nsrow); });
    else
      solveBelow(s, nscol, nsrow);
  }
  return true;
}

}  // namespace pdq
