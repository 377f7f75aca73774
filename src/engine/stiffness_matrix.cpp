#include "engine/stiffness_matrix.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "engine/bytes.hpp"
#include "engine/context.hpp"

namespace pdq {

namespace {
using bytes::append;
using bytes::take;

// Eigen's LDLᵀ, which also tells the size of its factor once the pattern is analysed.
struct Ldlt
    : Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> {
  long predictedNonzeros() const {
    long n = 0;
    for (Eigen::Index k = 0; k < m_nonZerosPerCol.size(); ++k) n += m_nonZerosPerCol[k];
    return n;
  }
};
}  // namespace

struct StiffnessMatrix::Factor {
  Ldlt ldlt;
  std::vector<long> row;  // per gathered DOF (rank order, then owned order): unknown or -1
  std::vector<long> out;  // per gathered DOF: where it stands in the solution sent back
  std::size_t total = 0;  // gathered DOFs
  long unknowns = 0, entries = 0, fill = 0;  // K̂'s stored entries, its factor's
  std::vector<int> outer, inner;  // the pattern (compressed columns) ldlt was ordered for
};

StiffnessMatrix::StiffnessMatrix() = default;
StiffnessMatrix::~StiffnessMatrix() = default;

long StiffnessMatrix::unknowns() const { return factor_ ? factor_->unknowns : 0; }
long StiffnessMatrix::matrixNonzeros() const { return factor_ ? factor_->entries : 0; }
long StiffnessMatrix::factorNonzeros() const { return factor_ ? factor_->fill : 0; }

StiffnessMatrix::Outcome StiffnessMatrix::factorise(Context& ctx, std::span<const Gid> gids,
                                                    int dofs, std::span<const unsigned char> free,
                                                    const std::vector<Entry>& entries,
                                                    std::span<const double> fallback, double shift,
                                                    double maxFill) {
  const std::size_t n = gids.size();
  values_ = n * dofs;
  std::vector<char> mine;
  const unsigned long count = n;
  append(mine, &count, 1);
  append(mine, gids.data(), n);
  append(mine, free.data(), n * dofs);
  append(mine, fallback.data(), n * dofs);
  std::vector<std::size_t> starts;
  const std::vector<char> particles = ctx.gather(mine, starts);
  std::vector<char> rows;
  append(rows, entries.data(), entries.size());
  const std::vector<char> gathered = ctx.gather(rows, starts);

  std::vector<char> reply;  // rank 0: whether K̂ is positive definite, then the sorted IDs
  if (ctx.root()) {
    if (!factor_) factor_ = std::make_unique<Factor>();
    Factor& F = *factor_;
    std::vector<Gid> all;
    std::vector<unsigned char> isFree;
    std::vector<double> diag;
    for (const char* in = particles.data(); in < particles.data() + particles.size();) {
      unsigned long m = 0;
      take(in, &m, 1);
      const std::size_t at = all.size();
      all.resize(at + m);
      isFree.resize((at + m) * dofs);
      diag.resize((at + m) * dofs);
      take(in, all.data() + at, m);
      take(in, isFree.data() + at * dofs, m * dofs);
      take(in, diag.data() + at * dofs, m * dofs);
    }
    // Unknowns in the order of global IDs, then DOFs: the same on any number of ranks.
    std::vector<std::pair<Gid, std::size_t>> order(all.size());
    for (std::size_t q = 0; q < all.size(); ++q) order[q] = {all[q], q};
    std::sort(order.begin(), order.end());
    F.total = all.size() * dofs;
    F.row.assign(F.total, -1);
    F.out.assign(F.total, 0);
    long unknowns = 0;
    for (std::size_t p = 0; p < order.size(); ++p)
      for (int d = 0; d < dofs; ++d) {
        const std::size_t k = order[p].second * dofs + d;
        F.out[k] = static_cast<long>(p * dofs + d);
        if (isFree[k]) F.row[k] = unknowns++;
      }
    F.unknowns = unknowns;
    auto unknown = [&](Gid g, int d) -> long {
      auto it = std::lower_bound(order.begin(), order.end(), std::pair<Gid, std::size_t>{g, 0});
      if (it == order.end() || it->first != g) return -1;
      return F.row[it->second * dofs + d];
    };
    // K̂ = (K + Kᵀ)/2, its lower half: an entry K_ij off the diagonal gives its half at
    // (max, min), where K_ji's half joins it; two terms add up to the same bits in either
    // order, so the ranks' order does not matter. A diagonal entry is whole, and the shift
    // (or the fallback of an empty row) comes after it.
    std::vector<Eigen::Triplet<double>> triplets;
    const std::size_t nEntries = gathered.size() / sizeof(Entry);
    triplets.reserve(nEntries + static_cast<std::size_t>(unknowns));
    std::vector<unsigned char> hasRow(unknowns, 0);
    const char* in = gathered.data();
    for (std::size_t e = 0; e < nEntries; ++e) {
      Entry x;
      take(in, &x, 1);
      const long i = unknown(x.row, x.rowDof), j = unknown(x.col, x.colDof);
      if (i < 0 || j < 0) continue;
      hasRow[i] = 1;
      triplets.emplace_back(static_cast<int>(std::max(i, j)), static_cast<int>(std::min(i, j)),
                            i == j ? x.value : x.value / 2);
    }
    for (std::size_t k = 0; k < F.total; ++k) {
      const int i = static_cast<int>(F.row[k]);
      if (i < 0) continue;
      if (!hasRow[i])
        triplets.emplace_back(i, i, diag[k]);
      else if (shift > 0)
        triplets.emplace_back(i, i, shift * diag[k]);
    }
    Eigen::SparseMatrix<double> K(unknowns, unknowns);
    K.setFromTriplets(triplets.begin(), triplets.end());
    // The ordering and the factor's structure depend on K̂'s pattern alone: kept while it
    // stays the same (the interactions that break only change values until one is lost).
    const std::span<const int> outer(K.outerIndexPtr(), static_cast<std::size_t>(unknowns) + 1),
        inner(K.innerIndexPtr(), static_cast<std::size_t>(K.nonZeros()));
    if (!std::ranges::equal(outer, F.outer) || !std::ranges::equal(inner, F.inner)) {
      F.ldlt.analyzePattern(K);
      F.outer.assign(outer.begin(), outer.end());
      F.inner.assign(inner.begin(), inner.end());
      F.fill = F.ldlt.predictedNonzeros();
    }
    F.entries = K.nonZeros();
    Outcome outcome = Outcome::TooLarge;
    if (static_cast<double>(F.fill) <= maxFill * static_cast<double>(F.entries)) {
      F.ldlt.factorize(K);
      const bool ok =
          F.ldlt.info() == Eigen::Success && unknowns > 0 && F.ldlt.vectorD().minCoeff() > 0;
      outcome = ok ? Outcome::Factorised : Outcome::NotDefinite;
    }
    reply.push_back(static_cast<char>(outcome));
    std::vector<Gid> sorted(order.size());
    for (std::size_t p = 0; p < order.size(); ++p) sorted[p] = order[p].first;
    append(reply, sorted.data(), sorted.size());
  }
  reply = ctx.broadcast(std::move(reply));
  const auto outcome = static_cast<Outcome>(reply.at(0));
  const std::size_t nAll = (reply.size() - 1) / sizeof(Gid);
  std::vector<Gid> sorted(nAll);
  const char* in = reply.data() + 1;
  take(in, sorted.data(), nAll);
  at_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    auto it = std::lower_bound(sorted.begin(), sorted.end(), gids[i]);
    if (it == sorted.end() || *it != gids[i])
      throw std::logic_error("stiffness matrix: an owned particle is missing");
    at_[i] = static_cast<std::size_t>(it - sorted.begin());
  }
  dofs_ = dofs;
  return outcome;
}

void StiffnessMatrix::solve(Context& ctx, std::span<const double> b, std::span<double> x) const {
  std::vector<char> mine;
  append(mine, b.data(), values_);
  std::vector<std::size_t> starts;
  const std::vector<char> all = ctx.gather(mine, starts);
  std::vector<char> reply;
  if (ctx.root()) {
    const Factor& F = *factor_;
    if (all.size() != F.total * sizeof(double))
      throw std::logic_error("stiffness matrix: the particles changed since the factorisation");
    std::vector<double> rhs(F.total);
    std::memcpy(rhs.data(), all.data(), all.size());
    Eigen::VectorXd r(F.unknowns);
    for (std::size_t k = 0; k < F.total; ++k)
      if (F.row[k] >= 0) r[F.row[k]] = rhs[k];
    const Eigen::VectorXd s = F.ldlt.solve(r);
    std::vector<double> out(F.total, 0.0);
    for (std::size_t k = 0; k < F.total; ++k)
      if (F.row[k] >= 0) out[F.out[k]] = s[F.row[k]];
    append(reply, out.data(), out.size());
  }
  reply = ctx.broadcast(std::move(reply));
  std::vector<double> s(reply.size() / sizeof(double));
  std::memcpy(s.data(), reply.data(), s.size() * sizeof(double));
  for (std::size_t i = 0; i < at_.size(); ++i)
    for (int d = 0; d < dofs_; ++d) x[i * dofs_ + d] = s[at_[i] * dofs_ + d];
}

}  // namespace pdq
