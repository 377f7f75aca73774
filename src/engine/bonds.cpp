#include "engine/bonds.hpp"

#include <algorithm>
#include <string>

#include "engine/error.hpp"

namespace pdq {

void Bonds::add(std::size_t owner, Gid partner) { pending_.emplace_back(owner, partner); }

void Bonds::finish(std::size_t nOwned) {
  std::sort(pending_.begin(), pending_.end());
  start_.assign(nOwned + 1, 0);
  partnerGid_.clear();
  for (std::size_t k = 0; k < pending_.size(); ++k) {
    if (k > 0 && pending_[k] == pending_[k - 1]) continue;  // the same pair added twice
    start_[pending_[k].first + 1]++;
    partnerGid_.push_back(pending_[k].second);
  }
  for (std::size_t i = 0; i < nOwned; ++i) start_[i + 1] += start_[i];
  partner_.assign(partnerGid_.size(), -1);
  attr_.assign(partnerGid_.size() * nAttr_, 0.0);
  dead_.assign(partnerGid_.size(), 0);
  pending_.clear();
  pending_.shrink_to_fit();
  ++version_;
}

void Bonds::resetEmpty(std::size_t nOwned) {
  start_.assign(nOwned + 1, 0);
  partnerGid_.clear();
  partner_.clear();
  attr_.clear();
  dead_.clear();
  ++version_;
}

void Bonds::permute(const std::vector<std::size_t>& perm) {
  std::vector<std::uint64_t> start(perm.size() + 1, 0);
  for (std::size_t k = 0; k < perm.size(); ++k)
    start[k + 1] = start[k] + (start_[perm[k] + 1] - start_[perm[k]]);
  std::vector<Gid> gids(start.back());
  std::vector<double> attrs(start.back() * nAttr_);
  std::vector<std::uint8_t> dead(start.back());
  for (std::size_t k = 0; k < perm.size(); ++k) {
    const auto b0 = start_[perm[k]], n = start_[perm[k] + 1] - b0;
    std::copy_n(&partnerGid_[b0], n, &gids[start[k]]);
    std::copy_n(&dead_[b0], n, &dead[start[k]]);
    if (nAttr_) std::copy_n(&attr_[b0 * nAttr_], n * nAttr_, &attrs[start[k] * nAttr_]);
  }
  start_ = std::move(start);
  partnerGid_ = std::move(gids);
  attr_ = std::move(attrs);
  dead_ = std::move(dead);
  partner_.assign(partnerGid_.size(), -1);
  ++version_;
}

void Bonds::appendParticle(const Gid* partners, const double* attrs, const std::uint8_t* dead,
                           std::size_t n) {
  partnerGid_.insert(partnerGid_.end(), partners, partners + n);
  dead_.insert(dead_.end(), dead, dead + n);
  attr_.insert(attr_.end(), attrs, attrs + n * nAttr_);
  partner_.resize(partnerGid_.size(), -1);
  start_.push_back(start_.back() + n);
  ++version_;
}

}  // namespace pdq
