#pragma once
// The procCube of one rank: its core cells (owned particles) and the skin around them, one
// cell deep or as many as the decomposition's divisions (ghost copies of the neighbours'
// wall cells), with
//   * the border pass, which rebuilds the skin with Plimpton's six steps Xp, Xn, Yp, Yn,
//     Zp, Zn — later steps forward what earlier ones received, so edges and corners
//     arrive without diagonal messages — and records the exchange plan;
//   * the halo exchange, which replays that plan every step and sends only the wall
//     particles' alterable attributes, one message per direction;
//   * the shuffle, which moves particles whose position left their cell into the right
//     cell, migrating to the neighbouring rank when they left the core.
// Cells are the global cell lattice of the Decomposition; within a cell, particles are
// visited in global-ID order, so neighbour iteration order is the same on any processor
// grid.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/bonds.hpp"
#include "engine/comm.hpp"
#include "engine/decomposition.hpp"
#include "engine/particles.hpp"

namespace pdq {

struct ExchangeStats {
  std::uint64_t haloMessages = 0, haloBytes = 0;        // last halo exchange
  std::uint64_t shuffleMessages = 0, shuffleBytes = 0;  // last shuffle (migrate + border)
  std::uint64_t haloWallParticles = 0;                  // particles sent by the last halo
};

class ProcCube {
 public:
  ProcCube(const Decomposition& dec, Comm& comm, Particles& particles, Bonds& bonds,
           bool binByCurrentPosition);

  const Decomposition& decomposition() const { return dec_; }

  // Keeps, from every particle of the problem, those in this core (thesis SetupProblem).
  // gid/fixed/alter are global tables in the schema's widths.
  void distribute(const std::vector<Gid>& gid, const std::vector<double>& fixed,
                  const std::vector<double>& alter);
  // Sorts owned particles by (cell, global ID), rebuilds the skin (border pass), the
  // cell lists and the bonds' local partner indices.
  void rebuild(long step);
  // Shuffle (thesis §3.3.4): wraps periodic positions, migrates particles that left the
  // core, then rebuild(). Call only for models whose particles change neighbours.
  void shuffle(long step);
  // Halo exchange of the alterable attributes ghosts need (Schema::nHalo), or of all of
  // them (`allColumns`: the engine's checks read the ghosts' velocities).
  void halo(bool allColumns = false);
  // The same plan for a model's own array of `width` values per local particle (owned
  // first, then ghosts): the ghosts' rows get their owners' values. Nothing is shifted
  // across periodic boundaries, so positions do not belong here.
  void refreshGhosts(std::span<double> values, int width);
  // How many times refreshGhosts ran (a model that refreshes its own arrays between force
  // passes reaches that many more cells).
  long ghostRefreshes() const { return refreshes_; }
  // Bonds: map each bond's partner global ID to a local index (nearest copy if several).
  void remapBonds(long step);

  // The largest distance an owned particle moved since the last rebuild (and which one).
  double maxDisplacementSinceRebuild(std::size_t* which = nullptr) const;

  // --- cells, for neighbour iteration ---
  // Visits every particle j (owned or ghost, j != i) in the cells around i's cell, in the
  // canonical order: cells by (dz, dy, dx), particles in a cell by global ID.
  template <class F>
  void forEachNearby(std::size_t i, F&& f) const {
    visit(stencil_, i, f);
  }
  // The same particles with the cells in memory order, so that nearby owned particles come
  // in index order (owned particles are sorted by cell). Which cell comes first depends on
  // the cells' layout, hence on the processor grid: for models whose sums do not depend on
  // the order (LJ's exact sums).
  template <class F>
  void forEachNearbyInMemoryOrder(std::size_t i, F&& f) const {
    visit(memoryStencil_, i, f);
  }

  // The local cell of particle i (owned particles are sorted by cell, so owned particles
  // of one cell are consecutive and share their nearby particles).
  int cellOf(std::size_t i) const { return cell_[i]; }
  // The global cell of local particle i (that of its listing).
  const std::array<int, 3>& globalCellOf(std::size_t i) const { return gcell_[i]; }

  const ExchangeStats& stats() const { return stats_; }
  std::uint64_t haloRecordBytes() const;

 private:
  struct Direction {
    int axis, dir, dest, src;
    bool wrapsOut;  // what I send crosses a periodic boundary (shift positions)
    std::vector<std::uint32_t> send;
    std::size_t recvFirst = 0, recvCount = 0;
  };
  int localCell(const std::array<int, 3>& globalCell) const;
  std::array<int, 3> globalCellOfPosition(const double* pos) const;
  void borderPass();
  void buildCellLists();
  void migrate(long step);
  const double* binPosition(std::size_t i) const;
  static double* buffer(std::vector<double>& b, std::size_t n);  // at least n values
  // Calls f(j) for every particle j != i in the cells at `stencil`'s offsets from i's.
  template <class F>
  void visit(const std::vector<int>& stencil, std::size_t i, F& f) const {
    const int c = cell_[i];
    for (int o : stencil) {
      const int cc = c + o;
      for (std::uint32_t k = cellStart_[cc]; k < cellStart_[cc + 1]; ++k) {
        const std::uint32_t j = cellList_[k];
        if (j != i) f(j);
      }
    }
  }

  const Decomposition& dec_;
  Comm& comm_;
  Particles& p_;
  Bonds& bonds_;
  bool byCurrent_;
  std::array<int, 3> ext_{}, skin_{};      // local cell extents (core + skin), skin depth
  std::array<int, 3> stride_{};            // a cell's index = Σ local cell coordinate × stride
  std::vector<int> stencil_;               // linear offsets of the neighbour cells, canonical
  std::vector<int> memoryStencil_;         // the same, ascending
  std::vector<std::int32_t> cell_;         // local cell of each local particle
  std::vector<std::array<int, 3>> gcell_;  // global cell of each local particle (unwrapped)
  std::vector<std::uint32_t> cellStart_, cellList_;
  std::vector<Direction> dirs_;
  std::vector<double> rebuildPos_;  // owned positions at the last rebuild
  std::vector<double> sendBuf_, recvBuf_;
  ExchangeStats stats_;
  long refreshes_ = 0;
};

}  // namespace pdq
