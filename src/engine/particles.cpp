#include "engine/particles.hpp"

#include <algorithm>

namespace pdq {

Particles::Particles(Schema schema)
    : schema_(std::move(schema)),
      nF_(schema_.nFixed()),
      nA_(schema_.nAlter()),
      nI_(schema_.nInteg()) {}

void Particles::clear() {
  gid_.clear();
  fixed_.clear();
  alter_.clear();
  integ_.clear();
  nOwned_ = 0;
}

std::size_t Particles::append(Gid id, const double* fixedRow, const double* alterRow) {
  gid_.push_back(id);
  fixed_.insert(fixed_.end(), fixedRow, fixedRow + nF_);
  alter_.insert(alter_.end(), alterRow, alterRow + nA_);
  integ_.resize(integ_.size() + nI_, 0.0);
  return gid_.size() - 1;
}

template <class T>
static void permuteRows(std::vector<T>& table, int width, const std::vector<std::size_t>& perm) {
  if (width == 0) return;
  std::vector<T> out(perm.size() * width);
  for (std::size_t k = 0; k < perm.size(); ++k)
    std::copy_n(&table[perm[k] * width], width, &out[k * width]);
  std::copy(out.begin(), out.end(), table.begin());
}

void Particles::permute(const std::vector<std::size_t>& perm) {
  permuteRows(gid_, 1, perm);
  permuteRows(fixed_, nF_, perm);
  permuteRows(alter_, nA_, perm);
  permuteRows(integ_, nI_, perm);
}

void Particles::truncate(std::size_t n) {
  gid_.resize(n);
  fixed_.resize(n * nF_);
  alter_.resize(n * nA_);
  integ_.resize(n * nI_);
  nOwned_ = std::min(nOwned_, n);
}

}  // namespace pdq
