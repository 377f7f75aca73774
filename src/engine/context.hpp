#pragma once
// What a model sees of the engine: the particles of its procCube (owned first, ghosts
// after), their bonds, the clock, canonical neighbour iteration, ghost refreshes of
// their own arrays, and global reductions that give the same bits on any number of
// ranks. Nothing here exposes MPI or rank boundaries.
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "engine/bonds.hpp"
#include "engine/exact_sum.hpp"
#include "engine/integrator.hpp"
#include "engine/particles.hpp"
#include "engine/proccube.hpp"

namespace pdq {

class Context {
 public:
  Context(Particles& p, Bonds& b, ProcCube& cube, Comm& comm, std::ostream& log)
      : particles(p), bonds(b), cube_(cube), comm_(comm), log_(log) {}

  Particles& particles;
  Bonds& bonds;

  long step() const { return step_; }    // the step being computed (1-based in the loop)
  long steps() const { return steps_; }  // the last step of the run
  double dt() const { return dt_; }
  double time() const { return step_ * dt_; }
  void setDt(double dt) { dt_ = dt; }
  // The load protocol (the scenario's [loading]) and its factor at the current time.
  const Loading& loading() const { return loading_; }
  // (Quasi-static: the factor of the load step being relaxed, whatever the time.)
  double loadFactor() const { return quasiStatic_ ? staticFactor_ : loading_.factor(time()); }
  // The engine's integrator, one step (the default Model::integrate).
  void integrate() { integrator_->step(*this); }
  const Integrator& integrator() const { return *integrator_; }
  int dim() const { return cube_.decomposition().dim(); }
  const Domain& domain() const { return cube_.decomposition().domain(); }
  // The radius of a pair list that stays complete until the next shuffle: every pair
  // closer than this is among a particle's nearby cells, and the engine shuffles before any
  // particle moves more than (listRadius - horizon) / 2. It is the edge of the cells the
  // model asks for (cells the engine widened, for a larger minimum cell size or a better
  // balance, keep it), so lists hold the same pairs whatever the cells.
  double listRadius() const { return listRadius_; }

  // Every particle j near owned particle i (same or adjacent cell, or up to the model's
  // cell divisions away), canonical order.
  template <class F>
  void forEachNearby(std::size_t i, F&& f) const {
    cube_.forEachNearby(i, std::forward<F>(f));
  }
  // The same particles, the cells in memory order: nearby owned particles come in index
  // order, but the order depends on the processor grid (for order-independent sums).
  template <class F>
  void forEachNearbyInMemoryOrder(std::size_t i, F&& f) const {
    cube_.forEachNearbyInMemoryOrder(i, std::forward<F>(f));
  }
  // The cell of particle i. Owned particles are sorted by cell: consecutive owned
  // particles with the same cell have the same nearby particles (but for themselves).
  int cellOf(std::size_t i) const { return cube_.cellOf(i); }
  // The global cell of particle i, the cells per undivided cell (whose edge is at least the
  // horizon) along each axis, and the global cells along axis a.
  const std::array<int, 3>& globalCellOf(std::size_t i) const { return cube_.globalCellOf(i); }
  int cellDivisions() const { return cube_.decomposition().divisions(); }
  int globalCells(int a) const { return cube_.decomposition().globalCells(a); }
  // Gives the ghosts of a model's own array their owners' values: `values` holds `width`
  // numbers per local particle (owned first, then ghosts; size >= particles.local() x
  // width), e.g. a state-based model's dilatation between its two force passes. Every
  // rank must call it alike.
  void refreshGhosts(std::span<double> values, int width) { cube_.refreshGhosts(values, width); }
  long ghostRefreshes() const { return cube_.ghostRefreshes(); }

  // Global reductions, identical on every rank and for every processor grid.
  double sum(ExactSum& acc) const { return comm_.sum(acc); }
  void sums(std::span<ExactSum> accs) const { comm_.exactSums(accs); }  // one message
  template <class F>
  double sumOwned(F&& value) const {
    ExactSum acc;
    for (std::size_t i = 0; i < particles.owned(); ++i) acc.add(value(i));
    return comm_.sum(acc);
  }
  double max(double v) const { return comm_.max(v); }
  double min(double v) const { return comm_.min(v); }
  long count(long v) const { return comm_.sum(v); }
  bool any(bool v) const { return comm_.any(v); }
  // Every rank's bytes on rank 0 in rank order (rank r's at [starts[r], starts[r + 1])), and
  // rank 0's bytes on every rank: for the engine's own global solves.
  std::vector<char> gather(const std::vector<char>& block, std::vector<std::size_t>& starts) const {
    return comm_.gather(block, starts);
  }
  std::vector<char> broadcast(std::vector<char> data) const {
    return comm_.broadcast(std::move(data));
  }
  int nodeSize() const { return comm_.nodeSize(); }  // collective: ranks on this one's node

  // Ends the run after this step (the reason is logged). Must be called on every rank
  // alike, i.e. decided from global reductions.
  void requestStop(const std::string& reason) { stopReason_ = reason; }
  const std::string& stopReason() const { return stopReason_; }
  // Lines for debug.txt (each rank writes its own section) and for the terminal (rank 0).
  std::ostream& log() { return log_; }
  // A warning for the user: logged, and printed on standard error by the pdq command.
  void warn(const std::string& text) {
    log_ << "warning: " << text << "\n";
    warnings_.push_back(text);
  }
  const std::vector<std::string>& warnings() const { return warnings_; }
  bool root() const { return comm_.root(); }
  // A model that knows its stable time step tells it; the engine names it when a run turns
  // out unstable.
  void setStableDt(double dt) { stableDt_ = dt; }
  double stableDt() const { return stableDt_; }

  // --- set by the engine ---
  void setStep(long s) { step_ = s; }
  void setSteps(long s) { steps_ = s; }
  void setLoading(const Loading& l) { loading_ = l; }
  void setIntegrator(Integrator* i) { integrator_ = i; }
  void setStaticFactor(double f) { quasiStatic_ = true, staticFactor_ = f; }
  void setListRadius(double r) { listRadius_ = r; }

 private:
  ProcCube& cube_;
  Comm& comm_;
  std::ostream& log_;
  long step_ = 0, steps_ = 0;
  double dt_ = 0, stableDt_ = 0, listRadius_ = 0;
  Loading loading_;
  bool quasiStatic_ = false;
  double staticFactor_ = 0;
  Integrator* integrator_ = nullptr;
  std::string stopReason_;
  std::vector<std::string> warnings_;
};

}  // namespace pdq
