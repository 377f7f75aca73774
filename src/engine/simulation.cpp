#include "engine/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <optional>

#include "engine/atomic_file.hpp"
#include "engine/error.hpp"

namespace pdq {

namespace {

// Quasi-static load stepping: a converged load step this many times as compliant as the
// secant of the last equilibrium halves the next increment, at most this many times below
// the largest when no peak bracket is asked for.
constexpr double kSoftening = 1.75;
constexpr int kSofteningCuts = 4;

// A particle's move in a step relative to a partner it is still bonded to (squares).
struct Jump {
  double relative = -1, own = 0;  // the relative move, and the particle's own
  Gid id = 0, partner = 0;        // the particle (of the two, the one that moved more)
};

// The largest such move, looked for from the owned particles that moved more than `half`
// (of a relative move of 2 × half, one of the two moved at least half); of equal ones the
// larger IDs, so that the grid does not choose. `vel`: the translations' velocity columns,
// the partners' (ghosts' too) this step's.
Jump largestJump(const Particles& P, const Bonds& B, const std::vector<int>& vel, double h,
                 double half) {
  auto moved = [&](std::size_t i) {
    double m = 0;
    for (int c : vel) m += (P.alter(i)[c] * h) * (P.alter(i)[c] * h);
    return m;
  };
  Jump best;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    const double own = moved(i);
    if (!(own > half * half)) continue;
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      if (!B.alive(b) || B.partner(b) < 0) continue;
      const auto j = static_cast<std::size_t>(B.partner(b));
      double r = 0;
      for (int c : vel)
        r += ((P.alter(i)[c] - P.alter(j)[c]) * h) * ((P.alter(i)[c] - P.alter(j)[c]) * h);
      const double other = moved(j);
      const Gid gi = P.gid(i), gj = B.partnerGid(b);
      const bool first = own > other || (own == other && gi > gj);
      const Jump J{r, first ? own : other, first ? gi : gj, first ? gj : gi};
      if (J.relative > best.relative ||
          (J.relative == best.relative &&
           (J.id > best.id || (J.id == best.id && J.partner > best.partner))))
        best = J;
    }
  }
  return best;
}

// A bond alive whose two particles moved apart (or together) by more than the horizon in
// one step: its length changed by more than its own, which no step that resolves the
// motion makes. Only bonds alive count: the pieces of a broken body fly apart freely, and
// a piece flies whole (however fast) without its bonds changing length. The horizon, not
// the cells (wider on fewer ranks), keeps the verdict the same on any grid. Called after
// the halo exchange, so that the partners' velocities are this step's; collective. Returns
// the particle to name and what it did, or nothing.
std::optional<std::pair<Gid, std::string>> bondJump(const Particles& P, const Bonds& B,
                                                    Model& model, Comm& comm, double h) {
  const double limit = model.horizon(), none = -std::numeric_limits<double>::infinity();
  std::vector<int> vel;
  for (const auto& n : model.motion().velocity) vel.push_back(P.schema().alterIndex(n));
  const Jump j = largestJump(P, B, vel, h, limit / 2);
  const double mine = j.relative >= 0 ? std::sqrt(j.relative) : none;
  const double r = comm.max(mine);
  if (!(r > limit)) return std::nullopt;
  const double id = comm.max(mine == r ? static_cast<double>(j.id) : none);
  const bool it = mine == r && static_cast<double>(j.id) == id;
  const double partner = comm.max(it ? static_cast<double>(j.partner) : none);
  const double own =
      comm.max(it && static_cast<double>(j.partner) == partner ? std::sqrt(j.own) : none);
  std::ostringstream os;
  os << "moved " << own << " in the last step, " << r << " relative to particle "
     << static_cast<Gid>(partner) << ", to which it is still bonded: more than the horizon "
     << limit << ", a bond's length changed by more than its own in one step";
  return std::make_pair(static_cast<Gid>(id), os.str());
}

}  // namespace

Simulation::Simulation(std::unique_ptr<Model> model, ParticleSet particles, RunConfig config,
                       Comm& comm)
    : model_(std::move(model)),
      initial_(std::move(particles)),
      cfg_(std::move(config)),
      comm_(comm),
      particles_(model_->schema()),
      bonds_(model_->schema().nBond()) {}

Simulation::~Simulation() = default;

void Simulation::addOutput(std::unique_ptr<Output> out) {
  if (setUp_) {  // added after setup (a strength trial's): it begins at the current step
    OutputContext oc{*ctx_, *model_, comm_, cfg_.outDir, step_, setupDt_};
    out->begin(oc, resumed_);
  }
  timedOutputs_ |= out->timed();
  outputs_.push_back(std::move(out));
}

Domain Simulation::makeDomain() const {
  const Schema schema = model_->schema();
  if (initial_.nFixed != schema.nFixed() || initial_.nAlter != schema.nAlter())
    throw InputError(cfg_.source, 0, "particle tables do not match the model's attributes");
  if (initial_.size() == 0) throw InputError(cfg_.source, 0, "the problem has no particles");
  std::array<double, 3> mn, mx;
  mn.fill(std::numeric_limits<double>::infinity());
  mx.fill(-std::numeric_limits<double>::infinity());
  for (std::size_t k = 0; k < initial_.size(); ++k)
    for (int a = 0; a < 3; ++a) {
      // Cells hold reference positions unless the model shuffles; take both into account
      // so every particle starts inside the domain.
      mn[a] = std::min({mn[a], initial_.fixedRow(k)[a], initial_.alterRow(k)[a]});
      mx[a] = std::max({mx[a], initial_.fixedRow(k)[a], initial_.alterRow(k)[a]});
    }
  Domain d;
  d.periodic = cfg_.periodic;
  d.dim = cfg_.dim;
  if (d.dim == 0)
    d.dim = mx[2] > mn[2] || cfg_.periodic[2] ? 3 : (mx[1] > mn[1] || cfg_.periodic[1] ? 2 : 1);
  const double margin = cfg_.margin >= 0 ? cfg_.margin : model_->horizon();
  for (int a = 0; a < 3; ++a) {
    if (a >= d.dim) {
      d.periodic[a] = false;
      d.lo[a] = mn[a] - 1;
      d.hi[a] = mx[a] + 1;
    } else if (d.periodic[a]) {
      d.lo[a] = cfg_.boxLo[a];
      d.hi[a] = cfg_.boxHi[a];
      if (!(d.hi[a] > d.lo[a]))
        throw InputError(cfg_.source, 0,
                         std::string("periodic axis ") + "XYZ"[a] + " needs a box with hi > lo");
    } else {
      d.lo[a] = mn[a] - margin;
      d.hi[a] = mx[a] + margin;
      if (!(d.hi[a] > d.lo[a]))
        throw InputError(
            cfg_.source, 0,
            std::string("the domain has no extent along ") + "XYZ"[a] + "; set a positive margin");
    }
  }
  return d;
}

void Simulation::setup() {
  if (setUp_) return;
  timers_.start();
  Timers::Scope t(timers_, Phase::Setup);
  const double horizon = model_->horizon();
  const double minCell = cfg_.minCellSize > 0 ? cfg_.minCellSize : model_->minCellSize();
  if (!(horizon > 0)) throw InputError(cfg_.source, 0, "the model's horizon must be positive");
  if (minCell < horizon) {
    std::ostringstream os;
    os << "minimum cell size " << minCell << " is below the model's horizon " << horizon
       << "; neighbours would be missed";
    throw InputError(cfg_.source, 0, os.str());
  }
  dec_ = std::make_unique<Decomposition>(makeDomain(), minCell, cfg_.procs, comm_.size(),
                                         comm_.rank(), cfg_.source, model_->cellDivisions());
  // Shuffle once some particle may have left the slack of its cells. A model that asks for
  // a skin (cells wider than its horizon) gets the slack of the cells it asks for even in
  // wider ones: shuffles wrap periodic positions, which changes the bits of later pair
  // differences, so their rhythm must not depend on a larger minimum cell size, nor on the
  // larger cells chosen below for balance.
  const double own = model_->minCellSize(), cell = dec_->minActiveCellSize();
  const double slackCell =
      own > horizon ? std::min(cell, Decomposition::minActiveCellSize(dec_->domain(), own)) : cell;
  slack_ = (slackCell - horizon) / 2;
  {
    // Cores of equal particle counts rather than equal cell counts (every rank holds every
    // particle here, so all find the same cells and cuts).
    const Domain& dom = dec_->domain();
    auto layers = [&](int a, int n) {
      std::vector<double> w(n, 0.0);
      for (std::size_t k = 0; k < initial_.size(); ++k) {
        const double* x = model_->shuffles() ? initial_.alterRow(k) : initial_.fixedRow(k);
        const int g = Decomposition::cellAlong(dom, a, n, x[a]);
        w[dom.periodic[a] ? ((g % n) + n) % n : std::clamp(g, 0, n - 1)] += 1;
      }
      return w;
    };
    if (!model_->resultsDependOnCells()) dec_->chooseCells(layers);
    std::array<std::vector<double>, 3> weights;
    for (int a = 0; a < dec_->dim(); ++a) weights[a] = layers(a, dec_->globalCells(a));
    dec_->balance(weights);
  }
  cube_ = std::make_unique<ProcCube>(*dec_, comm_, particles_, bonds_, model_->shuffles());
  cube_->distribute(initial_.gid, initial_.fixed, initial_.alter);
  initial_ = ParticleSet{};  // the global tables are no longer needed
  cube_->rebuild(cfg_.firstStep);
  ctx_ = std::make_unique<Context>(particles_, bonds_, *cube_, comm_, debug_);
  ctx_->setListRadius(slackCell);
  integrator_ = std::make_unique<Integrator>(*model_);
  {
    const Motion m = model_->motion();
    const Schema& s = particles_.schema();
    for (const auto* names : {&m.force, &m.moment})
      for (const auto& n : *names)
        if (s.integIndex(n) >= 0) forceColumns_.push_back(s.integIndex(n));
  }
  ctx_->setIntegrator(integrator_.get());
  ctx_->setLoading(cfg_.loading);
  step_ = cfg_.firstStep;
  checkedStep_ = step_;
  ctx_->setStep(step_);
  ctx_->setSteps(cfg_.steps);
  try {
    model_->setup(*ctx_);
  } catch (const InputError& e) {
    // A model's set-up judges the particles: an error tied to no line of its own is one of
    // the line that gave them.
    if (e.line() > 0) throw;
    throw InputError(cfg_.source, cfg_.particlesLine, e.problem());
  }
  setupDt_ = ctx_->dt();
  resumed_ = restart_.has_value();
  if (restart_) {
    // A restart brings its bonds: the saved list replaces what setup built from the
    // (possibly moved) particles, so nothing is lost or added on the way.
    bonds_.discardPending();
    std::map<Gid, std::size_t> local;
    for (std::size_t i = 0; i < particles_.owned(); ++i) local[particles_.gid(i)] = i;
    for (std::size_t k = 0; k < restart_->owner.size(); ++k) {
      auto it = local.find(restart_->owner[k]);
      if (it != local.end()) bonds_.add(it->second, restart_->partner[k]);
    }
  }
  bonds_.finish(particles_.owned());
  if (restart_) {
    const RestartState& s = *restart_;
    const int nB = bonds_.nAttr();
    std::map<std::pair<Gid, Gid>, std::size_t> where;
    for (std::size_t k = 0; k < s.owner.size(); ++k) where[{s.owner[k], s.partner[k]}] = k;
    for (std::size_t i = 0; i < particles_.owned(); ++i)
      for (std::size_t b = bonds_.begin(i); b < bonds_.end(i); ++b) {
        const std::size_t k = where.at({particles_.gid(i), bonds_.partnerGid(b)});
        std::copy_n(&s.attrs[k * nB], nB, bonds_.attr(b));
        if (s.dead[k]) bonds_.kill(b);
      }
  }
  cube_->remapBonds(step_);  // after restored dead flags: a dead bond's partner may be gone
  model_->prepare(*ctx_);
  if (restart_ && restart_->hasState) {
    // The run continues with the time step it had (a model may derive it from the current,
    // damaged, state) and what the integrator and the model kept.
    // Forced on with another time step (`adoptDt`): the model's new one.
    if (!restart_->adoptDt || restart_->setupDt == setupDt_) ctx_->setDt(restart_->dt);
    integrator_->setState(restart_->integrator);
    model_->loadState(restart_->model);
    restoreChecks(restart_->checks);
  }
  restart_.reset();
  cube_->halo();  // setup and prepare may have changed alterable attributes
  if (!(ctx_->dt() > 0)) throw InputError(cfg_.source, 0, "the model set no positive time step");
  if (cfg_.solver.quasiStatic) {
    if (model_->shuffles())
      throw InputError(cfg_.source, cfg_.solver.line,
                       "the quasi-static solver needs a model whose particles keep their "
                       "neighbours; this model's particles move between cells");
    if (cfg_.steps > cfg_.solver.loadSteps)
      throw InputError(cfg_.source, cfg_.solver.line,
                       "the run asks for " + std::to_string(cfg_.steps) +
                           " steps but the quasi-static solver has " +
                           std::to_string(cfg_.solver.loadSteps) + " load steps");
    // The run ends when the load path reaches load_scale (with cut-backs that may take more
    // load steps than load_steps), or after a fewer number of steps asked for.
    const Integrator::LoadPath& path = integrator_->loadPath();
    const double full = static_cast<double>(cfg_.solver.loadSteps);
    if (path.progress >= full)
      cfg_.steps = step_;
    else if (cfg_.steps < 0 || cfg_.steps == cfg_.solver.loadSteps)
      cfg_.steps = std::numeric_limits<long>::max();
    ctx_->setSteps(cfg_.steps);
    ctx_->setStaticFactor(staticFactor(path.progress));
    last_.fraction = path.progress / full;
    last_.factor = staticFactor(path.progress);
    {
      const StrengthSpec spec = model_->strengthSpec();
      const auto names = model_->globals();
      const auto at = std::find(names.begin(), names.end(), spec.damage);
      brokenGlobal_ =
          spec.damage.empty() || at == names.end() ? -1 : static_cast<int>(at - names.begin());
    }
  } else if (cfg_.steps < 0) {
    // The run lasts the load protocol's ramp and hold (a duration within round-off of a
    // whole number of steps takes that number).
    const Loading& L = cfg_.loading;
    cfg_.steps =
        std::max(0L, static_cast<long>(std::ceil((L.rampTime + L.holdTime) / ctx_->dt() - 1e-9)));
    ctx_->setSteps(cfg_.steps);
  }
  debug_ << "rank " << comm_.rank() << ": core cells [" << dec_->coreLo(0) << "," << dec_->coreHi(0)
         << ")x[" << dec_->coreLo(1) << "," << dec_->coreHi(1) << ")x[" << dec_->coreLo(2) << ","
         << dec_->coreHi(2) << "), " << particles_.owned() << " owned, " << particles_.ghosts()
         << " ghosts, " << bonds_.count() << " bonds\n";
  createFolder(cfg_.outDir);
  // What a run killed while writing left behind.
  if (comm_.root())
    for (const auto& name : removeStrayTemporaries(cfg_.outDir))
      debug_ << "removed " << name << ", left by a run killed while writing it\n";
  setUp_ = true;
  if (cfg_.solver.quasiStatic && resumed_ && comm_.root()) {
    // A restarted run continues the curve: the rows up to its restart step.
    std::ifstream in(cfg_.outDir + "/quasi_static.csv");
    std::string line;
    for (bool header = true; std::getline(in, line); header = false)
      if (header || std::atol(line.c_str()) <= step_) loadSteps_ += line + "\n";
  }
  if (!outputs_.empty()) {
    // Files that grow during the run: a resumed run continues them.
    if (comm_.root()) {
      const std::string timing = cfg_.outDir + "/timing.out";
      if (resumed_ && std::filesystem::exists(timing)) {
        std::ifstream in(timing, std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        timingBefore_ = ss.str() + "\n";
      }
      const std::string debug = cfg_.outDir + "/debug.txt";
      if (!resumed_) writeFileAtomically(debug, "");
      debugFile_.open(debug);
      if (resumed_) debugFile_.write("# restarted at step " + std::to_string(step_) + "\n");
    }
    OutputContext oc{*ctx_, *model_, comm_, cfg_.outDir, step_, setupDt_};
    for (auto& o : outputs_) o->begin(oc, resumed_);
  }
  writeOutputs(false);
}

double Simulation::staticFactor(double progress) const {
  return cfg_.loading.scale * progress / static_cast<double>(cfg_.solver.loadSteps);
}

long Simulation::brokenInteractions() {
  if (brokenGlobal_ >= 0)
    return std::lround(model_->globalValues(*ctx_)[static_cast<std::size_t>(brokenGlobal_)]);
  // A dead bond is listed by both its particles.
  long dead = 0;
  for (std::size_t b = 0; b < bonds_.count(); ++b) dead += !bonds_.alive(b);
  return comm_.sum(dead) / 2;
}

// Quasi-static: the run ends at the last equilibrium (load factor `previous`), none found at
// `beyond` for the reason `what`.
void Simulation::stopBelow(double previous, double beyond, const std::string& what) {
  last_.beyond = beyond;
  ctx_->setStaticFactor(previous);
  {
    Timers::Scope t(timers_, Phase::Force);
    model_->force(*ctx_);  // the last equilibrium's forces again (its damage is committed)
  }
  std::ostringstream reason;
  reason << "no equilibrium beyond load factor " << previous << ": " << what << ". "
         << (cfg_.solver.control.active()
                 ? "The displacement control cannot follow the curve here (a snap-back: "
                   "the load-displacement curve turns back) or the structure became a "
                   "mechanism"
                 : "The structure has passed its peak load (a limit point under force "
                   "control; displacement control follows the descending branch) or became "
                   "a mechanism")
         << "; or max_iterations is too small";
  ctx_->requestStop(reason.str());
}

// Quasi-static: step k relaxes the next load step to equilibrium, trying again with half
// the increment when it does not converge or breaks more than max_broken interactions;
// logs its iterations and residual and adds its row to quasi_static.csv. When even the
// smallest increment finds no equilibrium, the run ends at the last one (a limit point:
// the peak under force control, a snap-back under displacement control, or a mechanism).
bool Simulation::relaxLoadStep() {
  ++step_;
  ctx_->setStep(step_);
  auto forces = [&] {
    Timers::Scope t(timers_, Phase::Force);
    model_->force(*ctx_);
  };
  auto exchange = [&] {
    Timers::Scope t(timers_, Phase::Communication);
    cube_->halo();
  };
  const Solver& solver = cfg_.solver;
  Integrator::LoadPath& path = integrator_->loadPath();
  const double full = static_cast<double>(solver.loadSteps);
  const double previous = staticFactor(path.progress);
  // The last equilibrium, to try again from.
  const std::size_t width = static_cast<std::size_t>(particles_.schema().nAlter());
  const std::vector<double> positions(particles_.alter(0),
                                      particles_.alter(0) + particles_.local() * width);
  Bonds::Saved bonds;
  bonds_.save(bonds);
  const long brokenBefore = brokenInteractions();
  Integrator::Relaxed r;
  double factor = previous;
  long broken = brokenBefore;
  const double smallest = std::ldexp(1.0, -solver.maxCutBacks);
  for (int cuts = 0;; ++cuts) {  // cuts: cut-backs of this load step
    if (path.beyond > 0 && previous > 0 &&
        staticFactor(path.beyond) - previous <= solver.peakTolerance * previous) {
      std::ostringstream what;
      what << "load factor " << staticFactor(path.beyond)
           << " had no equilibrium near an earlier one, within peak_tolerance ("
           << solver.peakTolerance << ") of the last equilibrium";
      stopBelow(previous, staticFactor(path.beyond), what.str());
      return endStep(false);
    }
    double increment = std::min(path.increment, full - path.progress);
    // A load found to have no equilibrium near the last one is not tried again: the
    // increment is halved until the load step stays below it.
    while (path.beyond > 0 && path.progress + increment >= path.beyond && increment > smallest)
      increment /= 2, path.increment = increment, path.easy = 0;
    if (path.beyond > 0 && path.progress + increment >= path.beyond) {
      stopBelow(previous, staticFactor(path.beyond),
                "load factor " + numberText(staticFactor(path.beyond)) +
                    " had no equilibrium near an earlier one, and the smallest increment (2^-" +
                    std::to_string(solver.maxCutBacks) + " of the largest) reaches it");
      return endStep(false);
    }
    factor = staticFactor(path.progress + increment);
    ctx_->setStaticFactor(factor);
    {
      Timers::Scope t(timers_, Phase::Integrate);  // less the forces and halos it times
      r = integrator_->relax(*ctx_, solver, cfg_.source, factor, previous, forces, exchange);
    }
    broken = brokenInteractions();
    const bool tooMany = solver.maxBroken > 0 && broken - brokenBefore > solver.maxBroken;
    if (r.converged && !tooMany) {
      if (path.progress == 0) path.first = static_cast<double>(r.iterations);
      path.progress += increment;
      // Nearing a peak: a load step over kSoftening times as compliant as the secant halves
      // the next increment, down to the bracket the run ends at (peak_tolerance of the load
      // factor; 2^-kSofteningCuts of the largest increment when there is none), so that the
      // try beyond the peak is a short one (docs/quasi-static.md, "Nearing the peak").
      const double floor = solver.peakTolerance > 0
                               ? solver.peakTolerance * factor
                               : staticFactor(std::ldexp(1.0, -kSofteningCuts));
      if (r.softening > kSoftening && staticFactor(path.increment) >= floor &&
          path.increment / 2 >= smallest)
        path.increment /= 2, path.easy = 0;
      else if (cuts == 0 && ++path.easy >= 2 && path.increment < 1)
        path.increment = std::min(1.0, 2 * path.increment), path.easy = 0;
      break;
    }
    const double relative = r.reference > 0 ? r.residual / r.reference : 0.0;
    std::ostringstream what;
    what << "load step " << step_ << " (load factor " << factor << ") ";
    if (r.converged)
      what << "broke " << broken - brokenBefore << " interactions, more than max_broken "
           << solver.maxBroken;
    else if (r.runaway)
      what << "has no equilibrium near the last: after " << r.iterations
           << " iterations the structure had moved along the loads over ten times as "
              "far as at the last equilibrium, or snapped through to an equilibrium over ten "
              "times as compliant";
    else
      what << "did not converge in " << integrator_->iterationCap(solver)
           << " iterations: the out-of-balance force is still " << relative
           << " of the applied load (tolerance " << solver.tolerance << ")";
    if (abandoned_) {
      exchange();
      abandoned_();
    }
    std::copy(positions.begin(), positions.end(), particles_.alter(0));
    bonds_.restore(bonds);
    if (r.runaway && !solver.control.active() &&
        (path.beyond == 0 || path.progress + increment < path.beyond))
      path.beyond = path.progress + increment;
    // Increments never fall below 2^-max_cut_backs of the largest, so the run cannot creep.
    if (increment > smallest) {
      path.increment = increment / 2, path.easy = 0;
      if (comm_.root()) ctx_->log() << what.str() << "; the increment halved\n";
      continue;
    }
    // No equilibrium even with the smallest increment. Before any has been found and with
    // nothing broken, the input is at fault (too few iterations, or nothing holds the
    // structure); otherwise the run ends at its last equilibrium.
    what << ", even with the smallest increment (2^-" << solver.maxCutBacks << " of the largest)";
    if (path.progress == 0 && broken == brokenBefore)
      throw InputError(cfg_.source, solver.line,
                       what.str() +
                           "; raise max_iterations or use more load_steps (or the "
                           "structure is a mechanism: check its supports)");
    stopBelow(previous, factor, what.str());
    return endStep(false);
  }
  const double relative = r.reference > 0 ? r.residual / r.reference : 0.0;
  last_ = {path.progress / full, factor, r.load, r.displacement, relative, r.iterations, broken};
  if (comm_.root()) {
    ctx_->log() << "load step " << step_ << ": load factor " << factor << ", " << r.iterations
                << " iterations";
    if (r.momentumFrom >= 0) ctx_->log() << " (momentum from iteration " << r.momentumFrom << ")";
    ctx_->log() << ", residual " << r.residual << " (" << relative << " of the applied load), "
                << broken << " broken interactions\n";
    if (loadSteps_.empty())
      loadSteps_ =
          "load_step,load_factor,iterations,residual,reference,relative,load,displacement,"
          "broken\n";
    std::ostringstream row;
    row << step_ << "," << numberText(factor) << "," << r.iterations << ","
        << numberText(r.residual) << "," << numberText(r.reference) << "," << numberText(relative)
        << "," << numberText(r.load) << "," << numberText(r.displacement) << "," << broken << "\n";
    loadSteps_ += row.str();
    writeFileAtomically(cfg_.outDir + "/quasi_static.csv", loadSteps_);
  }
  if (path.progress >= full) {
    if (raise_ && raise_()) {
      // The same load factors, each load step's share of twice the load halved.
      cfg_.loading.scale *= 2;
      path.progress /= 2;
      if (comm_.root())
        ctx_->log() << "load path raised after load step " << step_ << ": towards "
                    << staticFactor(full) << "\n";
    } else {
      cfg_.steps = step_;
      ctx_->setSteps(step_);
    }
  }
  // A stop asked for from outside ends the run at this load step, and a timed output
  // (checkpoints every T minutes) is written at it, as at a time step: the ranks agree in
  // one reduction.
  bool asked = false;
  for (const auto& o : outputs_)
    if (o->timed()) asked |= o->requested();
  std::vector<double> probe{stopCheck_ && step_ < cfg_.steps ? stopCheck_() : 0.0,
                            asked ? 1.0 : 0.0};
  if (stopCheck_ || timedOutputs_) probe = comm_.max(probe);
  stopCode_ = static_cast<int>(probe[0]);
  requestedNow_ = probe[1] > 0;
  const bool interrupted = stopCode_ > 0;
  return endStep(interrupted);
}

bool Simulation::advance() {
  if (!setUp_) setup();
  if (ended_ || step_ >= cfg_.steps) return false;
  if (cfg_.solver.quasiStatic) return relaxLoadStep();
  ++step_;
  ctx_->setStep(step_);
  {
    Timers::Scope t(timers_, Phase::Force);
    model_->force(*ctx_);
  }
  bool saving = false, asked = false;  // restart files are due at this step
  for (const auto& o : outputs_)
    saving |= o->capturesState() && (o->due(step_) || (step_ == cfg_.steps && o->atEnd()));
  // Instability is looked for before anything is saved, so no restart file holds it. The
  // integrator gathers what the checks need as it moves each particle.
  const bool checkMoves = cfg_.checkEvery > 0 && step_ % cfg_.checkEvery == 0;
  const bool check = checkMoves || saving;
  Integrator::Watch watch;
  if (check) {
    watch.tracked = step_ - checkedStep_ == 1 ? tracked_ : kNone;
    integrator_->watchNextStep(&watch);
  }
  {
    Timers::Scope t(timers_, Phase::Integrate);
    model_->integrate(*ctx_);
    integrator_->watchNextStep(nullptr);
    if (check && !watch.done) integrator_->see(*ctx_, watch);  // the model's own integration
  }
  for (const auto& o : outputs_)
    if (o->timed()) asked |= o->requested();
  if (checkMoves) takeMoves(watch);
  // One reduction a step, when anything needs one: a stop asked for from outside, how far
  // particles moved since the last shuffle, the first unstable particle, a timed output
  // asked for and the largest distance moved in the step.
  const double none = -std::numeric_limits<double>::infinity();
  std::vector<double> probe{stopCheck_ ? static_cast<double>(stopCheck_()) : 0.0,
                            model_->shuffles() ? cube_->maxDisplacementSinceRebuild() : 0.0,
                            check && watch.nonFinite ? firstUnstable() : none,
                            asked ? 1.0 : 0.0,
                            checkMoves ? localMove_ : 0.0,
                            checkMoves && bounced_ ? 1.0 : 0.0};
  if (stopCheck_ || model_->shuffles() || check || timedOutputs_) probe = comm_.max(probe);
  requestedNow_ = probe[3] > 0;
  // A state saved on time is checked too (in a second reduction: checks were not due).
  if (requestedNow_ && !check) probe[2] = comm_.max(firstUnstable());
  if (probe[2] > none) reportInstability(static_cast<Gid>(-probe[2]), "");
  saving |= requestedNow_;
  if (model_->shuffles() && slack_ > 0 && probe[1] > 2 * slack_) {
    // Pairs may have come within the horizon unseen: the step was too violent.
    std::size_t i = 0;
    const double d = cube_->maxDisplacementSinceRebuild(&i);
    const double far = d == probe[1] ? static_cast<double>(particles_.gid(i)) : none;
    std::ostringstream os;
    os << "moved " << probe[1] << " since the last shuffle, more than the skin " << 2 * slack_
       << " (cell size minus horizon), so neighbours may have been missed";
    reportInstability(static_cast<Gid>(comm_.max(far)), os.str());
  }
  if (checkMoves) checkMotion(probe[4], probe[5] > 0);
  // The last step ends the run anyway, with its own outputs.
  stopCode_ = step_ < cfg_.steps ? static_cast<int>(probe[0]) : 0;
  const bool interrupted = stopCode_ > 0;
  bool shuffleNow = false;
  if (model_->shuffles())
    // Shuffle once some particle may have moved far enough to change neighbours, and at
    // steps whose state is saved for a restart, so that a restarted run starts from the
    // same cells (and periodic wraps) as the original and continues bit for bit.
    shuffleNow = probe[1] > slack_ || saving || interrupted;
  if (shuffleNow) {
    Timers::Scope t(timers_, Phase::Shuffle);
    // The particles change order (and ranks): the particle the growth check follows is
    // found again by its ID, so that its verdict does not depend on how often a run
    // shuffles (restart files force a shuffle).
    const std::vector<double> checks = checkMoves ? checkState() : std::vector<double>{};
    cube_->shuffle(step_);
    integrator_->particlesMoved();
    model_->neighboursChanged(*ctx_);
    tracked_ = kNone;
    restoreChecks(checks);
    stats_.shuffles++;
    stats_.maxShuffleMessages = std::max(stats_.maxShuffleMessages, cube_->stats().shuffleMessages);
  } else {
    Timers::Scope t(timers_, Phase::Communication);
    cube_->halo();
    stats_.haloMessages = cube_->stats().haloMessages;
    stats_.haloBytes = cube_->stats().haloBytes;
    stats_.haloWallParticles = cube_->stats().haloWallParticles;
  }
  if (checkMoves && probe[4] > model_->horizon() / 2) {
    // The ghosts' velocities are this step's only if the halo sent them.
    if (particles_.schema().nHalo() < particles_.schema().nAlter()) {
      Timers::Scope t(timers_, Phase::Communication);
      cube_->halo(true);
    }
    if (const auto jump = bondJump(particles_, bonds_, *model_, comm_, ctx_->dt()))
      reportInstability(jump->first, jump->second);
  }
  return endStep(interrupted);
}

// The end of a step (or load step): a stop the model asked for or one from outside, and the
// outputs due.
bool Simulation::endStep(bool interrupted) {
  const bool stop = !ctx_->stopReason().empty();
  if (stop) {
    ended_ = true;
    debug_ << "stopped at step " << step_ << ": " << ctx_->stopReason() << "\n";
  }
  if (interrupted) {
    ended_ = true;
    debug_ << "stopped early at step " << step_ << " (stop code " << stopCode_
           << "); a checkpoint written\n";
  }
  writeOutputs(stop || step_ == cfg_.steps, interrupted);
  return !ended_ && step_ < cfg_.steps;
}

void Simulation::run() {
  setup();
  while (advance()) {
  }
  finish();
}

double Simulation::firstUnstable() const {
  // Owned particles are not in ID order: the smallest ID is reported.
  double first = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < particles_.owned(); ++i)
    if (integrator_->notFinite(particles_, i))
      first = std::max(first, -static_cast<double>(particles_.gid(i)));
  return first;
}

void Simulation::takeMoves(const Integrator::Watch& w) {
  movedMost_ = w.fastest;
  mostStep_ = w.fastestStep;
  localMost_ = w.most;
  localMove_ = std::sqrt(w.most);
  bounced_ = false;
  if (w.sawTracked) {
    const auto& s = w.trackedStep;
    const double back = s[0] * trackedStep_[0] + s[1] * trackedStep_[1] + s[2] * trackedStep_[2];
    const double d = s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
    bounced_ = back < 0 && d >= kGrowth * kGrowth * trackedMove_;
  }
  checkedStep_ = step_;
}

std::vector<double> Simulation::checkState() {
  // The particle followed, from its owner (-1: none).
  const double none = -std::numeric_limits<double>::infinity();
  const bool mine = tracked_ != kNone;
  std::vector<double> t{mine ? static_cast<double>(particles_.gid(tracked_)) : none,
                        mine ? trackedStep_[0] : none, mine ? trackedStep_[1] : none,
                        mine ? trackedStep_[2] : none, mine ? trackedMove_ : none};
  t = comm_.max(t);
  if (t[0] == none) t = {-1, 0, 0, 0, 0};
  return {static_cast<double>(growing_),
          growthFrom_,
          lastMove_,
          static_cast<double>(checkedStep_),
          t[0],
          t[1],
          t[2],
          t[3],
          t[4]};
}

void Simulation::restoreChecks(const std::vector<double>& saved) {
  if (saved.empty()) return;  // a restart file written before the checks' state was saved
  growing_ = static_cast<int>(saved[0]);
  growthFrom_ = saved[1];
  lastMove_ = saved[2];
  checkedStep_ = static_cast<long>(saved[3]);
  tracked_ = kNone;
  for (std::size_t i = 0; i < particles_.owned(); ++i)
    if (saved[4] >= 0 && static_cast<double>(particles_.gid(i)) == saved[4]) tracked_ = i;
  trackedStep_ = {saved[5], saved[6], saved[7]};
  trackedMove_ = saved[8];
}

void Simulation::checkMotion(double move, bool bounced) {
  const double none = -std::numeric_limits<double>::infinity();
  const bool mine = movedMost_ != kNone && localMove_ == move;
  auto mover = [&] {
    return static_cast<Gid>(
        comm_.max(mine ? static_cast<double>(particles_.gid(movedMost_)) : none));
  };
  // A time step above the stable one shows in the fastest particle: the highest mode's
  // amplitude multiplies each step and, its frequency being above the step's Nyquist
  // limit, the particle goes back and forth from step to step. Physical motion, resolved
  // by many steps, keeps its direction from one step to the next (a load ramp, a released
  // bond, free flight), and an oscillation near the limit does not grow.
  if (bounced) {
    if (growing_++ == 0) growthFrom_ = lastMove_;
  } else {
    growing_ = 0;
  }
  lastMove_ = move;
  // Follow the fastest particle to the next step (on the rank that owns it).
  tracked_ = mine && move > 0 ? movedMost_ : kNone;
  trackedStep_ = mostStep_;
  trackedMove_ = localMost_;
  if (growing_ >= kGrowthSteps) {
    std::ostringstream os;
    os << "moved " << move << " in the last step: the fastest particle has gone back and forth "
       << "at every step since step " << step_ - growing_ << ", each move at least " << kGrowth
       << " times the one before (from " << growthFrom_ << "), so the motion grows without bound";
    reportInstability(mover(), os.str());
  }
}

void Simulation::reportInstability(Gid id, const std::string& what) {
  // The owner describes the particle; every rank throws the same message.
  std::string mine;
  for (std::size_t i = 0; i < particles_.owned(); ++i) {
    if (particles_.gid(i) != id) continue;
    const Schema& s = particles_.schema();
    std::ostringstream os;
    os << std::setprecision(9) << "particle " << id << " at (" << particles_.alter(i)[0] << ", "
       << particles_.alter(i)[1] << ", " << particles_.alter(i)[2] << ")";
    if (what.empty()) {
      std::string bad;
      for (int k = 0; k < s.nAlter(); ++k)
        if (!std::isfinite(particles_.alter(i)[k])) bad += " " + s.alter[k];
      for (int k : forceColumns_)
        if (!std::isfinite(particles_.integ(i)[k])) bad += " " + s.integ[k];
      os << " has non-finite" << bad;
    } else {
      os << " " << what;
    }
    mine = os.str();
  }
  auto blocks = comm_.gather(std::vector<char>(mine.begin(), mine.end()));
  std::vector<char> all;
  for (auto& b : blocks) all.insert(all.end(), b.begin(), b.end());
  all = comm_.broadcast(all);
  std::ostringstream os;
  os << "step " << step_ << ": " << std::string(all.begin(), all.end())
     << "; the run is unstable: lower the time step (dt = " << ctx_->dt();
  if (ctx_->stableDt() > 0) os << "; the model's stable step is " << ctx_->stableDt();
  os << ") or check the loads, supports and material parameters; checkpoints and restart "
        "files written before this step hold finite states";
  throw RunError(os.str());
}

void Simulation::writeOutputs(bool last, bool stopped) {
  Timers::Scope t(timers_, Phase::Output);
  OutputContext oc{*ctx_, *model_, comm_, cfg_.outDir, step_, setupDt_};
  auto due = [&](const Output& o) {
    return o.due(step_) || (last && o.atEnd()) || (stopped && o.writtenOnStop()) ||
           (requestedNow_ && o.timed());
  };
  bool saved = false;
  for (auto& o : outputs_) saved |= o->capturesState() && due(*o);
  if (saved) oc.checks = checkState();
  for (auto& o : outputs_)
    if (due(*o)) o->write(oc);
  // debug.txt and timing.out are brought up to date with each restart state.
  if (saved) writeLogs();
}

void Simulation::finish() {
  if (!setUp_) return;
  {
    Timers::Scope t(timers_, Phase::Output);
    OutputContext oc{*ctx_, *model_, comm_, cfg_.outDir, step_, setupDt_};
    for (auto& o : outputs_) o->finish(oc);
  }
  writeLogs();
}

void Simulation::writeLogs() {
  timers_.settleOther();
  std::ostringstream os;
  os << "# pdq timing: wall-clock seconds per phase over " << comm_.size() << " rank(s), "
     << step_ - cfg_.firstStep << " steps (" << cfg_.firstStep << " to " << step_ << ")\n";
  os << std::left << std::setw(16) << "# phase" << std::right << std::setw(14) << "min"
     << std::setw(14) << "mean" << std::setw(14) << "max\n";
  double total = 0;
  for (int p = 0; p < static_cast<int>(Phase::Count); ++p) total += timers_[static_cast<Phase>(p)];
  for (int p = 0; p <= static_cast<int>(Phase::Count); ++p) {
    const bool isTotal = p == static_cast<int>(Phase::Count);
    const double v = isTotal ? total : timers_[static_cast<Phase>(p)];
    const double mn = comm_.min(v), mx = comm_.max(v);
    ExactSum acc;
    acc.add(v);
    const double mean = comm_.sum(acc) / comm_.size();
    os << std::left << std::setw(16) << (isTotal ? "total" : phaseName(static_cast<Phase>(p)))
       << std::right << std::fixed << std::setprecision(6) << std::setw(14) << mn << std::setw(14)
       << mean << std::setw(14) << mx << "\n";
  }
  os << "# halo per step on rank 0: " << stats_.haloMessages << " messages, " << stats_.haloBytes
     << " bytes (" << stats_.haloWallParticles << " wall particles x " << cube_->haloRecordBytes()
     << " bytes)\n";
  if (stats_.shuffles)
    os << "# shuffles: " << stats_.shuffles << ", at most " << stats_.maxShuffleMessages
       << " messages each on rank 0\n";
  // debug.txt: every rank's lines since the last write, in rank order.
  const std::string text = debug_.str().substr(debugWritten_);
  debugWritten_ += text.size();
  auto blocks = comm_.gather(std::vector<char>(text.begin(), text.end()));
  if (comm_.root()) {
    writeFileAtomically(cfg_.outDir + "/timing.out", timingBefore_ + os.str());
    std::string dbg;
    for (auto& b : blocks) dbg.append(b.begin(), b.end());
    if (!debugFile_.isOpen()) {
      writeFileAtomically(cfg_.outDir + "/debug.txt", "");
      debugFile_.open(cfg_.outDir + "/debug.txt");
    }
    if (!dbg.empty()) debugFile_.write(dbg);
  }
}

}  // namespace pdq
