#include "engine/stiffness_matrix.hpp"

#include <cholmod.h>
#include <omp.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/bytes.hpp"
#include "engine/context.hpp"
#include "engine/helper_thread.hpp"
#include "engine/supernodal_factor.hpp"
#include "engine/supernodal_solve.hpp"

namespace pdq {

namespace {
using bytes::append;
using bytes::take;

// A factor that fills in over this many times the matrix's pattern (its stored entries, the
// zeros of the bonds' pattern included: 2D lattices about 3.9, 3D ones from about 5.6) is
// supernodal, its dense blocks factorised by BLAS (engine/supernodal_factor.hpp, on two
// threads where rank 0 has a helper): a 3D member's factorisation takes a fraction of the
// simplicial one's time. Sparser ones (2D lattices) stay simplicial LDLᵀ,
// whose solves are the faster there. The pattern, not the nonzeros, decides, so that a run
// restarted with more interactions broken chooses as the first run did.
constexpr double kSupernodalFill = 4.5;

// A supernodal factor's structure as CHOLMOD's analysis lays it out.
SupernodalLayout layout(const cholmod_factor& L) {
  return {static_cast<long>(L.n),          static_cast<long>(L.nsuper),
          static_cast<const int*>(L.Perm), static_cast<const int*>(L.super),
          static_cast<const int*>(L.pi),   static_cast<const int*>(L.s),
          static_cast<const int*>(L.px)};
}

void check(const cholmod_common& c, const char* what) {
  if (c.status < CHOLMOD_OK)
    throw std::runtime_error(std::string("stiffness matrix: CHOLMOD failed in ") + what +
                             " (status " + std::to_string(c.status) + ")");
}
}  // namespace

// CHOLMOD's simplicial LDLᵀ (SuiteSparse), or supernodal LLᵀ on its analysis where the
// factor fills in much: its ordering tries approximate minimum degree and, where that fills in much
// (3D lattices), nested dissection (METIS), and keeps the better; its analysis tells the size of
// the factor before the factorisation.
struct StiffnessMatrix::Factor {
  cholmod_common c;
  cholmod_sparse* K = nullptr;   // K̂'s lower half, compressed columns
  cholmod_factor* L = nullptr;   // analysed for K's pattern; factorised when simplicial
  cholmod_dense* rhs = nullptr;  // the solves' right-hand side, and their workspaces
  cholmod_dense *x = nullptr, *ys = nullptr, *e = nullptr;
  SupernodalFactor numeric;  // a supernodal factor's factorisation
  SupernodalSolve solver;    // and solves
  // Their second thread, where another rank of this node waits for them or the run has
  // OpenMP threads.
  std::unique_ptr<HelperThread> helper;
  std::vector<double> sol;  // a solution
  // Per gathered entry of the last assembly: its row's unknown and its place in K's values
  // (−1: not an unknown's); per unknown, its diagonal's place.
  std::vector<long> rowOf, placed, diagonal;
  std::vector<long> keyRows;  // `row` as it was then
  std::vector<long> row;      // per gathered DOF (rank order, then owned order): unknown or -1
  std::vector<long> out;      // per gathered DOF: where it stands in the solution sent back
  std::size_t total = 0;      // gathered DOFs
  long unknowns = 0, stored = 0, entries = 0, fill = 0;  // K̂'s stored entries, nonzero ones,
                                                         // its factor's

  Factor() {
    cholmod_start(&c);
    c.print = 0;  // its warnings (a matrix not positive definite) are handled here
    c.final_ll = 0;
  }
  ~Factor() {
    cholmod_free_sparse(&K, &c);
    cholmod_free_factor(&L, &c);
    cholmod_free_dense(&rhs, &c);
    cholmod_free_dense(&x, &c);
    cholmod_free_dense(&ys, &c);
    cholmod_free_dense(&e, &c);
    cholmod_finish(&c);
  }
  Factor(const Factor&) = delete;
  Factor& operator=(const Factor&) = delete;
};

StiffnessMatrix::StiffnessMatrix() = default;
StiffnessMatrix::~StiffnessMatrix() = default;

long StiffnessMatrix::unknowns() const { return factor_ ? factor_->unknowns : 0; }
long StiffnessMatrix::matrixNonzeros() const { return factor_ ? factor_->entries : 0; }
long StiffnessMatrix::matrixStored() const { return factor_ ? factor_->stored : 0; }
long StiffnessMatrix::factorNonzeros() const { return factor_ ? factor_->fill : 0; }
std::vector<double> StiffnessMatrix::twoThreadShares() const {
  if (!factor_ || !factor_->L || !factor_->L->is_super || !factor_->helper) return {};
  const auto s = factor_->solver.shares();
  if (s[0] == 0) return {};
  return {s.begin(), s.end()};
}

double StiffnessMatrix::twoThreadFactorisation() const {
  if (!factor_ || !factor_->L || !factor_->L->is_super || !factor_->helper ||
      !SupernodalFactor::blasFromTwoThreads())
    return 0;
  return factor_->numeric.cutShare();
}

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
  // The entries, or their values alone where every rank sends the same particles, free
  // DOFs and entries as the last time and rank 0 has placed those.
  const bool sameKeys =
      std::ranges::equal(gids, sentGids_) && std::ranges::equal(free, sentFree_) &&
      std::ranges::equal(entries, sentKeys_, [](const Entry& x, const Entry& y) {
        return x.row == y.row && x.col == y.col && x.rowDof == y.rowDof && x.colDof == y.colDof;
      });
  const bool placed = !ctx.root() || (factor_ && factor_->K && !factor_->placed.empty());
  const bool valuesOnly = !ctx.any(!(sameKeys && placed));
  std::vector<char> rows;
  if (valuesOnly) {
    std::vector<double> values(entries.size());
    std::ranges::transform(entries, values.begin(), &Entry::value);
    append(rows, values.data(), values.size());
  } else {
    append(rows, entries.data(), entries.size());
  }
  const std::vector<char> gathered = ctx.gather(rows, starts);
  // Rank 0's solves may take a second core of its node: the node's other ranks wait for them.
  const int nodeRanks = ctx.nodeSize();

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
    const std::size_t nEntries = gathered.size() / (valuesOnly ? sizeof(double) : sizeof(Entry));
    std::vector<Entry> got(valuesOnly ? 0 : nEntries);
    std::vector<double> value(nEntries);
    if (valuesOnly) {
      if (nEntries != F.placed.size() || F.keyRows != F.row)
        throw std::logic_error("stiffness matrix: the entries' values do not fit their places");
      if (nEntries > 0) std::memcpy(value.data(), gathered.data(), gathered.size());
    } else {
      if (nEntries > 0) std::memcpy(got.data(), gathered.data(), gathered.size());
      for (std::size_t e = 0; e < nEntries; ++e) value[e] = got[e].value;
    }
    // The values of entries placed before (the bonds' pattern, the same particles) each go
    // straight to their place in K̂, found the first time.
    cholmod_sparse* K = nullptr;
    if (valuesOnly) {
      K = cholmod_copy_sparse(F.K, &F.c);
      check(F.c, "copying the matrix");
      auto* kx = static_cast<double*>(K->x);
      const std::size_t stored = static_cast<const int*>(K->p)[K->ncol];
      std::vector<unsigned char> set(stored, 0);
      // The first term is put, the second added, as the triplets' sum does.
      auto put = [&](long at, double value) {
        kx[at] = set[at] ? kx[at] + value : value;
        set[at] = 1;
      };
      std::vector<unsigned char> hasRow(unknowns, 0);
      for (std::size_t e = 0; e < nEntries; ++e) {
        const long at = F.placed[e];
        if (at < 0) continue;
        if (value[e] != 0) hasRow[F.rowOf[e]] = 1;
        put(at, at == F.diagonal[F.rowOf[e]] ? value[e] : value[e] / 2);
      }
      for (std::size_t k = 0; k < F.total; ++k) {
        const long i = F.row[k];
        if (i < 0) continue;
        if (!hasRow[i])
          put(F.diagonal[i], diag[k]);
        else if (shift > 0)
          put(F.diagonal[i], shift * diag[k]);
      }
      for (std::size_t at = 0; at < stored; ++at)
        if (!set[at]) kx[at] = 0;
    } else {
      cholmod_triplet* T = cholmod_allocate_triplet(
          static_cast<std::size_t>(unknowns), static_cast<std::size_t>(unknowns),
          nEntries + static_cast<std::size_t>(unknowns), -1, CHOLMOD_REAL, &F.c);
      check(F.c, "allocating the matrix");
      auto* ti = static_cast<int*>(T->i);
      auto* tj = static_cast<int*>(T->j);
      auto* tx = static_cast<double*>(T->x);
      auto add = [&](long i, long j, double value) {
        ti[T->nnz] = static_cast<int>(i);
        tj[T->nnz] = static_cast<int>(j);
        tx[T->nnz] = value;
        ++T->nnz;
      };
      F.rowOf.assign(nEntries, -1);
      std::vector<long> colOf(nEntries, -1);
      std::vector<unsigned char> hasRow(unknowns, 0);
      for (std::size_t e = 0; e < nEntries; ++e) {
        const Entry& x = got[e];
        const long i = unknown(x.row, x.rowDof), j = unknown(x.col, x.colDof);
        F.rowOf[e] = i;
        colOf[e] = j;
        if (i < 0 || j < 0) continue;
        if (x.value != 0) hasRow[i] = 1;
        add(std::max(i, j), std::min(i, j), i == j ? x.value : x.value / 2);
      }
      for (std::size_t k = 0; k < F.total; ++k) {
        const long i = F.row[k];
        if (i < 0) continue;
        if (!hasRow[i])
          add(i, i, diag[k]);
        else if (shift > 0)
          add(i, i, shift * diag[k]);
      }
      K = cholmod_triplet_to_sparse(T, 0, &F.c);
      cholmod_free_triplet(&T, &F.c);
      check(F.c, "assembling the matrix");
      // Where each entry and each diagonal went (none without a place: a triplet's sum
      // that found none would be a matrix without it).
      const auto* kp = static_cast<const int*>(K->p);
      const auto* ki = static_cast<const int*>(K->i);
      auto place = [&](long r, long c) -> long {
        const int* at = std::lower_bound(ki + kp[c], ki + kp[c + 1], static_cast<int>(r));
        return at < ki + kp[c + 1] && *at == r ? at - ki : -2;
      };
      F.keyRows = F.row;
      F.placed.assign(nEntries, -1);
      for (std::size_t e = 0; e < nEntries; ++e) {
        const long i = F.rowOf[e], j = colOf[e];
        if (i < 0 || j < 0) continue;
        F.placed[e] = place(std::max(i, j), std::min(i, j));
      }
      F.diagonal.assign(unknowns, -1);
      for (long i = 0; i < unknowns; ++i) F.diagonal[i] = place(i, i);
      if (std::ranges::count(F.placed, -2) > 0 || std::ranges::count(F.diagonal, -2) > 0)
        F.placed.clear();
    }
    // The ordering and the factor's structure depend on K̂'s pattern alone: kept while it
    // stays the same (the interactions that break only change values until one is lost).
    auto pattern = [&](const cholmod_sparse* A) {
      const auto* p = static_cast<const int*>(A->p);
      return std::pair{std::span<const int>(p, A->ncol + 1),
                       std::span<const int>(static_cast<const int*>(A->i),
                                            static_cast<std::size_t>(p[A->ncol]))};
    };
    const bool same = F.K && F.L && F.K->ncol == K->ncol &&
                      std::ranges::equal(pattern(F.K).first, pattern(K).first) &&
                      std::ranges::equal(pattern(F.K).second, pattern(K).second);
    cholmod_free_sparse(&F.K, &F.c);
    F.K = K;
    F.stored = static_cast<long>(pattern(K).second.size());
    const auto* kx = static_cast<const double*>(K->x);
    F.entries = std::count_if(kx, kx + F.stored, [](double v) { return v != 0; });
    if (!same) {
      cholmod_free_factor(&F.L, &F.c);
      F.c.supernodal = CHOLMOD_SIMPLICIAL;
      F.L = cholmod_analyze(K, &F.c);
      check(F.c, "ordering the matrix");
      F.fill = static_cast<long>(F.c.lnz);
      if (static_cast<double>(F.fill) > kSupernodalFill * static_cast<double>(F.stored)) {
        // The same ordering, factorised by dense blocks (BLAS) instead of column by column.
        std::vector<int> perm(static_cast<const int*>(F.L->Perm),
                              static_cast<const int*>(F.L->Perm) + K->ncol);
        cholmod_free_factor(&F.L, &F.c);
        F.c.supernodal = CHOLMOD_SUPERNODAL;
        F.L = cholmod_analyze_p(K, perm.data(), nullptr, 0, &F.c);
        check(F.c, "analysing the matrix's supernodes");
        F.numeric.analyse(layout(*F.L), static_cast<const int*>(K->p),
                          static_cast<const int*>(K->i));
      }
    }
    if (F.L->is_super && std::max(omp_get_max_threads(), nodeRanks) > 1 && !F.helper)
      F.helper = std::make_unique<HelperThread>();
    Outcome outcome = Outcome::TooLarge;
    if (static_cast<double>(F.fill) <= maxFill * static_cast<double>(F.entries)) {
      bool ok = unknowns > 0;
      if (F.L->is_super) {
        ok = ok && F.numeric.factorise(static_cast<const double*>(K->x), F.helper.get());
        if (ok) F.solver.assign(layout(*F.L), F.numeric.values());
      } else {  // LDLᵀ: D is each column's first entry of the simplicial factor
        cholmod_factorize(K, F.L, &F.c);
        check(F.c, "factorising the matrix");
        ok = ok && F.c.status == CHOLMOD_OK && F.L->minor == F.L->n;
        const auto* Lp = static_cast<const int*>(F.L->p);
        const auto* Lx = static_cast<const double*>(F.L->x);
        for (long j = 0; ok && j < unknowns; ++j) ok = Lx[Lp[j]] > 0;
      }
      outcome = ok ? Outcome::Factorised : Outcome::NotDefinite;
    }
    reply.push_back(static_cast<char>(outcome));
    std::vector<Gid> sorted(order.size());
    for (std::size_t p = 0; p < order.size(); ++p) sorted[p] = order[p].first;
    append(reply, sorted.data(), sorted.size());
  }
  reply = ctx.broadcast(std::move(reply));
  const auto outcome = static_cast<Outcome>(reply.at(0));
  const char* in = reply.data() + 1;
  const std::size_t nAll = (reply.size() - 1) / sizeof(Gid);
  std::vector<Gid> sorted(nAll);
  take(in, sorted.data(), nAll);
  at_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    auto it = std::lower_bound(sorted.begin(), sorted.end(), gids[i]);
    if (it == sorted.end() || *it != gids[i])
      throw std::logic_error("stiffness matrix: an owned particle is missing");
    at_[i] = static_cast<std::size_t>(it - sorted.begin());
  }
  dofs_ = dofs;
  // Rank 0 has placed the entries sent: the next time their values may do.
  if (!valuesOnly) {
    sentGids_.assign(gids.begin(), gids.end());
    sentFree_.assign(free.begin(), free.end());
    sentKeys_ = entries;
  }
  return outcome;
}

double StiffnessMatrix::solve(Context& ctx, std::span<const double> b, std::span<double> x) const {
  std::vector<char> mine;
  append(mine, b.data(), values_);
  std::vector<std::size_t> starts;
  const std::vector<char> all = ctx.gather(mine, starts);
  std::vector<char> reply;
  if (ctx.root()) {
    Factor& F = *factor_;
    if (all.size() != F.total * sizeof(double))
      throw std::logic_error("stiffness matrix: the particles changed since the factorisation");
    std::vector<double> rhs(F.total);
    std::memcpy(rhs.data(), all.data(), all.size());
    if (!F.rhs || F.rhs->nrow != static_cast<std::size_t>(F.unknowns)) {
      cholmod_free_dense(&F.rhs, &F.c);
      F.rhs = cholmod_zeros(static_cast<std::size_t>(F.unknowns), 1, CHOLMOD_REAL, &F.c);
      check(F.c, "allocating a right-hand side");
    }
    auto* r = static_cast<double*>(F.rhs->x);
    for (std::size_t k = 0; k < F.total; ++k)
      if (F.row[k] >= 0) r[F.row[k]] = rhs[k];
    const double* s = nullptr;
    if (F.L->is_super) {
      F.sol.resize(static_cast<std::size_t>(F.unknowns));
      F.solver.solve(r, F.sol.data(), F.helper.get());
      s = F.sol.data();
    } else {
      cholmod_solve2(CHOLMOD_A, F.L, F.rhs, nullptr, &F.x, nullptr, &F.ys, &F.e, &F.c);
      check(F.c, "solving");
      s = static_cast<const double*>(F.x->x);
    }
    double bx = 0;  // in the order of the unknowns: the same on any number of ranks
    for (long u = 0; u < F.unknowns; ++u) bx += r[u] * s[u];
    append(reply, &bx, 1);
    std::vector<double> out(F.total, 0.0);
    for (std::size_t k = 0; k < F.total; ++k)
      if (F.row[k] >= 0) out[F.out[k]] = s[F.row[k]];
    append(reply, out.data(), out.size());
  }
  reply = ctx.broadcast(std::move(reply));
  std::vector<double> s(reply.size() / sizeof(double));
  std::memcpy(s.data(), reply.data(), s.size() * sizeof(double));
  for (std::size_t i = 0; i < at_.size(); ++i)
    for (int d = 0; d < dofs_; ++d) x[i * dofs_ + d] = s[1 + at_[i] * dofs_ + d];
  return s[0];
}

}  // namespace pdq
