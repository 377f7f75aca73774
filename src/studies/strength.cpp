#include "studies/strength.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <type_traits>

#include "engine/error.hpp"
#include "engine/model.hpp"
#include "io/standard_outputs.hpp"

namespace pdq::strength {
namespace {

// How a trial loads the structure: its peak (× the problem's loads), the ramp to it (in
// simulated time, and the steps it takes), the run in steps, and the hold-phase damping.
struct Loading {
  double scale = 1, rampTime = 0;
  long rampSteps = 0, steps = 0;
  double holdDamping = 0;
};

// The one place that turns a Loading into the run's load protocol and length.
void applyLoading(const Loading& l, RunConfig& run) {
  run.loading.scale = l.scale;
  run.loading.rampTime = l.rampTime;
  run.loading.holdDampingRatio = l.holdDamping;
  run.steps = l.steps;
}

std::unique_ptr<Simulation> simulation(const Case& c, const Params& params, RunConfig run,
                                       Comm& comm) {
  run.procs = {0, 0, 0};  // a trial runs on a group of ranks of its own
  auto sim = makeSimulation(makeProblem(c.model, params, c.particles, run), comm);
  sim->setup();
  return sim;
}

// The trials' ramp and run length in steps (the same for every load): the problem's ramp
// and its hold stretched by holdLength, over timeScale × its simulated time, at its own
// time step or (stableStep) the model's stable one, read once from the model set up.
Loading schedule(const Case& c, Comm& comm, const Options& opt) {
  Params p = c.params;
  const double dt0 = p.number("dt", 0.0);
  if (opt.stableStep) p.set("dt", "0");
  double dt = p.number("dt", 0.0);
  if (!(dt > 0)) {
    RunConfig run = c.run;
    run.steps = 1;
    run.outDir = ".";
    dt = simulation(c, p, run, comm)->context().dt();
  }
  const pdq::Loading& pl = c.run.loading;
  // The problem's simulated time: its steps at its own time step, or its ramp and hold.
  const double duration = opt.timeScale * (c.run.steps >= 0 ? c.run.steps * (dt0 > 0 ? dt0 : dt)
                                                            : pl.rampTime + pl.holdTime);
  const long steps = static_cast<long>(std::ceil(duration / dt - 1e-9));
  Loading l;
  l.rampTime = opt.timeScale * pl.rampTime;
  l.rampSteps = static_cast<long>(std::ceil(l.rampTime / dt - 1e-9));
  l.steps = l.rampSteps + static_cast<long>(std::ceil(opt.holdLength * (steps - l.rampSteps)));
  l.holdDamping = opt.holdDamping;
  return l;
}

std::string trialDir(const Options& opt, int index) {
  if (opt.outDir.empty()) return "";
  char name[32];
  std::snprintf(name, sizeof name, "/trial_%02d", index);
  return opt.outDir + name;
}

// The position of each named global among the model's (InputError if it has none such).
std::vector<std::size_t> positions(const Case& c, const std::vector<std::string>& globals,
                                   const std::vector<std::string>& wanted) {
  std::vector<std::size_t> out;
  for (const std::string& w : wanted) {
    const auto it = std::find(globals.begin(), globals.end(), w);
    if (it == globals.end())
      throw InputError(
          c.source, 0,
          "model " + c.model + " names '" + w + "' in its strength spec, but has no such global");
    out.push_back(static_cast<std::size_t>(it - globals.begin()));
  }
  return out;
}

Trial runTrial(const Case& c, Loading l, double load, int index, Comm& comm, const Options& opt) {
  Trial tr;
  tr.index = index;
  tr.load = load;
  tr.dir = trialDir(opt, index);
  l.scale = load / c.unitLoad;
  Params p = c.params;
  RunConfig run = c.run;
  run.outDir = tr.dir.empty() ? "." : tr.dir;
  if (opt.stableStep) p.set("dt", "0");
  applyLoading(l, run);
  auto simPtr = simulation(c, p, run, comm);
  Simulation& sim = *simPtr;
  const StrengthSpec spec = sim.model().strengthSpec();
  if (spec.load.empty() || spec.displacement.empty() || !spec.failureMode)
    throw InputError(c.source, 0, "model " + c.model + " declares no strength spec");
  const auto names = sim.model().globals();
  const std::size_t loadAt = positions(c, names, {spec.load})[0];
  const std::size_t damageAt = positions(c, names, {spec.damage})[0];
  const auto uAt = positions(c, names, spec.displacement);
  auto displacement = [&](const std::vector<double>& v) {
    double u = std::fabs(v[uAt[0]]);
    for (std::size_t k = 1; k < uAt.size(); ++k) u = std::hypot(u, v[uAt[k]]);
    return u;
  };
  if (!tr.dir.empty()) {
    OutputSettings out;  // the load–displacement history and the state at the end
    out.globalsEvery = std::max(1L, l.steps / 400);
    addStandardOutputs(sim, out);
  }
  const long holdStart = l.rampSteps, mid = holdStart + (l.steps - holdStart) / 2;
  const long check = std::max(1L, l.steps / 100);
  bool runaway = false;
  while (sim.advance()) {
    const long step = sim.step();
    if (step != holdStart && step != mid && step % check != 0) continue;
    const auto values = sim.model().globalValues(sim.context());
    const double u = displacement(values);
    if (!std::isfinite(u)) {
      runaway = true;
      break;
    }
    if (step == holdStart) tr.uHold = u;
    if (step == mid) {
      tr.uMid = u;
      tr.brokenMid = values[damageAt];
    }
    if (step >= holdStart && tr.uHold > 0 && u > opt.runaway * tr.uHold) {
      runaway = true;
      break;
    }
  }
  tr.steps = sim.step();
  const auto values = sim.model().globalValues(sim.context());
  // At the end of the hold the model must be applying the trial's peak.
  if (tr.steps == l.steps && !(std::fabs(values[loadAt] - l.scale) <= 1e-12 * std::fabs(l.scale)))
    throw InputError(c.source, 0,
                     "model " + c.model + "'s global '" + spec.load + "' is " +
                         numberText(values[loadAt]) + " at the end of a trial at load_scale " +
                         numberText(l.scale) + ": it does not follow the trial's loading");
  tr.uEnd = displacement(values);
  tr.brokenEnd = values[damageAt];
  tr.holds = !runaway && std::isfinite(tr.uEnd) &&
             tr.brokenEnd - tr.brokenMid <= opt.lateBreaks * tr.brokenEnd + 1 &&
             std::fabs(tr.uEnd - tr.uMid) <= opt.settle * std::fabs(tr.uMid);
  tr.mode = spec.failureMode(sim.context());
  if (!tr.dir.empty()) sim.finish();
  return tr;
}

// A trial travels between groups of ranks as its numbers, bit for bit, then its failure mode.
struct Numbers {
  double load, uHold, uMid, uEnd, brokenMid, brokenEnd;
  long steps;
  int index, holds;
  std::size_t modeLength;
};
static_assert(std::is_trivially_copyable_v<Numbers>);

void pack(const Trial& t, std::vector<char>& out) {
  const Numbers n{t.load,      t.uHold, t.uMid,  t.uEnd,          t.brokenMid,
                  t.brokenEnd, t.steps, t.index, t.holds ? 1 : 0, t.mode.size()};
  const char* p = reinterpret_cast<const char*>(&n);
  out.insert(out.end(), p, p + sizeof n);
  out.insert(out.end(), t.mode.begin(), t.mode.end());
}

// Reads the trial at `at` (all but its folder) and moves `at` past it.
Trial unpack(const std::vector<char>& in, std::size_t& at) {
  Numbers n;
  std::memcpy(&n, in.data() + at, sizeof n);
  at += sizeof n;
  Trial t;
  t.index = n.index;
  t.load = n.load;
  t.holds = n.holds != 0;
  t.uHold = n.uHold;
  t.uMid = n.uMid;
  t.uEnd = n.uEnd;
  t.brokenMid = n.brokenMid;
  t.brokenEnd = n.brokenEnd;
  t.steps = n.steps;
  t.mode.assign(in.data() + at, n.modeLength);
  at += n.modeLength;
  return t;
}

// Runs the loads side by side: rank r belongs to group r·groups/size, and group g runs the
// loads k ≡ g (mod groups). Every rank returns every trial, in the order of `loads`.
std::vector<Trial> runBatch(const Case& c, const Loading& l, const std::vector<double>& loads,
                            int firstIndex, Comm& comm, Comm& group, int colour, int groups,
                            const Options& opt) {
  std::vector<char> mine;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    if (static_cast<int>(k % groups) != colour) continue;
    const int index = firstIndex + static_cast<int>(k);
    const auto was = std::find_if(opt.done.begin(), opt.done.end(), [&](const Trial& t) {
      return t.index == index && t.load == loads[k];
    });
    if (was != opt.done.end()) continue;  // every rank takes it from the journal below
    const Trial t = runTrial(c, l, loads[k], index, group, opt);
    if (group.root()) pack(t, mine);
  }
  std::vector<char> all;
  for (const auto& block : comm.gather(mine)) all.insert(all.end(), block.begin(), block.end());
  all = comm.broadcast(std::move(all));
  std::vector<Trial> out(loads.size());
  for (std::size_t at = 0; at < all.size();) {
    Trial t = unpack(all, at);
    t.dir = trialDir(opt, t.index);
    out[t.index - firstIndex] = std::move(t);
  }
  for (const Trial& t : opt.done) {
    const long k = t.index - firstIndex;
    if (k >= 0 && k < static_cast<long>(loads.size()) && t.load == loads[k]) {
      out[k] = t;
      out[k].dir = trialDir(opt, t.index);
      out[k].fromJournal = true;
    }
  }
  return out;
}

}  // namespace

Result findStrength(const Case& c, double lo, double hi, Comm& comm, const Options& opt) {
  const int atOnce = std::max(1, opt.atOnce);
  const int groups = std::min(atOnce, comm.size());
  const int colour = comm.rank() * groups / comm.size();
  const Loading loading = schedule(c, comm, opt);
  Comm group = comm.split(colour);
  Result out;
  // The bracket so far: the smallest failing load, and the largest holding one below it.
  auto bracket = [&](double& holds, double& fails) {
    holds = fails = -1;
    for (const Trial& t : out.trials)
      if (!t.holds && (fails < 0 || t.load < fails)) fails = t.load;
    for (const Trial& t : out.trials)
      if (t.holds && (fails < 0 || t.load < fails) && t.load > holds) holds = t.load;
  };
  while (static_cast<int>(out.trials.size()) < opt.maxTrials) {
    double holds, fails;
    bracket(holds, fails);
    if (holds >= 0 && fails >= 0 && fails - holds <= opt.relTol * holds) break;
    const int n = std::min(atOnce, opt.maxTrials - static_cast<int>(out.trials.size()));
    std::vector<double> loads;
    if (out.trials.empty()) {
      loads.push_back(lo);  // the given bracket, and evenly inside it
      if (n > 1) loads.push_back(hi);
      for (int k = 1; k <= n - 2; ++k) loads.push_back(lo + (hi - lo) * k / (n - 1));
    } else if (holds < 0) {  // everything failed: halve
      for (int k = 1; k <= n; ++k) loads.push_back(fails / std::pow(2.0, k));
    } else if (fails < 0) {  // everything held: the given upper end, then doubling
      const bool hiTried = std::any_of(out.trials.begin(), out.trials.end(),
                                       [&](const Trial& t) { return t.load == hi; });
      double next = hi > holds && !hiTried ? hi : 2 * holds;
      for (int k = 0; k < n; ++k, next *= 2) loads.push_back(next);
    } else {
      for (int k = 1; k <= n; ++k) loads.push_back(holds + (fails - holds) * k / (n + 1));
    }
    const auto batch = runBatch(c, loading, loads, static_cast<int>(out.trials.size()) + 1, comm,
                                group, colour, groups, opt);
    out.trials.insert(out.trials.end(), batch.begin(), batch.end());
    if (opt.onTrial)
      for (const Trial& t : batch) opt.onTrial(t);
  }
  double holds, fails;
  bracket(holds, fails);
  out.lower = holds;
  out.upper = fails;
  for (const Trial& t : out.trials)
    if (t.load == fails) out.mode = t.mode;
  return out;
}

namespace {

// The quasi-static run takes one rank per this many particles: each relaxation iteration is
// one force evaluation and two messages (the halo and the exact sums), and on fewer
// particles per rank the messages' waits cost more than the split saves; the 1.16 m beams
// (about 1000 particles) still gain from a second rank (docs/quasi-static.md, "Ranks").
constexpr std::size_t kParticlesPerRank = 400;

// A quasi-static run that holds up to `hi` goes on towards twice as far, as the bisection
// widens its bracket, at most this many times.
constexpr int kRaises = 4;

// The quasi-static run itself, on the ranks of `comm`: one trial per load it held up to
// before going on (1, 2, ...), then the last.
Result staticRun(const Case& c, double hi, Comm& comm, const StaticOptions& opt) {
  RunConfig run = c.run;
  run.procs = {0, 0, 0};
  run.loading = {};
  run.loading.scale = hi / c.unitLoad;
  run.solver.quasiStatic = true;
  run.solver.tolerance = opt.tolerance;
  run.solver.loadSteps = opt.loadSteps;
  run.solver.maxIterations = opt.maxIterations;
  run.solver.maxBroken = opt.maxBroken;
  run.solver.maxCutBacks = opt.maxCutBacks;
  run.solver.peakTolerance = opt.peakTolerance;
  run.solver.masses = opt.masses;
  run.steps = opt.loadSteps;
  const std::string dir = opt.outDir.empty() ? "" : opt.outDir + "/quasi_static";
  run.outDir = dir.empty() ? "." : dir;
  auto simPtr = simulation(c, c.params, run, comm);
  Simulation& sim = *simPtr;
  const StrengthSpec spec = sim.model().strengthSpec();
  if (spec.load.empty() || spec.displacement.empty() || !spec.failureMode)
    throw InputError(c.source, 0, "model " + c.model + " declares no strength spec");
  if (!dir.empty()) {
    OutputSettings out;  // the load–displacement history and the state at the peak
    out.globalsEvery = 1;
    addStandardOutputs(sim, out);
  }
  Result r;
  // The state as a trial (collective: the globals and the failure mode).
  auto trial = [&] {
    Trial tr;
    tr.index = static_cast<int>(r.trials.size()) + 1;
    tr.dir = dir;
    const auto names = sim.model().globals();
    const auto values = sim.model().globalValues(sim.context());
    const auto uAt = positions(c, names, spec.displacement);
    double u = std::fabs(values[uAt[0]]);
    for (std::size_t k = 1; k < uAt.size(); ++k) u = std::hypot(u, values[uAt[k]]);
    tr.uHold = tr.uMid = tr.uEnd = u;
    tr.brokenMid = tr.brokenEnd = values[positions(c, names, {spec.damage})[0]];
    tr.steps = sim.step();
    tr.mode = spec.failureMode(sim.context());
    return tr;
  };
  sim.setRaise([&] {
    if (static_cast<int>(r.trials.size()) == kRaises) return false;
    Trial held = trial();
    held.holds = true;
    held.load = sim.lastLoadStep().factor * c.unitLoad;
    r.trials.push_back(std::move(held));
    return true;
  });
  // The last load step that found no equilibrium: past the peak, how the member fails.
  std::optional<Trial> failing;
  sim.setAbandoned([&] { failing = trial(); });
  while (sim.advance()) {
  }
  const Simulation::LoadStep& last = sim.lastLoadStep();
  r.lower = last.factor * c.unitLoad;
  r.upper = last.beyond > 0 ? last.beyond * c.unitLoad : -1;
  Trial tr = r.upper > 0 && failing ? *failing : trial();
  tr.index = static_cast<int>(r.trials.size()) + 1;
  if (!dir.empty()) sim.finish();
  r.mode = tr.mode;
  tr.holds = r.upper < 0;
  tr.load = tr.holds ? r.lower : r.upper;
  r.trials.push_back(std::move(tr));
  return r;
}

}  // namespace

Result staticStrength(const Case& c, double hi, Comm& comm, const StaticOptions& opt) {
  // The run on the first ranks, one per kParticlesPerRank particles (at least one); the
  // others wait for its result.
  const int ranks = static_cast<int>(std::clamp<std::size_t>(
      c.particles.size() / kParticlesPerRank, 1, static_cast<std::size_t>(comm.size())));
  Comm group = comm.split(comm.rank() < ranks ? 0 : 1);
  Result r;
  std::vector<char> message;
  if (comm.rank() < ranks) {
    r = staticRun(c, hi, group, opt);
    if (comm.root()) {
      const double bounds[2] = {r.lower, r.upper};
      const char* p = reinterpret_cast<const char*>(bounds);
      message.insert(message.end(), p, p + sizeof bounds);
      for (const Trial& t : r.trials) pack(t, message);
    }
  }
  message = comm.broadcast(std::move(message));
  if (comm.rank() < ranks) return r;
  double bounds[2];
  std::memcpy(bounds, message.data(), sizeof bounds);
  r.lower = bounds[0], r.upper = bounds[1];
  for (std::size_t at = sizeof bounds; at < message.size();) {
    Trial tr = unpack(message, at);
    tr.dir = opt.outDir.empty() ? "" : opt.outDir + "/quasi_static";
    r.mode = tr.mode;
    r.trials.push_back(std::move(tr));
  }
  return r;
}

}  // namespace pdq::strength
