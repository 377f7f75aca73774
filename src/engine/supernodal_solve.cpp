#include "engine/supernodal_solve.hpp"

#include <algorithm>
#include <cstring>
#include <functional>

#include "engine/helper_thread.hpp"

namespace pdq {
namespace {

using V8d = double __attribute__((vector_size(64)));
using V8f = float __attribute__((vector_size(32)));

// Columns taken together: the forward pass updates each row below them once per block (in
// the columns' order, so the bits are those of one column at a time), the backward pass
// forms their sums over the rows below them side by side.
constexpr long kBlock = 4;

// A supernode's column c, indexed by row within the supernode (c[k] for k ≥ the column).
inline const float* column(const float* block, long nr, long c) {
  return block + c * nr - c * (c + 1) / 2;
}

// w[r] −= Σ_k col[k][r] wc[k] for rows [r, nr), the columns in order.
template <int C>
[[gnu::always_inline]] inline void forwardColumns(const float* const* col, const double* wc,
                                                  double* w, long r, long nr) {
  V8d wv[C];
  for (int k = 0; k < C; ++k)
    for (int l = 0; l < 8; ++l) wv[k][l] = wc[k];
  for (; r + 8 <= nr; r += 8) {
    V8d t;
    std::memcpy(&t, w + r, sizeof t);
    for (int k = 0; k < C; ++k) {
      V8f f;
      std::memcpy(&f, col[k] + r, sizeof f);
      t -= __builtin_convertvector(f, V8d) * wv[k];
    }
    std::memcpy(w + r, &t, sizeof t);
  }
  for (; r < nr; ++r) {
    double t = w[r];
    for (int k = 0; k < C; ++k) t -= col[k][r] * wc[k];
    w[r] = t;
  }
}

// s[k] = Σ_r col[k][r] w[r] over rows [r, nr), in eight lanes of rows added as pairs.
template <int C>
[[gnu::always_inline]] inline void backwardColumns(const float* const* col, const double* w, long r,
                                                   long nr, double* s) {
  V8d a[C];
  for (int k = 0; k < C; ++k) a[k] = V8d{};
  for (; r + 8 <= nr; r += 8) {
    V8d wr;
    std::memcpy(&wr, w + r, sizeof wr);
    for (int k = 0; k < C; ++k) {
      V8f f;
      std::memcpy(&f, col[k] + r, sizeof f);
      a[k] += __builtin_convertvector(f, V8d) * wr;
    }
  }
  for (int l = 0; r < nr; ++r, ++l)
    for (int k = 0; k < C; ++k) a[k][l] += col[k][r] * w[r];
  for (int k = 0; k < C; ++k)
    s[k] =
        ((a[k][0] + a[k][1]) + (a[k][2] + a[k][3])) + ((a[k][4] + a[k][5]) + (a[k][6] + a[k][7]));
}

// The same for a block of 1 to kBlock columns.
[[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]] void forwardBlock(
    long cols, const float* const* col, const double* wc, double* w, long r, long nr) {
  switch (cols) {
    case 1:
      return forwardColumns<1>(col, wc, w, r, nr);
    case 2:
      return forwardColumns<2>(col, wc, w, r, nr);
    case 3:
      return forwardColumns<3>(col, wc, w, r, nr);
    default:
      return forwardColumns<kBlock>(col, wc, w, r, nr);
  }
}

[[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]] void backwardBlock(
    long cols, const float* const* col, const double* w, long r, long nr, double* s) {
  switch (cols) {
    case 1:
      return backwardColumns<1>(col, w, r, nr, s);
    case 2:
      return backwardColumns<2>(col, w, r, nr, s);
    case 3:
      return backwardColumns<3>(col, w, r, nr, s);
    default:
      return backwardColumns<kBlock>(col, w, r, nr, s);
  }
}

}  // namespace

void SupernodalSolve::assign(const SupernodalLayout& L, const double* values) {
  n_ = L.n, nsuper_ = L.nsuper;
  perm_.assign(L.perm, L.perm + n_);
  super_.assign(L.super, L.super + nsuper_ + 1);
  pi_.assign(L.pi, L.pi + nsuper_ + 1);
  rows_.assign(L.rows, L.rows + pi_[nsuper_]);
  packed_.assign(nsuper_, 0);
  workBefore_.assign(nsuper_ + 1, 0);
  values_.clear();
  long most = 0;
  for (long s = 0; s < nsuper_; ++s) {
    packed_[s] = static_cast<long>(values_.size());
    const long nc = super_[s + 1] - super_[s], nr = pi_[s + 1] - pi_[s];
    for (long c = 0; c < nc; ++c)
      values_.insert(values_.end(), values + L.px[s] + c * nr + c, values + L.px[s] + (c + 1) * nr);
    workBefore_[s + 1] = static_cast<long>(values_.size());
    most = std::max(most, nr);
  }
  y_.resize(n_);
  w0_.resize(most);
  w1_.resize(most);

  // The supernodal elimination tree: a supernode's parent holds the first row below its
  // columns. In a postorder (CHOLMOD's), each subtree is the range [first, root].
  std::vector<long> owner(n_), parent(nsuper_, -1), first(nsuper_);
  for (long s = 0; s < nsuper_; ++s)
    for (long k = super_[s]; k < super_[s + 1]; ++k) owner[k] = s;
  std::vector<std::vector<long>> children(nsuper_ + 1);  // the last: the roots'
  bool postorder = true;
  for (long s = 0; s < nsuper_; ++s) {
    first[s] = s;
    const long nc = super_[s + 1] - super_[s];
    if (pi_[s] + nc < pi_[s + 1]) parent[s] = owner[rows_[pi_[s] + nc]];
    postorder = postorder && (parent[s] < 0 || parent[s] > s);
  }
  cut_ = top_ = 0;
  if (!postorder) return;
  for (long s = 0; s < nsuper_; ++s) {
    if (parent[s] >= 0) first[parent[s]] = std::min(first[parent[s]], first[s]);
    children[parent[s] >= 0 ? parent[s] : nsuper_].push_back(s);
  }
  // Part one: [0, cut), part two: [cut, top), the children of supernode `top` (or roots)
  // from one of them on; neither part updates the other, and both update only themselves
  // and [top, nsuper). The cut that leaves the least work on the longer path.
  long best = work(0, nsuper_);
  for (long p = 0; p <= nsuper_; ++p)
    for (std::size_t k = 1; k < children[p].size(); ++k) {
      const long m = first[children[p][k]];
      const long path = std::max(work(0, m), work(m, p)) + work(p, nsuper_);
      if (path < best) best = path, cut_ = m, top_ = p;
    }
  if (5 * best > 4 * work(0, nsuper_)) cut_ = top_ = 0;
  // Room for part two's updates of the rows above both: the helper thread allocates nothing.
  std::size_t later = 0;
  for (long sn = cut_; sn < top_; ++sn)
    for (long r = pi_[sn]; r < pi_[sn + 1]; ++r) later += rows_[r] >= super_[top_];
  later_.clear();
  later_.reserve(later);
}

std::array<double, 3> SupernodalSolve::shares() const {
  const double total = static_cast<double>(std::max(work(0, nsuper_), 1L));
  return {static_cast<double>(work(0, cut_)) / total, static_cast<double>(work(cut_, top_)) / total,
          static_cast<double>(work(top_, nsuper_)) / total};
}

void SupernodalSolve::forward(long s0, long s1, std::vector<double>& ws,
                              std::vector<Deferred>* later, int limit) {
  double* w = ws.data();
  double* y = y_.data();
  for (long sn = s0; sn < s1; ++sn) {
    const long k1 = super_[sn], nc = super_[sn + 1] - k1, nr = pi_[sn + 1] - pi_[sn];
    const float* B = values_.data() + packed_[sn];
    const int* at = rows_.data() + pi_[sn];
    std::copy(y + k1, y + k1 + nc, w);
    std::fill(w + nc, w + nr, 0.0);
    for (long c0 = 0; c0 < nc; c0 += kBlock) {
      const long end = std::min(c0 + kBlock, nc);
      const float* col[kBlock];
      double wc[kBlock];
      for (long c = c0; c < end; ++c) {
        col[c - c0] = column(B, nr, c);
        wc[c - c0] = w[c] = w[c] / col[c - c0][c];
        for (long r = c + 1; r < end; ++r) w[r] -= col[c - c0][r] * wc[c - c0];
      }
      forwardBlock(end - c0, col, wc, w, end, nr);
    }
    std::copy(w, w + nc, y + k1);
    for (long r = nc; r < nr; ++r) {
      if (later && at[r] >= limit)
        later->push_back({at[r], w[r]});
      else
        y[at[r]] += w[r];
    }
  }
}

void SupernodalSolve::backward(long s0, long s1, std::vector<double>& ws) {
  double* w = ws.data();
  double* y = y_.data();
  for (long sn = s1 - 1; sn >= s0; --sn) {
    const long k1 = super_[sn], nc = super_[sn + 1] - k1, nr = pi_[sn + 1] - pi_[sn];
    const float* B = values_.data() + packed_[sn];
    const int* at = rows_.data() + pi_[sn];
    for (long r = 0; r < nr; ++r) w[r] = y[at[r]];
    for (long c0 = (nc - 1) / kBlock * kBlock; c0 >= 0; c0 -= kBlock) {
      const long end = std::min(c0 + kBlock, nc);
      const float* col[kBlock];
      double s[kBlock] = {0, 0, 0, 0};
      for (long c = c0; c < end; ++c) col[c - c0] = column(B, nr, c);
      backwardBlock(end - c0, col, w, end, nr, s);
      for (long c = end - 1; c >= c0; --c) {
        double t = s[c - c0];
        for (long r = c + 1; r < end; ++r) t += col[c - c0][r] * w[r];
        w[c] = (w[c] - t) / col[c - c0][c];
      }
    }
    std::copy(w, w + nc, y + k1);
  }
}

SupernodalSolve::SupernodalSolve() = default;
SupernodalSolve::~SupernodalSolve() = default;

void SupernodalSolve::solve(const double* b, double* x, HelperThread* helper) {
  for (long k = 0; k < n_; ++k) y_[k] = b[perm_[k]];
  // Part two's updates of the rows above both parts wait for part one's: the order in which
  // one thread adds them.
  const int limit = top_ < nsuper_ ? super_[top_] : static_cast<int>(n_);
  later_.clear();
  HelperThread* two = cut_ < top_ ? helper : nullptr;
  auto parts = [&](const std::function<void()>& one, const std::function<void()>& other) {
    inTwo(two, one, other);
  };
  parts([&] { forward(0, cut_, w0_, nullptr, 0); },
        [&] { forward(cut_, top_, w1_, &later_, limit); });
  for (const Deferred& d : later_) y_[d.row] += d.value;
  forward(top_, nsuper_, w0_, nullptr, 0);
  backward(top_, nsuper_, w0_);
  parts([&] { backward(0, cut_, w0_); }, [&] { backward(cut_, top_, w1_); });
  for (long k = 0; k < n_; ++k) x[perm_[k]] = y_[k];
}

}  // namespace pdq
