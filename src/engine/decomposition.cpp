#include "engine/decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "engine/error.hpp"

namespace pdq {

static int firstCell(int c, int nCells, int nProcs) {
  return static_cast<int>((static_cast<long>(c) * nCells) / nProcs);
}

// Cells along an active axis of length L: as many as fit, each at least minCellSize.
static int cellsAlong(double L, double minCellSize) {
  return std::max(1, static_cast<int>(std::floor(L / minCellSize)));
}

Decomposition::Decomposition(const Domain& domain, double minCellSize, std::array<int, 3> nP,
                             int nRanks, int rank, const std::string& source, int divisions)
    : dom_(domain), div_(nRanks > 1 ? divisions : 1) {  // one rank has no cuts to refine
  if (!(minCellSize > 0)) throw InputError(source, 0, "minimum cell size must be positive");
  if (divisions < 1) throw InputError(source, 0, "cell divisions must be at least 1");
  for (int a = 0; a < 3; ++a) {
    const double L = dom_.length(a);
    if (!active(a)) {
      nGC_[a] = 1;
    } else {
      if (!(L > 0))
        throw InputError(source, 0, "domain has no extent along axis " + std::to_string(a));
      nGC_[a] = cellsAlong(L, minCellSize);
      if (dom_.periodic[a] && nGC_[a] < 3) {
        std::ostringstream os;
        os << "periodic axis "
           << "XYZ"[a] << " of length " << L << " holds fewer than 3 cells of " << minCellSize
           << "; enlarge the box or reduce the minimum cell size";
        throw InputError(source, 0, os.str());
      }
    }
    reach_[a] = L > 0 ? L / nGC_[a] : 1.0;
    if (active(a)) nGC_[a] *= div_;
    cell_[a] = L > 0 ? L / nGC_[a] : 1.0;
  }
  const bool automatic = nP[0] <= 0 || nP[1] <= 0 || nP[2] <= 0;
  if (automatic) {
    // The grid that fits the ranks, respects the cell counts and cuts the least area.
    double best = std::numeric_limits<double>::infinity();
    for (int px = 1; px <= nRanks; ++px)
      for (int py = 1; px * py <= nRanks; ++py) {
        if (nRanks % (px * py)) continue;
        const int pz = nRanks / (px * py);
        const std::array<int, 3> p{px, py, pz};
        bool ok = true;
        for (int a = 0; a < 3; ++a) ok &= p[a] * div_ <= nGC_[a] && (active(a) || p[a] == 1);
        if (!ok) continue;
        double cost = 0;
        for (int a = 0; a < 3; ++a) {
          double area = 1;
          for (int b = 0; b < 3; ++b)
            if (b != a && active(b)) area *= dom_.length(b);
          cost += (p[a] - (dom_.periodic[a] ? 0 : 1)) * area;
        }
        if (cost < best) {
          best = cost;
          nP_ = p;
        }
      }
    if (!std::isfinite(best)) {
      std::ostringstream os;
      os << nRanks << " ranks do not fit a domain of " << nGC_[0] << " x " << nGC_[1] << " x "
         << nGC_[2] << " cells (each rank needs at least " << div_ << " per active axis)";
      throw InputError(source, 0, os.str());
    }
  } else {
    nP_ = nP;
    if (nP_[0] * nP_[1] * nP_[2] != nRanks) {
      std::ostringstream os;
      os << "processor grid " << nP_[0] << " x " << nP_[1] << " x " << nP_[2] << " needs "
         << nP_[0] * nP_[1] * nP_[2] << " ranks but the run has " << nRanks;
      throw InputError(source, 0, os.str());
    }
    for (int a = 0; a < 3; ++a) {
      if (nP_[a] * div_ > nGC_[a]) {
        std::ostringstream os;
        os << "processor grid has " << nP_[a] << " ranks along "
           << "XYZ"[a] << " but the domain has only " << nGC_[a] / div_
           << " cells there (cell size >= " << minCellSize << ")";
        throw InputError(source, 0, os.str());
      }
    }
  }
  me_ = {rank % nP_[0], (rank / nP_[0]) % nP_[1], rank / (nP_[0] * nP_[1])};
  for (int a = 0; a < 3; ++a) {
    cuts_[a].resize(nP_[a] + 1);
    for (int c = 0; c <= nP_[a]; ++c) cuts_[a][c] = firstCell(c, nGC_[a], nP_[a]);
    lo_[a] = cuts_[a][me_[a]];
    hi_[a] = cuts_[a][me_[a] + 1];
  }
}

// Cuts p cores along one axis from the layers' weight prefix: cut c at the cell boundary
// whose prefix is nearest c/p of the total, leaving at least `div` cells to each core
// before and after it (of equal distances, the lower boundary). cuts[0] and cuts[p] stay.
static void cutAtWeights(const std::vector<double>& prefix, int p, int div,
                         std::vector<int>& cuts) {
  const int n = static_cast<int>(prefix.size()) - 1;
  const double total = prefix[n];
  for (int c = 1; c < p; ++c) {
    const double target = total * c / p;
    int best = cuts[c - 1] + div;
    for (int b = best + 1; b <= n - (p - c) * div; ++b)
      if (std::fabs(prefix[b] - target) < std::fabs(prefix[best] - target)) best = b;
    cuts[c] = best;
  }
}

static std::vector<double> prefixOf(const std::vector<double>& w) {
  std::vector<double> prefix(w.size() + 1, 0);
  for (std::size_t g = 0; g < w.size(); ++g) prefix[g + 1] = prefix[g] + w[g];
  return prefix;
}

void Decomposition::balance(const std::array<std::vector<double>, 3>& weights) {
  for (int a = 0; a < dim(); ++a) {
    const int n = nGC_[a], p = nP_[a];
    if (p == 1 || static_cast<int>(weights[a].size()) != n) continue;
    const std::vector<double> prefix = prefixOf(weights[a]);
    if (!(prefix[n] > 0)) continue;
    cutAtWeights(prefix, p, div_, cuts_[a]);
    lo_[a] = cuts_[a][me_[a]];
    hi_[a] = cuts_[a][me_[a] + 1];
  }
}

void Decomposition::chooseCells(
    const std::function<std::vector<double>(int axis, int cells)>& layers) {
  for (int a = 0; a < dim(); ++a) {
    const int most = nGC_[a], p = nP_[a];
    if (p == 1 || div_ != 1) continue;  // sub-cells belong to models whose cells matter
    const int fewest = std::max({p, dom_.periodic[a] ? 3 : 1, (4 * most + 4) / 5});
    int best = most;
    double lightest = std::numeric_limits<double>::infinity();
    for (int n = most; n >= fewest; --n) {
      const std::vector<double> prefix = prefixOf(layers(a, n));
      std::vector<int> cuts(p + 1);
      for (int c = 0; c <= p; ++c) cuts[c] = firstCell(c, n, p);
      cutAtWeights(prefix, p, 1, cuts);
      double heaviest = 0;
      for (int c = 0; c < p; ++c)
        heaviest = std::max(heaviest, prefix[cuts[c + 1]] - prefix[cuts[c]]);
      if (heaviest < lightest) {
        lightest = heaviest;
        best = n;
      }
    }
    nGC_[a] = best;
    cell_[a] = reach_[a] = dom_.length(a) / best;
    for (int c = 0; c <= p; ++c) cuts_[a][c] = firstCell(c, best, p);
    lo_[a] = cuts_[a][me_[a]];
    hi_[a] = cuts_[a][me_[a] + 1];
  }
}

double Decomposition::minActiveCellSize() const {
  double m = std::numeric_limits<double>::infinity();
  for (int a = 0; a < dim(); ++a) m = std::min(m, reach_[a]);
  return m;
}

double Decomposition::minActiveCellSize(const Domain& domain, double minCellSize) {
  double m = std::numeric_limits<double>::infinity();
  for (int a = 0; a < domain.dim; ++a) {
    const double L = domain.length(a);
    m = std::min(m, L / cellsAlong(L, minCellSize));
  }
  return m;
}

int Decomposition::neighbour(int a, int dir) const {
  if (!active(a)) return -1;
  std::array<int, 3> c = me_;
  c[a] += dir;
  if (c[a] < 0 || c[a] >= nP_[a]) {
    if (!dom_.periodic[a]) return -1;
    c[a] = (c[a] + nP_[a]) % nP_[a];
  }
  return rankOf(c);
}

bool Decomposition::wraps(int a, int dir) const {
  if (!active(a) || !dom_.periodic[a]) return false;
  return dir > 0 ? me_[a] == nP_[a] - 1 : me_[a] == 0;
}

int Decomposition::globalCell(int a, double x) const {
  return active(a) ? cellAlong(dom_, a, nGC_[a], x) : 0;
}

int Decomposition::cellAlong(const Domain& domain, int a, int cells, double x) {
  return static_cast<int>(std::floor((x - domain.lo[a]) / (domain.length(a) / cells)));
}

int Decomposition::ownerCoord(int a, int g) const {
  // The last core whose first cell is at or before g.
  const std::vector<int>& cut = cuts_[a];
  return static_cast<int>(std::upper_bound(cut.begin() + 1, cut.end() - 1, g) - cut.begin()) - 1;
}

}  // namespace pdq
