#include "models/peri/bond_classes.hpp"

#include <bit>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace pdq::peri {
namespace {

std::size_t mix(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t h = (a * 0x9E3779B97F4A7C15ull) ^ (b * 0xC2B2AE3D27D4EB4Full);
  return static_cast<std::size_t>(h ^ (h >> 32));
}

std::size_t hashOf(const double row[2]) {
  return mix(std::bit_cast<std::uint64_t>(row[0]), std::bit_cast<std::uint64_t>(row[1]));
}

std::size_t hashOf(std::uint64_t key) { return mix(key, key >> 32); }

// Open addressing over `slots` (entry number + 1, 0 = empty), kept at most half full: the
// number of the entry `same` recognises, else of the one `add` appends after the n there
// are; hashAt(k) is entry k's hash, to spread them again when the slots grow.
template <class Same, class Add, class HashAt>
std::uint32_t intern(std::vector<std::uint32_t>& slots, std::size_t hash, std::size_t n, Same same,
                     Add add, HashAt hashAt) {
  std::size_t mask = slots.size() - 1, s = hash & mask;
  for (; slots[s] != 0; s = (s + 1) & mask)
    if (same(slots[s] - 1)) return slots[s] - 1;
  const auto c = static_cast<std::uint32_t>(n);
  add();
  slots[s] = c + 1;
  if (2 * (n + 1) > slots.size()) {
    slots.assign(2 * slots.size(), 0);
    mask = slots.size() - 1;
    for (std::uint32_t k = 0; k <= c; ++k) {
      std::size_t t = hashAt(k) & mask;
      while (slots[t]) t = (t + 1) & mask;
      slots[t] = k + 1;
    }
  }
  return c;
}

}  // namespace

std::uint32_t BondClasses::find(const double row[2]) {
  return intern(
      slots_, hashOf(row), broken_.size(),
      [&](std::uint32_t k) { return std::memcmp(&rows_[2 * k], row, 2 * sizeof(double)) == 0; },
      [&] {
        rows_.insert(rows_.end(), row, row + 2);
        broken_.push_back(0);  // set once every row is known
      },
      [&](std::uint32_t k) { return hashOf(&rows_[2 * k]); });
}

std::uint32_t BondClasses::findPair(std::uint32_t a, std::uint32_t b) {
  const std::uint64_t key = (std::uint64_t{a} << 32) | b;
  return intern(
      pairSlots_, hashOf(key), pairKeys_.size(),
      [&](std::uint32_t k) { return pairKeys_[k] == key; },
      [&] {
        pairKeys_.push_back(key);
        pairRows_.insert(pairRows_.end(),
                         {rows_[2 * a], rows_[2 * a + 1], rows_[2 * b], rows_[2 * b + 1]});
      },
      [&](std::uint32_t k) { return hashOf(pairKeys_[k]); });
}

bool BondClasses::update(const Bonds& B) {
  if (built_ && version_ == B.version()) return false;
  rows_.clear();
  broken_.clear();
  slots_.assign(1024, 0);
  const std::size_t n = B.count();
  std::vector<std::uint32_t> row(n);  // each bond's
  for (std::size_t b = 0; b < n; ++b) row[b] = find(B.attr(b));
  // Every row's broken twin is a row too (new twins are their own).
  for (std::uint32_t c = 0; c < broken_.size(); ++c) {
    const double twin[2] = {rows_[2 * c], 0.0};
    broken_[c] = find(twin);
  }
  // Each bond with the next (the last bond's own row stands in for the one it lacks).
  pairKeys_.clear();
  pairRows_.clear();
  pairSlots_.assign(1024, 0);
  pair_.resize(n);
  for (std::size_t b = 0; b < n; ++b) pair_[b] = 4 * findPair(row[b], row[b + 1 < n ? b + 1 : b]);
  // Every pair row's with either bond broken, theirs in turn (the list grows as it goes).
  pairBroken_.clear();
  for (std::size_t p = 0; p < pairKeys_.size(); ++p) {
    const auto a = static_cast<std::uint32_t>(pairKeys_[p] >> 32);
    const auto b = static_cast<std::uint32_t>(pairKeys_[p]);
    const std::uint32_t first = findPair(broken_[a], b), second = findPair(a, broken_[b]);
    pairBroken_.push_back(4 * first);
    pairBroken_.push_back(4 * second);
  }
  if (partnerRowStride_) {
    at_.resize(n);
    const auto stride = static_cast<std::int64_t>(partnerRowStride_);
    for (std::size_t b = 0; b < n; ++b) {
      const std::int64_t at = B.partner(b) * stride;
      if (at > std::numeric_limits<std::int32_t>::max())
        throw std::length_error("bond rows: more local particles than 4-byte row offsets reach");
      at_[b] = static_cast<std::int32_t>(at);
    }
  }
  built_ = true;
  version_ = B.version();
  return true;
}

}  // namespace pdq::peri
