#pragma once
// Spatial decomposition (thesis §3.3.1). The domain is divided into one global lattice of
// cells no smaller than the minimum cell size; each rank's core is a block of whole cells,
// so the cell grid — and with it the order in which neighbours are visited — is the same
// whatever the processor grid. A 2D problem has one cell layer in Z (a 1D one also one in
// Y) and exchanges nothing along the inactive axes.
//
// Divisions: a model may ask for each cell of at least the minimum cell size to be cut
// into k x k x k sub-cells; the lattice is then that of the sub-cells (cores are whole
// sub-cells, so the cuts between ranks are k times finer), and neighbours are looked for
// k sub-cells away, so the reach (k sub-cells, the whole cell) is what it was. A run on one
// rank has no cuts and keeps whole cells (sub-cells would only make more of them to visit).
#include <array>
#include <functional>
#include <string>
#include <vector>

namespace pdq {

struct Domain {
  std::array<double, 3> lo{}, hi{};
  std::array<bool, 3> periodic{};
  int dim = 3;  // active axes are 0 .. dim-1
  double length(int a) const { return hi[a] - lo[a]; }
};

class Decomposition {
 public:
  // nP: processors per axis, 0 = choose automatically. Throws InputError (naming
  // `source`) when the grid does not fit the ranks or has more ranks than cells.
  Decomposition(const Domain& domain, double minCellSize, std::array<int, 3> nP, int nRanks,
                int rank, const std::string& source = "processor grid", int divisions = 1);

  const Domain& domain() const { return dom_; }
  int dim() const { return dom_.dim; }
  bool active(int a) const { return a < dom_.dim; }
  int globalCells(int a) const { return nGC_[a]; }
  double cellSize(int a) const { return cell_[a]; }
  int divisions() const { return div_; }
  // The edge of `divisions` cells (the undivided cell): every pair closer than this is
  // among the cells `divisions` away.
  double reach(int a) const { return reach_[a]; }
  // The smallest reach of an active axis.
  double minActiveCellSize() const;
  // The smallest cell edge a decomposition of `domain` with this minimum cell size has.
  static double minActiveCellSize(const Domain& domain, double minCellSize);
  int procs(int a) const { return nP_[a]; }
  int coord(int a) const { return me_[a]; }
  int coreLo(int a) const { return lo_[a]; }  // first global cell of the core
  int coreHi(int a) const { return hi_[a]; }  // one past the last
  int coreCells(int a) const { return hi_[a] - lo_[a]; }

  // Rank of the neighbouring procCube in direction dir (+1/-1) along a, or -1 at a
  // non-periodic domain boundary. With one rank along a periodic axis, that is this rank.
  int neighbour(int a, int dir) const;
  // True when a message sent in direction dir along a wraps around a periodic boundary.
  bool wraps(int a, int dir) const;
  int rankOf(std::array<int, 3> c) const { return (c[2] * nP_[1] + c[1]) * nP_[0] + c[0]; }
  // Global cell of coordinate x along a (may be <0 or >= globalCells when outside).
  int globalCell(int a, double x) const;
  // The same for `cells` cells along a of `domain` (a count being considered).
  static int cellAlong(const Domain& domain, int a, int cells, double x);
  // Processor coordinate along a that owns global cell g (0 <= g < globalCells).
  int ownerCoord(int a, int g) const;

  // Moves the cuts between the cores along each active axis so that the cores hold about
  // equal weight (weights[a][g]: the particles in the layer of cells g along a; each core
  // keeps at least `divisions` cells). The cell lattice, and with it every result, stays the same;
  // without it the cores have equal numbers of cells. The same weights give the same cuts
  // on every rank.
  void balance(const std::array<std::vector<double>, 3>& weights);
  // For a model whose results do not depend on the cell lattice (bonds are its only
  // neighbours): along each axis cut among several cores, takes the cell count, from the
  // most that fit down to 4/5 of them, whose cores cut as `balance` cuts them leave the
  // heaviest core the least weight (of equal ones, the most cells). `layers(a, n)`: the
  // weight of each of n layers of cells along a. The same weights give the same cells on
  // every rank; call before `balance`.
  void chooseCells(const std::function<std::vector<double>(int axis, int cells)>& layers);

 private:
  Domain dom_;
  std::array<int, 3> nGC_{1, 1, 1}, nP_{1, 1, 1}, me_{0, 0, 0}, lo_{}, hi_{};
  std::array<std::vector<int>, 3> cuts_;  // first cell of each core along each axis, then nGC
  std::array<double, 3> cell_{}, reach_{};
  int div_ = 1;
};

}  // namespace pdq
