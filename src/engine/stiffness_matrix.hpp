#pragma once
// The quasi-static solver's assembled stiffness (docs/quasi-static.md, "Assembled
// stiffness"): entries K_ij of the free degrees of freedom, stated by the model or probed by
// finite differences on every rank, gathered on rank 0, made symmetric and factorised there
// (CHOLMOD's ordering by minimum degree or nested dissection and its sparse LDLᵀ; a factor
// that fills in much is supernodal, factorised by engine/supernodal_factor.hpp, its solves
// reading a single-precision copy of it), and solves with it: a right-hand side given per owned
// DOF on every rank, the solution sent back to each. Rows and columns are ordered
// by global ID, so the matrix, its factors and every solution are the same bits on any number of
// ranks.
#include <memory>
#include <span>
#include <vector>

#include "engine/particles.hpp"

namespace pdq {

class Context;

// One entry K_ij: row DOF `rowDof` of particle `row`, column DOF `colDof` of particle `col`.
struct StiffnessEntry {
  Gid row, col;
  int rowDof, colDof;
  double value;
};

class StiffnessMatrix {
 public:
  using Entry = StiffnessEntry;
  StiffnessMatrix();
  ~StiffnessMatrix();
  StiffnessMatrix(const StiffnessMatrix&) = delete;
  StiffnessMatrix& operator=(const StiffnessMatrix&) = delete;

  // Collective. `gids` are the owned particles (in their local order) with `dofs` DOFs
  // each; `free` says which DOFs are unknowns, `entries` are this rank's rows (free ones
  // only). K̂ = (K + Kᵀ)/2 + `shift` × diag(`fallback`), and a free DOF whose row holds no
  // nonzero takes `fallback` as its diagonal (entries of 0 are kept: they are pattern).
  // Not factorised when its factor would hold over `maxFill` times K̂'s nonzero entries
  // (the ordering's symbolic analysis says so first). The same outcome on every rank; the
  // solves need Factorised.
  enum class Outcome : char { Factorised, NotDefinite, TooLarge };
  Outcome factorise(Context& ctx, std::span<const Gid> gids, int dofs,
                    std::span<const unsigned char> free, const std::vector<Entry>& entries,
                    std::span<const double> fallback, double shift, double maxFill);
  // Collective: x = K̂⁻¹ b over the owned DOFs (b and x: `dofs` per owned particle; the
  // DOFs that are not free get 0). Returns bᵀx (the same bits on every rank).
  double solve(Context& ctx, std::span<const double> b, std::span<double> x) const;
  // The free DOFs, K̂'s nonzero entries and all its stored ones (its lower half, the
  // pattern's zeros included), and its factor's entries (rank 0; 0 elsewhere).
  long unknowns() const;
  long matrixNonzeros() const;
  long matrixStored() const;
  long factorNonzeros() const;
  // Rank 0, when the solves take two threads: the shares of the factor in the two parts of
  // its elimination tree and above them (engine/supernodal_solve.hpp); else empty.
  std::vector<double> twoThreadShares() const;
  // Rank 0, when the factorisation takes two threads: the share of its operations in
  // supernodes cut in two (engine/supernodal_factor.hpp); else 0.
  double twoThreadFactorisation() const;

 private:
  struct Factor;
  std::unique_ptr<Factor> factor_;  // rank 0
  std::size_t values_ = 0;          // this rank's values per solve (owned × dofs)
  int dofs_ = 0;
  std::vector<std::size_t> at_;  // per owned particle: its place in the order of global IDs
  // This rank's particles, free DOFs and entries as last sent to rank 0: while they stay
  // the same on every rank, only the entries' values are sent.
  std::vector<Gid> sentGids_;
  std::vector<unsigned char> sentFree_;
  std::vector<Entry> sentKeys_;
};

}  // namespace pdq
