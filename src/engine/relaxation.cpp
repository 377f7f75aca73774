// Quasi-static loading by dynamic relaxation (Underwood 1983) with kinetic damping (Cundall;
// Barnes), built on the integrator's degrees of freedom, bodies and constraints.
// Fictitious undamped dynamics with time step 1 and a diagonal fictitious mass per DOF,
//     v(n+½) = v(n−½) + Λ⁻¹ F(n),   x(n+1) = x(n) + v(n+½),
// started from rest at a predictor (the last equilibrium's displacements × λ/λ_last),
// v(½) = Λ⁻¹ F(0) / 2; when the kinetic energy ½ Σ Λ v² of the next step
// would fall, it has passed a peak (the motion crossed the equilibrium of the mode that
// dominates it) and the motion starts again from rest at x(n). No stiffness estimate is
// needed, so softening (a negative local stiffness) does not leave the motion undamped.
// Λ = M ω_max² s / 4 (M the model's masses and inertias, ω_max² the largest eigenvalue of
// M⁻¹K by power iteration on finite differences of the model's forces, s a safety factor),
// so the fictitious step is stable for every model that gives forces. A load step has
// converged when |F|, the out-of-balance force of the free DOFs, is below the tolerance ×
// the applied load |λP| (the reactions |R| when no load is applied), norms in M⁻¹.
// Damage: while the out-of-balance force exceeds kSettled of the applied load, every
// iteration evaluates the forces from the damage kept so far (the bonds are put back before
// each evaluation), so the transient of a load step's first iterations leaves no damage;
// below it the damage of each evaluation is kept, so that softening localizes once and for
// all instead of the relaxation revisiting which interaction cracks. The converged
// evaluation's forces, computed with the damage it left, are the ones in equilibrium.
// With masses = "assembled" the fictitious mass is the stiffness itself, assembled from the
// same finite differences and factorised (engine/stiffness_matrix.hpp): each iteration is a
// modified Newton step x += K̂⁻¹F while those steps converge fast (a linear structure's
// load step takes one), and once one leaves more than kNewtonContraction of the last
// out-of-balance force (cracking, K̂ stiffer than the lattice) the dynamic relaxation above
// with K̂ as the mass matrix, v += K̂⁻¹F, x += v, whose momentum crosses the soft modes' slow
// approach in far fewer iterations. See docs/quasi-static.md.
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <sstream>

#include "engine/bond_colouring.hpp"
#include "engine/context.hpp"
#include "engine/error.hpp"
#include "engine/frequency.hpp"
#include "engine/integrator.hpp"
#include "engine/model.hpp"
#include "engine/stiffness_matrix.hpp"

namespace pdq {

namespace {
// Λ = M ω_max² kSafety / 4: the power iteration approaches ω_max from below.
constexpr double kSafety = 1.5;
// With Gershgorin masses, Λ = G μ kGershgorinSafety / 4 puts the highest mode at
// ω² = 4 / kGershgorinSafety per iteration (μ is that eigenvalue, not a bound of it): 1.6.
// At 2 (a quarter turn per iteration) and at 2.67 the MPLM patch test's relaxation settled
// into a cycle 1e-8 short of its tolerance; at 1.6 it converges in fewer iterations than with
// the model's masses (docs/quasi-static.md, "Fictitious masses").
constexpr double kGershgorinSafety = 2.5;
constexpr int kPowerIterations = 100;
// The finite-difference probe moves no DOF more than this fraction of the horizon (or rad).
constexpr double kProbe = 1e-7;
// Per-DOF fictitious masses need one probe per colour and DOF each way; beyond this many (3D
// peridynamics coloured by cells), the masses are the model's scaled by ω_max² instead.
constexpr long kMaxProbes = 5000;
// The bond graph is coloured on rank 0 while it holds at most this many bonds (16 bytes
// each in transit); a larger one takes the cells' colouring.
constexpr double kMaxColouredBonds = 1 << 24;
// Damage is kept from the evaluations whose out-of-balance force is below this share of the
// applied load (or reactions).
constexpr double kSettled = 1e-2;
// Under force control a load step has no equilibrium near the last one when its displacement
// along the loads exceeds kRunaway times the last equilibrium's (looked at every
// kRunawayEvery iterations): past the peak the undamped motion between kinetic-energy peaks
// carries the structure away; or when the equilibrium it reaches lies on another branch
// (the step's displacement per load over kRunaway times the last equilibrium's).
constexpr double kRunaway = 10;
constexpr long kRunawayEvery = 10;
constexpr double kOvershoot = 2;
// A load step may take this many times the first load step's iterations (when more than
// max_iterations): the first, an elastic relaxation from rest, measures how slowly the
// lattice's lowest modes relax, which grows with the particles along the structure.
constexpr double kFirstStepsPerCap = 10;
// The assembled stiffness's diagonal shift, a share of the diagonal masses: it keeps a
// fragment that broke free (a rigid motion, no stiffness) from making K̂ singular, and is
// far below a long member's lowest stiffness (at 1e-6 a cantilever's bending mode was 36 %
// too stiff: 15 Newton iterations instead of 2).
constexpr double kAssembledShift = 1e-12;
// The assembled stiffness is used while its factor holds at most this many times the
// matrix's nonzero entries: 2D lattices (about 5) and 3D ones at s = 4 cm (about 14) take
// it; larger 3D lattices, whose factorisations would take minutes, relax with the
// Gershgorin masses (docs/quasi-static.md, "Assembled stiffness").
constexpr double kMaxFill = 16;
// The assembled stiffness's iteration takes up momentum once a modified Newton step leaves
// more than this share of the last out-of-balance force.
constexpr double kNewtonContraction = 0.8;

// The particles of each colour (owned ones), coloured by engine cell: cells `period` apart
// along some axis, so at least 2 × passes undivided cells (each at least a horizon) apart:
// a row, which reaches a horizon per force pass, meets one of them at most (two at exactly
// twice its reach apart would both be at the horizon's very edge); within a cell they
// differ by their rank of global ID. None when over `maxColours`, or when a periodic axis's
// cells are not a multiple of the period.
std::vector<std::vector<std::size_t>> cellColours(Context& ctx, long passes, long maxColours) {
  const Particles& P = ctx.particles;
  const std::size_t n = P.owned();
  const int dim = ctx.dim();
  const int period = 2 * static_cast<int>(passes) * ctx.cellDivisions() + 1;
  for (int a = 0; a < dim; ++a)
    if (ctx.domain().periodic[a] && ctx.globalCells(a) % period != 0) return {};
  std::vector<long> sub(n, 0);
  long most = 0;
  for (std::size_t b = 0; b < n;) {
    std::size_t e = b;
    while (e < n && ctx.cellOf(e) == ctx.cellOf(b)) ++e;
    std::vector<std::pair<Gid, std::size_t>> ids;
    for (std::size_t i = b; i < e; ++i) ids.push_back({P.gid(i), i});
    std::sort(ids.begin(), ids.end());
    for (std::size_t k = 0; k < ids.size(); ++k) sub[ids[k].second] = static_cast<long>(k);
    most = std::max(most, static_cast<long>(ids.size()));
    b = e;
  }
  most = static_cast<long>(ctx.max(static_cast<double>(most)));
  long cells = 1;
  for (int a = 0; a < dim; ++a) cells *= period;
  const long colours = cells * most;
  if (colours > maxColours) return {};
  std::vector<std::vector<std::size_t>> members(static_cast<std::size_t>(colours));
  for (std::size_t i = 0; i < n; ++i) {
    const auto& g = ctx.globalCellOf(i);
    long c = 0;
    for (int a = dim - 1; a >= 0; --a) c = c * period + ((g[a] % period) + period) % period;
    members[static_cast<std::size_t>(c * most + sub[i])].push_back(i);
  }
  return members;
}

}  // namespace

long Integrator::iterationCap(const Solver& solver) const {
  return std::max(solver.maxIterations, static_cast<long>(kFirstStepsPerCap * path_.first));
}

double Integrator::dofForce(const Particles& P, std::size_t i, int d, double factor) const {
  const double f = P.integ(i)[frc_[d]];
  const double load = bodies_[i].load[d] * factor;
  return perMass_ && d < nT_ ? f * bodies_[i].mass + load : f + load;
}

std::function<void(std::span<const double>, std::span<double>)> Integrator::stiffnessProbe(
    Context& ctx, const std::function<void()>& forces, long* passes) {
  Particles& P = ctx.particles;
  const std::size_t n = P.owned(), nl = P.local();
  const int nd = nT_ + nR_;
  struct State {
    Bonds::Saved bonds;
    std::vector<double> f0, saved;
  };
  auto st = std::make_shared<State>();
  ctx.bonds.save(st->bonds);
  const long before = ctx.ghostRefreshes();
  forces();
  if (passes) *passes = 1 + ctx.ghostRefreshes() - before;
  st->f0.resize(n * nd);
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < nd; ++d) st->f0[nd * i + d] = dofForce(P, i, d, 0);
  st->saved.assign(P.alter(0), P.alter(0) + nl * P.schema().nAlter());
  const double h = model_.horizon();
  return [this, &ctx, forces, st, n, nl, nd, h](std::span<const double> u, std::span<double> f) {
    Particles& P = ctx.particles;
    double big = 0;
    for (std::size_t i = 0; i < n; ++i)
      for (int d = 0; d < nd; ++d)
        big = std::max(big, std::fabs(u[nd * i + d]) / (d < nT_ ? h : 1.0));
    const double eps = kProbe / ctx.max(big);
    for (std::size_t i = 0; i < nl; ++i) {
      double* a = P.alter(i);
      for (int d = 0; d < nT_; ++d) a[pos_[d]] += eps * u[nd * i + d];
      if (rotation_ == Rotation::Planar) a[pos_[nT_]] += eps * u[nd * i + nT_];
      if (rotation_ == Rotation::Spatial) {
        const double phi[3] = {eps * u[nd * i + nT_], eps * u[nd * i + nT_ + 1],
                               eps * u[nd * i + nT_ + 2]};
        // Not turning the reference orientation by nothing gives its bits, for less work:
        // a colour's probe turns few of the particles.
        const bool still = phi[0] == 0 && phi[1] == 0 && phi[2] == 0 && a[quat_[0]] == 1 &&
                           a[quat_[1]] == 0 && a[quat_[2]] == 0 && a[quat_[3]] == 0;
        if (!still) turn(P, i, phi);
      }
    }
    forces();
    ctx.bonds.restore(st->bonds);
    for (std::size_t i = 0; i < n; ++i)
      for (int d = 0; d < nd; ++d)
        f[nd * i + d] = (dofForce(P, i, d, 0) - st->f0[nd * i + d]) / eps;
    std::copy(st->saved.begin(), st->saved.end(), P.alter(0));
  };
}

double Integrator::highestFrequencySquared(Context& ctx, const std::function<void()>& forces,
                                           const std::vector<double>& masses) {
  const std::size_t n = ctx.particles.owned();
  const int nd = nT_ + nR_;
  DofSystem sys;
  sys.dofs = nd;
  sys.mass.resize(n * nd);
  sys.held.resize(n * nd);
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < nd; ++d) {
      const Constraint c = bodies_[i].constraint[d];
      sys.mass[nd * i + d] = !masses.empty() ? masses[nd * i + d] : dofMass(i, d);
      sys.held[nd * i + d] = c == Constraint::Prescribed || c == Constraint::KeepVelocity;
    }
  const double omega = highestFrequency(ctx, sys, stiffnessProbe(ctx, forces), kPowerIterations);
  return omega * omega;
}

bool Integrator::statedRows(Context& ctx, std::vector<double>& rows,
                            std::vector<StiffnessEntry>* entries) {
  if (!model_.statesStiffness()) return false;
  Particles& P = ctx.particles;
  const std::size_t n = P.owned(), nl = P.local();
  const int nd = nT_ + nR_;
  // Per local DOF what a probe would move it by: 1/√m where free, 0 where held.
  std::vector<double> u(nl * nd, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < nd; ++d) {
      const Constraint c = bodies_[i].constraint[d];
      if (c != Constraint::Prescribed && c != Constraint::KeepVelocity)
        u[nd * i + d] = 1 / std::sqrt(dofMass(i, d));
    }
  ctx.refreshGhosts(u, nd);
  rows.assign(n * nd, 0.0);
  if (entries) entries->clear();
  model_.referenceStiffness(ctx, [&](std::size_t i, std::size_t j, std::span<const double> K,
                                     std::span<const double> bound) {
    for (int a = 0; a < nd; ++a) {
      const Constraint c = bodies_[i].constraint[a];
      const bool freeRow = c != Constraint::Prescribed && c != Constraint::KeepVelocity;
      // dofForce's units: a model whose force columns hold accelerations is scaled.
      const double scale = perMass_ && a < nT_ ? bodies_[i].mass : 1.0;
      for (int b = 0; b < nd; ++b) {
        const double m = u[nd * j + b];
        if (m == 0) continue;
        const auto at = static_cast<std::size_t>(nd * a + b);
        rows[nd * i + a] += std::fabs(bound[at] * scale) * m;
        // Zeros are kept as the probes keep them: the bonds' pattern.
        if (entries && freeRow) entries->push_back({P.gid(i), P.gid(j), a, b, K[at] * scale});
      }
    }
  });
  if (ctx.root()) ctx.log() << "quasi-static: the stiffness as the model states it (no probes)\n";
  return true;
}

std::vector<double> Integrator::gershgorinRows(Context& ctx, const std::function<void()>& forces,
                                               std::vector<StiffnessEntry>* entries) {
  if (std::vector<double> rows; statedRows(ctx, rows, entries)) return rows;
  Particles& P = ctx.particles;
  const std::size_t n = P.owned(), nl = P.local();
  const int nd = nT_ + nR_;
  // Probed at the reference configuration with the bonds as they are: the stiffness of
  // the damaged lattice unloaded, which no damage grows under (a probe at a strained state
  // would meet interactions softening at the crack fronts), and which depends on nothing a
  // restart file does not hold.
  const int nA = P.schema().nAlter();
  const std::vector<double> current(P.alter(0), P.alter(0) + nl * nA);
  Bonds::Saved bonds;  // an evaluation at the reference may change them (a yielded bar)
  ctx.bonds.save(bonds);
  auto putBack = [&] {
    std::copy(current.begin(), current.end(), P.alter(0));
    ctx.bonds.restore(bonds);
  };
  for (std::size_t i = 0; i < nl; ++i) {
    double* a = P.alter(i);
    for (int d = 0; d < nT_; ++d) a[pos_[d]] = P.fixed(i)[pos_[d]];
    if (rotation_ == Rotation::Planar) a[pos_[nT_]] = 0;
    if (rotation_ == Rotation::Spatial) {
      a[quat_[0]] = 1;
      a[quat_[1]] = a[quat_[2]] = a[quat_[3]] = 0;
    }
  }
  long passes = 1;
  auto probe = stiffnessProbe(ctx, forces, &passes);
  // The colours, each probed at once: with a model whose forces come from its bonds alone
  // (one force pass), a distance-2 colouring of the bond graph; otherwise the cells'.
  const bool byBonds = model_.forcesFromBonds() && passes == 1 && ctx.sumOwned([&](std::size_t i) {
    return static_cast<double>(ctx.bonds.end(i) - ctx.bonds.begin(i));
  }) <= kMaxColouredBonds;
  std::vector<std::vector<std::size_t>> members;
  if (byBonds) {
    long count = 0;
    const std::vector<long> colour = bondColours(ctx, count);
    if (count * nd > kMaxProbes) {
      putBack();
      return {};
    }
    members.resize(static_cast<std::size_t>(count));
    for (std::size_t i = 0; i < n; ++i) members[static_cast<std::size_t>(colour[i])].push_back(i);
  } else {
    members = cellColours(ctx, passes, kMaxProbes / nd);
    if (members.empty()) {
      putBack();
      return {};
    }
  }
  // The entries: a probe's response at row i comes from the one particle it moved that is
  // i or near i: one of its bonds' partners, or in the nearby cells (one force pass: the
  // model reaches no further).
  if (entries) {
    entries->clear();
    if (passes != 1) entries = nullptr;
  }
  std::vector<std::vector<std::size_t>> nearby(entries ? n : 0);
  for (std::size_t i = 0; i < nearby.size(); ++i) {
    nearby[i].push_back(i);
    if (byBonds) {
      for (std::size_t b = ctx.bonds.begin(i); b < ctx.bonds.end(i); ++b)
        if (ctx.bonds.partner(b) >= 0)
          nearby[i].push_back(static_cast<std::size_t>(ctx.bonds.partner(b)));
    } else {
      ctx.forEachNearby(i, [&](std::size_t j) { nearby[i].push_back(j); });
    }
  }
  std::vector<double> rows(n * nd, 0.0), u(nl * nd), f(n * nd), g(n * nd);
  long probes = 0;
  for (const auto& colour : members) {
    for (int d = 0; d < nd; ++d) {
      std::fill(u.begin(), u.end(), 0.0);
      bool any = false;
      for (std::size_t i : colour) {
        const Constraint k = bodies_[i].constraint[d];
        if (k == Constraint::Prescribed || k == Constraint::KeepVelocity) continue;
        u[nd * i + d] = 1 / std::sqrt(dofMass(i, d));
        any = true;
      }
      if (!ctx.any(any)) continue;
      // Both ways: an interaction that is damaged in tension may be whole in compression.
      ctx.refreshGhosts(u, nd);
      probe(u, f);
      for (std::size_t k = 0; k < nl * nd; ++k) u[k] = -u[k];
      probe(u, g);
      for (std::size_t k = 0; k < n * nd; ++k)
        rows[k] += std::max(std::fabs(f[k]), std::fabs(g[k]));
      ++probes;
      if (!entries) continue;
      // f = −K u and g = K u: K_ij = (g_i − f_i) / (2 u_j), j the moved particle near i.
      // An entry is kept where it is 0 too (a broken interaction, or DOFs that do not
      // couple): the pattern is then that of the bonds, whatever their damage, and the
      // ordering of the first factorisation serves every later one (and a restart's).
      for (std::size_t i = 0; i < n; ++i) {
        std::size_t j = nl;
        for (int di = 0; di < nd; ++di) {
          const std::size_t k = nd * i + di;
          const Constraint c = bodies_[i].constraint[di];
          if (c == Constraint::Prescribed || c == Constraint::KeepVelocity) continue;
          if (j == nl)
            for (std::size_t m : nearby[i])
              if (u[nd * m + d] != 0) {
                j = m;
                break;
              }
          if (j == nl) continue;
          entries->push_back(
              {P.gid(i), P.gid(j), di, d, (g[k] - f[k]) / (2 * std::fabs(u[nd * j + d]))});
        }
      }
    }
  }
  putBack();
  if (ctx.root()) ctx.log() << "quasi-static: " << probes << " stiffness probes each way\n";
  // |f_i| = |K_ij| / √m_j: the row sums of M^(−½) K M^(−½), times √m_i.
  return rows;
}

Integrator::Relaxed Integrator::relax(Context& ctx, const Solver& solver, const std::string& source,
                                      double factor, double previous,
                                      const std::function<void()>& forces,
                                      const std::function<void()>& exchange) {
  Particles& P = ctx.particles;
  ensureBodies(ctx);
  const std::size_t n = P.owned();
  const int nd = nT_ + nR_, nLinear = nT_ + (rotation_ == Rotation::Planar ? 1 : 0);
  // Displacement control: the controlled translation is prescribed (the bodies are asked
  // for again after a shuffle, so it is set on every call).
  const DisplacementControl& control = solver.control;
  std::vector<unsigned char> controlled(n, 0);
  if (control.active()) {
    if (control.axis >= nT_)
      throw InputError(source, control.line,
                       std::string("the displacement control moves particles along ") +
                           "xyz"[control.axis] + ", but the model moves them along " +
                           std::to_string(nT_) + " axes only");
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::binary_search(control.ids.begin(), control.ids.end(), P.gid(i))) continue;
      controlled[i] = 1;
      bodies_[i].constraint[control.axis] = Constraint::Prescribed;
      bodies_[i].value[control.axis] = control.displacement;
    }
    if (ctx.sumOwned([&](std::size_t i) { return controlled[i] ? 1.0 : 0.0; }) == 0)
      throw InputError(source, control.line, "the displacement control moves no particle");
    indexFreeBodies();
  }
  // The fictitious velocities are the solver's own: the model's stay zero, so no
  // velocity-dependent force (damping) acts on the static state.
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < nd; ++d) P.alter(i)[vel_[d]] = 0;
  exchange();
  // Fictitious masses (docs/quasi-static.md, "Fictitious masses"): unless the solver asks
  // for the model's, and where the probes are few enough, Λ_i = G_i μ kGershgorinSafety / 4
  // with G_i each free DOF's Gershgorin bound of the stiffness, probed at the start of every
  // load step from the last equilibrium (a restarted run, which starts from it, probes the
  // same), and μ = ω_max² of G⁻¹K by power iteration at the first load step; otherwise
  // Λ = M ω_max² kSafety / 4 with ω_max² of M⁻¹K. The first load step's choice holds for
  // the run, restarts included (μ > 0: Gershgorin masses).
  const bool first = omega2_ < 0;
  if (first && solver.masses == Solver::Masses::Assembled) {
    // Supports that only push make the unknowns change as particles lift off or come to
    // rest (a contact problem the modified Newton iteration would chatter on); a structure
    // that nothing holds (a plate pulled at both ends) has rigid motions that make the
    // matrix singular, and its solves amplify round-off along them.
    bool resting = false, held = false;
    for (std::size_t i = 0; i < n; ++i)
      for (int d = 0; d < nd; ++d) {
        const Constraint c = bodies_[i].constraint[d];
        resting |= c == Constraint::Resting;
        held |= c == Constraint::Prescribed || c == Constraint::KeepVelocity;
      }
    resting = ctx.any(resting);
    held = ctx.any(held);
    assembled_ = !resting && held;
    if (!assembled_)
      ctx.warn(std::string("quasi-static: masses = \"assembled\" ") +
               (resting ? "does not take supports that only push (bearings)"
                        : "needs supports that hold the structure") +
               "; the Gershgorin masses are used");
  }
  bool probed = false;
  std::vector<StiffnessEntry> entries;
  if (first ? solver.masses != Solver::Masses::Model : mu_ > 0) {
    // The rows (and the assembled stiffness) are probed at the reference configuration
    // with the interactions' state as it is, so they are at hand while that state is the
    // one they were probed with: a try after a cut-back, or load steps that damaged nothing.
    const bool same = !first && rows_.size() == n * nd && !ctx.any(!ctx.bonds.same(rowsBonds_));
    if (!same) {
      rows_ = gershgorinRows(ctx, forces, assembled_ ? &entries : nullptr);
      ctx.bonds.save(rowsBonds_);
      probed = true;
    }
    if (rows_.empty() && !first)
      throw std::logic_error("quasi-static: the Gershgorin probes are no longer possible");
  }
  // The Gershgorin mass of a DOF (a DOF with no stiffness, its interactions all broken,
  // takes the model's mass × the largest ratio of the first load step, omega2_).
  auto gershgorin = [&](std::size_t i, int d) {
    const double g = std::sqrt(dofMass(i, d)) * rows_[nd * i + d];
    return g > 0 ? g : dofMass(i, d) * omega2_;
  };
  if (first) {
    if (!rows_.empty()) {
      omega2_ = ctx.max([&] {
        double most = 0;
        for (std::size_t i = 0; i < n; ++i)
          for (int d = 0; d < nd; ++d)
            most = std::max(most, rows_[nd * i + d] / std::sqrt(dofMass(i, d)));
        return most;
      }());
      if (omega2_ > 0) {
        std::vector<double> g(n * nd);
        for (std::size_t i = 0; i < n; ++i)
          for (int d = 0; d < nd; ++d) g[nd * i + d] = gershgorin(i, d);
        mu_ = highestFrequencySquared(ctx, forces, g);
      }
    } else {
      omega2_ = highestFrequencySquared(ctx, forces, {});
    }
    if (!(omega2_ > 0) || (!rows_.empty() && !(mu_ > 0)))
      throw InputError(source, solver.line,
                       "the quasi-static solver found no stiffness (are all degrees of freedom "
                       "held, or does the model give no forces?)");
    if (ctx.root()) {
      if (mu_ > 0)
        ctx.log() << "quasi-static: fictitious masses per degree of freedom, the stiffness's "
                     "Gershgorin bounds × "
                  << mu_ << " (the highest eigenvalue of their inverse × K)\n";
      else
        ctx.log() << "quasi-static: highest frequency " << std::sqrt(omega2_)
                  << " rad/s of the free degrees of freedom\n";
    }
  }
  // The applied load (the sum of the loads' magnitudes) and the displacement along it
  // (u·P / Σ|P|: for loads all in one direction their load-weighted mean displacement).
  const double loadTotal = ctx.sumOwned([&](std::size_t i) {
    double a = 0;
    for (int d = 0; d < nd; ++d) a += std::fabs(bodies_[i].load[d]);
    return a;
  });
  auto alongLoads = [&] {
    const double work = ctx.sumOwned([&](std::size_t i) {
      double b = 0;
      for (int d = 0; d < nd; ++d) b += bodies_[i].load[d] * displacement(P, i, d);
      return b;
    });
    return loadTotal > 0 ? work / loadTotal : 0.0;
  };
  // Under force control, the last equilibrium's displacement along the loads: a load step
  // whose fictitious motion runs away from it has no
  // equilibrium near it (the structure is past its peak) and is stopped then instead of
  // after max_iterations.
  const double lastAlong = control.active() ? 0.0 : alongLoads();

  // Prescribed values of this load step (a spatial rotation turns by its increment).
  for (std::size_t i = 0; i < n; ++i) {
    const Body& b = bodies_[i];
    double* a = P.alter(i);
    for (int d = 0; d < nLinear; ++d)
      if (b.constraint[d] == Constraint::Prescribed)
        a[pos_[d]] = (d < nT_ ? P.fixed(i)[pos_[d]] : 0.0) + b.value[d] * factor;
    if (rotation_ == Rotation::Spatial) {
      double phi[3];
      for (int k = 0; k < 3; ++k)
        phi[k] = b.constraint[nT_ + k] == Constraint::Prescribed
                     ? b.value[nT_ + k] * (factor - previous)
                     : 0.0;
      if (phi[0] != 0 || phi[1] != 0 || phi[2] != 0) turn(P, i, phi);
    }
  }
  // Predictor: the free degrees of freedom start from the last equilibrium's displacements
  // scaled to this load step's factor (the secant: exact for a linear structure, and it
  // needs nothing but the state a restart file holds), not from the last equilibrium.
  if (previous > 0 && factor > previous) {
    const double scale = factor / previous;
    for (std::size_t i = 0; i < n; ++i) {
      const Body& b = bodies_[i];
      double* a = P.alter(i);
      for (int d = 0; d < nLinear; ++d) {
        const Constraint c = b.constraint[d];
        if (c != Constraint::Free && c != Constraint::Resting) continue;
        const double ref = d < nT_ ? P.fixed(i)[pos_[d]] : 0.0;
        a[pos_[d]] = ref + (a[pos_[d]] - ref) * scale;
        if (c == Constraint::Resting) a[pos_[d]] = std::max(a[pos_[d]], ref);
      }
      if (rotation_ == Rotation::Spatial) {
        double phi[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k)
          if (b.constraint[nT_ + k] == Constraint::Free)
            phi[k] = (scale - 1) * displacement(P, i, nT_ + k);
        if (phi[0] != 0 || phi[1] != 0 || phi[2] != 0) turn(P, i, phi);
      }
    }
  }
  exchange();

  // Per owned DOF: fictitious mass, velocity and acceleration.
  std::vector<double> lambda(n * nd), v(n * nd, 0.0), acc(n * nd);
  std::vector<unsigned char> free(n * nd);
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < nd; ++d) {
      const Constraint c = bodies_[i].constraint[d];
      lambda[nd * i + d] = mu_ > 0 ? gershgorin(i, d) * mu_ * kGershgorinSafety / 4
                                   : dofMass(i, d) * omega2_ * kSafety / 4;
      free[nd * i + d] = c == Constraint::Free || c == Constraint::Resting;
    }
  // The assembled stiffness, factorised with the rows it was probed with; a load step whose
  // matrix is not positive definite (a mechanism) relaxes with the diagonal masses.
  if (assembled_ && probed) {
    factorised_ = false;
    const bool any = ctx.any(!entries.empty());
    if (!matrix_) matrix_ = std::make_shared<StiffnessMatrix>();
    StiffnessMatrix& m = *matrix_;
    StiffnessMatrix::Outcome outcome = StiffnessMatrix::Outcome::TooLarge;
    if (any) {
      std::vector<Gid> gids(n);
      for (std::size_t i = 0; i < n; ++i) gids[i] = P.gid(i);
      outcome = m.factorise(ctx, gids, nd, free, entries, lambda, kAssembledShift, kMaxFill);
      if (ctx.root())
        ctx.log() << "quasi-static: assembled stiffness, " << m.unknowns() << " unknowns, "
                  << m.matrixNonzeros() << " nonzero entries (" << m.matrixStored()
                  << " stored, the bonds' zeros included), " << m.factorNonzeros()
                  << " in its factor";
      if (const double f = m.twoThreadFactorisation(); ctx.root() && f > 0)
        ctx.log() << ", factorised on two threads (" << std::lround(100 * f)
                  << " % of its operations in supernodes cut in two)";
      if (const auto s = m.twoThreadShares(); ctx.root() && !s.empty())
        ctx.log() << ", solved on two threads (parts of " << std::lround(100 * s[0]) << " % and "
                  << std::lround(100 * s[1]) << " % of the factor, " << std::lround(100 * s[2])
                  << " % above them)";
      if (ctx.root())
        ctx.log() << (outcome == StiffnessMatrix::Outcome::NotDefinite
                          ? ", not positive definite: this load step relaxes with the diagonal "
                            "masses\n"
                          : "\n");
    }
    factorised_ = outcome == StiffnessMatrix::Outcome::Factorised;
    if (outcome == StiffnessMatrix::Outcome::TooLarge) assembled_ = false;
    if (first && !assembled_) {
      ctx.warn(any ? "quasi-static: masses = \"assembled\": the stiffness's factor would fill "
                     "in too much (a 3D lattice of this size); the Gershgorin masses are used"
                   : "quasi-static: masses = \"assembled\" needs a model whose forces reach no "
                     "further than the nearby cells, and few enough probes; the diagonal "
                     "masses are used");
    }
  }
  const bool newton = assembled_ && factorised_;
  bool accelerated = false;  // the assembled stiffness's iteration has taken up momentum
  double lastResidual = 0;
  std::vector<double> step(newton ? n * nd : 0);
  auto weight = [&](std::size_t i, int d) { return 1 / dofMass(i, d); };
  auto onSupport = [&](std::size_t i, int d) {
    return bodies_[i].constraint[d] == Constraint::Resting &&
           P.alter(i)[pos_[d]] <= P.fixed(i)[pos_[d]];
  };
  // The applied load's norm (constant within the load step).
  const double pp = ctx.sumOwned([&](std::size_t i) {
    double p2 = 0;
    for (int d = 0; d < nd; ++d) {
      const double load = bodies_[i].load[d] * factor;
      p2 += load * load * weight(i, d);
    }
    return p2;
  });
  // The snap-through look's limit on this load step's displacement along the loads: kRunaway
  // times the last equilibrium's compliance u/λ for its increment. The motion from rest
  // overshoots a linear structure's equilibrium by at most the step's own increment, so a
  // motion past kOvershoot times that limit does not come back within it.
  const bool stepping = !control.active() && lastAlong != 0 && factor > previous && previous > 0;
  const double stepLimit = kRunaway * std::fabs(lastAlong) / previous * (factor - previous);
  Bonds::Saved kept;
  ctx.bonds.save(kept);
  Relaxed out;
  const long cap = iterationCap(solver);
  const long nOwned = static_cast<long>(n);
  double kinetic = 0;  // twice the kinetic energy of the last step
  for (long it = 0;; ++it) {
    if (it > 0) {  // the last evaluation's damage is kept once the motion has settled
      if (out.residual < kSettled * out.reference)
        ctx.bonds.save(kept);
      else
        ctx.bonds.restore(kept);
    }
    forces();
    // One pass and one global sum: the out-of-balance forces of the free DOFs; the reactions
    // of the held ones (and of a resting DOF its support pushes); for kinetic damping, twice
    // the kinetic energy of the undamped step and of a step from rest (diagonal masses) or
    // the power F·v (the assembled stiffness); every kRunawayEvery iterations the work of the
    // loads on the displacements (the runaway look).
    const bool look = !control.active() && lastAlong != 0 && it % kRunawayEvery == 0;
    enum { kResidual, kReaction, kMoving, kStill, kWork, kPower, kSums };
    std::array<ExactSum, kSums> sums;
    for (std::size_t i = 0; i < n; ++i) {
      double r2 = 0, R2 = 0, e = 0, e0 = 0, work = 0, power = 0;
      for (int d = 0; d < nd; ++d) {
        const std::size_t k = nd * i + d;
        const double f = dofForce(P, i, d, factor), w = weight(i, d);
        if (free[k] && !(onSupport(i, d) && f < 0)) {
          r2 += f * f * w;
          if (newton) power += f * v[k];
          acc[k] = newton ? f : f / lambda[k];
        } else {
          R2 += f * f * w;
          acc[k] = 0;
        }
        if (free[k] && !newton) {
          const double u = v[k] + acc[k];
          e += lambda[k] * u * u;
          e0 += lambda[k] * acc[k] * acc[k] / 4;
        }
        if (look && bodies_[i].load[d] != 0) work += bodies_[i].load[d] * displacement(P, i, d);
      }
      sums[kResidual].add(r2);
      sums[kReaction].add(R2);
      sums[kWork].add(work);
      if (newton) {
        sums[kPower].add(power);
      } else {
        sums[kMoving].add(e);
        sums[kStill].add(e0);
      }
    }
    ctx.sums(sums);
    const double rr = sums[kResidual].value(), reaction = sums[kReaction].value();
    out.residual = std::sqrt(rr);
    out.reference = pp > 0 ? std::sqrt(pp) : std::sqrt(reaction);
    out.iterations = it;
    if (out.residual <= solver.tolerance * out.reference) {
      // Snapped through: the equilibrium found is over kRunaway times as compliant, for this
      // load step's increment, as the last one was on average (u / λ): the structure passed
      // a limit point of its curve (a crack ran through) and came to rest on another branch.
      if (stepping && std::fabs(alongLoads() - lastAlong) > stepLimit) {
        out.converged = false;
        out.runaway = true;
      }
      break;
    }
    if (it >= cap) {
      out.converged = false;
      break;
    }
    // Ran away: the structure moved along the loads over kRunaway times as far as at the
    // last equilibrium, or, in this load step, over kOvershoot times the snap-through limit.
    if (look) {
      const double along = loadTotal > 0 ? sums[kWork].value() / loadTotal : 0.0;
      if (std::fabs(along) > kRunaway * std::fabs(lastAlong) ||
          (stepping && std::fabs(along - lastAlong) > kOvershoot * stepLimit)) {
        out.converged = false;
        out.runaway = true;
        break;
      }
    }
    // Assembled stiffness: modified Newton steps K̂⁻¹F, then dynamic relaxation with K̂ as
    // its mass matrix. Kinetic damping: when the kinetic energy of the undamped step would
    // fall, the motion has passed a peak and starts again from rest.
    bool rest = false;
    if (newton) {
      const double fk = matrix_->solve(ctx, acc, step);  // F·K̂⁻¹F
      if (!accelerated && it > 0 && out.residual > kNewtonContraction * lastResidual) {
        accelerated = rest = true;
        out.momentumFrom = it;
      } else if (accelerated)  // the kinetic energy ½vᵀK̂v changes by F·v + ½F·K̂⁻¹F
        rest = sums[kPower].value() + fk / 2 < 0;
      lastResidual = out.residual;
    } else {
      const double now = sums[kMoving].value(), fromRest = sums[kStill].value();
      rest = it == 0 || now < kinetic;
      kinetic = rest ? fromRest : now;
    }
#pragma omp parallel for schedule(static)
    for (long i = 0; i < nOwned; ++i) {
      double* a = P.alter(i);
      const double* X = P.fixed(i);
      double phi[3] = {0, 0, 0};
      for (int d = 0; d < nd; ++d) {
        const std::size_t k = nd * i + d;
        if (!free[k]) continue;
        if (!newton)
          v[k] = rest ? acc[k] / 2 : v[k] + acc[k];
        else if (accelerated)
          v[k] = rest ? step[k] / 2 : v[k] + step[k];
        const double move = newton && !accelerated ? step[k] : v[k];
        if (d >= nLinear) {
          phi[d - nT_] = move;
          continue;
        }
        a[pos_[d]] += move;
        const double ref = d < nT_ ? X[pos_[d]] : 0.0;
        if (bodies_[i].constraint[d] == Constraint::Resting && a[pos_[d]] < ref) {
          a[pos_[d]] = ref;  // on the support
          v[k] = 0;
        }
      }
      if (rotation_ == Rotation::Spatial) turn(P, i, phi);
    }
    exchange();
  }
  iterations_ += static_cast<double>(out.iterations);
  out.load = factor * loadTotal;
  out.displacement = alongLoads();
  if (out.converged && stepping && newton)
    out.softening = (out.displacement - lastAlong) / (factor - previous) / (lastAlong / previous);
  if (control.active()) {
    // The force the control exerts along its direction: minus the internal forces on the
    // controlled particles (the evaluation at which the load step converged).
    const double sign = control.displacement > 0 ? 1.0 : -1.0;
    out.load = -sign * ctx.sumOwned([&](std::size_t i) {
      return controlled[i] ? dofForce(P, i, control.axis, 0) : 0.0;
    });
    out.displacement = std::fabs(control.displacement) * factor;
  }
  return out;
}

}  // namespace pdq
