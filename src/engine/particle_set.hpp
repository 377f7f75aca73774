#pragma once
// Every particle of a problem, as read from the thesis's files or made by a generator,
// before it is distributed over ranks: global IDs and the fixed and alterable tables in
// the model's schema widths (row-major, one row per particle).
#include <cstddef>
#include <vector>

#include "engine/schema.hpp"

namespace pdq {

struct ParticleSet {
  int nFixed = 3, nAlter = 3;
  std::vector<Gid> gid;
  std::vector<double> fixed, alter;

  std::size_t size() const { return gid.size(); }
  double* fixedRow(std::size_t k) { return &fixed[k * nFixed]; }
  double* alterRow(std::size_t k) { return &alter[k * nAlter]; }
  const double* fixedRow(std::size_t k) const { return &fixed[k * nFixed]; }
  const double* alterRow(std::size_t k) const { return &alter[k * nAlter]; }
  // Appends a particle with zeroed extra attributes at reference = current position.
  std::size_t add(Gid id, double x, double y, double z) {
    gid.push_back(id);
    fixed.resize(fixed.size() + nFixed, 0.0);
    alter.resize(alter.size() + nAlter, 0.0);
    double* f = fixedRow(size() - 1);
    double* a = alterRow(size() - 1);
    f[0] = a[0] = x;
    f[1] = a[1] = y;
    f[2] = a[2] = z;
    return size() - 1;
  }
};

}  // namespace pdq
