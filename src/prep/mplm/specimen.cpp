#include "prep/mplm/specimen.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "engine/memory.hpp"
#include "models/mplm/2d/attributes.hpp"

namespace pdq::mplm {

ParticleSet newParticleSet() {
  ParticleSet ps;
  ps.nFixed = N_FIXED;
  ps.nAlter = N_ALTER;
  return ps;
}

void addConcrete(ParticleSet& ps, const std::vector<std::array<double, 2>>& points) {
  checkParticleCount(static_cast<double>(ps.size() + points.size()),
                     8.0 * (1 + ps.nFixed + ps.nAlter), "the specimen");
  for (const auto& p : points) ps.add(static_cast<Gid>(ps.size()), p[0], p[1], 0.0);
}

namespace {
// Steel particles of bar `barId`; every `linkEvery`-th one (the first included) linked.
void appendSteel(ParticleSet& ps, const std::vector<prep::Point>& points, double area,
                 double secondMoment, int barId, std::size_t linkEvery) {
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::size_t i =
        ps.add(static_cast<Gid>(ps.size()), points[k][0], points[k][1], points[k][2]);
    double* f = ps.fixedRow(i);
    f[MATERIAL] = STEEL;
    f[BAR] = barId;
    f[LINK] = k % linkEvery == 0 ? 1.0 : 0.0;
    f[AREA] = area;
    f[SECOND_MOMENT] = secondMoment;
  }
}
}  // namespace

void addSteel(ParticleSet& ps, const std::vector<prep::Point>& points,
              const prep::BarSection& section, int barId, int count) {
  appendSteel(ps, points, count * section.area(), count * section.secondMoment(), barId, 2);
}

void addPlate(ParticleSet& ps, const std::vector<prep::Point>& points, double area,
              double secondMoment, int barId) {
  appendSteel(ps, points, area, secondMoment, barId, 1);
}

void addBar(ParticleSet& ps, const prep::Bar& bar, double s, int barId, int count) {
  addSteel(ps, prep::barPoints(bar, s), bar.section, barId, count);
}

std::vector<std::size_t> select(const ParticleSet& ps,
                                const std::function<bool(const double*)>& pick) {
  std::vector<std::size_t> idx;
  for (std::size_t k = 0; k < ps.size(); ++k)
    if (pick(ps.fixedRow(k))) idx.push_back(k);
  return idx;
}

void constrain(ParticleSet& ps, const std::vector<std::size_t>& idx, int bits,
               std::array<double, 3> peak) {
  for (std::size_t k : idx) {
    double* f = ps.fixedRow(k);
    f[CONSTRAINT] = static_cast<double>(static_cast<int>(f[CONSTRAINT]) | bits);
    for (int d = 0; d < 3; ++d)
      if (bits & (1 << d)) f[DISP_X + d] = peak[d];
  }
}

void load(ParticleSet& ps, const std::vector<std::size_t>& idx, double fx, double fy, double m) {
  for (std::size_t k : idx) {
    double* f = ps.fixedRow(k);
    f[LOAD_X] += fx;
    f[LOAD_Y] += fy;
    f[LOAD_M] += m;
  }
}

void loadUniform(ParticleSet& ps, const std::vector<std::size_t>& idx, int axis, double lo,
                 double hi, double totalFx, double totalFy) {
  // Layers: particles sharing the other coordinate (to 1e-9 m), each sorted along `axis`.
  std::map<long long, std::vector<std::size_t>> layers;
  for (std::size_t k : idx) layers[std::llround(ps.fixedRow(k)[1 - axis] * 1e9)].push_back(k);
  std::vector<std::pair<std::size_t, double>> share;
  double total = 0;
  for (auto& [key, members] : layers) {
    std::sort(members.begin(), members.end(), [&](std::size_t a, std::size_t b) {
      return ps.fixedRow(a)[axis] < ps.fixedRow(b)[axis];
    });
    for (std::size_t m = 0; m < members.size(); ++m) {
      const double x = ps.fixedRow(members[m])[axis];
      const double left = m == 0 ? lo : 0.5 * (x + ps.fixedRow(members[m - 1])[axis]);
      const double right =
          m + 1 == members.size() ? hi : 0.5 * (x + ps.fixedRow(members[m + 1])[axis]);
      share.push_back({members[m], right - left});
      total += right - left;
    }
  }
  for (const auto& [k, w] : share) {
    ps.fixedRow(k)[LOAD_X] += totalFx * w / total;
    ps.fixedRow(k)[LOAD_Y] += totalFy * w / total;
  }
}

void monitor(ParticleSet& ps, const std::vector<std::size_t>& idx) {
  for (std::size_t k : idx) ps.fixedRow(k)[MONITOR] = 1;
}

bool isConcrete(const double* f) { return !isSteel(f); }

double maxCoord(const ParticleSet& ps, int axis) {
  double v = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < ps.size(); ++k) v = std::max(v, ps.fixedRow(k)[axis]);
  return v;
}

}  // namespace pdq::mplm
