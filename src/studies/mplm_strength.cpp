#include "studies/mplm_strength.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "engine/model.hpp"
#include "engine/simulation.hpp"
#include "io/standard_outputs.hpp"
#include "models/mplm/2d/attributes.hpp"

namespace pdq::mplm {
namespace {

double globalValue(const std::vector<std::string>& names, const std::vector<double>& values,
                   const std::string& name) {
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return values[k];
  return 0;
}

// Where the badly damaged (ω ≥ ½) concrete interactions are: mostly compressive → "compression";
// plates otherwise → "tension"; beams → "flexural" when most lie in the middle third of the span,
// else "shear".
std::string failureMode(const Example& ex, Context& ctx) {
  const Particles& P = ctx.particles;
  const Bonds& B = ctx.bonds;
  double tensile = 0, compressive = 0, middle = 0, total = 0;
  ExactSum t, c, m, all;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    if (isSteel(P.fixed(i))) continue;
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      const double* st = B.attr(b);
      if (std::max(st[OMEGA_T], st[OMEGA_C]) < 0.5) continue;
      (st[OMEGA_C] >= st[OMEGA_T] ? c : t).add(1);
      all.add(1);
      if (std::fabs(P.fixed(i)[FX_X] - ex.span / 2) < ex.span / 6) m.add(1);
    }
  }
  tensile = ctx.sum(t);
  compressive = ctx.sum(c);
  middle = ctx.sum(m);
  total = ctx.sum(all);
  if (total == 0) return "none";
  if (compressive > tensile) return "compression";
  if (!ex.beam) return "tension";
  return middle > total / 2 ? "flexural" : "shear";
}

}  // namespace

namespace {

std::unique_ptr<Simulation> makeSimulation(const Example& ex, const Params& p, long steps,
                                           const std::string& outDir, Comm& comm) {
  auto model = ModelRegistry::create("mplm2d");
  model->configure(p);
  p.checkAllUsed();
  RunConfig cfg;
  cfg.steps = steps;
  cfg.outDir = outDir.empty() ? "." : outDir;
  cfg.source = ex.name;
  auto sim = std::make_unique<Simulation>(std::move(model), ex.particles, cfg, comm);
  sim->setup();
  return sim;
}

std::string number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

Trial runTrial(const Example& ex, double load, Comm& comm, const StrengthOptions& opt, int index) {
  Params p("strength trial");
  for (const auto& [k, v] : ex.params) p.set(k, v);
  for (const auto& [k, v] : opt.overrides) p.set(k, v);
  p.set("load_scale", number(load / ex.unitLoad));
  const double dt0 = p.number("dt", 0.0);
  long steps = static_cast<long>(std::ceil(ex.steps * opt.timeScale));
  if (opt.stableStep) {
    const double duration = steps * dt0;
    p.set("dt", "0");
    const double dt = makeSimulation(ex, p, 1, "", comm)->context().dt();
    if (duration > 0) steps = static_cast<long>(std::ceil(duration / dt));
  }
  p.set("hold_damping_ratio", number(opt.holdDamping));
  // The example's ramp, then its hold stretched by holdLength.
  const double exRamp = p.number("ramp_fraction", 0.75);
  const long rampSteps = static_cast<long>(std::ceil(exRamp * steps));
  steps = rampSteps + static_cast<long>(std::ceil(opt.holdLength * (steps - rampSteps)));
  const double rampFraction = static_cast<double>(rampSteps) / steps;
  p.set("ramp_fraction", number(rampFraction));
  Trial tr;
  tr.index = index;
  tr.load = load;
  if (!opt.outDir.empty()) {
    char name[32];
    std::snprintf(name, sizeof name, "/trial_%02d", index);
    tr.dir = opt.outDir + name;
  }
  auto simPtr = makeSimulation(ex, p, steps, tr.dir, comm);
  Simulation& sim = *simPtr;
  if (!tr.dir.empty()) {
    OutputSettings out;  // the load–displacement history and the state at the end
    out.globalsEvery = std::max(1L, steps / 400);
    addStandardOutputs(sim, out);
  }
  const auto names = sim.model().globals();
  const long holdStart = static_cast<long>(std::ceil(rampFraction * steps));
  const long mid = holdStart + (steps - holdStart) / 2;
  const long check = std::max(1L, steps / 100);
  bool runaway = false;
  while (sim.advance()) {
    const long step = sim.step();
    if (step != holdStart && step != mid && step % check != 0) continue;
    const auto values = sim.model().globalValues(sim.context());
    const double u = std::hypot(globalValue(names, values, "ux"), globalValue(names, values, "uy"));
    if (!std::isfinite(u)) {
      runaway = true;
      break;
    }
    if (step == holdStart) tr.uHold = u;
    if (step == mid) {
      tr.uMid = u;
      tr.brokenMid = globalValue(names, values, "broken");
    }
    if (step >= holdStart && tr.uHold > 0 && u > opt.runaway * tr.uHold) {
      runaway = true;
      break;
    }
  }
  tr.steps = sim.step();
  const auto values = sim.model().globalValues(sim.context());
  tr.uEnd = std::hypot(globalValue(names, values, "ux"), globalValue(names, values, "uy"));
  tr.brokenEnd = globalValue(names, values, "broken");
  tr.holds = !runaway && std::isfinite(tr.uEnd) &&
             tr.brokenEnd - tr.brokenMid <= opt.lateBreaks * tr.brokenEnd + 1 &&
             std::fabs(tr.uEnd - tr.uMid) <= opt.settle * std::fabs(tr.uMid);
  tr.mode = failureMode(ex, sim.context());
  tr.log = sim.debugText();
  if (!tr.dir.empty()) sim.finish();
  return tr;
}

namespace {

// Trials travel between groups of ranks as text: numbers exactly, strings length-prefixed.
std::vector<char> pack(const Trial& t) {
  std::string s;
  for (double v : {double(t.index), t.load, double(t.holds), t.uHold, t.uMid, t.uEnd, t.uPeak,
                   t.brokenMid, t.brokenEnd, double(t.steps)})
    s += number(v) + "\n";
  for (const std::string* str : {&t.mode, &t.log, &t.dir})
    s += std::to_string(str->size()) + "\n" + *str;
  return {s.begin(), s.end()};
}

Trial unpack(const std::vector<char>& bytes) {
  std::string s(bytes.begin(), bytes.end());
  std::size_t at = 0;
  auto line = [&] {
    const std::size_t end = s.find('\n', at);
    const std::string out = s.substr(at, end - at);
    at = end + 1;
    return out;
  };
  double v[10];
  for (double& x : v) x = std::stod(line());
  Trial t;
  t.index = static_cast<int>(v[0]);
  t.load = v[1];
  t.holds = v[2] != 0;
  t.uHold = v[3];
  t.uMid = v[4];
  t.uEnd = v[5];
  t.uPeak = v[6];
  t.brokenMid = v[7];
  t.brokenEnd = v[8];
  t.steps = static_cast<long>(v[9]);
  for (std::string* str : {&t.mode, &t.log, &t.dir}) {
    const std::size_t n = std::stoul(line());
    *str = s.substr(at, n);
    at += n;
  }
  return t;
}

// Runs the loads side by side: rank r belongs to group r·groups/size, and group g runs the
// loads k ≡ g (mod groups). Every rank returns every trial, in the order of `loads`.
std::vector<Trial> runBatch(const Example& ex, const std::vector<double>& loads, int firstIndex,
                            Comm& comm, Comm& group, int colour, int groups,
                            const StrengthOptions& opt) {
  std::vector<char> mine;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    if (static_cast<int>(k % groups) != colour) continue;
    const Trial t = runTrial(ex, loads[k], group, opt, firstIndex + static_cast<int>(k));
    if (!group.root()) continue;
    const std::vector<char> b = pack(t);
    const std::string n = std::to_string(b.size()) + "\n";
    mine.insert(mine.end(), n.begin(), n.end());
    mine.insert(mine.end(), b.begin(), b.end());
  }
  std::vector<char> all;
  for (const auto& block : comm.gather(mine)) all.insert(all.end(), block.begin(), block.end());
  all = comm.broadcast(std::move(all));
  std::vector<Trial> out(loads.size());
  std::size_t at = 0;
  while (at < all.size()) {
    const auto nl = std::find(all.begin() + at, all.end(), '\n') - all.begin();
    const std::size_t n = std::stoul(std::string(all.begin() + at, all.begin() + nl));
    const Trial t = unpack({all.begin() + nl + 1, all.begin() + nl + 1 + n});
    out[t.index - firstIndex] = t;
    at = nl + 1 + n;
  }
  return out;
}

}  // namespace

Strength findStrength(const Example& ex, double lo, double hi, Comm& comm,
                      const StrengthOptions& opt) {
  const int atOnce = std::max(1, opt.atOnce);
  const int groups = std::min(atOnce, comm.size());
  const int colour = comm.rank() * groups / comm.size();
  Comm group = comm.split(colour);
  Strength out;
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
    const auto batch = runBatch(ex, loads, static_cast<int>(out.trials.size()) + 1, comm, group,
                                colour, groups, opt);
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

}  // namespace pdq::mplm
