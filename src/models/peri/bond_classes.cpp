#include "models/peri/bond_classes.hpp"

#include <bit>
#include <cstring>

namespace pdq::peri {
namespace {

std::size_t hashOf(const double row[2]) {
  const std::uint64_t h = (std::bit_cast<std::uint64_t>(row[0]) * 0x9E3779B97F4A7C15ull) ^
                          (std::bit_cast<std::uint64_t>(row[1]) * 0xC2B2AE3D27D4EB4Full);
  return static_cast<std::size_t>(h ^ (h >> 32));
}

}  // namespace

std::uint32_t BondClasses::find(const double row[2]) {
  const std::size_t mask = slots_.size() - 1;
  std::size_t s = hashOf(row) & mask;
  for (; slots_[s] != 0; s = (s + 1) & mask)
    if (std::memcmp(&rows_[2 * (slots_[s] - 1)], row, 2 * sizeof(double)) == 0)
      return slots_[s] - 1;
  // A new row; the table is kept at most half full.
  const auto c = static_cast<std::uint32_t>(broken_.size());
  rows_.insert(rows_.end(), row, row + 2);
  broken_.push_back(c);  // set once every row is known
  slots_[s] = c + 1;
  if (2 * broken_.size() > slots_.size()) {
    slots_.assign(2 * slots_.size(), 0);
    for (std::uint32_t k = 0; k < broken_.size(); ++k) {
      std::size_t t = hashOf(&rows_[2 * k]) & (slots_.size() - 1);
      while (slots_[t]) t = (t + 1) & (slots_.size() - 1);
      slots_[t] = k + 1;
    }
  }
  return c;
}

std::uint32_t BondClasses::findPair(std::uint32_t a, std::uint32_t b) {
  const std::uint64_t key = (std::uint64_t{a} << 32) | b;
  auto hashKey = [](std::uint64_t k) {
    const std::uint64_t h = k * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  };
  std::size_t mask = pairSlots_.size() - 1, s = hashKey(key) & mask;
  for (; pairSlots_[s] != 0; s = (s + 1) & mask)
    if (pairKeys_[pairSlots_[s] - 1] == key) return pairSlots_[s] - 1;
  const auto c = static_cast<std::uint32_t>(pairKeys_.size());
  pairKeys_.push_back(key);
  pairRows_.insert(pairRows_.end(),
                   {rows_[2 * a], rows_[2 * a + 1], rows_[2 * b], rows_[2 * b + 1]});
  pairSlots_[s] = c + 1;
  if (2 * pairKeys_.size() > pairSlots_.size()) {
    pairSlots_.assign(2 * pairSlots_.size(), 0);
    mask = pairSlots_.size() - 1;
    for (std::uint32_t k = 0; k < pairKeys_.size(); ++k) {
      std::size_t t = hashKey(pairKeys_[k]) & mask;
      while (pairSlots_[t]) t = (t + 1) & mask;
      pairSlots_[t] = k + 1;
    }
  }
  return c;
}

bool BondClasses::update(const Bonds& B) {
  if (built_ && version_ == B.version()) return false;
  rows_.clear();
  broken_.clear();
  slots_.assign(1024, 0);
  index_.resize(B.count());
  for (std::size_t b = 0; b < B.count(); ++b) index_[b] = find(B.attr(b));
  // Every row's broken twin is a row too (new twins are their own).
  for (std::uint32_t c = 0; c < broken_.size(); ++c) {
    const double twin[2] = {rows_[2 * c], 0.0};
    broken_[c] = find(twin);
  }
  // Each bond with the next (the last bond's own row stands in for the one it lacks).
  const std::size_t n = B.count();
  pairKeys_.clear();
  pairRows_.clear();
  pairSlots_.assign(1024, 0);
  pair_.resize(n);
  for (std::size_t b = 0; b < n; ++b) pair_[b] = findPair(index_[b], index_[b + 1 < n ? b + 1 : b]);
  // Every pair row's with either bond broken, theirs in turn (the list grows as it goes).
  pairBroken_.clear();
  for (std::size_t p = 0; p < pairKeys_.size(); ++p) {
    const auto a = static_cast<std::uint32_t>(pairKeys_[p] >> 32);
    const auto b = static_cast<std::uint32_t>(pairKeys_[p]);
    const std::uint32_t first = findPair(broken_[a], b), second = findPair(a, broken_[b]);
    pairBroken_.push_back(first);
    pairBroken_.push_back(second);
  }
  built_ = true;
  version_ = B.version();
  return true;
}

}  // namespace pdq::peri
