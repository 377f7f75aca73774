#include "engine/schema.hpp"

#include <algorithm>

namespace pdq {

Schema Schema::make(std::vector<std::string> fixedExtra, std::vector<std::string> alterExtra,
                    std::vector<std::string> integ, std::vector<std::string> bond) {
  Schema s;
  s.fixed.insert(s.fixed.end(), fixedExtra.begin(), fixedExtra.end());
  s.alter.insert(s.alter.end(), alterExtra.begin(), alterExtra.end());
  s.integ = std::move(integ);
  s.bond = std::move(bond);
  return s;
}

static int indexOf(const std::vector<std::string>& v, const std::string& name) {
  auto it = std::find(v.begin(), v.end(), name);
  return it == v.end() ? -1 : static_cast<int>(it - v.begin());
}

int Schema::fixedIndex(const std::string& n) const { return indexOf(fixed, n); }
int Schema::alterIndex(const std::string& n) const { return indexOf(alter, n); }
int Schema::integIndex(const std::string& n) const { return indexOf(integ, n); }
int Schema::bondIndex(const std::string& n) const { return indexOf(bond, n); }

}  // namespace pdq
