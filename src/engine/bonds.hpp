#pragma once
// Bonds (links) of the owned particles, stored with their particle in compressed rows:
// particle i's bonds are [begin(i), end(i)). A bond names its partner by global ID; the
// engine keeps partner(b), the partner's local index (owned or ghost), up to date after
// every shuffle, so bonds survive shuffles and migration with no help from the model.
// Each particle's bonds are sorted by partner global ID, which fixes the order in which a
// model sums them: results do not depend on where particles sit in memory.
#include <cstdint>
#include <vector>

#include "engine/schema.hpp"

namespace pdq {

class Bonds {
 public:
  explicit Bonds(int nAttr = 0) : nAttr_(nAttr) {}

  std::size_t count() const { return partnerGid_.size(); }
  int nAttr() const { return nAttr_; }
  std::size_t begin(std::size_t i) const { return start_[i]; }
  std::size_t end(std::size_t i) const { return start_[i + 1]; }
  std::int32_t partner(std::size_t b) const { return partner_[b]; }
  Gid partnerGid(std::size_t b) const { return partnerGid_[b]; }
  const Gid* partnerGids(std::size_t b) const { return &partnerGid_[b]; }
  double* attr(std::size_t b) { return &attr_[b * nAttr_]; }
  const double* attr(std::size_t b) const { return &attr_[b * nAttr_]; }
  bool empty() const { return partnerGid_.empty(); }
  // Changes whenever the bonds are made, reordered, moved in, put back or their partners
  // renumbered (not when a model writes their attributes): a model keeping something per
  // bond or per partner rebuilds it then.
  std::uint64_t version() const { return version_; }

  // A broken bond is killed by its model (on each of its two sides alike); a dead bond
  // keeps its attributes but no longer needs its partner nearby: partner(b) is -1 once
  // the partner has left the procCube.
  bool alive(std::size_t b) const { return dead_[b] == 0; }
  void kill(std::size_t b) { dead_[b] = 1; }

  // --- building, in a model's setup: add pairs, then the engine calls finish() ---
  void add(std::size_t owner, Gid partner);
  // Sorts each owner's bonds by partner ID, rejects duplicates, zeroes attributes.
  void finish(std::size_t nOwned);

  // --- used by the engine ---
  void resetEmpty(std::size_t nOwned);
  void discardPending() { pending_.clear(); }
  // New owned particle k takes old particle perm[k]'s bonds (departed ones are dropped).
  void permute(const std::vector<std::size_t>& perm);
  // Appends the bonds of one newly arrived owned particle (at the end of the owned range).
  void appendParticle(const Gid* partners, const double* attrs, const std::uint8_t* dead,
                      std::size_t n);
  const std::uint8_t* deadFlags(std::size_t b) const { return &dead_[b]; }
  // Every bond's attributes and dead flag, to be put back by restore(): the quasi-static
  // solver evaluates trial states whose damage it keeps only once they are in equilibrium.
  struct Saved {
    std::vector<double> attr;
    std::vector<std::uint8_t> dead;
  };
  void save(Saved& s) const { s.attr = attr_, s.dead = dead_; }
  void restore(const Saved& s) { attr_ = s.attr, dead_ = s.dead, ++version_; }
  bool same(const Saved& s) const { return attr_ == s.attr && dead_ == s.dead; }
  const std::vector<std::int32_t>& partners() const { return partner_; }
  // The engine renumbers the partners' local indices here (after the particles moved).
  std::vector<std::int32_t>& renumberPartners() {
    ++version_;
    return partner_;
  }

 private:
  int nAttr_;
  std::uint64_t version_ = 0;
  std::vector<std::uint64_t> start_{0};
  std::vector<Gid> partnerGid_;
  std::vector<std::int32_t> partner_;
  std::vector<double> attr_;
  std::vector<std::uint8_t> dead_;
  std::vector<std::pair<std::size_t, Gid>> pending_;
};

}  // namespace pdq
