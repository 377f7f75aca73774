#include "prep/fcc.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/error.hpp"
#include "engine/memory.hpp"
#include "prep/lattice.hpp"

namespace pdq {

namespace {

// Uniform in (0, 1]: 53 random bits, never 0 so the logarithm below is finite.
double uniform(std::mt19937_64& rng) {
  return (static_cast<double>(rng() >> 11) + 1.0) * 0x1.0p-53;
}

// Two independent standard normal numbers (Box-Muller).
std::array<double, 2> normalPair(std::mt19937_64& rng) {
  const double r = std::sqrt(-2.0 * std::log(uniform(rng)));
  const double t = 2.0 * std::numbers::pi * uniform(rng);
  return {r * std::cos(t), r * std::sin(t)};
}

}  // namespace

FccBox makeFcc(const FccSpec& s, ParticleSet& out) {
  const std::string where = "fcc lattice";
  for (int a = 0; a < 3; ++a)
    if (s.cells[a] < 1) throw InputError(where, 0, "the number of unit cells must be at least 1");
  if (!(s.density > 0) || !std::isfinite(s.density))
    throw InputError(where, 0, "the density must be a positive number");
  if (!(s.temperature >= 0) || !std::isfinite(s.temperature))
    throw InputError(where, 0, "the temperature must be zero or positive");
  if (s.temperature > 0 && (s.velocityColumn < 3 || s.velocityColumn + 3 > out.nAlter))
    throw InputError(where, 0, "a temperature needs the model's velocity attributes");
  if (!(s.mass > 0)) throw InputError(where, 0, "the mass must be positive");

  FccBox box;
  const double a = std::cbrt(4.0 / s.density);
  box.latticeConstant = a;
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = s.origin[k];
    box.hi[k] = s.origin[k] + s.cells[k] * a;
  }
  // The four basis sites of the cubic cell, in units of a; the quarter offset keeps every
  // site strictly inside the box, away from the cell boundaries.
  static constexpr double basis[4][3] = {
      {0.25, 0.25, 0.25}, {0.75, 0.75, 0.25}, {0.75, 0.25, 0.75}, {0.25, 0.75, 0.75}};
  checkParticleCount(4.0 * s.cells[0] * s.cells[1] * s.cells[2],
                     8.0 * (1 + out.nFixed + out.nAlter), "the fcc lattice");
  const std::size_t first = out.size();
  Gid id = s.firstId;
  for (int k = 0; k < s.cells[2]; ++k)
    for (int j = 0; j < s.cells[1]; ++j)
      for (int i = 0; i < s.cells[0]; ++i)
        for (const auto& b : basis)
          out.add(id++, s.origin[0] + (i + b[0]) * a, s.origin[1] + (j + b[1]) * a,
                  s.origin[2] + (k + b[2]) * a);
  if (s.temperature == 0) return box;

  const std::size_t n = out.size() - first;
  std::mt19937_64 rng(s.seed);
  std::vector<double> v(3 * n);
  for (std::size_t k = 0; k < 3 * n; k += 2) {
    const auto g = normalPair(rng);
    v[k] = g[0];
    if (k + 1 < 3 * n) v[k + 1] = g[1];
  }
  // Zero total momentum (all masses equal), then scale to the exact temperature.
  for (int c = 0; c < 3; ++c) {
    double mean = 0;
    for (std::size_t p = 0; p < n; ++p) mean += v[3 * p + c];
    mean /= static_cast<double>(n);
    for (std::size_t p = 0; p < n; ++p) v[3 * p + c] -= mean;
  }
  double twoKe = 0;
  for (double w : v) twoKe += s.mass * w * w;
  const double dof = n > 1 ? 3.0 * static_cast<double>(n) - 3.0 : 3.0;
  const double scale = twoKe > 0 ? std::sqrt(s.temperature * dof / twoKe) : 0.0;
  for (std::size_t p = 0; p < n; ++p)
    for (int c = 0; c < 3; ++c)
      out.alterRow(first + p)[s.velocityColumn + c] = v[3 * p + c] * scale;
  return box;
}

double closePackedLayerPitch(double s) { return std::sqrt(2.0 / 3.0) * s; }

std::array<double, 3> closePackedMinimumBox(const ClosePacked& L) {
  std::array<double, 3> need{};
  need[L.bondAxis] = L.s;
  need[3 - L.bondAxis - L.stackAxis] = std::sqrt(3.0) / 2 * L.s;
  need[L.stackAxis] = closePackedLayerPitch(L.s);
  return need;
}

std::vector<std::array<double, 3>> closePackedBox(const ClosePacked& L,
                                                  const std::array<double, 3>& size,
                                                  const std::array<double, 3>& origin) {
  const int a = L.bondAxis, z = L.stackAxis;
  if (a < 0 || a > 2 || z < 0 || z > 2 || a == z)
    throw std::invalid_argument("the bond axis and the stacking axis must be two different axes");
  if (!(L.s > 0)) throw std::invalid_argument("the lattice spacing must be positive");
  const int c = 3 - a - z;  // across the rows, within a layer
  const double s = L.s, p = std::sqrt(3.0) / 2 * s, h = closePackedLayerPitch(s);
  const char* names[3] = {"X", "Y", "Z"};
  const auto need = closePackedMinimumBox(L);
  for (int k = 0; k < 3; ++k)
    if (!(size[k] + 1e-9 * s >= need[k]))
      throw std::invalid_argument("the lattice does not fit the box: " + std::to_string(size[k]) +
                                  " m along " + names[k] + " is less than the lattice's stride " +
                                  std::to_string(need[k]) + " m there (two particles at least)");
  const double tol = 1e-9 * s;
  checkParticleCount((size[z] / h + 1) * (size[c] / p + 1) * (size[a] / s + 1),
                     sizeof(std::array<double, 3>), "the close-packed lattice");
  std::vector<std::array<double, 3>> pts;
  for (long k = 0; k * h <= size[z] + tol; ++k) {
    const int phase = static_cast<int>(k % 3);  // A, B, C
    for (long r = 0; r * p + phase * p / 3 <= size[c] + tol; ++r) {
      const double v = r * p + phase * p / 3;
      double shift = (r % 2) * s / 2 + phase * s / 2;
      if (shift >= s) shift -= s;
      for (long i = 0; shift + i * s <= size[a] + tol; ++i) {
        std::array<double, 3> q{};
        q[a] = origin[a] + shift + i * s;
        q[c] = origin[c] + v;
        q[z] = origin[z] + k * h;
        pts.push_back(q);
      }
    }
  }
  return pts;
}

std::array<double, 3> closePackedInset(const ClosePacked& L) {
  std::array<double, 3> inset{};
  inset[L.bondAxis] = L.s / 4;
  inset[3 - L.bondAxis - L.stackAxis] = std::sqrt(3.0) / 2 * L.s / 6;
  inset[L.stackAxis] = closePackedLayerPitch(L.s) / 2;
  return inset;
}

std::vector<std::array<double, 3>> closePackedFill(const ClosePacked& L,
                                                   const std::array<double, 3>& size,
                                                   const std::array<double, 3>& origin) {
  const auto inset = closePackedInset(L);
  std::array<double, 3> inner{}, start{};
  for (int k = 0; k < 3; ++k) {
    inner[k] = size[k] - inset[k];
    start[k] = origin[k] + inset[k];
  }
  return closePackedBox(L, inner, start);
}

double closePackedFillCount(const ClosePacked& L, const std::array<double, 3>& size) {
  const int a = L.bondAxis, z = L.stackAxis, c = 3 - a - z;
  const auto inset = closePackedInset(L);
  const double s = L.s, p = std::sqrt(3.0) / 2 * s, tol = 1e-9 * s;
  auto inner = [&](int k) { return size[k] - inset[k] + tol; };
  // As closePackedBox lays them: layer k has phase k % 3, its rows start phase p/3 across,
  // and a row's first point is shifted by its parity and phase.
  const double layers = prep::latticeSteps(inner(z), 0, closePackedLayerPitch(s));
  double count = 0;
  for (int phase = 0; phase < 3; ++phase) {
    const double ofPhase = std::max(0.0, std::ceil((layers - phase) / 3));
    const double rows = prep::latticeSteps(inner(c), phase * p / 3, p);
    for (int parity = 0; parity < 2; ++parity) {
      const double shift = std::fmod(parity * s / 2 + phase * s / 2, s);
      const double ofParity = parity ? std::floor(rows / 2) : std::ceil(rows / 2);
      count += ofPhase * ofParity * prep::latticeSteps(inner(a), shift, s);
    }
  }
  return count;
}

std::array<std::array<double, 3>, 3> closePackedVectors(const ClosePacked& L) {
  const int a = L.bondAxis, z = L.stackAxis, c = 3 - a - z;
  const double s = L.s, p = std::sqrt(3.0) / 2 * s;
  std::array<std::array<double, 3>, 3> v{};
  v[0][a] = s;
  v[1][a] = s / 2;
  v[1][c] = p;
  v[2][a] = s / 2;
  v[2][c] = p / 3;
  v[2][z] = closePackedLayerPitch(s);
  return v;
}

}  // namespace pdq
