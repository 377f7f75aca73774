#include "engine/integrator.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "engine/context.hpp"
#include "engine/error.hpp"
#include "engine/model.hpp"
#include "engine/rotation.hpp"

namespace pdq {

namespace {

int column(const std::vector<std::string>& names, const std::string& name, const char* table) {
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return static_cast<int>(k);
  throw std::logic_error(std::string("the model's motion names '") + name +
                         "', which is not in its " + table + " attributes");
}

// Nonzero when x is not finite: x − x is +0 for every finite x and NaN for ±inf and NaN,
// so the OR of many such bits tells whether any is not finite (no branch, no comparison
// for a NaN to fool).
inline std::uint64_t notFiniteBits(double x) { return std::bit_cast<std::uint64_t>(x - x); }

[[gnu::always_inline]] inline bool anyNotFiniteIn(const double* a, std::size_t n) {
  std::uint64_t bits = 0;
  for (std::size_t k = 0; k < n; ++k) bits |= notFiniteBits(a[k]);
  return bits != 0;
}
bool anyNotFinitePortable(const double* a, std::size_t n) { return anyNotFiniteIn(a, n); }
[[gnu::target("avx2")]] bool anyNotFiniteAvx2(const double* a, std::size_t n) {
  return anyNotFiniteIn(a, n);
}

// The integrator moves particles in blocks of this many, each looked at by the instability
// checks while it is in cache.
constexpr std::size_t kBlock = 128;

}  // namespace

Loading readLoading(const Params& p) {
  constexpr double big = 1e300;
  Loading l;
  l.scale = p.number("load_scale", l.scale, -big, big);
  l.rampTime = p.number("ramp_time", l.rampTime, 0.0, big);
  l.holdTime = p.number("hold_time", l.holdTime, 0.0, big);
  l.holdDampingRatio = p.number("hold_damping_ratio", l.holdDampingRatio, 0.0, big);
  return l;
}

std::string writeLoading(const Loading& l) {
  const Loading none;
  std::string out;
  auto line = [&](const char* key, double v, double fallback) {
    if (v == fallback) return;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s %.17g\n", key, v);
    out += buf;
  };
  line("load_scale", l.scale, none.scale);
  line("ramp_time", l.rampTime, none.rampTime);
  line("hold_time", l.holdTime, none.holdTime);
  line("hold_damping_ratio", l.holdDampingRatio, none.holdDampingRatio);
  return out;
}

Solver::Masses readMasses(const Params& p, const std::string& key, const std::string& fallback) {
  const std::string m = p.choice(key, fallback, {"stiffness", "model", "assembled"});
  return m == "model"       ? Solver::Masses::Model
         : m == "assembled" ? Solver::Masses::Assembled
                            : Solver::Masses::Stiffness;
}

Solver readSolver(const Params& p, const std::string& kindKey) {
  Solver s;
  const std::string kind = p.choice(kindKey, "dynamic", {"dynamic", "quasi_static"});
  s.quasiStatic = kind == "quasi_static";
  if (const auto where = p.raw(kindKey)) s.line = where->line;
  for (const char* key :
       {"tolerance", "max_iterations", "load_steps", "max_broken", "max_cut_backs",
        "peak_tolerance", "masses", "control_axis", "control_displacement", "control_ids"})
    if (!s.quasiStatic && p.has(key))
      throw InputError(p.raw(key)->file, p.raw(key)->line,
                       std::string(key) + " is a quasi-static solver parameter; set " + kindKey +
                           " = quasi_static");
  s.tolerance = p.number("tolerance", s.tolerance);
  if (!(s.tolerance > 0))
    throw InputError(p.raw("tolerance")->file, p.raw("tolerance")->line,
                     "tolerance must be positive (the out-of-balance force relative to the "
                     "applied load at which a load step has converged)");
  s.maxIterations = p.integer("max_iterations", s.maxIterations);
  if (s.maxIterations < 1)
    throw InputError(p.raw("max_iterations")->file, p.raw("max_iterations")->line,
                     "max_iterations must be at least 1 (iterations per load step)");
  if (const auto r = p.raw("max_iterations")) s.line = r->line;
  s.loadSteps = p.integer("load_steps", s.loadSteps);
  if (s.loadSteps < 1)
    throw InputError(p.raw("load_steps")->file, p.raw("load_steps")->line,
                     "load_steps must be at least 1");
  s.maxBroken = p.integer("max_broken", s.maxBroken);
  if (s.maxBroken < 0)
    throw InputError(p.raw("max_broken")->file, p.raw("max_broken")->line,
                     "max_broken must be >= 0 (0: any number of interactions may break in a "
                     "load step)");
  const long cuts = p.integer("max_cut_backs", s.maxCutBacks);
  if (cuts < 0 || cuts > 50)
    throw InputError(p.raw("max_cut_backs")->file, p.raw("max_cut_backs")->line,
                     "max_cut_backs must be between 0 and 50 (halvings of the increment)");
  s.maxCutBacks = static_cast<int>(cuts);
  s.masses = readMasses(p, "masses", "stiffness");
  s.peakTolerance = p.number("peak_tolerance", s.peakTolerance);
  if (!(s.peakTolerance >= 0))
    throw InputError(p.raw("peak_tolerance")->file, p.raw("peak_tolerance")->line,
                     "peak_tolerance must be >= 0 (the peak's bracket relative to the last "
                     "load in equilibrium; 0: down to the smallest increment)");
  s.control = readControl(p, "control_");
  if (p.has("control_ids")) {
    const int at = p.raw("control_ids")->line;
    if (!s.control.active())
      throw InputError(p.raw("control_ids")->file, at,
                       "control_ids needs control_axis and control_displacement");
    for (double v : p.numbers("control_ids")) {
      if (!(v >= 0 && v <= 9.0e15) || v != static_cast<double>(static_cast<Gid>(v)))
        throw InputError(
            p.raw("control_ids")->file, at,
            "control_ids: " + numberText(v) + " is not a particle's ID (a whole number >= 0)");
      s.control.ids.push_back(static_cast<Gid>(v));
    }
    std::sort(s.control.ids.begin(), s.control.ids.end());
  } else if (s.control.active() && p.has("control_axis"))
    throw InputError(p.raw("control_axis")->file, s.control.line,
                     "the displacement control needs control_ids (the particles it moves)");
  return s;
}

DisplacementControl readControl(const Params& p, const std::string& prefix) {
  DisplacementControl c;
  const std::string axisKey = prefix + "axis", valueKey = prefix + "displacement";
  if (!p.has(axisKey) && !p.has(valueKey)) return c;
  const auto where = p.raw(p.has(axisKey) ? axisKey : valueKey);
  if (!p.has(axisKey) || !p.has(valueKey))
    throw InputError(where->file, where->line,
                     "the displacement control needs both " + axisKey + " (x, y or z) and " +
                         valueKey + " (the peak displacement along it)");
  const std::string axis = p.choice(axisKey, "x", {"x", "y", "z"});
  c.axis = axis == "x" ? 0 : axis == "y" ? 1 : 2;
  c.line = where->line;
  c.displacement = p.number(valueKey, 0.0);
  if (c.displacement == 0 || !std::isfinite(c.displacement))
    throw InputError(p.raw(valueKey)->file, p.raw(valueKey)->line,
                     valueKey + " must be a nonzero number (the peak displacement)");
  return c;
}

std::string writeSolver(const Solver& s) {
  if (!s.quasiStatic) return "";
  char buf[160];
  std::snprintf(buf, sizeof buf, "solver quasi_static\ntolerance %.17g\nmax_iterations %ld\n",
                s.tolerance, s.maxIterations);
  std::string out = std::string(buf) + "load_steps " + std::to_string(s.loadSteps) + "\n";
  const Solver none;
  if (s.maxBroken != none.maxBroken) out += "max_broken " + std::to_string(s.maxBroken) + "\n";
  if (s.maxCutBacks != none.maxCutBacks)
    out += "max_cut_backs " + std::to_string(s.maxCutBacks) + "\n";
  if (s.masses == Solver::Masses::Model) out += "masses model\n";
  if (s.masses == Solver::Masses::Assembled) out += "masses assembled\n";
  if (s.peakTolerance != none.peakTolerance)
    out += "peak_tolerance " + numberText(s.peakTolerance) + "\n";
  if (s.control.active()) {
    out += std::string("control_axis ") + "xyz"[s.control.axis] + "\ncontrol_displacement " +
           numberText(s.control.displacement) + "\ncontrol_ids";
    for (Gid g : s.control.ids) out += " " + std::to_string(g);
    out += "\n";
  }
  return out;
}

void checkStaticLoading(const Solver& s, const Params& loading) {
  if (!s.quasiStatic) return;
  for (const char* k : {"ramp_time", "hold_time", "hold_damping_ratio"})
    if (loading.has(k))
      throw InputError(loading.raw(k)->file, loading.raw(k)->line,
                       std::string(k) +
                           " belongs to dynamic loading; the quasi-static solver applies "
                           "load_scale in load_steps increments");
}

void Integrator::resolve(const Schema& s) {
  const Motion m = model_.motion();
  if (m.position.size() != m.velocity.size() || m.position.size() != m.force.size() ||
      m.position.size() > 3)
    throw std::logic_error(
        "the model's motion needs as many velocity and force columns as positions (at most 3)");
  nT_ = static_cast<int>(m.position.size());
  nA_ = s.nAlter();
  for (int d = 0; d < nT_; ++d) {
    pos_[d] = column(s.alter, m.position[d], "alterable");
    if (pos_[d] > 2) throw std::logic_error("the model's motion: positions are among x y z");
    vel_[d] = column(s.alter, m.velocity[d], "alterable");
    frc_[d] = column(s.integ, m.force[d], "integ");
  }
  rotation_ = m.rotation;
  perMass_ = m.perMass;
  damping_ = m.damping;
  const std::size_t nq = m.rotation == Rotation::Spatial ? 4 : 1, nw = nq == 4 ? 3 : 1;
  nR_ = m.rotation == Rotation::None ? 0 : static_cast<int>(nw);
  if (nR_ &&
      (m.orientation.size() != nq || m.angularVelocity.size() != nw || m.moment.size() != nw))
    throw std::logic_error("the model's motion: wrong number of rotation columns");
  for (int k = 0; k < nR_; ++k) {
    vel_[nT_ + k] = column(s.alter, m.angularVelocity[k], "alterable");
    frc_[nT_ + k] = column(s.integ, m.moment[k], "integ");
  }
  for (std::size_t k = 0; nR_ && k < nq; ++k)
    quat_[k] = column(s.alter, m.orientation[k], "alterable");
  if (rotation_ == Rotation::Planar) pos_[nT_] = quat_[0];
  anyNotFinite_ = __builtin_cpu_supports("avx2") ? anyNotFiniteAvx2 : anyNotFinitePortable;
  // Every integ column a force or moment, in order: the watch sweeps them as one array.
  forcesOnly_ = s.nInteg() == nT_ + nR_;
  for (int d = 0; d < nT_ + nR_; ++d) forcesOnly_ &= frc_[d] == d;
  resolved_ = true;
}

std::vector<double> Integrator::state() const {
  if (omega2_ < 0) return {holdDamping_};
  return {
      holdDamping_, omega2_,     iterations_, path_.progress,        path_.increment, path_.easy,
      path_.beyond, path_.first, mu_,         assembled_ ? 1.0 : 0.0};
}

void Integrator::setState(std::span<const double> s) {
  if (s.size() != 1 && (s.size() < 6 || s.size() > 10))
    throw std::logic_error("integrator state: one or six to ten values expected");
  holdDamping_ = s[0];
  // Six to nine: written before the load path kept `beyond` and `first`, before the
  // Gershgorin masses (μ = 0: the model's masses, as those runs had) and before the
  // assembled stiffness.
  if (s.size() >= 6) {
    omega2_ = s[1], iterations_ = s[2];
    path_ = {s[3], s[4], s[5], s.size() >= 7 ? s[6] : 0.0, s.size() >= 8 ? s[7] : 0.0};
    mu_ = s.size() >= 9 ? s[8] : 0.0;
    assembled_ = s.size() == 10 && s[9] != 0;
  }
}

void Integrator::ensureBodies(Context& ctx) {
  Particles& P = ctx.particles;
  if (!resolved_) resolve(P.schema());
  const std::size_t n = P.owned();
  if (haveBodies_ && bodies_.size() == n) return;
  bodies_.assign(n, Body{});
  model_.bodies(ctx, bodies_);
  for (const Body& b : bodies_)
    for (int d = nT_; d < nT_ + nR_; ++d)
      if (rotation_ == Rotation::Spatial && b.constraint[d] == Constraint::Resting)
        throw std::logic_error("a spatial rotation cannot rest on a support");
  haveBodies_ = true;
  indexFreeBodies();
}

void Integrator::indexFreeBodies() {
  const std::size_t n = bodies_.size();
  freeInverseMass_.assign(n, 0.0);
  freeInverseInertia_.assign(rotation_ == Rotation::Planar ? n : 0, 0.0);
  if (rotation_ == Rotation::Spatial) return;
  const int nLinear = nT_ + (rotation_ == Rotation::Planar ? 1 : 0);
  for (std::size_t i = 0; i < n; ++i) {
    const Body& b = bodies_[i];
    bool free = true;
    for (int d = 0; d < nLinear; ++d) free &= b.constraint[d] == Constraint::Free && b.load[d] == 0;
    if (!free) continue;
    freeInverseMass_[i] = 1 / b.mass;
    if (rotation_ == Rotation::Planar) freeInverseInertia_[i] = 1 / b.inertia;
  }
}

void Integrator::turn(Particles& P, std::size_t i, const double phi[3]) const {
  // The orientation turns by the increment's quaternion, renormalised against round-off.
  double* a = P.alter(i);
  const Quat q = normalised(
      mul(expRot({phi[0], phi[1], phi[2]}), {a[quat_[0]], a[quat_[1]], a[quat_[2]], a[quat_[3]]}));
  a[quat_[0]] = q.w;
  a[quat_[1]] = q.x;
  a[quat_[2]] = q.y;
  a[quat_[3]] = q.z;
}

// The displacement of DOF d of owned particle i from its reference (rotations: the angle,
// or the rotation vector's component).
double Integrator::displacement(const Particles& P, std::size_t i, int d) const {
  const double* a = P.alter(i);
  if (d < nT_) return a[pos_[d]] - P.fixed(i)[pos_[d]];
  if (rotation_ == Rotation::Planar) return a[pos_[d]];
  return logRot({a[quat_[0]], a[quat_[1]], a[quat_[2]], a[quat_[3]]})[d - nT_];
}

// 2 ζ_h ω₁, ω₁² = F·u / (u·M·u) the Rayleigh quotient of the current deflection under the
// held loads (close to static by the end of a slow ramp); 0 without loads.
double Integrator::rayleighDamping(Context& ctx, double factor) const {
  const Particles& P = ctx.particles;
  const int n = nT_ + nR_;
  const double work = ctx.sumOwned([&](std::size_t i) {
    double w = 0;
    for (int d = 0; d < n; ++d) w += bodies_[i].load[d] * displacement(P, i, d);
    return factor * w;
  });
  const double inertia = ctx.sumOwned([&](std::size_t i) {
    double t = 0, r = 0;
    for (int d = 0; d < nT_; ++d) t += displacement(P, i, d) * displacement(P, i, d);
    for (int d = nT_; d < n; ++d) r += displacement(P, i, d) * displacement(P, i, d);
    return bodies_[i].mass * t + bodies_[i].inertia * r;
  });
  if (!(work > 0 && inertia > 0)) return 0;
  const double omega1 = std::sqrt(work / inertia);
  const double ratio = ctx.loading().holdDampingRatio;
  if (ctx.root())
    ctx.log() << "loads held from step " << ctx.step() << "; Rayleigh frequency " << omega1
              << " rad/s, hold damping " << 2 * ratio * omega1 << " 1/s\n";
  return 2 * ratio * omega1;
}

void Integrator::step(Context& ctx) {
  Particles& P = ctx.particles;
  ensureBodies(ctx);
  const std::size_t n = P.owned();
  const Loading& L = ctx.loading();
  const double h = ctx.dt();
  // The first step of a run from step 0 starts from v(0): half a kick (velocity Verlet).
  const double kick = ctx.step() == 1 ? 0.5 * h : h;
  const double tNow = static_cast<double>(ctx.step() - 1) * h;
  const double tNext = static_cast<double>(ctx.step()) * h;
  const double fNow = L.factor(tNow), fNext = L.factor(tNext);
  const bool held = L.held(tNow);
  if (held && L.holdDampingRatio > 0 && holdDamping_ < 0) holdDamping_ = rayleighDamping(ctx, fNow);
  const double c = damping_ + (held && holdDamping_ > 0 ? holdDamping_ : 0.0);
  const double zero = 0.0 * fNow;  // an unloaded DOF's load term, signed as advance's
  Watch* const w = watch_;
  watch_ = nullptr;
#pragma omp parallel
  {
    Watch mine;  // this thread's share of the watch
    if (w) mine.tracked = w->tracked;
    const long nBlocks = static_cast<long>((n + kBlock - 1) / kBlock);
#pragma omp for schedule(static) nowait
    for (long k = 0; k < nBlocks; ++k) {
      const std::size_t begin = static_cast<std::size_t>(k) * kBlock;
      const std::size_t end = std::min(n, begin + kBlock);
      if (!w) {
        for (std::size_t i = begin; i < end; ++i)
          if (freeInverseMass_[i] > 0)
            advanceFree<false>(P, i, h, kick, zero, c);
          else
            advance<false>(P, i, h, kick, fNow, fNext, c);
        continue;
      }
      double moves[kBlock], most = 0;
      for (std::size_t i = begin; i < end; ++i) {
        moves[i - begin] = freeInverseMass_[i] > 0 ? advanceFree<true>(P, i, h, kick, zero, c)
                                                   : advance<true>(P, i, h, kick, fNow, fNext, c);
        most = std::max(most, moves[i - begin]);
      }
      seeBlock(P, begin, end, moves, most, h, mine);
    }
    if (w) {
#pragma omp critical(pdq_integrator_watch)
      merge(P, mine, *w);
    }
  }
  if (w) w->done = true;
}

// Inlined in the step's loops, so that the move is taken from registers.
template <bool kMove>
[[gnu::always_inline]] inline double Integrator::advance(Particles& P, std::size_t i, double h,
                                                         double kick, double fNow, double fNext,
                                                         double c) const {
  const int nLinear = nT_ + (rotation_ == Rotation::Planar ? 1 : 0);
  double* a = P.alter(i);
  const double* X = P.fixed(i);
  const double* F = P.integ(i);
  const Body& b = bodies_[i];
  const double invM = 1 / b.mass, invI = 1 / b.inertia;
  double moved = 0;  // the square of the move v Δt, the velocities' final values
  for (int d = 0; d < nLinear; ++d) {
    const bool rot = d >= nT_;
    const int p = pos_[d], v = vel_[d];
    const double ref = rot ? 0.0 : X[p];
    if (b.constraint[d] == Constraint::Prescribed) {
      const double target = ref + b.value[d] * fNext;
      a[v] = (target - a[p]) / h;
      a[p] = target;
    } else {
      if (b.constraint[d] != Constraint::KeepVelocity) {
        const double inv = rot ? invI : invM;
        double acc = perMass_ && !rot ? F[frc_[d]] + b.load[d] * fNow * inv
                                      : (F[frc_[d]] + b.load[d] * fNow) * inv;
        acc -= c * a[v];
        a[v] += acc * kick;
      }
      a[p] += a[v] * h;
      if (b.constraint[d] == Constraint::Resting && a[p] < ref) {
        a[p] = ref;  // on the support: no penetration, no bounce
        a[v] = 0;
      }
    }
    if (kMove && !rot) {
      const double s = a[v] * h;
      moved += s * s;
    }
  }
  if (rotation_ != Rotation::Spatial) return moved;
  Vec phi;
  for (int k = 0; k < 3; ++k) {
    const int d = nT_ + k, v = vel_[d];
    if (b.constraint[d] == Constraint::Prescribed) {
      a[v] = b.value[d] * (fNext - fNow) / h;
    } else if (b.constraint[d] == Constraint::Free) {
      const double acc = (F[frc_[d]] + b.load[d] * fNow) * invI - c * a[v];
      a[v] += acc * kick;
    }
    phi[k] = a[v] * h;
  }
  turn(P, i, phi.data());
  return moved;
}

template <bool kMove>
[[gnu::always_inline]] inline double Integrator::advanceFree(Particles& P, std::size_t i, double h,
                                                             double kick, double zero,
                                                             double c) const {
  double* a = P.alter(i);
  const double* F = P.integ(i);
  const double invM = freeInverseMass_[i];
  double moved = 0;
  for (int d = 0; d < nT_; ++d) {
    const int p = pos_[d], v = vel_[d];
    // advance's (F + load fNow) / m, or F / m + load fNow / m, with load = 0: zero / m is
    // zero itself (m > 0).
    double acc = perMass_ ? F[frc_[d]] + zero : (F[frc_[d]] + zero) * invM;
    acc -= c * a[v];
    a[v] += acc * kick;
    a[p] += a[v] * h;
    if (kMove) {
      const double s = a[v] * h;
      moved += s * s;
    }
  }
  if (rotation_ == Rotation::Planar) {  // the angle: advance's (M + load fNow) / I
    const int p = pos_[nT_], v = vel_[nT_];
    double acc = (F[frc_[nT_]] + zero) * freeInverseInertia_[i];
    acc -= c * a[v];
    a[v] += acc * kick;
    a[p] += a[v] * h;
  }
  return moved;
}

bool Integrator::notFinite(const Particles& P, std::size_t i) const {
  const double* a = P.alter(i);
  const double* F = P.integ(i);
  std::uint64_t bits = 0;
  for (int k = 0; k < nA_; ++k) bits |= notFiniteBits(a[k]);
  for (int d = 0; d < nT_ + nR_; ++d) bits |= notFiniteBits(F[frc_[d]]);
  return bits != 0;
}

double Integrator::moveSquared(const Particles& P, std::size_t i, double h) const {
  const double* a = P.alter(i);
  double m = 0;
  for (int d = 0; d < nT_; ++d) {
    const double s = a[vel_[d]] * h;
    m += s * s;
  }
  return m;
}

// The move v Δt of a particle with alterable attributes `a`, by position column.
inline std::array<double, 3> moveOf(const double* a, double h, int nT, const int* pos,
                                    const int* vel) {
  std::array<double, 3> step{};
  for (int d = 0; d < nT; ++d) step[pos[d]] = a[vel[d]] * h;
  return step;
}

void Integrator::seeBlock(const Particles& P, std::size_t begin, std::size_t end,
                          const double* moves, double most, double h, Watch& w) const {
  if (begin >= end) return;
  // Rows are contiguous: one branch-free sweep over the block's attributes (and its forces
  // when every integ column is one), in cache since the step has just moved them.
  const std::size_t n = end - begin;
  bool bad = anyNotFinite_(P.alter(begin), n * static_cast<std::size_t>(nA_));
  if (forcesOnly_) {
    bad |= anyNotFinite_(P.integ(begin), n * static_cast<std::size_t>(nT_ + nR_));
  } else {
    std::uint64_t bits = 0;
    for (std::size_t i = begin; i < end; ++i)
      for (int d = 0; d < nT_ + nR_; ++d) bits |= notFiniteBits(P.integ(i)[frc_[d]]);
    bad |= bits != 0;
  }
  w.nonFinite |= bad;
  if (w.tracked >= begin && w.tracked < end) {
    w.trackedStep = moveOf(P.alter(w.tracked), h, nT_, pos_.data(), vel_.data());
    w.sawTracked = true;
  }
  // Which particle: rarely needed (the largest move so far seldom grows), so looked for
  // only then. Of equal moves the largest ID, so that neither the grid nor the threads
  // choose.
  if (most == 0 || most < w.most) return;
  const std::size_t before = w.fastest;
  for (std::size_t i = begin; i < end; ++i) {
    const double m = moves[i - begin];
    if (m > w.most || (m == w.most && w.fastest != kNoParticle && P.gid(i) > P.gid(w.fastest)))
      w.most = m, w.fastest = i;
  }
  if (w.fastest != before)
    w.fastestStep = moveOf(P.alter(w.fastest), h, nT_, pos_.data(), vel_.data());
}

void Integrator::merge(const Particles& P, const Watch& part, Watch& w) {
  w.nonFinite |= part.nonFinite;
  if (part.sawTracked) w.trackedStep = part.trackedStep, w.sawTracked = true;
  if (part.most > w.most ||
      (part.most == w.most && part.most > 0 && P.gid(part.fastest) > P.gid(w.fastest)))
    w.most = part.most, w.fastest = part.fastest, w.fastestStep = part.fastestStep;
}

void Integrator::see(Context& ctx, Watch& w) {
  const Particles& P = ctx.particles;
  if (!resolved_) resolve(P.schema());
  const double h = ctx.dt();
  for (std::size_t begin = 0; begin < P.owned(); begin += kBlock) {
    const std::size_t end = std::min(P.owned(), begin + kBlock);
    double moves[kBlock], most = 0;
    for (std::size_t i = begin; i < end; ++i) {
      moves[i - begin] = moveSquared(P, i, h);
      most = std::max(most, moves[i - begin]);
    }
    seeBlock(P, begin, end, moves, most, h, w);
  }
  w.done = true;
}

}  // namespace pdq
