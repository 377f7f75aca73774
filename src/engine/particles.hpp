#pragma once
// The particles of one procCube: owned (core) particles first, ghosts (skin copies)
// after, so `i < owned()` is the only ownership test anywhere. Each attribute group is a
// row-major table (one row of doubles per particle): a force kernel that reads a
// neighbour's alterable row touches one or two cache lines, and the halo packs rows.
#include <cstddef>
#include <vector>

#include "engine/schema.hpp"

namespace pdq {

class Particles {
 public:
  explicit Particles(Schema schema);

  const Schema& schema() const { return schema_; }
  std::size_t owned() const { return nOwned_; }
  std::size_t local() const { return gid_.size(); }  // owned + ghosts
  std::size_t ghosts() const { return local() - owned(); }

  Gid gid(std::size_t i) const { return gid_[i]; }
  double* fixed(std::size_t i) { return &fixed_[i * nF_]; }
  const double* fixed(std::size_t i) const { return &fixed_[i * nF_]; }
  double* alter(std::size_t i) { return &alter_[i * nA_]; }
  const double* alter(std::size_t i) const { return &alter_[i * nA_]; }
  double* integ(std::size_t i) { return &integ_[i * nI_]; }  // owned particles only
  const double* integ(std::size_t i) const { return &integ_[i * nI_]; }

  // --- used by the engine (decomposition, exchange, shuffle, restart) ---
  void clear();
  // Appends a particle; fixed/alter rows of the schema's widths, integ row zeroed.
  std::size_t append(Gid id, const double* fixedRow, const double* alterRow);
  void setOwned(std::size_t n) { nOwned_ = n; }
  // Reorders the first perm.size() particles: new position k takes old particle perm[k].
  void permute(const std::vector<std::size_t>& perm);
  void truncate(std::size_t n);  // drops particles n.. (ghosts, or departed owned ones)
  std::vector<double>& alterTable() { return alter_; }

 private:
  Schema schema_;
  int nF_, nA_, nI_;
  std::size_t nOwned_ = 0;
  std::vector<Gid> gid_;
  std::vector<double> fixed_, alter_, integ_;
};

}  // namespace pdq
